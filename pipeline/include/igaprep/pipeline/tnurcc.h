#pragma once
// The T-NURCC surfaces of a model (docs/tnurcc.md), for `igaprep tnurcc`:
// per surface label, the cage of its patch sides (spline/tnurcc_cage.h),
// fitted to its input mesh when one is given (least squares on the limit
// surface, closest points both ways), with the figures that compare it to
// the C0 multipatch: fidelity both ways and the normal jumps across patch
// edges.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "igaprep/iga_check/tnurcc_fidelity.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/tnurcc_cage.h"
#include "igaprep/spline/tnurcc_quality.h"

namespace igaprep::pipeline {

struct TnurccSettings {
  std::vector<int> labels;     // the surfaces to build; empty: every label a patch side stands for
  double crease_angle = 60.0;  // degrees: the model's nets and the input mesh turn more at a crease
  bool equal_intervals = false;  // spline::CageOptions; needed for models with non-uniform knots
  int fit_iterations = 8;      // 0: the cage as the model gives it, not fitted
  double smoothing = 0.1;      // the fit's fairing weight (spline::CageFitOptions)
  int samples_per_face = 4;    // fit and fidelity (iga_check::LimitFidelityOptions)
  int vtu_per_face = 6;        // quads per cage face and direction in limit.vtu
};

struct TnurccSurface {
  int label = 0;
  std::string name;
  spline::Cage cage;  // fitted when its mesh was given
  int extraordinary_vertices = 0, crease_edges = 0;
  std::vector<double> fit_rms;  // rms pair distance before each fit iteration, then after the last
  // With a mesh: the limit surface's fidelity, and the C0 model's for the same surface.
  std::optional<iga_check::LimitFidelity> limit_fidelity;
  std::optional<iga_check::SurfaceFidelity> model_fidelity;
  double diagonal = 0.0;  // the mesh's bounding-box diagonal (the relative figures' length)
  spline::NormalJumps model_jumps, limit_jumps_patch_edges, limit_jumps;
  // Fairness: the limit surface's mean curvature at its samples (the
  // fidelity's grid), 1st, 50th and 99th percentile, model units^-1.
  std::array<double, 3> mean_curvature{{0.0, 0.0, 0.0}};
};

// Inputs: a conforming model, meshes indexed by label (an empty mesh: not
// fitted), the settings. Each surface's summary goes to the observer as a
// stage "tnurcc". Throws bad_input for an unknown label, a cage it cannot
// build (spline::surface_cage), or unequal knot intervals (a model with
// non-uniform knots, unless equal_intervals).
std::vector<TnurccSurface> tnurcc_surfaces(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& meshes,
                                           const TnurccSettings& settings, Observer& observer);

// Writes, per surface, NAME_cage.obj, NAME_intervals.json and NAME_limit.vtu
// into `dir` (made when missing). Returns the paths written.
std::vector<std::string> write_tnurcc(const std::vector<TnurccSurface>& surfaces, const std::string& dir,
                                      const TnurccSettings& settings);

}  // namespace igaprep::pipeline
