#include "igaprep/param/streamline_column.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "igaprep/core/error.h"

namespace igaprep::param {

double StreamlineColumn::arc_at_level(double level) const {
  const Eigen::Index k = w.size();
  if (level >= w(0)) return 0.0;
  // T1 is where the column ends. w is 0 before that inside a tet whose four
  // vertices lie on T1 (a sliver TetGen leaves against a concave part of
  // T1), and the first point at w = 0 would lie up to a tet inside.
  if (level <= 0.0) return arc(k - 1);
  for (Eigen::Index j = 0; j + 1 < k; ++j) {
    if (w(j + 1) <= level) {
      const double dw = w(j) - w(j + 1);
      const double t = dw > 0.0 ? (w(j) - level) / dw : 1.0;
      return (1.0 - t) * arc(j) + t * arc(j + 1);
    }
  }
  return arc(k - 1);
}

Eigen::Vector3d StreamlineColumn::at_arc(double s) const {
  const Eigen::Index k = arc.size();
  if (s <= 0.0) return path.row(0).transpose();
  const Eigen::Index j = std::upper_bound(arc.data(), arc.data() + k, s) - arc.data();  // arc(j - 1) <= s < arc(j)
  if (j >= k) return path.row(k - 1).transpose();
  const double len = arc(j) - arc(j - 1);
  const double t = len > 0.0 ? (s - arc(j - 1)) / len : 0.0;
  return ((1.0 - t) * path.row(j - 1) + t * path.row(j)).transpose();
}

StreamlineColumn trace_column(const FieldProbe& probe, const Eigen::Vector3d& start, double step, int* start_hint,
                              double stop_level, int max_steps) {
  auto fail = [&](const std::string& why) {
    std::ostringstream m;
    m << "streamline from (" << start.transpose() << "): " << why;
    return check_failed(m.str());
  };
  int hint = start_hint ? *start_hint : -1;
  // Unit descent direction at x; false outside H. Where w was flattened
  // around an interior extremum (w_field.h) its gradient is zero: the
  // streamline crosses that plateau straight, in its last direction.
  Eigen::Vector3d last = Eigen::Vector3d::Zero();
  auto direction = [&](const Eigen::Vector3d& x, Eigen::Vector3d* d) {
    Eigen::Vector3d g;
    if (!probe.gradient(x, &hint, &g)) return false;
    const double len = g.norm();
    if (len > 0.0) {
      *d = -g / len;
      return true;
    }
    if (last.norm() == 0.0)
      throw bad_input("param: the streamline from (" + std::to_string(start.x()) + ", " + std::to_string(start.y()) + ", " +
                      std::to_string(start.z()) + ") starts where the gradient of w vanishes (a flattened extremum of the "
                      "discrete w); a finer tet mesh ('tetmesh.max_volume') or other cut loops ('midsurface.cut') can remove it");
    *d = last;
    return true;
  };
  std::vector<Eigen::Vector3d> pts{start};
  std::vector<double> ws{probe.value(start, &hint)};
  if (std::isnan(ws[0])) hint = -1, ws[0] = probe.value(start, &hint);  // the hint was far away
  if (std::isnan(ws[0])) throw fail("the start point lies outside H");
  if (start_hint) *start_hint = hint;
  auto column = [&] {
    StreamlineColumn c;
    c.path.resize(static_cast<Eigen::Index>(pts.size()), 3);
    c.w.resize(static_cast<Eigen::Index>(pts.size()));
    c.arc = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(pts.size()));
    for (std::size_t j = 1; j < pts.size(); ++j)
      c.arc(static_cast<Eigen::Index>(j)) = c.arc(static_cast<Eigen::Index>(j) - 1) + (pts[j] - pts[j - 1]).norm();
    for (std::size_t j = 0; j < pts.size(); ++j) {
      c.path.row(static_cast<Eigen::Index>(j)) = pts[j].transpose();
      c.w(static_cast<Eigen::Index>(j)) = j == 0 ? ws[j] : std::min(ws[j], c.w(static_cast<Eigen::Index>(j) - 1));
    }
    return c;
  };
  Eigen::Vector3d x = start;
  for (int it = 0; it < max_steps; ++it) {
    // Classical Runge-Kutta (4th order): streamlines that start close
    // together (the samples next to a block's edge) must stay in order.
    Eigen::Vector3d d1, d2, d3, d4, next;
    bool inside = direction(x, &d1);
    if (inside) inside = direction(x + 0.5 * step * d1, &d2);
    if (inside) inside = direction(x + 0.5 * step * d2, &d3);
    if (inside) inside = direction(x + step * d3, &d4);
    next = inside ? Eigen::Vector3d(x + step / 6.0 * (d1 + 2.0 * d2 + 2.0 * d3 + d4)) : Eigen::Vector3d(x + step * d1);
    if ((next - x).norm() > 0.0) last = (next - x).normalized();
    if (inside && probe.locate(next, &hint, nullptr) >= 0) {
      x = next;
      pts.push_back(x);
      ws.push_back(probe.value(x, &hint));
      if (stop_level > 0.0 && ws.back() <= stop_level) return column();
      continue;
    }
    // The step leaves H: bisect for the crossing of the outer boundary (T1).
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 50; ++k) {
      const double mid = 0.5 * (lo + hi);
      (probe.locate(x + mid * (next - x), &hint, nullptr) >= 0 ? lo : hi) = mid;
    }
    const Eigen::Vector3d end = x + lo * (next - x);
    pts.push_back(end);
    ws.push_back(probe.value(end, &hint));
    return column();
  }
  // Caught at an extremum of the discrete w inside the solid (the decompose
  // stage counts them): a property of the mesh and cut, which the user can
  // change, not a failed check of a built model.
  std::ostringstream m;
  m << "param: the streamline from (" << start.transpose() << ") finds no exit through T1 within " << max_steps
    << " steps: it is caught where the discrete w has an extremum inside the solid; a finer tet mesh "
       "('tetmesh.max_volume') or other cut loops ('midsurface.cut') can remove it";
  throw bad_input(m.str());
}

}  // namespace igaprep::param
