#pragma once
// Writing files so that a failure never leaves a half-written output
// (ARCHITECTURE.md): write to a new temporary file beside the target (created
// with O_EXCL under an unpredictable name, so never through a planted
// symlink), sync it, rename it into place, sync the folder.
#include <functional>
#include <ostream>
#include <string>

namespace igaprep {

// Makes renames in `folder` durable: its entries reach the disk.
void sync_folder(const std::string& folder);
// The same for the folder that holds `path`.
void sync_folder_of(const std::string& path);

// Makes the folder an output goes into (and its parents). Throws bad_input
// naming it when it is an existing file or cannot be made (no permission, a
// read-only or virtual file system), before any work is spent on the output.
void create_output_folder(const std::string& dir);

// Calls write(stream) on a temporary file next to `path` and renames it into
// place when write returns and the stream is good. On any failure the
// temporary is removed, `path` is untouched, and an Error is thrown.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

// For libraries that write by file name (HDF5): creates the empty temporary
// file next to `path` (they then truncate it); call commit() after a
// successful write to sync it and rename it into place. The destructor
// removes the temporary if commit() was not called. Throws bad_input when
// the folder does not take a new file.
class AtomicPath {
 public:
  explicit AtomicPath(std::string path);
  ~AtomicPath();
  AtomicPath(const AtomicPath&) = delete;
  AtomicPath& operator=(const AtomicPath&) = delete;
  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_; }
  int descriptor() const { return fd_; }  // the temporary file, open for writing
  // Calls write(stream) on the temporary file; throws bad_input when the
  // stream fails. Several outputs can be written first and committed together.
  void write(const std::function<void(std::ostream&)>& write, bool binary = false);
  void commit();

 private:
  std::string path_;
  std::string temp_;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace igaprep
