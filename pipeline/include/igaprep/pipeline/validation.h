#pragma once
// The validation stage of a run: the manufactured-solution study
// (docs/elasticity-solver.md) on the fitted model or on a connected set of
// its patches; and the load case: a solve with the case's materials,
// constraints and loads on labelled sides (optionally only the sides whose
// centre lies in a box), written as result.h5.
#include <string>
#include <vector>

#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::pipeline {

// The label given to the sides of a validation sub-model that are neither on
// an interface nor labelled (cuts to left-out patches, collapsed sides): the
// study prescribes the exact displacement there too.
inline constexpr const char* kValidationCutLabel = "validation_cut";

// Inputs: the model, the check report (patch verdicts and quality choose the
// patches), the case's validation options. Output: the figures for the
// report; ran = false with a message when the study could not run (e.g. a
// patch with a negative Jacobian). Errors other than bad input pass through.
iga_check::PipelineValidation validation_stage(const spline::MultiPatch& mp, const iga_check::CheckReport& check,
                                               const CaseValidation& options, Observer& observer);

// Inputs: model, the load case. Output: a copy of the model whose sides
// selected by boxes carry derived labels ("outer[box 0]", ...), and for each
// selection of the load case (fix, pressure, traction, force, in order)
// the labels it stands for. Throws bad_input naming the key when a label
// names no boundary side or a box holds no side.
struct LoadCaseLabels {
  spline::MultiPatch model;
  std::vector<std::vector<std::string>> fix, pressure, traction, force;
};
LoadCaseLabels load_case_labels(const spline::MultiPatch& mp, const CaseLoadCase& lc);

struct LoadCaseResult {
  iga_check::ElasticitySolution solution;  // the model with its displacement, and the solve's report
  double seconds = 0.0;
};

// Solves the load case with the model's materials.
LoadCaseResult load_case_stage(const spline::MultiPatch& mp, const CaseLoadCase& lc, Observer& observer);

}  // namespace igaprep::pipeline
