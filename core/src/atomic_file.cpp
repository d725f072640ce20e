#include "igaprep/core/atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "igaprep/core/error.h"

namespace igaprep {

namespace {
std::string temporary_name(const std::string& path) {
  return path + ".tmp" + std::to_string(static_cast<long>(getpid()));
}
}  // namespace

AtomicPath::AtomicPath(std::string path) : path_(std::move(path)), temp_(temporary_name(path_)) {}

AtomicPath::~AtomicPath() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicPath::commit() {
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) {
    std::remove(temp_.c_str());
    throw bad_input("cannot write '" + path_ + "': rename from temporary file failed");
  }
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary) {
  AtomicPath target(path);
  {
    std::ofstream out(target.temp_path(), binary ? std::ios::binary | std::ios::out : std::ios::out);
    if (!out) throw bad_input("cannot write '" + path + "': cannot open a file in that folder");
    write(out);
    out.flush();
    if (!out) throw bad_input("cannot write '" + path + "': write failed (disk full?)");
  }
  target.commit();
}

}  // namespace igaprep
