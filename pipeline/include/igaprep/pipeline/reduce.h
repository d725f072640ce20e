#pragma once
// The reduce stage of a run and of `igaprep reduce`: data reduction of a
// fitted model (spline/reduce_model.h) that keeps what its check certified.
//  - Jacobian: no element the check certified positive (or degenerate where
//    allowed) loses its certificate. A reduced patch is refined back to the
//    original knots and certified element by element; the removals that
//    touched a patch that fails are undone, latest first.
//  - Fidelity: no point moves farther than the tolerance, so a distance to
//    an input surface grows by at most the tolerance: the tolerance is
//    lowered to the margin below the fidelity limit.
//  - Volumes: a region within its limit must stay within it; the reduction
//    is made again at half the tolerance until it does.
// A limit the model already fails sets no margin.
#include <string>

#include "igaprep/iga_check/report.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/pipeline/check.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/reduce_model.h"

namespace igaprep::pipeline {

// Case section "reduce" (docs/case-format.md): exactly one of the two.
struct ReduceSettings {
  double tolerance = 0.0;           // model units
  double relative_tolerance = 0.0;  // fraction of the model's bounding-box diagonal
};

struct ReduceFigures {
  double tolerance_asked = 0.0;  // model units
  double tolerance = 0.0;        // used: the asked one, or less where a margin is smaller
  std::string limited_by;        // empty, or what lowered it ("fidelity T1", "volume region 0")
  long control_points_before = 0, control_points_after = 0;
  long elements_before = 0, elements_after = 0;
  long uncertified_before = 0;  // elements the check did not certify (the reduced model has at most as many)
  int knots_removed = 0, removals_undone = 0, inconsistent_families = 0;
  double bound = 0.0;     // model units: no point of the model moved farther
  double measured = 0.0;  // the largest distance found at the sampled parameters
  long samples = 0;
  double seconds = 0.0;
};

struct Reduction {
  spline::MultiPatch model;
  ReduceFigures figures;
};

// Inputs: the model; the report of its check (certificates, fidelity,
// region volumes: its margins) and the options it was made with. Throws
// bad_input for settings without a positive tolerance.
Reduction reduce_stage(const spline::MultiPatch& mp, const ReduceSettings& settings,
                       const iga_check::CheckReport& before, const iga_check::CheckOptions& options,
                       Observer& observer);

// The model checked ("check_fitted"), reduced ("reduce") and the reduced
// model checked ("check"), each stage's summary to the observer: what a run
// with a "reduce" section and `igaprep reduce` do.
struct CheckedReduction {
  Check fitted;  // the check of the model as given
  Reduction reduction;
  Check reduced;  // the check of the reduced model
};
CheckedReduction reduce_checked(const spline::MultiPatch& mp, const ReduceSettings& settings,
                                const std::vector<mesh::TriMesh>& surfaces, const iga_check::CheckOptions& options,
                                Observer& observer);

}  // namespace igaprep::pipeline
