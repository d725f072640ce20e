// Benchmark of the run's validation study (manufactured_study.h) on a fitted
// model: the given patches of MODEL.h5 as a sub-model, as the pipeline's
// validation stage does it.
// Usage: bench_solve_validation_study MODEL.h5 P,P,... [coarse fine [cholesky|cg|amg]]
// Plain main: prints each level's figures and times, then the rates.
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/manufactured_study.h"
#include "igaprep/spline/submodel.h"
#include "peak_memory.h"

using namespace igaprep;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s MODEL.h5 P,P,... [coarse fine [cholesky|cg|amg]]\n", argv[0]);
    return 2;
  }
  try {
    const spline::MultiPatch model = exporter::read_hdf5_model(argv[1]);
    std::vector<int> patches;
    std::stringstream list(argv[2]);
    for (std::string p; std::getline(list, p, ',');) patches.push_back(std::stoi(p));
    iga_check::ManufacturedOptions options;
    options.coarse_refine = argc > 3 ? std::atoi(argv[3]) : 0;
    options.fine_refine = argc > 4 ? std::atoi(argv[4]) : 1;
    if (argc > 5) options.solver = iga_check::linear_solver_named(argv[5]);
    const spline::MultiPatch sub = spline::submodel(model, patches, "validation cut");
    const auto st = iga_check::manufactured_study(sub, options);
    for (const auto& L : st.levels)
      std::printf("refine %d: %lld elements, %lld unknowns, rel L2 %.6e, rel energy %.6e, assembly %.2f s, solve (%s) "
                  "%.2f s, level %.2f s\n",
                  L.refine, L.elements, L.unknowns, L.l2_relative, L.energy_relative, L.assembly_seconds,
                  L.solver.c_str(), L.solve_seconds, L.seconds);
    std::printf("L2 rate %.4f, energy rate %.4f, peak memory %ld KiB\n", st.l2_rate, st.energy_rate,
                peak_memory_kib());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
