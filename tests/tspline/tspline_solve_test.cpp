// Linear elasticity on T-splines in extraction form (issue 18): the patch
// test on a locally refined two-patch T-spline with T-junctions, the
// extraction solve against the multipatch solve on the same model, a
// manufactured solution's L2 rate, and the two-material thick cylinder
// (Lame) refined around its bore against uniform refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "igaprep/core/parallel.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/iga_check/extraction_solve.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/gauss_legendre.h"
#include "igaprep/spline/tspline_model.h"
#include "solve/lame_cylinder.h"
#include "solve/solve_models.h"

using namespace igaprep;
using namespace solve_test;

namespace {

// Two cubic boxes [0,1] and [1,2] x [0,1]^2 with their inner control points
// moved by a field that vanishes on the outer faces; every side "outer".
MultiPatch two_cubic_boxes() {
  MultiPatch mp;
  mp.patches = {box_patch({0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {4, 3, 3}), box_patch({1, 0, 0}, {2, 1, 1}, {3, 3, 3}, {4, 3, 3})};
  for (Patch& p : mp.patches)
    for (Eigen::Index i = 0; i < p.control_points.rows(); ++i) {
      const Eigen::Vector3d x = p.control_points.row(i);
      const double s = std::sin(kPi * x(0) / 2) * std::sin(kPi * x(1)) * std::sin(kPi * x(2));
      p.control_points.row(i) += 0.05 * s * Eigen::RowVector3d(1.0, -0.7, 0.5);
    }
  mp.patches[1] = reorient(mp.patches[1], {1, 2, 0}, {true, false, false});
  mp.materials = {{"steel", 1000.0, 0.3}};
  find_interfaces(mp);
  label_boundaries(mp, [](const Eigen::Vector3d&) { return std::string("outer"); });
  return mp;
}

TEST(TSplineSolve, PatchTestOnARefinedTSplineWithTJunctions) {
  spline::TSplineModel t = spline::tspline_model(two_cubic_boxes());
  ASSERT_GT(spline::refine_in_region(t, Eigen::AlignedBox3d(Eigen::Vector3d(0.6, -1, -1), Eigen::Vector3d(1.4, 0.5, 0.5)), 1), 0);
  const spline::ExtractionModel m = spline::extraction_model(t);
  ASSERT_GT(m.elements.size(), 2u * 4 * 3 * 3);
  const Eigen::Matrix3d A = (Eigen::Matrix3d() << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, -4e-4, 3e-4, 1.5e-3).finished();
  const Eigen::Vector3d b(1e-3, -2e-3, 5e-4);
  iga_check::ElasticityProblem problem;
  problem.prescribed = {{"outer", [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(A * x + b); }}};
  const iga_check::ExtractionSolution s = iga_check::solve_elasticity(m, problem);
  EXPECT_GT(s.report.unknowns, 0);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const Eigen::Vector3d tp(unit(rng), unit(rng), unit(rng));
    const Eigen::Vector3d x = spline::evaluate_element(m, static_cast<int>(e), tp);
    ASSERT_LT((iga_check::evaluate_solution(m, s.displacement, static_cast<int>(e), tp).x - x).norm(), 1e-12);
    const iga_check::ExtractionPointValue v = iga_check::evaluate_solution(m, s.displacement, static_cast<int>(e), tp);
    worst = std::max(worst, (v.displacement - (A * x + b)).norm());
    worst = std::max(worst, (v.gradient - A).norm());
  }
  EXPECT_LT(worst, 1e-10 * (A.norm() + b.norm()));
}

TEST(TSplineSolve, AgreesWithTheMultipatchSolveOnTheSameModel) {
  const MultiPatch mp = composite_cylinder(3, 2);
  const iga_check::ElasticitySolution reference = iga_check::solve_elasticity(mp, cylinder_problem());
  const iga_check::ExtractionSolution s = iga_check::solve_elasticity(spline::extraction_model(spline::tspline_model(mp)), cylinder_problem());
  EXPECT_EQ(s.report.unknowns, reference.report.unknowns);
  EXPECT_NEAR(s.report.strain_energy, reference.report.strain_energy, 1e-10 * reference.report.strain_energy);
  EXPECT_NEAR(s.report.max_displacement, reference.report.max_displacement, 1e-9 * reference.report.max_displacement);
  // The element matrices are computed on all cores and added in element
  // order: one thread gives the same numbers bit for bit.
  igaprep::set_thread_count(1);
  const iga_check::ExtractionSolution serial = iga_check::solve_elasticity(spline::extraction_model(spline::tspline_model(mp)), cylinder_problem());
  igaprep::set_thread_count(0);
  EXPECT_EQ(serial.report.strain_energy, s.report.strain_energy);
  EXPECT_EQ((serial.displacement - s.displacement).cwiseAbs().maxCoeff(), 0.0);
}

// The largest relative deviation of the hoop stress from Lame's over
// 3 x 3 x 1 points per element (the error of a stress converges like h^p,
// slower than the strain energy's h^(2p)).
double hoop_stress_deviation(const spline::ExtractionModel& m, const Eigen::MatrixXd& u) {
  const Lame ex = lame_solution();
  double worst = 0.0;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const int ring = m.elements[e].material;
    const iga_check::LameParameters lame = iga_check::lame_parameters(kE[ring], kNu[ring]);
    for (const double a : {0.0, 0.5, 1.0})
      for (const double b : {0.0, 0.5, 1.0}) {
        const iga_check::ExtractionPointValue v = iga_check::evaluate_solution(m, u, static_cast<int>(e), {a, b, 0.5});
        const double r = std::hypot(v.x(0), v.x(1));
        const Eigen::Vector3d et(-v.x(1) / r, v.x(0) / r, 0);
        const double stt = et.dot(iga_check::isotropic_stress(lame, v.gradient) * et);
        worst = std::max(worst, std::abs(stt - ex.stt(r, ring)) / std::abs(ex.stt(r, ring)));
      }
  }
  return worst;
}

struct CylinderRun {
  long long unknowns = 0;
  double deviation = 0.0, energy_error = 0.0;
};

CylinderRun cylinder_run(const spline::ExtractionModel& m) {
  const iga_check::ExtractionSolution s = iga_check::solve_elasticity(m, cylinder_problem());
  return {s.report.unknowns, hoop_stress_deviation(m, s.displacement),
          std::abs(s.report.strain_energy - cylinder_strain_energy()) / cylinder_strain_energy()};
}

// To 1e-4 in the hoop stress (the tolerance; the strain energy is
// within 1e-6 already on the coarsest mesh): the cylinder at level 1 (2 x 2
// elements per sector) with the elements within r < 1.25 refined 2 levels
// in u and v, against the uniform levels (the same solve on tensor
// meshes, equal to the multipatch solve: the test above).
TEST(TSplineSolve, CylinderRefinedAtTheBoreNeedsFewerUnknownsThanUniform) {
  const double tolerance = 1e-4;
  spline::TSplineModel t = spline::tspline_model(composite_cylinder(3, 1), {0, 1});
  spline::refine_in_region(t, Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1.25, 1.25, 1)), 2);
  const CylinderRun local = cylinder_run(spline::extraction_model(t));
  std::printf("T-spline: %lld unknowns, hoop stress deviation %.3e, strain energy error %.3e\n", local.unknowns,
              local.deviation, local.energy_error);
  EXPECT_LT(local.deviation, tolerance);
  CylinderRun uniform;
  int level = 1;
  for (; level <= 5; ++level) {
    uniform = cylinder_run(spline::extraction_model(spline::tspline_model(composite_cylinder(3, level))));
    std::printf("uniform level %d: %lld unknowns, hoop stress deviation %.3e, strain energy error %.3e\n", level,
                uniform.unknowns, uniform.deviation, uniform.energy_error);
    if (uniform.deviation < tolerance) break;
  }
  ASSERT_LT(uniform.deviation, tolerance);
  EXPECT_EQ(level, 3);
  EXPECT_LT(local.unknowns, uniform.unknowns);
}

// u_i = s = sin(pi x) sin(pi y) sin(pi z) for every component i on the unit
// cube (zero on its sides); b = -div sigma = 3 mu pi^2 s - (lambda + mu) grad(div u).
struct Manufactured {
  iga_check::LameParameters lame = iga_check::lame_parameters(1000.0, 0.3);
  static double s(const Eigen::Vector3d& x) { return std::sin(kPi * x(0)) * std::sin(kPi * x(1)) * std::sin(kPi * x(2)); }
  Eigen::Vector3d body(const Eigen::Vector3d& x) const {
    Eigen::Array3d sn, cs;
    for (int d = 0; d < 3; ++d) sn[d] = std::sin(kPi * x(d)), cs[d] = std::cos(kPi * x(d));
    Eigen::Vector3d b;
    for (int i = 0; i < 3; ++i) {
      double grad_div = -kPi * kPi * s(x);
      for (int j = 0; j < 3; ++j)
        if (j != i) grad_div += kPi * kPi * cs[i] * cs[j] * sn[3 - i - j];
      b[i] = 3 * lame.mu * kPi * kPi * s(x) - (lame.lambda + lame.mu) * grad_div;
    }
    return b;
  }
};

// The L2 error of the T-spline solution on the unit cube with 2^k elements
// per direction and the corner x, y, z < 1/2 refined once more (T-junctions).
double manufactured_l2_error(int k) {
  MultiPatch mp;
  mp.patches = {box_patch({0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {1 << k, 1 << k, 1 << k})};
  mp.materials = {{"steel", 1000.0, 0.3}};
  label_boundaries(mp, [](const Eigen::Vector3d&) { return std::string("outer"); });
  spline::TSplineModel t = spline::tspline_model(mp);
  spline::refine_in_region(t, Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(0.5, 0.5, 0.5)), 1);
  const spline::ExtractionModel m = spline::extraction_model(t);
  const Manufactured exact;
  iga_check::ElasticityProblem problem;
  problem.fixed = {{"outer"}};
  problem.body_force_function = [&](const Eigen::Vector3d& x) { return exact.body(x); };
  const iga_check::ExtractionSolution sol = iga_check::solve_elasticity(m, problem);
  Eigen::VectorXd g, w;
  spline::gauss_legendre(5, g, w);
  double error = 0.0;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const auto& dom = m.elements[e].domain;
    const double volume = (dom[0][1] - dom[0][0]) * (dom[1][1] - dom[1][0]) * (dom[2][1] - dom[2][0]);  // the identity map
    for (int a = 0; a < 5; ++a)
      for (int b = 0; b < 5; ++b)
        for (int c = 0; c < 5; ++c) {
          const iga_check::ExtractionPointValue v = iga_check::evaluate_solution(m, sol.displacement, static_cast<int>(e), {g[a], g[b], g[c]});
          error += w[a] * w[b] * w[c] * volume * (v.displacement - Eigen::Vector3d::Constant(Manufactured::s(v.x))).squaredNorm();
        }
  }
  return std::sqrt(error);
}

TEST(TSplineSolve, ManufacturedSolutionConvergesAtTheOptimalL2Rate) {
  const double coarse = manufactured_l2_error(2), fine = manufactured_l2_error(3);
  const double rate = std::log2(coarse / fine);
  std::printf("L2 error %.3e -> %.3e, rate %.2f\n", coarse, fine, rate);
  EXPECT_GT(rate, 3.5);  // p + 0.5 for cubics
}

}  // namespace
