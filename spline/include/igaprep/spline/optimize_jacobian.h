#pragma once
// Raises the lowest scaled Jacobians of a fitted multipatch model by moving
// its control points (after the fit, before the check).
//
// Where the decomposition's blocks meet T1 at narrow angles (docs/
// decomposition.md, "Known limits") the fitted patches have scaled Jacobians
// near 0.1 and below; the samples there cannot be fitted better. Here the
// control points next to samples below the target move: first all at once,
// by L-BFGS on a penalty of the samples below the target (joint_repair.h),
// then, for what is left, Gauss-Seidel sweeps that move one control point
// at a time to raise the lowest sample in its support (a move is kept only
// if that minimum rises). A control point inside the model moves freely,
// one on T1 or a material interface along that surface (through `slide`),
// so that the narrow corners of the layout on those surfaces can open. A
// shared control point moves once for all patches that hold it: interfaces
// stay conforming. Then every patch with a moved control point is sampled
// twice as densely; where that finds a point more than 0.1 below the target
// (a fold between the first samples), both steps run again with those
// patches on the dense samples. Where dense samples are still negative, a
// last pass aims at them alone (target 0), kept only if it raises their
// lowest sample.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "igaprep/core/progress.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/side.h"

namespace igaprep::spline {

struct JacobianOptimizationOptions {
  // Control points with a sampled scaled Jacobian below this in their support
  // move (0: only those next to negative samples; the run skips the step when
  // the case's target is 0). The check samples more densely (a 5-point grid
  // and the Gauss points per element): 0.35 here gave 0.29 there on ring2 and torus3.
  double target = 0.35;
  int iterations = 200;  // at most this many L-BFGS iterations of the joint optimization (0: sweeps only)
  int sweeps = 40;       // then at most this many sweeps over the control points (0: none)
  int points = 5;   // sample points per element and direction, ends included (>= 2); 3 let folds through between them
  // Told each L-BFGS iteration ("Jacobian repair (optimization)", of
  // `iterations`) and each sweep ("Jacobian repair (sweeps)", of `sweeps`).
  ProgressCallback progress;
};

struct JacobianOptimizationResult {
  double min_before = 1.0, min_after = 1.0;  // lowest sampled scaled Jacobian
  // Sample points below the target. Where the target is not reached (a fold
  // held by fixed control points) the count can grow while the minimum rises.
  int below_before = 0, below_after = 0;
  int moved_points = 0;                      // distinct control points that moved
  long long moves = 0;
  int sweeps = 0;                            // sweeps run (both passes)
  int joint_variables = 0, joint_iterations = 0;  // the joint optimization's control points and iterations (both passes)
  std::string joint_stop;                    // why its last pass stopped
  int dense_patches = 0;                     // patches optimized again on twice as dense samples
  int focus_patches = 0;                     // patches with negative dense samples after that, in the last pass (target 0)
  bool focus_kept = true;                    // whether that pass raised their lowest sample (else it was undone)
  double focus_min_before = 0.0, focus_min_after = 0.0;  // that lowest sample before the pass and as left
  double max_move = 0.0;                     // largest distance a control point moved
  // Why the last pass of sweeps stopped: "the target reached", "no control point can
  // move", "no progress in 10 sweeps" or "the sweep limit".
  std::string stop_reason;
};

// The position a control point on surface `surface` (a label index: 0 = T1)
// may take when it would move from `from` to `to`.
using SlideFn = std::function<Eigen::Vector3d(int surface, const Eigen::Vector3d& from, const Eigen::Vector3d& to)>;

// Inputs: the model with its interfaces and labelled boundaries found
// (find_interfaces; an interface's `surface` >= 0 puts its control points on
// that surface, a boundary side on its label); `slide` for those; sides
// (patch, side 1..6) whose control points must stay (collapsed sides).
// Control points on two different surfaces stay. The scaled Jacobian is
// spline::scaled_jacobian, the check's; sample points where it is
// degenerate (degenerate_jacobian: collapsed sides; the check reports 0)
// are left out, as no move can raise them.
JacobianOptimizationResult optimize_jacobians(MultiPatch& mp, const SlideFn& slide,
                                              const std::vector<std::pair<int, Side>>& fixed_sides,
                                              const JacobianOptimizationOptions& options = {});

// The last pass of optimize_jacobians alone, for folds its samples missed:
// `witnesses` are points (patch, its parameters) where det J was found
// negative elsewhere (the check's certificate finds them between the
// samples). Each witness's coordinates, and those halfway from it to the
// next dense samples, join its patch's dense samples in every direction; the patches whose dense samples are then negative are
// repaired with target 0, kept only if their lowest sample rises (focus_*
// in the result; min_before / min_after include the witnesses' samples).
// Inputs as optimize_jacobians; options.points sets the dense grid (2
// points - 1 per element and direction). Throws bad_input for a witness
// naming no patch of the model.
JacobianOptimizationResult repair_at_witnesses(MultiPatch& mp, const SlideFn& slide,
                                               const std::vector<std::pair<int, Side>>& fixed_sides,
                                               const std::vector<std::pair<int, Eigen::Vector3d>>& witnesses,
                                               const JacobianOptimizationOptions& options = {});

}  // namespace igaprep::spline
