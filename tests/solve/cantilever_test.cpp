// Cantilever beam: a slender box L x h x h (L = 20 h) of two patches, clamped at x = 0, a
// uniform shear traction on x = L. The tip deflection must be within 1 % of
// Timoshenko beam theory after refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "igaprep/iga_check/elasticity_evaluate.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "solve_models.h"

using namespace igaprep;
using namespace solve_test;

namespace {

const double kL = 20.0, kH = 1.0, kE = 1000.0, kNu = 0.3, kQ = 0.1;  // kQ: traction (force per area)

MultiPatch cantilever(int elements_along, int elements_across) {
  MultiPatch mp;
  mp.patches = {box_patch({0, 0, 0}, {kL / 2, kH, kH}, {2, 2, 2}, {elements_along, elements_across, elements_across}),
                box_patch({kL / 2, 0, 0}, {kL, kH, kH}, {2, 2, 2}, {elements_along, elements_across, elements_across})};
  mp.materials = {{"steel", kE, kNu}};
  find_interfaces(mp);
  label_boundaries(mp, [](const Eigen::Vector3d& x) {
    if (std::abs(x(0)) < 1e-9) return std::string("clamp");
    if (std::abs(x(0) - kL) < 1e-9) return std::string("tip");
    return std::string("free");
  });
  return mp;
}

}  // namespace

TEST(SolveCantilever, TipDeflectionMatchesTimoshenko) {
  const double P = kQ * kH * kH, I = kH * kH * kH * kH / 12.0, A = kH * kH;
  const double G = kE / (2 * (1 + kNu)), kappa = 10 * (1 + kNu) / (12 + 11 * kNu);  // rectangle (Cowper)
  const double timoshenko = P * kL * kL * kL / (3 * kE * I) + P * kL / (kappa * G * A);

  iga_check::ElasticityProblem problem;
  problem.fixed = {{"clamp", {{true, true, true}}}};
  problem.tractions = {{"tip", Eigen::Vector3d(0, 0, -kQ)}};
  double previous = 0.0;
  for (int level : {1, 2}) {
    iga_check::ElasticityOptions options;
    options.elevate = 1;  // cubic
    options.refine = level;
    const auto sol = iga_check::solve_elasticity(cantilever(4, 1), problem, options);
    ASSERT_EQ(sol.model.interfaces.size(), 1u);
    // Deflection of the tip's centre (patch 1, u = 1, v = w = 1/2).
    const auto pt = iga_check::evaluate_elasticity(sol.model, 1, Eigen::Vector3d(1, 0.5, 0.5));
    EXPECT_NEAR(pt.x(0), kL, 1e-12);
    const double tip = -pt.displacement(2);
    std::printf("level %d: unknowns %lld, tip deflection %.6f, Timoshenko %.6f, deviation %.3f %%\n", level,
                sol.report.unknowns, tip, timoshenko, 100 * (tip / timoshenko - 1));
    // Work of the load equals twice the strain energy: P * (mean tip deflection) = 2 U.
    EXPECT_GT(sol.report.max_displacement, 0.99 * tip);
    if (level == 2) {
      EXPECT_NEAR(tip, timoshenko, 0.01 * timoshenko);
      EXPECT_GE(tip, previous * (1 - 1e-9)) << "a conforming refinement can only soften the model";
      EXPECT_NEAR(2 * sol.report.strain_energy / P, tip, 0.01 * tip);
    }
    previous = tip;
  }
}
