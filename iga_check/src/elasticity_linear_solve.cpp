#include "elasticity_linear_solve.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <sstream>
#include <string>

#ifdef IGAPREP_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include "igaprep/core/error.h"

namespace igaprep::iga_check::detail {

namespace {

// CHOLMOD stores a double per entry of its factor (and far fewer indices).
constexpr double kBytesPerFactorEntry = 8.0;

const char* const kSingular =
    "the stiffness matrix is not positive definite: the constraints leave a mechanism free "
    "(e.g. patches that are not connected through interfaces and not fixed) ";

#ifdef IGAPREP_HAVE_CHOLMOD
using Cholmod = Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>;

// The factorization after chol's symbolic analysis of K (its ordering).
Eigen::VectorXd factorize_and_solve(Cholmod& chol, const SparseMatrix& K, const Eigen::VectorXd& F,
                                    ElasticityReport& report) {
  report.solver = "cholmod";
  chol.factorize(K);
  if (chol.info() != Eigen::Success) throw bad_input(std::string(kSingular) + "(Cholesky factorization failed)");
  Eigen::VectorXd u = chol.solve(F);
  if (chol.info() != Eigen::Success || !u.allFinite()) throw bad_input(std::string(kSingular) + "(the solve failed)");
  return u;
}
#else
Eigen::VectorXd solve_ldlt(const SparseMatrix& K, const Eigen::VectorXd& F, ElasticityReport& report) {
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> chol;
  report.solver = "simplicial-ldlt";
  chol.compute(K);
  if (chol.info() != Eigen::Success) throw bad_input(std::string(kSingular) + "(Cholesky factorization failed)");
  if (chol.vectorD().minCoeff() <= 1e-14 * chol.vectorD().cwiseAbs().maxCoeff())
    throw bad_input(std::string(kSingular) + "(zero or negative pivot)");
  Eigen::VectorXd u = chol.solve(F);
  if (chol.info() != Eigen::Success || !u.allFinite()) throw bad_input(std::string(kSingular) + "(the solve failed)");
  return u;
}
#endif

Eigen::VectorXd solve_cg(const SparseMatrix& K, const Eigen::VectorXd& F, const ElasticityOptions& options,
                         ElasticityReport& report) {
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower, Eigen::IncompleteCholesky<double, Eigen::Lower>> cg;
  report.solver = "cg-ichol";
  cg.setTolerance(options.cg_tolerance);
  cg.setMaxIterations(options.cg_max_iterations > 0 ? options.cg_max_iterations : 10 * static_cast<int>(F.size()));
  cg.compute(K);
  if (cg.info() != Eigen::Success) throw bad_input(std::string(kSingular) + "(incomplete Cholesky failed)");
  Eigen::VectorXd u = cg.solve(F);
  report.cg_iterations = static_cast<int>(cg.iterations());
  report.cg_residual = cg.error();
  if (cg.info() != Eigen::Success || !u.allFinite()) {
    std::ostringstream s;
    s << "conjugate gradients did not converge in " << cg.iterations() << " iterations (residual " << cg.error()
      << "); the direct solver (LinearSolver::Cholesky) does not depend on convergence";
    throw internal_error(s.str());
  }
  return u;
}

}  // namespace

}  // namespace igaprep::iga_check::detail

namespace igaprep::iga_check {

LinearSolver linear_solver_named(const std::string& name) {
  if (name == "auto") return LinearSolver::Automatic;
  if (name == "cholesky") return LinearSolver::Cholesky;
  if (name == "cg") return LinearSolver::ConjugateGradient;
  if (name == "amg") return LinearSolver::Amg;
  throw bad_input("the linear solver must be 'auto', 'cholesky', 'cg' or 'amg', got '" + name + "'");
}

const char* linear_solver_name(LinearSolver solver) {
  switch (solver) {
    case LinearSolver::Automatic: return "auto";
    case LinearSolver::Cholesky: return "cholesky";
    case LinearSolver::ConjugateGradient: return "cg";
    case LinearSolver::Amg: return "amg";
  }
  return "auto";
}

}  // namespace igaprep::iga_check

namespace igaprep::iga_check::detail {

Eigen::VectorXd solve_linear_system(const SparseMatrix& K, const Eigen::VectorXd& F, const NodalLayout& layout,
                                    const ElasticityOptions& options, ElasticityReport& report) {
  if (F.size() == 0) return Eigen::VectorXd::Zero(0);
  LinearSolver solver = options.solver;
  if (solver == LinearSolver::Automatic && F.size() > options.direct_max_unknowns) solver = LinearSolver::Amg;
  if (solver == LinearSolver::Automatic || solver == LinearSolver::Cholesky) {
#ifdef IGAPREP_HAVE_CHOLMOD
    // The symbolic analysis predicts the factor's size before any of it is
    // stored; the factorization reuses it.
    Cholmod chol;
    chol.analyzePattern(K);
    if (chol.info() != Eigen::Success) throw bad_input(std::string(kSingular) + "(the Cholesky analysis failed)");
    report.factor_entries = chol.cholmod().lnz;
    if (solver == LinearSolver::Cholesky || kBytesPerFactorEntry * report.factor_entries <= options.direct_max_factor_bytes)
      return factorize_and_solve(chol, K, F, report);
    solver = LinearSolver::Amg;
#else
    return solve_ldlt(K, F, report);
#endif
  }
  if (solver == LinearSolver::Amg)
    return solve_amg(K, F, layout, options.cg_tolerance, options.cg_max_iterations, report);
  return solve_cg(K, F, options, report);
}

}  // namespace igaprep::iga_check::detail
