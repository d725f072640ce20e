#pragma once
// Wall-clock time of a stage, for its summary.
#include <chrono>

namespace igaprep::pipeline {

class StageTimer {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace igaprep::pipeline
