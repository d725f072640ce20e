#pragma once
// The composite thick-walled cylinder in plane strain and Lame's closed form
// (shared by the multipatch and the T-spline solve tests): two rings of
// different materials (a < r < b, b < r < c), each a quarter cross-section
// in two exact NURBS sectors (four patches), extruded in z; symmetry on
// x = 0 and y = 0, u_z = 0 on both z faces, internal pressure P at r = a.
#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_problem.h"
#include "solve_models.h"

namespace solve_test {

inline const double kPi = 3.14159265358979323846;
inline const double ka = 1.0, kb = 1.5, kc = 2.0, kP = 1.0, kH = 0.25;
inline const double kE[2] = {200.0, 70.0}, kNu[2] = {0.3, 0.33};

// u_r = A_i r + B_i / r in ring i; plane strain:
// sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2, sigma_tt = 2 (lambda + mu) A + 2 mu B / r^2,
// sigma_zz = 2 lambda A. Conditions: sigma_rr1(a) = -P, u1(b) = u2(b),
// sigma_rr1(b) = sigma_rr2(b), sigma_rr2(c) = 0.
struct Lame {
  double A[2], B[2];
  igaprep::iga_check::LameParameters m[2];
  int ring(double r) const { return r < kb ? 0 : 1; }
  double ur(double r, int i) const { return A[i] * r + B[i] / r; }
  double srr(double r, int i) const { return 2 * (m[i].lambda + m[i].mu) * A[i] - 2 * m[i].mu * B[i] / (r * r); }
  double stt(double r, int i) const { return 2 * (m[i].lambda + m[i].mu) * A[i] + 2 * m[i].mu * B[i] / (r * r); }
  double szz(int i) const { return 2 * m[i].lambda * A[i]; }
};

inline Lame lame_solution() {
  Lame s;
  for (int i = 0; i < 2; ++i) s.m[i] = igaprep::iga_check::lame_parameters(kE[i], kNu[i]);
  auto rr = [&](int i, double r) {  // sigma_rr coefficients of (A_i, B_i)
    return Eigen::RowVector2d(2 * (s.m[i].lambda + s.m[i].mu), -2 * s.m[i].mu / (r * r));
  };
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  Eigen::Vector4d f(-kP, 0, 0, 0);
  M.block<1, 2>(0, 0) = rr(0, ka);
  M.block<1, 2>(1, 0) << kb, 1 / kb;
  M.block<1, 2>(1, 2) << -kb, -1 / kb;
  M.block<1, 2>(2, 0) = rr(0, kb);
  M.block<1, 2>(2, 2) = -rr(1, kb);
  M.block<1, 2>(3, 2) = rr(1, kc);
  const Eigen::Vector4d x = M.fullPivLu().solve(f);
  s.A[0] = x(0), s.B[0] = x(1), s.A[1] = x(2), s.B[1] = x(3);
  return s;
}

// Four exact NURBS sectors at degree p with 2^level elements in u (radial)
// and v (angular); one element in z, where the exact field is constant.
inline MultiPatch composite_cylinder(int p, int level) {
  MultiPatch mp;
  const double r[3] = {ka, kb, kc};
  for (int ring = 0; ring < 2; ++ring)
    for (int half = 0; half < 2; ++half) {
      Patch pa = sector_patch(r[ring], r[ring + 1], half * kPi / 4, (half + 1) * kPi / 4, 0.0, kH);
      for (int d = 0; d < 3; ++d) pa = igaprep::spline::elevate_degree(pa, d, p - 2);
      std::vector<double> X;
      for (int i = 1; i < (1 << level); ++i) X.push_back(double(i) / (1 << level));
      for (int d = 0; d < 2; ++d)
        if (!X.empty()) pa = igaprep::spline::insert_knots(pa, d, X);
      pa.material = ring;
      mp.patches.push_back(pa);
    }
  // The outer ring's second sector reversed in u and swapped u/v: the
  // interfaces then carry non-identity orientations as well.
  mp.patches[3] = reorient(mp.patches[3], {1, 0, 2}, {true, false, false});
  mp.materials = {{"inner", kE[0], kNu[0]}, {"outer", kE[1], kNu[1]}};
  find_interfaces(mp);
  label_boundaries(mp, [](const Eigen::Vector3d& x) {
    const double rr = std::hypot(x(0), x(1));
    if (std::abs(x(2)) < 1e-9) return std::string("z0");
    if (std::abs(x(2) - kH) < 1e-9) return std::string("z1");
    if (std::abs(x(0)) < 1e-9) return std::string("x0");
    if (std::abs(x(1)) < 1e-9) return std::string("y0");
    if (std::abs(rr - ka) < 1e-9) return std::string("inner");
    if (std::abs(rr - kc) < 1e-9) return std::string("outer");
    return std::string("unknown");
  });
  return mp;
}

inline igaprep::iga_check::ElasticityProblem cylinder_problem() {
  igaprep::iga_check::ElasticityProblem problem;
  problem.fixed = {{"x0", {{true, false, false}}},
                   {"y0", {{false, true, false}}},
                   {"z0", {{false, false, true}}},
                   {"z1", {{false, false, true}}}};
  problem.pressures = {{"inner", kP}};
  return problem;
}

// The strain energy equals the work of the pressure: 1/2 P u_r(a) (pi/2) a H.
inline double cylinder_strain_energy() {
  const Lame ex = lame_solution();
  return 0.5 * kP * ex.ur(ka, 0) * kPi / 2 * ka * kH;
}

}  // namespace solve_test
