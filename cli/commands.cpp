#include "commands.h"

#include <map>

namespace igaprep::cli {

namespace {
std::map<CLI::App*, CommandBody>& bodies() {
  static std::map<CLI::App*, CommandBody> table;
  return table;
}
}  // namespace

void set_body(CLI::App* sub, CommandBody body) { bodies()[sub] = std::move(body); }

void register_commands(CLI::App& app) {
  (void)app;
}

int run_selected(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands()) {
    auto it = bodies().find(sub);
    if (it != bodies().end()) return it->second();
  }
  return 1;
}

}  // namespace igaprep::cli
