#include "igaprep/param/maximum_principle.h"

#include <algorithm>
#include <limits>
#include <string>

#include "igaprep/core/error.h"

namespace igaprep::param {

std::vector<LocalExtremum> find_interior_extrema(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& u,
                                                 const std::vector<char>& is_dirichlet, double tolerance) {
  const Eigen::Index n = K.cols();
  if (u.size() != n || static_cast<Eigen::Index>(is_dirichlet.size()) != n)
    throw bad_input("find_interior_extrema: field (" + std::to_string(u.size()) + ") and Dirichlet flags (" +
                    std::to_string(is_dirichlet.size()) + ") must have one entry per vertex (" +
                    std::to_string(n) + ")");
  std::vector<LocalExtremum> out;
  if (n == 0) return out;
  const double tol = tolerance * (u.maxCoeff() - u.minCoeff());
  for (Eigen::Index j = 0; j < n; ++j) {
    if (is_dirichlet[j]) continue;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    int count = 0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it) {
      if (it.index() == j) continue;
      lo = std::min(lo, u(it.index()));
      hi = std::max(hi, u(it.index()));
      ++count;
    }
    if (count == 0) continue;
    if (u(j) - hi > tol) out.push_back({static_cast<int>(j), true, u(j) - hi});
    else if (lo - u(j) > tol) out.push_back({static_cast<int>(j), false, lo - u(j)});
  }
  return out;
}

int flatten_interior_extrema(const Eigen::SparseMatrix<double>& K, Eigen::VectorXd& u,
                             const std::vector<char>& is_dirichlet, double tolerance, int max_rounds) {
  int changed = 0;
  for (int round = 0; round < max_rounds; ++round) {
    const std::vector<LocalExtremum> extrema = find_interior_extrema(K, u, is_dirichlet, tolerance);
    if (extrema.empty()) break;
    for (const LocalExtremum& e : extrema) {
      double sum = 0.0;
      int count = 0;
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, e.vertex); it; ++it)
        if (it.index() != e.vertex) sum += u(it.index()), ++count;
      u(e.vertex) = sum / count;
      ++changed;
    }
  }
  return changed;
}

}  // namespace igaprep::param
