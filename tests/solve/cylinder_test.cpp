// Composite thick-walled cylinder in plane strain against Lame's closed form:
// two rings of different materials (a < r < b, b < r < c), each a quarter
// cross-section in two exact NURBS sectors (four patches), extruded in z;
// symmetry on x = 0 and y = 0, u_z = 0 on both z faces (plane strain),
// internal pressure P at r = a.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/elasticity_evaluate.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "lame_cylinder.h"
#include "solve_models.h"

using namespace igaprep;
using namespace solve_test;

namespace {

struct Deviation {
  double ur = 0, srr = 0, stt = 0, szz = 0;
};

Deviation compare(const iga_check::ElasticitySolution& sol, const Lame& ex) {
  Deviation dev;
  for (int p = 0; p < 4; ++p)
    for (double s : {0.0, 0.1, 0.5, 0.9, 1.0})
      for (double t : {0.0, 0.3, 0.7, 1.0}) {
        const auto pt = iga_check::evaluate_elasticity(sol.model, p, Eigen::Vector3d(s, t, 0.5));
        const double r = std::hypot(pt.x(0), pt.x(1));
        const Eigen::Vector3d er(pt.x(0) / r, pt.x(1) / r, 0), et(-er(1), er(0), 0);
        // Which side of r = b a point on the interface belongs to: its patch's material.
        const int ring = sol.model.patches[p].material;
        EXPECT_EQ(ring, ex.ring(r < kb + 1e-12 && r > kb - 1e-12 ? (ring == 0 ? kb - 1 : kb + 1) : r));
        dev.ur = std::max(dev.ur, std::abs(pt.displacement.dot(er) - ex.ur(r, ring)) / std::abs(ex.ur(r, ring)));
        dev.srr = std::max(dev.srr, std::abs(er.dot(pt.stress * er) - ex.srr(r, ring)) / kP);
        dev.stt = std::max(dev.stt, std::abs(et.dot(pt.stress * et) - ex.stt(r, ring)) / std::abs(ex.stt(r, ring)));
        dev.szz = std::max(dev.szz, std::abs(pt.stress(2, 2) - ex.szz(ring)) / std::abs(ex.szz(ring)));
        EXPECT_LT(std::abs(pt.displacement(2)), 1e-12);
        EXPECT_LT(std::abs(pt.displacement.dot(et)), 1e-5 * std::abs(ex.ur(r, ring)));
      }
  return dev;
}

}  // namespace

TEST(SolveCylinder, TwoMaterialPlaneStrainMatchesLame) {
  const Lame ex = lame_solution();
  // Sanity of the closed form: the interface conditions hold.
  EXPECT_NEAR(ex.ur(kb, 0), ex.ur(kb, 1), 1e-14);
  EXPECT_NEAR(ex.srr(kb, 0), ex.srr(kb, 1), 1e-13);
  EXPECT_NEAR(ex.srr(ka, 0), -kP, 1e-13);
  EXPECT_NEAR(ex.srr(kc, 1), 0.0, 1e-13);

  Deviation coarse;
  for (int level : {1, 4}) {
    MultiPatch mp = composite_cylinder(3, level);
    ASSERT_EQ(mp.patches.size(), 4u);
    ASSERT_EQ(mp.interfaces.size(), 4u);  // two angular, two radial (r = b)
    const auto sol = iga_check::solve_elasticity(mp, cylinder_problem());
    const Deviation d = compare(sol, ex);
    std::printf("level %d: unknowns %lld, relative deviation u_r %.2e sigma_rr %.2e sigma_tt %.2e sigma_zz %.2e\n",
                level, sol.report.unknowns, d.ur, d.srr, d.stt, d.szz);
    if (level == 1) {
      coarse = d;
      continue;
    }
    EXPECT_LT(d.ur, 1e-3);
    EXPECT_LT(d.srr, 1e-3);
    EXPECT_LT(d.stt, 1e-3);
    EXPECT_LT(d.szz, 1e-3);
    EXPECT_LT(d.stt, coarse.stt) << "refinement must reduce the hoop-stress error";
    // The strain energy equals the work of the pressure: 1/2 P u_r(a) * (pi/2) a H.
    const double work = 0.5 * kP * ex.ur(ka, 0) * kPi / 2 * ka * kH;
    EXPECT_NEAR(sol.report.strain_energy, work, 1e-4 * work);
  }
}

// Issue 22: the AMG-preconditioned CG and the direct solver on the composite
// cylinder refined in every direction (two materials, symmetry rollers, four
// patches with reoriented interfaces): the same strain energy and field.
TEST(SolveCylinder, BoomerAmgAgreesWithCholesky) {
  iga_check::ElasticityOptions options;
  options.refine = 2;
  options.cg_tolerance = 1e-12;
  options.solver = iga_check::LinearSolver::Cholesky;
  const auto direct = iga_check::solve_elasticity(composite_cylinder(3, 1), cylinder_problem(), options);
  options.solver = iga_check::LinearSolver::Amg;
  const auto amg = iga_check::solve_elasticity(composite_cylinder(3, 1), cylinder_problem(), options);
  EXPECT_EQ(amg.report.solver, "boomeramg-pcg");
  EXPECT_EQ(amg.report.unknowns, direct.report.unknowns);
  EXPECT_GT(amg.report.cg_iterations, 0);
  EXPECT_LT(amg.report.cg_residual, 1.25e-12);
  std::printf("unknowns %lld: BoomerAMG %d iterations, energy %.15g (Cholesky %.15g)\n", amg.report.unknowns,
              amg.report.cg_iterations, amg.report.strain_energy, direct.report.strain_energy);
  EXPECT_NEAR(amg.report.strain_energy, direct.report.strain_energy, 1e-10 * direct.report.strain_energy);
  double diff = 0.0;
  for (std::size_t p = 0; p < 4; ++p)
    diff = std::max(diff, (amg.model.patches[p].displacement - direct.model.patches[p].displacement).cwiseAbs().maxCoeff());
  EXPECT_LT(diff, 1e-8 * direct.report.max_displacement);
  const double work = cylinder_strain_energy();
  EXPECT_NEAR(amg.report.strain_energy, work, 1e-4 * work);
}

// Automatic: the direct solver up to direct_max_unknowns and a factor of
// direct_max_factor_bytes (predicted by CHOLMOD's analysis), AMG above.
TEST(SolveCylinder, AutomaticChoiceBySize) {
  iga_check::ElasticityOptions options;
  options.refine = 1;
  const auto small = iga_check::solve_elasticity(composite_cylinder(3, 1), cylinder_problem(), options);
  EXPECT_EQ(small.report.solver, "cholmod");
  // The factor holds at least K's lower triangle and at most a dense one.
  const double n = static_cast<double>(small.report.unknowns);
  EXPECT_GE(small.report.factor_entries, static_cast<double>(small.report.nonzeros));
  EXPECT_LE(small.report.factor_entries, n * (n + 1) / 2);
  options.direct_max_unknowns = small.report.unknowns - 1;
  const auto large = iga_check::solve_elasticity(composite_cylinder(3, 1), cylinder_problem(), options);
  EXPECT_EQ(large.report.solver, "boomeramg-pcg");
  EXPECT_NEAR(large.report.strain_energy, small.report.strain_energy, 1e-8 * small.report.strain_energy);

  options.direct_max_unknowns = small.report.unknowns;
  options.direct_max_factor_bytes = 8.0 * small.report.factor_entries;
  EXPECT_EQ(iga_check::solve_elasticity(composite_cylinder(3, 1), cylinder_problem(), options).report.solver, "cholmod");
  options.direct_max_factor_bytes = 8.0 * small.report.factor_entries - 1.0;
  const auto wide = iga_check::solve_elasticity(composite_cylinder(3, 1), cylinder_problem(), options);
  EXPECT_EQ(wide.report.solver, "boomeramg-pcg");
  EXPECT_EQ(wide.report.factor_entries, small.report.factor_entries);
  EXPECT_NEAR(wide.report.strain_energy, small.report.strain_energy, 1e-8 * small.report.strain_energy);
}

// An iteration limit too small for the tolerance is an error naming the
// true residual, never an answer.
TEST(SolveCylinder, BoomerAmgThatDoesNotConvergeIsAnError) {
  iga_check::ElasticityOptions options;
  options.refine = 1;
  options.solver = iga_check::LinearSolver::Amg;
  options.cg_max_iterations = 2;
  try {
    iga_check::solve_elasticity(composite_cylinder(3, 1), cylinder_problem(), options);
    ADD_FAILURE() << "two iterations reached the relative residual 1e-8";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::Internal);
    EXPECT_NE(std::string(e.what()).find("did not converge in 2 iterations (relative residual"), std::string::npos) << e.what();
  }
}
