// Offset and tetrahedralization timings on the shared models.
// Usage: bench_mesh_volume offset [pelvis|propeller] [D] | pelvis_tets | propeller_tets
//   offset defaults to the pelvis at D = 0.8; the propeller has no default D
//   (its thin blades vanish at 0.3), so give one, e.g. 0.15.
// Each case runs in its own process so that peak memory (VmHWM) is its own.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "igaprep/mesh/check_surface.h"
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

int run(int argc, char** argv) {
  using namespace igaprep::mesh;
  const std::string what = argc > 1 ? argv[1] : "";
  const std::string models = IGAPREP_SHARED_MODELS_DIR;
  const std::string pelvis = models + "/pelvis_hip.stl", propeller = models + "/propeller.stl";
  if (!std::filesystem::exists(pelvis)) {
    std::fprintf(stderr, "shared models not found in %s\n", models.c_str());
    return 1;
  }
  if (what == "offset") {
    const std::string model = argc > 2 ? argv[2] : "pelvis";
    if (model != "pelvis" && model != "propeller") {
      std::fprintf(stderr, "offset: unknown model '%s' (pelvis or propeller)\n", model.c_str());
      return 2;
    }
    if (model == "propeller" && argc <= 3) {
      std::fprintf(stderr, "offset propeller: give D (e.g. 0.15; 0.3 is refused, the blades vanish)\n");
      return 2;
    }
    const double d = argc > 3 ? std::atof(argv[3]) : 0.8;
    const TriMesh outer = read_surface(model == "pelvis" ? pelvis : propeller);
    const auto t0 = std::chrono::steady_clock::now();
    const TriMesh inner = offset_inward(outer, {d});
    const double t = seconds_since(t0);
    const long hwm = vm_hwm_kib();  // before the check below adds its own memory
    const SurfaceReport rep = check_surface(inner, "offset");
    std::printf("offset %s D=%g: %.2f s, %d -> %d triangles, genus %d, self-intersections %d, VmHWM %ld MiB\n",
                model.c_str(), d, t, int(outer.F.rows()), int(inner.F.rows()), rep.genus, rep.self_intersections,
                hwm / 1024);
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
    std::fprintf(stderr, "usage: %s offset [pelvis|propeller] [D] | pelvis_tets | propeller_tets\n", argv[0]);
    return 2;
  }
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {  // e.g. a refused offset distance
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
