// Block fitting (block_fit.h): the sample parameters, exact reproduction of
// tricubic polynomial maps, and conforming shared sides between two blocks
// sampled from one smooth map (then stitched and found as an interface).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "igaprep/core/error.h"
#include "igaprep/spline/block_fit.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch_topology.h"

namespace {

using namespace igaprep::spline;
using Map = std::function<Eigen::Vector3d(double, double, double)>;

// Samples of a map at params^3, first direction fastest.
Eigen::MatrixXd sample_block(const Map& f, const std::vector<double>& g) {
  const int m = static_cast<int>(g.size());
  Eigen::MatrixXd S(static_cast<Eigen::Index>(m) * m * m, 3);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) S.row(i + m * (j + m * k)) = f(g[i], g[j], g[k]).transpose();
  return S;
}

Eigen::Vector3d cubic_map(double s, double t, double r) {
  return {s + 0.3 * t * t * r, t * t * t - s * r, r + 0.1 * s * t};
}

// A smooth map that no spline reproduces exactly.
Eigen::Vector3d smooth_map(double a, double b, double c) {
  return {a + 0.15 * std::sin(2.0 * b) * c, b + 0.1 * std::exp(0.5 * a) - 0.05 * c * c,
          c + 0.2 * std::cos(a + b)};
}

TEST(BlockSampleParams, GrevilleWithOversampling) {
  for (int degree : {2, 3}) {
    for (int elements : {1, 4, 6}) {
      for (int oversample : {1, 2, 3}) {
        BlockFitOptions o;
        o.degree = degree;
        o.elements = elements;
        o.oversample = oversample;
        const std::vector<double> g = block_sample_params(o);
        const int n = elements + degree;  // control points per direction
        const int expected = oversample == 1 ? n : oversample * (n - 1) + 1;
        ASSERT_EQ(static_cast<int>(g.size()), expected) << degree << " " << elements << " " << oversample;
        EXPECT_EQ(g.front(), 0.0);
        EXPECT_EQ(g.back(), 1.0);
        for (std::size_t i = 1; i < g.size(); ++i) EXPECT_LT(g[i - 1], g[i]) << "index " << i;
        // Every oversample-th parameter is a Greville abscissa of the knot vector.
        const std::vector<double> grev = greville_abscissae(uniform_knot_vector(degree, n), degree);
        ASSERT_EQ(static_cast<int>(grev.size()), n);
        for (int i = 0; i < n; ++i) EXPECT_NEAR(g[static_cast<std::size_t>(i * oversample)], grev[i], 1e-15);
      }
    }
  }
}

TEST(FitBlock, ReproducesTricubicPolynomialMap) {
  for (int oversample : {1, 2}) {
    BlockFitOptions o;
    o.degree = 3;
    o.elements = 4;
    o.oversample = oversample;
    const std::vector<double> g = block_sample_params(o);
    const Patch P = fit_block(sample_block(cubic_map, g), o);
    ASSERT_EQ(P.degrees[0], 3);
    for (int d = 0; d < 3; ++d) ASSERT_EQ(P.count(d), o.elements + o.degree);
    EXPECT_EQ(P.weights.size(), 0);
    EXPECT_EQ(P.material, 0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector3d q(U(rng), U(rng), U(rng));
      worst = std::max(worst, (evaluate_point(P, q) - cubic_map(q.x(), q.y(), q.z())).norm());
    }
    for (int c = 0; c < 8; ++c) {  // the corners are the corner samples
      const Eigen::Vector3d q(c & 1, (c >> 1) & 1, (c >> 2) & 1);
      worst = std::max(worst, (evaluate_point(P, q) - cubic_map(q.x(), q.y(), q.z())).norm());
    }
    EXPECT_LT(worst, 1e-12) << "oversample " << oversample;
  }
}

TEST(FitBlock, DegreeTwoDoesNotReproduceCubic) {
  // The same check must be able to fail: a quadratic fit of a cubic map is off.
  BlockFitOptions o;
  o.degree = 2;
  o.elements = 2;
  const Patch P = fit_block(sample_block(cubic_map, block_sample_params(o)), o);
  const Eigen::Vector3d q(0.37, 0.61, 0.23);
  EXPECT_GT((evaluate_point(P, q) - cubic_map(q.x(), q.y(), q.z())).norm(), 1e-5);
}

TEST(FitBlock, WrongSampleCountIsBadInput) {
  BlockFitOptions o;
  const std::vector<double> g = block_sample_params(o);
  const int m = static_cast<int>(g.size());
  const Eigen::MatrixXd good = sample_block(cubic_map, g);
  EXPECT_NO_THROW(fit_block(good, o));
  const Eigen::MatrixXd fewer = good.topRows(good.rows() - 1);
  const Eigen::MatrixXd two_cols = good.leftCols(2);
  for (const Eigen::MatrixXd* S : {&fewer, &two_cols}) {
    try {
      fit_block(*S, o);
      ADD_FAILURE() << "no exception for " << S->rows() << " x " << S->cols();
    } catch (const igaprep::Error& e) {
      EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
      EXPECT_NE(std::string(e.what()).find(std::to_string(m * m * m)), std::string::npos) << e.what();
    }
  }
  BlockFitOptions bad = o;
  bad.oversample = 0;
  EXPECT_THROW(block_sample_params(bad), igaprep::Error);
}

// Two blocks on adjacent boxes of one smooth map: block A on [0,1]^3 with
// its own parameters; block B on [1,2] x [0,1]^2 with its directions
// permuted and one reversed: B(s, t, r) = F(1 + r, 1 - s, t). A's side u1
// (a = 1) is B's side w0; A's t runs against B's s, A's r along B's t.
TEST(FitBlock, SharedSideConformsAndIsFound) {
  BlockFitOptions o;
  o.degree = 3;
  o.elements = 5;
  o.oversample = 2;
  const std::vector<double> g = block_sample_params(o);
  const Patch A = fit_block(sample_block(smooth_map, g), o);
  const Patch B = fit_block(
      sample_block([](double s, double t, double r) { return smooth_map(1.0 + r, 1.0 - s, t); }, g), o);

  // The smooth map is not reproduced: the blocks are a real approximation.
  EXPECT_GT((evaluate_point(A, Eigen::Vector3d(0.41, 0.53, 0.29)) - smooth_map(0.41, 0.53, 0.29)).norm(), 1e-9);

  const int n = o.elements + o.degree;
  auto a_index = [&](int j, int k) { return A.index(n - 1, j, k); };          // A's side u1 at (t_j, r_k)
  auto b_index = [&](int j, int k) { return B.index(n - 1 - j, k, 0); };      // the same point of B's side w0
  double before = 0.0, side_size = 0.0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j) {
      before = std::max(before, (A.control_points.row(a_index(j, k)) - B.control_points.row(b_index(j, k))).norm());
      side_size = std::max(side_size, A.control_points.row(a_index(j, k)).norm());
    }
  EXPECT_LT(before, 1e-13) << "side control points differ before stitching";
  EXPECT_GT(side_size, 1.0);

  MultiPatch mp;
  mp.patches = {A, B};
  mp.materials.resize(1);
  mp.labels = {"T1"};
  double max_move = -1.0;
  const int moved = stitch_control_points(mp, 1e-9, &max_move);
  EXPECT_GE(moved, 0);
  EXPECT_LE(max_move, before);
  if (before > 0.0) EXPECT_GT(moved, 0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(mp.patches[0].control_points(a_index(j, k), c), mp.patches[1].control_points(b_index(j, k), c))
            << "side point (" << j << ", " << k << ") coordinate " << c;
  // Interior control points are not touched by stitching.
  EXPECT_EQ((mp.patches[0].control_points.row(A.index(2, 2, 2)) - A.control_points.row(A.index(2, 2, 2))).norm(), 0.0);

  find_interfaces(mp, 1e-9);
  ASSERT_EQ(mp.interfaces.size(), 1u);
  const Interface& itf = mp.interfaces[0];
  EXPECT_EQ(itf.patch_a, 0);
  EXPECT_EQ(itf.side_a, kU1);
  EXPECT_EQ(itf.patch_b, 1);
  EXPECT_EQ(itf.side_b, kW0);
  EXPECT_EQ(itf.dirmap, (std::array<int, 3>{{2, 0, 1}}));
  EXPECT_EQ(itf.orient, (std::array<int, 3>{{1, 0, 1}}));
  EXPECT_EQ(itf.surface, -1);
  const ConformityReport report = check_conformity(mp, 1e-12);
  EXPECT_TRUE(report.conforming) << (report.problems.empty() ? "" : report.problems[0]);
  EXPECT_EQ(report.max_deviation, 0.0);

  // The fitted blocks match across the side everywhere, not only at the
  // control points: A(1, t, r) = B(1 - t, r, 0).
  for (double t : {0.1, 0.45, 0.8})
    for (double r : {0.2, 0.7})
      EXPECT_LT((evaluate_point(mp.patches[0], Eigen::Vector3d(1.0, t, r)) -
                 evaluate_point(mp.patches[1], Eigen::Vector3d(1.0 - t, r, 0.0)))
                    .norm(),
                1e-12);
}

}  // namespace
