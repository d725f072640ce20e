#include "igaprep/spline/fit_model_surface.h"

#include <Eigen/IterativeLinearSolvers>
#include <algorithm>

#include "igaprep/core/error.h"
#include "igaprep/spline/knot_vector.h"
#include "model_points.h"

namespace igaprep::spline {

using namespace detail;

void carry_moves_inside(MultiPatch& mp, const MultiPatch& before, const std::vector<std::pair<int, Side>>& fixed_sides) {
  const GlobalNumbering gn = global_numbering(mp);
  std::vector<char> all(static_cast<size_t>(gn.count), 1), held(static_cast<size_t>(gn.count), 0);
  mark_faces(mp, gn, faces_of(mp, [](int) { return true; }), held);
  mark_faces(mp, gn, fixed_sides, held);
  const Columns c = free_columns(all, held);
  if (c.point.empty()) return;
  const Eigen::MatrixXd X = global_points(mp, gn), move = X - global_points(before, gn);
  // The graph Laplacian of the patches' control nets, free rows: deg m_v - sum of neighbours' m.
  std::vector<std::pair<int, int>> edges;
  for (size_t p = 0; p < mp.patches.size(); ++p) {
    const Patch& P = mp.patches[p];
    const std::array<int, 3> n{{basis_count(P.knots[0], P.degrees[0]), basis_count(P.knots[1], P.degrees[1]),
                                basis_count(P.knots[2], P.degrees[2])}};
    const std::array<int, 3> stride{{1, n[0], n[0] * n[1]}};
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          const std::array<int, 3> at{{i, j, k}};
          const int l = i + stride[1] * j + stride[2] * k;
          for (int d = 0; d < 3; ++d)
            if (at[d] + 1 < n[d])
              edges.emplace_back(std::minmax(gn.global[p][static_cast<size_t>(l)], gn.global[p][static_cast<size_t>(l + stride[d])]));
        }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const int n = static_cast<int>(c.point.size());
  std::vector<Eigen::Triplet<double>> t;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  auto add = [&](int from, int to) {
    const int row = c.of_point[static_cast<size_t>(from)];
    if (row < 0) return;
    t.emplace_back(row, row, 1.0);
    const int col = c.of_point[static_cast<size_t>(to)];
    if (col >= 0)
      t.emplace_back(row, col, -1.0);
    else
      rhs.row(row) += move.row(to);
  };
  for (const auto& [a, b] : edges) {
    add(a, b);
    add(b, a);
  }
  // A free part with no held point in reach has no move to follow: a tiny
  // diagonal term keeps it where it is.
  for (int k = 0; k < n; ++k) t.emplace_back(k, k, 1e-12);
  Sparse K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper> cg(K);
  cg.setTolerance(1e-10);
  cg.setMaxIterations(10 * n);
  const Eigen::MatrixXd m = cg.solve(rhs);
  if (cg.info() != Eigen::Success) throw internal_error("carry_moves_inside: conjugate gradients did not converge");
  Eigen::MatrixXd Xn = X;
  for (int k = 0; k < n; ++k) Xn.row(c.point[static_cast<size_t>(k)]) += m.row(k);
  scatter(Xn, gn, mp);
}

}  // namespace igaprep::spline
