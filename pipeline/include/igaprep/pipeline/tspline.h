#pragma once
// The T-spline stage of a run (docs/tspline.md, "Fit-driven refinement"):
// the certified multipatch as a T-spline, its faces fitted to the input
// surfaces and refined where they stay farther than the tolerance, then the
// Jacobian repair; the result's certificate and fidelity, measured as the
// check measures the multipatch's, so the report can set the two side by side.
#include <vector>

#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/tspline_surface_fit.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::pipeline {

// Case section "tspline" (docs/case-format.md): exactly one tolerance.
struct TSplineSettings {
  double tolerance = 0.0;           // model units
  double relative_tolerance = 0.0;  // of the outer input surface's diagonal, as the check's fidelity
  int rounds = spline::TSplineFitOptions{}.max_rounds;
};

struct TSplineFigures {
  double tolerance = 0.0;  // model units
  std::vector<spline::TSplineFitRound> rounds;
  bool reached = false;
  iga_check::TSplineRepairResult repair;
  long elements = 0, uncertified = 0;  // Bezier elements; those not certified positive (degenerate counts as not)
  double min_lower_bound = 0.0;        // smallest certified lower bound of det J
  // Per input surface, as CheckFigures::fidelity: the larger of the two
  // largest distances over the outer surface's diagonal.
  std::vector<double> fidelity;
};

struct TSplineStage {
  spline::ExtractionModel model;
  TSplineFigures figures;
};

// Inputs: the run's model, its input surfaces (outermost first), the
// settings. Its summary goes to the observer as stage "tspline". Throws
// bad_input for a model of even degree (no local refinement for those yet).
TSplineStage tspline_stage(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                           const TSplineSettings& settings, Observer& observer);

}  // namespace igaprep::pipeline
