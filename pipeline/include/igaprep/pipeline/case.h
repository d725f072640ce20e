#pragma once
// Case files (docs/case-format.md): the surfaces of a model, its materials,
// the output folder and the parameters of each stage, as one JSON object.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/base_surface.h"
#include "igaprep/param/midsurface_pipeline.h"
#include "igaprep/param/volume_param.h"
#include "igaprep/pipeline/reduce.h"
#include "igaprep/pipeline/tnurcc.h"
#include "igaprep/pipeline/tspline.h"
#include "igaprep/spline/block_fit.h"
#include "igaprep/spline/fit_model_surface.h"
#include "igaprep/spline/optimize_jacobian.h"

namespace igaprep::pipeline {

struct CaseSurface {
  std::string label;
  std::string file;                 // absolute; empty for an offset or an in-memory surface
  std::optional<int> offset_of;     // index of an earlier surface to offset inward
  double inward = 0.0;              // offset distance (model units)
  std::optional<mesh::TriMesh> mesh;  // given in memory (built-in models): no file is read
  // Remeshing before the method meshes it: automatic (when its triangles are
  // long and thin, pipeline/surfaces.h), off, or to this edge length.
  enum class Remesh { Auto, Off, Length } remesh = Remesh::Auto;
  double remesh_length = 0.0;
};

struct CaseMaterial {
  std::string name;
  double young_modulus = 0.0;
  double poisson_ratio = 0.0;
};

// Section "validation": the manufactured-solution study of a run. It runs on
// a connected set of at most `patches` patches (0 = the whole model), grown
// from the certified patch with the smallest scaled Jacobian, so its cost
// does not grow with the model.
struct CaseValidation {
  bool enabled = true;
  int coarse_refine = 0;
  int fine_refine = 1;
  int patches = 4;
  iga_check::LinearSolver solver = iga_check::LinearSolver::Automatic;  // CHOLMOD while its factor is small, else AMG
  // A rate that misses at coarse/fine is measured once more a level finer
  // (validation.h, kFinerStudyUnknowns).
  bool finer_when_missed = true;
};

// Section "fit", keys max_elements and max_model_elements: when the check
// fails for want of resolution, the blocks are sampled and fitted again with
// more elements per direction (fit_retry.h).
struct CaseFitRetry {
  int max_elements = 12;                  // per direction; at most fit.elements: never
  long long max_model_elements = 200000;  // a finer attempt's elements in all, at most
};

// A labelled boundary, optionally only its sides whose centre (the mean of
// the side's control points) lies in the box [lo, hi].
struct CaseSideSelection {
  std::string label;
  std::optional<std::array<Eigen::Vector3d, 2>> box;
};

struct CaseFix {
  CaseSideSelection where;
  std::array<bool, 3> components{{true, true, true}};
};

struct CasePressure {
  CaseSideSelection where;
  double value = 0.0;
};

struct CaseTraction {
  CaseSideSelection where;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

// A total force (newtons with MPa and mm) spread over the selected sides.
struct CaseForce {
  CaseSideSelection where;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

// Section "load_case": a solve with the case's materials, written as result.h5.
struct CaseLoadCase {
  std::vector<CaseFix> fix;
  std::vector<CasePressure> pressure;
  std::vector<CaseTraction> traction;
  std::vector<CaseForce> force;
  Eigen::Vector3d body_force = Eigen::Vector3d::Zero();
  std::optional<iga_check::RotationLoad> rotation;
  int refine = 0;
  iga_check::LinearSolver solver = iga_check::LinearSolver::Automatic;  // CHOLMOD while its factor is small, else AMG
};

struct Case {
  std::string path;        // the case file itself; empty for a case made in memory
  std::string text;        // the case file's text as read (provenance); empty for a built-in case
  std::string name;        // case name (defaults to the file's folder name)
  std::vector<CaseSurface> surfaces;    // T1..Tn, outermost first
  std::vector<CaseMaterial> materials;  // one per surface: material i lies inside T(i+1)
  std::string output_dir;               // resolved against the case file's folder
  mesh::TetgenOptions tetmesh;
  param::MidsurfaceOptions midsurface;  // section "midsurface" (docs/midsurface.md)
  param::BaseSurfaceOptions base;       // section "decomposition": inset, smoothing, sliding_uv
  param::VolumeParamOptions volume;     // section "decomposition" (docs/decomposition.md)
  // "decomposition.spread_deviation": "auto" (default): volume.spread_deviation
  // is 0 unless the blocks' samples miss T1 by more than check.fidelity_limit
  // (the param stage then runs again with a share of that limit).
  bool auto_spread_deviation = true;
  // "decomposition.cover_rounds": while the blocks' samples miss T1 by more
  // than check.fidelity_limit, the layout's rectangles under the shell faces
  // nearest the missed parts are halved and the param stage runs again, at
  // most this many times (0: never; docs/decomposition.md, "Rectangles halved
  // where T1 is missed").
  int cover_rounds = 2;
  spline::BlockFitOptions fit;          // section "fit"
  CaseFitRetry fit_retry;               // section "fit", keys max_elements, max_model_elements
  spline::SurfaceFitOptions surface_fit;         // section "fit", keys surface_* (iterations 0: off)
  spline::JacobianOptimizationOptions jacobian;  // section "fit", keys jacobian_*
  // Section "export": besides model.h5, in order. Default: model.vtu, so
  // that a first run has something to open in ParaView; [] writes none.
  std::vector<std::string> export_formats{"vtu"};
  iga_check::CheckOptions check;            // section "check": fidelity_limit, volume_limit (percent in the file)
  CaseValidation validation;                // section "validation"
  std::optional<ReduceSettings> reduce;     // section "reduce": data reduction after the fit
  std::optional<TnurccSettings> tnurcc;     // section "tnurcc": T-NURCC surfaces of the model (folder tnurcc/)
  std::optional<TSplineSettings> tspline;   // section "tspline": a fitted, locally refined T-spline (model_tspline.h5)
  std::optional<CaseLoadCase> load_case;    // section "load_case"
};

// Reads and validates a case file. Unknown keys, wrong types, missing files
// and inconsistent counts throw Error(BadInput) naming the file and the key.
Case read_case(const std::string& path);

// The same from JSON text; relative surface files and the output folder are
// resolved against `folder`; `source` names the case in messages.
Case parse_case(const std::string& json_text, const std::string& folder, const std::string& source);

// A built-in model (sphere2, ring2, torus3; models/README) as a case whose
// surfaces are generated in memory: it needs no file, so an installed
// igaprep runs it from any folder. Output folder: "output" in the working dir.
Case builtin_case(const std::string& name);

// The case as JSON text, paths relative to `relative_to` (empty: as stored).
// Sections after "tetmesh" only where they differ from their defaults (the
// committed built-in cases), or every option's value with `all_options`
// (provenance). In-memory surfaces are named by their label.
std::string case_json(const Case& c, const std::string& relative_to, bool all_options = false);

}  // namespace igaprep::pipeline
