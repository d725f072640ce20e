#pragma once
// Internal to the elasticity solver: the solve of K u = F.
#include <Eigen/Core>

#include "elasticity_amg.h"
#include "elasticity_pattern.h"
#include "igaprep/iga_check/elasticity_problem.h"

namespace igaprep::iga_check::detail {

// Inputs: K (symmetric, lower triangle), F, where its rows sit (for Amg),
// the options (solver, its size limits, CG tolerance and iterations).
// Output: u; sets report.solver, factor_entries, cg_iterations,
// cg_residual. Throws bad_input when K is not positive definite (a free
// mechanism) and internal_error when conjugate gradients do not converge.
Eigen::VectorXd solve_linear_system(const SparseMatrix& K, const Eigen::VectorXd& F, const NodalLayout& layout,
                                    const ElasticityOptions& options, ElasticityReport& report);

}  // namespace igaprep::iga_check::detail
