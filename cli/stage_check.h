#pragma once
// The check stage of `igaprep run`: the report of `igaprep check`
// (certificates, quality, fidelity, conformity, volumes) on the fitted model,
// written as report.json / report.html, and one summary line.
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
};

// Inputs: model, surfaces (outermost first), labels, check options.
// Output: the report and its headline figures.
iga_check::CheckReport run_check_stage(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                                       const std::vector<std::string>& labels,
                                       const iga_check::CheckOptions& options, const std::string& dir,
                                       CheckFigures* figures);

}  // namespace igaprep::cli
