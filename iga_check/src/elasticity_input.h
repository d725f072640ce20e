#pragma once
// Internal to the elasticity solver: the checks of a problem before any work
// (model, options, materials, labels, finite loads) and the boundary sides a
// label names.
#include <string>
#include <vector>

#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check::detail {

// Boundary sides labelled `name`. Throws bad_input, starting with `what` (the
// kind of condition, e.g. "pressure load"), for an unknown label or a label
// that names no boundary side (an interface or unused label carries no condition).
std::vector<spline::BoundarySide> sides_with_label(const spline::MultiPatch& mp, const std::string& name,
                                                   const char* what);

// Validates the model, the options and the problem so that bad input fails
// before any work. Output: the Lame parameters of every material of the model.
// Throws bad_input naming the material, patch or label at fault.
std::vector<LameParameters> check_elasticity_input(const spline::MultiPatch& mp, const ElasticityProblem& problem,
                                                   const ElasticityOptions& options);

}  // namespace igaprep::iga_check::detail
