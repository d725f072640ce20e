// Time and peak memory of reading and checking the real test surfaces
// (read_surface + check_surface, which includes CGAL's self-intersection
// test). Plain main: prints one line per model and the process's peak RSS.
// Usage: bench_mesh_check [repetitions] [files...]   (default: 5 repetitions of
// pelvis_hip.stl and propeller.stl from ../shared/models)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/read_surface.h"
#include "peak_memory.h"

namespace {

// Peak resident set size of this process so far, in MiB.
double peak_rss_mib() { return peak_memory_kib() / 1024.0; }

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  std::vector<std::string> files;
  for (int i = 2; i < argc; ++i) files.push_back(argv[i]);
  if (files.empty()) {
    const std::string dir = IGAPREP_SHARED_MODELS_DIR;
    files = {dir + "/pelvis_hip.stl", dir + "/propeller.stl"};
  }
  std::printf("%-40s %8s %8s %6s %9s %9s %9s %9s\n", "file", "vertices", "faces", "genus", "read_s", "check_s",
              "total_s", "rss_MiB");
  for (const std::string& file : files) {
    std::vector<double> read_s, check_s, total_s;
    igaprep::mesh::SurfaceReport report;
    try {
      for (int r = 0; r < reps; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        igaprep::mesh::TriMesh mesh = igaprep::mesh::read_surface(file);
        const double t_read = seconds_since(t0);
        const auto t1 = std::chrono::steady_clock::now();
        report = igaprep::mesh::check_and_repair_surface(mesh, file);
        check_s.push_back(seconds_since(t1));
        read_s.push_back(t_read);
        total_s.push_back(seconds_since(t0));
      }
    } catch (const igaprep::Error& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 1;
    }
    // Median of the repetitions.
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    const std::string name = file.substr(file.find_last_of('/') + 1);
    std::printf("%-40s %8d %8d %6d %9.3f %9.3f %9.3f %9.1f\n", name.c_str(), report.vertices, report.faces,
                report.genus, median(read_s), median(check_s), median(total_s), peak_rss_mib());
    if (!report.ok() || !report.warnings.empty()) std::printf("%s", igaprep::mesh::format_report(report).c_str());
  }
  std::printf("median of %d repetitions; rss_MiB is the process's peak RSS so far (VmHWM)\n", reps);
  return 0;
}
