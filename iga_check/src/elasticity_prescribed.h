#pragma once
// Internal to the elasticity solver: the values prescribed displacements give
// to the control points of their sides.
#include <Eigen/Core>
#include <vector>

#include "elasticity_tables.h"
#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check::detail {

struct PrescribedValues {
  std::vector<unsigned char> is_prescribed;  // per global control point, 0/1
  Eigen::MatrixXd values;                    // count x 3; rows of other points zero
};

// L2 projection of the prescribed displacements onto the spline space traced
// on the prescribed sides, all sides together: one boundary mass matrix over
// the global numbering, so a coefficient shared by sides or patches gets one
// value. A function whose trace has no area takes the value at its control
// point. Throws bad_input for a non-finite prescribed value or a singular
// boundary mass matrix.
PrescribedValues project_prescribed(const spline::MultiPatch& mp, const spline::GlobalNumbering& num,
                                    const std::vector<PatchTables>& tables,
                                    const std::vector<PrescribedSide>& prescribed);

}  // namespace igaprep::iga_check::detail
