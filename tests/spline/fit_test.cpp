// Fitting: exactness on polynomials, convergence rates, fixed control points,
// scattered fit with smoothing.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cstdio>

#include "igaprep/core/error.h"
#include "spline_test_util.h"

using namespace spline_test;

namespace {
// A polynomial map of total degree <= p in each variable separately.
Eigen::RowVector3d poly(const Eigen::Vector3d& u, int p) {
  const double a = std::pow(u[0], p), b = std::pow(u[1], p), c = std::pow(u[2], p);
  return Eigen::RowVector3d(a * u[1] + 1.0 - 2 * c, b * u[2] - u[0] + 0.5 * a * b * c, c + a * u[1] * u[2]);
}
Eigen::RowVector3d smooth(const Eigen::Vector3d& u) {
  return Eigen::RowVector3d(std::sin(2 * u[0] + u[1]), std::cos(1.5 * u[1]) * std::exp(0.7 * u[2]),
                            u[0] * u[1] + std::sin(3 * u[2]));
}
std::vector<double> linspace(double a, double b, int m) {
  std::vector<double> v(m);
  for (int i = 0; i < m; ++i) v[i] = a + (b - a) * i / (m - 1);
  return v;
}
template <class F>
Eigen::MatrixXd sample_grid(const std::array<std::vector<double>, 3>& g, F f) {
  Eigen::MatrixXd S(g[0].size() * g[1].size() * g[2].size(), 3);
  long q = 0;
  for (double w : g[2])
    for (double v : g[1])
      for (double u : g[0]) S.row(q++) = f(Eigen::Vector3d(u, v, w));
  return S;
}
template <class F>
double max_error(const Patch& P, F f, int m) {
  std::array<std::vector<double>, 3> g = {linspace(0, 1, m), linspace(0, 1, m), linspace(0, 1, m)};
  const Eigen::MatrixXd X = evaluate_grid(P, g, 0).points;
  const Eigen::MatrixXd Y = sample_grid(g, f);
  return (X - Y).rowwise().norm().maxCoeff();
}
}  // namespace

TEST(SplineFit, GridFitOfPolynomialIsExact) {
  std::mt19937 rng(41);
  for (int p = 1; p <= 3; ++p) {
    std::array<int, 3> deg = {{p, p, p}};
    std::array<std::vector<double>, 3> knots;
    std::array<std::vector<double>, 3> params;
    for (int d = 0; d < 3; ++d) {
      knots[d] = random_knots(rng, p, p + 4 + d, 1);
      params[d] = linspace(0, 1, 3 * (p + 4 + d));
    }
    auto f = [p](const Eigen::Vector3d& u) { return poly(u, p - (p > 1 ? 1 : 0)); };
    const Patch P = fit_grid(deg, knots, params, sample_grid(params, f));
    EXPECT_LT(max_error(P, f, 23), 1e-10) << "p = " << p;
  }
}

TEST(SplineFit, GridFitConvergesAtRatePPlusOne) {
  for (int p = 2; p <= 3; ++p) {
    std::vector<double> err;
    for (int ne : {3, 6, 12, 24}) {
      std::array<int, 3> deg = {{p, p, p}};
      std::array<std::vector<double>, 3> knots, params;
      for (int d = 0; d < 3; ++d) {
        knots[d] = uniform_knot_vector(p, ne + p);
        params[d] = linspace(0, 1, ne * (p + 1) + 1);
      }
      const Patch P = fit_grid(deg, knots, params, sample_grid(params, smooth));
      err.push_back(max_error(P, smooth, 61));
      std::printf("p = %d, %d elements: max error %.3e\n", p, ne, err.back());
    }
    for (size_t k = 0; k + 1 < err.size(); ++k) {
      const double rate = std::log2(err[k] / err[k + 1]);
      EXPECT_GE(rate, p + 0.8) << "p = " << p << " refinement " << k << " errors " << err[k] << " -> " << err[k + 1];
    }
  }
}

// Dense reference: constrained least squares by brute force (small problem).
TEST(SplineFit, FixedControlPointsGiveTheConstrainedLeastSquaresSolution) {
  std::mt19937 rng(42);
  const int p = 2;
  std::array<int, 3> deg = {{p, p, p}};
  std::array<std::vector<double>, 3> knots, params;
  for (int d = 0; d < 3; ++d) {
    knots[d] = uniform_knot_vector(p, 5 + d);
    params[d] = linspace(0, 1, 9 + d);
  }
  const Eigen::MatrixXd S = sample_grid(params, smooth);
  const Patch free_fit = fit_grid(deg, knots, params, S);
  const long ncp = free_fit.control_points.rows();
  // Dense B.
  Eigen::MatrixXd B(S.rows(), ncp);
  {
    std::array<Eigen::MatrixXd, 3> b;
    for (int d = 0; d < 3; ++d) b[d] = collocation_matrix(knots[d], p, params[d]);
    long r = 0;
    for (size_t k = 0; k < params[2].size(); ++k)
      for (size_t j = 0; j < params[1].size(); ++j)
        for (size_t i = 0; i < params[0].size(); ++i, ++r)
          for (int c = 0; c < ncp; ++c) {
            const int ci = c % 5, cj = (c / 5) % 6, ck = c / 30;
            B(r, c) = b[0](i, ci) * b[1](j, cj) * b[2](k, ck);
          }
  }
  // The unconstrained Kronecker fit solves the normal equations.
  EXPECT_LT((B.transpose() * (B * free_fit.control_points - S)).cwiseAbs().maxCoeff(), 1e-11);
  auto check = [&](const FixedControlPoints& fx, const char* what) {
    const Patch P = fit_grid(deg, knots, params, S, fx);
    std::vector<char> isf(ncp, 0);
    for (size_t k = 0; k < fx.indices.size(); ++k) {
      isf[fx.indices[k]] = 1;
      EXPECT_EQ(P.control_points.row(fx.indices[k]), fx.values.row(k)) << what;
    }
    std::vector<int> fr;
    for (int i = 0; i < ncp; ++i)
      if (!isf[i]) fr.push_back(i);
    Eigen::MatrixXd Bf(B.rows(), fr.size()), Xc = Eigen::MatrixXd::Zero(ncp, 3);
    for (size_t k = 0; k < fx.indices.size(); ++k) Xc.row(fx.indices[k]) = fx.values.row(k);
    for (size_t i = 0; i < fr.size(); ++i) Bf.col(i) = B.col(fr[i]);
    const Eigen::MatrixXd ref = Bf.colPivHouseholderQr().solve(S - B * Xc);
    double worst = 0;
    for (size_t i = 0; i < fr.size(); ++i) worst = std::max(worst, (P.control_points.row(fr[i]) - ref.row(i)).norm());
    EXPECT_LT(worst, 1e-10) << what;
  };
  // A whole face (u0) and a face plus an adjacent face: box path.
  Patch tmp = free_fit;
  FixedControlPoints face;
  face.indices = side_control_points(tmp, kU0);
  face.values.resize(face.indices.size(), 3);
  for (size_t k = 0; k < face.indices.size(); ++k)
    face.values.row(k) = free_fit.control_points.row(face.indices[k]) + Eigen::RowVector3d(0.01, -0.02, 0.03);
  check(face, "face u0");
  FixedControlPoints two = face;
  for (int i : side_control_points(tmp, kW1))
    if (std::find(two.indices.begin(), two.indices.end(), i) == two.indices.end()) {
      two.indices.push_back(i);
      two.values.conservativeResize(two.indices.size(), 3);
      two.values.row(two.indices.size() - 1) = free_fit.control_points.row(i);
    }
  check(two, "faces u0 + w1");
  // Scattered single points and an edge: conjugate-gradient path.
  FixedControlPoints scattered;
  for (int i : {0, 17, 33, 64, 100, 149}) scattered.indices.push_back(i);
  scattered.values.resize(scattered.indices.size(), 3);
  std::uniform_real_distribution<double> R(-0.1, 0.1);
  for (size_t k = 0; k < scattered.indices.size(); ++k)
    scattered.values.row(k) = free_fit.control_points.row(scattered.indices[k]) + Eigen::RowVector3d(R(rng), R(rng), R(rng));
  check(scattered, "scattered points");
}

TEST(SplineFit, ScatteredFitIsExactForSplinesAndSmoothsWithLambda) {
  std::mt19937 rng(43);
  const Patch target = random_patch(rng, {{2, 2, 2}}, {{5, 5, 4}}, false);
  std::uniform_real_distribution<double> R(0, 1);
  const int N = 3000;
  Eigen::MatrixXd uvw(N, 3), pts(N, 3);
  for (int i = 0; i < N; ++i) {
    uvw.row(i) << R(rng), R(rng), R(rng);
    pts.row(i) = evaluate_point(target, uvw.row(i).transpose()).transpose();
  }
  const Patch P = fit_scattered(target.degrees, target.knots, uvw, pts, 0.0);
  EXPECT_LT((P.control_points - target.control_points).cwiseAbs().maxCoeff(), 1e-10);
  // With smoothing, a linear map is still reproduced (the energy vanishes on it).
  Eigen::MatrixXd lin(N, 3);
  for (int i = 0; i < N; ++i) lin.row(i) << 2 * uvw(i, 0) + uvw(i, 1), uvw(i, 1) - uvw(i, 2), 3 * uvw(i, 2) + 1;
  const Patch L = fit_scattered(target.degrees, target.knots, uvw, lin, 10.0);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d u(R(rng), R(rng), R(rng));
    const Eigen::Vector3d ex(2 * u[0] + u[1], u[1] - u[2], 3 * u[2] + 1);
    EXPECT_LT((evaluate_point(L, u) - ex).norm(), 1e-10);
  }
  // Few samples: plain least squares is singular, smoothing makes it solvable.
  const Eigen::MatrixXd few_u = uvw.topRows(20), few_p = pts.topRows(20);
  EXPECT_THROW(fit_scattered(target.degrees, target.knots, few_u, few_p, 0.0), igaprep::Error);
  const Patch S = fit_scattered(target.degrees, target.knots, few_u, few_p, 1e-3);
  EXPECT_TRUE(S.control_points.allFinite());
  // Fixed control points are kept and the rest is the constrained optimum.
  FixedControlPoints fx;
  fx.indices = side_control_points(target, kV1);
  fx.values.resize(fx.indices.size(), 3);
  for (size_t k = 0; k < fx.indices.size(); ++k) fx.values.row(k) = target.control_points.row(fx.indices[k]);
  const Patch F = fit_scattered(target.degrees, target.knots, uvw, pts, 0.0, fx);
  EXPECT_LT((F.control_points - target.control_points).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(SplineFit, SurfaceGridFitAndBadInput) {
  std::array<std::vector<double>, 2> knots = {uniform_knot_vector(3, 6), uniform_knot_vector(2, 5)};
  std::array<std::vector<double>, 2> params = {linspace(0, 1, 15), linspace(0, 1, 12)};
  Eigen::MatrixXd S(15 * 12, 3);
  for (int j = 0, q = 0; j < 12; ++j)
    for (int i = 0; i < 15; ++i, ++q) {
      const double u = params[0][i], v = params[1][j];
      S.row(q) << u * u * u - v, v * v + u, u * v * v;
    }
  const Surface s = fit_grid(std::array<int, 2>{{3, 2}}, knots, params, S);
  EXPECT_LT(std::abs(evaluate_point(s, Eigen::Vector2d(0.3, 0.7))[2] - 0.3 * 0.49), 1e-12);
  // Too few samples in one direction.
  std::array<std::vector<double>, 3> k3 = {uniform_knot_vector(2, 6), uniform_knot_vector(2, 6), uniform_knot_vector(2, 6)};
  std::array<std::vector<double>, 3> p3 = {linspace(0, 1, 3), linspace(0, 1, 10), linspace(0, 1, 10)};
  EXPECT_THROW(fit_grid(std::array<int, 3>{{2, 2, 2}}, k3, p3, Eigen::MatrixXd::Zero(300, 3)), igaprep::Error);
  EXPECT_THROW(fit_grid(std::array<int, 3>{{2, 2, 2}}, k3, p3, Eigen::MatrixXd::Zero(299, 3)), igaprep::Error);
}
