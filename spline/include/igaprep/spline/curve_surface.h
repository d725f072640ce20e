#pragma once
// B-spline / NURBS curves and surfaces in 3-D (same conventions as Patch:
// control points u fastest, Cartesian, weights separate and empty for a
// B-spline), and the boundary faces and edges of a volume patch as such.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

struct Curve {
  int degree = 0;
  std::vector<double> knots;      // length n + p + 1
  Eigen::MatrixXd control_points; // n x 3
  Eigen::VectorXd weights;        // empty, or n

  int count() const { return static_cast<int>(knots.size()) - degree - 1; }
  bool rational() const { return weights.size() > 0; }
};

struct Surface {
  std::array<int, 2> degrees{{0, 0}};
  std::array<std::vector<double>, 2> knots;
  Eigen::MatrixXd control_points; // (n_u*n_v) x 3, u fastest
  Eigen::VectorXd weights;        // empty, or n_u*n_v

  int count(int dir) const { return static_cast<int>(knots[dir].size()) - degrees[dir] - 1; }
  int index(int i, int j) const { return i + count(0) * j; }
  bool rational() const { return weights.size() > 0; }
};

// Indices of the control points of patch `p` on `side`, ordered u fastest over
// side.tangent_directions() (the face's own control-point order).
std::vector<int> side_control_points(const Patch& p, Side side);

// The face of a volume on `side` as a surface: surface direction 0/1 =
// side.tangent_directions()[0/1], same knots, points and weights. Exact.
Surface boundary_surface(const Patch& p, Side side);

// The edge of a volume running along `direction`, at the low (false) or high
// (true) end of the two other directions (taken in increasing order). Exact.
Curve boundary_curve(const Patch& p, int direction, bool end_first, bool end_second);

// The edge of a surface on side 1..4 (u0, u1, v0, v1) as a curve. Exact.
Curve boundary_curve(const Surface& s, Side side);

// A surface or curve as a degenerate Patch (degree 0, one element in the
// missing directions), so that every Patch algorithm applies to it.
Patch as_patch(const Surface& s);
Patch as_patch(const Curve& c);

}  // namespace igaprep::spline
