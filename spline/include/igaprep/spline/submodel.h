#pragma once
// Parts of a multipatch model: a connected set of patches chosen by a score,
// and the model those patches make alone (for a study on part of a model).
#include <string>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

// Inputs: model, per-patch eligibility and score (e.g. min scaled Jacobian),
// the largest count (0 or >= patches: every eligible patch).
// Output: a connected set of eligible patches grown breadth-first (neighbours
// by increasing index) from the eligible patch with the smallest score,
// sorted; empty when none is eligible.
std::vector<int> connected_patches(const MultiPatch& mp, const std::vector<bool>& eligible,
                                   const std::vector<double>& score, int max_patches);

// Inputs: model, patch indices (distinct, valid), a label name. Output: those
// patches with the interfaces between them, their labelled sides, and every
// other side (cuts to left-out patches, collapsed sides) labelled `cut_label`
// (added to the labels when used). Solutions are dropped.
MultiPatch submodel(const MultiPatch& mp, const std::vector<int>& patches, const std::string& cut_label);

}  // namespace igaprep::spline
