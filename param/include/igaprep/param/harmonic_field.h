#pragma once
// Harmonic fields (seed paper, section 2.1): K u = f on the free vertices,
// u fixed on Dirichlet vertex sets, natural (zero Neumann) conditions elsewhere.
// HarmonicSolver factors the free-free block once for a mesh and a Dirichlet
// vertex set and then solves cheaply for many value sets / right-hand sides.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace igaprep::param {

enum class LinearSolverKind {
  Default,            // = ConjugateGradient: measured fastest for one field on every mesh size tried
                      // (docs/harmonic-fields.md); pick Cholesky for many fields on one mesh
  Cholesky,           // CHOLMOD supernodal LL^T when built with CHOLMOD, else Eigen's SimplicialLDLT;
                      // factor once, each further solve is two triangular solves
  ConjugateGradient,  // CG with an incomplete-Cholesky preconditioner (natural ordering; Jacobi if it fails)
};

struct HarmonicSolverOptions {
  LinearSolverKind solver = LinearSolverKind::Default;
  double cg_tolerance = 1e-10;   // relative residual |r| / |b| for CG
  int cg_max_iterations = 20000;
  bool cg_jacobi_only = false;   // diagonal preconditioner instead of incomplete Cholesky
};

// Vertices that share one Dirichlet value.
struct DirichletSet {
  std::vector<int> vertices;
  double value = 0.0;
};

class HarmonicSolver {
 public:
  // Inputs: K (#V x #V) symmetric positive semi-definite with zero row sums
  // (tet_stiffness, tri_cotan_laplacian); dirichlet_sets, disjoint vertex sets.
  // Throws bad_input when a vertex is out of range or in two sets, or when a
  // connected component of free vertices touches no Dirichlet vertex (the
  // problem is singular there; the message names a vertex of that component).
  HarmonicSolver(const Eigen::SparseMatrix<double>& K, const std::vector<std::vector<int>>& dirichlet_sets,
                 const HarmonicSolverOptions& options = {});
  ~HarmonicSolver();
  HarmonicSolver(HarmonicSolver&&) noexcept;
  HarmonicSolver& operator=(HarmonicSolver&&) noexcept;

  // Output: u (#V) with u = set_values[s] on set s and K u = 0 on the free rows.
  Eigen::VectorXd solve(const std::vector<double>& set_values) const;
  // Inputs: values (#V), read only at Dirichlet vertices; rhs (#V load vector
  // f, read only at free vertices) or empty for zero.
  // Output: u (#V), u = values on Dirichlet vertices, (K u)_i = f_i on free ones.
  Eigen::VectorXd solve_with(const Eigen::VectorXd& values, const Eigen::VectorXd& rhs = Eigen::VectorXd()) const;

  int num_free() const;
  const std::vector<int>& free_vertices() const;  // ascending
  bool uses_cholmod() const;                      // the Cholesky path went through CHOLMOD
  LinearSolverKind kind() const;                  // Cholesky or ConjugateGradient (never Default)
  double setup_seconds() const;                   // block extraction + factorization (or preconditioner)
  int last_cg_iterations() const;                 // CG iterations of the last solve (0 for Cholesky)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One-shot helpers. K from stiffness_matrix; sets must be disjoint.
Eigen::VectorXd harmonic_field(const Eigen::SparseMatrix<double>& K, const std::vector<DirichletSet>& sets,
                               const HarmonicSolverOptions& options = {});
// Inputs: V (#V x 3), cells (#C x 4 tets or #C x 3 triangles), sets.
Eigen::VectorXd harmonic_field(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells,
                               const std::vector<DirichletSet>& sets, const HarmonicSolverOptions& options = {});

}  // namespace igaprep::param
