// A knot family that comes back to itself reversed: a solid ring whose
// square cross-section turns by half a turn on the way round (two patches).
// Its knot vectors across the section must stay symmetric.
#include <gtest/gtest.h>

#include <cmath>

#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/reduce_model.h"
#include "reduce_test_util.h"

namespace {

using namespace igaprep::spline;
using namespace reduce_test;

constexpr double kPi = 3.14159265358979323846;

// The ring at angle theta, section coordinates (r, h) in [-1/2, 1/2]^2
// bulged by an odd map (so half a turn maps (r, h) to (-r, -h) and no knot
// of the section is exact) and turned by theta / 2.
Eigen::Vector3d twisted_ring(double theta, double r0, double h0) {
  const double r = r0 + 0.8 * r0 * r0 * r0, h = h0 + 0.8 * h0 * h0 * h0;
  const double c = std::cos(theta / 2), s = std::sin(theta / 2);
  const double radial = 3.0 + r * c - h * s, z = r * s + h * c;
  return {radial * std::cos(theta), radial * std::sin(theta), z};
}

// Half of the ring, theta from `from` to from + pi; control points at the
// Greville points of the map.
Patch half_ring(double from) {
  Patch p;
  p.degrees = {{3, 2, 2}};
  p.knots = {uniform_knot_vector(3, 7), uniform_knot_vector(2, 4), uniform_knot_vector(2, 4)};
  std::array<std::vector<double>, 3> g;
  for (int d = 0; d < 3; ++d) g[d] = greville_abscissae(p.knots[d], p.degrees[d]);
  p.control_points.resize(p.count(0) * p.count(1) * p.count(2), 3);
  for (int k = 0; k < p.count(2); ++k)
    for (int j = 0; j < p.count(1); ++j)
      for (int i = 0; i < p.count(0); ++i)
        p.control_points.row(p.index(i, j, k)) = twisted_ring(from + kPi * g[0][i], g[1][j] - 0.5, g[2][k] - 0.5);
  return p;
}

MultiPatch twisted_ring_model() {
  MultiPatch mp;
  mp.patches = {half_ring(0.0), half_ring(kPi)};
  mp.labels = {"outer"};
  mp.materials = {{"solid", 1.0, 0.3}};
  Interface straight;  // theta = pi
  straight.patch_a = 0;
  straight.side_a = kU1;
  straight.patch_b = 1;
  straight.side_b = kU0;
  straight.orient = {{0, 1, 1}};
  Interface turned = straight;  // theta = 2 pi = 0: the section half a turn round
  turned.patch_a = 1;
  turned.patch_b = 0;
  turned.orient = {{0, 0, 0}};
  mp.interfaces = {straight, turned};
  for (int p = 0; p < 2; ++p)
    for (Side s : {kV0, kV1, kW0, kW1}) mp.boundaries.push_back({p, s, 0});
  return mp;
}

const KnotFamily& family_of(const std::vector<KnotFamily>& families, int patch, int direction) {
  for (const KnotFamily& f : families)
    for (const FamilyMember& m : f.members)
      if (m.patch == patch && m.direction == direction) return f;
  throw std::runtime_error("no family");
}

TEST(TwistedRing, ItsSectionFamiliesComeBackReversed) {
  const MultiPatch mp = twisted_ring_model();
  ASSERT_TRUE(check_conformity(mp, 1e-12).conforming) << check_conformity(mp, 1e-12).problems.at(0);
  const std::vector<KnotFamily> families = knot_families(mp);
  EXPECT_EQ(families.size(), 4u);  // u of each half, and the section's v and w
  for (int d : {1, 2}) {
    const KnotFamily& f = family_of(families, 0, d);
    EXPECT_EQ(f.members.size(), 2u);
    EXPECT_TRUE(f.self_reversed);
    EXPECT_TRUE(f.consistent);
  }
  EXPECT_FALSE(family_of(families, 0, 0).self_reversed);
}

TEST(TwistedRing, ASymmetricPairOfKnotsComesBackOut) {
  const MultiPatch original = twisted_ring_model();
  MultiPatch refined = original;
  const KnotFamily f = family_of(knot_families(original), 0, 1);
  insert_family_knot(refined, f, 0.3);
  insert_family_knot(refined, f, 0.7);
  ASSERT_TRUE(check_conformity(refined, 1e-12).conforming);
  ModelReductionOptions o;
  o.tolerance = 1e-12;
  const ModelReduction r = reduce_model(refined, o);
  for (int p = 0; p < 2; ++p) EXPECT_EQ(r.model.patches[p].knots[1], original.patches[p].knots[1]) << "patch " << p;
  EXPECT_EQ(r.knots_removed, 1);  // the pair, removed as one
  EXPECT_LE(r.bound, 1e-12);
  EXPECT_TRUE(check_conformity(r.model, 0.0).conforming);
}

TEST(TwistedRing, AnAsymmetricKnotLeavesTheFamilyAlone) {
  MultiPatch mp = twisted_ring_model();
  const KnotFamily f = family_of(knot_families(mp), 0, 1);
  insert_family_knot(mp, f, 0.3);  // the turned interface no longer matches
  ModelReductionOptions o;
  o.tolerance = 1.0;  // anything may go, but not this family's knots
  const ModelReduction r = reduce_model(mp, o);
  EXPECT_EQ(r.inconsistent_families, 1);
  for (int p = 0; p < 2; ++p) EXPECT_EQ(r.model.patches[p].knots[1], mp.patches[p].knots[1]);
}

}  // namespace
