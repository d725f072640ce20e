#pragma once
// Private helpers of the mesh module: TriMesh <-> CGAL::Surface_mesh and the
// few topological counts the volume code needs. Not installed.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh::detail {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;

// Builds a Surface_mesh; throws bad_input naming `what` when a triangle cannot
// be added (non-manifold or inconsistently oriented).
SurfaceMesh to_surface_mesh(const TriMesh& mesh, const std::string& what);

// Copies vertices (compacted, in index order) and triangles back to arrays.
TriMesh from_surface_mesh(const SurfaceMesh& mesh);

// Topology of a closed triangle surface: connected components and total genus
// from Euler's formula, sum over components of (2 - chi) / 2.
struct SurfaceTopology {
  int components = 0;
  int genus = 0;
};
SurfaceTopology surface_topology(const TriMesh& mesh);

// Enclosed volume by the divergence theorem (positive for outward orientation).
double enclosed_volume(const TriMesh& mesh);

}  // namespace igaprep::mesh::detail
