#pragma once
// The tet mesh H of the decomposition (seed paper, section 5.1): T1 with the
// material boundaries T2..Tn and the base surface M all kept as tet faces, so
// that the w-field can be pinned on each of them.
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tet_mesh.h"
#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param {

struct DecompositionMesh {
  mesh::TetMesh tets;  // H; F_marker k < n for T(k+1), n for M
  int num_surfaces = 0;  // n
  // n + 2 entries: the vertices of T(k+1) are H vertices
  // surface_vertex_offset[k] .. surface_vertex_offset[k+1] - 1 (same order as
  // the input surface), those of M follow (k = n); TetGen's Steiner points
  // come after surface_vertex_offset[n+1].
  std::vector<int> surface_vertex_offset;
  Eigen::MatrixXi base_faces;  // #M.F x 3: M's triangles in H vertex indices
  std::vector<std::vector<int>> surface_faces;  // per marker (0..n): rows of tets.F
};

// H vertex of vertex i of surface k (k = n: M).
inline int decomposition_vertex(const DecompositionMesh& H, int surface, int i) {
  return H.surface_vertex_offset[static_cast<std::size_t>(surface)] + i;
}

// Inputs: T (#T x 4), faces (#F x 3) vertex triples. Output: the rows of
// `faces` that are no face of any tet (any vertex order), ascending.
std::vector<int> faces_not_in_tets(const Eigen::MatrixXi& T, const Eigen::MatrixXi& faces);

// Inputs: surfaces T1..Tn (validated, nested, outward), base surface M
// (strictly inside Tn), TetGen options. Output: H. Throws bad_input when the
// surfaces cannot be meshed together (e.g. M touches Tn) and check_failed
// when one of M's triangles is not a tet face of the result.
DecompositionMesh decomposition_mesh(const std::vector<mesh::TriMesh>& surfaces, const mesh::TriMesh& M,
                                     const mesh::TetgenOptions& options = {});

}  // namespace igaprep::param
