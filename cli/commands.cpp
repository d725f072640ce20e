#include "commands.h"

#include <cstdio>
#include <filesystem>
#include <map>

#include "igaprep/mesh/read_surface.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/surfaces.h"

namespace igaprep::cli {

void add_check_mesh_command(CLI::App& app);
void add_tetmesh_command(CLI::App& app);
void add_offset_command(CLI::App& app);
void add_model_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_export_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_solve_command(CLI::App& app);
void add_tspline_command(CLI::App& app);
void add_midsurface_command(CLI::App& app);
void add_reduce_command(CLI::App& app);
void add_tnurcc_command(CLI::App& app);

namespace {
std::map<CLI::App*, CommandBody>& bodies() {
  static std::map<CLI::App*, CommandBody> table;
  return table;
}
}  // namespace

void set_body(CLI::App* sub, CommandBody body) { bodies()[sub] = std::move(body); }

void CheckLimitFlags::apply(iga_check::CheckOptions& options) const {
  if (fidelity_percent) options.fidelity_limit = *fidelity_percent / 100.0;
  if (volume_percent) options.volume_limit = *volume_percent / 100.0;
}

std::shared_ptr<CheckLimitFlags> add_check_limit_flags(CLI::App* sub) {
  auto flags = std::make_shared<CheckLimitFlags>();
  sub->add_option("--fidelity-limit", flags->fidelity_percent,
                  "largest distance between an input surface and the model, percent of the input's diagonal "
                  "(default 0.5, or the case's check.fidelity_limit)")
      ->check(CLI::Range(1e-6, 100.0));
  sub->add_option("--volume-limit", flags->volume_percent,
                  "largest material volume difference, percent of the input's (default 0.5, or the case's "
                  "check.volume_limit)")
      ->check(CLI::Range(1e-6, 100.0));
  return flags;
}

CheckInputs read_check_inputs(const std::string& case_file, const std::vector<std::string>& surface_files) {
  CheckInputs in;
  if (!case_file.empty()) {
    const pipeline::Case c = pipeline::read_case(case_file);
    in.options = c.check;
    in.meshes = pipeline::load_surfaces(c).inputs;
    for (const auto& cs : c.surfaces) in.labels.push_back(cs.label);
    return in;
  }
  for (const std::string& f : surface_files) {
    in.meshes.push_back(mesh::read_surface(f));
    in.labels.push_back(std::filesystem::path(f).stem().string());
  }
  return in;
}

void print_failed_criteria(const iga_check::CheckReport& report) {
  for (const std::string& line : iga_check::failure_lines(report)) std::printf("  %s\n", line.c_str());
}

void register_commands(CLI::App& app) {
  add_run_command(app);
  add_check_mesh_command(app);
  add_offset_command(app);
  add_tetmesh_command(app);
  add_midsurface_command(app);
  add_model_command(app);
  add_export_command(app);
  add_check_command(app);
  add_reduce_command(app);
  add_solve_command(app);
  add_tspline_command(app);
  add_tnurcc_command(app);
}

int run_selected(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands()) {
    auto it = bodies().find(sub);
    if (it != bodies().end()) return it->second();
  }
  return 1;
}

}  // namespace igaprep::cli
