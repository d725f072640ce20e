// igaprep: the command-line entry point. Each subcommand lives in its own
// cmd_*.cpp file and registers itself here; errors become exit codes as
// ARCHITECTURE.md fixes them (1 bad input, 2 check failed, 3 internal).
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "commands.h"
#include "igaprep/core/allocator.h"
#include "igaprep/core/error.h"
#include "igaprep/pipeline/run.h"

namespace {

// A first argument that is no option and no command: named, with the commands.
bool refuse_unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == argv[1]) return false;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  std::cerr << "error: unknown command '" << argv[1] << "' (commands: " << names << ")\n";
  return true;
}

// Help and version go to stdout with exit 0; usage errors get the same
// "error: " prefix as every other error, exit 1.
int usage(const CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == 0) return app.exit(e);
  std::cerr << "error: " << e.what() << "\nRun with --help for more information.\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  igaprep::keep_freed_memory_for_reuse();
  CLI::App app{"igaprep: analysis-ready trivariate spline models from nested triangle meshes"};
  app.set_version_flag("--version", igaprep::pipeline::generator_name());
  app.require_subcommand(1);
  igaprep::cli::register_commands(app);
  if (refuse_unknown_command(app, argc, argv)) return 1;
  try {
    app.parse(argc, argv);
    return igaprep::cli::run_selected(app);
  } catch (const CLI::ParseError& e) {
    return usage(app, e);
  } catch (const igaprep::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "error: internal failure: " << e.what() << "\n";
    return 3;
  }
}
