// Fitting the faces of a model on one surface to target points, and carrying
// the moves inside (spline/fit_model_surface.h).
#include <gtest/gtest.h>

#include <cmath>

#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/fit_model_surface.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch_topology.h"

namespace {
using namespace igaprep::spline;

constexpr int kN = 7;  // control points per direction: degree 3, 4 elements

// The box [x0, x0 + 1] x [0, 1] x [0, 1] as a degree-3 patch (identity map).
Patch box(double x0) {
  Patch P;
  P.degrees = {{3, 3, 3}};
  for (int d = 0; d < 3; ++d) P.knots[d] = uniform_knot_vector(3, kN);
  const std::vector<double> g = greville_abscissae(P.knots[0], 3);
  P.control_points.resize(kN * kN * kN, 3);
  for (int k = 0; k < kN; ++k)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) P.control_points.row(P.index(i, j, k)) << x0 + g[i], g[j], g[k];
  return P;
}

// Two boxes side by side sharing the face x = 1; their tops (w1) are label
// 0, their bottoms (w0) label 1.
MultiPatch two_boxes() {
  MultiPatch mp;
  mp.patches = {box(0.0), box(1.0)};
  mp.labels = {"top", "bottom"};
  find_interfaces(mp, 1e-12);
  for (int p = 0; p < 2; ++p) {
    mp.boundaries.push_back({p, kW1, 0});
    mp.boundaries.push_back({p, kW0, 1});
  }
  return mp;
}

double tilted_plane(const Eigen::Vector3d& x) { return 1.0 + 0.1 * x[0] - 0.05 * x[1]; }

// Each top face sampled on a 9 x 9 grid, the target straight above or below on the tilted plane.
std::vector<SurfaceFitPair> pairs_to_plane(const MultiPatch& mp) {
  std::vector<SurfaceFitPair> out;
  for (int p = 0; p < 2; ++p)
    for (int j = 0; j <= 8; ++j)
      for (int i = 0; i <= 8; ++i) {
        const Eigen::Vector2d uv(i / 8.0, j / 8.0);
        Eigen::Vector3d x = evaluate_point(mp.patches[p], Eigen::Vector3d(uv[0], uv[1], 1.0));
        x[2] = tilted_plane(x);
        out.push_back({p, kW1, uv, x});
      }
  return out;
}

double largest_distance_to_plane(const MultiPatch& mp) {
  double worst = 0.0;
  for (int p = 0; p < 2; ++p)
    for (int j = 0; j <= 12; ++j)
      for (int i = 0; i <= 12; ++i) {
        const Eigen::Vector3d x = evaluate_point(mp.patches[p], Eigen::Vector3d(i / 12.0, j / 12.0, 1.0));
        worst = std::max(worst, std::abs(x[2] - tilted_plane(x)));
      }
  return worst;
}

TEST(FitModelSurface, BumpedTopsComeBackToAPlaneAndStayConforming) {
  MultiPatch mp = two_boxes();
  ASSERT_EQ(mp.interfaces.size(), 1u);
  for (auto& P : mp.patches)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        const Eigen::Vector3d x = P.control_points.row(P.index(i, j, kN - 1)).transpose();
        P.control_points(P.index(i, j, kN - 1), 2) += 0.05 * std::sin(M_PI * x[0] / 2) * std::sin(M_PI * x[1]);
      }
  const double before = largest_distance_to_plane(mp);
  EXPECT_GT(before, 0.09);
  SurfaceFitOptions o;
  o.iterations = 30;
  o.smoothing = 0.0;  // the plane is in the spline space: plain least squares reaches it
  o.stop_improvement = 0.0;
  const SurfaceFitResult r = fit_model_surface(mp, 0, pairs_to_plane, {}, o);
  EXPECT_EQ(r.moved_points, 2 * kN * kN - kN);  // the shared column counted once
  EXPECT_LT(largest_distance_to_plane(mp), 1e-9);
  EXPECT_LT(r.rms.back(), 1e-9);
  EXPECT_GT(r.rms.front(), 0.01);
  EXPECT_TRUE(check_conformity(mp, 1e-12).conforming);
  // The bottoms (another surface) did not move.
  for (const auto& P : mp.patches)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) EXPECT_EQ(P.control_points(P.index(i, j, 0), 2), 0.0);
}

TEST(FitModelSurface, FixedSidesStay) {
  MultiPatch mp = two_boxes();
  const MultiPatch start = mp;
  SurfaceFitOptions o;
  o.iterations = 3;
  fit_model_surface(mp, 0, pairs_to_plane, {{0, kU0}}, o);
  const Patch& P = mp.patches[0];
  for (int j = 0; j < kN; ++j)
    EXPECT_EQ(P.control_points.row(P.index(0, j, kN - 1)), start.patches[0].control_points.row(P.index(0, j, kN - 1)));
  EXPECT_GT((P.control_points.row(P.index(3, 3, kN - 1)) - start.patches[0].control_points.row(P.index(3, 3, kN - 1))).norm(), 0.01);
}

TEST(FitModelSurface, MovesCarriedInsideLinearlyBetweenTwoSurfaces) {
  MultiPatch mp = two_boxes();
  const MultiPatch before = mp;
  for (auto& P : mp.patches)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) P.control_points(P.index(i, j, kN - 1), 2) += 0.2;
  carry_moves_inside(mp, before, {});
  // Every layer moves alike, so its in-layer neighbours cancel: the harmonic
  // extension along w is linear, 0 on the bottom and 0.2 on the top.
  for (size_t p = 0; p < 2; ++p)
    for (int k = 0; k < kN; ++k)
      for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
          const int l = mp.patches[p].index(i, j, k);
          const Eigen::RowVector3d move = mp.patches[p].control_points.row(l) - before.patches[p].control_points.row(l);
          EXPECT_NEAR(move[2], 0.2 * k / (kN - 1), 1e-8);
          EXPECT_NEAR(move.head<2>().norm(), 0.0, 1e-12);
        }
  EXPECT_TRUE(check_conformity(mp, 1e-12).conforming);
}

}  // namespace
