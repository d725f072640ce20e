#include "igaprep/param/field_probe.h"

#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Dense>

#include "igaprep/core/error.h"

namespace igaprep::param {

int FieldProbe::locate(const Eigen::Vector3d& p, int* hint, Eigen::Vector4d* bary) const {
  // A hinted query is a short step from a known tet: a walk that leaves the
  // mesh means p is outside. A fresh one may leave a non-convex mesh: scan.
  const bool fresh = !(hint && *hint >= 0 && *hint < T_.rows());
  const int c = locate_in_tets(V_, T_, topo_, p, fresh ? -1 : *hint, bary, fresh);
  if (c >= 0 && hint) *hint = c;
  return c;
}

double FieldProbe::value(const Eigen::Vector3d& p, int* hint) const {
  Eigen::Vector4d b;
  const int c = locate(p, hint, &b);
  if (c < 0) return std::numeric_limits<double>::quiet_NaN();
  double s = 0.0;
  for (int k = 0; k < 4; ++k) s += b(k) * u_(T_(c, k));
  return s;
}

double FieldProbe::smooth_value(const Eigen::Vector3d& p, int* hint) const {
  Eigen::Vector4d b;
  const int c = locate(p, hint, &b);
  if (c < 0) return std::numeric_limits<double>::quiet_NaN();
  double s = 0.0;
  for (int k = 0; k < 4; ++k) {
    const int v = T_(c, k);
    s += b(k) * (u_(v) + grad_.row(v).dot((p - V_.row(v).transpose()).transpose()));
  }
  return s;
}

bool FieldProbe::gradient(const Eigen::Vector3d& p, int* hint, Eigen::Vector3d* g) const {
  Eigen::Vector4d b;
  const int c = locate(p, hint, &b);
  if (c < 0) return false;
  bool on_ridge = false;
  for (int k = 0; k < 4; ++k) on_ridge |= u_(T_(c, k)) >= ridge_;
  if (on_ridge) {  // the tet's own (P1) gradient: solve E^T g = du
    Eigen::Matrix3d E;
    Eigen::Vector3d du;
    for (int k = 0; k < 3; ++k) {
      E.row(k) = V_.row(T_(c, k + 1)) - V_.row(T_(c, 0));
      du(k) = u_(T_(c, k + 1)) - u_(T_(c, 0));
    }
    *g = E.fullPivLu().solve(du);
    return true;
  }
  g->setZero();
  for (int k = 0; k < 4; ++k) *g += b(k) * grad_.row(T_(c, k)).transpose();
  return true;
}

Eigen::Vector3d FieldProbe::ray_to_level(const Eigen::Vector3d& start, const Eigen::Vector3d& direction, double level,
                                         double step, double max_length, int* start_hint) const {
  int hint = start_hint ? *start_hint : -1;
  auto fail = [&](const char* why) {
    std::ostringstream m;
    m << "ray to the level " << level << " from (" << start.transpose() << ") along (" << direction.transpose()
      << "): " << why;
    return check_failed(m.str());
  };
  double lo = 0.0;
  double u0 = smooth_value(start, &hint);
  if (std::isnan(u0)) hint = -1, u0 = smooth_value(start, &hint);  // the hint was far away: search afresh
  if (!(u0 > level)) throw fail("the start point is not above the level");
  for (double t = step; t <= max_length + step; t += step) {
    const double u = smooth_value(start + t * direction, &hint);
    if (std::isnan(u)) throw fail("the ray leaves the mesh first");
    if (u <= level) {
      double hi = t;
      for (int it = 0; it < 60 && hi - lo > 1e-12 * step; ++it) {
        const double mid = 0.5 * (lo + hi);
        (smooth_value(start + mid * direction, &hint) > level ? lo : hi) = mid;
      }
      if (start_hint) *start_hint = hint;
      return start + hi * direction;
    }
    lo = t;
  }
  throw fail("the level is not reached within the maximum length");
}

}  // namespace igaprep::param
