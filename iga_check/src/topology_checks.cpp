#include "igaprep/iga_check/topology_checks.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/core/parallel.h"
#include "igaprep/mesh/enclosed_volume.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/gauss_legendre.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check {

namespace {

// Gauss points and weights over all elements of a knot vector.
void gauss_grid(const std::vector<double>& U, int n, std::vector<double>* pts, std::vector<double>* wts) {
  Eigen::VectorXd gp, gw;
  spline::gauss_legendre(n, gp, gw);
  const std::vector<double> brk = spline::unique_knots(U);
  for (size_t e = 0; e + 1 < brk.size(); ++e) {
    const double h = brk[e + 1] - brk[e];
    for (int g = 0; g < n; ++g) {
      pts->push_back(brk[e] + h * gp[g]);
      wts->push_back(h * gw[g]);
    }
  }
}

}  // namespace

double winding_number(const mesh::TriMesh& m, const Eigen::Vector3d& x) {
  // Sum of signed solid angles (Van Oosterom & Strackee) over 4 pi.
  double total = 0.0;
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)).transpose() - x, b = m.V.row(m.F(f, 1)).transpose() - x,
                          c = m.V.row(m.F(f, 2)).transpose() - x;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(num, den);
  }
  return total / (4.0 * M_PI);
}

double patch_volume(const spline::Patch& p) {
  std::array<std::vector<double>, 3> pts, wts;
  // det J of a polynomial patch has degree 3p-1: (3p+1)/2 Gauss points are
  // exact. Rational integrands are not polynomial: use more points.
  for (int d = 0; d < 3; ++d) {
    const int n = p.rational() ? 3 * p.degrees[d] + 3 : (3 * p.degrees[d] + 1) / 2 + 1;
    gauss_grid(p.knots[d], n, &pts[d], &wts[d]);
  }
  const spline::GridEvaluation ev = spline::evaluate_grid(p, pts, 1);
  double vol = 0.0;
  long at = 0;
  for (size_t k = 0; k < pts[2].size(); ++k)
    for (size_t j = 0; j < pts[1].size(); ++j)
      for (size_t i = 0; i < pts[0].size(); ++i, ++at) {
        vol += spline::grid_jacobian(ev, at).determinant() * wts[0][i] * wts[1][j] * wts[2][k];
      }
  return vol;
}

double side_area(const spline::Patch& p, spline::Side side) {
  const spline::Surface s = spline::boundary_surface(p, side);
  std::array<std::vector<double>, 2> pts, wts;
  for (int d = 0; d < 2; ++d) gauss_grid(s.knots[d], s.degrees[d] + 2, &pts[d], &wts[d]);
  const spline::GridEvaluation ev = spline::evaluate_grid(s, pts, 1);
  double area = 0.0;
  long at = 0;
  for (size_t j = 0; j < pts[1].size(); ++j)
    for (size_t i = 0; i < pts[0].size(); ++i, ++at) {
      Eigen::Vector3d xs, xt;
      for (int c = 0; c < 3; ++c) {
        xs[c] = ev.jacobians(at, 2 * c);
        xt[c] = ev.jacobians(at, 2 * c + 1);
      }
      area += xs.cross(xt).norm() * wts[0][i] * wts[1][j];
    }
  return area;
}

TopologyReport topology_checks(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                               double diagonal, double conformity_tolerance) {
  TopologyReport r;
  if (!(diagonal > 0.0)) diagonal = model_diagonal(mp);
  const spline::ConformityReport conf = spline::check_conformity(mp, conformity_tolerance * diagonal);
  r.conforming = conf.conforming;
  r.interface_max_gap = conf.max_deviation;
  r.interface_max_gap_relative = diagonal > 0.0 ? conf.max_deviation / diagonal : 0.0;
  r.conformity_problems = conf.problems;

  // Watertightness: count how each side is accounted for.
  const int np = static_cast<int>(mp.patches.size());
  std::vector<std::array<int, 6>> uses(np, {{0, 0, 0, 0, 0, 0}});
  std::vector<std::array<bool, 6>> is_interface(np, {{false, false, false, false, false, false}});
  auto count = [&](int patch, spline::Side side, bool itf, const std::string& what) {
    if (patch < 0 || patch >= np || !side.valid()) {
      r.watertight = false;
      r.watertight_problems.push_back(what + " names patch " + std::to_string(patch) + " side " +
                                      std::to_string(side) + ", which does not exist");
      return;
    }
    ++uses[patch][side.array_index()];
    if (itf) is_interface[patch][side.array_index()] = true;
  };
  for (size_t i = 0; i < mp.interfaces.size(); ++i) {
    const auto& itf = mp.interfaces[i];
    count(itf.patch_a, itf.side_a, true, "interface " + std::to_string(i));
    count(itf.patch_b, itf.side_b, true, "interface " + std::to_string(i));
  }
  for (size_t i = 0; i < mp.boundaries.size(); ++i)
    count(mp.boundaries[i].patch, mp.boundaries[i].side, false, "boundary " + std::to_string(i));
  for (int p = 0; p < np; ++p)
    for (const spline::Side s : spline::Side::all()) {
      SideStatus st{p, s, ""};
      const int n = uses[p][s.array_index()];
      if (n == 1) {
        st.kind = is_interface[p][s.array_index()] ? "interface" : "boundary";
      } else if (n > 1) {
        st.kind = "duplicate";
        r.watertight = false;
        r.watertight_problems.push_back("patch " + std::to_string(p) + " side " + std::to_string(s) +
                                        " is listed " + std::to_string(n) + " times");
      } else if (side_area(mp.patches[p], s) <= 1e-10 * diagonal * diagonal) {
        st.kind = "collapsed";
      } else {
        st.kind = "missing";
        r.watertight = false;
        r.watertight_problems.push_back("patch " + std::to_string(p) + " side " + std::to_string(s) +
                                        " is neither an interface nor a labelled boundary");
      }
      r.sides.push_back(st);
    }

  // Volumes: the patches' on all cores, summed in patch order.
  r.material_volumes.assign(std::max<size_t>(mp.materials.size(), 1), 0.0);
  r.patch_volumes.assign(static_cast<size_t>(np), 0.0);
  parallel_for(static_cast<size_t>(np), [&](size_t p) { r.patch_volumes[p] = patch_volume(mp.patches[p]); });
  for (int p = 0; p < np; ++p) {
    const double v = r.patch_volumes[static_cast<size_t>(p)];
    const int m = mp.patches[p].material;
    if (m >= 0) {
      if (m >= static_cast<int>(r.material_volumes.size())) r.material_volumes.resize(m + 1, 0.0);
      r.material_volumes[m] += v;
    }
  }
  if (!surfaces.empty()) {
    const std::vector<double> input = mesh::region_volumes(surfaces);
    for (size_t i = 0; i < surfaces.size(); ++i) {
      RegionVolume rv;
      rv.region = static_cast<int>(i);
      rv.input_volume = input[i];
      r.regions.push_back(rv);
    }
    for (int p = 0; p < np; ++p) {
      const spline::Patch& patch = mp.patches[p];
      Eigen::Vector3d mid;
      for (int d = 0; d < 3; ++d) {
        const auto& U = patch.knots[d];
        mid[d] = 0.5 * (U[patch.degrees[d]] + U[U.size() - patch.degrees[d] - 1]);
      }
      const Eigen::Vector3d x = spline::evaluate_point(patch, mid);
      int region = -1;
      for (size_t i = 0; i < surfaces.size(); ++i)
        if (std::abs(winding_number(surfaces[i], x)) > 0.5) region = static_cast<int>(i);
      r.patch_region.push_back(region);
      if (region >= 0) {
        r.regions[region].spline_volume += r.patch_volumes[p];
        ++r.regions[region].patches;
      }
    }
    for (auto& rv : r.regions)
      rv.relative_difference = rv.input_volume != 0.0 ? (rv.spline_volume - rv.input_volume) / rv.input_volume : 0.0;
  }
  return r;
}

}  // namespace igaprep::iga_check
