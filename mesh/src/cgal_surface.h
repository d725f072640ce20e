#pragma once
// Private helpers of the mesh module: the CGAL names its volume code uses and
// the few topological counts it needs. Not installed.
#include "igaprep/mesh/to_surface_mesh.h"
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh::detail {

using Kernel = CgalKernel;
using Point3 = CgalPoint;
using mesh::SurfaceMesh;

// Topology of a closed triangle surface: connected components and total genus
// from Euler's formula, sum over components of (2 - chi) / 2.
struct SurfaceTopology {
  int components = 0;
  int genus = 0;
};
SurfaceTopology surface_topology(const TriMesh& mesh);

}  // namespace igaprep::mesh::detail
