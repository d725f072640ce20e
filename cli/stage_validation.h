#pragma once
// The validation stage of `igaprep run`: the manufactured-solution study
// (docs/elasticity-solver.md) on the fitted model or on a connected set of its
// patches, and the optional load case: a solve with the case's materials,
// constraints and loads on labelled sides (optionally only the sides whose
// centre lies in a box), written as result.h5. One summary line each.
#include <string>
#include <vector>

#include "case_file.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::cli {

// The label given to the sides of a validation sub-model that are neither on
// an interface nor labelled (cuts to left-out patches, collapsed sides): the
// study prescribes the exact displacement there too.
inline constexpr const char* kValidationCutLabel = "validation_cut";

// Inputs: model, patch indices (distinct, valid). Output: those patches with
// the interfaces between them, their labelled sides, and every other side
// labelled kValidationCutLabel (added to the labels when used).
spline::MultiPatch validation_submodel(const spline::MultiPatch& mp, const std::vector<int>& patches);

// Inputs: model, per-patch eligibility and score (e.g. min scaled Jacobian),
// the largest count (0 or >= patches: every eligible patch).
// Output: a connected set of eligible patches grown breadth-first (neighbours
// by increasing index) from the eligible patch with the smallest score,
// sorted; empty when none is eligible.
std::vector<int> validation_patches(const spline::MultiPatch& mp, const std::vector<bool>& eligible,
                                    const std::vector<double>& score, int max_patches);

// Inputs: the model, the check report (patch verdicts and quality choose the
// patches), the case's validation options. Output: the figures for the
// report; ran = false with a message when the study could not run (e.g. a
// patch with a negative Jacobian). Errors other than bad input pass through.
iga_check::PipelineValidation run_validation_stage(const spline::MultiPatch& mp,
                                                   const iga_check::CheckReport& check,
                                                   const CaseValidation& options);

// Inputs: model, one load-case entry selection. Output: a copy of the model
// whose sides selected by boxes carry derived labels ("outer[box 0]", ...),
// and for each selection of the load case (fix, then pressure, then
// traction, in order) the labels it stands for. Throws bad_input naming the
// key when a label names no boundary side or a box holds no side.
struct LoadCaseLabels {
  spline::MultiPatch model;
  std::vector<std::vector<std::string>> fix, pressure, traction;
};
LoadCaseLabels load_case_labels(const spline::MultiPatch& mp, const CaseLoadCase& lc);

struct LoadCaseResult {
  long long unknowns = 0;
  double strain_energy = 0.0, max_displacement = 0.0, seconds = 0.0;
  std::string solver, path;
};

// Solves the load case with the model's materials and writes dir/result.h5.
LoadCaseResult run_load_case_stage(const spline::MultiPatch& mp, const CaseLoadCase& lc, const std::string& dir);

}  // namespace igaprep::cli
