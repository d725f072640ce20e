// Patch test: a linear displacement field on a three-patch box with distorted
// interior control points, a rational patch and two non-identity interface
// orientations is reproduced exactly (to 1e-9) when imposed through its
// tractions and constraints.
#include <gtest/gtest.h>

#include <cmath>

#include "igaprep/iga_check/elasticity_evaluate.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "solve_models.h"

using namespace igaprep;
using namespace solve_test;

namespace {

const double kPi = 3.14159265358979323846;

// Box [0,3] x [0,1] x [0,1] in three patches along x; patches 1 and 2 are
// reoriented so that both interfaces have non-identity dirmap and orient.
MultiPatch distorted_box() {
  MultiPatch mp;
  Patch p0 = box_patch({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {2, 3, 2});
  Patch p1 = box_patch({1, 0, 0}, {2, 1, 1}, {2, 2, 2}, {2, 3, 2});
  Patch p2 = box_patch({2, 0, 0}, {3, 1, 1}, {3, 2, 2}, {2, 3, 2});
  // Patch 1 rational, with weights that are 1 on its interfaces (x = 1, 2).
  p1.weights.resize(p1.control_points.rows());
  for (int i = 0; i < p1.control_points.rows(); ++i) {
    const Eigen::Vector3d x = p1.control_points.row(i);
    p1.weights(i) = 1.0 + 0.4 * std::sin(kPi * (x(0) - 1.0)) * (0.5 + x(1) * x(2));
  }
  // Distort by a smooth field that vanishes on the outer faces, so the faces
  // stay planar, shared control points move together and interfaces match.
  auto distort = [](Patch& p) {
    for (int i = 0; i < p.control_points.rows(); ++i) {
      const Eigen::Vector3d x = p.control_points.row(i);
      const double s = std::sin(kPi * x(0) / 3.0) * std::sin(kPi * x(1)) * std::sin(kPi * x(2));
      p.control_points.row(i) += 0.08 * s * Eigen::RowVector3d(1.0, -0.7, 0.5);
    }
  };
  distort(p0);
  distort(p1);
  distort(p2);
  mp.patches = {p0, reorient(p1, {1, 2, 0}, {true, false, false}), reorient(p2, {2, 0, 1}, {false, true, true})};
  mp.patches[1].material = 0;
  mp.patches[2].material = 1;
  mp.materials = {{"steel", 1000.0, 0.3}, {"soft", 400.0, 0.25}};
  find_interfaces(mp);
  label_boundaries(mp, [](const Eigen::Vector3d& c) {
    if (std::abs(c(0)) < 1e-9) return std::string("x0");
    if (std::abs(c(0) - 3) < 1e-9) return std::string("x1");
    if (std::abs(c(1)) < 1e-9) return std::string("y0");
    if (std::abs(c(1) - 1) < 1e-9) return std::string("y1");
    if (std::abs(c(2)) < 1e-9) return std::string("z0");
    return std::string("z1");
  });
  return mp;
}

// Gauss points beyond p + 1. Exactness needs them: with distorted control
// points the integrand cof(J) grad_u R is a polynomial of degree 3p per
// direction (ceil((3p+1)/2) points), and on the rational patch it is rational,
// so the quadrature error falls exponentially (measured: 1.7e-4 with p + 1
// points, 2.9e-11 with p + 6, 1.2e-12 with p + 7).
const int kExtra = 6;

const char* kFaces[6] = {"x0", "x1", "y0", "y1", "z0", "z1"};
Eigen::Vector3d face_normal(int f) { return (f % 2 ? 1.0 : -1.0) * Eigen::Vector3d::Unit(f / 2); }

// The patch test needs one material: a linear field has constant stress only
// then (at a material interface the tractions would not balance).
void run_patch_test(const Eigen::Matrix3d& A, const std::vector<iga_check::FixedSide>& fixed, int elevate, int extra,
                    iga_check::LinearSolver solver = iga_check::LinearSolver::Automatic) {
  MultiPatch mp = distorted_box();
  ASSERT_EQ(mp.interfaces.size(), 2u);
  for (const auto& itf : mp.interfaces) {
    const bool identity = itf.dirmap == std::array<int, 3>{0, 1, 2} && itf.orient == std::array<int, 3>{1, 1, 1};
    EXPECT_FALSE(identity) << "interface " << itf.patch_a << "/" << itf.patch_b << " has the identity orientation";
  }
  ASSERT_EQ(mp.boundaries.size(), 14u);
  for (auto& p : mp.patches) p.material = 0;
  const auto lame = iga_check::lame_parameters(1000.0, 0.3);
  const Eigen::Matrix3d sigma = iga_check::isotropic_stress(lame, A);

  iga_check::ElasticityProblem problem;
  problem.fixed = fixed;
  for (int f = 0; f < 6; ++f) {
    bool all_fixed = false;
    for (const auto& fx : fixed)
      all_fixed |= fx.label == kFaces[f] && fx.components[0] && fx.components[1] && fx.components[2];
    if (!all_fixed) problem.tractions.push_back({kFaces[f], sigma * face_normal(f)});
  }
  iga_check::ElasticityOptions options;
  options.elevate = elevate;
  options.extra_quadrature = extra;
  options.solver = solver;
  options.cg_tolerance = 1e-14;  // iterative solvers: the field to 1e-9 needs it
  const auto sol = iga_check::solve_elasticity(mp, problem, options);
  EXPECT_GT(sol.report.unknowns, 0);

  double max_err = 0.0, max_u = 0.0;
  for (const auto& p : sol.model.patches)
    for (int i = 0; i < p.control_points.rows(); ++i) {
      const Eigen::Vector3d exact = A * p.control_points.row(i).transpose();
      max_err = std::max(max_err, (p.displacement.row(i).transpose() - exact).norm());
      max_u = std::max(max_u, exact.norm());
    }
  EXPECT_GT(max_u, 0.05);
  EXPECT_LT(max_err, 1e-9) << "largest coefficient error";
  // Stress at points inside every patch, and the strain energy 1/2 sigma:eps V (V = 3).
  for (int p = 0; p < 3; ++p)
    for (double t : {0.13, 0.5, 0.91}) {
      const auto pt = iga_check::evaluate_elasticity(sol.model, p, Eigen::Vector3d(t, 1 - t, 0.37));
      EXPECT_LT((pt.displacement - A * pt.x).norm(), 1e-9);
      EXPECT_LT((pt.stress - sigma).norm(), 1e-9 * sigma.norm()) << "patch " << p << " t " << t;
    }
  const double energy = 0.5 * sigma.cwiseProduct(0.5 * (A + A.transpose())).sum() * 3.0;
  EXPECT_NEAR(sol.report.strain_energy, energy, 1e-9 * energy);
  EXPECT_NEAR(sol.model.strain_energy, energy, 1e-9 * energy);
  EXPECT_TRUE(sol.model.has_solution);
}

}  // namespace

TEST(SolvePatchTest, ClampedFaceGeneralShear) {
  // u = x (a, b, c): zero on x = 0, so all of x0 is fixed; shear and stretch.
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  A.col(0) << 0.04, -0.03, 0.05;
  run_patch_test(A, {{"x0", {{true, true, true}}}}, 0, kExtra);
}

TEST(SolvePatchTest, RollerFacesTriaxialStretch) {
  // u = (a x, b y, c z): symmetry (roller) constraints on x0, y0, z0.
  Eigen::Matrix3d A = Eigen::Vector3d(0.03, -0.02, 0.045).asDiagonal();
  run_patch_test(A,
                 {{"x0", {{true, false, false}}}, {"y0", {{false, true, false}}}, {"z0", {{false, false, true}}}},
                 1, kExtra);
}

// Issue 22: the AMG-preconditioned CG reproduces the linear field as the
// direct solver does (roller faces: most components are unknowns).
TEST(SolvePatchTest, BoomerAmgReproducesTheTriaxialStretch) {
  Eigen::Matrix3d A = Eigen::Vector3d(0.03, -0.02, 0.045).asDiagonal();
  run_patch_test(A,
                 {{"x0", {{true, false, false}}}, {"y0", {{false, true, false}}}, {"z0", {{false, false, true}}}},
                 1, kExtra, iga_check::LinearSolver::Amg);
}

TEST(SolvePatchTest, BoomerAmgReproducesTheGeneralShear) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  A.col(0) << 0.04, -0.03, 0.05;
  run_patch_test(A, {{"x0", {{true, true, true}}}}, 0, kExtra, iga_check::LinearSolver::Amg);
}
