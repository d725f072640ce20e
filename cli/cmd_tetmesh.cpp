// igaprep tetmesh CASE.json: the case's surfaces checked and tetrahedralized,
// written as <output>/tetmesh.vtu.
#include <filesystem>

#include "case_file.h"
#include "case_surfaces.h"
#include "commands.h"
#include "stage_tetmesh.h"

namespace igaprep::cli {

void add_tetmesh_command(CLI::App& app) {
  auto* sub = app.add_subcommand("tetmesh", "Tetrahedralize a case's nested surfaces with a material per tet");
  auto case_path = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  sub->add_option("case", *case_path, "case file (JSON, docs/case-format.md)")->required();
  sub->add_option("-o,--output", *output, "output folder (default: the case's output folder)");
  set_body(sub, [case_path, output] {
    const CaseFile c = read_case_file(*case_path);
    const CaseSurfaces surfaces = load_case_surfaces(c);
    const std::string dir = output->empty() ? c.output_dir : *output;
    run_tetmesh_stage(c, surfaces, (std::filesystem::path(dir) / "tetmesh.vtu").string());
    return 0;
  });
}

}  // namespace igaprep::cli
