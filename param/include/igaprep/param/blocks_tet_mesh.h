#pragma once
// The blocks of the volume parameterization (volume_param.h) as one conforming
// tet mesh: every sample cell of every block split into 6 tets, the samples
// shared by neighbouring blocks merged. The decomposition surfaces (S+, S-,
// the corner surfaces, the Ti) are the blocks' faces, so they are real faces
// of this mesh, never staircase unions of tets.
//
// The split (pulling triangulation for one global vertex order): every square
// cell face is cut along its diagonal through its vertex with the smallest
// global index, and a cell is the cone from its smallest vertex over the six
// triangles of its three faces that do not contain that vertex. The face rule
// depends only on the face's four global indices, so two cells sharing a face
// cut it the same way, whichever block they belong to and however their
// parameter directions are permuted or reversed: the mesh is conforming
// wherever neighbouring blocks' face grids coincide sample for sample. Within
// one block (global indices growing with i + m(j + m k)) this is the Kuhn
// split along each cell's diagonal from its (0,0,0) to its (1,1,1) corner.
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tet_mesh.h"
#include "igaprep/param/volume_param.h"

namespace igaprep::param {

// Markers of the faces in tets.F: a block side on the model boundary keeps its
// side_label (0 = T1, ...); a face between blocks of different materials a
// and b gets kInterfaceMarker + max(a, b) (it lies on T(max(a, b) + 1), whose
// 0-based surface index is max(a, b)).
constexpr int kInterfaceMarker = 1000;

struct BlocksTetMesh {
  // V; T positively oriented where the block's map is (its (u, v, w) order);
  // material; F (outward from the tet for boundary faces, as one side's cell
  // face for interfaces) and F_marker as above.
  mesh::TetMesh tets;
  Eigen::VectorXi block;     // per tet: the block it comes from
  Eigen::VectorXi material;  // per tet: the block's material (same as tets.material)
  int merged_points = 0;     // sample points merged with a point of another (earlier) block: shared faces
  int collapsed_points = 0;  // sample points merged with a point of their own block: collapsed sides
  int collapsed_tets = 0;    // tets left out because merged points made them flat (repeated vertex)
  int non_positive_tets = 0; // tets kept with volume <= 0 (folded sample cells)
  int open_faces = 0;        // triangles of one tet only on a side without a label: a gap between blocks
  int nonmanifold_faces = 0; // triangles of more than two tets (overlapping blocks)
};

// Inputs: the blocks (all with the same m >= 2, m^3 x 3 finite samples), the
// merge tolerance (absolute, > 0): samples closer than it become one vertex,
// whichever blocks they belong to (shared faces; the repeated samples of a
// collapsed side). Output: the mesh. Folded cells and collapsed sides do not
// throw: they are counted. Throws bad_input for an empty list, a wrong sample
// count, blocks of different m or a bad tolerance.
BlocksTetMesh blocks_tet_mesh(const std::vector<SampledBlock>& blocks, double merge_tolerance);

}  // namespace igaprep::param
