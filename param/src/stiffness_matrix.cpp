#include "igaprep/param/stiffness_matrix.h"

#include <algorithm>
#include <vector>

#include "cell_geometry.h"
#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"

namespace igaprep::param {
namespace {

// Index of the local pair (a, b), a != b, among the K(K-1)/2 pairs of a cell.
template <int K>
constexpr int pair_index(int a, int b) {
  if (a > b) std::swap(a, b);
  if constexpr (K == 4) {
    constexpr int table[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
    return table[a][b];
  } else {
    return a + b - 1;  // (0,1)->0, (0,2)->1, (1,2)->2
  }
}

// Local off-diagonal entries |cell| grad phi_a . grad phi_b for cells [begin, end).
// Returns the first degenerate cell in the range or -1.
template <int K>
Eigen::Index local_entries(const Eigen::MatrixXd& V, const Eigen::MatrixXi& C, Eigen::Index begin, Eigen::Index end,
                           double* out) {
  constexpr int P = K * (K - 1) / 2;
  for (Eigen::Index c = begin; c < end; ++c) {
    Eigen::Matrix<double, K, 3> gp;
    const double m = std::abs(detail::cell_grad_phi(V, C, c, gp));
    if (m == 0.0) return c;
    double* o = out + P * c;
    for (int a = 0; a < K; ++a)
      for (int b = a + 1; b < K; ++b) o[pair_index<K>(a, b)] = m * gp.row(a).dot(gp.row(b));
  }
  return -1;
}

// Compressed-column assembly without triplets: the local entries are computed
// once per cell (two threads), then each column j is summed over the cells
// around vertex j with a marker array, so every output entry is written once.
template <int K>
Eigen::SparseMatrix<double> assemble(const Eigen::MatrixXd& V, const Eigen::MatrixXi& C, const char* who) {
  constexpr int P = K * (K - 1) / 2;
  detail::check_cells(V, C, who);
  const Eigen::Index n = V.rows(), m = C.rows();
  std::vector<double> local(static_cast<size_t>(P * m));
  {
    Eigen::Index bad[2] = {-1, -1};
    const Eigen::Index half = m / 2;
    parallel_for(2, [&](std::size_t t) {
      bad[t] = t == 0 ? local_entries<K>(V, C, 0, half, local.data()) : local_entries<K>(V, C, half, m, local.data());
    });
    for (Eigen::Index b : bad)
      if (b >= 0) detail::throw_degenerate(who, b, K);
  }
  // Vertex -> (cell * K + local index) incidence in compressed form.
  std::vector<int> start(n + 1, 0);
  for (Eigen::Index c = 0; c < m; ++c)
    for (int k = 0; k < K; ++k) ++start[C(c, k) + 1];
  for (Eigen::Index i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<int> inc(start[n]);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (Eigen::Index c = 0; c < m; ++c)
      for (int k = 0; k < K; ++k) inc[fill[C(c, k)]++] = static_cast<int>(c * K + k);
  }
  std::vector<int> outer(n + 1, 0);
  std::vector<int> inner;
  std::vector<double> values;
  inner.reserve(static_cast<size_t>(start[n]) * 2 / (K - 1) + n);  // rough: ~(valence + 1) per column
  values.reserve(inner.capacity());
  std::vector<int> mark(n, -1);
  std::vector<double> acc(n, 0.0);
  std::vector<int> rows;
  for (Eigen::Index j = 0; j < n; ++j) {
    rows.clear();
    double diag = 0.0;
    for (int s = start[j]; s < start[j + 1]; ++s) {
      const int c = inc[s] / K, kj = inc[s] % K;
      const double* o = local.data() + static_cast<size_t>(P) * c;
      for (int k = 0; k < K; ++k) {
        if (k == kj) continue;
        const int i = C(c, k);
        const double w = o[pair_index<K>(k, kj)];
        if (mark[i] != j) {
          mark[i] = static_cast<int>(j);
          acc[i] = w;
          rows.push_back(i);
        } else {
          acc[i] += w;
        }
        diag -= w;  // rows sum to zero exactly: constants stay in the kernel
      }
    }
    if (start[j + 1] > start[j]) rows.push_back(static_cast<int>(j));
    std::sort(rows.begin(), rows.end());
    for (int i : rows) {
      inner.push_back(i);
      values.push_back(i == j ? diag : acc[i]);
    }
    outer[j + 1] = static_cast<int>(inner.size());
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), A.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), A.innerIndexPtr());
  std::copy(values.begin(), values.end(), A.valuePtr());
  return A;
}

}  // namespace

Eigen::SparseMatrix<double> tet_stiffness(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T) {
  if (T.cols() != 4) throw bad_input("tet_stiffness: tets must have 4 columns");
  return assemble<4>(V, T, "tet_stiffness");
}

Eigen::SparseMatrix<double> tri_cotan_laplacian(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  if (F.cols() != 3) throw bad_input("tri_cotan_laplacian: triangles must have 3 columns");
  return assemble<3>(V, F, "tri_cotan_laplacian");
}

Eigen::SparseMatrix<double> stiffness_matrix(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells) {
  if (cells.cols() == 4) return tet_stiffness(V, cells);
  return tri_cotan_laplacian(V, cells);
}

}  // namespace igaprep::param
