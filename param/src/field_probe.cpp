#include "igaprep/param/field_probe.h"

#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Dense>

#include "igaprep/core/error.h"
#include "tet_grid.h"

namespace igaprep::param {

FieldProbe::FieldProbe(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const TetTopology& topology,
                       const Eigen::VectorXd& u, const Eigen::MatrixXd& vertex_gradient)
    : V_(V), T_(T), topo_(topology), u_(u), grad_(vertex_gradient), grid_(std::make_shared<detail::TetGrid>(V, T)) {}

int FieldProbe::locate(const Eigen::Vector3d& p, int* hint, Eigen::Vector4d* bary) const {
  // A hinted query is a short step from a known tet: a walk that leaves the
  // mesh means p is outside. A fresh one asks the grid (a walk from afar
  // may leave a non-convex mesh), then the grid again with the looser rule
  // of locate_in_tets's scan (a scan of every tet for each point outside H
  // was most of the param stage on meshes of 100,000 tets).
  const bool fresh = !(hint && *hint >= 0 && *hint < T_.rows());
  int c = -1;
  if (fresh) {
    c = grid_->locate(p, bary);
    if (c < 0) c = grid_->locate_as_scan(p, bary);
  } else {
    c = locate_in_tets(V_, T_, topo_, p, *hint, bary, false);
  }
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
  // The smooth value (recovered gradients) in general; the P1 value where
  // the smooth one is off: at a start point whose smooth value is not above
  // the level, and once a step has jumped across a layer thinner than itself
  // (the recovered gradients of a layer a tet or two thick are unreliable).
  bool p1 = false;
  auto field = [&](double t) {
    const Eigen::Vector3d p = start + t * direction;
    double u = p1 ? value(p, &hint) : smooth_value(p, &hint);
    // A hinted walk can leave a non-convex mesh on its way to a point inside
    // it (across a re-entrant edge of the boundary): the grid decides. Rays
    // are few; in every query of the streamlines this look-up cost the
    // propeller's param stage 2.5 times its time and changed no figure.
    if (std::isnan(u)) {
      Eigen::Vector4d b;
      const int c = grid_->locate(p, &b);
      if (c >= 0) {
        hint = c;
        u = p1 ? value(p, &hint) : smooth_value(p, &hint);
      }
    }
    return u;
  };
  double lo = 0.0;
  double u0 = field(0.0);
  if (std::isnan(u0)) hint = -1, u0 = field(0.0);  // the hint was far away: search afresh
  if (!(u0 > level) && !std::isnan(u0)) {
    p1 = true;
    u0 = field(0.0);
  }
  if (!(u0 > level)) throw fail("the start point is not above the level");
  for (double t = step; t <= max_length + step; t += step) {
    double u = field(t);
    if (std::isnan(u)) {  // the last point inside, by bisection, must be below the level
      double in = lo, out = t;
      for (int it = 0; it < 60 && out - in > 1e-12 * step; ++it) {
        const double mid = 0.5 * (in + out);
        (std::isnan(field(mid)) ? out : in) = mid;
      }
      p1 = true;
      u = field(in);
      if (std::isnan(u) || u > level) throw fail("the ray leaves the mesh first");
      t = in;
    }
    if (u <= level) {
      double hi = t;
      for (int it = 0; it < 60 && hi - lo > 1e-12 * step; ++it) {
        const double mid = 0.5 * (lo + hi);
        (field(mid) > level ? lo : hi) = mid;
      }
      if (start_hint) *start_hint = hint;
      return start + hi * direction;
    }
    lo = t;
  }
  throw fail("the level is not reached within the maximum length");
}

}  // namespace igaprep::param
