#pragma once
// Internal to the elasticity solver: quadrature on a boundary side of a
// patch, shared by the surface loads and the projection of prescribed
// displacements.
#include <Eigen/Geometry>
#include <vector>

#include "elasticity_basis.h"
#include "elasticity_tables.h"
#include "igaprep/spline/curve_surface.h"

namespace igaprep::iga_check::detail {

// Calls f(ev, q, normal, dA) at every Gauss point of side `side` of patch pa:
// the side's fixed direction is a one-point table at its end, the other two
// use the patch's volume tables. `normal` is the unit outward normal; points
// where the side collapses (zero area) are skipped. end_element() follows the
// points of each element of the side.
template <class F, class E>
void for_side_points(const spline::Patch& pa, int side, const PatchTables& tables, F&& f, E&& end_element) {
  const int d = spline::side_direction(side);
  const bool at_max = spline::side_is_max(side);
  const auto t = spline::side_tangent_directions(side);
  const std::vector<double>& U = pa.knots[d];
  const int nd = pa.count(d);
  std::vector<DirElement> fixed_dir{direction_point(U, pa.degrees[d], at_max ? U[nd] : U[pa.degrees[d]])};
  std::array<const std::vector<DirElement>*, 3> dirs;
  for (int k = 0; k < 3; ++k) dirs[k] = k == d ? &fixed_dir : &tables[k];
  ElementValues ev;
  for (const auto& ew : *dirs[2])
    for (const auto& evv : *dirs[1])
      for (const auto& eu : *dirs[0]) {
        element_values(pa, eu, evv, ew, false, ev);
        for (Eigen::Index q = 0; q < ev.w.size(); ++q) {
          Eigen::Matrix3d J;
          for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) J(c, k) = ev.J(q, 3 * c + k);
          Eigen::Vector3d nv = J.col(t[0]).cross(J.col(t[1]));
          const double area = nv.norm();
          if (area == 0.0) continue;  // a collapsed point of the face carries no load
          nv /= area;
          // Outward: against the inward parameter direction at a min side.
          const double s = nv.dot(J.col(d));
          if (at_max ? s < 0 : s > 0) nv = -nv;
          f(ev, q, nv, area * ev.w(q));
        }
        end_element();
      }
}

}  // namespace igaprep::iga_check::detail
