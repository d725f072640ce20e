// Evaluation of volumes, surfaces and curves: exact circles, derivatives
// against central differences, grid evaluation against single points,
// boundary faces and edges.
#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "spline_test_util.h"

using namespace spline_test;

TEST(SplineEvaluate, NurbsQuarterCircleIsExact) {
  const Curve c = quarter_circle();
  double worst = 0;
  for (int i = 0; i <= 1000; ++i) {
    const double u = i / 1000.0;
    const Eigen::Vector3d x = evaluate_point(c, u);
    worst = std::max(worst, std::abs(x.head<2>().norm() - 1.0));
    EXPECT_EQ(x[2], 0.0);
    // Tangent is orthogonal to the radius.
    const Eigen::Vector3d t = evaluate_tangent(c, u);
    EXPECT_LT(std::abs(t.dot(x)) / t.norm(), 1e-14);
  }
  EXPECT_LT(worst, 1e-14);
  // Grid evaluation gives the same.
  std::vector<double> us;
  for (int i = 0; i <= 100; ++i) us.push_back(i / 100.0);
  const GridEvaluation g = evaluate_grid(c, us, 1);
  for (int i = 0; i <= 100; ++i) EXPECT_LT(std::abs(g.points.row(i).norm() - 1.0), 1e-14);
}

TEST(SplineEvaluate, QuarterAnnulusVolumeIsExact) {
  const Patch P = quarter_annulus();
  std::mt19937 rng(3);
  double worst = 0;
  for (int s = 0; s < 2000; ++s) {
    const Eigen::Vector3d u = random_param(rng, P);
    const Eigen::Vector3d x = evaluate_point(P, u);
    worst = std::max(worst, std::abs(x.head<2>().norm() - (1.0 + u[1])));
    worst = std::max(worst, std::abs(x[2] - u[2]));
  }
  EXPECT_LT(worst, 1e-14);
  // On a grid, and on the boundary faces v0 (unit circle) and v1 (radius 2).
  std::array<std::vector<double>, 3> grid;
  for (int d = 0; d < 3; ++d)
    for (int i = 0; i <= 20; ++i) grid[d].push_back(i / 20.0);
  const GridEvaluation g = evaluate_grid(P, grid, 2);
  worst = 0;
  for (int k = 0, q = 0; k <= 20; ++k)
    for (int j = 0; j <= 20; ++j)
      for (int i = 0; i <= 20; ++i, ++q)
        worst = std::max(worst, std::abs(g.points.row(q).head<2>().norm() - (1.0 + j / 20.0)));
  EXPECT_LT(worst, 1e-14);
  const Surface inner = boundary_surface(P, kV0), outer = boundary_surface(P, kV1);
  for (int i = 0; i <= 50; ++i) {
    const Eigen::Vector2d uv(i / 50.0, 0.3);  // surface dirs (u, w)
    EXPECT_LT(std::abs(evaluate_point(inner, uv).head<2>().norm() - 1.0), 1e-14);
    EXPECT_LT(std::abs(evaluate_point(outer, uv).head<2>().norm() - 2.0), 1e-14);
  }
}

// Derivatives of random (rational) volumes against central differences.
TEST(SplineEvaluate, JacobianAndHessianMatchCentralDifferences) {
  std::mt19937 rng(4);
  double worst1 = 0, worst2 = 0;
  for (bool rational : {false, true})
    for (int trial = 0; trial < 6; ++trial) {
      const int p = 2 + trial % 3;
      const Patch P = random_patch(rng, {{p, p, p - 1}}, {{p + 3, p + 2, p + 2}}, rational);
      for (int s = 0; s < 40; ++s) {
        const Eigen::Vector3d u = random_param(rng, P) * 0.98 + Eigen::Vector3d::Constant(0.01);
        const PointDerivatives D = evaluate_derivatives(P, u, 2);
        EXPECT_LT((D.x - evaluate_point(P, u)).norm(), 1e-14);
        const double h = 1e-6;
        for (int a = 0; a < 3; ++a) {
          Eigen::Vector3d e = Eigen::Vector3d::Zero();
          e[a] = h;
          // Skip when a knot lies within h (derivatives jump there for low continuity).
          bool near_knot = false;
          for (double k : P.knots[a]) near_knot |= std::abs(k - u[a]) < 2 * h;
          if (near_knot) continue;
          const Eigen::Vector3d fd = (evaluate_point(P, u + e) - evaluate_point(P, u - e)) / (2 * h);
          const double s1 = std::max(1.0, D.jacobian.col(a).norm());
          worst1 = std::max(worst1, (fd - D.jacobian.col(a)).norm() / s1);
          const PointDerivatives Dp = evaluate_derivatives(P, u + e, 1);
          const PointDerivatives Dm = evaluate_derivatives(P, u - e, 1);
          const Eigen::Matrix3d fd2 = (Dp.jacobian - Dm.jacobian) / (2 * h);  // (c, b) = d2x_c/du_a du_b
          for (int c = 0; c < 3; ++c) {
            const double s2 = std::max(1.0, D.hessian[c].norm());
            worst2 = std::max(worst2, (fd2.row(c).transpose() - D.hessian[c].col(a)).norm() / s2);
          }
        }
      }
    }
  EXPECT_LT(worst1, 1e-6);
  EXPECT_LT(worst2, 1e-6);
}

TEST(SplineEvaluate, GridMatchesSinglePoints) {
  std::mt19937 rng(5);
  for (bool rational : {false, true}) {
    const Patch P = random_patch(rng, {{3, 2, 1}}, {{7, 5, 4}}, rational, 2);
    std::array<std::vector<double>, 3> grid;
    std::uniform_real_distribution<double> R(0, 1);
    for (int d = 0; d < 3; ++d) {
      grid[d] = {0.0, 1.0};
      for (int i = 0; i < 6; ++i) grid[d].push_back(R(rng));
      for (int i = 2; i < 4; ++i) grid[d].push_back(P.knots[d][P.degrees[d] + 1]);  // on a knot
    }
    const GridEvaluation g = evaluate_grid(P, grid, 2);
    const Eigen::MatrixXd pts = evaluate_grid_points(P, grid_basis(P, grid, 0));
    double worst = 0;
    int q = 0;
    for (double w : grid[2])
      for (double v : grid[1])
        for (double u : grid[0]) {
          const PointDerivatives D = evaluate_derivatives(P, {u, v, w}, 2);
          worst = std::max(worst, (g.points.row(q).transpose() - D.x).norm());
          worst = std::max(worst, (pts.row(q).transpose() - D.x).norm());
          for (int c = 0; c < 3; ++c)
            for (int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(g.jacobians(q, 3 * c + a) - D.jacobian(c, a)));
          const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
          for (int k = 0; k < 6; ++k)
            for (int c = 0; c < 3; ++c)
              worst = std::max(worst, std::abs(g.second(q, 3 * k + c) - D.hessian[c](pairs[k][0], pairs[k][1])) /
                                          std::max(1.0, D.hessian[c].norm()));
          ++q;
        }
    EXPECT_LT(worst, 1e-11);
  }
}

TEST(SplineEvaluate, BoundaryFacesAndEdgesAreExact) {
  std::mt19937 rng(6);
  const Patch P = random_patch(rng, {{2, 3, 1}}, {{4, 5, 3}}, true);
  std::uniform_real_distribution<double> R(0, 1);
  for (const Side side : Side::all()) {
    const Surface S = boundary_surface(P, side);
    const auto t = side.tangent_directions();
    for (int s = 0; s < 50; ++s) {
      Eigen::Vector3d u;
      u[side.direction()] = side.parameter() ? 1.0 : 0.0;
      u[t[0]] = R(rng);
      u[t[1]] = R(rng);
      EXPECT_LT((evaluate_point(S, Eigen::Vector2d(u[t[0]], u[t[1]])) - evaluate_point(P, u)).norm(), 1e-14);
      const Eigen::Matrix<double, 3, 2> J = evaluate_jacobian(S, Eigen::Vector2d(u[t[0]], u[t[1]]));
      const Eigen::Matrix3d JP = evaluate_jacobian(P, u);
      EXPECT_LT((J.col(0) - JP.col(t[0])).norm(), 1e-12);
      EXPECT_LT((J.col(1) - JP.col(t[1])).norm(), 1e-12);
    }
  }
  for (int dir = 0; dir < 3; ++dir)
    for (int e = 0; e < 4; ++e) {
      const Curve C = boundary_curve(P, dir, e & 1, e & 2);
      int o[2], k = 0;
      for (int d = 0; d < 3; ++d)
        if (d != dir) o[k++] = d;
      for (int s = 0; s < 20; ++s) {
        Eigen::Vector3d u;
        u[dir] = R(rng);
        u[o[0]] = (e & 1) ? 1.0 : 0.0;
        u[o[1]] = (e & 2) ? 1.0 : 0.0;
        EXPECT_LT((evaluate_point(C, u[dir]) - evaluate_point(P, u)).norm(), 1e-14);
      }
    }
}

TEST(SplineEvaluate, MismatchedGridBasisIsRejected) {
  std::mt19937 rng(7);
  const Patch A = random_patch(rng, {{2, 2, 2}}, {{4, 4, 4}}, false);
  const Patch B = random_patch(rng, {{2, 2, 2}}, {{5, 4, 4}}, false);
  const GridBasis g = grid_basis(A, {{{0.5}, {0.5}, {0.5}}}, 0);
  EXPECT_THROW(evaluate_grid(B, g), igaprep::Error);
}
