#include "tetgen_run.h"

#include <tetgen.h>

#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "igaprep/core/error.h"

namespace igaprep::mesh::detail {
namespace {

constexpr std::int64_t kMagicOk = 0x7465746f6b;  // "tetok"
constexpr std::int64_t kMagicFail = 0x74657466;  // "tetf"

bool write_all(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

std::string code_reason(int code) {
  switch (code) {
    case 1:
      return "out of memory";
    case 2:
      return "TetGen internal error";
    case 3:
      return "two input facets intersect";
    case 4:
      return "a very small input feature (nearly coincident points or facets)";
    case 5:
      return "two input facets are very close to each other";
    case 10:
      return "TetGen rejected the input";
    default:
      return "TetGen error code " + std::to_string(code);
  }
}

// The last few non-empty lines TetGen printed, joined.
std::string tail_lines(const std::string& text, int count) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line.substr(line.find_first_not_of(" \t")));
  std::string out;
  for (std::size_t i = lines.size() > static_cast<std::size_t>(count) ? lines.size() - count : 0; i < lines.size(); ++i) {
    if (!out.empty()) out += " | ";
    out += lines[i];
  }
  return out;
}

}  // namespace

TetgenOutput run_tetgen(tetgenio& in, const std::string& switches, bool echo, const std::string& what) {
  tetgenbehavior behavior;
  std::vector<char> sw(switches.begin(), switches.end());
  sw.push_back('\0');
  if (!behavior.parse_commandline(sw.data())) {
    throw internal_error(what + ": TetGen rejected the switches '" + switches + "'");
  }

  FILE* log = std::tmpfile();
  int fds[2];
  if (!log || ::pipe(fds) != 0) {
    if (log) std::fclose(log);
    throw internal_error(what + ": cannot create a pipe for TetGen: " + std::strerror(errno));
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    std::fclose(log);
    throw internal_error(what + ": cannot fork for TetGen: " + std::strerror(errno));
  }
  if (pid == 0) {
    // Child: dies with its parent (a SIGKILL of igaprep, a CI timeout), also
    // when the parent died before the request took effect.
    if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || ::getppid() != parent) ::_exit(1);
    // TetGen's stdout goes to the log; results go to the pipe.
    ::close(fds[0]);
    ::dup2(fileno(log), 1);
    // Unbuffered, so that TetGen's last words survive a crash.
    std::setvbuf(stdout, nullptr, _IONBF, 0);
    tetgenio out;
    std::int64_t header[4] = {kMagicFail, 0, 0, 0};
    try {
      ::tetrahedralize(&behavior, &in, &out);
    } catch (int code) {
      std::fflush(stdout);
      header[1] = code;
      write_all(fds[1], header, sizeof header);
      ::_exit(0);
    } catch (...) {
      std::fflush(stdout);
      header[1] = 1;
      write_all(fds[1], header, sizeof header);
      ::_exit(0);
    }
    std::fflush(stdout);
    header[0] = kMagicOk;
    header[1] = out.numberofpoints;
    header[2] = out.numberoftetrahedra;
    header[3] = out.numberofcorners;
    bool ok = write_all(fds[1], header, sizeof header);
    ok = ok && write_all(fds[1], out.pointlist, sizeof(double) * 3 * out.numberofpoints);
    ok = ok && write_all(fds[1], out.tetrahedronlist, sizeof(int) * out.numberofcorners * out.numberoftetrahedra);
    ok = ok && (out.neighborlist == nullptr ||
                write_all(fds[1], out.neighborlist, sizeof(int) * 4 * out.numberoftetrahedra));
    ::_exit(ok ? 0 : 1);
  }

  // Parent: read everything, then reap the child.
  ::close(fds[1]);
  std::vector<char> data;
  {
    char buf[1 << 16];
    for (;;) {
      const ssize_t n = ::read(fds[0], buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      data.insert(data.end(), buf, buf + n);
    }
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  struct rusage usage {};
  ::getrusage(RUSAGE_CHILDREN, &usage);

  std::string printed;
  {
    std::fflush(log);
    std::rewind(log);
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, log)) > 0) printed.append(buf, n);
    std::fclose(log);
  }
  if (echo) {
    std::fwrite(printed.data(), 1, printed.size(), stdout);
    std::fflush(stdout);
  }
  const std::string said = tail_lines(printed, 3);
  const std::string tetgen_said = said.empty() ? "" : " (TetGen: " + said + ")";

  std::int64_t header[4] = {0, 0, 0, 0};
  if (data.size() >= sizeof header) std::memcpy(header, data.data(), sizeof header);
  if (header[0] == kMagicFail) {
    throw bad_input(what + ": TetGen failed: " + code_reason(static_cast<int>(header[1])) + tetgen_said);
  }
  if (WIFSIGNALED(status) || header[0] != kMagicOk) {
    const std::string how = WIFSIGNALED(status) ? "its process ended with signal " + std::to_string(WTERMSIG(status))
                                                : "its process exited with status " + std::to_string(WEXITSTATUS(status));
    throw bad_input(what + ": TetGen failed on this input" + (said.empty() ? "" : ": " + said) + " (" + how + ")");
  }
  const std::int64_t np = header[1], nt = header[2], nc = header[3];
  const std::size_t need = sizeof header + sizeof(double) * 3 * np + sizeof(int) * (nc + 4) * nt;
  if (nc != 4 || data.size() != need) {
    throw internal_error(what + ": TetGen's output was truncated or malformed");
  }
  TetgenOutput result;
  result.points.resize(3 * np);
  result.tets.resize(4 * nt);
  result.neighbors.resize(4 * nt);
  const char* p = data.data() + sizeof header;
  std::memcpy(result.points.data(), p, sizeof(double) * 3 * np);
  p += sizeof(double) * 3 * np;
  std::memcpy(result.tets.data(), p, sizeof(int) * 4 * nt);
  p += sizeof(int) * 4 * nt;
  std::memcpy(result.neighbors.data(), p, sizeof(int) * 4 * nt);
  result.child_max_rss_kib = usage.ru_maxrss;
  return result;
}

}  // namespace igaprep::mesh::detail
