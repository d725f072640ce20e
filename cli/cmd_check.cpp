// igaprep check MODEL.h5 [--case CASE.json | --surface FILE ...] --report DIR
// [--allow-degenerate] [--fidelity-limit P] [--volume-limit P]: certified
// Jacobian, quality, fidelity and topology of a model; writes DIR/report.json
// and DIR/report.html (docs/check-report.md). Exit 0 when every criterion
// passes (docs/check-report.md), 2 otherwise, 1 on bad input.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "igaprep/core/input_files.h"
#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_extraction.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/pipeline/provenance.h"

namespace igaprep::cli {

namespace {

struct CheckArgs {
  std::string model, case_file, report_dir;
  std::vector<std::string> surfaces;
  bool allow_degenerate = false;
  int max_degree = iga_check::CertifyOptions{}.max_degree;
};

// The Jacobian criterion on every Bezier element of a model in extraction
// form; true when it passes.
bool check_extraction_jacobian(const spline::ExtractionModel& m, const CheckArgs& a) {
  iga_check::CertifyOptions options;
  options.max_degree = a.max_degree;
  const std::vector<iga_check::ElementCertificate> c = iga_check::certify_extraction_model(m, options);
  std::size_t failed = 0;
  double lowest = INFINITY;
  int worst = -1;
  for (std::size_t e = 0; e < c.size(); ++e) {
    if (!iga_check::element_certified(c[e], a.allow_degenerate)) ++failed;
    if (c[e].lower_bound < lowest) lowest = c[e].lower_bound, worst = static_cast<int>(e);
  }
  if (failed == 0)
    std::cout << "PASS: jacobian: all " << c.size() << " Bezier elements certified (smallest lower bound of det J "
              << lowest << ", element " << worst << ")\n";
  else
    std::cout << "FAIL: jacobian: " << failed << " of " << c.size()
              << " Bezier elements not certified positive (smallest lower bound of det J " << lowest << ", element "
              << worst << ")\n";
  return failed == 0;
}

// The fidelity criterion as the multipatch check has it: per surface the
// larger of the two largest distances, over the outer surface's diagonal,
// against the limit; true when every surface passes.
bool check_extraction_fidelity(const spline::ExtractionModel& m, const CheckInputs& in) {
  const double diagonal = iga_check::mesh_diagonal(in.meshes.front());
  bool passed = true;
  for (const iga_check::SurfaceFidelity& f : iga_check::fidelity(m, in.meshes, diagonal)) {
    const double worst = std::max(f.spline_to_mesh.max_relative, f.mesh_to_spline.max_relative);
    const bool ok = worst <= in.options.fidelity_limit;
    passed = passed && ok;
    const std::string label = static_cast<std::size_t>(f.surface) < in.labels.size() ? in.labels[static_cast<std::size_t>(f.surface)] : f.label;
    std::cout << (ok ? "PASS" : "FAIL") << ": fidelity " << label << ": " << 100.0 * worst << " % of the diagonal (model to surface "
              << 100.0 * f.spline_to_mesh.max_relative << " %, surface to model " << 100.0 * f.mesh_to_spline.max_relative
              << " %; limit " << 100.0 * in.options.fidelity_limit << " %)\n";
  }
  return passed;
}

// A model in extraction form (a T-spline): every Bezier element certified,
// and with input surfaces the fidelity; the other criteria and the report
// files are not there yet for this form.
int run_check_extraction(const CheckArgs& a, const CheckLimitFlags& limits) {
  const spline::ExtractionModel m = exporter::read_hdf5_extraction(a.model);
  bool passed = check_extraction_jacobian(m, a);
  const bool with_surfaces = !a.case_file.empty() || !a.surfaces.empty();
  if (with_surfaces) {
    CheckInputs in = read_check_inputs(a.case_file, a.surfaces);
    limits.apply(in.options);
    passed = check_extraction_fidelity(m, in) && passed;
  }
  std::cout << "not checked on a Bezier-extraction model yet: conformity, watertightness, "
            << (with_surfaces ? "" : "fidelity (give --surface or --case), ") << "volume; no report files written ("
            << a.report_dir << " untouched)\n";
  return passed ? 0 : 2;
}

int run_check(const CheckArgs& a, const CheckLimitFlags& limits) {
  if (exporter::is_hdf5_extraction(a.model)) return run_check_extraction(a, limits);
  std::vector<std::string> inputs = a.surfaces;
  inputs.push_back(a.model);
  if (!a.case_file.empty()) inputs.push_back(a.case_file);
  refuse_replacing_inputs(inputs, {(std::filesystem::path(a.report_dir) / "report.json").string(),
                                   (std::filesystem::path(a.report_dir) / "report.html").string()});
  const spline::MultiPatch mp = exporter::read_hdf5_model(a.model);
  CheckInputs in = read_check_inputs(a.case_file, a.surfaces);
  in.options.allow_degenerate = a.allow_degenerate;
  in.options.certify.max_degree = a.max_degree;
  limits.apply(in.options);
  iga_check::CheckReport r = iga_check::build_check_report(mp, in.meshes, in.labels, in.options, a.model);
  pipeline::stamp_report(r);
  iga_check::write_report(r, a.report_dir);
  for (const auto& w : r.warnings) std::cerr << "warning: " << w << "\n";
  std::cout << r.verdict << "\n" << std::flush;
  print_failed_criteria(r);
  std::cout << "report: " << (std::filesystem::path(a.report_dir) / "report.html").string() << "\n";
  return r.passed ? 0 : 2;
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "check", "Certify the Jacobian of every element and report quality, fidelity and topology of a model");
  auto args = std::make_shared<CheckArgs>();
  sub->add_option("model", args->model, "Model file (HDF5, docs/hdf5-format.md)")->required()->check(CLI::ExistingFile);
  auto* case_opt = sub->add_option("--case", args->case_file, "Case file naming the input surfaces (docs/case-format.md)")
                       ->check(CLI::ExistingFile);
  auto* surf_opt = sub->add_option("--surface", args->surfaces, "Input surface, repeated, outermost first (without --case)")
                       ->check(CLI::ExistingFile);
  case_opt->excludes(surf_opt);
  sub->add_option("--report", args->report_dir, "Folder for report.json and report.html")->required();
  sub->add_flag("--allow-degenerate", args->allow_degenerate,
                "Accept elements whose Jacobian vanishes only on their boundary (collapsed faces, poles)");
  sub->add_option("--max-degree", args->max_degree,
                  "Refuse patches of a higher degree (the certificate's cost grows as degree^3 per element; default 10)")
      ->check(CLI::Range(1, 40));
  auto limits = add_check_limit_flags(sub);
  set_body(sub, [args, limits] { return run_check(*args, *limits); });
}

}  // namespace igaprep::cli
