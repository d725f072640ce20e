#pragma once
// Registration of the igaprep subcommands. Each command file defines one
// add_*_command function that adds its subcommand and a callback.
#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <optional>

#include <string>
#include <vector>

#include "igaprep/iga_check/report.h"
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::cli {

// A subcommand's body; returns the exit code.
using CommandBody = std::function<int()>;

void register_commands(CLI::App& app);
int run_selected(CLI::App& app);

// Called by register_commands; each stores its body with set_body.
void set_body(CLI::App* sub, CommandBody body);

// --fidelity-limit and --volume-limit (percent) of `check` and `run`; unset
// flags leave the case's (or the default) limits.
struct CheckLimitFlags {
  std::optional<double> fidelity_percent, volume_percent;
  void apply(iga_check::CheckOptions& options) const;
};
std::shared_ptr<CheckLimitFlags> add_check_limit_flags(CLI::App* sub);

// The input surfaces of `check` and `reduce`: a case's, with its check
// options, or surface files outermost first (labels: the files' stems).
struct CheckInputs {
  std::vector<mesh::TriMesh> meshes;
  std::vector<std::string> labels;
  iga_check::CheckOptions options;
};
CheckInputs read_check_inputs(const std::string& case_file, const std::vector<std::string>& surface_files);

// Prints the failed criteria of a check and where they fail, one line each.
void print_failed_criteria(const iga_check::CheckReport& report);

}  // namespace igaprep::cli
