#pragma once
// The check stage of `igaprep run`: the report of `igaprep check`
// (certificates, quality, fidelity, conformity, volumes) on the fitted model
// and one summary line. The run adds its "pipeline" section to the report and
// writes report.json / report.html once, at its end (write_run_report).
#include <string>
#include <vector>

#include "igaprep/iga_check/report.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::cli {

struct CheckFigures {
  long elements = 0, positive = 0, negative = 0, degenerate = 0, undecided = 0;
  double min_scaled_jacobian = 0.0;
  // Per input surface: the larger of the two max distances (spline -> mesh,
  // mesh -> spline) over the bounding-box diagonal of that surface.
  std::vector<double> fidelity;
  std::vector<double> volume_difference;  // per material region, (spline - input) / input
  double interface_gap = 0.0;             // relative to the model's diagonal
  double seconds = 0.0;                   // the stage's wall-clock time
};

// Inputs: model, surfaces (outermost first), labels, check options.
// Output: the report (not written yet) and its headline figures.
iga_check::CheckReport run_check_stage(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                                       const std::vector<std::string>& labels,
                                       const iga_check::CheckOptions& options, CheckFigures* figures);

// Writes dir/report.json and dir/report.html (with the pipeline section when
// set); returns the path of report.html.
std::string write_run_report(const iga_check::CheckReport& report, const std::string& dir);

}  // namespace igaprep::cli
