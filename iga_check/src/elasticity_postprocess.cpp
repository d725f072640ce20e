#include "elasticity_postprocess.h"

#include <algorithm>

namespace igaprep::iga_check::detail {

void store_solution(const Eigen::VectorXd& u, const ElasticityDofs& dofs, const StiffnessSystem& system,
                    spline::MultiPatch& mp, ElasticityReport& report) {
  const Eigen::VectorXd Ku = system.matrix.selfadjointView<Eigen::Lower>() * u;
  report.strain_energy = 0.5 * u.dot(Ku) + u.dot(system.lifting) + 0.5 * system.constrained_energy;
  for (size_t p = 0; p < mp.patches.size(); ++p) {
    spline::Patch& pa = mp.patches[p];
    pa.displacement = Eigen::MatrixXd::Zero(pa.control_points.rows(), 3);
    for (Eigen::Index l = 0; l < pa.displacement.rows(); ++l)
      for (int i = 0; i < 3; ++i) {
        const int g = dofs.numbering.global[p][l];
        const int r = dofs.equation[3 * g + i];
        pa.displacement(l, i) = r >= 0 ? u(r) : dofs.values(3 * g + i);
      }
    if (pa.displacement.rows() > 0)
      report.max_displacement = std::max(report.max_displacement, pa.displacement.rowwise().norm().maxCoeff());
  }
  mp.has_solution = true;
  mp.strain_energy = report.strain_energy;
  mp.max_displacement = report.max_displacement;
}

}  // namespace igaprep::iga_check::detail
