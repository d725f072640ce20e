// igaprep reduce MODEL.h5 (--tolerance T | --relative-tolerance R) -o OUT.h5
// [--case CASE.json | --surface FILE ...] [--report DIR] [--allow-degenerate]
// [--fidelity-limit P] [--volume-limit P]: data reduction that keeps the model
// conforming and certified (docs/spline.md, "Data reduction"). The model is
// checked, reduced and checked again; with surfaces the tolerance is held
// within the margins of the fidelity and volume limits. Exit 0 when the
// reduced model passes its check, 2 when it does not (it is written all the
// same), 1 on bad input (nothing written).
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.h"
#include "number_args.h"
#include "igaprep/core/input_files.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/pipeline/provenance.h"
#include "igaprep/pipeline/reduce.h"
#include "print_observer.h"

namespace igaprep::cli {

namespace {

struct ReduceArgs {
  std::string model, output, case_file, report_dir;
  std::vector<std::string> surfaces;
  std::optional<double> tolerance, relative_tolerance;
  bool allow_degenerate = false;
};

int run_reduce(const ReduceArgs& a, const CheckLimitFlags& limits) {
  std::vector<std::string> inputs = a.surfaces;
  inputs.push_back(a.model);
  if (!a.case_file.empty()) inputs.push_back(a.case_file);
  std::vector<std::string> outputs{a.output};
  if (!a.report_dir.empty())
    for (const char* f : {"report.json", "report.html"}) outputs.push_back((std::filesystem::path(a.report_dir) / f).string());
  refuse_replacing_inputs(inputs, outputs);
  const spline::MultiPatch mp = exporter::read_hdf5_model(a.model);
  CheckInputs in = read_check_inputs(a.case_file, a.surfaces);
  in.options.allow_degenerate = a.allow_degenerate;
  limits.apply(in.options);
  pipeline::ReduceSettings settings;
  settings.tolerance = a.tolerance.value_or(0.0);
  settings.relative_tolerance = a.relative_tolerance.value_or(0.0);
  PrintObserver observer("", {});
  pipeline::CheckedReduction r = pipeline::reduce_checked(mp, settings, in.meshes, in.options, observer);
  r.reduced.report.model = a.output;
  exporter::write_hdf5_model(r.reduction.model, a.output);
  pipeline::stamp_report(r.reduced.report);
  if (!a.report_dir.empty()) iga_check::write_report(r.reduced.report, a.report_dir);
  std::cout << r.reduced.report.verdict << "\n" << std::flush;
  print_failed_criteria(r.reduced.report);
  std::cout << "model: " << a.output << "\n";
  return r.reduced.report.passed ? 0 : 2;
}

}  // namespace

void add_reduce_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "reduce", "Remove knots of a model within a tolerance, keeping it conforming and its certified elements certified");
  auto args = std::make_shared<ReduceArgs>();
  sub->add_option("model", args->model, "Model file (HDF5, docs/hdf5-format.md)")->required()->check(CLI::ExistingFile);
  sub->add_option("-o,--output", args->output, "The reduced model (HDF5)")->required();
  auto* tol = sub->add_option("--tolerance", args->tolerance, "Largest move of any point of the model, model units")
                  ->check(positive_number());
  auto* rel = sub->add_option("--relative-tolerance", args->relative_tolerance,
                              "Largest move of any point, as a fraction of the model's diagonal (e.g. 0.001)")
                  ->check(CLI::Range(1e-15, 1.0));
  tol->excludes(rel);
  sub->add_option("--case", args->case_file,
                  "Case file naming the input surfaces (docs/case-format.md): the fidelity and volume margins")
      ->check(CLI::ExistingFile);
  sub->add_option("--surface", args->surfaces, "Input surface, repeated, outermost first (without --case)")
      ->check(CLI::ExistingFile)
      ->excludes("--case");
  sub->add_option("--report", args->report_dir, "Folder for report.json and report.html of the reduced model");
  sub->add_flag("--allow-degenerate", args->allow_degenerate,
                "Accept elements whose Jacobian vanishes only on their boundary (collapsed faces, poles)");
  auto limits = add_check_limit_flags(sub);
  sub->callback([sub, tol, rel] {
    if (tol->count() + rel->count() != 1) throw CLI::ValidationError("reduce", "give --tolerance or --relative-tolerance");
  });
  set_body(sub, [args, limits] { return run_reduce(*args, *limits); });
}

}  // namespace igaprep::cli
