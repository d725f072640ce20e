#pragma once
// Multipatch topology: validation of a model, the control-point
// correspondence across an interface (G+Smo convention: dirmap, orient),
// the conformity check, and a global numbering of control points in which
// points shared by an interface are counted once.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

// Throws bad_input naming the patch/direction/interface at fault: knot
// vectors, control-point and weight counts, non-positive weights, non-finite
// coordinates, material and label indices, interface sides and dirmaps.
void validate_patch(const Patch& p, const std::string& what = "patch");
void validate_multipatch(const MultiPatch& mp);

// For control point `local_a` (index in patch a, must lie on side_a) the index
// of the coincident control point of patch b. Works for every dirmap/orient.
int map_to_neighbour(const MultiPatch& mp, const Interface& itf, int local_a);

// All pairs (index in patch a, index in patch b) of an interface, in the order
// of side_control_points(patch a, side_a). Throws bad_input when the sides'
// control-point counts do not match after the direction map.
std::vector<std::pair<int, int>> interface_point_pairs(const MultiPatch& mp, const Interface& itf);

struct ConformityReport {
  bool conforming = true;
  double max_deviation = 0.0;          // largest interface control-point distance found
  std::vector<std::string> problems;   // one line per fault, naming the interface, e.g.
                                       // "interface 3 (patch 1 side 2 / patch 4 side 1):
                                       //  control point 17 / 5 off by 1.2e-03"
};
// Matching knot vectors after orientation (each normalised to its own domain,
// compared to 1e-10 relative) and coincident control points (and equal
// weights) within tol. Never throws for non-conforming input; structural
// errors (bad side, count mismatch) are reported as problems too.
ConformityReport check_conformity(const MultiPatch& mp, double tol);

// Control points summed over the patches (points shared by interfaces counted
// in each patch, as the model files store them).
long control_point_count(const MultiPatch& mp);

struct GlobalNumbering {
  int count = 0;                          // number of distinct control points
  std::vector<std::vector<int>> global;   // global[patch][local] in 0..count-1
  std::vector<int> patch_offset;          // first global number introduced by each patch
};
// Union-find over all interface correspondences; numbers are assigned in
// order of first appearance (patch 0 local 0 first), so they are deterministic.
GlobalNumbering global_numbering(const MultiPatch& mp);

// The control points by global number (count x 3; a shared point from the
// last patch that holds it: on a conforming model its copies agree).
Eigen::MatrixXd global_points(const MultiPatch& mp, const GlobalNumbering& gn);

}  // namespace igaprep::spline
