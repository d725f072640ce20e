#pragma once
// Data reduction of a whole multipatch model that keeps it conforming: knots
// are removed per knot family (knot_families.h), from every member at once,
// so the control nets of every interface stay identical.
//
// A patch is reduced by least squares: for the kept knots of each direction,
// the coarse control points whose re-insertion comes closest to the original
// ones (the first and last row of each direction kept exactly, so a side's
// points depend only on that side's points and both patches of an interface
// compute the same side). Projected from the original each time, so errors do
// not add up over removals. The bound of a patch is the control-point change
// after re-inserting every removed knot (change_bound), or where that is above
// the tolerance, the change in the basis with every span halved once more
// (tighter): no point of the volume moves farther. A removal is made only if every patch it touches
// keeps its bound within the tolerance; knots whose removal would cost least
// go first.
#include <array>
#include <functional>
#include <vector>

#include "igaprep/core/progress.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

struct ModelReductionOptions {
  double tolerance = 0.0;          // model units: the largest move of any point of the model
  int samples_per_direction = 22;  // measured deviation: 22^3 > 10^4 parameters per patch
  ProgressCallback progress;       // task "reduce": candidate knots tried
};

// The caller's say on a reduced patch (e.g. its Jacobian certificate): false
// undoes the removals that touched it, latest first, until it says true.
using ReducedPatchCheck = std::function<bool(int patch, const Patch& reduced)>;

struct ModelReduction {
  MultiPatch model;  // the reduced model (no solution: the basis changed)
  long control_points_before = 0, control_points_after = 0;
  long elements_before = 0, elements_after = 0;
  int knots_removed = 0;          // family knots removed, each counted once for all its members
  int families = 0;               // knot families of the model
  int inconsistent_families = 0;  // not conforming in their knots: left as they are
  int removals_undone = 0;        // removals the patch check refused
  double bound = 0.0;             // largest bound of a patch (model units)
  double measured = 0.0;          // largest distance between the models at the sampled parameters
  long samples = 0;               // parameters sampled in all
};

// Throws bad_input for a negative tolerance or an invalid model.
ModelReduction reduce_model(const MultiPatch& mp, const ModelReductionOptions& options,
                            const ReducedPatchCheck& check = {});

// The least-squares projection of a patch onto coarser knot vectors (each a
// sub-multiset of the patch's, with the same ends); ends of every direction
// kept. Throws bad_input when a knot vector is not nested in the patch's.
Patch project_patch(const Patch& patch, const std::array<std::vector<double>, 3>& knots);

}  // namespace igaprep::spline
