// Offset and tetrahedralization timings on the shared models.
// Usage: bench_mesh_volume offset | pelvis_tets | propeller_tets
// Each case runs in its own process so that peak memory (VmHWM) is its own.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "igaprep/mesh/offset_surface.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/mesh/tetrahedralize.h"

#include <sys/resource.h>

namespace {

long vm_hwm_kib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

long children_max_rss_kib() {
  struct rusage u {};
  getrusage(RUSAGE_CHILDREN, &u);
  return u.ru_maxrss;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace igaprep::mesh;
  const std::string what = argc > 1 ? argv[1] : "";
  const std::string models = IGAPREP_SHARED_MODELS_DIR;
  const std::string pelvis = models + "/pelvis_hip.stl", propeller = models + "/propeller.stl";
  if (!std::filesystem::exists(pelvis)) {
    std::fprintf(stderr, "shared models not found in %s\n", models.c_str());
    return 1;
  }
  if (what == "offset") {
    const TriMesh outer = read_surface(pelvis);
    const auto t0 = std::chrono::steady_clock::now();
    const TriMesh inner = offset_inward(outer, {0.8});
    std::printf("offset pelvis D=0.8: %.2f s, %d -> %d triangles, VmHWM %ld MiB\n", seconds_since(t0),
                int(outer.F.rows()), int(inner.F.rows()), vm_hwm_kib() / 1024);
  } else if (what == "pelvis_tets") {
    const TriMesh outer = read_surface(pelvis);
    const auto t0 = std::chrono::steady_clock::now();
    const TriMesh inner = offset_inward(outer, {0.8});
    const double t_offset = seconds_since(t0);
    const auto t1 = std::chrono::steady_clock::now();
    const TetMesh tm = tetrahedralize({outer, inner});
    std::printf("tetrahedralize pelvis + 0.8 offset (q1.5): %.2f s (offset %.2f s before), %d tets, %d points, "
                "VmHWM %ld MiB, TetGen process peak %ld MiB\n",
                seconds_since(t1), t_offset, int(tm.T.rows()), int(tm.V.rows()), vm_hwm_kib() / 1024,
                children_max_rss_kib() / 1024);
  } else if (what == "propeller_tets") {
    const TriMesh surface = read_surface(propeller);
    const auto t0 = std::chrono::steady_clock::now();
    const TetMesh tm = tetrahedralize({surface});
    std::printf("tetrahedralize propeller (q1.5): %.2f s, %d tets, %d points, VmHWM %ld MiB, TetGen process peak %ld MiB\n",
                seconds_since(t0), int(tm.T.rows()), int(tm.V.rows()), vm_hwm_kib() / 1024,
                children_max_rss_kib() / 1024);
  } else {
    std::fprintf(stderr, "usage: %s offset | pelvis_tets | propeller_tets\n", argv[0]);
    return 2;
  }
  return 0;
}
