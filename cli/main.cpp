// igaprep: the command-line entry point. Each subcommand lives in its own
// cmd_*.cpp file and registers itself here; errors become exit codes as
// ARCHITECTURE.md fixes them (1 bad input, 2 check failed, 3 internal).
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "commands.h"
#include "igaprep/core/error.h"

int main(int argc, char** argv) {
  CLI::App app{"igaprep: analysis-ready trivariate spline models from nested triangle meshes"};
  app.require_subcommand(1);
  igaprep::cli::register_commands(app);
  try {
    app.parse(argc, argv);
    return igaprep::cli::run_selected(app);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;
  } catch (const igaprep::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "error: internal failure: " << e.what() << "\n";
    return 3;
  }
}
