#pragma once
// Knot families of a multipatch model: the (patch, direction) pairs that must
// keep one knot vector for the model to stay conforming. Across an interface
// the two directions of patch a that run along its side are tied to the
// directions of patch b they map to (Interface::dirmap), reversed where the
// interface reverses them (Interface::orient). A family can come back to
// itself reversed (a ring of patches with a twist): its knot vector must then
// stay symmetric.
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

struct FamilyMember {
  int patch = 0;
  int direction = 0;
  bool reversed = false;  // runs against the family's first member
};

struct KnotFamily {
  std::vector<FamilyMember> members;  // first member: the smallest (patch, direction)
  bool self_reversed = false;         // tied to itself reversed: knots stay symmetric
  // Every member has the first member's degree and knot vector (each mapped
  // to [0, 1], reversed members reversed, within 1e-10). A family without it
  // is not conforming and cannot be reduced.
  bool consistent = true;
};

// Every (patch, direction) of the model lies in exactly one family; families
// are ordered by their first member.
std::vector<KnotFamily> knot_families(const MultiPatch& mp);

// A knot vector's interior knots mapped to [0, 1] of its domain, in the
// family's sense (reversed when `reversed`), increasing.
std::vector<double> family_parameters(const Patch& p, int direction, bool reversed);

}  // namespace igaprep::spline
