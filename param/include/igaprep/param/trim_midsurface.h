#pragma once
// M0trim = M0 inside the innermost surface Tn (seed paper, section 4.2).
// Every triangle of M0 lies in one tet and Tn is a union of tet faces, so the
// part inside Tn is exactly the triangles in tets of the innermost material:
// no triangle crosses Tn, and the boundary of M0trim lies on Tn's faces.
#include <Eigen/Core>

#include "igaprep/mesh/tet_mesh.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/midsurface.h"

namespace igaprep::param {

struct TrimmedSheet {
  mesh::TriMesh mesh;          // M0trim, oriented like M0
  Eigen::VectorXi m0_vertex;   // #V: index of each vertex in M0
  Eigen::VectorXi m0_face;     // #F: index of each face in M0
  std::vector<std::vector<int>> boundary_loops;
};

// Inputs: tets (its `material`), M0, the innermost material index (n - 1 for
// n surfaces; every tet has material n - 1 when n = 1, so M0trim = M0),
// expected_loops = g + 1. Output: M0trim. Throws bad_input when it is empty
// or not a single sheet (one piece, no handles) with expected_loops boundary
// loops, saying which.
TrimmedSheet trim_midsurface(const mesh::TetMesh& tets, const Midsurface& m0, int innermost_material,
                             int expected_loops);

}  // namespace igaprep::param
