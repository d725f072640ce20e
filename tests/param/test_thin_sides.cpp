// The two sides of a thin solid as cut loops (thin_sides.h, cut_by_field).
#include <gtest/gtest.h>

#include <cmath>

#include "igaprep/core/error.h"
#include "igaprep/param/cut_loops.h"
#include "igaprep/param/thin_sides.h"
#include "igaprep/models/shapes.h"

namespace {

using igaprep::mesh::TriMesh;

// Largest |z| over the loops' vertices.
double loops_max_height(const igaprep::param::CutLoops& cut) {
  double h = 0.0;
  for (const auto& loop : cut.loops)
    for (int v : loop) h = std::max(h, std::abs(cut.surface.V(v, 2)));
  return h;
}

TEST(ThinSides, APancakesSidesAreItsTopAndBottomAndTheLoopItsRim) {
  const TriMesh pancake = igaprep::models::make_ellipsoid(10.0, 6.0, 0.8, 4);
  const igaprep::param::ThinSides sides = igaprep::param::thin_sides(pancake);
  EXPECT_GT(std::abs(sides.up.z()), 1.0 - 1e-9);
  EXPECT_LT(sides.median_thickness, 1.6);
  EXPECT_EQ(sides.flipped_pieces, 0);
  // Every vertex clearly above or below the rim is on its own side.
  const double sign = sides.up.z() > 0 ? 1.0 : -1.0;
  int wrong = 0, counted = 0;
  for (Eigen::Index i = 0; i < pancake.V.rows(); ++i) {
    const double z = pancake.V(i, 2);
    if (std::abs(z) < 0.2) continue;
    ++counted;
    wrong += (sign * z > 0) != (sides.vertex_value(i) > 0);
  }
  EXPECT_GT(counted, 100);
  EXPECT_EQ(wrong, 0);
  const igaprep::param::CutLoops cut =
      igaprep::param::cut_by_field(pancake, sides.vertex_value, "pancake", "thin sides");
  EXPECT_EQ(cut.loops.size(), 1u);
  EXPECT_LT(loops_max_height(cut), 0.2);  // the rim is z = 0; 0.2 = a quarter of the half-thickness
}

TEST(ThinSides, AFlatRingGetsItsInnerAndOuterRimAsTwoLoops) {
  const TriMesh ring = igaprep::models::make_torus(5.0, 0.5, 96, 24);
  const igaprep::param::ThinSides sides = igaprep::param::thin_sides(ring);
  const igaprep::param::CutLoops cut = igaprep::param::cut_by_field(ring, sides.vertex_value, "ring", "thin sides");
  EXPECT_EQ(cut.genus, 1);
  ASSERT_EQ(cut.loops.size(), 2u);
  EXPECT_LT(loops_max_height(cut), 0.1);
  // One loop on the inner equator (radius 4.5), one on the outer (5.5).
  std::vector<double> radius;
  for (const auto& loop : cut.loops) {
    double r = 0.0;
    for (int v : loop) r += cut.surface.V.row(v).head<2>().norm();
    radius.push_back(r / static_cast<double>(loop.size()));
  }
  std::sort(radius.begin(), radius.end());
  EXPECT_NEAR(radius[0], 4.5, 0.02);
  EXPECT_NEAR(radius[1], 5.5, 0.02);
}

TEST(CutByField, AFieldOfOneSignIsRefused) {
  const TriMesh sphere = igaprep::models::make_ellipsoid(1.0, 1.0, 1.0, 2);
  const Eigen::VectorXd positive = Eigen::VectorXd::Ones(sphere.V.rows());
  EXPECT_THROW(igaprep::param::cut_by_field(sphere, positive, "sphere", "a constant"), igaprep::Error);
}

}  // namespace

namespace {

// n points on the circle of radius r in the plane z = 0, counter-clockwise seen from +z.
std::vector<Eigen::Vector3d> circle(double rx, double ry, int n) {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n;
    p.emplace_back(rx * std::cos(t), ry * std::sin(t), 0.0);
  }
  return p;
}

TEST(CutByWaypoints, EightPointsOnAPancakesRimGiveItsRimAsTheLoop) {
  const TriMesh pancake = igaprep::models::make_ellipsoid(10.0, 6.0, 0.8, 4);
  const igaprep::param::CutLoops cut = igaprep::param::cut_by_waypoints(pancake, {circle(10.0, 6.0, 8)}, "pancake");
  ASSERT_EQ(cut.loops.size(), 1u);
  EXPECT_LT(loops_max_height(cut), 0.3);  // smoothed edge paths near the rim z = 0 (half-thickness 0.8)
  // R+ on the left of the loop as drawn (counter-clockwise from +z): the top.
  for (Eigen::Index i = 0; i < cut.surface.V.rows(); ++i)
    if (std::abs(cut.surface.V(i, 2)) > 0.5) EXPECT_EQ(cut.vertex_side(i) > 0, cut.surface.V(i, 2) > 0) << i;
}

TEST(CutByWaypoints, ARingsTwoRimsFromTwoDrawnLoops) {
  const TriMesh ring = igaprep::models::make_torus(5.0, 0.5, 96, 24);
  const igaprep::param::CutLoops cut =
      igaprep::param::cut_by_waypoints(ring, {circle(5.5, 5.5, 8), circle(4.5, 4.5, 8)}, "ring");
  EXPECT_EQ(cut.loops.size(), 2u);
  EXPECT_LT(loops_max_height(cut), 0.2);
}

TEST(CutByWaypoints, PointsSnappingToOneVertexAreRefused) {
  const TriMesh pancake = igaprep::models::make_ellipsoid(10.0, 6.0, 0.8, 3);
  const Eigen::Vector3d p(10.0, 0.0, 0.0);
  try {
    igaprep::param::cut_by_waypoints(pancake, {{p, p, p}}, "pancake");
    FAIL() << "no error";
  } catch (const igaprep::Error& e) {
    EXPECT_NE(std::string(e.what()).find("waypoint loop 0: the waypoints snap to fewer than 3"), std::string::npos)
        << e.what();
  }
}

}  // namespace
