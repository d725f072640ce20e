// Boundary faces and edges, and curves/surfaces as degenerate patches.
#include "igaprep/spline/curve_surface.h"

#include "igaprep/core/error.h"

namespace igaprep::spline {

std::vector<int> side_control_points(const Patch& p, Side side) {
  const int d = side.direction();
  const auto t = side.tangent_directions();
  const int fixed = side.parameter() ? p.count(d) - 1 : 0;
  std::vector<int> out;
  out.reserve(static_cast<size_t>(p.count(t[0])) * p.count(t[1]));
  int ijk[3];
  ijk[d] = fixed;
  for (int b = 0; b < p.count(t[1]); ++b)
    for (int a = 0; a < p.count(t[0]); ++a) {
      ijk[t[0]] = a;
      ijk[t[1]] = b;
      out.push_back(p.index(ijk[0], ijk[1], ijk[2]));
    }
  return out;
}

Surface boundary_surface(const Patch& p, Side side) {
  const auto t = side.tangent_directions();
  Surface s;
  for (int k = 0; k < 2; ++k) {
    s.degrees[k] = p.degrees[t[k]];
    s.knots[k] = p.knots[t[k]];
  }
  const std::vector<int> idx = side_control_points(p, side);
  s.control_points.resize(static_cast<long>(idx.size()), 3);
  if (p.rational()) s.weights.resize(static_cast<long>(idx.size()));
  for (size_t i = 0; i < idx.size(); ++i) {
    s.control_points.row(i) = p.control_points.row(idx[i]);
    if (p.rational()) s.weights[i] = p.weights[idx[i]];
  }
  return s;
}

Curve boundary_curve(const Patch& p, int direction, bool end_first, bool end_second) {
  if (direction < 0 || direction > 2) throw bad_input("boundary_curve: direction must be 0, 1 or 2");
  int others[2], k = 0;
  for (int d = 0; d < 3; ++d)
    if (d != direction) others[k++] = d;
  Curve c;
  c.degree = p.degrees[direction];
  c.knots = p.knots[direction];
  const int n = p.count(direction);
  c.control_points.resize(n, 3);
  if (p.rational()) c.weights.resize(n);
  int ijk[3];
  ijk[others[0]] = end_first ? p.count(others[0]) - 1 : 0;
  ijk[others[1]] = end_second ? p.count(others[1]) - 1 : 0;
  for (int i = 0; i < n; ++i) {
    ijk[direction] = i;
    const int g = p.index(ijk[0], ijk[1], ijk[2]);
    c.control_points.row(i) = p.control_points.row(g);
    if (p.rational()) c.weights[i] = p.weights[g];
  }
  return c;
}

Curve boundary_curve(const Surface& s, Side side) {
  if (!side.valid() || side.direction() > 1)
    throw bad_input("surface side " + std::to_string(side.index()) + " is outside 1..4");
  const Patch p = as_patch(s);
  // A u-side's curve runs along v, a v-side's along u.
  return boundary_curve(p, side.direction() == 0 ? 1 : 0, side.parameter(), false);
}

Patch as_patch(const Surface& s) {
  Patch p;
  p.degrees = {{s.degrees[0], s.degrees[1], 0}};
  p.knots = {{s.knots[0], s.knots[1], {0.0, 1.0}}};
  p.control_points = s.control_points;
  p.weights = s.weights;
  return p;
}

Patch as_patch(const Curve& c) {
  Patch p;
  p.degrees = {{c.degree, 0, 0}};
  p.knots = {{c.knots, {0.0, 1.0}, {0.0, 1.0}}};
  p.control_points = c.control_points;
  p.weights = c.weights;
  return p;
}

}  // namespace igaprep::spline
