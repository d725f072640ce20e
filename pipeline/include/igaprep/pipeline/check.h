#pragma once
// The check stage of a run: the report of `igaprep check` (certificates,
// quality, fidelity, conformity, volumes) on the fitted model and its
// headline figures. The run adds its "pipeline" section to the report and
// writes report.json / report.html once, at its end.
#include <string>
#include <vector>

#include "igaprep/iga_check/report.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::pipeline {

struct CheckFigures {
  long elements = 0, positive = 0, negative = 0, degenerate = 0, undecided = 0;
  double min_scaled_jacobian = 0.0;
  // Per input surface: the larger of the two max distances (spline -> mesh,
  // mesh -> spline) over the bounding-box diagonal of the outermost surface
  // (the check's fidelity criterion).
  std::vector<double> fidelity;
  std::vector<double> volume_difference;  // per material region, (spline - input) / input
  double interface_gap = 0.0;             // relative to the model's diagonal
  double seconds = 0.0;                   // the stage's wall-clock time
};

struct Check {
  iga_check::CheckReport report;  // not written yet
  CheckFigures figures;
};

// Inputs: model, surfaces (outermost first; labels = the model's), options;
// the stage's name in its summary ("check", or "check_fitted" for the check
// of a model before its reduction).
Check check_stage(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                  const iga_check::CheckOptions& options, Observer& observer, const std::string& stage = "check");

}  // namespace igaprep::pipeline
