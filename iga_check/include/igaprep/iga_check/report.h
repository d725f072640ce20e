#pragma once
// The analysis-suitability report of a model: the Jacobian certificate of
// every element, quality metrics, fidelity to the input surfaces, topology and
// volumes, and a verdict; as data (CheckReport), as report.json (keys
// documented in docs/check-report.md, stable) and as report.html (one
// self-contained file: inline CSS and SVG, no scripts, fonts or links).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "igaprep/iga_check/criteria.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/iga_check/quality_metrics.h"
#include "igaprep/iga_check/topology_checks.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

struct CheckOptions {
  CertifyOptions certify;
  QualityOptions quality;
  FidelityOptions fidelity;
  double conformity_tolerance = 1e-9;  // relative to the bounding-box diagonal
  double fidelity_limit = 0.005;       // largest input-to-model distance, relative to the input's diagonal
  double volume_limit = 0.005;         // largest |material volume difference|, relative to the input's
  bool allow_degenerate = false;       // degenerate elements pass
  int worst_elements = 10;             // elements listed by smallest certified lower bound
};

struct PatchSummary {
  int patch = -1, material = 0;
  int elements = 0, positive = 0, negative = 0, degenerate = 0, undecided = 0;
  double det_j_lower_bound = 0.0;  // smallest certified lower bound of its elements
  bool passed = true;
};

// Optional section "pipeline": the figures of an `igaprep run` that made the
// model (stage times, counts, the manufactured-solution validation). Absent
// from reports of `igaprep check`.
struct PipelineStage {
  std::string name;      // "validate", "tetmesh", ... in the order run
  double seconds = 0.0;  // wall clock
};

struct PipelineValidationLevel {
  int refine = 0;
  long long elements = 0, unknowns = 0;
  double h = 0.0;  // largest knot span / parameter-domain length
  double l2_error = 0.0, l2_relative = 0.0, energy_relative = 0.0;
  double seconds = 0.0;
};

struct PipelineValidation {
  bool ran = false;            // false: the study could not run (`message` says why)
  std::string message;         // empty, or why it did not run
  int degree = 0;              // smallest patch degree of the model
  int patches = 0;             // patches the study ran on
  int model_patches = 0;       // patches of the whole model
  std::vector<int> patch_list; // which ones (all when patches == model_patches)
  std::string solver;
  std::vector<PipelineValidationLevel> levels;  // coarse, fine
  double l2_rate = 0.0, energy_rate = 0.0;
  double required_rate = 0.0;  // degree + 0.5
  bool met = false;            // ran and l2_rate >= required_rate
  // When the rate missed at the case's levels and the study was made once
  // more a level finer (`levels` and the rates are then the finer ones):
  // the L2 rate at the case's levels; < 0: not made.
  double first_l2_rate = -1.0;
};

struct PipelineSection {
  std::string case_name, case_file;
  std::vector<PipelineStage> stages;
  // Named figures in a fixed order (patches, elements, interfaces, ...);
  // every value a finite number.
  std::vector<std::pair<std::string, double>> figures;
  std::vector<std::string> outputs;  // files written, relative to the output folder
  std::optional<PipelineValidation> validation;  // absent when disabled
  bool passed = false;   // the check passed and the validation (when run) met its rate
  std::string verdict;   // one line
};

struct CheckReport {
  std::string model;                        // name shown in the report (e.g. the file)
  std::string generator;                    // program and version that made it (set by the caller; may be empty)
  std::string date;                         // when, ISO 8601 UTC (set by the caller; may be empty)
  double diagonal = 0.0;                    // bounding-box diagonal of the model
  double input_diagonal = 0.0;              // of the outermost input surface (0 without surfaces)
  std::vector<std::string> surface_labels;  // input surfaces, outermost first (may be empty)
  std::vector<std::string> material_names;
  std::vector<ElementCertificate> certificates;  // every element of every patch
  // The model's labelled boundary for report.html (model_picture.h), coloured
  // by quality (the worst elements marked), by patch and by material; may be empty.
  std::string picture_svg, picture_by_patch_svg, picture_by_material_svg;
  std::vector<PatchSummary> patches;
  std::vector<ElementCertificate> worst_elements;
  QualityReport quality;
  std::vector<SurfaceFidelity> fidelity;
  TopologyReport topology;
  bool allow_degenerate = false;
  std::vector<Criterion> criteria;  // jacobian, conformity, watertight, fidelity, volume (criteria.h)
  bool passed = false;            // every criterion passed
  std::vector<int> failed_patches;    // patches with an element that is not certified positive
  std::vector<std::string> warnings;  // criteria that could not be checked (do not change `passed`)
  std::string verdict;            // one line: PASS, or FAIL and every failed criterion
  std::optional<PipelineSection> pipeline;  // set by `igaprep run` only
};

// Inputs: model, input surfaces outermost first (label i = surface i; may be
// empty: no fidelity, no region volumes), their labels (may be empty),
// options, the name shown in the report.
// Output: the report. Throws bad_input for a model that cannot be checked
// (degree 0, non-positive weight, inconsistent sides).
CheckReport build_check_report(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                               const std::vector<std::string>& surface_labels = {},
                               const CheckOptions& options = {}, const std::string& model = "");

// Element counts of the whole model: the sums of the patches' counts.
struct ElementTotals {
  long elements = 0, positive = 0, negative = 0, degenerate = 0, undecided = 0;
};
ElementTotals element_totals(const CheckReport& r);

// Each failed criterion as "NAME FAILED: summary", then its findings
// indented by two spaces: what `igaprep check` and a run print under the verdict.
std::vector<std::string> failure_lines(const CheckReport& r);

std::string report_json(const CheckReport& r);  // pretty-printed, deterministic
std::string report_html(const CheckReport& r);

// Creates `dir` if needed and writes dir/report.json and dir/report.html,
// each atomically. Throws bad_input when the folder cannot be written.
void write_report(const CheckReport& r, const std::string& dir);

}  // namespace igaprep::iga_check
