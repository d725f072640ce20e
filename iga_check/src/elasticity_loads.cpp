#include "elasticity_loads.h"

#include "elasticity_basis.h"
#include "elasticity_input.h"
#include "elasticity_side_points.h"
#include "igaprep/core/error.h"

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
            const Eigen::Vector3d x = ev.x.row(q).transpose();
            Eigen::Vector3d b = problem.body_force;
            if (problem.body_force_function) b += problem.body_force_function(x);
            if (problem.rotation) b += problem.rotation->body_force(x);
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

// A total force as the constant traction force / area on its sides, the
// area summed by the loads' own quadrature.
void add_force_load(const spline::MultiPatch& mp, const std::vector<PatchTables>& tables, const ElasticityDofs& dofs,
                    const ForceLoad& fl, Eigen::VectorXd& F) {
  std::vector<spline::BoundarySide> sides;
  for (const auto& l : fl.labels) {
    const std::vector<spline::BoundarySide> of_label = sides_with_label(mp, l, "force load");
    sides.insert(sides.end(), of_label.begin(), of_label.end());
  }
  double area = 0.0;
  for (const auto& b : sides)
    for_side_points(
        mp.patches[b.patch], b.side, tables[b.patch],
        [&](const ElementValues&, Eigen::Index, const Eigen::Vector3d&, double dA) { area += dA; }, [] {});
  if (!(area > 0.0)) throw bad_input("force load on '" + fl.labels.front() + "': its sides have no area");
  for (const auto& b : sides) add_surface_load(mp, tables, dofs, b, fl.force / area, 0.0, F);
}

}  // namespace

Eigen::VectorXd assemble_loads(const spline::MultiPatch& mp, const std::vector<PatchTables>& tables,
                               const ElasticityDofs& dofs, const ElasticityProblem& problem) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(dofs.unknowns);
  if (problem.body_force.squaredNorm() > 0.0 || problem.body_force_function || problem.rotation)
    add_body_force(mp, tables, dofs, problem, F);
  for (const auto& tl : problem.tractions)
    for (const auto& b : sides_with_label(mp, tl.label, "traction load"))
      add_surface_load(mp, tables, dofs, b, tl.traction, 0.0, F);
  for (const auto& pl : problem.pressures)
    for (const auto& b : sides_with_label(mp, pl.label, "pressure load"))
      add_surface_load(mp, tables, dofs, b, Eigen::Vector3d::Zero(), pl.pressure, F);
  for (const auto& fl : problem.forces) add_force_load(mp, tables, dofs, fl, F);
  return F;
}

}  // namespace igaprep::iga_check::detail
