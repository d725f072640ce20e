#pragma once
// Knot removal with an error bound (Tiller / Piegl & Tiller A5.8, generalised
// to volumes: a knot of direction d is removed across all control-point rows
// of the volume at once). The error of a removal is measured exactly: the
// removed patch is re-refined to the old knots and compared control point by
// control point; by partition of unity and non-negativity this bounds the
// change of the volume everywhere (for NURBS a bound through the weights, see
// knot_removal.cpp). Errors of successive removals are added up.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

// Bound of |x(u) - x'(u)| over the whole domain for two patches in one basis
// (the same degrees and knots): the largest control-point distance for
// B-splines, a bound through the weights for NURBS (knot_removal.cpp);
// infinite when `after` has a weight <= 0 or a non-finite point.
double change_bound(const Patch& before, const Patch& after);

// 1-D core: removes the knot U[r] once from rows P (n x m, homogeneous when
// rational). Returns the max row distance (Euclidean over each row's
// `block`-wide groups of columns; block = m means whole row) between P and the
// result re-inserted, i.e. the control-point change. Does not check a tolerance.
double remove_knot_once_1d(const std::vector<double>& U, int p, const Eigen::MatrixXd& P, int r,
                           int block, std::vector<double>* U_new, Eigen::MatrixXd* P_new);

// Removes the interior knot u of direction `dir` up to `times` times, each
// removal only while the accumulated bound stays <= tol. Returns how many were
// removed; *error (if given) receives the accumulated bound (0 when none).
int remove_knot(Patch* patch, int dir, double u, int times, double tol, double* error = nullptr);

struct ReductionReport {
  int removed = 0;                        // knots removed in total
  std::array<int, 3> removed_per_dir{{0, 0, 0}};
  double error_bound = 0.0;               // the volume moved by at most this much
};
// Data reduction: greedily removes interior knots of all directions while the
// accumulated bound stays <= tol. `directions` selects which may be reduced.
ReductionReport reduce_knots(Patch* patch, double tol,
                             std::array<bool, 3> directions = {{true, true, true}});

}  // namespace igaprep::spline
