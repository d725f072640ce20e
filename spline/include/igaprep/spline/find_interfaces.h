#pragma once
// Multipatch topology from geometry: which patch sides coincide (interfaces
// with their orientation) and the merging of control points that coincide to
// round-off, for models assembled from independently fitted patches.
#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

// Makes every group of control points lying on patch sides (of any patch)
// within tol of each other exactly equal (to the group's first point, in
// patch/index order). Returns the number of points moved and sets
// *max_move to the largest move. Interior control points are untouched.
int stitch_control_points(MultiPatch& mp, double tol, double* max_move = nullptr);

// Replaces mp.interfaces by every pair of patch sides whose control points
// coincide within tol under some orientation (the dirmap/orient that
// check_conformity accepts). Sides with no partner are left to the caller
// (boundaries). Surface indices are left at -1.
void find_interfaces(MultiPatch& mp, double tol);

}  // namespace igaprep::spline
