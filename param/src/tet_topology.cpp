#include "igaprep/param/tet_topology.h"

#include <algorithm>
#include <string>

#include "igaprep/core/error.h"

namespace igaprep::param {
namespace {

// Local index of vertex v in cell c, -1 if absent.
inline int local_index(const Eigen::MatrixXi& C, int c, int v) {
  for (int k = 0; k < C.cols(); ++k)
    if (C(c, k) == v) return k;
  return -1;
}

// Cell other than `self` that holds all vertices f[0..nf); its missing local vertex in `facet`.
// Returns the number of such cells (2+ means non-manifold); `found` the first.
int find_facet_cells(const Eigen::MatrixXi& C, const TetTopology& topo, const int* f, int nf, int self, int& found,
                     int& facet) {
  // Walk the smallest star among the facet's vertices.
  int best = f[0];
  for (int k = 1; k < nf; ++k)
    if (topo.vertex_cells_start[f[k] + 1] - topo.vertex_cells_start[f[k]] <
        topo.vertex_cells_start[best + 1] - topo.vertex_cells_start[best])
      best = f[k];
  int count = 0;
  found = -1;
  facet = -1;
  for (int s = topo.vertex_cells_start[best]; s < topo.vertex_cells_start[best + 1]; ++s) {
    const int d = topo.vertex_cells[s];
    if (d == self) continue;
    bool all = true;
    for (int k = 0; k < nf && all; ++k) all = local_index(C, d, f[k]) >= 0;
    if (!all) continue;
    if (count++ == 0) {
      found = d;
      int used = 0;
      for (int k = 0; k < nf; ++k) used |= 1 << local_index(C, d, f[k]);
      for (int k = 0; k < C.cols(); ++k)
        if (!(used & (1 << k))) facet = k;
    }
  }
  return count;
}

}  // namespace

TetTopology build_tet_topology(const Eigen::MatrixXi& C, Eigen::Index nv) {
  if (C.cols() != 3 && C.cols() != 4)
    throw bad_input("build_tet_topology: cells must have 3 or 4 columns, got " + std::to_string(C.cols()));
  const int K = static_cast<int>(C.cols());
  const int m = static_cast<int>(C.rows());
  TetTopology topo;
  topo.cell_size = K;
  topo.vertex_cells_start.assign(nv + 1, 0);
  for (int c = 0; c < m; ++c)
    for (int k = 0; k < K; ++k) {
      if (C(c, k) < 0 || C(c, k) >= nv)
        throw bad_input("build_tet_topology: cell " + std::to_string(c) + " references vertex " +
                        std::to_string(C(c, k)) + ", but there are " + std::to_string(nv) + " vertices");
      ++topo.vertex_cells_start[C(c, k) + 1];
    }
  for (Eigen::Index i = 0; i < nv; ++i) topo.vertex_cells_start[i + 1] += topo.vertex_cells_start[i];
  topo.vertex_cells.resize(topo.vertex_cells_start[nv]);
  {
    std::vector<int> fill(topo.vertex_cells_start.begin(), topo.vertex_cells_start.end() - 1);
    for (int c = 0; c < m; ++c)  // cells in ascending order, so each list is sorted
      for (int k = 0; k < K; ++k) topo.vertex_cells[fill[C(c, k)]++] = c;
  }
  topo.neighbor.setConstant(m, K, -2);  // -2: not yet looked up
  topo.neighbor_facet.setConstant(m, K, -1);
  int f[3];
  for (int c = 0; c < m; ++c)
    for (int i = 0; i < K; ++i) {
      if (topo.neighbor(c, i) != -2) continue;
      int nf = 0;
      for (int k = 0; k < K; ++k)
        if (k != i) f[nf++] = C(c, k);
      int d, j;
      const int count = find_facet_cells(C, topo, f, nf, c, d, j);
      if (count > 1)
        throw bad_input("build_tet_topology: the facet opposite local vertex " + std::to_string(i) + " of cell " +
                        std::to_string(c) + " is shared by " + std::to_string(count + 1) +
                        " cells (non-manifold mesh)");
      topo.neighbor(c, i) = d;
      if (d >= 0) {
        topo.neighbor_facet(c, i) = j;
        topo.neighbor(d, j) = c;
        topo.neighbor_facet(d, j) = i;
      }
    }
  return topo;
}

std::vector<int> mark_facets(const Eigen::MatrixXi& C, const TetTopology& topo, const Eigen::MatrixXi& F) {
  const int K = static_cast<int>(C.cols());
  if (F.rows() > 0 && F.cols() != K - 1)
    throw bad_input("mark_facets: facets must have " + std::to_string(K - 1) + " columns, got " +
                    std::to_string(F.cols()));
  std::vector<int> marks(static_cast<size_t>(C.rows()) * K, -1);
  const Eigen::Index nv = static_cast<Eigen::Index>(topo.vertex_cells_start.size()) - 1;
  int f[3];
  for (Eigen::Index r = 0; r < F.rows(); ++r) {
    for (int k = 0; k < K - 1; ++k) {
      f[k] = F(r, k);
      if (f[k] < 0 || f[k] >= nv)
        throw bad_input("mark_facets: facet " + std::to_string(r) + " references vertex " + std::to_string(f[k]) +
                        ", but there are " + std::to_string(nv) + " vertices");
    }
    // Every cell holding the facet gets the mark (both sides of an interior facet).
    int d, j;
    const bool found = find_facet_cells(C, topo, f, K - 1, -1, d, j) > 0;
    if (found) {
      marks[static_cast<size_t>(d) * K + j] = static_cast<int>(r);
      const int n = topo.neighbor(d, j);
      if (n >= 0) marks[static_cast<size_t>(n) * K + topo.neighbor_facet(d, j)] = static_cast<int>(r);
    }
    if (!found)
      throw bad_input("mark_facets: facet " + std::to_string(r) + " (" + std::to_string(f[0]) + ", " +
                      std::to_string(f[1]) + (K == 4 ? ", " + std::to_string(f[2]) : std::string()) +
                      ") is not a facet of any cell");
  }
  return marks;
}

}  // namespace igaprep::param
