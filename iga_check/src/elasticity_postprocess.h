#pragma once
// Internal to the elasticity solver: from the solution of the linear system
// to the model's displacement coefficients and the figures of the report.
#include <Eigen/Core>

#include "elasticity_dofs.h"
#include "elasticity_stiffness.h"
#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check::detail {

// Inputs: u (dofs.unknowns), the degrees of freedom and the assembled system.
// Sets every patch's displacement (constrained components take their values),
// the model's has_solution, strain_energy (1/2 u^T K u over all coefficients)
// and max_displacement (largest |u| over the coefficients), and the same
// figures in the report.
void store_solution(const Eigen::VectorXd& u, const ElasticityDofs& dofs, const StiffnessSystem& system,
                    spline::MultiPatch& mp, ElasticityReport& report);

}  // namespace igaprep::iga_check::detail
