#pragma once
// Internal to the elasticity solver: assembly of the stiffness matrix over
// the free components, and of the pull of the prescribed values on them.
#include <Eigen/Core>
#include <vector>

#include "elasticity_dofs.h"
#include "elasticity_pattern.h"
#include "elasticity_tables.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check::detail {

struct StiffnessSystem {
  SparseMatrix matrix;              // K_ff, lower triangle
  Eigen::VectorXd lifting;          // K_fd u_d: enters the right-hand side as -K_fd u_d
  double constrained_energy = 0.0;  // u_d^T K_dd u_d; with lifting it completes the strain energy
};

// Inputs: the model, its tables, its degrees of freedom, the Lame parameters
// per material. Sets report.elements, report.quadrature_points and
// report.nonzeros. Throws bad_input when the Jacobian vanishes or changes sign
// in a patch.
StiffnessSystem assemble_stiffness(const spline::MultiPatch& mp, const std::vector<PatchTables>& tables,
                                   const ElasticityDofs& dofs, const std::vector<LameParameters>& lame,
                                   ElasticityReport& report, const ProgressCallback& progress);

}  // namespace igaprep::iga_check::detail
