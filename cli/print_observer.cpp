#include "print_observer.h"

#include <cstdio>
#include <filesystem>

namespace igaprep::cli {

PrintObserver::PrintObserver(std::string dir, std::set<std::string> wanted, bool all)
    : dir_(std::move(dir)), wanted_(std::move(wanted)), all_(all) {}

void PrintObserver::stage_finished(const pipeline::StageSummary& s) {
  std::printf("%-10s %7.2f s  %s\n", s.stage.c_str(), s.seconds, s.headline.c_str());
  for (const auto& line : s.details) std::printf("             %s\n", line.c_str());
  std::fflush(stdout);
}

bool PrintObserver::wants_intermediate(const std::string& name) const { return all_ || wanted_.count(name) > 0; }

void PrintObserver::intermediate(const std::string& name, const mesh::VtuMesh& mesh) {
  std::filesystem::create_directories(dir_);
  const std::string path = (std::filesystem::path(dir_) / (name + ".vtu")).string();
  mesh::write_vtu(path, mesh);
  std::printf("             wrote %s\n", path.c_str());
  std::fflush(stdout);
}

std::set<std::string> default_intermediates() {
  return {"tetmesh",          "midsurface_t1_regions", "midsurface_loops",     "midsurface_m0",
          "midsurface_m0trim", "midsurface_m0trim_uv",  "midsurface_rectangles", "base_surface"};
}

}  // namespace igaprep::cli
