// igaprep midsurface CASE.json [-o DIR]: cut loops, the midsurface M0, M0trim
// with its 2D polycube (u, v), the rectangle layout and the base surface M
// (seed paper, section 4), each written as VTU, with a summary on stdout.
#include "commands.h"
#include "igaprep/pipeline/midsurface.h"
#include "print_observer.h"

namespace igaprep::cli {

void add_midsurface_command(CLI::App& app) {
  auto* sub = app.add_subcommand("midsurface", "Cut loops, midsurface M0, M0trim with its 2D polycube, base surface M");
  auto case_path = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  sub->add_option("case", *case_path, "case file (JSON, docs/case-format.md, docs/midsurface.md)")->required();
  sub->add_option("-o,--output", *output, "output folder (default: the case's output folder)");
  set_body(sub, [case_path, output] {
    const pipeline::Case c = pipeline::read_case(*case_path);
    PrintObserver observer(output->empty() ? c.output_dir : *output, default_intermediates());
    const pipeline::Surfaces surfaces = pipeline::load_surfaces(c);
    pipeline::base_stage(c, surfaces, pipeline::midsurface_stage(c, surfaces, observer), observer);
    return 0;
  });
}

}  // namespace igaprep::cli
