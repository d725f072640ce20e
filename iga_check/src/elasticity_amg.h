#pragma once
// Internal to the elasticity solvers: conjugate gradients preconditioned by
// one V-cycle of hypre's BoomerAMG, set up for elasticity as MFEM's
// HypreBoomerAMG::SetElasticityOptions is: the three components of a control
// point coarsened together (nodal coarsening) and the rigid rotations as
// interpolation vectors (docs/elasticity-solver.md, "Large problems").
#include <Eigen/Core>
#include <vector>

#include "elasticity_pattern.h"
#include "igaprep/iga_check/elasticity_problem.h"

namespace igaprep::iga_check::detail {

// Where the unknowns sit: row_of[3 g + i] is the row of K for component i of
// control point g, or -1 when that component is constrained (it becomes an
// identity row of the preconditioner's matrix, which needs all three
// components of every point); points are the control points (g x 3).
struct NodalLayout {
  std::vector<int> row_of;
  Eigen::MatrixXd points;
};

// Inputs: K (symmetric, lower triangle), F, the layout, the relative residual
// to reach and the iteration limit (0: 1,000). Output: u; sets
// report.solver ("boomeramg-pcg"), cg_iterations and cg_residual (the true
// relative residual |F - K u| / |F|, computed from K). Throws
// internal_error when hypre fails or the residual is not reached.
Eigen::VectorXd solve_amg(const SparseMatrix& K, const Eigen::VectorXd& F, const NodalLayout& layout, double tolerance,
                          int max_iterations, ElasticityReport& report);

}  // namespace igaprep::iga_check::detail
