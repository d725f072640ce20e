// The validation cases' loads against closed forms: a total force spread
// over its sides (a bar in uniaxial tension, exact in the spline space) and
// the centrifugal body force of a rotation (a spinning thick cylinder in
// plane strain, Timoshenko's solution).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "expect_bad_input.h"
#include "igaprep/iga_check/elasticity_evaluate.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "solve_models.h"

using namespace igaprep;
using namespace solve_test;

namespace {

const double kPi = 3.14159265358979323846;

// The box [0, 2] x [0, 3] x [0, 1.5] in two patches split at y = 1; E = 1000,
// nu = 0.3. Sides: x0, y0, z0 (rollers) and x1 (loaded, two sides of summed
// area 4.5), the rest free.
MultiPatch split_box() {
  MultiPatch mp;
  mp.patches = {box_patch({0, 0, 0}, {2, 1, 1.5}, {2, 2, 2}, {2, 1, 2}),
                box_patch({0, 1, 0}, {2, 3, 1.5}, {2, 2, 2}, {2, 2, 2})};
  mp.materials = {{"steel", 1000.0, 0.3}};
  find_interfaces(mp);
  label_boundaries(mp, [](const Eigen::Vector3d& x) {
    if (std::abs(x(0)) < 1e-9) return std::string("x0");
    if (std::abs(x(0) - 2) < 1e-9) return std::string("x1");
    if (std::abs(x(1)) < 1e-9) return std::string("y0");
    if (std::abs(x(2)) < 1e-9) return std::string("z0");
    return std::string("free");
  });
  return mp;
}

iga_check::ElasticityProblem rollers() {
  iga_check::ElasticityProblem problem;
  problem.fixed = {{"x0", {{true, false, false}}}, {"y0", {{false, true, false}}}, {"z0", {{false, false, true}}}};
  return problem;
}

}  // namespace

// 9 N along x on 4.5 mm^2: sigma_xx = 2 everywhere, u = (2/E) (x, -nu y, -nu z).
TEST(SolveLoadKinds, TotalForceIsSpreadOverTheSummedAreaOfItsSides) {
  const MultiPatch mp = split_box();
  iga_check::ElasticityProblem problem = rollers();
  problem.forces = {{{"x1"}, {9.0, 0.0, 0.0}}};
  const auto sol = iga_check::solve_elasticity(mp, problem);
  const double strain = 2.0 / 1000.0;
  for (int p = 0; p < 2; ++p)
    for (const Eigen::Vector3d uvw : {Eigen::Vector3d(0.3, 0.6, 0.2), Eigen::Vector3d(1.0, 1.0, 1.0)}) {
      const auto pt = iga_check::evaluate_elasticity(sol.model, p, uvw);
      const Eigen::Vector3d exact(strain * pt.x(0), -0.3 * strain * pt.x(1), -0.3 * strain * pt.x(2));
      EXPECT_LT((pt.displacement - exact).norm(), 1e-12) << "patch " << p;
      EXPECT_NEAR(pt.stress(0, 0), 2.0, 1e-9);
      EXPECT_NEAR(pt.stress(1, 1), 0.0, 1e-9);
    }
  // The work of the force: 1/2 F u_x(2).
  EXPECT_NEAR(sol.report.strain_energy, 0.5 * 9.0 * strain * 2.0, 1e-12);
}

TEST(SolveLoadKinds, ForceAndRotationInputIsCheckedFirst) {
  const MultiPatch mp = split_box();
  iga_check::ElasticityProblem problem = rollers();
  problem.forces = {{{"x1", "nowhere"}, {9.0, 0.0, 0.0}}};
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"force load: unknown label 'nowhere'"});
  problem.forces = {{{}, {9.0, 0.0, 0.0}}};
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"force load: no label given"});
  problem.forces.clear();
  problem.rotation = iga_check::RotationLoad{1.0, 10.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"rotation: the axis must be a non-zero vector"});
  problem.rotation->axis = Eigen::Vector3d::UnitX();
  problem.rotation->density = -1.0;
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"rotation: the density must be finite and not negative"});
}

namespace {

const double ka = 1.0, kc = 2.0, kH = 0.25, kE = 200.0, kNu = 0.3, kRho = 2.0, kOmega = 3.0;

// Plane strain, free at r = a and r = c: u_r = A r + B / r - k r^3 with
// k = rho omega^2 / (8 (lambda + 2 mu)), and
// sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2 - (4 lambda + 6 mu) k r^2.
struct SpinningCylinder {
  double A = 0, B = 0, k = 0;
  iga_check::LameParameters m;
  SpinningCylinder() {
    m = iga_check::lame_parameters(kE, kNu);
    k = kRho * kOmega * kOmega / (8.0 * (m.lambda + 2.0 * m.mu));
    Eigen::Matrix2d M;
    Eigen::Vector2d f;
    for (int i = 0; i < 2; ++i) {
      const double r = i == 0 ? ka : kc;
      M.row(i) << 2.0 * (m.lambda + m.mu), -2.0 * m.mu / (r * r);
      f(i) = (4.0 * m.lambda + 6.0 * m.mu) * k * r * r;
    }
    const Eigen::Vector2d x = M.fullPivLu().solve(f);
    A = x(0), B = x(1);
  }
  double ur(double r) const { return A * r + B / r - k * r * r * r; }
};

// A quarter of the cylinder in two exact NURBS sectors of degree 3 with
// 2^level elements radially and angularly; rollers on x = 0, y = 0 and both
// z faces.
MultiPatch quarter_cylinder(int level) {
  MultiPatch mp;
  for (int half = 0; half < 2; ++half) {
    Patch pa = sector_patch(ka, kc, half * kPi / 4, (half + 1) * kPi / 4, 0.0, kH);
    for (int d = 0; d < 3; ++d) pa = igaprep::spline::elevate_degree(pa, d, 1);
    std::vector<double> X;
    for (int i = 1; i < (1 << level); ++i) X.push_back(double(i) / (1 << level));
    for (int d = 0; d < 2; ++d) pa = igaprep::spline::insert_knots(pa, d, X);
    mp.patches.push_back(pa);
  }
  mp.materials = {{"steel", kE, kNu}};
  find_interfaces(mp);
  label_boundaries(mp, [](const Eigen::Vector3d& x) {
    if (std::abs(x(2)) < 1e-9 || std::abs(x(2) - kH) < 1e-9) return std::string("z");
    if (std::abs(x(0)) < 1e-9) return std::string("x0");
    if (std::abs(x(1)) < 1e-9) return std::string("y0");
    return std::string("round");
  });
  return mp;
}

}  // namespace

TEST(SolveLoadKinds, SpinningThickCylinderMatchesTheClosedForm) {
  const SpinningCylinder ex;
  iga_check::ElasticityProblem problem;
  problem.fixed = {{"x0", {{true, false, false}}}, {"y0", {{false, true, false}}}, {"z", {{false, false, true}}}};
  // The axis given off the origin along -z through (0, 0, 5): the same line.
  problem.rotation = iga_check::RotationLoad{kRho, kOmega, Eigen::Vector3d(0, 0, -2), Eigen::Vector3d(0, 0, 5)};
  double coarse = 0.0;
  for (int level : {1, 3}) {
    const auto sol = iga_check::solve_elasticity(quarter_cylinder(level), problem);
    double deviation = 0.0;
    for (int p = 0; p < 2; ++p)
      for (double s : {0.0, 0.25, 0.5, 0.75, 1.0})
        for (double t : {0.0, 0.4, 1.0}) {
          const auto pt = iga_check::evaluate_elasticity(sol.model, p, Eigen::Vector3d(s, t, 0.5));
          const double r = std::hypot(pt.x(0), pt.x(1));
          const Eigen::Vector3d er(pt.x(0) / r, pt.x(1) / r, 0);
          deviation = std::max(deviation, std::abs(pt.displacement.dot(er) - ex.ur(r)) / std::abs(ex.ur(kc)));
          EXPECT_LT(std::abs(pt.displacement(2)), 1e-12);
        }
    // The strain energy is half the work of the body force,
    // 1/2 rho omega^2 (pi/2) H int_a^c u_r(r) r^2 dr (Simpson, 2000 intervals).
    double integral = 0.0;
    const int n = 2000;
    for (int i = 0; i <= n; ++i) {
      const double r = ka + (kc - ka) * i / n, wgt = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      integral += wgt * ex.ur(r) * r * r;
    }
    integral *= (kc - ka) / n / 3.0;
    const double energy = 0.5 * kRho * kOmega * kOmega * kPi / 2 * kH * integral;
    std::printf("level %d: relative deviation of u_r %.2e, strain energy %.10g (closed form %.10g)\n", level,
                deviation, sol.report.strain_energy, energy);
    if (level == 1) {
      coarse = deviation;
      EXPECT_LT(deviation, 1e-3);
      continue;
    }
    EXPECT_LT(deviation, 1e-5);
    EXPECT_LT(deviation, coarse / 10) << "refinement must reduce the error";
    EXPECT_NEAR(sol.report.strain_energy, energy, 1e-7 * energy);
  }
}
