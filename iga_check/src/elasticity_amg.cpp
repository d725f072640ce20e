#include "elasticity_amg.h"

#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <_hypre_parcsr_mv.h>
#include <mpi.h>

#include <array>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <sstream>
#include <string>

#include "igaprep/core/error.h"

// In libHYPRE but not in its public headers (MFEM declares them too).
extern "C" {
HYPRE_Int HYPRE_BoomerAMGSetSmoothInterpVectors(HYPRE_Solver solver, HYPRE_Int smooth_interp_vectors);
HYPRE_Int HYPRE_BoomerAMGSetInterpRefine(HYPRE_Solver solver, HYPRE_Int num_refine);
}

namespace igaprep::iga_check::detail {

namespace {

// Debian's hypre is built on MPI: the solve runs in this one process
// (MPI_COMM_SELF), MPI started on first use and finished at exit.
void start_hypre_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    int started = 0;
    MPI_Initialized(&started);
    if (!started) {
      MPI_Init(nullptr, nullptr);
      std::atexit([] {
        int finished = 0;
        MPI_Finalized(&finished);
        if (!finished) MPI_Finalize();
      });
    }
    HYPRE_Init();
  });
}

void check_hypre(HYPRE_Int code, const char* call) {
  if (code == 0) return;
  char text[256] = {0};
  HYPRE_DescribeError(code, text);
  HYPRE_ClearAllErrors();
  throw internal_error(std::string("hypre: ") + call + " failed: " + text);
}

// The preconditioner's matrix in rows of the nodal numbering (3 g + i), both
// triangles, constrained components as identity rows, written straight into
// hypre's CSR arrays (its IJ interface took a copy and 5 s at 74,000
// unknowns). hypre wants each row's diagonal entry first.
class NodalMatrix {
 public:
  NodalMatrix(const SparseMatrix& K, const std::vector<int>& row_of);
  ~NodalMatrix() { hypre_ParCSRMatrixDestroy(m_); }
  NodalMatrix(const NodalMatrix&) = delete;
  NodalMatrix& operator=(const NodalMatrix&) = delete;
  HYPRE_ParCSRMatrix parcsr() const { return reinterpret_cast<HYPRE_ParCSRMatrix>(m_); }

 private:
  hypre_ParCSRMatrix* m_ = nullptr;
};

NodalMatrix::NodalMatrix(const SparseMatrix& K, const std::vector<int>& row_of) {
  const std::size_t n = row_of.size();
  std::vector<int> nodal_of(static_cast<std::size_t>(K.rows()));
  for (std::size_t r = 0; r < n; ++r)
    if (row_of[r] >= 0) nodal_of[static_cast<std::size_t>(row_of[r])] = static_cast<int>(r);
  std::vector<long long> start(n + 1, 0);  // row sizes, then their offsets
  for (std::size_t r = 0; r < n; ++r)
    if (row_of[r] < 0) start[r + 1] = 1;
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
      ++start[static_cast<std::size_t>(nodal_of[static_cast<std::size_t>(it.row())]) + 1];
      if (it.row() != j) ++start[static_cast<std::size_t>(nodal_of[static_cast<std::size_t>(j)]) + 1];
    }
  for (std::size_t r = 0; r < n; ++r) start[r + 1] += start[r];
  if (start[n] > std::numeric_limits<HYPRE_Int>::max())
    throw bad_input("the stiffness matrix has " + std::to_string(start[n]) +
                    " non-zeros, more than hypre's 32-bit indices hold; use the direct solver");
  HYPRE_BigInt partition[2] = {0, static_cast<HYPRE_BigInt>(n)};
  m_ = hypre_ParCSRMatrixCreate(MPI_COMM_SELF, partition[1], partition[1], partition, partition, 0,
                                static_cast<HYPRE_Int>(start[n]), 0);
  hypre_ParCSRMatrixInitialize(m_);
  hypre_CSRMatrix* diag = hypre_ParCSRMatrixDiag(m_);
  HYPRE_Int* I = hypre_CSRMatrixI(diag);
  HYPRE_Int* J = hypre_CSRMatrixJ(diag);
  double* value = hypre_CSRMatrixData(diag);
  std::vector<HYPRE_Int> next(n);
  for (std::size_t r = 0; r <= n; ++r) I[r] = static_cast<HYPRE_Int>(start[r]);
  for (std::size_t r = 0; r < n; ++r) {
    next[r] = I[r] + 1;  // after the diagonal
    if (row_of[r] < 0) J[I[r]] = static_cast<HYPRE_Int>(r), value[I[r]] = 1.0;
  }
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
      const int a = nodal_of[static_cast<std::size_t>(it.row())], b = nodal_of[static_cast<std::size_t>(j)];
      if (a == b) {
        J[I[a]] = a, value[I[a]] = it.value();
        continue;
      }
      const HYPRE_Int at_a = next[static_cast<std::size_t>(a)]++, at_b = next[static_cast<std::size_t>(b)]++;
      J[at_a] = b, value[at_a] = it.value();
      J[at_b] = a, value[at_b] = it.value();
    }
  hypre_ParCSRMatrixSetNumNonzeros(m_);
}

// hypre's objects, destroyed with their owner.
struct IJVector {
  HYPRE_IJVector ij = nullptr;
  ~IJVector() {
    if (ij) HYPRE_IJVectorDestroy(ij);
  }
  HYPRE_ParVector par() const {
    void* p = nullptr;
    check_hypre(HYPRE_IJVectorGetObject(ij, &p), "HYPRE_IJVectorGetObject");
    return static_cast<HYPRE_ParVector>(p);
  }
};

struct Solvers {
  HYPRE_Solver amg = nullptr, pcg = nullptr;
  ~Solvers() {
    if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
    if (amg) HYPRE_BoomerAMGDestroy(amg);
  }
};

void make_vector(IJVector& v, const Eigen::VectorXd& values) {
  const HYPRE_BigInt last = static_cast<HYPRE_BigInt>(values.size()) - 1;
  check_hypre(HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, last, &v.ij), "HYPRE_IJVectorCreate");
  check_hypre(HYPRE_IJVectorSetObjectType(v.ij, HYPRE_PARCSR), "HYPRE_IJVectorSetObjectType");
  check_hypre(HYPRE_IJVectorInitialize(v.ij), "HYPRE_IJVectorInitialize");
  std::vector<HYPRE_BigInt> index(static_cast<std::size_t>(values.size()));
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<HYPRE_BigInt>(i);
  check_hypre(HYPRE_IJVectorSetValues(v.ij, static_cast<HYPRE_Int>(values.size()), index.data(), values.data()),
              "HYPRE_IJVectorSetValues");
  check_hypre(HYPRE_IJVectorAssemble(v.ij), "HYPRE_IJVectorAssemble");
}

// The three rotations about the points' centroid (translations are the
// nodal coarsening's own), in the nodal numbering.
std::array<Eigen::VectorXd, 3> rotations(const Eigen::MatrixXd& points) {
  const Eigen::RowVector3d centre = points.colwise().mean();
  std::array<Eigen::VectorXd, 3> r;
  for (auto& v : r) v = Eigen::VectorXd::Zero(3 * points.rows());
  for (Eigen::Index g = 0; g < points.rows(); ++g) {
    const Eigen::RowVector3d d = points.row(g) - centre;
    r[0].segment<3>(3 * g) << -d.y(), d.x(), 0.0;  // about z
    r[1].segment<3>(3 * g) << 0.0, -d.z(), d.y();  // about x
    r[2].segment<3>(3 * g) << d.z(), 0.0, -d.x();  // about y
  }
  return r;
}

// One V-cycle per CG step with the elasticity options of MFEM's set-up
// (nodal coarsening, the GM-2 interpolation of the rotations: Baker, Kolev,
// Yang 2010) on HMIS coarsening and extended+i interpolation. The strength
// threshold 0.25 and one level of aggressive coarsening were measured on the
// degree-3 cylinder (docs/performance.md): 43 iterations instead of 58, the
// set-up 2.8 s instead of 6.4 s at 74,000 unknowns.
void set_up_boomeramg(HYPRE_Solver amg, std::array<IJVector, 3>& modes) {
  HYPRE_BoomerAMGSetMaxIter(amg, 1);
  HYPRE_BoomerAMGSetTol(amg, 0.0);
  HYPRE_BoomerAMGSetPrintLevel(amg, 0);
  HYPRE_BoomerAMGSetCoarsenType(amg, 10);
  HYPRE_BoomerAMGSetInterpType(amg, 6);
  HYPRE_BoomerAMGSetPMaxElmts(amg, 4);
  HYPRE_BoomerAMGSetRelaxType(amg, 8);
  HYPRE_BoomerAMGSetNumSweeps(amg, 1);
  HYPRE_BoomerAMGSetNumFunctions(amg, 3);
  HYPRE_BoomerAMGSetAggNumLevels(amg, 1);
  HYPRE_BoomerAMGSetStrongThreshold(amg, 0.25);
  HYPRE_BoomerAMGSetNodal(amg, 4);
  HYPRE_BoomerAMGSetNodalDiag(amg, 1);
  HYPRE_BoomerAMGSetCycleRelaxType(amg, 8, 3);
  HYPRE_BoomerAMGSetInterpVecVariant(amg, 2);
  HYPRE_BoomerAMGSetInterpVecQMax(amg, 4);
  HYPRE_BoomerAMGSetSmoothInterpVectors(amg, 1);
  HYPRE_BoomerAMGSetInterpRefine(amg, 1);
  std::array<HYPRE_ParVector, 3> vectors{};
  for (int k = 0; k < 3; ++k) vectors[static_cast<std::size_t>(k)] = modes[static_cast<std::size_t>(k)].par();
  HYPRE_BoomerAMGSetInterpVectors(amg, 3, vectors.data());
}

double relative_residual(const SparseMatrix& K, const Eigen::VectorXd& F, const Eigen::VectorXd& u) {
  const Eigen::VectorXd r = F - K.selfadjointView<Eigen::Lower>() * u;
  const double f = F.norm();
  return f > 0 ? r.norm() / f : r.norm();
}

// hypre's PCG on A x = rhs (x starts at zero) with BoomerAMG on A as its
// preconditioner; the iterations it made.
int run_pcg(const NodalMatrix& A, const IJVector& rhs, const IJVector& x, std::array<IJVector, 3>& modes, double tolerance,
            int max_iterations) {
  Solvers s;
  check_hypre(HYPRE_BoomerAMGCreate(&s.amg), "HYPRE_BoomerAMGCreate");
  set_up_boomeramg(s.amg, modes);
  check_hypre(HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &s.pcg), "HYPRE_ParCSRPCGCreate");
  HYPRE_PCGSetTol(s.pcg, tolerance);
  HYPRE_PCGSetTwoNorm(s.pcg, 1);
  HYPRE_PCGSetMaxIter(s.pcg, max_iterations > 0 ? max_iterations : 1000);
  HYPRE_PCGSetPrecond(s.pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                      reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), s.amg);
  // As in MFEM: the set-up may flag a singular coarse level (hypre's l1 row
  // norms), which the V-cycle handles; the caller's residual is the judge.
  HYPRE_ParCSRPCGSetup(s.pcg, A.parcsr(), rhs.par(), x.par());
  HYPRE_ClearAllErrors();
  HYPRE_ParCSRPCGSolve(s.pcg, A.parcsr(), rhs.par(), x.par());
  HYPRE_ClearAllErrors();
  HYPRE_Int iterations = 0;
  HYPRE_PCGGetNumIterations(s.pcg, &iterations);
  return static_cast<int>(iterations);
}

// x's entries at the rows of K (the free components), in K's order.
Eigen::VectorXd free_values(const IJVector& x, const NodalLayout& layout, Eigen::Index rows) {
  const int n = static_cast<int>(layout.row_of.size());
  Eigen::VectorXd full(n);
  std::vector<HYPRE_BigInt> index(static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r) index[static_cast<std::size_t>(r)] = r;
  check_hypre(HYPRE_IJVectorGetValues(x.ij, n, index.data(), full.data()), "HYPRE_IJVectorGetValues");
  Eigen::VectorXd u(rows);
  for (int r = 0; r < n; ++r)
    if (layout.row_of[static_cast<std::size_t>(r)] >= 0) u[layout.row_of[static_cast<std::size_t>(r)]] = full[r];
  return u;
}

}  // namespace

Eigen::VectorXd solve_amg(const SparseMatrix& K, const Eigen::VectorXd& F, const NodalLayout& layout, double tolerance,
                          int max_iterations, ElasticityReport& report) {
  start_hypre_once();
  // hypre keeps global state (its error flag, its memory tracking): one solve at a time.
  static std::mutex hypre_mutex;
  const std::lock_guard<std::mutex> lock(hypre_mutex);
  report.solver = "boomeramg-pcg";
  Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(layout.row_of.size()));
  for (std::size_t r = 0; r < layout.row_of.size(); ++r)
    if (layout.row_of[r] >= 0) b[static_cast<Eigen::Index>(r)] = F[layout.row_of[r]];
  const NodalMatrix A(K, layout.row_of);
  IJVector rhs, x;
  make_vector(rhs, b);
  make_vector(x, Eigen::VectorXd::Zero(b.size()));
  std::array<IJVector, 3> modes;
  const std::array<Eigen::VectorXd, 3> rotation = rotations(layout.points);
  for (std::size_t k = 0; k < 3; ++k) make_vector(modes[k], rotation[k]);
  report.cg_iterations = run_pcg(A, rhs, x, modes, tolerance, max_iterations);
  const Eigen::VectorXd u = free_values(x, layout, F.size());
  report.cg_residual = relative_residual(K, F, u);
  // Round-off in hypre's recurrence leaves the true residual a little above
  // the one it tracks: a tenth of a digit is allowed, more is a failure.
  if (!u.allFinite() || !(report.cg_residual <= 1.25 * tolerance)) {
    std::ostringstream msg;
    msg << "conjugate gradients with BoomerAMG did not converge in " << report.cg_iterations
        << " iterations (relative residual " << report.cg_residual << ", asked " << tolerance
        << "); the direct solver (LinearSolver::Cholesky) does not depend on convergence";
    throw internal_error(msg.str());
  }
  return u;
}

}  // namespace igaprep::iga_check::detail
