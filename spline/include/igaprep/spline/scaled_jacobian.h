#pragma once
// The scaled Jacobian of a volume parameterization at a point: det J over
// the product of the lengths of J's columns (the derivatives along u, v, w).
// 1 for orthogonal columns, <= 0 where the map folds. One definition for
// the step that raises it (optimize_jacobian.h) and the check that reports
// it (iga_check/quality_metrics.h), so both speak of the same number.
#include <Eigen/Core>

namespace igaprep::spline {

// Whether a column of J (nearly) vanishes: shorter than 1e-9 times the
// longest, or J not finite. There the map is degenerate (e.g. on a side
// collapsed to a curve or a point), and det J / (|x_u| |x_v| |x_w|) would be
// round-off divided by round-off, anywhere in [-1, 1].
bool degenerate_jacobian(const Eigen::Matrix3d& J);

// Inputs: J, column d = d x / d u_d.
// Output: det J / (|x_u| |x_v| |x_w|), in [-1, 1]; 0 where
// degenerate_jacobian(J): degenerate, neither folded nor fine.
double scaled_jacobian(const Eigen::Matrix3d& J);

}  // namespace igaprep::spline
