#pragma once
// What the two Jacobian repairs (optimize_jacobian.cpp's sweeps and
// joint_repair.cpp's one optimization) share: which control points may move
// and how, and where they sample the scaled Jacobian. Not installed API.
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/multipatch_topology.h"
#include "igaprep/spline/scaled_jacobian.h"

namespace igaprep::spline::detail {

// A control point's constraint: free, fixed, or (>= 0) the surface it slides on.
constexpr int kFree = -1, kFixed = -2;

// One patch's copy of a global control point: its local index and grid indices.
struct Copy {
  int patch, local, a, b, c;
};

// The scaled Jacobian the repairs raise (the check's), or +infinity where J
// is degenerate (a collapsed side): the check reports 0 there, but no
// control point can raise it, so the repairs leave those points out.
inline double repair_scaled(const Eigen::Matrix3d& J) {
  return scaled_jacobian_or(J, std::numeric_limits<double>::infinity());
}

// Per global control point, its copies in the patches that hold it.
std::vector<std::vector<Copy>> control_point_copies(const MultiPatch& mp, const GlobalNumbering& num);

// Per global control point: kFree, the surface it slides on (labelled
// boundary sides, interfaces on a surface), or kFixed (fixed sides, two
// surfaces, or a surface without a slide function).
std::vector<int> control_point_constraints(const MultiPatch& mp, const GlobalNumbering& num,
                                           const std::vector<std::pair<int, Side>>& fixed_sides, bool can_slide);

// Sample parameters of one direction: `points` per element, ends included,
// each element boundary once.
std::vector<double> repair_sample_params(const std::vector<double>& knots, int points);
// A patch's sample parameters per direction: a tensor grid.
using SampleGrid = std::array<std::vector<double>, 3>;
// repair_sample_params in each direction of a patch, with each of `extra`'s
// parameter points added to every direction (so the grid holds them).
SampleGrid repair_sample_grid(const Patch& p, int points, const std::vector<Eigen::Vector3d>& extra = {});

// Distance from x to the nearest distinct neighbouring control point in any copy's grid
// (+infinity when every neighbour coincides with x).
double nearest_neighbour(const MultiPatch& mp, const std::vector<Copy>& copies, const Eigen::Vector3d& x);

}  // namespace igaprep::spline::detail
