#pragma once
// Registration of the igaprep subcommands. Each command file defines one
// add_*_command function that adds its subcommand and a callback.
#include <CLI/CLI.hpp>
#include <functional>

namespace igaprep::cli {

// A subcommand's body; returns the exit code.
using CommandBody = std::function<int()>;

void register_commands(CLI::App& app);
int run_selected(CLI::App& app);

// Called by register_commands; each stores its body with set_body.
void set_body(CLI::App* sub, CommandBody body);

}  // namespace igaprep::cli
