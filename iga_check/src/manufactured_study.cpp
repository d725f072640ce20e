#include "igaprep/iga_check/manufactured_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/elasticity_evaluate.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check {

namespace {

// An iterative solve's relative residual in the study: its error must lie
// far below the fine level's discretization error (1e-7 relative on the
// kitten's patches at refine 2), which the default 1e-8 does not give
// (docs/elasticity-solver.md, "Manufactured-solution study").
constexpr double kStudyResidual = 1e-11;

// One plane wave coef * s(w . xi + phase) in component `comp`.
enum class Wave { Sin, Cos, Exp };
struct Term {
  int comp;
  Wave kind;
  double coef;
  double w[3];
  double phase;
};
// Directions off the axes and wave numbers <= 3 over a unit diagonal: less
// than half a period across the model, smooth at every scale the fit uses.
const Term kTerms[] = {
    {0, Wave::Sin, 1.0, {2.1, 1.4, -0.9}, 0.3},  {0, Wave::Exp, 0.4, {0.7, -0.5, 0.6}, 0.0},
    {1, Wave::Cos, 1.0, {-1.2, 2.3, 1.1}, 0.5},  {1, Wave::Sin, 0.3, {1.7, 0.8, 2.0}, 1.2},
    {2, Wave::Sin, 1.0, {0.9, -1.5, 2.2}, 0.9},  {2, Wave::Exp, 0.4, {-0.6, 0.8, 0.5}, 0.0},
};

// s, s', s'' of a wave at theta.
void wave(Wave k, double t, double& s0, double& s1, double& s2) {
  switch (k) {
    case Wave::Sin: s0 = std::sin(t), s1 = std::cos(t), s2 = -s0; break;
    case Wave::Cos: s0 = std::cos(t), s1 = -std::sin(t), s2 = -s0; break;
    case Wave::Exp: s0 = s1 = s2 = std::exp(t); break;
  }
}

// Largest knot span relative to its parameter domain over every patch and direction.
double largest_span(const spline::MultiPatch& mp) {
  double h = 0.0;
  for (const auto& p : mp.patches)
    for (int d = 0; d < 3; ++d) {
      const auto& U = p.knots[d];
      const double len = U.back() - U.front();
      for (size_t i = 0; i + 1 < U.size(); ++i) h = std::max(h, (U[i + 1] - U[i]) / len);
    }
  return h;
}

}  // namespace

Eigen::Vector3d ManufacturedField::displacement(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d xi = (x - center) / length;
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  for (const Term& t : kTerms) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0;
    wave(t.kind, Eigen::Vector3d(t.w[0], t.w[1], t.w[2]).dot(xi) + t.phase, s0, s1, s2);
    u(t.comp) += t.coef * s0;
  }
  return amplitude * length * u;
}

Eigen::Matrix3d ManufacturedField::gradient(const Eigen::Vector3d& x) const {
  // d/dx = (1/length) d/dxi cancels the length factor of u.
  const Eigen::Vector3d xi = (x - center) / length;
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  for (const Term& t : kTerms) {
    const Eigen::Vector3d w(t.w[0], t.w[1], t.w[2]);
    double s0 = 0.0, s1 = 0.0, s2 = 0.0;
    wave(t.kind, w.dot(xi) + t.phase, s0, s1, s2);
    g.row(t.comp) += t.coef * s1 * w.transpose();
  }
  return amplitude * g;
}

std::array<Eigen::Matrix3d, 3> ManufacturedField::hessians(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d xi = (x - center) / length;
  std::array<Eigen::Matrix3d, 3> H;
  for (auto& h : H) h.setZero();
  for (const Term& t : kTerms) {
    const Eigen::Vector3d w(t.w[0], t.w[1], t.w[2]);
    double s0 = 0.0, s1 = 0.0, s2 = 0.0;
    wave(t.kind, w.dot(xi) + t.phase, s0, s1, s2);
    H[t.comp] += (amplitude / length * t.coef * s2) * (w * w.transpose());
  }
  return H;
}

Eigen::Vector3d ManufacturedField::body_force(const Eigen::Vector3d& x, const LameParameters& lame) const {
  const auto H = hessians(x);
  Eigen::Vector3d b;
  for (int i = 0; i < 3; ++i) {
    double grad_div = 0.0;  // d/dx_i (sum_j d u_j / d x_j)
    for (int j = 0; j < 3; ++j) grad_div += H[j](i, j);
    b(i) = -((lame.lambda + lame.mu) * grad_div + lame.mu * H[i].trace());
  }
  return b;
}

ManufacturedField manufactured_field(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double amplitude) {
  if (!lo.allFinite() || !hi.allFinite() || (hi - lo).minCoeff() < 0.0 || !((hi - lo).norm() > 0.0))
    throw bad_input("manufactured field: the bounding box is empty, a point or not finite");
  if (!(amplitude > 0.0) || !std::isfinite(amplitude))
    throw bad_input("manufactured field: the amplitude must be positive and finite");
  ManufacturedField f;
  f.center = 0.5 * (lo + hi);
  f.length = (hi - lo).norm();
  f.amplitude = amplitude;
  return f;
}

ManufacturedStudy manufactured_study(const spline::MultiPatch& model, const ManufacturedOptions& options) {
  spline::validate_multipatch(model);
  if (model.patches.empty()) throw bad_input("manufactured study: the model has no patches");
  if (options.coarse_refine < 0 || options.fine_refine <= options.coarse_refine || options.fine_refine > 8)
    throw bad_input("manufactured study: need 0 <= coarse refine < fine refine <= 8");

  // Every side must be on an interface or carry a label: an unlabelled outer
  // side would be traction free, which u_exact is not.
  std::set<std::pair<int, int>> covered;
  for (const auto& itf : model.interfaces) {
    covered.insert({itf.patch_a, itf.side_a});
    covered.insert({itf.patch_b, itf.side_b});
  }
  std::set<int> used_labels;
  for (const auto& b : model.boundaries) {
    covered.insert({b.patch, b.side});
    used_labels.insert(b.label);
  }
  for (int p = 0; p < static_cast<int>(model.patches.size()); ++p)
    for (const spline::Side s : spline::Side::all())
      if (!covered.count({p, s}))
        throw bad_input("manufactured study: patch " + std::to_string(p) + " side " + std::to_string(s) +
                        " is neither on an interface nor a labelled boundary side");
  if (used_labels.empty()) throw bad_input("manufactured study: the model has no labelled boundary sides");

  ManufacturedStudy study;
  study.box_min = study.box_max = model.patches[0].control_points.row(0).transpose();
  for (const auto& p : model.patches)
    for (Eigen::Index i = 0; i < p.control_points.rows(); ++i) {
      study.box_min = study.box_min.cwiseMin(p.control_points.row(i).transpose());
      study.box_max = study.box_max.cwiseMax(p.control_points.row(i).transpose());
    }
  study.field = manufactured_field(study.box_min, study.box_max, options.amplitude);

  // One material, E = 1, nu = 0.3.
  spline::MultiPatch mp = model;
  mp.materials = {{"manufactured", 1.0, 0.3}};
  for (auto& p : mp.patches) {
    p.material = 0;
    p.displacement.resize(0, 0);
  }
  mp.has_solution = false;
  const LameParameters lame = lame_parameters(1.0, 0.3);

  const ManufacturedField field = study.field;
  ElasticityProblem problem;
  for (int l : used_labels) {
    study.prescribed_labels.push_back(model.labels[l]);
    problem.prescribed.push_back({model.labels[l], [field](const Eigen::Vector3d& x) { return field.displacement(x); }});
  }
  problem.body_force_function = [field, lame](const Eigen::Vector3d& x) { return field.body_force(x, lame); };
  const DisplacementField exact = [field](const Eigen::Vector3d& x) { return field.displacement(x); };
  const DisplacementGradientField exact_gradient = [field](const Eigen::Vector3d& x) { return field.gradient(x); };

  Progress levels("manufactured solution, levels solved", 2, options.progress);
  for (int refine : {options.coarse_refine, options.fine_refine}) {
    const auto t0 = std::chrono::steady_clock::now();
    ElasticityOptions eo;
    eo.progress = options.progress;
    eo.refine = refine;
    eo.extra_quadrature = options.extra_quadrature;
    eo.solver = options.solver;
    eo.cg_tolerance = kStudyResidual;
    const ElasticitySolution sol = solve_elasticity(mp, problem, eo);
    const ElasticityErrors err = elasticity_errors(sol.model, exact, exact_gradient, options.extra_quadrature + 2);
    ManufacturedLevel L;
    L.refine = refine;
    L.elements = sol.report.elements;
    L.h = largest_span(sol.model);
    L.unknowns = sol.report.unknowns;
    L.prescribed_dofs = sol.report.prescribed_dofs;
    L.l2_error = err.l2_error;
    L.l2_norm = err.l2_norm;
    L.l2_relative = err.l2_norm > 0 ? err.l2_error / err.l2_norm : 0.0;
    L.energy_error = err.energy_error;
    L.energy_norm = err.energy_norm;
    L.energy_relative = err.energy_norm > 0 ? err.energy_error / err.energy_norm : 0.0;
    L.assembly_seconds = sol.report.assembly_seconds;
    L.solve_seconds = sol.report.solve_seconds;
    L.solver = sol.report.solver;
    L.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    study.levels.push_back(L);
    levels.update(study.levels.size());
  }
  levels.finish();
  const ManufacturedLevel &c = study.levels[0], &f = study.levels[1];
  study.h_ratio = c.h / f.h;
  const double lh = std::log(study.h_ratio);
  // A zero error (field reproduced) has no rate: report infinity rather than NaN.
  auto rate = [lh](double ec, double ef) {
    if (ef == 0.0) return ec == 0.0 ? 0.0 : INFINITY;
    return std::log(ec / ef) / lh;
  };
  study.l2_rate = rate(c.l2_error, f.l2_error);
  study.energy_rate = rate(c.energy_error, f.energy_error);
  return study;
}

}  // namespace igaprep::iga_check
