// Basis functions: partition of unity, non-negativity, derivatives against
// central differences, span search and knot-vector validation.
#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "spline_test_util.h"

using namespace spline_test;

TEST(SplineBasis, PartitionOfUnityAndNonNegativity) {
  std::mt19937 rng(1);
  double worst = 0, most_negative = 0;
  for (int p = 0; p <= 5; ++p)
    for (int trial = 0; trial < 20; ++trial) {
      const int n = p + 1 + trial % 7;
      const auto U = random_knots(rng, p, n, std::max(1, p));
      validate_knot_vector(U, p, n, "test");
      std::uniform_real_distribution<double> R(0, 1);
      for (int s = 0; s < 200; ++s) {
        const double u = R(rng);
        const int span = find_span(U, p, u);
        ASSERT_LE(U[span], u);
        ASSERT_TRUE(u < U[span + 1] || span == n - 1);
        const Eigen::VectorXd N = basis_functions(U, p, span, u);
        worst = std::max(worst, std::abs(N.sum() - 1.0));
        most_negative = std::min(most_negative, N.minCoeff());
      }
    }
  EXPECT_LT(worst, 1e-14);
  EXPECT_GE(most_negative, 0.0);
}

TEST(SplineBasis, DerivativesMatchCentralDifferences) {
  std::mt19937 rng(2);
  double worst = 0;
  for (int p = 1; p <= 5; ++p)
    for (int trial = 0; trial < 10; ++trial) {
      const int n = p + 4;
      const auto U = random_knots(rng, p, n, 1);
      std::uniform_real_distribution<double> R(0.01, 0.99);
      for (int s = 0; s < 50; ++s) {
        const double u = R(rng);
        const int span = find_span(U, p, u);
        const double h = 1e-6;
        // Stay inside one span so the differences see a polynomial.
        if (u - h <= U[span] || u + h >= U[span + 1]) continue;
        const Eigen::MatrixXd D = basis_derivatives(U, p, span, u, p);
        // Row 0 equals basis_functions.
        ASSERT_LT((D.row(0).transpose() - basis_functions(U, p, span, u)).norm(), 1e-15);
        for (int k = 1; k <= std::min(p, 3); ++k) {
          const Eigen::MatrixXd Dp = basis_derivatives(U, p, span, u + h, k - 1);
          const Eigen::MatrixXd Dm = basis_derivatives(U, p, span, u - h, k - 1);
          const Eigen::VectorXd fd = (Dp.row(k - 1) - Dm.row(k - 1)).transpose() / (2 * h);
          const double scale = std::max(1.0, D.row(k).cwiseAbs().maxCoeff());
          worst = std::max(worst, (fd - D.row(k).transpose()).cwiseAbs().maxCoeff() / scale);
        }
        // Orders above p vanish.
        const Eigen::MatrixXd Dh = basis_derivatives(U, p, span, u, p + 2);
        EXPECT_EQ(Dh.bottomRows(2).cwiseAbs().maxCoeff(), 0.0);
      }
    }
  EXPECT_LT(worst, 1e-6);
}

TEST(SplineBasis, BernsteinIsBasisOfSingleElement) {
  for (int p = 0; p <= 6; ++p) {
    std::vector<double> U(p + 1, 0.0);
    U.insert(U.end(), p + 1, 1.0);
    for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
      std::vector<double> B(p + 1);
      bernstein_basis(p, t, B.data());
      const Eigen::VectorXd N = basis_functions(U, p, find_span(U, p, t), t);
      for (int i = 0; i <= p; ++i) EXPECT_NEAR(B[i], N[i], 1e-15);
    }
  }
}

TEST(SplineBasis, SpanSearchAtEndsAndRepeatedKnots) {
  const std::vector<double> U = {0, 0, 0, 0.5, 0.5, 1, 1, 1};  // p = 2, n = 5
  EXPECT_EQ(find_span(U, 2, 0.0), 2);
  EXPECT_EQ(find_span(U, 2, 0.5), 4);
  EXPECT_EQ(find_span(U, 2, 0.49), 2);
  EXPECT_EQ(find_span(U, 2, 1.0), 4);
  EXPECT_EQ(find_span(U, 2, 7.0), 4);
  EXPECT_EQ(find_span(U, 2, -1.0), 2);
}

TEST(SplineBasis, ValidationNamesTheFault) {
  auto msg = [](const std::vector<double>& U, int p, int n) -> std::string {
    try {
      validate_knot_vector(U, p, n, "patch 7 direction v");
    } catch (const igaprep::Error& e) {
      EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
      return e.what();
    }
    return "";
  };
  EXPECT_NE(msg({0, 0, 0, 1, 1}, 2, 3).find("expected n + p + 1 = 6"), std::string::npos);
  EXPECT_NE(msg({0, 0, 0, 0.7, 0.3, 1, 1, 1}, 2, 5).find("decrease at index 4"), std::string::npos);
  EXPECT_NE(msg({0, 0, 0.1, 0.5, 1, 1, 1, 1}, 2, 5).find("not open"), std::string::npos);
  EXPECT_EQ(msg({0, 0, 0, 1, 1, 1}, 2, 3), "");
  EXPECT_NE(msg({0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1}, 2, 7).find("repeated more than"), std::string::npos);
  EXPECT_NE(msg({0, 0, 0, 0, 1, 1, 1}, 2, 4).find("patch 7 direction v"), std::string::npos);
}
