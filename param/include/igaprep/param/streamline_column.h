#pragma once
// A streamline of -grad w from a point down to T1 (w = 0), with w along it:
// the shell patches of the volume layout sample it at the w-levels of their
// layers (w = (i - 1)/n on Ti), so the layer faces lie exactly on the Ti;
// between them by arc length, which is smooth along the path (w sampled
// along a path through P1 tets is not).
// The streamline follows the continuous (vertex-interpolated) gradient, so
// neighbouring streamlines never merge.
#include <Eigen/Core>

#include "igaprep/param/field_probe.h"

namespace igaprep::param {

struct StreamlineColumn {
  Eigen::MatrixXd path;  // k x 3, from the start point to T1
  Eigen::VectorXd w;     // k: w at each point, made non-increasing (running minimum)
  Eigen::VectorXd arc;   // k: arc length from the start

  // Arc length where w first reaches level (linear along the path); 0 for
  // level >= w(0), the whole length for level <= w(end) and for level 0
  // (T1, where the column ends).
  double arc_at_level(double level) const;
  // The point at arc length s (clamped to the path).
  Eigen::Vector3d at_arc(double s) const;
  Eigen::Vector3d at_level(double level) const { return at_arc(arc_at_level(level)); }
};

// Inputs: probe of H's w-field, start point (inside H), step length (model
// units), a tet near the start (or null), maximum number of steps. Output: the column, integrated with the
// classical Runge-Kutta rule along the unit direction -g/|g| until it leaves H through
// its outer boundary T1 (the last point is on T1, found by bisection).
// Throws check_failed naming the start point when it lies outside H, and
// bad_input naming the case keys that change it when the gradient vanishes
// at the start or the step budget runs out (an extremum of the discrete w
// inside the solid).
// With stop_level > 0 the column ends at the first point where w <= stop_level.
StreamlineColumn trace_column(const FieldProbe& probe, const Eigen::Vector3d& start, double step,
                              int* start_hint = nullptr, double stop_level = 0.0, int max_steps = 100000);

}  // namespace igaprep::param
