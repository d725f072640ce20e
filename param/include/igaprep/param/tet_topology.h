#pragma once
// Cell adjacency of a tet mesh (or of a triangle surface), built once and
// reused by every gradient trace: the neighbour across each facet and the
// cells around each vertex.
#include <vector>

#include <Eigen/Core>

namespace igaprep::param {

struct TetTopology {
  int cell_size = 4;               // 4 for tets, 3 for triangles
  Eigen::MatrixXi neighbor;        // #C x cell_size: cell across the facet opposite local vertex i, -1 on the boundary
  Eigen::MatrixXi neighbor_facet;  // #C x cell_size: that facet's local index in the neighbour, -1 on the boundary
  std::vector<int> vertex_cells_start;  // #V + 1 offsets into vertex_cells
  std::vector<int> vertex_cells;        // cells around each vertex, ascending
};

// Inputs: cells (#C x 4 tets or #C x 3 triangles); num_vertices (#V).
// Output: the adjacency. Facet i of a cell is the cell without its local
// vertex i. Throws bad_input naming the cells when a facet is shared by more
// than two cells (non-manifold) or a vertex index is out of range.
TetTopology build_tet_topology(const Eigen::MatrixXi& cells, Eigen::Index num_vertices);

// Per-facet target marks for gradient tracing: Inputs: cells, topology,
// facets (#F x 3 vertex triples for tets, #F x 2 vertex pairs for triangles).
// Output: #C * cell_size entries, entry c * cell_size + i = row of `facets`
// that is facet i of cell c, or -1. Throws bad_input naming the row of a
// facet that is no facet of any cell.
std::vector<int> mark_facets(const Eigen::MatrixXi& cells, const TetTopology& topology, const Eigen::MatrixXi& facets);

// The tet holding point p: a visibility walk from `hint` (tet 0 when hint is
// -1) through the neighbours, then a scan of all tets (bounding boxes first)
// when the walk cycles (flat tets, non-Delaunay meshes) or, with
// scan_when_walk_leaves, when it leaves the mesh (a walk from far away can
// leave a non-convex mesh). Returns -1 when no tet holds p (or the walk left
// the mesh and the scan was not asked for); *bary receives p's barycentric
// coordinates (clamped to >= 0, normalized).
int locate_in_tets(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const TetTopology& topology,
                   const Eigen::Vector3d& p, int hint, Eigen::Vector4d* bary, bool scan_when_walk_leaves = true);

}  // namespace igaprep::param
