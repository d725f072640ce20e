#pragma once
// Helpers of the export tests: a scratch folder per test and running the
// independent Python readers (IGAPREP_PYTHON) with their output captured.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace igaprep::test {

inline std::string scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("igaprep_export_test_" + name + "_" + std::to_string(static_cast<long>(::getpid())));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct CommandResult {
  int status = -1;
  std::string output;  // stdout
};

inline CommandResult run_command(const std::string& command) {
  CommandResult r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof(buf), pipe)) > 0) r.output.append(buf, n);
  r.status = ::pclose(pipe);
  return r;
}

// Runs tests/export/<script> with the Debian python that has numpy, scipy,
// h5py and vtk; arguments are quoted here.
inline CommandResult run_python(const std::string& script, const std::vector<std::string>& args) {
  std::string cmd = std::string(IGAPREP_PYTHON) + " " +
                    shell_quote(std::string(IGAPREP_SOURCE_DIR) + "/tests/export/" + script);
  for (const std::string& a : args) cmd += " " + shell_quote(a);
  return run_command(cmd);
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace igaprep::test
