#include "igaprep/pipeline/run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "igaprep/core/error.h"
#include "igaprep/core/input_files.h"
#include "igaprep/core/output_folder.h"
#include "igaprep/export/export_model.h"
#include "igaprep/export/hdf5_extraction.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/export/pvd.h"
#include "igaprep/pipeline/check.h"
#include "igaprep/pipeline/export.h"
#include "igaprep/pipeline/fit_retry.h"
#include "igaprep/pipeline/midsurface.h"
#include "igaprep/pipeline/provenance.h"
#include "igaprep/pipeline/reduce.h"
#include "igaprep/pipeline/surfaces.h"
#include "igaprep/pipeline/tspline.h"
#include "igaprep/pipeline/validation.h"
#include "igaprep/pipeline/volume.h"
#include "igaprep/spline/multipatch_topology.h"
#include "stage_timer.h"
#include "igaprep/core/text.h"

namespace igaprep::pipeline {
namespace {

namespace fs = std::filesystem;

// The reduction's figures (docs/check-report.md); the model's counts above are the reduced model's.
void add_reduce_figures(const ReduceFigures& r, iga_check::PipelineSection& p) {
  auto add = [&](const std::string& name, double value) { p.figures.emplace_back(name, value); };
  add("reduce_tolerance_asked", r.tolerance_asked);
  add("reduce_tolerance", r.tolerance);
  add("reduce_bound", r.bound);
  add("reduce_measured_deviation", r.measured);
  add("reduce_control_points_before", static_cast<double>(r.control_points_before));
  add("reduce_elements_before", static_cast<double>(r.elements_before));
  add("reduce_uncertified_elements_before", static_cast<double>(r.uncertified_before));
  add("reduce_knots_removed", r.knots_removed);
  add("reduce_removals_undone", r.removals_undone);
}

// The run's section of the report: figures in a fixed order (docs/check-report.md).
iga_check::PipelineSection pipeline_section(const Case& c, const param::MidsurfaceResult& mid, const Fit& fit,
                                            int fit_attempts, const CheckFigures& check,
                                            const std::optional<ReduceFigures>& reduce) {
  const spline::MultiPatch& mp = fit.model;
  iga_check::PipelineSection p;
  p.case_name = c.name;
  p.case_file = c.path.empty() ? "built-in model " + c.name : c.path;
  auto add = [&](const std::string& name, double value) { p.figures.emplace_back(name, value); };
  add("surfaces", static_cast<double>(c.surfaces.size()));
  add("materials", static_cast<double>(c.materials.size()));
  add("tets", static_cast<double>(mid.tets.T.rows()));
  add("patches", static_cast<double>(mp.patches.size()));
  int degree = 0, elements_per_direction = 0;
  if (!mp.patches.empty()) {
    degree = mp.patches[0].degrees[0];
    elements_per_direction = mp.patches[0].count(0) - degree;
  }
  add("degree", degree);
  add("elements_per_direction", elements_per_direction);  // of patch 0, direction u (before any knot insertion)
  add("fit_attempts", fit_attempts);                       // fit_retry.h
  add("elements", static_cast<double>(check.elements));
  add("control_points", static_cast<double>(spline::control_point_count(mp)));
  add("interfaces", static_cast<double>(mp.interfaces.size()));
  add("boundary_sides", static_cast<double>(mp.boundaries.size()));
  add("unmatched_sides", fit.unmatched_sides);
  add("stitched_control_points", fit.stitched);
  add("max_stitch", fit.max_stitch);
  for (std::size_t i = 0; i < fit.surface_fits.size(); ++i) {  // fit_model_surface, per surface that has faces
    const auto& rms = fit.surface_fits[i].rms;
    if (rms.empty()) continue;
    add("surface_fit_rms_before_" + std::to_string(i), rms.front());
    add("surface_fit_rms_after_" + std::to_string(i), rms.back());
  }
  if (c.jacobian.target > 0.0) {  // optimize_jacobians: its own samples' lowest scaled Jacobian before and after
    add("fit_min_scaled_jacobian", fit.jacobians.min_before);
    add("optimized_min_scaled_jacobian", fit.jacobians.min_after);
    add("optimized_control_points", fit.jacobians.moved_points);
  }
  if (reduce) add_reduce_figures(*reduce, p);
  add("positive_elements", static_cast<double>(check.positive));
  add("negative_elements", static_cast<double>(check.negative));
  add("degenerate_elements", static_cast<double>(check.degenerate));
  add("undecided_elements", static_cast<double>(check.undecided));
  add("min_scaled_jacobian", check.min_scaled_jacobian);
  add("interface_gap_relative", check.interface_gap);
  for (std::size_t i = 0; i < check.fidelity.size(); ++i)
    add("fidelity_relative_" + (i < mp.labels.size() ? mp.labels[i] : std::to_string(i)), check.fidelity[i]);
  for (std::size_t i = 0; i < check.volume_difference.size(); ++i)
    add("volume_difference_region_" + std::to_string(i), check.volume_difference[i]);
  return p;
}

// The T-spline's figures beside the multipatch's (docs/check-report.md).
void add_tspline_figures(const TSplineStage& t, const std::vector<std::string>& labels, iga_check::PipelineSection& p) {
  const TSplineFigures& f = t.figures;
  auto add = [&](const std::string& name, double value) { p.figures.emplace_back(name, value); };
  add("tspline_tolerance", f.tolerance);
  add("tspline_rounds", static_cast<double>(f.rounds.size()));
  add("tspline_reached", f.reached ? 1.0 : 0.0);
  // The multipatch's distinct control points (its global numbering: one per
  // function of the unrefined T-spline), to set beside the T-spline's.
  add("tspline_base_control_points", f.rounds.empty() ? 0.0 : f.rounds.front().functions);
  add("tspline_control_points", static_cast<double>(t.model.function_count()));
  add("tspline_elements", static_cast<double>(f.elements));
  add("tspline_uncertified_elements", static_cast<double>(f.uncertified));
  add("tspline_repair_uncertified_before", f.repair.uncertified_before);
  add("tspline_repair_functions_backed_off", f.repair.functions_backed_off);
  for (std::size_t i = 0; i < f.fidelity.size(); ++i)
    add("tspline_fidelity_relative_" + (i < labels.size() ? labels[i] : std::to_string(i)), f.fidelity[i]);
}

// model_tspline.h5 beside model.h5, and its figures in the report.
void run_tspline(const Case& c, const Surfaces& surfaces, Observer& observer, OutputFolder* folder, RunResult& r) {
  iga_check::PipelineSection& p = *r.report.pipeline;
  const TSplineStage t = tspline_stage(r.model, surfaces.inputs, *c.tspline, observer);
  add_tspline_figures(t, r.model.labels, p);
  r.tspline_uncertified = t.figures.uncertified;
  if (!folder) return;
  exporter::write_hdf5_extraction(t.model, (fs::path(folder->staging()) / "model_tspline.h5").string());
  p.outputs.push_back("model_tspline.h5");
}

std::string verdict_of(const iga_check::CheckReport& report, const iga_check::PipelineSection& p,
                       long tspline_uncertified) {
  std::string verdict =
      report.passed ? "check passed" : "check FAILED (" + iga_check::failed_criterion_names(report.criteria) + ")";
  if (tspline_uncertified > 0) verdict += text("; T-spline: %ld elements NOT certified", tspline_uncertified);
  if (!p.validation)
    verdict += "; validation off";
  else if (!p.validation->ran)
    verdict += "; validation NOT RUN (" + p.validation->message + ")";
  else
    verdict += text("; validation L2 rate %.2f %s %.1f", p.validation->l2_rate, p.validation->met ? ">=" : "<",
                    p.validation->required_rate);
  return (p.passed ? "PASS: " : "FAIL: ") + verdict;
}

// run.pvd: every VTU the run wrote (the model first), to open together in
// ParaView; none when it wrote no VTU.
void write_collection(const OutputFolder& folder, std::vector<std::string>& outputs) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(folder.staging()))
    if (e.path().extension() == ".vtu") files.push_back(e.path().filename().string());
  if (files.empty()) return;
  std::sort(files.begin(), files.end(), [](const std::string& a, const std::string& b) {
    const bool ma = a.rfind("model", 0) == 0, mb = b.rfind("model", 0) == 0;
    return ma != mb ? ma : a < b;
  });
  exporter::write_pvd((fs::path(folder.staging()) / "run.pvd").string(), files);
  outputs.push_back("run.pvd");
}

// The report goes in last; then the run's outputs replace the previous
// ones at once (OutputFolder).
void write_report_and_commit(RunResult& r, OutputFolder* folder) {
  if (!folder) return;
  write_collection(*folder, r.report.pipeline->outputs);
  r.report.pipeline->outputs.push_back("report.json");
  r.report.pipeline->outputs.push_back("report.html");
  stamp_report(r.report);
  iga_check::write_report(r.report, folder->staging());
  folder->commit({"report.json", "report.html"});
}

// The load case's solve; on failure the report so far is written, then the
// error goes on (bad input named by the case). On a model the check did not
// certify (a folded or degenerate element) it is not solved: the solve would
// integrate a map that is not one-to-one. Its selections are checked still.
void run_load_case(const Case& c, Observer& observer, OutputFolder* folder, RunResult& r,
                   std::vector<iga_check::PipelineStage>& stages) {
  StageTimer timer;
  iga_check::PipelineSection& p = *r.report.pipeline;
  try {
    if (!r.report.failed_patches.empty()) {
      load_case_labels(r.model, *c.load_case);
      observer.stage_finished({"load_case", timer.seconds(),
                               text("not solved: %zu patches have elements the check did not certify positive",
                                    r.report.failed_patches.size()),
                               {}});
      return;
    }
    const LoadCaseResult lc = load_case_stage(r.model, *c.load_case, observer);
    const auto& rep = lc.solution.report;
    r.load_case = LoadCaseFigures{rep.unknowns, rep.strain_energy, rep.max_displacement};
    p.figures.emplace_back("load_case_unknowns", static_cast<double>(rep.unknowns));
    p.figures.emplace_back("load_case_strain_energy", rep.strain_energy);
    p.figures.emplace_back("load_case_max_displacement", rep.max_displacement);
    if (folder) {
      exporter::write_hdf5_model(lc.solution.model, (fs::path(folder->staging()) / "result.h5").string());
      p.outputs.push_back("result.h5");
    }
  } catch (const Error& e) {
    stages.push_back({"load_case", timer.seconds()});
    p.stages = stages;
    p.verdict = std::string("ERROR: load case: ") + e.what();
    write_report_and_commit(r, folder);
    if (e.kind() == ErrorKind::BadInput) throw bad_input((c.path.empty() ? c.name : c.path) + ": " + e.what());
    throw;
  }
}

// A stage's time goes to the report as the observer hears of it.
class StageRecorder : public Observer {
 public:
  StageRecorder(Observer& next, std::vector<iga_check::PipelineStage>& stages) : next_(next), stages_(stages) {}
  void stage_finished(const StageSummary& s) override {
    stages_.push_back({s.stage, s.seconds});
    next_.stage_finished(s);
  }
  void progress(const std::string& task, std::size_t done, std::size_t total) override {
    next_.progress(task, done, total);
  }
  bool wants_intermediate(const std::string& name) const override { return next_.wants_intermediate(name); }
  void intermediate(const std::string& name, const mesh::VtuMesh& mesh) override { next_.intermediate(name, mesh); }
  void staging_folder(const std::string& folder) override { next_.staging_folder(folder); }

 private:
  Observer& next_;
  std::vector<iga_check::PipelineStage>& stages_;
};

StageSummary validate_summary(const Surfaces& s, double seconds) {
  std::string line = text("%zu surface(s), nested", s.meshes.size());
  for (std::size_t i = 0; i < s.reports.size(); ++i)
    line += text("; %s: %d faces, genus %d", s.names[i].c_str(), s.reports[i].faces, s.reports[i].genus);
  for (std::size_t i = 0; i < s.remeshed_to.size(); ++i)
    if (s.remeshed_to[i] > 0.0)
      line += text("; %s remeshed (long thin triangles) to edge %g, %d faces", s.names[i].c_str(), s.remeshed_to[i],
                   static_cast<int>(s.meshes[i].F.rows()));
  return {"validate", seconds, line, {}};
}

// The case file and its surfaces are never among the files a run writes.
void refuse_replacing_case_files(const Case& c, const std::string& output_dir) {
  std::vector<std::string> inputs;
  if (!c.path.empty()) inputs.push_back(c.path);
  for (const CaseSurface& s : c.surfaces)
    if (!s.file.empty()) inputs.push_back(s.file);
  std::vector<std::string> outputs;
  for (const char* name : {"model.h5", "model_tspline.h5", "report.json", "report.html", "result.h5", "run.pvd"})
    outputs.push_back((fs::path(output_dir) / name).string());
  for (const std::string& format : c.export_formats)
    for (const std::string& path :
         exporter::format_paths((fs::path(output_dir) / "model").string(), exporter::parse_formats(format).at(0),
                                static_cast<int>(c.materials.size())))
      outputs.push_back(path);
  refuse_replacing_inputs(inputs, outputs);
}

// The stages in order; outputs go into `folder`'s staging folder (none:
// nothing is written).
void run_stages(const Case& c, Observer& outer, OutputFolder* folder, RunResult& r) {
  std::vector<iga_check::PipelineStage> stages;
  StageRecorder observer(outer, stages);
  if (folder) observer.staging_folder(folder->staging());

  StageTimer validate_timer;
  const Surfaces surfaces = load_surfaces(c);
  observer.stage_finished(validate_summary(surfaces, validate_timer.seconds()));
  const param::MidsurfaceResult mid = midsurface_stage(c, surfaces, observer);
  const param::BaseSurface base = base_stage(c, surfaces, mid, observer);
  const Decomposition d = decompose_stage(c, surfaces, base, observer);
  std::optional<ReduceFigures> reduced;
  Fit fit;
  Check check;
  int fit_attempts = 1;
  if (c.reduce) {  // the reduction checks the reduced model; a finer fit is not tried
    const param::VolumeParam vp = param_stage(c, surfaces, d, observer);
    r.rectangles = vp.rectangles;  // the param stage may have halved some (cover_rounds)
    r.boundary_segments = vp.crests;
    fit = fit_stage(c, surfaces, d, vp, observer);
    fill_provenance(c, fit.model);
    CheckedReduction cr = reduce_checked(fit.model, *c.reduce, surfaces.inputs, c.check, observer);
    fit.model = std::move(cr.reduction.model);
    reduced = cr.reduction.figures;
    check = std::move(cr.reduced);
  } else {
    FitAttempt kept = fit_and_check(c, surfaces, d, observer);
    fill_provenance(kept.settings, kept.fit.model);
    fit_attempts = kept.attempts;
    r.rectangles = kept.rectangles;
    r.boundary_segments = kept.boundary_segments;
    fit = std::move(kept.fit);
    check = std::move(kept.check);
  }
  r.report = std::move(check.report);
  r.report.model = "model.h5";
  r.report.pipeline = pipeline_section(c, mid, fit, fit_attempts, check.figures, reduced);
  iga_check::PipelineSection& p = *r.report.pipeline;
  r.model = std::move(fit.model);
  if (folder)
    for (const auto& f : export_stage(r.model, c.export_formats, folder->staging(), r.report.certificates, observer).written)
      p.outputs.push_back(fs::path(f).filename().string());
  if (c.tnurcc) {
    r.tnurcc = tnurcc_surfaces(r.model, surfaces.inputs, *c.tnurcc, observer);
    if (folder)
      for (const auto& f : write_tnurcc(r.tnurcc, (fs::path(folder->staging()) / "tnurcc").string(), *c.tnurcc))
        p.outputs.push_back((fs::path("tnurcc") / fs::path(f).filename()).string());
  }
  if (c.tspline) run_tspline(c, surfaces, observer, folder, r);
  if (c.validation.enabled) p.validation = validation_stage(r.model, r.report, c.validation, observer);
  if (c.load_case) run_load_case(c, observer, folder, r, stages);
  p.stages = stages;
  p.passed = r.report.passed && (!p.validation || p.validation->met) && r.tspline_uncertified == 0;
  p.verdict = verdict_of(r.report, p, r.tspline_uncertified);
  r.passed = p.passed;
  write_report_and_commit(r, folder);
}

}  // namespace

RunResult run(const Case& c, Observer& outer, const RunOptions& o) {
  RunResult r;
  r.output_dir = o.output_dir.empty() ? c.output_dir : o.output_dir;
  // Made before any work (a folder that cannot be made fails now, not after
  // minutes). A run killed at any moment leaves the previous outputs; one
  // that fails puts in the intermediates it made (to show where it failed)
  // and keeps the previous model and report.
  std::optional<OutputFolder> folder;
  if (o.write_outputs) {
    refuse_replacing_case_files(c, r.output_dir);
    folder.emplace(r.output_dir);
  }
  try {
    run_stages(c, outer, folder ? &*folder : nullptr, r);
  } catch (...) {
    if (folder && !folder->committed()) {
      try {
        folder->commit();
      } catch (const Error&) {
        // the run's own error is the one to report
      }
    }
    throw;
  }
  return r;
}

}  // namespace igaprep::pipeline
