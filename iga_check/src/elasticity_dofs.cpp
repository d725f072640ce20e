#include "elasticity_dofs.h"

#include "elasticity_input.h"
#include "elasticity_rigid_modes.h"
#include "igaprep/spline/curve_surface.h"

namespace igaprep::iga_check::detail {

ElasticityDofs constrain_dofs(const spline::MultiPatch& mp, spline::GlobalNumbering numbering,
                              const PrescribedValues& prescribed, const std::vector<FixedSide>& fixed) {
  const int ncp = numbering.count;
  ElasticityDofs d;
  d.constrained.assign(3 * static_cast<size_t>(ncp), 0);
  d.values = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(ncp));
  // The side's control points carry its trace (open knot vectors).
  for (int g = 0; g < ncp; ++g)
    if (prescribed.is_prescribed[g])
      for (int i = 0; i < 3; ++i) {
        d.constrained[3 * g + i] = 1;
        d.values(3 * g + i) = prescribed.values(g, i);
      }
  std::vector<unsigned char> zero(3 * static_cast<size_t>(ncp), 0);
  for (const auto& f : fixed)
    for (const auto& b : sides_with_label(mp, f.label, "fixed boundary"))
      for (int l : spline::side_control_points(mp.patches[b.patch], b.side))
        for (int i = 0; i < 3; ++i)
          if (f.components[i]) {
            const int k = 3 * numbering.global[b.patch][l] + i;
            d.constrained[k] = 1;
            zero[k] = 1;
            d.values(k) = 0.0;
          }
  check_rigid_modes(mp, numbering, d.constrained);
  d.equation.assign(d.constrained.size(), -1);
  for (size_t k = 0; k < d.constrained.size(); ++k)
    if (!d.constrained[k]) d.equation[k] = d.unknowns++;
    else if (!zero[k]) ++d.prescribed;
  d.numbering = std::move(numbering);
  return d;
}

NodalLayout nodal_layout(const spline::MultiPatch& mp, const ElasticityDofs& dofs) {
  NodalLayout layout;
  layout.row_of = dofs.equation;
  layout.points = spline::global_points(mp, dofs.numbering);
  return layout;
}

}  // namespace igaprep::iga_check::detail
