// Knot insertion, degree elevation and knot removal keep (or bound) the geometry.
#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "spline_test_util.h"

using namespace spline_test;

namespace {
double max_deviation(const Patch& A, const Patch& B, std::mt19937& rng, int samples) {
  double worst = 0;
  for (int s = 0; s < samples; ++s) {
    const Eigen::Vector3d u = random_param(rng, A);
    worst = std::max(worst, (evaluate_point(A, u) - evaluate_point(B, u)).norm());
  }
  return worst;
}
// Dense grid deviation (includes element boundaries and domain ends).
double grid_deviation(const Patch& A, const Patch& B, int m) {
  std::array<std::vector<double>, 3> g;
  for (int d = 0; d < 3; ++d)
    for (int i = 0; i <= m; ++i) g[d].push_back(A.knots[d].front() + (A.knots[d].back() - A.knots[d].front()) * i / m);
  const Eigen::MatrixXd a = evaluate_grid(A, g, 0).points, b = evaluate_grid(B, g, 0).points;
  return (a - b).rowwise().norm().maxCoeff();
}
}  // namespace

TEST(SplineRefine, KnotInsertionKeepsGeometry) {
  std::mt19937 rng(11);
  for (bool rational : {false, true})
    for (int p = 1; p <= 4; ++p) {
      const Patch P = random_patch(rng, {{p, p, std::max(1, p - 1)}}, {{p + 4, p + 3, p + 2}}, rational, 2);
      Patch R = P;
      std::uniform_real_distribution<double> U(0.02, 0.98);
      for (int d = 0; d < 3; ++d) {
        std::vector<double> X = {U(rng), U(rng), U(rng)};
        if (R.degrees[d] >= 2) X.push_back(X[0]);  // a repeated new knot
        R = insert_knots(R, d, X);
      }
      // Raise an existing knot's multiplicity where the degree allows it.
      const double k0 = P.knots[0][P.degrees[0] + 1];
      const int extra = knot_multiplicity(P.knots[0], k0) < p ? 1 : 0;
      R = insert_knot(R, 0, k0, extra);
      ASSERT_EQ(R.count(0), P.count(0) + (p >= 2 ? 4 : 3) + extra);
      EXPECT_LT(max_deviation(P, R, rng, 1000), 1e-12) << "p = " << p << " rational " << rational;
    }
}

TEST(SplineRefine, InsertionRejectsBadKnots) {
  std::mt19937 rng(12);
  const Patch P = random_patch(rng, {{2, 2, 2}}, {{4, 4, 4}}, false);
  EXPECT_THROW(insert_knots(P, 0, {1.5}), igaprep::Error);
  EXPECT_THROW(insert_knots(P, 0, {0.5, 0.5, 0.5}), igaprep::Error);
}

TEST(SplineRefine, DegreeElevationKeepsGeometry) {
  std::mt19937 rng(13);
  for (bool rational : {false, true})
    for (int p = 1; p <= 3; ++p)
      for (int t = 1; t <= 2; ++t) {
        const Patch P = random_patch(rng, {{p, p + 1, 1}}, {{p + 5, p + 4, 3}}, rational, p);
        Patch E = P;
        for (int d = 0; d < 3; ++d) E = elevate_degree(E, d, t);
        for (int d = 0; d < 3; ++d) {
          EXPECT_EQ(E.degrees[d], P.degrees[d] + t);
          // Every distinct knot's multiplicity grows by t.
          for (double u : unique_knots(P.knots[d]))
            EXPECT_EQ(knot_multiplicity(E.knots[d], u), knot_multiplicity(P.knots[d], u) + t);
        }
        EXPECT_LT(max_deviation(P, E, rng, 1000), 1e-12) << "p = " << p << " t = " << t;
      }
}

TEST(SplineRefine, CurveAndSurfaceRefinement) {
  const Curve c = quarter_circle();
  const Curve r = elevate_degree(insert_knots(c, {0.3, 0.6}), 2);
  for (int i = 0; i <= 200; ++i) EXPECT_LT(std::abs(evaluate_point(r, i / 200.0).norm() - 1.0), 1e-14);
}

TEST(SplineRefine, RemovingAnInsertedKnotRecoversControlPoints) {
  std::mt19937 rng(14);
  for (bool rational : {false, true})
    for (int p = 1; p <= 4; ++p)
      for (int d = 0; d < 3; ++d) {
        const Patch P = random_patch(rng, {{p, p, p}}, {{p + 3, p + 3, p + 3}}, rational);
        const double u = 0.37;  // not a knot of P (random knots are never exactly this)
        Patch R = insert_knot(P, d, u, std::min(p, 2));
        double err = -1;
        const int removed = remove_knot(&R, d, u, 2, 1e-10, &err);
        ASSERT_EQ(removed, std::min(p, 2));
        EXPECT_LT(err, 1e-12);
        EXPECT_EQ(R.knots[d], P.knots[d]);
        EXPECT_LT((R.control_points - P.control_points).cwiseAbs().maxCoeff(), 1e-12);
        if (rational) EXPECT_LT((R.weights - P.weights).cwiseAbs().maxCoeff(), 1e-12);
      }
}

TEST(SplineRefine, RemovalWithToleranceNeverMovesMoreThanTolerance) {
  std::mt19937 rng(15);
  for (bool rational : {false, true})
    for (double tol : {1e-3, 1e-2}) {
      const Patch coarse = random_patch(rng, {{3, 2, 2}}, {{5, 4, 4}}, rational);
      Patch fine = refine_uniformly(coarse, 2);
      // Perturb so removal is no longer exact.
      std::normal_distribution<double> N(0.0, 0.01 * tol);
      for (long i = 0; i < fine.control_points.size(); ++i) fine.control_points.data()[i] += N(rng);
      Patch reduced = fine;
      const ReductionReport rep = reduce_knots(&reduced, tol);
      EXPECT_GT(rep.removed, 0);
      EXPECT_LE(rep.error_bound, tol);
      const double dev = grid_deviation(fine, reduced, 40);
      EXPECT_LE(dev, rep.error_bound + 1e-14) << "tol " << tol;
      EXPECT_LE(std::max(dev, max_deviation(fine, reduced, rng, 3000)), tol);
      // Knots never removed below the coarse patch's when tolerance is small.
      EXPECT_LT(reduced.control_points.rows(), fine.control_points.rows());
    }
}

TEST(SplineRefine, RemovalRefusesWhenOverTolerance) {
  std::mt19937 rng(16);
  const Patch P = random_patch(rng, {{2, 2, 2}}, {{6, 6, 6}}, false);
  Patch Q = P;
  double err = 1;
  const int removed = remove_knot(&Q, 1, P.knots[1][4], 1, 1e-9, &err);
  EXPECT_EQ(removed, 0);
  EXPECT_EQ(err, 0.0);
  EXPECT_EQ(Q.control_points, P.control_points);
}
