// Benchmark of the linear solvers on the two-material thick cylinder
// (tests/solve/lame_cylinder.h: four exact NURBS sectors at degree 3, one
// element each, refined uniformly in every direction): unknowns, assembly
// and solve time, CG iterations, the true relative residual, peak memory and
// the strain energy against the closed form's.
// Usage: bench_solve_cylinder REFINE [auto|cholesky|cg|amg [TOLERANCE]]
// (default: refinements 3 and 4 with amg). One solve per process, so the
// peak memory is that solve's.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "igaprep/iga_check/elasticity_solve.h"
#include "lame_cylinder.h"
#include "peak_memory.h"

using namespace igaprep;

namespace {

void run(int refine, const std::string& solver, double tolerance) {
  iga_check::ElasticityOptions options;
  options.refine = refine;
  options.solver = iga_check::linear_solver_named(solver);
  options.cg_tolerance = tolerance;
  options.max_unknowns = 10'000'000;
  const auto sol = iga_check::solve_elasticity(solve_test::composite_cylinder(3, 0), solve_test::cylinder_problem(), options);
  const auto& r = sol.report;
  const double exact = solve_test::cylinder_strain_energy();
  std::printf(
      "refine=%d solver=%s unknowns=%lld nonzeros=%lld assembly=%.2fs solve=%.2fs total=%.2fs iterations=%d "
      "residual=%.2e energy=%.13g relative_to_closed_form=%.2e VmHWM=%.0f MiB\n",
      refine, r.solver.c_str(), r.unknowns, r.nonzeros, r.assembly_seconds, r.solve_seconds,
      r.assembly_seconds + r.solve_seconds, r.cg_iterations, r.cg_residual, r.strain_energy,
      (r.strain_energy - exact) / exact, peak_memory_kib() / 1024.0);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2) {
    run(std::atoi(argv[1]), argc >= 3 ? argv[2] : "amg", argc >= 4 ? std::atof(argv[3]) : 1e-8);
    return 0;
  }
  run(3, "amg", 1e-8);
  run(4, "amg", 1e-8);
  return 0;
}
