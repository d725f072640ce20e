#pragma once
// The scaled Jacobian of a volume parameterization at a point: det J over
// the product of the lengths of J's columns (the derivatives along u, v, w).
// 1 for orthogonal columns, <= 0 where the map folds. One definition for
// the step that raises it (optimize_jacobian.h) and the check that reports
// it (iga_check/quality_metrics.h), so both speak of the same number.
#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace igaprep::spline {

// Inputs: J, column d = d x / d u_d; the value to give where J is degenerate
// (below). Output: det J / (|x_u| |x_v| |x_w|), in [-1, 1], or that value.
// Inline: the repairs call it for every sample of every trial step.
inline double scaled_jacobian_or(const Eigen::Matrix3d& J, double if_degenerate) {
  if (!J.allFinite()) return if_degenerate;
  const double a = J.col(0).norm(), b = J.col(1).norm(), c = J.col(2).norm();
  if (!(std::min({a, b, c}) > 1e-9 * std::max({a, b, c}))) return if_degenerate;  // also when all three vanish
  return J.determinant() / (a * b * c);
}

// Whether a column of J (nearly) vanishes: shorter than 1e-9 times the
// longest, or J not finite. There the map is degenerate (e.g. on a side
// collapsed to a curve or a point), and det J / (|x_u| |x_v| |x_w|) would be
// round-off divided by round-off, anywhere in [-1, 1].
inline bool degenerate_jacobian(const Eigen::Matrix3d& J) { return std::isnan(scaled_jacobian_or(J, NAN)); }

// det J / (|x_u| |x_v| |x_w|); 0 where degenerate_jacobian(J): degenerate,
// neither folded nor fine.
inline double scaled_jacobian(const Eigen::Matrix3d& J) { return scaled_jacobian_or(J, 0.0); }

}  // namespace igaprep::spline
