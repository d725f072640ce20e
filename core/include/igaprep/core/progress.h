#pragma once
// Progress of a long step on stderr: a redrawn bar when stderr is a terminal,
// nothing per tick otherwise (the caller prints one summary line per stage).
#include <chrono>
#include <cstddef>
#include <string>

namespace igaprep {

class Progress {
 public:
  Progress(std::string label, std::size_t total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Sets the number of finished units; cheap to call often.
  void update(std::size_t done);
  void finish();
  double elapsed_seconds() const;

  // True when stderr is a terminal (and IGAPREP_NO_PROGRESS is unset).
  static bool enabled();

 private:
  void draw(std::size_t done);
  std::string label_;
  std::size_t total_;
  std::size_t last_drawn_percent_ = static_cast<std::size_t>(-1);
  bool active_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace igaprep
