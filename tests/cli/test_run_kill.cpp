// `igaprep run` killed with SIGKILL at any moment leaves the previous
// outputs intact and consistent, and no process of its own behind (issue
// 21, item 8; core/output_folder.h).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;

// sphere2 with three exports and no validation; `keys` (the fit's and
// TetGen's) make the runs' files differ from the first one on.
std::string write_case(const std::string& path, const std::string& keys) {
  const std::string m = models_dir() + "/sphere2/";
  std::ofstream(path) << R"({"name": "kill", "surfaces": [{"file": ")" << m << R"(outer.off", "label": "outer"},
    {"file": ")" << m << R"(inner.off", "label": "inner"}], "export": ["gismo", "mfem", "vtu"],
    "validation": {"enabled": false}, )" << keys << "}";
  return path;
}

// Every file in the output folder, by name: the outputs and the intermediates.
std::map<std::string, std::string> folder_contents(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) files[e.path().filename().string()] = read_all(e.path().string());
  return files;
}

pid_t spawn_run(const std::string& case_path, const std::string& out) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  std::vector<std::string> args = {IGAPREP_CLI, "run", case_path, "-o", out};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  if (posix_spawn(&pid, IGAPREP_CLI, &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Waits up to `seconds` for the process to end; kills it with SIGKILL if it
// has not. True when it ended by itself (with exit status `*code`).
bool ended_within(pid_t pid, double seconds, int* code) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < until) {
    if (waitpid(pid, &status, WNOHANG) == pid) {
      *code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return false;
}

// Processes other than this one whose command line holds `marker`.
int processes_naming(const std::string& marker) {
  int count = 0;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos || std::stol(name) == getpid()) continue;
    std::string cmdline = read_all(e.path().string() + "/cmdline");
    for (char& ch : cmdline)
      if (ch == '\0') ch = ' ';
    if (cmdline.find(marker) != std::string::npos) ++count;
  }
  return count;
}

std::vector<std::string> names_of(const std::map<std::string, std::string>& files) {
  std::vector<std::string> names;
  for (const auto& f : files) names.push_back(f.first);
  return names;
}

int elements_per_direction(const std::string& out) {
  const auto report = nlohmann::json::parse(read_all(out + "/report.json"));
  return report.at("pipeline").at("figures").at("elements_per_direction").get<int>();
}

TEST(RunKill, AKilledRunLeavesThePreviousOutputsAndNoProcess) {
  const auto dir = scratch_dir("run_kill");
  const std::string small = write_case(
      dir + "/small.json", R"("fit": {"elements": 2, "jacobian_target": 0}, "tetmesh": {"radius_edge_ratio": 2},
      "decomposition": {"cover_rounds": 0})");  // halved rectangles would make it pass
  const std::string full = write_case(dir + "/full.json", R"("fit": {"elements": 6})");
  const std::string out = dir + "/out";
  fs::create_directories(out);
  std::ofstream(out + "/notes.txt") << "the user's own file";
  // The full run takes about 2.5 to 3 s (TetGen in its worker, the fit's repair,
  // the check, four exports): killed at each of these times, then let finish.
  for (const double seconds : {0.05, 0.3, 0.9, 1.8, 2.6, 120.0}) {
    SCOPED_TRACE("killed after " + std::to_string(seconds) + " s");
    const CliResult previous = run_cli("run " + small + " -o " + out);
    ASSERT_EQ(previous.exit_code, 2) << previous.out;  // a 2-element sphere fails its fidelity
    const auto before = folder_contents(out);
    ASSERT_EQ(elements_per_direction(out), 2);

    const pid_t pid = spawn_run(full, out);
    ASSERT_GT(pid, 0);
    int code = -1;
    const bool ended = ended_within(pid, seconds, &code);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // TetGen's worker dies with its parent
    EXPECT_EQ(processes_naming(full), 0);

    const auto after = folder_contents(out);
    EXPECT_EQ(after.at("notes.txt"), "the user's own file");
    EXPECT_EQ(names_of(after), names_of(before));
    // Killed before its outputs went in: every file as it was (compared
    // whole, reported by name). Killed after (the outputs are exchanged at
    // once, then the previous folder is removed): the new run's, whole.
    if (!ended && elements_per_direction(out) != 6) {
      for (const auto& [name, data] : after) EXPECT_TRUE(data == before.at(name)) << name << " changed";
      continue;
    }
    if (ended) EXPECT_EQ(code, 0);
    // The new run's: the model, its exports, the report and the tet mesh
    // (the first intermediate; some later ones do not depend on TetGen).
    EXPECT_EQ(elements_per_direction(out), 6);
    for (const char* name : {"tetmesh.vtu", "model.h5", "model.xml", "model.mesh", "model.vtu", "report.json", "report.html"})
      EXPECT_FALSE(after.at(name) == before.at(name)) << name << " is the previous run's";
  }
  // The killed runs' staging folders are gone (each run removes those of
  // processes that no longer run) and no temporary file is left.
  for (const std::string& folder : {dir, out})
    for (const auto& e : fs::directory_iterator(folder)) {
      const std::string name = e.path().filename().string();
      EXPECT_EQ(name.find(".igaprep-"), std::string::npos) << folder << "/" << name;
      EXPECT_EQ(name.find(".tmp"), std::string::npos) << folder << "/" << name;
    }
}

}  // namespace
