#include "elasticity_input.h"

#include <cmath>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/label_sides.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check::detail {

namespace {

// Index of a label by name; bad_input naming the known labels otherwise.
int find_label(const spline::MultiPatch& mp, const std::string& name, const char* what) {
  const int label = spline::label_index(mp, name);
  if (label < 0)
    throw bad_input(std::string(what) + ": unknown label '" + name + "' (labels of the model: " +
                    spline::label_list(mp) + ")");
  return label;
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
  for (const auto& f : problem.forces) {
    if (f.labels.empty()) throw bad_input("force load: no label given");
    for (const auto& l : f.labels) sides_with_label(mp, l, "force load");
  }
}

void check_loads_finite(const ElasticityProblem& problem) {
  if (!problem.body_force.allFinite()) throw bad_input("the body force is not finite");
  for (const auto& t : problem.tractions)
    if (!t.traction.allFinite()) throw bad_input("traction on '" + t.label + "': not finite");
  for (const auto& t : problem.pressures)
    if (!std::isfinite(t.pressure)) throw bad_input("pressure on '" + t.label + "': not finite");
  for (const auto& f : problem.forces)
    if (!f.force.allFinite()) throw bad_input("force on '" + f.labels.front() + "': not finite");
  if (const auto& r = problem.rotation) {
    if (!(std::isfinite(r->density) && r->density >= 0.0))
      throw bad_input("rotation: the density must be finite and not negative");
    if (!std::isfinite(r->angular_velocity)) throw bad_input("rotation: the angular velocity is not finite");
    if (!r->point.allFinite()) throw bad_input("rotation: the axis point is not finite");
    if (!(r->axis.allFinite() && r->axis.norm() > 0.0)) throw bad_input("rotation: the axis must be a non-zero vector");
  }
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

// What the solve cannot integrate: a degree-0 direction (no derivative, so
// no strain) and coordinates so large that the stiffness and the rigid-body
// test (cubes and squares of them) overflow. Said as such rather than as the
// singular system they would make.
void check_geometry_usable(const spline::MultiPatch& mp) {
  constexpr double kLargest = 1e100;
  for (std::size_t p = 0; p < mp.patches.size(); ++p) {
    const spline::Patch& patch = mp.patches[p];
    for (int d = 0; d < 3; ++d)
      if (patch.degrees[d] < 1)
        throw bad_input("patch " + std::to_string(p) + " has degree 0 in direction " + std::to_string(d) +
                        ": its displacement has no derivative there, so no strain; elevate its degree first");
    const double largest = patch.control_points.cwiseAbs().maxCoeff();
    if (!(largest <= kLargest)) {
      std::ostringstream s;
      s << "patch " << p << " has a control point coordinate of " << largest
        << ": beyond 1e100 the stiffness overflows; scale the model (and its loads) first";
      throw bad_input(s.str());
    }
  }
}

// Control points along one direction after degree elevation by `elevate`
// (each interior knot's multiplicity grows with it) and `refine` bisections
// of every knot span. Open knot vectors (end multiplicity p + 1).
double refined_count(const std::vector<double>& U, int p, int elevate, int refine) {
  const double spans = static_cast<double>(spline::unique_knots(U).size()) - 1.0;
  const double interior = static_cast<double>(U.size()) - 2.0 * (p + 1);  // summed multiplicities
  return (p + elevate + 1) + interior + (spans - 1.0) * elevate + spans * (std::pow(2.0, refine) - 1.0);
}

// The size of the refined problem, estimated before it is made.
void check_size(const spline::MultiPatch& mp, const ElasticityOptions& options) {
  double unknowns = 0.0;
  for (const spline::Patch& p : mp.patches) {
    double n = 3.0;
    for (int d = 0; d < 3; ++d) n *= refined_count(p.knots[d], p.degrees[d], options.elevate, options.refine);
    unknowns += n;
  }
  if (unknowns > static_cast<double>(options.max_unknowns)) {
    std::ostringstream s;
    s << "the refined model would have about " << std::llround(unknowns) << " unknowns (" << mp.patches.size()
      << " patches, elevate " << options.elevate << ", refine " << options.refine << "), more than the limit of "
      << options.max_unknowns << " (ElasticityOptions::max_unknowns); refine less, or raise the limit if the machine "
      << "has the memory";
    throw bad_input(s.str());
  }
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
  check_geometry_usable(mp);
  check_interfaces_conform(mp);
  check_size(mp, options);
  check_conditions(mp, problem);
  check_loads_finite(problem);
  return lame;
}

}  // namespace igaprep::iga_check::detail
