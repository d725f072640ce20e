// Bezier extraction reproduces every basis function and the geometry.
#include <gtest/gtest.h>

#include "spline_test_util.h"

using namespace spline_test;

namespace {
int element_of(const Extraction1d& ex, double u) {
  for (int e = 0; e < ex.element_count(); ++e)
    if (u < ex.breaks[e + 1] || e + 1 == ex.element_count()) return e;
  return ex.element_count() - 1;
}
}  // namespace

TEST(SplineBezier, ExtractionReproducesBasisFunctions) {
  std::mt19937 rng(21);
  double worst = 0;
  for (int p = 0; p <= 5; ++p)
    for (int trial = 0; trial < 10; ++trial) {
      const int n = p + 1 + 2 * trial;
      const auto U = random_knots(rng, p, n, std::max(1, p));
      const Extraction1d ex = bezier_extraction_1d(U, p);
      ASSERT_EQ(ex.element_count(), static_cast<int>(unique_knots(U).size()) - 1);
      std::uniform_real_distribution<double> R(0, 1);
      for (int s = 0; s < 200; ++s) {
        const double u = R(rng);
        const int e = element_of(ex, u);
        const double a = ex.breaks[e], b = ex.breaks[e + 1];
        std::vector<double> B(p + 1);
        bernstein_basis(p, (u - a) / (b - a), B.data());
        const Eigen::VectorXd Ne = ex.C[e] * Eigen::Map<Eigen::VectorXd>(B.data(), p + 1);
        const int span = find_span(U, p, u);
        ASSERT_EQ(span - p, ex.first[e]);
        const Eigen::VectorXd N = basis_functions(U, p, span, u);
        worst = std::max(worst, (Ne - N).cwiseAbs().maxCoeff());
      }
    }
  EXPECT_LT(worst, 1e-13);
}

TEST(SplineBezier, BernsteinControlPointsReproduceTheVolume) {
  std::mt19937 rng(22);
  for (bool rational : {false, true}) {
    const Patch P = random_patch(rng, {{3, 2, 2}}, {{7, 5, 4}}, rational, 2);
    const PatchExtraction ex = bezier_extraction(P);
    double worst = 0, worst_basis = 0;
    for (int s = 0; s < 300; ++s) {
      const Eigen::Vector3d u = random_param(rng, P);
      int el[3];
      Eigen::Vector3d t;
      for (int d = 0; d < 3; ++d) {
        el[d] = element_of(ex.dirs[d], u[d]);
        const double a = ex.dirs[d].breaks[el[d]], b = ex.dirs[d].breaks[el[d] + 1];
        t[d] = (u[d] - a) / (b - a);
      }
      const BezierElement be = bernstein_control_points(P, ex, el[0], el[1], el[2]);
      worst = std::max(worst, (evaluate_bezier(be, P.degrees, t) - evaluate_point(P, u)).norm());
      // Tensor-product operator times Bernstein values = product of 1-D basis values.
      const Eigen::MatrixXd C = element_extraction_operator(ex, el[0], el[1], el[2]);
      Eigen::VectorXd Bt(C.cols());
      double B[3][8];
      for (int d = 0; d < 3; ++d) bernstein_basis(P.degrees[d], t[d], B[d]);
      int q = 0;
      for (int k = 0; k <= P.degrees[2]; ++k)
        for (int j = 0; j <= P.degrees[1]; ++j)
          for (int i = 0; i <= P.degrees[0]; ++i) Bt[q++] = B[0][i] * B[1][j] * B[2][k];
      const Eigen::VectorXd Nt = C * Bt;
      Eigen::VectorXd N1[3];
      for (int d = 0; d < 3; ++d)
        N1[d] = basis_functions(P.knots[d], P.degrees[d], find_span(P.knots[d], P.degrees[d], u[d]), u[d]);
      q = 0;
      for (int k = 0; k <= P.degrees[2]; ++k)
        for (int j = 0; j <= P.degrees[1]; ++j)
          for (int i = 0; i <= P.degrees[0]; ++i)
            worst_basis = std::max(worst_basis, std::abs(Nt[q++] - N1[0][i] * N1[1][j] * N1[2][k]));
    }
    EXPECT_LT(worst, 1e-13);
    EXPECT_LT(worst_basis, 1e-13);
  }
}
