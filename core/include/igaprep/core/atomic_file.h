#pragma once
// Writing files so that a failure never leaves a half-written output
// (ARCHITECTURE.md): write to a temporary name beside the target, then rename.
#include <functional>
#include <ostream>
#include <string>

namespace igaprep {

// Calls write(stream) on a temporary file next to `path` and renames it into
// place when write returns and the stream is good. On any failure the
// temporary is removed, `path` is untouched, and an Error is thrown.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

// For libraries that write by file name (HDF5, TetGen): returns a temporary
// name next to `path`; call commit() after a successful write to rename it
// into place. The destructor removes the temporary if commit() was not called.
class AtomicPath {
 public:
  explicit AtomicPath(std::string path);
  ~AtomicPath();
  AtomicPath(const AtomicPath&) = delete;
  AtomicPath& operator=(const AtomicPath&) = delete;
  const std::string& temp_path() const { return temp_; }
  void commit();

 private:
  std::string path_;
  std::string temp_;
  bool committed_ = false;
};

}  // namespace igaprep
