// Prescribed (non-zero) displacements: a linear field imposed on every outer
// side of a distorted, curved-boundary model of three patches (one rational,
// two interfaces with non-identity orientation) is reproduced exactly, with
// zero body force: the boundary L2 projection reproduces it, and it solves
// the equations. Prescribed and zero (FixedSide) constraints combine. Bad
// input: unknown labels, labels without sides, missing or non-finite functions.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/elasticity_evaluate.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "solve_models.h"
#include "solve/expect_bad_input.h"

using namespace igaprep;
using namespace solve_test;

namespace {

using solve_test::expect_bad_input;

const double kPi = 3.14159265358979323846;

// An L of three unit boxes, ([0,1]^3, [1,2]x[0,1]^2, [0,1]x[1,2]x[0,1]);
// patches 1 and 2 reoriented. Every control point moves by a smooth field of
// its position (so interfaces still match) scaled by `distortion(x)`; weights
// of patch 1 are also a function of position (equal on both sides).
MultiPatch distorted_l(const std::function<double(const Eigen::Vector3d&)>& distortion) {
  Patch p0 = box_patch({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {2, 2, 3});
  Patch p1 = box_patch({1, 0, 0}, {2, 1, 1}, {2, 2, 2}, {2, 2, 3});
  Patch p2 = box_patch({0, 1, 0}, {1, 2, 1}, {2, 2, 2}, {2, 2, 3});
  // 1 on the interfaces x = 1 (with patch 0, a B-spline) and nowhere else shared.
  auto weight = [](const Eigen::Vector3d& x) { return 1.0 + 0.3 * std::sin(kPi * (x(0) - 1)) * (0.5 + x(1) * x(2)); };
  p1.weights.resize(p1.control_points.rows());
  for (Eigen::Index i = 0; i < p1.control_points.rows(); ++i) p1.weights(i) = weight(p1.control_points.row(i));
  for (Patch* p : {&p0, &p1, &p2})
    for (Eigen::Index i = 0; i < p->control_points.rows(); ++i) {
      const Eigen::Vector3d x = p->control_points.row(i);
      const Eigen::Vector3d d(std::sin(kPi * x(1) / 2) * std::cos(x(2)), std::sin(1.7 * x(0) + x(2)),
                              std::cos(kPi * x(0) / 2) * std::sin(kPi * x(1) / 2));
      p->control_points.row(i) += 0.07 * distortion(x) * d.transpose();
    }
  MultiPatch mp;
  mp.patches = {p0, reorient(p1, {1, 2, 0}, {true, false, false}), reorient(p2, {2, 0, 1}, {false, true, true})};
  mp.materials = {{"steel", 1000.0, 0.3}};
  find_interfaces(mp);
  return mp;
}

// Gauss points beyond p + 1: the patch test's choice (exact to ~1e-12 on
// distorted and rational patches, see patch_test.cpp).
const int kExtra = 6;

Eigen::Matrix3d kA = (Eigen::Matrix3d() << 0.02, -0.013, 0.007, 0.011, 0.031, -0.017, -0.009, 0.004, 0.025).finished();
const Eigen::Vector3d kC(0.003, -0.002, 0.005);

// Largest coefficient error against u(X_a) (exact for a linear field: the
// coefficients of the interpolant of a linear field are its control-point values).
double coefficient_error(const MultiPatch& solved, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u) {
  double e = 0.0;
  for (const auto& p : solved.patches)
    for (Eigen::Index i = 0; i < p.control_points.rows(); ++i)
      e = std::max(e, (p.displacement.row(i).transpose() - u(p.control_points.row(i).transpose())).norm());
  return e;
}

// The linear field A x + c, reproduced exactly by any patch.
Eigen::Vector3d linear_field(const Eigen::Vector3d& x) { return kA * x + kC; }

// Solves with u prescribed on every side labelled T1 (with the extra
// quadrature points distorted patches need for exactness).
auto solve_with_t1_prescribed(const MultiPatch& mp, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u,
                              int refine = 0) {
  iga_check::ElasticityProblem problem;
  problem.prescribed = {{"T1", u}};
  iga_check::ElasticityOptions options;
  options.extra_quadrature = kExtra;
  options.refine = refine;
  return iga_check::solve_elasticity(mp, problem, options);
}

}  // namespace

TEST(SolvePrescribed, LinearFieldOnCurvedDistortedMultipatchIsExact) {
  MultiPatch mp = distorted_l([](const Eigen::Vector3d&) { return 1.0; });
  ASSERT_EQ(mp.interfaces.size(), 2u);
  for (const auto& itf : mp.interfaces)
    EXPECT_FALSE(itf.dirmap == (std::array<int, 3>{0, 1, 2}) && itf.orient == (std::array<int, 3>{1, 1, 1}));
  label_boundaries(mp, [](const Eigen::Vector3d&) { return std::string("T1"); });
  ASSERT_EQ(mp.boundaries.size(), 14u);
  ASSERT_EQ(mp.labels[0], "T1");
  const auto u = linear_field;
  const auto sol = solve_with_t1_prescribed(mp, u);
  EXPECT_GT(sol.report.unknowns, 0);
  EXPECT_EQ(sol.report.prescribed_dofs, sol.report.fixed_dofs);
  EXPECT_GT(sol.report.prescribed_dofs, 0);
  EXPECT_LT(coefficient_error(sol.model, u), 1e-9);

  // Error norms and the strain energy 1/2 int eps:C:eps of the whole field
  // (prescribed coefficients included) against the exact field's.
  const auto grad = [](const Eigen::Vector3d&) { return kA; };
  const auto err = iga_check::elasticity_errors(sol.model, u, grad, 4);
  EXPECT_GT(err.l2_norm, 1e-3);
  EXPECT_LT(err.l2_error, 1e-9 * err.l2_norm);
  EXPECT_LT(err.energy_error, 1e-9 * err.energy_norm);
  const double energy = 0.5 * err.energy_norm * err.energy_norm;
  EXPECT_NEAR(sol.report.strain_energy, energy, 1e-9 * energy);
  // Stress inside each patch is the constant sigma(A).
  const Eigen::Matrix3d sigma = iga_check::isotropic_stress(iga_check::lame_parameters(1000.0, 0.3), kA);
  for (int p = 0; p < 3; ++p) {
    const auto pt = iga_check::evaluate_elasticity(sol.model, p, Eigen::Vector3d(0.31, 0.77, 0.52));
    EXPECT_LT((pt.displacement - u(pt.x)).norm(), 1e-9);
    EXPECT_LT((pt.stress - sigma).norm(), 1e-8 * sigma.norm()) << "patch " << p;
  }
  // After refinement (projection on a finer boundary space), still exact.
  const auto fine = solve_with_t1_prescribed(mp, u, 1);
  EXPECT_LT(coefficient_error(fine.model, u), 1e-9);
}

// u = x_0 a vanishes on x = 0: clamp that face (FixedSide, which wins on the
// shared edges) and prescribe u on the others, on a model whose x = 0 face
// stays planar.
TEST(SolvePrescribed, CombinesWithZeroConstraints) {
  MultiPatch mp = distorted_l([](const Eigen::Vector3d& x) { return x(0) * (2.5 - x(0)); });
  ASSERT_EQ(mp.interfaces.size(), 2u);
  label_boundaries(mp, [](const Eigen::Vector3d& c) { return std::string(std::abs(c(0)) < 1e-9 ? "x0" : "rest"); });
  const Eigen::Vector3d a(0.04, -0.03, 0.05);
  const auto u = [a](const Eigen::Vector3d& x) { return Eigen::Vector3d(x(0) * a); };
  iga_check::ElasticityProblem problem;
  problem.fixed = {{"x0", {{true, true, true}}}};
  problem.prescribed = {{"rest", u}};
  iga_check::ElasticityOptions options;
  options.extra_quadrature = kExtra;
  const auto sol = iga_check::solve_elasticity(mp, problem, options);
  EXPECT_GT(sol.report.prescribed_dofs, 0);
  EXPECT_LT(sol.report.prescribed_dofs, sol.report.fixed_dofs);
  EXPECT_LT(coefficient_error(sol.model, u), 1e-9);
  EXPECT_GT(sol.report.max_displacement, 0.05);
}

// A non-polynomial field is not reproduced, but its boundary projection is
// close: the solution converges (a smoke check that the values are used).
TEST(SolvePrescribed, PrescribedValuesAreTheBoundaryProjection) {
  MultiPatch mp = distorted_l([](const Eigen::Vector3d&) { return 1.0; });
  ASSERT_EQ(mp.interfaces.size(), 2u);
  label_boundaries(mp, [](const Eigen::Vector3d&) { return std::string("T1"); });
  const auto u = [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(std::sin(x(0) + 0.5 * x(1)), std::cos(x(2) - x(0)), std::exp(0.3 * x(1)));
  };
  iga_check::ElasticityProblem problem;
  problem.prescribed = {{"T1", u}};
  // Coefficients at patch corners that lie on the boundary approximate u
  // there; shared corners got one value (the numbering), checked through the
  // interface: the displacement field is continuous across it.
  iga_check::ElasticityOptions options;
  options.refine = 1;
  const auto sol = iga_check::solve_elasticity(mp, problem, options);
  double corner_err = 0.0;
  for (const auto& p : sol.model.patches)
    for (int c = 0; c < 8; ++c) {
      const int i = (c & 1) ? p.count(0) - 1 : 0, j = (c & 2) ? p.count(1) - 1 : 0, k = (c & 4) ? p.count(2) - 1 : 0;
      const int l = p.index(i, j, k);
      corner_err = std::max(corner_err, (p.displacement.row(l).transpose() - u(p.control_points.row(l))).norm());
    }
  EXPECT_LT(corner_err, 2e-3);
  EXPECT_GT(corner_err, 0.0);
  for (const auto& itf : sol.model.interfaces)
    for (const auto& [la, lb] : spline::interface_point_pairs(sol.model, itf))
      EXPECT_EQ(sol.model.patches[itf.patch_a].displacement.row(la), sol.model.patches[itf.patch_b].displacement.row(lb));
}

// A wedge: the side u = 1 of a box collapses to a segment (zero area), so the
// functions living only on it have no boundary mass; they take the field's
// value at their control point, and a linear field is still exact.
TEST(SolvePrescribed, CollapsedSideTakesPointValues) {
  Patch p = box_patch({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {2, 2, 2});
  for (int k = 0; k < p.count(2); ++k)
    for (int j = 0; j < p.count(1); ++j) {
      auto row = p.control_points.row(p.index(p.count(0) - 1, j, k));
      row(1) = 0.5;
    }
  MultiPatch mp;
  mp.patches = {p};
  mp.materials = {{"steel", 1000.0, 0.3}};
  label_boundaries(mp, [](const Eigen::Vector3d&) { return std::string("T1"); });
  const auto sol = solve_with_t1_prescribed(mp, linear_field);
  EXPECT_GT(sol.report.unknowns, 0);
  EXPECT_LT(coefficient_error(sol.model, linear_field), 1e-9);
}

TEST(SolvePrescribed, BadInput) {
  MultiPatch mp = distorted_l([](const Eigen::Vector3d& x) { return x(0); });
  label_boundaries(mp, [](const Eigen::Vector3d& c) { return std::string(std::abs(c(0)) < 1e-9 ? "x0" : "T1"); });
  const auto u = [](const Eigen::Vector3d& x) { return Eigen::Vector3d(0.01 * x); };
  iga_check::ElasticityProblem problem;
  problem.prescribed = {{"T1", u}, {"nowhere", u}};
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); },
                   {"prescribed displacement", "unknown label 'nowhere'", "T1", "x0"});
  mp.labels.push_back("inner");
  problem.prescribed = {{"T1", u}, {"inner", u}};
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"'inner'", "no boundary side"});
  problem.prescribed = {{"T1", nullptr}};
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"'T1'", "no function"});
  problem.prescribed = {{"x0", [](const Eigen::Vector3d& x) {
                           return Eigen::Vector3d(x(1) > 0.5 ? std::numeric_limits<double>::quiet_NaN() : 0.0, 0, 0);
                         }}};
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"'x0'", "not finite"});
}
