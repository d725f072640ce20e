#include "igaprep/core/output_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "ended_processes.h"

namespace igaprep {

namespace fs = std::filesystem;

namespace {

const char* const kStagingTag = ".igaprep-";

// A new folder `prefix` + "<pid>-XXXXXX" (mkdtemp: created exclusively, mode
// 0700), or "" when the folder it goes into takes none.
std::string make_staging(const std::string& prefix) {
  std::string pattern = prefix + detail::pid_tag() + "XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  return ::mkdtemp(name.data()) ? std::string(name.data()) : std::string();
}

// Only files and symlinks: nothing that a swap of the folder could strand.
bool holds_files_only(const fs::path& folder) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const fs::file_type t = entry.symlink_status(ec).type();
    if (t != fs::file_type::regular && t != fs::file_type::symlink) return false;
  }
  return !ec;
}

bool is_within(const fs::path& inner, const fs::path& outer) {
  const std::string a = inner.string(), b = outer.string();
  return a == b || (a.size() > b.size() && a.compare(0, b.size(), b) == 0 && a[b.size()] == '/');
}

bool same_device(const fs::path& a, const fs::path& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev;
}

}  // namespace

OutputFolder::OutputFolder(std::string dir) : dir_(std::move(dir)) {
  create_output_folder(dir_);
  std::error_code ec;
  const fs::path real = fs::canonical(dir_, ec);
  if (ec) throw bad_input("cannot resolve the output folder '" + dir_ + "': " + ec.message());
  real_ = real.string();
  const fs::path parent = real.parent_path();
  const std::string sibling_prefix = "." + real.filename().string() + kStagingTag;
  detail::remove_left_by_ended_processes(parent, sibling_prefix);
  detail::remove_left_by_ended_processes(real, kStagingTag);
  const fs::path cwd = fs::current_path(ec);
  const bool swappable = real != parent && holds_files_only(real) && !(!ec && is_within(cwd, real)) &&
                         same_device(real, parent);
  if (swappable) staging_ = make_staging((parent / sibling_prefix).string());
  atomic_ = !staging_.empty();
  if (atomic_) {
    struct stat st {};
    if (::stat(real.c_str(), &st) == 0) ::chmod(staging_.c_str(), st.st_mode & 07777);
  } else {
    staging_ = make_staging((real / kStagingTag).string());
    if (staging_.empty())
      throw bad_input("cannot write into the output folder '" + dir_ + "': " + std::strerror(errno));
  }
}

OutputFolder::~OutputFolder() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void OutputFolder::commit(const std::vector<std::string>& summaries) {
  if (committed_) throw internal_error("OutputFolder: committed twice");
  if (atomic_ && holds_files_only(real_)) commit_by_exchange(summaries);
  else commit_file_by_file(summaries);
  committed_ = true;
}

void OutputFolder::commit_by_exchange(const std::vector<std::string>& summaries) {
  // The folder's other files go into the new one too (hard links: the same
  // files, nothing copied), so the swap keeps them.
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(real_, ec)) {
    const fs::path target = fs::path(staging_) / entry.path().filename();
    if (fs::exists(fs::symlink_status(target, ec))) continue;
    if (::linkat(AT_FDCWD, entry.path().c_str(), AT_FDCWD, target.c_str(), 0) != 0) return commit_file_by_file(summaries);
  }
  if (ec) return commit_file_by_file(summaries);
  sync_folder(staging_);
  // The resolved folder: a symlink named as the output folder stays a symlink.
  if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, real_.c_str(), RENAME_EXCHANGE) != 0) {
    if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP) return commit_file_by_file(summaries);
    throw bad_input("cannot put the outputs into '" + dir_ + "': " + std::strerror(errno));
  }
  sync_folder_of(real_);  // the parent: both names changed there
  fs::remove_all(staging_, ec);  // now the previous folder; a killed run's is removed by the next
}

void OutputFolder::commit_file_by_file(const std::vector<std::string>& summaries) {
  auto is_summary = [&](const fs::path& name) {
    return std::find(summaries.begin(), summaries.end(), name.string()) != summaries.end();
  };
  auto put_in_place = [&](const fs::path& staged) {
    const fs::path target = fs::path(dir_) / staged.filename();
    if (std::rename(staged.c_str(), target.c_str()) != 0)
      throw bad_input("cannot put '" + target.string() + "' in place: " + std::strerror(errno));
  };
  std::error_code ec;
  for (const std::string& name : summaries)
    if (fs::exists(fs::path(staging_) / name, ec)) fs::remove(fs::path(dir_) / name, ec);
  sync_folder(dir_);
  std::vector<fs::path> last;
  for (const auto& entry : fs::directory_iterator(staging_, ec)) {
    if (is_summary(entry.path().filename())) last.push_back(entry.path());
    else put_in_place(entry.path());
  }
  if (ec) throw bad_input("cannot read the staged outputs in '" + staging_ + "': " + ec.message());
  sync_folder(dir_);
  for (const fs::path& staged : last) put_in_place(staged);
  sync_folder(dir_);
  fs::remove_all(staging_, ec);
}

}  // namespace igaprep
