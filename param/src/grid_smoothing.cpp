#include "igaprep/param/grid_smoothing.h"

#include <algorithm>
#include <string>

#include <Eigen/Dense>

#include "igaprep/core/error.h"

namespace igaprep::param {

namespace {

// t (1 - t) P_a(2t - 1), a = 0..count-1 (Legendre polynomials: a well
// conditioned basis of the bubbles that vanish at both ends).
Eigen::VectorXd bubbles(double t, int count) {
  Eigen::VectorXd b(count);
  const double x = 2.0 * t - 1.0, w = t * (1.0 - t);
  double prev = 1.0, cur = x;
  for (int a = 0; a < count; ++a) {
    if (a == 0) b(a) = w;
    else if (a == 1) b(a) = w * x;
    else {
      const double next = ((2.0 * a - 1.0) * x * cur - (a - 1.0) * prev) / a;
      prev = cur;
      cur = next;
      b(a) = w * cur;
    }
  }
  return b;
}

void check_inputs(std::size_t points, std::size_t expected, const std::vector<double>& params, int degree,
                  const char* what) {
  if (params.size() < 3 || params.front() != 0.0 || params.back() != 1.0)
    throw bad_input(std::string(what) + ": need at least 3 parameters from 0 to 1");
  for (std::size_t k = 1; k < params.size(); ++k)
    if (!(params[k] > params[k - 1])) throw bad_input(std::string(what) + ": the parameters are not ascending");
  if (points != expected)
    throw bad_input(std::string(what) + ": " + std::to_string(points) + " points for " + std::to_string(params.size()) +
                    " parameters (expected " + std::to_string(expected) + ")");
  if (degree < 2) throw bad_input(std::string(what) + ": degree must be at least 2, got " + std::to_string(degree));
}

// How much of its sample a side keeps at parameter t: (1 - d / share)^2 at
// distance d below share from a kept end (ends: t = 0, t = 1), else none.
double end_weight(double t, const std::array<bool, 2>& ends, double share) {
  const double d = std::min(ends[0] ? t : 1.0, ends[1] ? 1.0 - t : 1.0);
  if (!(d < share)) return 0.0;
  const double r = 1.0 - d / share;
  return r * r;
}

}  // namespace

std::vector<Eigen::Vector3d> smooth_polyline(const std::vector<Eigen::Vector3d>& points,
                                             const std::vector<double>& params, int degree) {
  check_inputs(points.size(), params.size(), params, degree, "smooth_polyline");
  const int m = static_cast<int>(params.size());
  const int nb = std::min(degree - 1, m - 2);  // never more unknowns than inner samples
  const Eigen::Vector3d p0 = points.front(), p1 = points.back();
  Eigen::MatrixXd A(m - 2, nb), rhs(m - 2, 3);
  for (int k = 1; k + 1 < m; ++k) {
    const double t = params[static_cast<std::size_t>(k)];
    A.row(k - 1) = bubbles(t, nb).transpose();
    rhs.row(k - 1) = (points[static_cast<std::size_t>(k)] - ((1.0 - t) * p0 + t * p1)).transpose();
  }
  const Eigen::MatrixXd c = A.colPivHouseholderQr().solve(rhs);
  std::vector<Eigen::Vector3d> out(points.size());
  out.front() = p0;
  out.back() = p1;
  for (int k = 1; k + 1 < m; ++k) {
    const double t = params[static_cast<std::size_t>(k)];
    out[static_cast<std::size_t>(k)] = (1.0 - t) * p0 + t * p1 + (bubbles(t, nb).transpose() * c).transpose();
  }
  return out;
}

std::vector<Eigen::Vector3d> smooth_grid(const std::vector<Eigen::Vector3d>& grid, const std::vector<double>& params,
                                         int degree, const KeptCorners& kept) {
  check_inputs(grid.size(), params.size() * params.size(), params, degree, "smooth_grid");
  if (!(kept.end_share >= 0.0 && kept.end_share <= 0.5))
    throw bad_input("smooth_grid: end_share must be between 0 and 0.5, got " + std::to_string(kept.end_share));
  const int m = static_cast<int>(params.size());
  auto at = [&](int i, int j) { return static_cast<std::size_t>(i + m * j); };
  std::vector<Eigen::Vector3d> out(grid.size());
  // The four sides, each from its own samples in increasing index order,
  // with the flags of the corners at its start and its end.
  auto side = [&](auto index, int start, int end) {
    std::vector<Eigen::Vector3d> s(static_cast<std::size_t>(m));
    for (int k = 0; k < m; ++k) s[static_cast<std::size_t>(k)] = grid[index(k)];
    const std::vector<Eigen::Vector3d> smooth = smooth_polyline(s, params, degree);
    const std::array<bool, 2> ends{{kept.corners[static_cast<std::size_t>(start)], kept.corners[static_cast<std::size_t>(end)]}};
    for (int k = 0; k < m; ++k) {
      const double w = end_weight(params[static_cast<std::size_t>(k)], ends, kept.end_share);
      out[index(k)] = w == 0.0 ? smooth[static_cast<std::size_t>(k)]
                               : Eigen::Vector3d((1.0 - w) * smooth[static_cast<std::size_t>(k)] + w * s[static_cast<std::size_t>(k)]);
    }
  };
  side([&](int k) { return at(k, 0); }, 0, 1);
  side([&](int k) { return at(k, m - 1); }, 2, 3);
  side([&](int k) { return at(0, k); }, 0, 2);
  side([&](int k) { return at(m - 1, k); }, 1, 3);
  // Coons patch of the smoothed sides: exact on the sides.
  auto coons = [&](int i, int j) {
    const double s = params[static_cast<std::size_t>(i)], t = params[static_cast<std::size_t>(j)];
    return Eigen::Vector3d((1.0 - t) * out[at(i, 0)] + t * out[at(i, m - 1)] + (1.0 - s) * out[at(0, j)] +
                           s * out[at(m - 1, j)] -
                           ((1.0 - s) * (1.0 - t) * out[at(0, 0)] + s * (1.0 - t) * out[at(m - 1, 0)] +
                            (1.0 - s) * t * out[at(0, m - 1)] + s * t * out[at(m - 1, m - 1)]));
  };
  const int nb = std::min(degree - 1, m - 2);
  const int inner = (m - 2) * (m - 2);
  Eigen::MatrixXd A(inner, nb * nb), rhs(inner, 3);
  std::vector<Eigen::VectorXd> b(static_cast<std::size_t>(m));
  for (int k = 0; k < m; ++k) b[static_cast<std::size_t>(k)] = bubbles(params[static_cast<std::size_t>(k)], nb);
  int row = 0;
  for (int j = 1; j + 1 < m; ++j)
    for (int i = 1; i + 1 < m; ++i, ++row) {
      for (int bj = 0; bj < nb; ++bj)
        for (int bi = 0; bi < nb; ++bi) A(row, bi + nb * bj) = b[static_cast<std::size_t>(i)](bi) * b[static_cast<std::size_t>(j)](bj);
      rhs.row(row) = (grid[at(i, j)] - coons(i, j)).transpose();
    }
  const Eigen::MatrixXd c = A.colPivHouseholderQr().solve(rhs);
  row = 0;
  for (int j = 1; j + 1 < m; ++j)
    for (int i = 1; i + 1 < m; ++i, ++row) out[at(i, j)] = coons(i, j) + (A.row(row) * c).transpose();
  return out;
}

}  // namespace igaprep::param
