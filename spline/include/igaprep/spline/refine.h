#pragma once
// Refinement that leaves the geometry exactly unchanged: knot insertion
// (Boehm / Oslo, Piegl & Tiller A5.4) and degree elevation. Volumes are
// refined direction by direction; rational patches in homogeneous coordinates.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

// ---- 1-D core on coefficient matrices ----
// P is n x m: row i holds every coefficient attached to basis function i
// (e.g. all control points of a volume with index i along the refined
// direction, in homogeneous coordinates). Outputs the new knots and rows.

// Inserts the knots X (any order, repeats allowed; each must lie inside the
// domain and the resulting multiplicity may not exceed p; bad_input otherwise).
void insert_knots_1d(const std::vector<double>& U, int p, const Eigen::MatrixXd& P,
                     const std::vector<double>& X, std::vector<double>* U_new, Eigen::MatrixXd* P_new);

// Raises the degree by t >= 0: every knot multiplicity grows by t.
void elevate_degree_1d(const std::vector<double>& U, int p, const Eigen::MatrixXd& P, int t,
                       std::vector<double>* U_new, Eigen::MatrixXd* P_new);

// ---- patches, surfaces, curves ----
Patch insert_knots(const Patch& patch, int dir, const std::vector<double>& X);
Patch insert_knot(const Patch& patch, int dir, double u, int times = 1);
Patch elevate_degree(const Patch& patch, int dir, int t = 1);
// The patch on finer knot vectors: each of `knots` must hold the patch's
// knots (as a multiset, same ends); the missing ones are inserted. bad_input
// when a knot vector is not nested.
Patch refine_to_knots(const Patch& patch, const std::array<std::vector<double>, 3>& knots);
// The knots of `fine` that `coarse` lacks (multisets); bad_input unless
// coarse is nested in fine with the same ends.
std::vector<double> missing_knots(const std::vector<double>& fine, const std::vector<double>& coarse);
// h-refinement: `k` new knots evenly inside every element, each direction.
Patch refine_uniformly(const Patch& patch, int k = 1);

Surface insert_knots(const Surface& s, int dir, const std::vector<double>& X);
Surface elevate_degree(const Surface& s, int dir, int t = 1);
Curve insert_knots(const Curve& c, const std::vector<double>& X);
Curve elevate_degree(const Curve& c, int t = 1);

// Patch <-> rows along one direction (homogeneous w*x, w*y, w*z, w when rational).
// rows is n_dir x (other counts * dim), used by refinement and knot removal.
Eigen::MatrixXd patch_rows(const Patch& patch, int dir);
void set_patch_rows(Patch* patch, int dir, const Eigen::MatrixXd& rows, int n_dir);

}  // namespace igaprep::spline
