// igaprep midsurface CASE.json [-o DIR]: cut loops, the midsurface M0, M0trim
// with its 2D polycube (u, v), the rectangle layout and the base surface M
// (seed paper, section 4), each written as VTU, with a summary on stdout.
#include "case_file.h"
#include "case_surfaces.h"
#include "commands.h"
#include "stage_midsurface.h"

namespace igaprep::cli {

void add_midsurface_command(CLI::App& app) {
  auto* sub = app.add_subcommand("midsurface", "Cut loops, midsurface M0, M0trim with its 2D polycube, base surface M");
  auto case_path = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  sub->add_option("case", *case_path, "case file (JSON, docs/case-format.md, docs/midsurface.md)")->required();
  sub->add_option("-o,--output", *output, "output folder (default: the case's output folder)");
  set_body(sub, [case_path, output] {
    const CaseFile c = read_case_file(*case_path);
    const CaseSurfaces surfaces = load_case_surfaces(c);
    run_midsurface_stage(c, surfaces, output->empty() ? c.output_dir : *output);
    return 0;
  });
}

}  // namespace igaprep::cli
