// igaprep run [CASE.json] [-o OUTDIR] [--keep-intermediate] [--fidelity-limit P]
// [--volume-limit P]: the main job on a
// case (the built-in default model ring2 when no case is given), through
// pipeline::run with an observer that prints one line per stage.
// Exit 0: the check passed and the validation met its rate (or was disabled);
// 2: the model was made but the check or the validation failed; 1: bad input.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "igaprep/models/builtin_models.h"
#include "igaprep/pipeline/run.h"
#include "print_observer.h"

namespace igaprep::cli {

void add_run_command(CLI::App& app) {
  auto* sub = app.add_subcommand("run", "Run the pipeline on a case file (default: the built-in model ring2)");
  auto case_path = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto keep = std::make_shared<bool>(false);
  sub->add_option("case", *case_path, "case file (JSON, docs/case-format.md)");
  sub->add_option("-o,--output", *output, "output folder (default: the case's output folder)");
  sub->add_flag("--keep-intermediate", *keep, "also write every intermediate mesh and field as VTU files");
  auto limits = add_check_limit_flags(sub);
  set_body(sub, [case_path, output, keep, limits] {
    pipeline::Case c = case_path->empty() ? pipeline::builtin_case(models::default_model_name())
                                          : pipeline::read_case(*case_path);
    limits->apply(c.check);
    pipeline::RunOptions options;
    options.output_dir = output->empty() ? c.output_dir : *output;
    std::printf("igaprep run: case '%s' (%s), output %s\n", c.name.c_str(),
                c.path.empty() ? "built-in model" : c.path.c_str(), options.output_dir.c_str());
    PrintObserver observer(options.output_dir, default_intermediates(), *keep);
    const pipeline::RunResult r = pipeline::run(c, observer, options);
    double total = 0.0;
    for (const auto& s : r.report.pipeline->stages) total += s.seconds;
    std::printf("report     %7.2f s total; %s; %s\n", total, r.report.pipeline->verdict.c_str(),
                (std::filesystem::path(r.output_dir) / "report.html").c_str());
    return r.passed ? 0 : 2;
  });
}

}  // namespace igaprep::cli
