// Benchmark of the elasticity solver: assembly throughput (unknowns/s,
// quadrature points/s), solve time and peak memory, for a cantilever box of
// one B-spline patch at degree p with n elements per direction.
// Usage: bench_solve_elasticity [p n [cholesky|cg]]   (default: the four
// cases of docs/performance.md). Plain main: each case is one solve.
#include <Eigen/Core>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "igaprep/iga_check/elasticity_solve.h"
#include "bench_models.h"
#include "peak_memory.h"

using namespace igaprep;

namespace {

void run(int p, int n, iga_check::LinearSolver solver) {
  iga_check::ElasticityProblem problem;
  problem.fixed = {{"clamp", {{true, true, true}}}};
  problem.tractions = {{"tip", Eigen::Vector3d(0, 0, -1e6)}};
  iga_check::ElasticityOptions options;
  options.solver = solver;
  const auto sol = iga_check::solve_elasticity(cantilever_box(p, n), problem, options);
  const auto& r = sol.report;
  std::printf(
      "p=%d n=%d solver=%s unknowns=%lld nonzeros=%lld elements=%lld qpoints=%lld assembly=%.2fs "
      "(%.3g unknowns/s, %.3g qpoints/s) solve=%.2fs total=%.2fs cg_iterations=%d energy=%.6g max_u=%.6g "
      "VmHWM=%.0f MiB\n",
      p, n, r.solver.c_str(), r.unknowns, r.nonzeros, r.elements, r.quadrature_points, r.assembly_seconds,
      r.unknowns / r.assembly_seconds, r.quadrature_points / r.assembly_seconds, r.solve_seconds,
      r.assembly_seconds + r.solve_seconds, r.cg_iterations, r.strain_energy, r.max_displacement,
      peak_memory_kib() / 1024.0);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3) {
    const auto solver = (argc >= 4 && std::string(argv[3]) == "cg") ? iga_check::LinearSolver::ConjugateGradient
                                                                     : iga_check::LinearSolver::Cholesky;
    run(std::atoi(argv[1]), std::atoi(argv[2]), solver);
    return 0;
  }
  // About 50,000 and 200,000 unknowns at p = 2 and 3, preconditioned CG
  // (with Debian's reference BLAS the supernodal Cholesky factorization of
  // these 3-D problems takes minutes; run "2 24 cholesky" to see it).
  run(2, 24, iga_check::LinearSolver::ConjugateGradient);
  run(3, 23, iga_check::LinearSolver::ConjugateGradient);
  run(2, 39, iga_check::LinearSolver::ConjugateGradient);
  run(3, 38, iga_check::LinearSolver::ConjugateGradient);
  return 0;
}
