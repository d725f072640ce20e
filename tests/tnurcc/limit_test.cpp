// The limit surface (OpenSubdiv, double precision) against closed forms:
// a regular region is the uniform bicubic B-spline of its 4 x 4 points.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "igaprep/spline/tnurcc_limit.h"
#include "igaprep/spline/tnurcc_quality.h"
#include "tnurcc/tnurcc_models.h"

namespace {

using namespace igaprep::spline;

// Uniform cubic B-spline basis (derivative order 0, 1 or 2) at t in [0, 1].
std::array<double, 4> uniform_cubic(double t, int order) {
  const double u = 1.0 - t;
  if (order == 0) return {{u * u * u / 6, (3 * t * t * t - 6 * t * t + 4) / 6, (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6,
                           t * t * t / 6}};
  if (order == 1) return {{-u * u / 2, (3 * t * t - 4 * t) / 2, (-3 * t * t + 2 * t + 1) / 2, t * t / 2}};
  return {{u, 3 * t - 2, -3 * t + 1, t}};
}

// An open n x n grid cage over the plane, heights random.
Cage wavy_grid(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> h(-0.5, 0.5);
  Cage c;
  c.points.resize(n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) c.points.row(i + n * j) << i + 0.2 * h(rng), j + 0.2 * h(rng), h(rng);
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) c.faces.push_back({{i + n * j, i + 1 + n * j, i + 1 + n * (j + 1), i + n * (j + 1)}});
  build_cage_edges(c);
  return c;
}

TEST(TnurccLimit, RegularRegionIsTheUniformBicubicBSpline) {
  std::mt19937 rng(7);
  const int n = 8;
  const Cage c = wavy_grid(n, rng);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<LimitLocation> at;
  std::vector<std::array<int, 2>> cell;
  for (int j = 1; j + 2 < n; ++j)  // faces whose 4 x 4 points are all in the grid
    for (int i = 1; i + 2 < n; ++i)
      for (int r = 0; r < 5; ++r) {
        at.push_back({i + (n - 1) * j, unit(rng), unit(rng)});
        cell.push_back({{i, j}});
      }
  LimitOptions o;
  o.second_derivatives = true;
  const LimitStencils st = limit_stencils(c, at, o);
  const Eigen::MatrixXd X = st.value * c.points, Xs = st.ds * c.points, Xt = st.dt * c.points,
                        Xss = st.dss * c.points, Xst = st.dst * c.points, Xtt = st.dtt * c.points;
  double worst = 0.0;
  for (size_t r = 0; r < at.size(); ++r) {
    const auto [i, j] = cell[r];
    auto bspline = [&](int os, int ot) {
      const auto bs = uniform_cubic(at[r].s, os), bt = uniform_cubic(at[r].t, ot);
      Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) x += bs[a] * bt[b] * c.points.row(i - 1 + a + n * (j - 1 + b));
      return x;
    };
    const int row = static_cast<int>(r);
    worst = std::max({worst, (X.row(row) - bspline(0, 0)).norm(), (Xs.row(row) - bspline(1, 0)).norm(),
                      (Xt.row(row) - bspline(0, 1)).norm(), (Xss.row(row) - bspline(2, 0)).norm(),
                      (Xst.row(row) - bspline(1, 1)).norm(), (Xtt.row(row) - bspline(0, 2)).norm()});
  }
  EXPECT_LT(worst, 1e-12);
  // Every stencil row sums to 1 (affine invariance), derivatives' rows to 0.
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(c.points.rows());
  EXPECT_LT(((st.value * ones).array() - 1.0).abs().maxCoeff(), 1e-13);
  EXPECT_LT((st.ds * ones).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(TnurccLimit, RefusesUnequalIntervalsAndLocationsOutsideTheCage) {
  std::mt19937 rng(3);
  Cage c = wavy_grid(4, rng);
  EXPECT_THROW(limit_stencils(c, {{9, 0.5, 0.5}}), igaprep::Error);
  EXPECT_THROW(limit_stencils(c, {{0, 1.5, 0.5}}), igaprep::Error);
  c.edges[0].interval = 2.0;
  EXPECT_THROW(limit_stencils(c, {{0, 0.5, 0.5}}), igaprep::Error);
}

TEST(TnurccLimit, NeighbouringFacesAgreeOnTheirEdgeAroundExtraordinaryVertices) {
  // The box's cage without creases: 8 vertices of valence 3 (Gregory end caps).
  CageOptions smooth;
  smooth.crease_angle = 180.0;
  const Cage c = surface_cage(tnurcc_test::boxes(1, 2), 0, smooth);
  std::vector<LimitLocation> at;
  for (size_t e = 0; e < c.edges.size(); ++e)
    for (int f : c.edges[e].faces)
      for (int k = 0; k < 4; ++k)
        if (c.face_edges[f][k] == static_cast<int>(e)) {
          // 30 % of the way from the edge's first vertex, seen from either face.
          const bool forward = c.faces[f][k] == c.edges[e].vertices[0];
          at.push_back(edge_location(f, k, forward ? 0.3 : 0.7));
        }
  const LimitValues v = limit_values(limit_stencils(c, at), c.points);
  double gap = 0.0, turn = 0.0;
  for (int i = 0; i + 1 < v.point.rows(); i += 2) {
    gap = std::max(gap, (v.point.row(i) - v.point.row(i + 1)).norm());
    const Eigen::Vector3d a = v.normal.row(i), b = v.normal.row(i + 1);
    turn = std::max(turn, std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / M_PI);
  }
  EXPECT_LT(gap, 1e-12);  // the limit surface is continuous ...
  EXPECT_LT(turn, 1e-6);  // ... and its normal too, Gregory patches included
  // Outward normals: on the box's top face the normal points up.
  int up = 0, top = 0;
  for (int i = 0; i < v.point.rows(); ++i)
    if (v.point(i, 2) > 0.999) {
      ++top;
      up += v.normal(i, 2) > 0.99;
    }
  EXPECT_GT(top, 0);
  EXPECT_EQ(up, top);
}

}  // namespace

namespace {

using namespace igaprep::spline;

TEST(TnurccQuality, CreasesKeepTheBoxsRightAnglesAndTheRestIsSmooth) {
  const MultiPatch mp = tnurcc_test::boxes(1, 3);
  const Cage c = surface_cage(mp, 0);
  const NormalJumps creases = limit_normal_jumps(c, JumpEdges::creases);
  EXPECT_EQ(creases.points, 12 * 5 * 3);  // 12 box edges of 5 cage edges, 3 samples each
  EXPECT_NEAR(creases.max, 90.0, 1e-9);
  EXPECT_NEAR(creases.mean, 90.0, 1e-9);
  EXPECT_LT(creases.max_gap, 1e-12);
  const NormalJumps smooth = limit_normal_jumps(c, JumpEdges::smooth);
  EXPECT_GT(smooth.points, 0);
  EXPECT_LT(smooth.max, 1e-9);
  // The C0 model: its patch sides meet at the box's edges only, all creases.
  EXPECT_EQ(model_normal_jumps(mp, c).points, 0);
}

TEST(TnurccQuality, ModelJumpMeasuresTheKinkBetweenTwoPatches) {
  // Two boxes, the second's top raised along x: the outer surface kinks at x = 1.
  MultiPatch mp = tnurcc_test::boxes(2, 2);
  for (int r = 0; r < mp.patches[1].control_points.rows(); ++r) {
    auto p = mp.patches[1].control_points.row(r);
    p[2] += 0.2 * (p[0] - 1.0) * p[2];  // z scaled by 1 + 0.2 (x - 1): the top turns by atan(0.2)
  }
  CageOptions o;
  o.crease_angle = 45.0;
  const Cage c = surface_cage(mp, 0, o);
  const NormalJumps j = model_normal_jumps(mp, c);
  EXPECT_NEAR(j.max, std::atan(0.2) * 180 / M_PI, 1e-9);
  EXPECT_LT(j.max_gap, 1e-14);
  EXPECT_LT(limit_normal_jumps(c, JumpEdges::smooth_patch_edges).max, 1e-9);
}

}  // namespace
