// The scaled Jacobian shared by optimize_jacobians and the check: its value
// on regular, folded and degenerate Jacobians.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "igaprep/spline/scaled_jacobian.h"

using igaprep::spline::degenerate_jacobian;
using igaprep::spline::scaled_jacobian;

TEST(ScaledJacobian, OrthogonalShearedAndFolded) {
  Eigen::Matrix3d J = Eigen::Vector3d(2.0, 3.0, 0.5).asDiagonal();
  EXPECT_DOUBLE_EQ(scaled_jacobian(J), 1.0);  // column lengths do not matter
  J(0, 1) = 3.0;                               // x_v at 45 degrees to x_u
  EXPECT_NEAR(scaled_jacobian(J), std::sqrt(0.5), 1e-15);
  J.col(2) *= -1.0;  // folded
  EXPECT_NEAR(scaled_jacobian(J), -std::sqrt(0.5), 1e-15);
  EXPECT_FALSE(degenerate_jacobian(J));
}

// A column that vanishes (a collapsed side) or is round-off next to the
// others: degenerate, scaled Jacobian 0, not the sign of the round-off.
TEST(ScaledJacobian, VanishingColumnIsDegenerateWithZero) {
  Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
  J.col(2).setZero();
  EXPECT_TRUE(degenerate_jacobian(J));
  EXPECT_EQ(scaled_jacobian(J), 0.0);
  J.col(2) = Eigen::Vector3d(0.0, 1e-17, -1e-17);  // round-off: det < 0, det / lengths = -0.7
  EXPECT_TRUE(degenerate_jacobian(J));
  EXPECT_EQ(scaled_jacobian(J), 0.0);
  J.col(2) = Eigen::Vector3d(0.0, 0.0, 1e-8);  // short, but 1e8 above round-off: a real column
  EXPECT_FALSE(degenerate_jacobian(J));
  EXPECT_DOUBLE_EQ(scaled_jacobian(J), 1.0);
  J(0, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(degenerate_jacobian(J));
  EXPECT_EQ(scaled_jacobian(J), 0.0);
}
