#pragma once
// Uniform refinement of a whole multipatch model before an analysis.
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

// Inputs: a conforming model; elevate >= 0 (degree raised by this in every
// direction of every patch); refine >= 0 (levels of uniform h-refinement, each
// bisecting every knot span). Degree elevation comes first (k-refinement).
// Output: the refined model; the geometry is unchanged, and since every patch
// is refined the same way in parameter space, sides that matched still match
// (a reversed direction maps span midpoints to span midpoints). Interfaces,
// boundaries, labels and materials are copied; any displacement is dropped.
spline::MultiPatch refine_for_analysis(const spline::MultiPatch& model, int elevate, int refine);

}  // namespace igaprep::iga_check
