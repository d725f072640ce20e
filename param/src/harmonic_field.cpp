#include "igaprep/param/harmonic_field.h"

#include <chrono>
#include <cmath>
#include <string>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#ifdef IGAPREP_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include "igaprep/core/error.h"
#include "igaprep/param/stiffness_matrix.h"

namespace igaprep::param {

using SpMat = Eigen::SparseMatrix<double>;

struct HarmonicSolver::Impl {
  Eigen::Index n = 0;
  std::vector<int> free;         // free vertices, ascending
  std::vector<int> dirichlet;    // Dirichlet vertices, ascending
  std::vector<int> set_of;       // #V: set index of a Dirichlet vertex, -1 if free
  std::vector<int> local;        // #V: index among free (or among dirichlet) vertices
  SpMat Kff, Kfd;
  LinearSolverKind kind = LinearSolverKind::Cholesky;
  bool cholmod = false;
  double setup_seconds = 0.0;
  mutable int cg_iterations = 0;
  HarmonicSolverOptions options;
#ifdef IGAPREP_HAVE_CHOLMOD
  std::unique_ptr<Eigen::CholmodSupernodalLLT<SpMat, Eigen::Lower>> chol;
#endif
  std::unique_ptr<Eigen::SimplicialLDLT<SpMat, Eigen::Lower>> ldlt;
  std::unique_ptr<Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::NaturalOrdering<int>>>>
      cg_ic;
  std::unique_ptr<Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper>> cg_jacobi;

  Eigen::VectorXd solve_free(const Eigen::VectorXd& b) const;
};

namespace {

// Splits K into the free-free and free-Dirichlet blocks in one pass over its columns.
void split_blocks(const SpMat& K, const std::vector<int>& set_of, const std::vector<int>& local, Eigen::Index nf,
                  Eigen::Index nd, SpMat& Kff, SpMat& Kfd) {
  std::vector<int> ff_outer(nf + 1, 0), fd_outer(nd + 1, 0), ff_inner, fd_inner;
  std::vector<double> ff_val, fd_val;
  ff_inner.reserve(K.nonZeros());
  ff_val.reserve(K.nonZeros());
  for (Eigen::Index j = 0; j < K.outerSize(); ++j) {
    const bool jfree = set_of[j] < 0;
    for (SpMat::InnerIterator it(K, j); it; ++it) {
      const Eigen::Index i = it.index();
      if (set_of[i] >= 0) continue;  // Dirichlet rows are not unknowns
      if (jfree) {
        ff_inner.push_back(local[i]);
        ff_val.push_back(it.value());
      } else {
        fd_inner.push_back(local[i]);
        fd_val.push_back(it.value());
      }
    }
    if (jfree)
      ff_outer[local[j] + 1] = static_cast<int>(ff_inner.size());
    else
      fd_outer[local[j] + 1] = static_cast<int>(fd_inner.size());
  }
  auto build = [](SpMat& A, Eigen::Index rows, Eigen::Index cols, const std::vector<int>& outer,
                  const std::vector<int>& inner, const std::vector<double>& val) {
    A.resize(rows, cols);
    A.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
    std::copy(outer.begin(), outer.end(), A.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), A.innerIndexPtr());
    std::copy(val.begin(), val.end(), A.valuePtr());
  };
  build(Kff, nf, nf, ff_outer, ff_inner, ff_val);
  build(Kfd, nf, nd, fd_outer, fd_inner, fd_val);
}

// Each connected component of free vertices (coupled by nonzero entries) must
// couple to some Dirichlet vertex, or K_ff is singular on it.
void check_components(const SpMat& Kff, const SpMat& Kfd, const std::vector<int>& free) {
  const Eigen::Index nf = Kff.rows();
  std::vector<char> touches(nf, 0);
  for (Eigen::Index j = 0; j < Kfd.outerSize(); ++j)
    for (SpMat::InnerIterator it(Kfd, j); it; ++it)
      if (it.value() != 0.0) touches[it.index()] = 1;
  std::vector<int> comp(nf, -1), stack;
  int ncomp = 0;
  for (Eigen::Index s = 0; s < nf; ++s) {
    if (comp[s] >= 0) continue;
    bool ok = false;
    Eigen::Index size = 0;
    comp[s] = ncomp;
    stack.assign(1, static_cast<int>(s));
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      ++size;
      ok = ok || touches[v];
      for (SpMat::InnerIterator it(Kff, v); it; ++it)
        if (it.value() != 0.0 && comp[it.index()] < 0) {
          comp[it.index()] = ncomp;
          stack.push_back(static_cast<int>(it.index()));
        }
    }
    if (!ok)
      throw bad_input("harmonic field: a connected component of " + std::to_string(size) +
                      " free vertices (containing vertex " + std::to_string(free[s]) +
                      ") touches no Dirichlet vertex, so the problem is singular there; give that part of the "
                      "mesh a Dirichlet value or remove it");
    ++ncomp;
  }
}

}  // namespace

HarmonicSolver::HarmonicSolver(const SpMat& K, const std::vector<std::vector<int>>& sets,
                               const HarmonicSolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  const auto t0 = std::chrono::steady_clock::now();
  Impl& m = *impl_;
  m.options = options;
  if (K.rows() != K.cols()) throw bad_input("harmonic field: the stiffness matrix is not square");
  m.n = K.rows();
  m.set_of.assign(m.n, -1);
  for (size_t s = 0; s < sets.size(); ++s)
    for (int v : sets[s]) {
      if (v < 0 || v >= m.n)
        throw bad_input("harmonic field: Dirichlet set " + std::to_string(s) + " names vertex " + std::to_string(v) +
                        ", but there are " + std::to_string(m.n) + " vertices");
      if (m.set_of[v] >= 0 && m.set_of[v] != static_cast<int>(s))
        throw bad_input("harmonic field: vertex " + std::to_string(v) + " is in Dirichlet sets " +
                        std::to_string(m.set_of[v]) + " and " + std::to_string(s) + "; the sets must be disjoint");
      m.set_of[v] = static_cast<int>(s);
    }
  m.local.assign(m.n, -1);
  for (Eigen::Index v = 0; v < m.n; ++v) {
    if (m.set_of[v] < 0) {
      m.local[v] = static_cast<int>(m.free.size());
      m.free.push_back(static_cast<int>(v));
    } else {
      m.local[v] = static_cast<int>(m.dirichlet.size());
      m.dirichlet.push_back(static_cast<int>(v));
    }
  }
  const Eigen::Index nf = static_cast<Eigen::Index>(m.free.size());
  const Eigen::Index nd = static_cast<Eigen::Index>(m.dirichlet.size());
  split_blocks(K, m.set_of, m.local, nf, nd, m.Kff, m.Kfd);
  check_components(m.Kff, m.Kfd, m.free);

  m.kind = options.solver == LinearSolverKind::Cholesky ? LinearSolverKind::Cholesky
                                                         : LinearSolverKind::ConjugateGradient;
  if (nf > 0) {
    if (m.kind == LinearSolverKind::Cholesky) {
#ifdef IGAPREP_HAVE_CHOLMOD
      m.chol = std::make_unique<Eigen::CholmodSupernodalLLT<SpMat, Eigen::Lower>>();
      m.chol->compute(m.Kff);
      if (m.chol->info() != Eigen::Success)
        throw internal_error("harmonic field: CHOLMOD could not factor the " + std::to_string(nf) +
                             " x " + std::to_string(nf) + " system (not positive definite?)");
      m.cholmod = true;
#else
      m.ldlt = std::make_unique<Eigen::SimplicialLDLT<SpMat, Eigen::Lower>>();
      m.ldlt->compute(m.Kff);
      if (m.ldlt->info() != Eigen::Success)
        throw internal_error("harmonic field: sparse LDL^T could not factor the " + std::to_string(nf) + " x " +
                             std::to_string(nf) + " system");
#endif
    } else {
      if (!options.cg_jacobi_only) {
        m.cg_ic = std::make_unique<
            Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::NaturalOrdering<int>>>>();
        m.cg_ic->setTolerance(options.cg_tolerance);
        m.cg_ic->setMaxIterations(options.cg_max_iterations);
        m.cg_ic->compute(m.Kff);
        if (m.cg_ic->info() != Eigen::Success) m.cg_ic.reset();  // fall back to Jacobi below
      }
      if (!m.cg_ic) {
        m.cg_jacobi = std::make_unique<Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper>>();
        m.cg_jacobi->setTolerance(options.cg_tolerance);
        m.cg_jacobi->setMaxIterations(options.cg_max_iterations);
        m.cg_jacobi->compute(m.Kff);
      }
    }
  }
  m.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

HarmonicSolver::~HarmonicSolver() = default;
HarmonicSolver::HarmonicSolver(HarmonicSolver&&) noexcept = default;
HarmonicSolver& HarmonicSolver::operator=(HarmonicSolver&&) noexcept = default;

Eigen::VectorXd HarmonicSolver::Impl::solve_free(const Eigen::VectorXd& b) const {
  if (b.size() == 0) return b;
#ifdef IGAPREP_HAVE_CHOLMOD
  if (chol) return chol->solve(b);
#endif
  if (ldlt) return ldlt->solve(b);
  Eigen::VectorXd x;
  bool ok;
  if (cg_ic) {
    x = cg_ic->solve(b);
    cg_iterations = static_cast<int>(cg_ic->iterations());
    ok = cg_ic->info() == Eigen::Success;
  } else {
    x = cg_jacobi->solve(b);
    cg_iterations = static_cast<int>(cg_jacobi->iterations());
    ok = cg_jacobi->info() == Eigen::Success;
  }
  if (!ok)
    throw internal_error("harmonic field: conjugate gradients did not reach the tolerance " +
                         std::to_string(options.cg_tolerance) + " in " + std::to_string(cg_iterations) +
                         " iterations");
  return x;
}

Eigen::VectorXd HarmonicSolver::solve_with(const Eigen::VectorXd& values, const Eigen::VectorXd& rhs) const {
  const Impl& m = *impl_;
  if (values.size() != m.n)
    throw bad_input("harmonic field: " + std::to_string(values.size()) + " values for " + std::to_string(m.n) +
                    " vertices");
  if (rhs.size() != 0 && rhs.size() != m.n)
    throw bad_input("harmonic field: right-hand side has " + std::to_string(rhs.size()) + " entries for " +
                    std::to_string(m.n) + " vertices");
  Eigen::VectorXd ud(m.dirichlet.size());
  for (size_t k = 0; k < m.dirichlet.size(); ++k) {
    ud(k) = values(m.dirichlet[k]);
    if (!std::isfinite(ud(k)))
      throw bad_input("harmonic field: Dirichlet value at vertex " + std::to_string(m.dirichlet[k]) +
                      " is not finite");
  }
  Eigen::VectorXd b = -(m.Kfd * ud);
  if (rhs.size() != 0)
    for (size_t k = 0; k < m.free.size(); ++k) b(k) += rhs(m.free[k]);
  const Eigen::VectorXd x = m.solve_free(b);
  Eigen::VectorXd u(m.n);
  for (size_t k = 0; k < m.free.size(); ++k) u(m.free[k]) = x(k);
  for (size_t k = 0; k < m.dirichlet.size(); ++k) u(m.dirichlet[k]) = ud(k);
  return u;
}

Eigen::VectorXd HarmonicSolver::solve(const std::vector<double>& set_values) const {
  const Impl& m = *impl_;
  Eigen::VectorXd values = Eigen::VectorXd::Zero(m.n);
  for (int v : m.dirichlet) {
    const int s = m.set_of[v];
    if (s >= static_cast<int>(set_values.size()))
      throw bad_input("harmonic field: no value given for Dirichlet set " + std::to_string(s) + " (" +
                      std::to_string(set_values.size()) + " values given)");
    values(v) = set_values[s];
  }
  return solve_with(values);
}

int HarmonicSolver::num_free() const { return static_cast<int>(impl_->free.size()); }
const std::vector<int>& HarmonicSolver::free_vertices() const { return impl_->free; }
bool HarmonicSolver::uses_cholmod() const { return impl_->cholmod; }
LinearSolverKind HarmonicSolver::kind() const { return impl_->kind; }
double HarmonicSolver::setup_seconds() const { return impl_->setup_seconds; }
int HarmonicSolver::last_cg_iterations() const { return impl_->cg_iterations; }

Eigen::VectorXd harmonic_field(const SpMat& K, const std::vector<DirichletSet>& sets,
                               const HarmonicSolverOptions& options) {
  std::vector<std::vector<int>> vs;
  std::vector<double> values;
  for (const DirichletSet& s : sets) {
    vs.push_back(s.vertices);
    values.push_back(s.value);
  }
  return HarmonicSolver(K, vs, options).solve(values);
}

Eigen::VectorXd harmonic_field(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells,
                               const std::vector<DirichletSet>& sets, const HarmonicSolverOptions& options) {
  return harmonic_field(stiffness_matrix(V, cells), sets, options);
}

}  // namespace igaprep::param
