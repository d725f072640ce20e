#pragma once
// Progress of a long step, reported to a callback the caller supplies (the
// CLI draws a bar from it, a test records it, Python may ignore it). The
// library never prints: without a callback nothing happens.
#include <cstddef>
#include <functional>
#include <string>

namespace igaprep {

// (task, done, total): `done` of `total` units of the named task.
using ProgressCallback = std::function<void(const std::string& task, std::size_t done, std::size_t total)>;

// Calls the callback when the finished share changes by a whole percent (so
// a caller may update it for every unit) and once more at the end.
class Progress {
 public:
  Progress(std::string task, std::size_t total, ProgressCallback callback);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void update(std::size_t done);  // cheap to call often
  void finish();                  // reports total of total (once)

 private:
  std::string task_;
  std::size_t total_;
  ProgressCallback callback_;
  std::size_t last_percent_ = static_cast<std::size_t>(-1);
  bool finished_ = false;
};

}  // namespace igaprep
