#pragma once
// Runs the igaprep executable from a test and captures its output.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

struct CliResult {
  int exit_code = -1;
  std::string out;  // stdout and stderr together
};

// Any shell command, stdout and stderr together.
inline CliResult run_command(const std::string& shell_command) {
  CliResult r;
  const std::string command = shell_command + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline CliResult run_cli(const std::string& args) { return run_command(std::string(IGAPREP_CLI) + " " + args); }

inline std::string models_dir() { return std::string(IGAPREP_SOURCE_DIR) + "/models"; }

// An empty folder of the test's own below the build tree.
inline std::string scratch_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(IGAPREP_BINARY_DIR) / "tests" / "cli_scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
