#pragma once
// The Jacobian repair as one optimization (optimize_jacobian.h): every
// movable control point next to a low sample moves at once, by L-BFGS
// (Ceres' GradientProblemSolver) on
//   E = sum over samples s of max(0, target + 0.05 - q_s)^2 + sum over points of c |y|^2,
// q the check's scaled Jacobian, each point moved by at most its neighbour
// distance (docs/decomposition.md, section 6). Not installed API.
#include <string>
#include <vector>

#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/optimize_jacobian.h"
#include "repair_common.h"

namespace igaprep::spline::detail {

struct JointRepairResult {
  int variables = 0;   // control points optimized
  int iterations = 0;  // L-BFGS iterations
  std::string stop;    // why it stopped
};

// Inputs: the model, its global numbering (global_numbering), its global
// control points' copies and constraints (repair_common.h), `slide` for the surfaces, the target, each
// patch's sample grid, and at most `iterations` L-BFGS
// iterations. Control points whose support holds a sample below
// target + 0.1 move: free ones in space, sliding ones along their surface
// (in the tangent plane found through `slide`, then put back by it), fixed
// ones not. Sets moved[g] for each global control point that moved.
// progress, if given, hears of each iteration.
JointRepairResult joint_repair(MultiPatch& mp, const GlobalNumbering& num, const std::vector<std::vector<Copy>>& copies,
                               const std::vector<int>& cons, const SlideFn& slide, double target,
                               const std::vector<SampleGrid>& grids, int iterations, std::vector<char>* moved,
                               const ProgressCallback& progress = {});

}  // namespace igaprep::spline::detail
