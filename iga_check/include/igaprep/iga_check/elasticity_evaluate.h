#pragma once
// Post-processing of a solved model (solve_elasticity): displacement, its
// gradient and the stress at a parameter, and error norms against a known
// displacement field (manufactured solutions, closed forms).
#include <Eigen/Core>
#include <functional>

#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

struct ElasticityPoint {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();             // physical point
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
  Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();      // (i, j) = d u_i / d x_j
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();        // Cauchy stress of the patch's material
};

// Inputs: a model whose patches carry `displacement`; patch index; uvw the
// parameter (clamped into the patch domain).
// Throws bad_input when the patch has no displacement or the Jacobian is singular there.
ElasticityPoint evaluate_elasticity(const spline::MultiPatch& solved, int patch, const Eigen::Vector3d& uvw);

// von Mises equivalent stress of a Cauchy stress.
double von_mises_stress(const Eigen::Matrix3d& stress);

using DisplacementField = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;
using DisplacementGradientField = std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>;

struct ElasticityErrors {
  double l2_error = 0.0;      // || u - u_h ||_L2
  double l2_norm = 0.0;       // || u ||_L2
  double energy_error = 0.0;  // sqrt( int (eps - eps_h) : C : (eps - eps_h) )
  double energy_norm = 0.0;   // sqrt( int eps : C : eps )
};

// Gauss quadrature with degree + 1 + extra_quadrature points per direction on
// every element of every patch.
ElasticityErrors elasticity_errors(const spline::MultiPatch& solved, const DisplacementField& exact,
                                   const DisplacementGradientField& exact_gradient, int extra_quadrature = 2);

}  // namespace igaprep::iga_check
