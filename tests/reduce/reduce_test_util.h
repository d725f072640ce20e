#pragma once
// Knot families for the reduction tests: inserting a knot into a whole family
// (so the model stays conforming) and comparing models patch by patch.
#include <gtest/gtest.h>

#include "igaprep/spline/knot_families.h"
#include "igaprep/spline/multipatch_topology.h"
#include "igaprep/spline/refine.h"

namespace reduce_test {

using namespace igaprep::spline;

// Inserts the knot at t in [0, 1] of the family's sense into every member.
inline void insert_family_knot(MultiPatch& mp, const KnotFamily& f, double t) {
  for (const FamilyMember& m : f.members) {
    Patch& p = mp.patches[static_cast<std::size_t>(m.patch)];
    const auto& U = p.knots[static_cast<std::size_t>(m.direction)];
    const double a = U[static_cast<std::size_t>(p.degrees[m.direction])];
    const double b = U[static_cast<std::size_t>(p.count(m.direction))];
    p = insert_knot(p, m.direction, m.reversed ? b - t * (b - a) : a + t * (b - a));
  }
}

// The first family with at least `members` members and a reversed one.
inline KnotFamily family_with_reversed_member(const MultiPatch& mp, std::size_t members) {
  for (const KnotFamily& f : knot_families(mp)) {
    bool reversed = false;
    for (const FamilyMember& m : f.members) reversed = reversed || m.reversed;
    if (f.members.size() >= members && reversed && f.consistent) return f;
  }
  ADD_FAILURE() << "no family with " << members << " members and a reversed one";
  return {};
}

// Largest control-point distance between two models of the same knots.
inline double control_point_distance(const MultiPatch& a, const MultiPatch& b) {
  double d = 0.0;
  for (std::size_t p = 0; p < a.patches.size(); ++p) {
    EXPECT_EQ(a.patches[p].knots, b.patches[p].knots) << "patch " << p;
    if (a.patches[p].knots != b.patches[p].knots) return 1e300;
    d = std::max(d, (a.patches[p].control_points - b.patches[p].control_points).rowwise().norm().maxCoeff());
  }
  return d;
}

}  // namespace reduce_test
