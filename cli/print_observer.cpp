#include "print_observer.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "igaprep/core/atomic_file.h"

namespace igaprep::cli {

PrintObserver::PrintObserver(std::string dir, std::set<std::string> wanted, bool all)
    : dir_(std::move(dir)),
      wanted_(std::move(wanted)),
      all_(all),
      bar_(isatty(STDERR_FILENO) != 0 && std::getenv("IGAPREP_NO_PROGRESS") == nullptr) {}

void PrintObserver::progress(const std::string& task, std::size_t done, std::size_t total) {
  if (!bar_ || total == 0) return;
  if (done == 0 || task_start_ == std::chrono::steady_clock::time_point{}) task_start_ = std::chrono::steady_clock::now();
  const std::size_t percent = done * 100 / total;
  constexpr std::size_t kWidth = 30;
  std::fprintf(stderr, "\r%-24s [", task.c_str());
  for (std::size_t i = 0; i < kWidth; ++i) std::fputc(i < percent * kWidth / 100 ? '#' : '.', stderr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - task_start_).count();
  std::fprintf(stderr, "] %3zu%% %6.1fs", percent, seconds);
  if (done == total) {
    std::fputc('\n', stderr);
    task_start_ = {};
  }
  std::fflush(stderr);
}

void PrintObserver::stage_finished(const pipeline::StageSummary& s) {
  std::printf("%-10s %7.2f s  %s\n", s.stage.c_str(), s.seconds, s.headline.c_str());
  for (const auto& line : s.details) std::printf("             %s\n", line.c_str());
  std::fflush(stdout);
}

bool PrintObserver::wants_intermediate(const std::string& name) const { return all_ || wanted_.count(name) > 0; }

void PrintObserver::intermediate(const std::string& name, const mesh::VtuMesh& mesh) {
  // Where it is now (to look at during the run): the staging folder, moved
  // into dir_ with the outputs at the end.
  const std::string& into = staging_.empty() ? dir_ : staging_;
  create_output_folder(into);
  const std::string path = (std::filesystem::path(into) / (name + ".vtu")).string();
  mesh::write_vtu(path, mesh);
  std::printf("             wrote %s\n", path.c_str());
  std::fflush(stdout);
}

std::set<std::string> default_intermediates() {
  return {"tetmesh",          "midsurface_t1_regions", "midsurface_loops",     "midsurface_m0",
          "midsurface_m0trim", "midsurface_m0trim_uv",  "midsurface_rectangles", "base_surface"};
}

}  // namespace igaprep::cli
