// The 2D polycube parameterization of M0trim (seed paper, section 4.2).
#include <algorithm>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "igaprep/param/sheet_topology.h"
#include "test_midsurface_cache.h"

using namespace igaprep::param;
using midsurface_test::cached;
using midsurface_test::kVariants;
using midsurface_test::Variant;
using midsurface_test::variant_name;

namespace {
class Polycube : public ::testing::TestWithParam<Variant> {};
}  // namespace

TEST_P(Polycube, BijectiveIsoParametricAndTiled) {
  const auto& r = cached(GetParam().model, GetParam().variant).result;
  const auto& S = r.m0trim.mesh;
  const Polycube2D& pc = r.polycube;
  const int g = GetParam().genus;
  ASSERT_EQ(pc.uv.rows(), S.V.rows());
  // Four corners and segments per loop, one outer loop.
  ASSERT_EQ(static_cast<int>(pc.loops.size()), g + 1);
  EXPECT_EQ(std::count_if(pc.loops.begin(), pc.loops.end(), [](const PolycubeLoop& l) { return l.outer; }), 1);
  EXPECT_EQ(static_cast<int>(pc.segments.size()), 4 * (g + 1));
  EXPECT_EQ(static_cast<int>(pc.domain.holes.size()), g);
  // Every triangle positively oriented in (u, v), computed here from the coordinates.
  double min_area = 1e300, total = 0.0;
  for (int f = 0; f < S.F.rows(); ++f) {
    const Eigen::Vector2d a = pc.uv.row(S.F(f, 0)), b = pc.uv.row(S.F(f, 1)), c = pc.uv.row(S.F(f, 2));
    const double A = 0.5 * ((b - a)(0) * (c - a)(1) - (c - a)(0) * (b - a)(1));
    min_area = std::min(min_area, A);
    total += A;
  }
  EXPECT_GT(min_area, 0.0);
  EXPECT_GT(pc.min_jacobian, 0.0);
  // Bijective with a margin: no near-fold. Jacobian = (u, v) area / 3D area,
  // computed here; the smallest must stay above 1e-4 of the median.
  std::vector<double> jac;
  for (int f = 0; f < S.F.rows(); ++f) {
    const Eigen::Vector3d p = S.V.row(S.F(f, 0)), q = S.V.row(S.F(f, 1)), s = S.V.row(S.F(f, 2));
    const Eigen::Vector2d a = pc.uv.row(S.F(f, 0)), b = pc.uv.row(S.F(f, 1)), c = pc.uv.row(S.F(f, 2));
    const double A3 = 0.5 * (q - p).cross(s - p).norm();
    ASSERT_GT(A3, 0.0) << "face " << f << " has zero 3D area";
    jac.push_back(0.5 * ((b - a)(0) * (c - a)(1) - (c - a)(0) * (b - a)(1)) / A3);
  }
  const double jmin = *std::min_element(jac.begin(), jac.end());
  std::nth_element(jac.begin(), jac.begin() + static_cast<std::ptrdiff_t>(jac.size() / 2), jac.end());
  const double jmed = jac[jac.size() / 2];
  ASSERT_GT(jmed, 0.0);
  RecordProperty("min_over_median_jacobian", std::to_string(jmin / jmed));
  RecordProperty("uv_weights", pc.weights);
  EXPECT_GT(jmin / jmed, 1e-4) << "min Jacobian " << jmin << ", median " << jmed << " (" << pc.weights << ")";
  // The image covers the domain: total area = W H - holes.
  double domain_area = pc.domain.width * pc.domain.height;
  for (const auto& h : pc.domain.holes) domain_area -= (h(2) - h(0)) * (h(3) - h(1));
  EXPECT_NEAR(total, domain_area, 1e-9 * domain_area);
  // Each boundary segment iso-parametric, the other coordinate monotone within the side.
  for (const auto& s : pc.segments) {
    const int c = s.u_iso ? 0 : 1;
    for (int v : s.vertices) EXPECT_NEAR(pc.uv(v, c), s.value, 1e-12);
    ASSERT_GE(s.vertices.size(), 2u);
  }
  // Rectangles tile the domain: inside it, outside every hole, no overlaps, areas add up.
  double rect_area = 0.0;
  for (std::size_t i = 0; i < pc.rectangles.size(); ++i) {
    const Eigen::Vector4d& R = pc.rectangles[i];
    EXPECT_GT(R(2), R(0));
    EXPECT_GT(R(3), R(1));
    EXPECT_GE(R(0), 0.0);
    EXPECT_GE(R(1), 0.0);
    EXPECT_LE(R(2), pc.domain.width);
    EXPECT_LE(R(3), pc.domain.height);
    rect_area += (R(2) - R(0)) * (R(3) - R(1));
    for (const auto& h : pc.domain.holes)
      EXPECT_TRUE(R(2) <= h(0) || R(0) >= h(2) || R(3) <= h(1) || R(1) >= h(3)) << "rectangle " << i << " in a hole";
    for (std::size_t j = i + 1; j < pc.rectangles.size(); ++j) {
      const Eigen::Vector4d& Q = pc.rectangles[j];
      EXPECT_TRUE(R(2) <= Q(0) || Q(2) <= R(0) || R(3) <= Q(1) || Q(3) <= R(1)) << i << " overlaps " << j;
    }
  }
  EXPECT_NEAR(rect_area, domain_area, 1e-12 * domain_area);
  EXPECT_EQ(static_cast<int>(pc.rectangles.size()), g == 0 ? 1 : (g == 1 ? 8 : static_cast<int>(pc.rectangles.size())));
  if (g == 3) EXPECT_GE(pc.rectangles.size(), 10u);  // 3 holes in a row: at least 3 x 3 + ... cells
}

// torus3's M0trim, three holes in a row, mapped with the cuts from its
// holes' corners (the fallback where the plain map folds): 4 cuts a hole,
// each from a hole corner, every triangle positive, the holes where they were.
TEST(PolycubeHoleCuts, TheThreeHolesCutFromTheirCornersMapBijectively) {
  const auto& r = cached("torus3").result;
  igaprep::mesh::TriMesh sheet = r.m0trim.mesh;
  Polycube2D pc = r.polycube;
  pc.domain = rectilinear_domain(sheet, pc.loops);
  ASSERT_TRUE(map_with_hole_cuts(sheet, pc));
  ASSERT_EQ(pc.hole_cuts.size(), 12u);
  for (std::size_t h = 0; h < 3; ++h)
    for (std::size_t k = 0; k < 4; ++k) {
      const Eigen::Vector4d& box = pc.domain.holes[h];
      const Eigen::Vector2d start = pc.uv.row(pc.hole_cuts[4 * h + k].front()).transpose();
      const Eigen::Vector2d corner(k == 0 || k == 3 ? box(0) : box(2), k < 2 ? box(1) : box(3));
      EXPECT_NEAR((start - corner).norm(), 0.0, 1e-9) << "hole " << h << " cut " << k;
      EXPECT_GE(pc.hole_cuts[4 * h + k].size(), 2u);
    }
  EXPECT_GT(pc.min_jacobian, 0.0) << pc.weights;
  EXPECT_EQ(pc.jacobian.size(), sheet.F.rows());
  EXPECT_NE(pc.weights.find("cut from the holes' corners"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Models, Polycube,
                         ::testing::ValuesIn(kVariants), variant_name);

TEST(PolycubeCorners, UserPointsSnapToTheNearestBoundaryVertex) {
  const auto& r = cached("sphere2").result;
  const auto& S = r.m0trim.mesh;
  const auto& L = r.polycube.loops[0];
  // The automatic corners, moved slightly off the sheet, give the same corners back.
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 4; ++k)
    points.push_back(S.V.row(L.vertices[L.corners[k]]).transpose() + Eigen::Vector3d(0.0, 0.0, 1e-3));
  const auto loops = corners_from_points(S, {L.vertices}, points, r.polycube.frame);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].corners, L.corners);
  EXPECT_EQ(loops[0].sides, L.sides);
  // Three points for a loop is refused.
  points.pop_back();
  try {
    corners_from_points(S, {L.vertices}, points, r.polycube.frame);
    FAIL();
  } catch (const igaprep::Error& e) {
    EXPECT_NE(std::string(e.what()).find("got 3 corner points"), std::string::npos) << e.what();
  }
}

// A long domain's grid is cut into rectangles at most max_aspect times the
// longest interval across: 10 x 1 with a hole [4, 6] x [0.25, 0.75] has
// columns 4, 2, 4 and rows 0.25, 0.5, 0.25 (the longest across: 0.5). At 4
// each 4 becomes two of 2 (5 columns); at 2 every column is cut to 1.
TEST(DomainRectangles, LongIntervalsAreCutIntoEqualParts) {
  RectilinearDomain d;
  d.width = 10.0;
  d.height = 1.0;
  d.holes.push_back(Eigen::Vector4d(4.0, 0.25, 6.0, 0.75));
  EXPECT_EQ(domain_rectangles(d).size(), 8u);       // 3 x 3 less the hole
  EXPECT_EQ(domain_rectangles(d, 8.0).size(), 8u);  // 4 is within 8 x 0.5
  for (const auto& [aspect, count, longest] : {std::tuple{4.0, 14u, 2.0}, std::tuple{2.0, 28u, 1.0}}) {
    const std::vector<Eigen::Vector4d> cut = domain_rectangles(d, aspect);
    EXPECT_EQ(cut.size(), count) << aspect;  // 5 x 3 less the hole; 10 x 3 less its 2 cells
    double area = 0.0, widest = 0.0;
    for (const auto& r : cut) {
      area += (r(2) - r(0)) * (r(3) - r(1));
      widest = std::max(widest, r(2) - r(0));
    }
    EXPECT_NEAR(area, 10.0 - 1.0, 1e-12) << aspect;
    EXPECT_NEAR(widest, longest, 1e-12) << aspect;
  }
}

// Extra lines cut the whole grid like the holes' sides; one on the domain's
// edge or within a millionth of a line already there adds nothing.
TEST(DomainRectangles, ExtraLinesCutTheWholeGrid) {
  RectilinearDomain d;
  d.width = 10.0;
  d.height = 1.0;
  d.holes.push_back(Eigen::Vector4d(4.0, 0.25, 6.0, 0.75));
  GridLines extra;
  extra.u = {2.0, 4.0 + 1e-7, 10.0};
  extra.v = {0.5};
  const std::vector<Eigen::Vector4d> cut = domain_rectangles(d, 0.0, extra);
  EXPECT_EQ(cut.size(), 14u);  // 4 columns x 4 rows less the hole's 2 cells
  double area = 0.0;
  for (const auto& r : cut) area += (r(2) - r(0)) * (r(3) - r(1));
  EXPECT_NEAR(area, 10.0 - 1.0, 1e-12);
  EXPECT_EQ(domain_rectangles(d, 0.0, GridLines{{0.0, 1e-9}, {}}).size(), 8u);
}

// Sides of different boxes within the tolerance across the domain move onto
// their mean (a bottom arm's right side and a top arm's left side; two
// bottom arms' outer ends), onto the outer rectangle's side when that is
// one of them, and two sides of one box stay apart: the grid then has no
// sliver column between the arms.
TEST(MergeCloseSides, NearlyCoincidentSidesOfDifferentBoxesBecomeOne) {
  RectilinearDomain d;
  d.width = 10.0;
  d.height = 4.0;
  d.arms = {DomainArm{DomainSide::Bottom, 2.0, 3.0, 1.0}, DomainArm{DomainSide::Bottom, 5.0, 6.0, 1.01},
            arm_from_box(DomainSide::Top, Eigen::Vector4d(3.02, 4.0, 4.0, 5.0), 10.0, 4.0)};
  d.holes = {Eigen::Vector4d(7.0, 1.0, 7.01, 2.0), Eigen::Vector4d(8.5, 2.0, 9.0, 3.97)};
  auto narrowest_column = [](const std::vector<Eigen::Vector4d>& rects) {
    double w = 1e9;
    for (const auto& r : rects)
      if (r(0) < 6.0) w = std::min(w, r(2) - r(0));
    return w;
  };
  EXPECT_NEAR(narrowest_column(domain_rectangles(d)), 0.02, 1e-12);
  merge_close_sides(d, 0.05);
  EXPECT_DOUBLE_EQ(arm_box(d, d.arms[0])(2), 3.01);
  EXPECT_DOUBLE_EQ(arm_box(d, d.arms[2])(0), 3.01);
  EXPECT_DOUBLE_EQ(d.arms[0].length, 1.005);
  EXPECT_DOUBLE_EQ(d.arms[1].length, 1.005);
  EXPECT_DOUBLE_EQ(d.arms[0].from, 2.0);
  EXPECT_DOUBLE_EQ(d.arms[2].length, 1.0);
  EXPECT_EQ(d.holes[0], Eigen::Vector4d(7.0, 1.0, 7.01, 2.0));
  EXPECT_EQ(d.holes[1], Eigen::Vector4d(8.5, 2.0, 9.0, 4.0));
  EXPECT_NEAR(narrowest_column(domain_rectangles(d)), 0.99, 1e-12);  // [2, 3.01]
}

// Four unit right triangles in 3D (area 0.5 each); the squeezed share is
// the area under a tenth of the area-weighted median Jacobian.
TEST(SqueezedShare, CountsTheAreaUnderATenthOfTheMedianScale) {
  igaprep::mesh::TriMesh m;
  m.V.resize(6, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 0, 0, 2, 1, 0;
  m.F.resize(4, 3);
  m.F << 0, 1, 2, 1, 3, 2, 1, 4, 3, 4, 5, 3;
  Eigen::VectorXd J(4);
  J << 1.0, 2.0, 0.09, 1.5;  // median 1.0 by area (half the area lies at or below it)
  EXPECT_DOUBLE_EQ(squeezed_share(m, J), 0.25);
  J(2) = 0.16;  // over 0.1 * 1.0
  EXPECT_DOUBLE_EQ(squeezed_share(m, J), 0.0);
  EXPECT_DOUBLE_EQ(squeezed_share(m, J, 0.5), 0.25);
}
