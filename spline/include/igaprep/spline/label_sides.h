#pragma once
// Labels of a fitted multipatch model's sides: which input surface each
// material interface lies on, and which boundary label each outer side has.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/side.h"

namespace igaprep::spline {

// Inputs: a model whose interfaces are found (find_interfaces.h) and whose
// patches carry materials 0..n-1 (material i inside surface T(i+1)); per
// patch and side (indexed by Side::array_index(): u0, u1, v0, v1, w0, w1) the
// label of the surface the side lies on (-1: none) and whether the side is
// collapsed to a curve.
// Effect: an interface between materials i-1 and i gets surface i; every side
// that is not on an interface and has a label becomes a boundary with it.
// Output: the number of sides left neither on an interface, nor labelled,
// nor collapsed (0 for a valid model).
int label_sides(MultiPatch& mp, const std::vector<std::array<int, 6>>& side_labels,
                const std::vector<std::array<bool, 6>>& collapsed);

// Index of the label called `name`, or -1.
int label_index(const MultiPatch& mp, const std::string& name);

// The model's labels as "a, b, c" ("none" when it has none), for messages.
std::string label_list(const MultiPatch& mp);

// The labels that a boundary side or a material interface stands for, increasing.
std::vector<int> labels_with_sides(const MultiPatch& mp);

// The patch sides standing for surface `label`, as (patch, side): boundary
// sides labelled with it, then the interfaces lying on it, each taken from
// the inner material's patch (material i lies inside surface i, the higher
// index), so that out of the patch is out of the surface.
std::vector<std::pair<int, Side>> sides_on_surface(const MultiPatch& mp, int label);

}  // namespace igaprep::spline
