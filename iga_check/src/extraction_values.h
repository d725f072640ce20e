#pragma once
// Internal to the extraction-form solve: the rational basis of one element
// at tensor quadrature points (or any points of [0, 1]^3), its geometry and
// physical gradients, through C_e.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/extraction_model.h"

namespace igaprep::iga_check::detail {

struct ExtractionValues {
  Eigen::MatrixXd R;               // n x nq basis values
  std::array<Eigen::MatrixXd, 3> dR;  // n x nq derivatives in t (Bernstein coordinates)
  Eigen::MatrixXd x;               // 3 x nq points
  std::vector<Eigen::Matrix3d> J;  // dx/dt per point
};

// Bernstein values (order 0) or derivatives (order 1) of degree p at t.
Eigen::MatrixXd bernstein_table(int p, const Eigen::VectorXd& t, int order);

// The element's values at the tensor grid of points t[d] (first fastest).
ExtractionValues extraction_values(const spline::ExtractionModel& m, int element, const std::array<Eigen::VectorXd, 3>& t);

}  // namespace igaprep::iga_check::detail
