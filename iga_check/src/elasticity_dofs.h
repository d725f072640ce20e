#pragma once
// Internal to the elasticity solver: the degrees of freedom. Control points
// are numbered once across interfaces (C0 coupling); each of their three
// displacement components is either constrained (fixed to zero or
// prescribed) or an unknown with its own equation.
#include <Eigen/Core>
#include <vector>

#include "elasticity_amg.h"
#include "elasticity_prescribed.h"
#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check::detail {

struct ElasticityDofs {
  spline::GlobalNumbering numbering;       // control points, shared ones counted once
  std::vector<unsigned char> constrained;  // 3 g + i: component i of control point g is set
  Eigen::VectorXd values;                  // 3 g + i: its value when constrained (zero or prescribed), else 0
  std::vector<int> equation;               // 3 g + i: row of the linear system, -1 when constrained
  int unknowns = 0;
  long long prescribed = 0;                // constrained components set by a PrescribedSide
};

// Inputs: the model and its numbering; the prescribed values
// (project_prescribed); the fixed sides, whose components are zero even where
// a prescribed side also sets them.
// Throws bad_input when the constraints leave a rigid-body motion free
// (check_rigid_modes).
ElasticityDofs constrain_dofs(const spline::MultiPatch& mp, spline::GlobalNumbering numbering,
                              const PrescribedValues& prescribed, const std::vector<FixedSide>& fixed);

// The unknowns by control point for the AMG preconditioner: dofs.equation
// and each distinct control point's position.
NodalLayout nodal_layout(const spline::MultiPatch& mp, const ElasticityDofs& dofs);

}  // namespace igaprep::iga_check::detail
