#include "ended_processes.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>

namespace igaprep::detail {

namespace {

// The pid in a name PREFIX<pid>-XXXXXX, or 0 when the name is not one.
pid_t pid_in_name(const std::string& name, const std::string& prefix) {
  if (name.rfind(prefix, 0) != 0) return 0;
  const std::string rest = name.substr(prefix.size());
  const std::size_t dash = rest.find('-');
  if (dash == 0 || dash == std::string::npos || dash > 9 || rest.size() != dash + 7) return 0;
  for (std::size_t i = 0; i < dash; ++i)
    if (rest[i] < '0' || rest[i] > '9') return 0;
  return static_cast<pid_t>(std::stol(rest.substr(0, dash)));
}

}  // namespace

std::string pid_tag() { return std::to_string(::getpid()) + "-"; }

bool process_runs(pid_t pid) {
  if (::kill(pid, 0) != 0 && errno == ESRCH) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;  // no /proc: trust kill()
  const std::size_t close = line.rfind(')');  // the command name may hold spaces and parentheses
  return close == std::string::npos || close + 2 >= line.size() || line[close + 2] != 'Z';
}

void remove_left_by_ended_processes(const std::filesystem::path& folder, const std::string& prefix) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder.empty() ? "." : folder, ec)) {
    const pid_t pid = pid_in_name(entry.path().filename().string(), prefix);
    if (pid > 0 && !process_runs(pid)) std::filesystem::remove_all(entry.path(), ec);
  }
}

}  // namespace igaprep::detail
