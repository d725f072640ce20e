#pragma once
// The isotropic linear-elastic material law.
#include <Eigen/Core>
#include <string>

namespace igaprep::iga_check {

struct LameParameters {
  double lambda = 0.0;
  double mu = 0.0;  // shear modulus
};

// Inputs: Young's modulus E > 0 and Poisson ratio -1 < nu < 0.5; `what` names
// the material in the error message.
// Outputs: the Lame parameters. Throws bad_input for a non-finite or
// non-positive E or a nu outside (-1, 0.5).
LameParameters lame_parameters(double young_modulus, double poisson_ratio, const std::string& what = "material");

// Cauchy stress (3x3, symmetric) of the displacement gradient grad_u
// (grad_u(i, j) = d u_i / d x_j): sigma = lambda tr(eps) I + 2 mu eps.
Eigen::Matrix3d isotropic_stress(const LameParameters& lame, const Eigen::Matrix3d& grad_u);

// Strain-energy density 1/2 sigma : eps of grad_u.
double strain_energy_density(const LameParameters& lame, const Eigen::Matrix3d& grad_u);

}  // namespace igaprep::iga_check
