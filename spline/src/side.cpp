#include "igaprep/spline/side.h"

#include <string>

#include "igaprep/core/error.h"

namespace igaprep::spline {

namespace {

void require_valid(const Side& s) {
  if (!s.valid())
    throw bad_input("patch side " + std::to_string(s.index()) + " is outside 1..6 (u0, u1, v0, v1, w0, w1)");
}

}  // namespace

Side Side::of(int direction, bool parameter) {
  if (direction < 0 || direction > 2)
    throw bad_input("side of direction " + std::to_string(direction) + ": the direction must be 0, 1 or 2");
  return Side(2 * direction + (parameter ? 2 : 1));
}

int Side::direction() const {
  require_valid(*this);
  return (index_ - 1) / 2;
}

bool Side::parameter() const {
  require_valid(*this);
  return (index_ - 1) % 2 == 1;
}

int Side::array_index() const {
  require_valid(*this);
  return index_ - 1;
}

Side Side::opposite() const { return of(direction(), !parameter()); }

std::array<int, 2> Side::tangent_directions() const {
  switch (direction()) {
    case 0: return {{1, 2}};
    case 1: return {{0, 2}};
    default: return {{0, 1}};
  }
}

}  // namespace igaprep::spline
