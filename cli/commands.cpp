#include "commands.h"

#include <map>

namespace igaprep::cli {

void add_check_mesh_command(CLI::App& app);
void add_tetmesh_command(CLI::App& app);
void add_offset_command(CLI::App& app);
void add_model_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_export_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_solve_command(CLI::App& app);
void add_midsurface_command(CLI::App& app);

namespace {
std::map<CLI::App*, CommandBody>& bodies() {
  static std::map<CLI::App*, CommandBody> table;
  return table;
}
}  // namespace

void set_body(CLI::App* sub, CommandBody body) { bodies()[sub] = std::move(body); }

void register_commands(CLI::App& app) {
  add_run_command(app);
  add_check_mesh_command(app);
  add_offset_command(app);
  add_tetmesh_command(app);
  add_midsurface_command(app);
  add_model_command(app);
  add_export_command(app);
  add_check_command(app);
  add_solve_command(app);
}

int run_selected(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands()) {
    auto it = bodies().find(sub);
    if (it != bodies().end()) return it->second();
  }
  return 1;
}

}  // namespace igaprep::cli
