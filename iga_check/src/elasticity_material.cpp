#include "igaprep/iga_check/elasticity_material.h"

#include <cmath>
#include <sstream>

#include "igaprep/core/error.h"

namespace igaprep::iga_check {

LameParameters lame_parameters(double E, double nu, const std::string& what) {
  if (!std::isfinite(E) || E <= 0.0) {
    std::ostringstream s;
    s << what << ": Young's modulus must be positive, got " << E;
    throw bad_input(s.str());
  }
  if (!std::isfinite(nu) || nu <= -1.0 || nu >= 0.5) {
    std::ostringstream s;
    s << what << ": Poisson ratio must lie in (-1, 0.5), got " << nu;
    throw bad_input(s.str());
  }
  LameParameters l;
  l.lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  l.mu = E / (2.0 * (1.0 + nu));
  return l;
}

Eigen::Matrix3d isotropic_stress(const LameParameters& lame, const Eigen::Matrix3d& grad_u) {
  const Eigen::Matrix3d eps = 0.5 * (grad_u + grad_u.transpose());
  return lame.lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2.0 * lame.mu * eps;
}

double strain_energy_density(const LameParameters& lame, const Eigen::Matrix3d& grad_u) {
  const Eigen::Matrix3d eps = 0.5 * (grad_u + grad_u.transpose());
  return 0.5 * lame.lambda * eps.trace() * eps.trace() + lame.mu * eps.cwiseProduct(eps).sum();
}

}  // namespace igaprep::iga_check
