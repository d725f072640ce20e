#include "igaprep/iga_check/elasticity_evaluate.h"

#include <cmath>

#include "elasticity_basis.h"
#include "igaprep/core/error.h"
#include "igaprep/iga_check/elasticity_material.h"

namespace igaprep::iga_check {

namespace {

const spline::Patch& solved_patch(const spline::MultiPatch& mp, int patch) {
  if (patch < 0 || patch >= static_cast<int>(mp.patches.size()))
    throw bad_input("patch " + std::to_string(patch) + " does not exist");
  const spline::Patch& p = mp.patches[patch];
  if (p.displacement.rows() != p.control_points.rows() || p.displacement.cols() != 3)
    throw bad_input("patch " + std::to_string(patch) + " carries no displacement (not a solve result)");
  return p;
}

LameParameters patch_lame(const spline::MultiPatch& mp, int patch) {
  const int m = mp.patches[patch].material;
  if (m < 0 || m >= static_cast<int>(mp.materials.size()))
    throw bad_input("patch " + std::to_string(patch) + ": material index out of range");
  return lame_parameters(mp.materials[m].young_modulus, mp.materials[m].poisson_ratio,
                         "material " + std::to_string(m));
}

// Displacement and its physical gradient at every point of ev.
void field_at(const spline::Patch& p, const detail::ElementValues& ev, Eigen::MatrixXd& U,
              std::vector<Eigen::Matrix3d>& G) {
  const int n = static_cast<int>(ev.local.size());
  Eigen::MatrixXd C(n, 3);
  for (int a = 0; a < n; ++a) C.row(a) = p.displacement.row(ev.local[a]);
  U = ev.R * C;
  G.resize(ev.R.rows());
  for (Eigen::Index q = 0; q < ev.R.rows(); ++q)
    for (int j = 0; j < 3; ++j) G[q].col(j) = (ev.grad.block(q, j * n, 1, n) * C).transpose();
}

}  // namespace

ElasticityPoint evaluate_elasticity(const spline::MultiPatch& mp, int patch, const Eigen::Vector3d& uvw) {
  const spline::Patch& p = solved_patch(mp, patch);
  std::array<detail::DirElement, 3> e;
  for (int d = 0; d < 3; ++d) {
    const auto& U = p.knots[d];
    const double lo = U[p.degrees[d]], hi = U[p.count(d)];
    e[d] = detail::direction_point(U, p.degrees[d], std::min(hi, std::max(lo, uvw(d))));
  }
  detail::ElementValues ev;
  detail::element_values(p, e[0], e[1], e[2], true, ev);
  if (!(std::abs(ev.det(0)) > 0.0) || !std::isfinite(ev.det(0)))
    throw bad_input("patch " + std::to_string(patch) + ": singular Jacobian at the evaluation point");
  Eigen::MatrixXd U;
  std::vector<Eigen::Matrix3d> G;
  field_at(p, ev, U, G);
  ElasticityPoint out;
  out.x = ev.x.row(0).transpose();
  out.displacement = U.row(0).transpose();
  out.gradient = G[0];
  out.stress = isotropic_stress(patch_lame(mp, patch), G[0]);
  return out;
}

double von_mises_stress(const Eigen::Matrix3d& s) {
  const Eigen::Matrix3d dev = s - s.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * dev.cwiseProduct(dev).sum());
}

ElasticityErrors elasticity_errors(const spline::MultiPatch& mp, const DisplacementField& exact,
                                   const DisplacementGradientField& exact_gradient, int extra) {
  ElasticityErrors r;
  double l2e = 0, l2n = 0, ene = 0, enn = 0;
  for (int pi = 0; pi < static_cast<int>(mp.patches.size()); ++pi) {
    const spline::Patch& p = solved_patch(mp, pi);
    const LameParameters lame = patch_lame(mp, pi);
    const std::array<std::vector<detail::DirElement>, 3> t = detail::patch_elements(p, extra);
    detail::ElementValues ev;
    Eigen::MatrixXd U;
    std::vector<Eigen::Matrix3d> G;
    for (const auto& ew : t[2])
      for (const auto& evv : t[1])
        for (const auto& eu : t[0]) {
          detail::element_values(p, eu, evv, ew, true, ev);
          field_at(p, ev, U, G);
          for (Eigen::Index q = 0; q < ev.w.size(); ++q) {
            const double dV = ev.w(q) * std::abs(ev.det(q));
            const Eigen::Vector3d x = ev.x.row(q).transpose();
            const Eigen::Vector3d ue = exact(x);
            const Eigen::Matrix3d ge = exact_gradient(x);
            l2e += (ue - U.row(q).transpose()).squaredNorm() * dV;
            l2n += ue.squaredNorm() * dV;
            ene += 2.0 * strain_energy_density(lame, ge - G[q]) * dV;
            enn += 2.0 * strain_energy_density(lame, ge) * dV;
          }
        }
  }
  r.l2_error = std::sqrt(l2e);
  r.l2_norm = std::sqrt(l2n);
  r.energy_error = std::sqrt(ene);
  r.energy_norm = std::sqrt(enn);
  return r;
}

}  // namespace igaprep::iga_check
