// Sheet-consistent knot removal on small models built for it: a knot comes
// out of every member of its family or of none, interfaces stay conforming.
#include <gtest/gtest.h>

#include <cmath>

#include "export/test_model.h"
#include "igaprep/core/error.h"
#include "igaprep/spline/reduce_model.h"
#include "reduce_test_util.h"

namespace {

using namespace igaprep::spline;
using namespace reduce_test;

TEST(KnotFamilies, TieTheDirectionsAlongEachInterfaceWithTheirSense) {
  const MultiPatch mp = igaprep::test::make_test_model();
  const std::vector<KnotFamily> families = knot_families(mp);
  // u of patch 1 (domain [0, 2]) runs against u of patch 3 (interface 1 v1 / 3 v1).
  bool found = false;
  for (const KnotFamily& f : families) {
    if (f.members.size() != 2 || f.members[0].patch != 1 || f.members[0].direction != 0) continue;
    found = true;
    EXPECT_EQ(f.members[1].patch, 3);
    EXPECT_EQ(f.members[1].direction, 0);
    EXPECT_TRUE(f.members[1].reversed);
    EXPECT_TRUE(f.consistent);
    EXPECT_FALSE(f.self_reversed);
  }
  EXPECT_TRUE(found);
  // Every (patch, direction) in exactly one family: 4 pair families and w.
  std::size_t members = 0;
  for (const KnotFamily& f : families) members += f.members.size();
  EXPECT_EQ(members, 12u);
  EXPECT_EQ(families.size(), 5u);
}

TEST(ReduceModel, AnInsertedKnotFamilyComesBackOutAtTolerance1e12) {
  const MultiPatch original = igaprep::test::make_test_model();
  const KnotFamily f = family_with_reversed_member(original, 2);  // includes rational patch 3
  MultiPatch refined = original;
  insert_family_knot(refined, f, 0.37);
  ASSERT_TRUE(check_conformity(refined, 1e-12).conforming);

  ModelReductionOptions o;
  o.tolerance = 1e-12;
  const ModelReduction from_original = reduce_model(original, o);
  const ModelReduction from_refined = reduce_model(refined, o);
  // The knot is gone from every member and the model is the one the
  // reduction of the original gives (which keeps every knot of the family).
  for (const FamilyMember& m : f.members)
    EXPECT_EQ(from_refined.model.patches[m.patch].knots[m.direction], original.patches[m.patch].knots[m.direction]);
  EXPECT_LT(control_point_distance(from_refined.model, from_original.model), 1e-12);
  EXPECT_EQ(from_refined.knots_removed, from_original.knots_removed + 1);
  EXPECT_LE(from_refined.bound, 1e-12);
  EXPECT_LE(from_refined.measured, from_refined.bound + 1e-15);
  const ConformityReport c = check_conformity(from_refined.model, 0.0);
  EXPECT_TRUE(c.conforming) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_FALSE(from_refined.model.has_solution);
}

TEST(ReduceModel, AKnotThatFailsInOneMemberIsRemovedFromNone) {
  MultiPatch mp = igaprep::test::make_test_model();
  const KnotFamily f = family_with_reversed_member(mp, 2);
  insert_family_knot(mp, f, 0.37);
  // Move an inner control point of the last member near the new knot: that
  // member alone no longer lies in the coarse space.
  const FamilyMember& last = f.members.back();
  Patch& p = mp.patches[last.patch];
  const int n = p.count(last.direction);
  std::array<int, 3> ijk{{1, 1, 1}};
  ijk[last.direction] = n / 2;
  p.control_points(p.index(ijk[0], ijk[1], ijk[2]), 2) += 1e-3;
  ASSERT_TRUE(check_conformity(mp, 1e-12).conforming);

  ModelReductionOptions o;
  o.tolerance = 1e-6;
  const ModelReduction r = reduce_model(mp, o);
  for (const FamilyMember& m : f.members)
    EXPECT_EQ(r.model.patches[m.patch].knots[m.direction], mp.patches[m.patch].knots[m.direction])
        << "patch " << m.patch << " direction " << m.direction;
  EXPECT_LE(r.bound, 1e-6);
  EXPECT_TRUE(check_conformity(r.model, 0.0).conforming);
}

TEST(ReduceModel, APatchTheCheckRefusesKeepsItsKnots) {
  MultiPatch mp = igaprep::test::make_test_model();
  const KnotFamily f = family_with_reversed_member(mp, 2);
  insert_family_knot(mp, f, 0.37);
  ModelReductionOptions o;
  o.tolerance = 1e-12;
  const int refused = f.members.back().patch;
  const ModelReduction r = reduce_model(mp, o, [&](int patch, const Patch&) { return patch != refused; });
  for (const FamilyMember& m : f.members)
    EXPECT_EQ(r.model.patches[m.patch].knots[m.direction], mp.patches[m.patch].knots[m.direction]);
  EXPECT_GE(r.removals_undone, 1);
  EXPECT_TRUE(check_conformity(r.model, 0.0).conforming);
}

TEST(ReduceModel, RefusesANegativeTolerance) {
  const MultiPatch mp = igaprep::test::make_test_model();
  ModelReductionOptions o;
  o.tolerance = -1.0;
  EXPECT_THROW(reduce_model(mp, o), igaprep::Error);
}

}  // namespace
