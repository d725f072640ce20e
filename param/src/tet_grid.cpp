#include "tet_grid.h"

#include <algorithm>
#include <cmath>

#include "cell_geometry.h"

namespace igaprep::param::detail {

namespace {

// About this many tets per cell on average (a tet meets a few cells).
constexpr double kTetsPerCell = 2.0;

}  // namespace

TetGrid::TetGrid(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T) : V_(V), T_(T) {
  if (T.rows() == 0 || V.rows() == 0) {
    start_.assign(2, 0);
    return;
  }
  lo_ = V.colwise().minCoeff().transpose();
  const Eigen::Vector3d extent = (V.colwise().maxCoeff().transpose() - lo_).cwiseMax(1e-300);
  // Cells about cubic, their number about the tets' over kTetsPerCell.
  const double edge = std::cbrt(extent.prod() * kTetsPerCell / static_cast<double>(T.rows()));
  for (int d = 0; d < 3; ++d) {
    n_[static_cast<std::size_t>(d)] = std::clamp(static_cast<int>(std::ceil(extent(d) / std::max(edge, 1e-300))), 1, 1024);
    size_(d) = extent(d) / n_[static_cast<std::size_t>(d)];
  }
  std::vector<std::array<int, 6>> range(static_cast<std::size_t>(T.rows()));
  start_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    Eigen::Vector3d a = vrow(V, T(t, 0)), b = a;
    for (int k = 1; k < 4; ++k) a = a.cwiseMin(vrow(V, T(t, k))), b = b.cwiseMax(vrow(V, T(t, k)));
    const std::array<int, 3> ca = cell_of(a), cb = cell_of(b);
    range[static_cast<std::size_t>(t)] = {ca[0], ca[1], ca[2], cb[0], cb[1], cb[2]};
    for (int k = ca[2]; k <= cb[2]; ++k)
      for (int j = ca[1]; j <= cb[1]; ++j)
        for (int i = ca[0]; i <= cb[0]; ++i) ++start_[static_cast<std::size_t>(cell_index({i, j, k})) + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  tets_.resize(static_cast<std::size_t>(start_.back()));
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    const std::array<int, 6>& r = range[static_cast<std::size_t>(t)];
    for (int k = r[2]; k <= r[5]; ++k)
      for (int j = r[1]; j <= r[4]; ++j)
        for (int i = r[0]; i <= r[3]; ++i) tets_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_index({i, j, k}))]++)] = static_cast<int>(t);
  }
}

std::array<int, 3> TetGrid::cell_of(const Eigen::Vector3d& p) const {
  std::array<int, 3> c{};
  for (int d = 0; d < 3; ++d)
    c[static_cast<std::size_t>(d)] = std::clamp(static_cast<int>(std::floor((p(d) - lo_(d)) / size_(d))), 0, n_[static_cast<std::size_t>(d)] - 1);
  return c;
}

int TetGrid::deepest(const Eigen::Vector3d& p, Eigen::Vector4d* bary, double tolerance, bool later_ties) const {
  if (tets_.empty()) return -1;
  const int cell = cell_index(cell_of(p));
  int best = -1;
  double best_min = -tolerance;
  Eigen::Vector4d b, best_b = Eigen::Vector4d::Zero();
  // A cell's tets are in index order (filled so).
  for (int s = start_[static_cast<std::size_t>(cell)]; s < start_[static_cast<std::size_t>(cell) + 1]; ++s) {
    const int t = tets_[static_cast<std::size_t>(s)];
    Eigen::Matrix<double, 4, 3> gp;
    if (cell_grad_phi(V_, T_, t, gp) == 0.0) continue;
    const Eigen::Vector3d r = p - vrow(V_, T_(t, 0));
    for (int k = 1; k < 4; ++k) b(k) = gp.row(k).dot(r);
    b(0) = 1.0 - b(1) - b(2) - b(3);
    if (b.minCoeff() > best_min || (later_ties && b.minCoeff() == best_min)) best_min = b.minCoeff(), best = t, best_b = b;
  }
  if (best >= 0 && bary) *bary = best_b.cwiseMax(0.0) / best_b.cwiseMax(0.0).sum();
  return best;
}

int TetGrid::locate(const Eigen::Vector3d& p, Eigen::Vector4d* bary) const { return deepest(p, bary, 1e-12, true); }

int TetGrid::locate_as_scan(const Eigen::Vector3d& p, Eigen::Vector4d* bary) const {
  return deepest(p, bary, 1e-9, false);
}

}  // namespace igaprep::param::detail
