// igaprep run [CASE.json] [-o OUTDIR] [--keep-intermediate]: the main job on a
// case (the default model ring2 when no case is given). Stages, one summary
// line each: validate, tetmesh, midsurface, decompose, param, fit, check,
// export, validation (and the load case when the case has one); then
// report.json / report.html with the run's figures, written once at the end.
// Exit 0: the check passed and the validation met its rate (or was disabled);
// 2: the model was made but the check or the validation failed; 1: bad input.
#include <cstdio>
#include <filesystem>
#include <optional>

#include "case_file.h"
#include "case_surfaces.h"
#include "commands.h"
#include "igaprep/core/error.h"
#include "igaprep/models/builtin_models.h"
#include "stage_check.h"
#include "stage_export.h"
#include "stage_midsurface.h"
#include "stage_tetmesh.h"
#include "stage_timer.h"
#include "stage_validation.h"
#include "stage_volume.h"

namespace igaprep::cli {

namespace {

long count_control_points(const spline::MultiPatch& mp) {
  long n = 0;
  for (const auto& p : mp.patches) n += static_cast<long>(p.control_points.rows());
  return n;
}

// The run's section of the report: figures in a fixed order.
iga_check::PipelineSection pipeline_section(const CaseFile& c, const std::string& case_path,
                                            const VolumeStageResult& volume, const CheckFigures& check,
                                            const TetMeshSummary& tets) {
  const spline::MultiPatch& mp = volume.model;
  iga_check::PipelineSection p;
  p.case_name = c.name;
  p.case_file = case_path;
  auto add = [&](const std::string& name, double value) { p.figures.emplace_back(name, value); };
  add("surfaces", static_cast<double>(c.surfaces.size()));
  add("materials", static_cast<double>(c.materials.size()));
  add("tets", static_cast<double>(tets.tets));
  add("patches", static_cast<double>(mp.patches.size()));
  int degree = 0, elements_per_direction = 0;
  if (!mp.patches.empty()) {
    degree = mp.patches[0].degrees[0];
    elements_per_direction = mp.patches[0].count(0) - degree;
  }
  add("degree", degree);
  add("elements_per_direction", elements_per_direction);  // of patch 0, direction u (before any knot insertion)
  add("elements", static_cast<double>(check.elements));
  add("control_points", static_cast<double>(count_control_points(mp)));
  add("interfaces", static_cast<double>(mp.interfaces.size()));
  add("boundary_sides", static_cast<double>(mp.boundaries.size()));
  add("unmatched_sides", volume.unmatched_sides);
  add("stitched_control_points", volume.stitched);
  add("max_stitch", volume.max_stitch);
  if (c.jacobian.target > 0.0) {  // optimize_jacobians: its own samples' lowest scaled Jacobian before and after
    add("fit_min_scaled_jacobian", volume.jacobians.min_before);
    add("optimized_min_scaled_jacobian", volume.jacobians.min_after);
    add("optimized_control_points", volume.jacobians.moved_points);
  }
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

}  // namespace

void add_run_command(CLI::App& app) {
  auto* sub = app.add_subcommand("run", "Run the pipeline on a case file (default: the built-in model ring2)");
  auto case_path = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto keep = std::make_shared<bool>(false);
  sub->add_option("case", *case_path, "case file (JSON, docs/case-format.md)");
  sub->add_option("-o,--output", *output, "output folder (default: the case's output folder)");
  sub->add_flag("--keep-intermediate", *keep, "also write the intermediate meshes and fields as VTU files");
  set_body(sub, [case_path, output, keep] {
    const std::string path = case_path->empty() ? models::builtin_case_path(models::default_model_name()) : *case_path;
    const CaseFile c = read_case_file(path);
    const std::string dir = output->empty() ? c.output_dir : *output;
    std::printf("igaprep run: case '%s' (%s), output %s\n", c.name.c_str(), path.c_str(), dir.c_str());
    std::vector<iga_check::PipelineStage> stages;

    StageTimer validate_timer;
    const CaseSurfaces surfaces = load_case_surfaces(c);
    stages.push_back({"validate", validate_timer.seconds()});
    std::printf("validate   %7.2f s  %zu surface(s), nested", stages.back().seconds, surfaces.meshes.size());
    for (std::size_t i = 0; i < surfaces.reports.size(); ++i)
      std::printf("; %s: %d faces, genus %d", surfaces.names[i].c_str(), surfaces.reports[i].faces,
                  surfaces.reports[i].genus);
    std::printf("\n");
    std::fflush(stdout);

    StageTimer tet_timer;
    const TetMeshSummary tets = summarize(run_tetmesh_stage(c, surfaces, (std::filesystem::path(dir) / "tetmesh.vtu").string()),
                                          static_cast<int>(c.materials.size()));
    stages.push_back({"tetmesh", tet_timer.seconds()});
    StageTimer mid_timer;
    const param::MidsurfaceResult mid = run_midsurface_stage(c, surfaces, dir);
    stages.push_back({"midsurface", mid_timer.seconds()});
    // decompose, param and fit print their own lines; the report has their sum.
    const VolumeStageResult volume = run_volume_stages(c, surfaces, mid, dir, *keep);
    stages.push_back({"decompose", volume.decompose_seconds});
    stages.push_back({"param", volume.param_seconds});
    stages.push_back({"fit", volume.fit_seconds});

    CheckFigures figures;
    iga_check::CheckReport report = run_check_stage(volume.model, surfaces.meshes, volume.model.labels, {}, &figures);
    report.model = "model.h5";
    stages.push_back({"check", figures.seconds});

    const ExportStageResult exported = run_export_stage(volume.model, c.export_formats, dir);
    stages.push_back({"export", exported.seconds});

    iga_check::PipelineSection pipeline = pipeline_section(c, path, volume, figures, tets);
    for (const auto& f : exported.written)
      pipeline.outputs.push_back(std::filesystem::path(f).filename().string());
    if (c.validation.enabled) {
      StageTimer timer;
      pipeline.validation = run_validation_stage(volume.model, report, c.validation);
      stages.push_back({"validation", timer.seconds()});
    } else {
      std::printf("validation    off   (case key validation.enabled = false)\n");
    }
    if (c.load_case) {
      StageTimer timer;
      try {
        const LoadCaseResult lc = run_load_case_stage(volume.model, *c.load_case, dir);
        stages.push_back({"load_case", lc.seconds});
        pipeline.figures.emplace_back("load_case_unknowns", static_cast<double>(lc.unknowns));
        pipeline.figures.emplace_back("load_case_strain_energy", lc.strain_energy);
        pipeline.figures.emplace_back("load_case_max_displacement", lc.max_displacement);
        pipeline.outputs.push_back("result.h5");
      } catch (const Error& e) {
        // The model is made: keep the report of what ran, then fail (exit 1 for bad input).
        stages.push_back({"load_case", timer.seconds()});
        pipeline.stages = stages;
        pipeline.verdict = std::string("ERROR: load case: ") + e.what();
        pipeline.outputs.push_back("report.json");
        pipeline.outputs.push_back("report.html");
        report.pipeline = pipeline;
        write_run_report(report, dir);
        if (e.kind() == ErrorKind::BadInput) throw bad_input(path + ": " + e.what());
        throw;
      }
    }
    pipeline.stages = stages;

    const bool validation_ok = !pipeline.validation || pipeline.validation->met;
    pipeline.passed = report.passed && validation_ok;
    std::string verdict = report.passed ? "check passed" : "check FAILED";
    if (!pipeline.validation) {
      verdict += "; validation off";
    } else if (!pipeline.validation->ran) {
      verdict += "; validation NOT RUN (" + pipeline.validation->message + ")";
    } else {
      char buf[160];
      std::snprintf(buf, sizeof buf, "; validation L2 rate %.2f %s %.1f", pipeline.validation->l2_rate,
                    pipeline.validation->met ? ">=" : "<", pipeline.validation->required_rate);
      verdict += buf;
    }
    pipeline.verdict = (pipeline.passed ? "PASS: " : "FAIL: ") + verdict;
    pipeline.outputs.push_back("report.json");
    pipeline.outputs.push_back("report.html");
    report.pipeline = pipeline;
    const std::string html = write_run_report(report, dir);

    double total = 0.0;
    for (const auto& s : stages) total += s.seconds;
    std::printf("report     %7.2f s total; %s; %s\n", total, pipeline.verdict.c_str(), html.c_str());
    std::fflush(stdout);
    return pipeline.passed ? 0 : 2;
  });
}

}  // namespace igaprep::cli
