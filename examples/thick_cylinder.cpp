// A two-material thick cylinder built by hand on the public API, checked,
// solved and compared with Lame's closed form: a quarter of the cross
// section, one exact NURBS patch per material (steel inside aluminium),
// plane strain, internal pressure. Prints the errors at three refinements.
//
//   thick_cylinder            (exit 0 when the finest L2 error is below 1e-5)
#include <cmath>
#include <cstdio>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/elasticity_evaluate.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/multipatch.h"

using namespace igaprep;

namespace {

const double kInner = 1.0, kInterface = 1.4, kOuter = 2.0, kHeight = 0.5, kPressure = 10.0;
const spline::Material kSteel{"steel", 200e3, 0.3}, kAluminium{"aluminium", 70e3, 0.33};

// Quarter ring a < r < b, 0 <= z <= H: degree 2 everywhere, the 90-degree arc
// exact (weights 1, 1/sqrt 2, 1), u radial, v angular, w axial.
spline::Patch quarter_ring(double a, double b, int material) {
  spline::Patch p;
  p.degrees = {2, 2, 2};
  p.knots = {std::vector<double>{0, 0, 0, 1, 1, 1}, std::vector<double>{0, 0, 0, 1, 1, 1},
             std::vector<double>{0, 0, 0, 1, 1, 1}};
  p.material = material;
  p.control_points.resize(27, 3);
  p.weights.resize(27);
  const double corner[3][2] = {{1, 0}, {1, 1}, {0, 1}}, weight[3] = {1, std::sqrt(0.5), 1};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const double r = a + 0.5 * i * (b - a);  // Greville points: r is linear in u
        p.control_points.row(p.index(i, j, k)) << r * corner[j][0], r * corner[j][1], 0.5 * k * kHeight;
        p.weights(p.index(i, j, k)) = weight[j];
      }
  return p;
}

spline::MultiPatch cylinder() {
  spline::MultiPatch mp;
  mp.materials = {kSteel, kAluminium};
  mp.patches = {quarter_ring(kInner, kInterface, 0), quarter_ring(kInterface, kOuter, 1)};
  spline::find_interfaces(mp, 1e-12);
  mp.labels = {"inner", "outer", "y0", "x0", "z0", "z1"};
  mp.boundaries = {{0, spline::kU0, 0}, {1, spline::kU1, 1}};
  for (int p = 0; p < 2; ++p)
    for (const spline::Side side : {spline::kV0, spline::kV1, spline::kW0, spline::kW1})
      mp.boundaries.push_back({p, side, side.index() - 1});
  return mp;
}

// Lame, plane strain: in a ring a < r < b with pressure pi inside and po
// outside, u = A r + B / r with 2 (lambda + mu) A = (pi a^2 - po b^2) / (b^2 - a^2)
// and 2 mu B = (pi - po) a^2 b^2 / (b^2 - a^2). The interface pressure q makes
// both rings agree at the interface (u is linear in q).
struct Ring {
  double a, b, A = 0, B = 0;
  iga_check::LameParameters lame{};
  void load(double pi, double po) {
    const double d = b * b - a * a;
    A = (pi * a * a - po * b * b) / d / (2 * (lame.lambda + lame.mu));
    B = (pi - po) * a * a * b * b / d / (2 * lame.mu);
  }
  double u(double r) const { return A * r + B / r; }
};

struct Lame {
  Ring steel{kInner, kInterface}, aluminium{kInterface, kOuter};
  Lame() {
    steel.lame = iga_check::lame_parameters(kSteel.young_modulus, kSteel.poisson_ratio);
    aluminium.lame = iga_check::lame_parameters(kAluminium.young_modulus, kAluminium.poisson_ratio);
    auto gap = [&](double q) {
      steel.load(kPressure, q);
      aluminium.load(q, 0.0);
      return steel.u(kInterface) - aluminium.u(kInterface);
    };
    const double g0 = gap(0.0), g1 = gap(1.0);
    gap(-g0 / (g1 - g0));
  }
  const Ring& at(double r) const { return r < kInterface ? steel : aluminium; }
  Eigen::Vector3d displacement(const Eigen::Vector3d& x) const {
    const double r = std::hypot(x.x(), x.y());
    return Eigen::Vector3d(x.x(), x.y(), 0.0) * (at(r).u(r) / r);
  }
  // d u_i / d x_j of u = (u(r) / r) (x, y, 0): g(r) = A + B / r^2.
  Eigen::Matrix3d gradient(const Eigen::Vector3d& x) const {
    const double r2 = x.x() * x.x() + x.y() * x.y();
    const Ring& ring = at(std::sqrt(r2));
    const double g = ring.A + ring.B / r2, dg = -2 * ring.B / (r2 * r2);  // dg/dx_j = dg * x_j
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) G(i, j) = (i == j ? g : 0.0) + x(i) * dg * x(j);
    return G;
  }
};

}  // namespace

int main() {
  try {
    const spline::MultiPatch model = cylinder();
    const iga_check::CheckReport check = iga_check::build_check_report(model, {});
    std::printf("check: %s (%zu patches, %zu interface)\n", check.verdict.c_str(), model.patches.size(),
                model.interfaces.size());
    if (!check.passed) return 2;
    iga_check::ElasticityProblem problem;
    problem.fixed = {{"x0", {{true, false, false}}}, {"y0", {{false, true, false}}},
                     {"z0", {{false, false, true}}}, {"z1", {{false, false, true}}}};
    problem.pressures = {{"inner", kPressure}};
    const Lame exact;
    // Work of the pressure on the inner quarter face: the strain energy of the exact solution.
    const double energy = 0.5 * kPressure * exact.steel.u(kInner) * (0.5 * M_PI * kInner * kHeight);
    double l2 = 1.0;
    for (int refine = 1; refine <= 3; ++refine) {
      iga_check::ElasticityOptions options;
      options.refine = refine;
      const iga_check::ElasticitySolution s = iga_check::solve_elasticity(model, problem, options);
      const iga_check::ElasticityErrors e = iga_check::elasticity_errors(
          s.model, [&](const Eigen::Vector3d& x) { return exact.displacement(x); },
          [&](const Eigen::Vector3d& x) { return exact.gradient(x); });
      l2 = e.l2_error / e.l2_norm;
      std::printf("refine %d: %6lld unknowns, relative L2 error %.2e, energy error %.2e, strain energy %.8g "
                  "(Lame %.8g)\n",
                  refine, s.report.unknowns, l2, e.energy_error / e.energy_norm, s.report.strain_energy, energy);
    }
    return l2 < 1e-5 ? 0 : 2;
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return e.exit_code();
  }
}
