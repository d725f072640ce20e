// Harmonic field on about a million tets: assembly, CHOLMOD (or LDL^T) vs
// preconditioned CG, factorization and solve timed separately, and the
// speed-up of reusing the factorization for new Dirichlet values.
// Mesh: a structured box, 55^3 cubes x 6 tets = 998,250 tets (TetGen takes far
// longer than the solve to make a million tets), interior vertices jittered.
// Usage: bench_param_laplace [cubes per side, default 55 | shell] [nochol: skip the Cholesky row]
// `shell`: the graded spherical shell 1 < r < 2 (icosphere level 5 x 8 layers,
// 491,520 tets, 4x larger tets outside than inside) with u = 1 / 0 on the spheres.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../tests/param/param_meshes.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/stiffness_matrix.h"

using namespace igaprep::param;
using Clock = std::chrono::steady_clock;

static double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

int main(int argc, char** argv) {
  const bool shell = argc > 1 && std::string(argv[1]) == "shell";
  const int n = argc > 1 && !shell ? std::atoi(argv[1]) : 55;
  auto t0 = Clock::now();
  const auto sh = param_test::spherical_shell(5, 8);
  const auto m = shell ? sh.mesh : param_test::box_tets(n, n, n, 0.1, 11);
  std::printf("mesh: %ld tets, %ld vertices (built in %.2f s)\n", (long)m.T.rows(), (long)m.V.rows(), since(t0));

  double t_asm = 1e9;
  Eigen::SparseMatrix<double> K;
  for (int r = 0; r < 3; ++r) {
    t0 = Clock::now();
    K = tet_stiffness(m.V, m.T);
    t_asm = std::min(t_asm, since(t0));
  }
  std::printf("assembly: %.3f s (best of 3), nnz %ld\n", t_asm, (long)K.nonZeros());

  // Three Dirichlet sets: x = 0, x = 1, and z = 1 (minus the edges already taken).
  std::vector<std::vector<int>> sets(3);
  if (shell) sets = {sh.inner, sh.outer, {}};
  for (Eigen::Index i = 0; i < m.V.rows() && !shell; ++i) {
    if (m.V(i, 0) == 0.0) sets[0].push_back(int(i));
    else if (m.V(i, 0) == 1.0) sets[1].push_back(int(i));
    else if (m.V(i, 2) == 1.0) sets[2].push_back(int(i));
  }
  const std::vector<double> values1 = {0.0, 1.0, 0.5}, values2 = {1.0, -1.0, 3.0};

  Eigen::VectorXd reference;
  struct Row { const char* name; HarmonicSolverOptions opt; };
  HarmonicSolverOptions chol, ic, jac;
  chol.solver = LinearSolverKind::Cholesky;
  ic.solver = jac.solver = LinearSolverKind::ConjugateGradient;
  jac.cg_jacobi_only = true;
  const bool skip_chol = argc > 2 && std::string(argv[2]) == "nochol";
  for (const Row& row : {Row{"cholesky", chol}, Row{"cg+ichol", ic}, Row{"cg+jacobi", jac}}) {
    if (skip_chol && row.opt.solver == LinearSolverKind::Cholesky) continue;
    t0 = Clock::now();
    HarmonicSolver solver(K, sets, row.opt);
    const double t_setup = since(t0);
    t0 = Clock::now();
    const Eigen::VectorXd u = solver.solve(values1);
    const double t_solve = since(t0);
    t0 = Clock::now();
    const Eigen::VectorXd u2 = solver.solve(values2);
    const double t_resolve = since(t0);
    if (reference.size() == 0) reference = u;
    const double diff = (u - reference).cwiseAbs().maxCoeff();
    std::printf(
        "%-10s%s setup (blocks + factor/preconditioner) %.3f s, solve %.3f s%s, re-solve with new values %.3f s; "
        "end to end incl. assembly %.3f s; reuse speed-up %.1fx; max |u - u_cholesky| %.1e\n",
        row.name, solver.uses_cholmod() ? " (CHOLMOD)" : "", t_setup, t_solve,
        solver.kind() == LinearSolverKind::ConjugateGradient
            ? (" (" + std::to_string(solver.last_cg_iterations()) + " it)").c_str() : "",
        t_resolve, t_asm + t_setup + t_solve, (t_setup + t_solve) / t_resolve, diff);
  }
  return 0;
}
