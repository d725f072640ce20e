// Benchmark of the manufactured-solution study (manufactured_study.h) on a
// multipatch model like a fitted one: a thick ring (1 < r < 2, 0 < z < 1)
// of 8 exact NURBS sectors x 2 layers = 16 patches of degree 3, every other
// patch reoriented, every outer side labelled T1.
// Usage: bench_solve_manufactured [coarse fine [cholesky|cg]]  (default 1 2 cholesky).
// Plain main: prints the figures of both levels and the rates.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "../tests/solve/solve_models.h"
#include "igaprep/iga_check/manufactured_study.h"
#include "peak_memory.h"

using namespace igaprep;

namespace {

spline::MultiPatch ring() {
  const double pi = 3.14159265358979323846;
  spline::MultiPatch mp;
  for (int layer = 0; layer < 2; ++layer)
    for (int s = 0; s < 8; ++s) {
      spline::Patch p = solve_test::sector_patch(1.0, 2.0, s * pi / 4, (s + 1) * pi / 4, 0.5 * layer, 0.5 * (layer + 1));
      for (int d = 0; d < 3; ++d) p = spline::elevate_degree(p, d, 1);
      if ((s + layer) % 2) p = solve_test::reorient(p, {2, 0, 1}, {true, false, true});
      mp.patches.push_back(p);
    }
  mp.materials = {{"m", 1.0, 0.3}};
  solve_test::find_interfaces(mp);
  solve_test::label_boundaries(mp, [](const Eigen::Vector3d&) { return std::string("T1"); });
  return mp;
}


}  // namespace

int main(int argc, char** argv) {
  iga_check::ManufacturedOptions options;
  options.coarse_refine = argc > 1 ? std::atoi(argv[1]) : 1;
  options.fine_refine = argc > 2 ? std::atoi(argv[2]) : 2;
  if (argc > 3 && std::strcmp(argv[3], "cg") == 0) {
    options.solver = iga_check::LinearSolver::ConjugateGradient;
  }
  try {
    const spline::MultiPatch mp = ring();
    std::printf("model: %zu patches, %zu interfaces, %zu boundary sides\n", mp.patches.size(), mp.interfaces.size(),
                mp.boundaries.size());
    const auto st = iga_check::manufactured_study(mp, options);
    for (const auto& L : st.levels)
      std::printf("refine %d: %lld elements, h %.4f, %lld unknowns, %lld prescribed, rel L2 %.3e, rel energy %.3e, "
                  "assembly %.2f s, solve (%s) %.2f s, level %.2f s\n",
                  L.refine, L.elements, L.h, L.unknowns, L.prescribed_dofs, L.l2_relative, L.energy_relative,
                  L.assembly_seconds, L.solver.c_str(), L.solve_seconds, L.seconds);
    std::printf("L2 rate %.3f, energy rate %.3f (h ratio %.1f), peak memory %ld KiB\n", st.l2_rate, st.energy_rate,
                st.h_ratio, peak_memory_kib());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
