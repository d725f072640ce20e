#include "igaprep/core/progress.h"

#include <algorithm>

namespace igaprep {

Progress::Progress(std::string task, std::size_t total, ProgressCallback callback)
    : task_(std::move(task)), total_(total), callback_(std::move(callback)) {}

Progress::~Progress() { finish(); }

void Progress::update(std::size_t done) {
  if (!callback_ || total_ == 0) return;
  const std::size_t percent = std::min<std::size_t>(100, done * 100 / total_);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  callback_(task_, std::min(done, total_), total_);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (callback_ && total_ > 0 && last_percent_ != 100) callback_(task_, total_, total_);
}

}  // namespace igaprep
