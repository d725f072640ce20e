#pragma once
// The tet mesh H of the decomposition (seed paper, section 5.1): T1 with the
// material boundaries T2..Tn and the base surface M all kept as tet faces, so
// that the w-field can be pinned on each of them.
#include <utility>
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
  int chords_split = 0;  // edges split by split_surface_chords
  int flat_tets = 0;     // tets with all four vertices on one surface (count_flat_tets)
};

// H vertex of vertex i of surface k (k = n: M).
inline int decomposition_vertex(const DecompositionMesh& H, int surface, int i) {
  return H.surface_vertex_offset[static_cast<std::size_t>(surface)] + i;
}

// Inputs: T (#T x 4), faces (#F x 3) vertex triples. Output: the rows of
// `faces` that are no face of any tet (any vertex order), ascending.
std::vector<int> faces_not_in_tets(const Eigen::MatrixXi& T, const Eigen::MatrixXi& faces);

// Vertex labels of H: the surface k (0..n, n = M) a vertex belongs to, -1
// for TetGen's Steiner points.
std::vector<int> vertex_surfaces(const DecompositionMesh& H);

// The edges of each surface's marked faces (0..n), as sorted vertex pairs.
std::vector<std::vector<std::pair<int, int>>> surface_edges(const DecompositionMesh& H);

// Tets whose four vertices lie on one surface: w is constant on them (a flat
// spot of the w-field where a gradient trace stalls; on torus3 some boundary
// vertices of M have only such tets around them).
int count_flat_tets(const Eigen::MatrixXi& T, const std::vector<int>& vertex_surface);

// Splits at its midpoint every tet edge whose two ends lie on one surface k
// but that is no edge of that surface (a chord through the volume; `edges`
// lists each surface's edges, sorted pairs). The new vertices are
// appended to V (label -1), each tet around a chord is halved (orientation
// and material kept); marked faces are unaffected (a chord is no edge of any
// surface triangle). Returns the number of edges split. A tet whose six
// edges are all surface edges (three faces on a sheet around a valence-3
// vertex) has no chord and stays flat.
int split_surface_chords(mesh::TetMesh& H, std::vector<int>& vertex_surface,
                         const std::vector<std::vector<std::pair<int, int>>>& edges);

// Inputs: surfaces T1..Tn (validated, nested, outward), base surface M
// (strictly inside Tn), TetGen options. Output: H. Throws bad_input when the
// surfaces cannot be meshed together (e.g. M touches Tn) and check_failed
// when one of M's triangles is not a tet face of the result. With
// split_chords the surface chords are split (split_surface_chords) so that w
// has no flat tets; off by default: the midpoints make slivers that break the
// discrete maximum principle where M comes close to T1 (torus3: 4 interior
// maxima up to w = 1.002, none without the split), which matters more than
// the few traces that start in a flat spot (docs/decomposition.md).
DecompositionMesh decomposition_mesh(const std::vector<mesh::TriMesh>& surfaces, const mesh::TriMesh& M,
                                     const mesh::TetgenOptions& options = {}, bool split_chords = false);

}  // namespace igaprep::param
