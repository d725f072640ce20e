#include "igaprep/spline/scaled_jacobian.h"

#include <Eigen/LU>
#include <algorithm>

namespace igaprep::spline {

bool degenerate_jacobian(const Eigen::Matrix3d& J) {
  if (!J.allFinite()) return true;
  const double a = J.col(0).norm(), b = J.col(1).norm(), c = J.col(2).norm();
  return !(std::min({a, b, c}) > 1e-9 * std::max({a, b, c}));  // also true when all three vanish
}

double scaled_jacobian(const Eigen::Matrix3d& J) {
  if (degenerate_jacobian(J)) return 0.0;
  return J.determinant() / (J.col(0).norm() * J.col(1).norm() * J.col(2).norm());
}

}  // namespace igaprep::spline
