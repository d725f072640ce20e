// Interfaces from geometry (find_interfaces.h): a 2 x 2 x 1 arrangement of
// patches, one of them with its directions permuted and reversed; stitching
// within a tolerance only; no interface across a shared edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "igaprep/core/error.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch_topology.h"

namespace {

using namespace igaprep::spline;

// A smooth warp of space, so that no face is symmetric.
Eigen::Vector3d warp(const Eigen::Vector3d& x) {
  return {x.x() + 0.05 * x.y() * x.y() + 0.02 * x.z(), x.y() + 0.07 * std::sin(x.x()) + 0.03 * x.x() * x.z(),
          x.z() + 0.04 * x.x() * x.y()};
}

// Knot vectors with dyadic knots, different counts and no symmetry per
// global direction (x: 3 control points, y: 4, z: 5), so that exactly one
// orientation matches each face.
const std::vector<double> kX{0, 0, 0, 1, 1, 1};                   // degree 2, 3 points
const std::vector<double> kY{0, 0, 0, 0.25, 1, 1, 1};             // degree 2, 4 points
const std::vector<double> kZ{0, 0, 0, 0, 0.125, 1, 1, 1, 1};      // degree 3, 5 points

std::vector<double> reversed(const std::vector<double>& U) {
  std::vector<double> r;
  for (auto it = U.rbegin(); it != U.rend(); ++it) r.push_back(1.0 - *it);
  return r;
}

// Patch on the box [ox, ox + 1] x [oy, oy + 1] x [0, 1], (u, v, w) = (x, y, z).
Patch box_patch(double ox, double oy) {
  Patch P;
  P.degrees = {{2, 2, 3}};
  P.knots = {{kX, kY, kZ}};
  const auto gx = greville_abscissae(kX, 2), gy = greville_abscissae(kY, 2), gz = greville_abscissae(kZ, 3);
  P.control_points.resize(P.count(0) * P.count(1) * P.count(2), 3);
  for (int k = 0; k < P.count(2); ++k)
    for (int j = 0; j < P.count(1); ++j)
      for (int i = 0; i < P.count(0); ++i)
        P.control_points.row(P.index(i, j, k)) = warp(Eigen::Vector3d(ox + gx[i], oy + gy[j], gz[k])).transpose();
  return P;
}

// The same box, parameterized with u = y reversed, v = z, w = x.
Patch permuted_patch(double ox, double oy) {
  Patch P;
  P.degrees = {{2, 3, 2}};
  P.knots = {{reversed(kY), kZ, kX}};
  const auto gu = greville_abscissae(P.knots[0], 2), gz = greville_abscissae(kZ, 3), gx = greville_abscissae(kX, 2);
  P.control_points.resize(P.count(0) * P.count(1) * P.count(2), 3);
  for (int k = 0; k < P.count(2); ++k)
    for (int j = 0; j < P.count(1); ++j)
      for (int i = 0; i < P.count(0); ++i)
        P.control_points.row(P.index(i, j, k)) =
            warp(Eigen::Vector3d(ox + gx[k], oy + (1.0 - gu[i]), gz[j])).transpose();
  return P;
}

// Patches 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1, permuted). 0 and 3 share only an edge.
MultiPatch arrangement() {
  MultiPatch mp;
  mp.patches = {box_patch(0, 0), box_patch(1, 0), box_patch(0, 1), permuted_patch(1, 1)};
  mp.materials.resize(1);
  mp.labels = {"T1"};
  return mp;
}

std::set<std::pair<int, int>> pairs(const MultiPatch& mp) {
  std::set<std::pair<int, int>> s;
  for (const auto& itf : mp.interfaces) s.insert(std::minmax(itf.patch_a, itf.patch_b));
  return s;
}

const Interface* find(const MultiPatch& mp, int a, int b) {
  for (const auto& itf : mp.interfaces)
    if (itf.patch_a == a && itf.patch_b == b) return &itf;
  return nullptr;
}

TEST(FindInterfaces, TwoByTwoWithPermutedPatch) {
  MultiPatch mp = arrangement();
  // Reversal of the y knots is exact (dyadic), so the permuted patch's
  // points on its shared faces coincide bitwise with its neighbours'.
  find_interfaces(mp, 1e-9);
  ASSERT_EQ(mp.interfaces.size(), 4u);
  EXPECT_EQ(pairs(mp), (std::set<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 3}, {2, 3}}));
  for (const auto& itf : mp.interfaces) EXPECT_EQ(itf.surface, -1);

  const Interface* x01 = find(mp, 0, 1);
  ASSERT_NE(x01, nullptr);
  EXPECT_EQ(x01->side_a, kU1);
  EXPECT_EQ(x01->side_b, kU0);
  EXPECT_EQ(x01->dirmap, (std::array<int, 3>{{0, 1, 2}}));
  EXPECT_EQ(x01->orient, (std::array<int, 3>{{1, 1, 1}}));

  // Patch 2's x = 1 face is patch 3's w0 face; patch 2's y runs against 3's u, its z along 3's v.
  const Interface* x23 = find(mp, 2, 3);
  ASSERT_NE(x23, nullptr);
  EXPECT_EQ(x23->side_a, kU1);
  EXPECT_EQ(x23->side_b, kW0);
  EXPECT_EQ(x23->dirmap, (std::array<int, 3>{{2, 0, 1}}));
  EXPECT_EQ(x23->orient, (std::array<int, 3>{{1, 0, 1}}));

  // Patch 1's y = 1 face is patch 3's u1 face (u runs against y: u0 lies at y = 2), so the
  // normal directions run against each other too (orient 0): v1 meets u1.
  const Interface* x13 = find(mp, 1, 3);
  ASSERT_NE(x13, nullptr);
  EXPECT_EQ(x13->side_a, kV1);
  EXPECT_EQ(x13->side_b, kU1);
  EXPECT_EQ(x13->dirmap, (std::array<int, 3>{{2, 0, 1}}));
  EXPECT_EQ(x13->orient, (std::array<int, 3>{{1, 0, 1}}));

  const ConformityReport report = check_conformity(mp, 1e-12);
  EXPECT_TRUE(report.conforming) << (report.problems.empty() ? "" : report.problems[0]);
  EXPECT_EQ(report.max_deviation, 0.0);
  // Shared points counted once: 4 * 60 points, minus the 4 shared faces.
  const GlobalNumbering g = global_numbering(mp);
  const int face_x = 4 * 5, face_y = 3 * 5, edge_z = 5;  // x = const faces (y, z), y = const faces (x, z)
  EXPECT_EQ(g.count, 4 * 3 * 4 * 5 - 2 * face_x - 2 * face_y + edge_z);
}

TEST(FindInterfaces, WrongOrientationIsRejectedByConformity) {
  // The orientation find_interfaces picks is the only one that conforms.
  MultiPatch mp = arrangement();
  find_interfaces(mp, 1e-9);
  const Interface* x23 = find(mp, 2, 3);
  ASSERT_NE(x23, nullptr);
  MultiPatch wrong = mp;
  for (auto& itf : wrong.interfaces)
    if (itf.patch_a == 2 && itf.patch_b == 3) itf.orient[1] = 1;  // not reversed
  const ConformityReport report = check_conformity(wrong, 1e-9);
  EXPECT_FALSE(report.conforming);
  EXPECT_GT(report.max_deviation, 0.1);
}

TEST(FindInterfaces, NoInterfaceAcrossASharedEdge) {
  // Patches 0 and 3 alone: they touch along the edge x = y = 1 only.
  MultiPatch full = arrangement();
  MultiPatch mp;
  mp.patches = {full.patches[0], full.patches[3]};
  find_interfaces(mp, 1e-6);
  EXPECT_TRUE(mp.interfaces.empty());
  // Yet their control points on the edge do coincide (5 along z), so sides
  // of both patches touch: patch 0's u1 (x = 1, y in [0, 1]) and patch 3's
  // w0 (x = 1, y in [1, 2]) share exactly that edge.
  const auto a = side_control_points(mp.patches[0], kU1);
  const auto b = side_control_points(mp.patches[1], kW0);
  int shared = 0;
  for (int i : a)
    for (int j : b)
      if ((mp.patches[0].control_points.row(i) - mp.patches[1].control_points.row(j)).norm() == 0.0) ++shared;
  EXPECT_EQ(shared, 5);
  // Stitching leaves them alone too (they coincide already).
  double max_move = -1.0;
  EXPECT_EQ(stitch_control_points(mp, 1e-6, &max_move), 0);
  EXPECT_EQ(max_move, 0.0);
}

TEST(StitchControlPoints, MovesWithinToleranceOnly) {
  const double tol = 1e-6;
  MultiPatch mp = arrangement();
  // An inner point of patch 1's u0 face (shared with patch 0 only), nudged by 0.3 tol.
  Patch& p1 = mp.patches[1];
  const int near_index = p1.index(0, 1, 2);
  const Eigen::RowVector3d near_orig = p1.control_points.row(near_index);
  const Eigen::RowVector3d nudge = Eigen::RowVector3d(0.2, -0.2, 0.1) * tol;  // |nudge| = 0.3 tol
  p1.control_points.row(near_index) += nudge;
  // An inner point of patch 3's u1 face (y = 1, shared with patch 1), moved 10 tol.
  Patch& p3 = mp.patches[3];
  const int far_index = p3.index(p3.count(0) - 1, 2, 1);
  const Eigen::RowVector3d far_moved = p3.control_points.row(far_index) + Eigen::RowVector3d(0, 0, 10 * tol);
  p3.control_points.row(far_index) = far_moved;
  // An interior control point (on no side) next to nothing: never considered.
  const Eigen::RowVector3d interior = p1.control_points.row(p1.index(1, 1, 1));

  double max_move = -1.0;
  const int moved = stitch_control_points(mp, tol, &max_move);
  EXPECT_EQ(moved, 1);
  EXPECT_NEAR(max_move, 0.3 * tol, 1e-6 * tol);
  // The nudged point went back onto patch 0's point (the group's first), bitwise.
  EXPECT_EQ((mp.patches[1].control_points.row(near_index) - near_orig).norm(), 0.0);
  EXPECT_EQ((mp.patches[1].control_points.row(near_index) -
             mp.patches[0].control_points.row(mp.patches[0].index(2, 1, 2)))
                .norm(),
            0.0);
  // The far point stays where it was.
  EXPECT_EQ((mp.patches[3].control_points.row(far_index) - far_moved).norm(), 0.0);
  EXPECT_EQ((mp.patches[1].control_points.row(p1.index(1, 1, 1)) - interior).norm(), 0.0);

  // With the far point off, interface 1-3 is not found at tol, but at 20 tol.
  find_interfaces(mp, tol);
  EXPECT_EQ(pairs(mp), (std::set<std::pair<int, int>>{{0, 1}, {0, 2}, {2, 3}}));
  find_interfaces(mp, 20 * tol);
  EXPECT_EQ(pairs(mp), (std::set<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 3}, {2, 3}}));
  const ConformityReport loose = check_conformity(mp, 20 * tol);
  EXPECT_TRUE(loose.conforming);
  EXPECT_NEAR(loose.max_deviation, 10 * tol, 1e-12);
  EXPECT_FALSE(check_conformity(mp, tol).conforming);

  EXPECT_THROW(stitch_control_points(mp, 0.0), igaprep::Error);
}

}  // namespace
