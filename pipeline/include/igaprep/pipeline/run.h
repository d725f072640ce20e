#pragma once
// The whole job on a case: validate, midsurface, base, decompose, param, fit,
// check, export, T-spline, validation and the load case, in that order, each stage's
// summary, progress and intermediates through the observer. Writes the
// model (with its provenance), the asked formats, report.json/.html and,
// for a load case, result.h5 into the output folder.
#include <optional>
#include <string>

#include "igaprep/iga_check/report.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/pipeline/tnurcc.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::pipeline {

struct RunOptions {
  std::string output_dir;     // empty: the case's output folder
  bool write_outputs = true;  // false: nothing is written (model and report are returned only)
};

struct LoadCaseFigures {
  long long unknowns = 0;
  double strain_energy = 0.0, max_displacement = 0.0;
};

struct RunResult {
  spline::MultiPatch model;                   // with its provenance filled
  iga_check::CheckReport report;              // with the "pipeline" section (stages, figures, verdict)
  std::optional<LoadCaseFigures> load_case;   // when the case has one
  std::vector<TnurccSurface> tnurcc;          // when the case asks for them (section "tnurcc")
  int rectangles = 0, boundary_segments = 0;  // of M's layout
  long tspline_uncertified = 0;               // section "tspline": its elements not certified positive
  bool passed = false;                        // the check passed and the validation met its rate (or was off)
  std::string output_dir;                     // where the outputs went (when written)
};

// Throws Error like the stages: bad_input for the case or its surfaces,
// check_failed for a folded parameterization. A model that was built but
// failed its check is not an error: passed is false. When the load case
// fails, report.json is still written (with the error as verdict) before the
// error is thrown on.
RunResult run(const Case& c, Observer& observer, const RunOptions& options = {});

// "igaprep <version> (git <revision>)", the generator written into models.
std::string generator_name();

}  // namespace igaprep::pipeline
