#pragma once
// Internal to the elasticity solver: the load vector over the free components.
#include <Eigen/Core>
#include <vector>

#include "elasticity_dofs.h"
#include "elasticity_tables.h"
#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check::detail {

// Inputs: the model, its tables and degrees of freedom, the problem.
// Output: F (dofs.unknowns): the body force (constant, function and
// rotation), then the tractions, the pressures (traction -pressure * outward
// normal) and the total forces (force / area), integrated against every
// basis function.
Eigen::VectorXd assemble_loads(const spline::MultiPatch& mp, const std::vector<PatchTables>& tables,
                               const ElasticityDofs& dofs, const ElasticityProblem& problem);

}  // namespace igaprep::iga_check::detail
