#include "igaprep/core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ext/stdio_filebuf.h>
#include <filesystem>
#include <fstream>
#include <vector>

#include "ended_processes.h"
#include "igaprep/core/error.h"

namespace igaprep {

namespace {

// The process's umask without changing it (umask(2) would, for all threads).
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::stoul(line.substr(6), nullptr, 8));
  return 022;
}

// A file beside `path` that did not exist before (mkostemp: O_CREAT|O_EXCL,
// so never through a planted symlink) under a name no one can predict, with
// the permissions an ordinary new file gets.
// The name is NAME.tmp<pid>-XXXXXX: a temporary that a killed process left
// is removed by the next write of the same output.
int create_temporary(const std::string& path, std::string& name) {
  const std::filesystem::path target(path);
  detail::remove_left_by_ended_processes(target.parent_path(), target.filename().string() + ".tmp");
  std::vector<char> pattern(path.begin(), path.end());
  for (char c : ".tmp" + detail::pid_tag() + "XXXXXX") pattern.push_back(c);
  pattern.push_back('\0');
  const int fd = ::mkostemp(pattern.data(), O_CLOEXEC);
  if (fd < 0) throw bad_input("cannot write '" + path + "': cannot create a file in that folder: " + std::strerror(errno));
  name = pattern.data();
  if (::fchmod(fd, 0666 & ~current_umask()) != 0) {
    ::close(fd);
    std::remove(name.c_str());
    throw bad_input("cannot write '" + path + "': cannot set the permissions of a new file: " + std::strerror(errno));
  }
  return fd;
}

}  // namespace

void sync_folder_of(const std::string& path) {
  const std::string folder = std::filesystem::path(path).parent_path().string();
  sync_folder(folder.empty() ? "." : folder);
}

void sync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // the file itself is synced; some file systems refuse folders
  ::fsync(fd);
  ::close(fd);
}

AtomicPath::AtomicPath(std::string path) : path_(std::move(path)) { fd_ = create_temporary(path_, temp_); }

AtomicPath::~AtomicPath() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicPath::commit() {
  // The contents reach the disk before the name does: after a power loss the
  // final name holds the old file or the whole new one, never an empty one.
  const bool synced = ::fsync(fd_) == 0;
  if (!synced || std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(temp_.c_str());
    throw bad_input("cannot write '" + path_ + "': " + (synced ? "rename from temporary file failed: " : "sync failed: ") +
                    why);
  }
  committed_ = true;
  sync_folder_of(path_);
}

void AtomicPath::write(const std::function<void(std::ostream&)>& write, bool binary) {
  // Through the descriptor mkostemp opened, not the name.
  const int fd = ::dup(fd_);
  if (fd < 0) throw bad_input("cannot write '" + path_ + "': " + std::strerror(errno));
  __gnu_cxx::stdio_filebuf<char> buffer(fd, binary ? std::ios::binary | std::ios::out : std::ios::out);
  std::ostream out(&buffer);
  write(out);
  out.flush();
  if (!out) throw bad_input("cannot write '" + path_ + "': write failed (disk full?)");
}

void create_output_folder(const std::string& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw bad_input("output folder '" + dir + "' is an existing file, not a folder");
  std::filesystem::create_directories(dir, ec);
  if (ec) throw bad_input("cannot create the output folder '" + dir + "': " + ec.message());
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary) {
  AtomicPath target(path);
  target.write(write, binary);
  target.commit();
}

}  // namespace igaprep
