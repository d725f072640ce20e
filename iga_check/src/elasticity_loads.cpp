#include "elasticity_loads.h"

#include "elasticity_basis.h"
#include "elasticity_input.h"
#include "elasticity_side_points.h"

namespace igaprep::iga_check::detail {

namespace {

// Adds R_a(x) b(x) |det J| w at every Gauss point of every element, elements
// in the order of the stiffness assembly.
void add_body_force(const spline::MultiPatch& mp, const std::vector<PatchTables>& tables, const ElasticityDofs& dofs,
                    const ElasticityProblem& problem, Eigen::VectorXd& F) {
  ElementValues ev;
  for (size_t p = 0; p < mp.patches.size(); ++p) {
    const spline::Patch& pa = mp.patches[p];
    const std::vector<int>& global = dofs.numbering.global[p];
    for (const auto& ew : tables[p][2])
      for (const auto& evv : tables[p][1])
        for (const auto& eu : tables[p][0]) {
          element_values(pa, eu, evv, ew, false, ev);
          const Eigen::VectorXd wdet = ev.w.cwiseProduct(ev.det.cwiseAbs());
          const int n = static_cast<int>(ev.local.size());
          for (Eigen::Index q = 0; q < wdet.size(); ++q) {
            Eigen::Vector3d b = problem.body_force;
            if (problem.body_force_function) b += problem.body_force_function(ev.x.row(q).transpose());
            for (int a = 0; a < n; ++a)
              for (int i = 0; i < 3; ++i) {
                const int r = dofs.equation[3 * global[ev.local[a]] + i];
                if (r >= 0) F(r) += ev.R(q, a) * b(i) * wdet(q);
              }
          }
        }
  }
}

// Adds R_a(x) (traction - pressure n) dA at every Gauss point of side b.
void add_surface_load(const spline::MultiPatch& mp, const std::vector<PatchTables>& tables, const ElasticityDofs& dofs,
                      const spline::BoundarySide& b, const Eigen::Vector3d& traction, double pressure,
                      Eigen::VectorXd& F) {
  const std::vector<int>& global = dofs.numbering.global[b.patch];
  for_side_points(
      mp.patches[b.patch], b.side, tables[b.patch],
      [&](const ElementValues& ev, Eigen::Index q, const Eigen::Vector3d& nv, double dA) {
        const Eigen::Vector3d tr = traction - pressure * nv;
        const int n = static_cast<int>(ev.local.size());
        for (int a = 0; a < n; ++a) {
          const int g = global[ev.local[a]];
          for (int i = 0; i < 3; ++i) {
            const int r = dofs.equation[3 * g + i];
            if (r >= 0) F(r) += ev.R(q, a) * tr(i) * dA;
          }
        }
      },
      [] {});
}

}  // namespace

Eigen::VectorXd assemble_loads(const spline::MultiPatch& mp, const std::vector<PatchTables>& tables,
                               const ElasticityDofs& dofs, const ElasticityProblem& problem) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(dofs.unknowns);
  if (problem.body_force.squaredNorm() > 0.0 || problem.body_force_function)
    add_body_force(mp, tables, dofs, problem, F);
  for (const auto& tl : problem.tractions)
    for (const auto& b : sides_with_label(mp, tl.label, "traction load"))
      add_surface_load(mp, tables, dofs, b, tl.traction, 0.0, F);
  for (const auto& pl : problem.pressures)
    for (const auto& b : sides_with_label(mp, pl.label, "pressure load"))
      add_surface_load(mp, tables, dofs, b, Eigen::Vector3d::Zero(), pl.pressure, F);
  return F;
}

}  // namespace igaprep::iga_check::detail
