#include "elasticity_input.h"

#include <cmath>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check::detail {

namespace {

std::string label_list(const spline::MultiPatch& mp) {
  std::string s;
  for (size_t i = 0; i < mp.labels.size(); ++i) s += (i ? ", " : "") + mp.labels[i];
  return s.empty() ? "none" : s;
}

// Index of a label by name; bad_input naming the known labels otherwise.
int find_label(const spline::MultiPatch& mp, const std::string& name, const char* what) {
  for (size_t i = 0; i < mp.labels.size(); ++i)
    if (mp.labels[i] == name) return static_cast<int>(i);
  throw bad_input(std::string(what) + ": unknown label '" + name + "' (labels of the model: " + label_list(mp) + ")");
}

std::vector<LameParameters> check_materials(const spline::MultiPatch& mp) {
  std::vector<LameParameters> lame;
  for (size_t m = 0; m < mp.materials.size(); ++m)
    lame.push_back(lame_parameters(mp.materials[m].young_modulus, mp.materials[m].poisson_ratio,
                                   "material " + std::to_string(m) + " ('" + mp.materials[m].name + "')"));
  for (size_t p = 0; p < mp.patches.size(); ++p)
    if (mp.patches[p].material < 0 || mp.patches[p].material >= static_cast<int>(lame.size()))
      throw bad_input("patch " + std::to_string(p) + ": material index " + std::to_string(mp.patches[p].material) +
                      " has no entry in the model's materials");
  return lame;
}

void check_conditions(const spline::MultiPatch& mp, const ElasticityProblem& problem) {
  for (const auto& f : problem.fixed) {
    sides_with_label(mp, f.label, "fixed boundary");
    if (!f.components[0] && !f.components[1] && !f.components[2])
      throw bad_input("fixed boundary '" + f.label + "': no displacement component chosen");
  }
  for (const auto& pr : problem.prescribed) {
    sides_with_label(mp, pr.label, "prescribed displacement");
    if (!pr.displacement) throw bad_input("prescribed displacement on '" + pr.label + "': no function given");
  }
  for (const auto& t : problem.tractions) sides_with_label(mp, t.label, "traction load");
  for (const auto& t : problem.pressures) sides_with_label(mp, t.label, "pressure load");
}

void check_loads_finite(const ElasticityProblem& problem) {
  if (!problem.body_force.allFinite()) throw bad_input("the body force is not finite");
  for (const auto& t : problem.tractions)
    if (!t.traction.allFinite()) throw bad_input("traction on '" + t.label + "': not finite");
  for (const auto& t : problem.pressures)
    if (!std::isfinite(t.pressure)) throw bad_input("pressure on '" + t.label + "': not finite");
}

}  // namespace

// Interfaces glue control points by index: they must coincide, to the
// tolerance of the check's conformity criterion (criteria.h).
void check_interfaces_conform(const spline::MultiPatch& mp) {
  const double tol = CheckOptions{}.conformity_tolerance * model_diagonal(mp);
  const spline::ConformityReport c = spline::check_conformity(mp, tol);
  if (!c.conforming)
    throw bad_input("the model's interfaces do not conform (" + c.problems.front() +
                    "): a solve would glue control points that do not coincide; igaprep check names every such interface");
}

std::vector<spline::BoundarySide> sides_with_label(const spline::MultiPatch& mp, const std::string& name,
                                                   const char* what) {
  const int label = find_label(mp, name, what);
  std::vector<spline::BoundarySide> out;
  for (const auto& b : mp.boundaries)
    if (b.label == label) out.push_back(b);
  if (out.empty()) throw bad_input(std::string(what) + ": label '" + name + "' names no boundary side of the model");
  return out;
}

std::vector<LameParameters> check_elasticity_input(const spline::MultiPatch& mp, const ElasticityProblem& problem,
                                                   const ElasticityOptions& options) {
  spline::validate_multipatch(mp);
  if (mp.patches.empty()) throw bad_input("the model has no patches");
  if (options.extra_quadrature < 0 || options.extra_quadrature > 10)
    throw bad_input("extra quadrature points must lie in 0..10");
  std::vector<LameParameters> lame = check_materials(mp);
  check_interfaces_conform(mp);
  check_conditions(mp, problem);
  check_loads_finite(problem);
  return lame;
}

}  // namespace igaprep::iga_check::detail
