#include "igaprep/core/progress.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace igaprep {

bool Progress::enabled() {
  static const bool on = isatty(STDERR_FILENO) != 0 && std::getenv("IGAPREP_NO_PROGRESS") == nullptr;
  return on;
}

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), active_(enabled()), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

double Progress::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(std::size_t done) {
  if (!active_ || total_ == 0) return;
  const std::size_t percent = std::min<std::size_t>(100, done * 100 / total_);
  if (percent != last_drawn_percent_) draw(done);
}

void Progress::draw(std::size_t done) {
  const std::size_t percent = std::min<std::size_t>(100, done * 100 / total_);
  last_drawn_percent_ = percent;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(percent * kWidth / 100);
  std::fprintf(stderr, "\r%-24s [", label_.c_str());
  for (int i = 0; i < kWidth; ++i) std::fputc(i < filled ? '#' : '.', stderr);
  std::fprintf(stderr, "] %3zu%% %6.1fs", percent, elapsed_seconds());
  std::fflush(stderr);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (!active_ || total_ == 0) return;
  draw(total_);
  std::fputc('\n', stderr);
}

}  // namespace igaprep
