// The cage of a model's surface: topology, orientation, knot intervals and
// creases on boxes whose cages are known exactly.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "igaprep/spline/tnurcc_cage.h"
#include "igaprep/spline/tnurcc_limit.h"
#include "tnurcc/tnurcc_models.h"

namespace {

using namespace igaprep::spline;

// Volume enclosed by a closed cage (faces split into triangles), positive
// when the faces are oriented outward.
double signed_volume(const Cage& c) {
  double v = 0.0;
  for (const auto& f : c.faces)
    for (int k : {1, 2}) {
      const Eigen::Vector3d a = c.points.row(f[0]), b = c.points.row(f[k]), d = c.points.row(f[k + 1]);
      v += a.dot(b.cross(d)) / 6.0;
    }
  return v;
}

TEST(TnurccCage, BoxIsClosedWithThreeValentCornersAndCreasedEdges) {
  const MultiPatch mp = tnurcc_test::boxes(1, 4);
  const Cage c = surface_cage(mp, 0);
  // 7 control points per direction: the surface points of a 7^3 grid.
  EXPECT_EQ(c.points.rows(), 7 * 7 * 7 - 5 * 5 * 5);
  EXPECT_EQ(c.faces.size(), 6u * 36u);
  EXPECT_EQ(long(c.points.rows()) - long(c.edges.size()) + long(c.faces.size()), 2);  // a sphere
  const std::vector<int> valence = vertex_valences(c);
  EXPECT_EQ(std::count(valence.begin(), valence.end(), 3), 8);
  EXPECT_EQ(std::count(valence.begin(), valence.end(), 4), long(c.points.rows()) - 8);
  EXPECT_NEAR(signed_volume(c), 1.0, 1e-14);
  for (const auto& e : c.edges) {
    EXPECT_NE(e.faces[1], -1);
    EXPECT_NEAR(e.interval, 0.25, 1e-15);  // the clamped ends' zero intervals take the interior's
  }
  EXPECT_TRUE(opposite_edge_violations(c).empty());
  // The box's 12 edges, 6 cage edges each, turn by 90 degrees: creases.
  const long creases = std::count_if(c.edges.begin(), c.edges.end(),
                                     [](const CageEdge& e) { return e.sharpness == kInfiniteSharpness; });
  EXPECT_EQ(creases, 12 * 6);
  CageOptions never;
  never.crease_angle = 90.5;
  const Cage smooth = surface_cage(mp, 0, never);
  EXPECT_EQ(std::count_if(smooth.edges.begin(), smooth.edges.end(), [](const CageEdge& e) { return e.sharpness > 0; }),
            0);
}

TEST(TnurccCage, PatchesSideBySideShareTheirEdgeRows) {
  const MultiPatch mp = tnurcc_test::boxes(2, 2);
  ASSERT_EQ(mp.interfaces.size(), 1u);
  const Cage c = surface_cage(mp, 0);
  // A 9 x 5 x 5 grid of control points (two 5^3 nets sharing a layer): its surface.
  EXPECT_EQ(c.points.rows(), 9 * 5 * 5 - 7 * 3 * 3);
  EXPECT_EQ(long(c.points.rows()) - long(c.edges.size()) + long(c.faces.size()), 2);
  EXPECT_NEAR(signed_volume(c), 2.0, 1e-14);
  // The flat joins between the boxes are not creases; the box's edges are.
  const long creases = std::count_if(c.edges.begin(), c.edges.end(),
                                     [](const CageEdge& e) { return e.sharpness > 0; });
  EXPECT_EQ(creases, 4 * 8 + 8 * 4);
  EXPECT_TRUE(opposite_edge_violations(c).empty());
}

TEST(TnurccCage, RefusesALabelWithoutSidesAndNonManifoldFaces) {
  MultiPatch mp = tnurcc_test::boxes(1, 2);
  mp.labels.push_back("unused");
  EXPECT_THROW(surface_cage(mp, 1), igaprep::Error);
  EXPECT_THROW(surface_cage(mp, 2), igaprep::Error);
  Cage c;
  c.points = Eigen::MatrixXd::Random(6, 3);
  c.faces = {{{0, 1, 2, 3}}, {{0, 1, 4, 5}}, {{1, 0, 5, 2}}};
  EXPECT_THROW(build_cage_edges(c), igaprep::Error);
}

TEST(TnurccCage, OppositeEdgeRuleNamesTheFace) {
  Cage c;
  c.points = Eigen::MatrixXd::Random(4, 3);
  c.faces = {{{0, 1, 2, 3}}};
  build_cage_edges(c);
  EXPECT_TRUE(opposite_edge_violations(c).empty());
  c.edges[c.face_edges[0][2]].interval = 2.0;
  const auto v = opposite_edge_violations(c);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NE(v[0].find("face 0"), std::string::npos);
}

}  // namespace

namespace {

using namespace igaprep::spline;

TEST(TnurccCage, NonUniformKnotsGiveTheirIntervalsOrEqualOnesWhenAsked) {
  MultiPatch mp = tnurcc_test::boxes(1, 3);
  mp.patches[0].knots[0] = {0, 0, 0, 0, 0.2, 0.7, 1, 1, 1, 1};  // intervals 0.2, 0.5, 0.3 along u
  const Cage c = surface_cage(mp, 0);
  EXPECT_FALSE(uniform_intervals(c));
  EXPECT_TRUE(opposite_edge_violations(c).empty());  // still a valid T-NURCC cage
  std::vector<double> seen;
  for (const auto& e : c.edges) seen.push_back(e.interval);
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }),
             seen.end());
  // u: 0.2 (the clamped end's zero taking the nearest), 0.5, 0.3; v and w: 1/3.
  ASSERT_EQ(seen.size(), 4u);
  EXPECT_NEAR(seen[0], 0.2, 1e-12);
  EXPECT_NEAR(seen[1], 0.3, 1e-12);
  EXPECT_NEAR(seen[2], 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(seen[3], 0.5, 1e-12);
  EXPECT_THROW(limit_stencils(c, {{0, 0.5, 0.5}}), igaprep::Error);
  CageOptions equal;
  equal.equal_intervals = true;
  const Cage e = surface_cage(mp, 0, equal);
  EXPECT_TRUE(uniform_intervals(e));
  EXPECT_EQ(e.edges[0].interval, 1.0);
  EXPECT_NO_THROW(limit_stencils(e, {{0, 0.5, 0.5}}));
}

}  // namespace
