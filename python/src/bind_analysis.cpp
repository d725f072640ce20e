// The elasticity solve on a model's labelled sides, refinement for analysis,
// and export to other formats.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "convert.h"
#include "igaprep/core/error.h"
#include "igaprep/export/export_model.h"
#include "igaprep/iga_check/elasticity_refine.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/pipeline/reduce.h"

#include <optional>

namespace igaprep::python {

namespace {

// fix: a label, a list of labels, or a dict label -> components ("xyz", "xz", ...).
std::vector<iga_check::FixedSide> fixed_sides(const py::object& fix) {
  std::vector<iga_check::FixedSide> out;
  auto add = [&](const std::string& label, const std::string& components) {
    iga_check::FixedSide f{label, {{false, false, false}}};
    for (char c : components) {
      if (c < 'x' || c > 'z') throw bad_input("fix['" + label + "']: components must be letters of 'xyz'");
      f.components[c - 'x'] = true;
    }
    out.push_back(f);
  };
  if (fix.is_none()) return out;
  if (py::isinstance<py::str>(fix)) add(fix.cast<std::string>(), "xyz");
  else if (py::isinstance<py::dict>(fix))
    for (auto [k, v] : fix.cast<py::dict>()) add(k.cast<std::string>(), v.cast<std::string>());
  else
    for (auto l : fix) add(l.cast<std::string>(), "xyz");
  return out;
}

// rotation: None, or {"density", "angular_velocity", "axis" (default z), "point" (default the origin)}.
std::optional<iga_check::RotationLoad> rotation_load(const py::object& rotation) {
  if (rotation.is_none()) return std::nullopt;
  const py::dict d = rotation.cast<py::dict>();
  iga_check::RotationLoad r;
  for (auto [k, v] : d) {
    const std::string key = k.cast<std::string>();
    if (key == "density") r.density = v.cast<double>();
    else if (key == "angular_velocity") r.angular_velocity = v.cast<double>();
    else if (key == "axis") r.axis = v.cast<Eigen::Vector3d>();
    else if (key == "point") r.point = v.cast<Eigen::Vector3d>();
    else throw bad_input("rotation: unknown key '" + key + "' (density, angular_velocity, axis, point)");
  }
  if (!d.contains("density") || !d.contains("angular_velocity"))
    throw bad_input("rotation: needs 'density' and 'angular_velocity'");
  return r;
}

py::dict solve(const spline::MultiPatch& model, const py::object& fix, const std::map<std::string, double>& pressure,
               const std::map<std::string, Eigen::Vector3d>& traction, const std::map<std::string, Eigen::Vector3d>& force,
               const Eigen::Vector3d& body_force, const py::object& rotation, int refine, const std::string& solver) {
  iga_check::ElasticityProblem problem;
  problem.fixed = fixed_sides(fix);
  for (const auto& [label, p] : pressure) problem.pressures.push_back({label, p});
  for (const auto& [label, t] : traction) problem.tractions.push_back({label, t});
  for (const auto& [label, f] : force) problem.forces.push_back({{label}, f});
  problem.body_force = body_force;
  problem.rotation = rotation_load(rotation);
  iga_check::ElasticityOptions options;
  options.refine = refine;
  options.solver = iga_check::linear_solver_named(solver);
  iga_check::ElasticitySolution s;
  {
    py::gil_scoped_release release;
    s = iga_check::solve_elasticity(model, problem, options);
  }
  py::list displacements;
  for (const auto& p : s.model.patches) displacements.append(per_control_point(p, p.displacement));
  return py::dict(py::arg("displacements") = displacements, py::arg("strain_energy") = s.report.strain_energy,
                  py::arg("max_displacement") = s.report.max_displacement, py::arg("unknowns") = s.report.unknowns,
                  py::arg("solver") = s.report.solver, py::arg("model") = py::cast(std::move(s.model)));
}

// Data reduction guarded by the model's own certificates (no surfaces).
py::tuple reduce(const spline::MultiPatch& model, double tolerance, double relative_tolerance) {
  pipeline::ReduceSettings settings;
  settings.tolerance = tolerance;
  settings.relative_tolerance = relative_tolerance;
  pipeline::CheckedReduction r;
  {
    py::gil_scoped_release release;
    pipeline::Observer quiet;
    r = pipeline::reduce_checked(model, settings, {}, {}, quiet);
  }
  const pipeline::ReduceFigures& f = r.reduction.figures;
  py::dict figures(py::arg("tolerance") = f.tolerance, py::arg("bound") = f.bound, py::arg("measured") = f.measured,
                   py::arg("control_points_before") = f.control_points_before,
                   py::arg("control_points_after") = f.control_points_after,
                   py::arg("elements_before") = f.elements_before, py::arg("elements_after") = f.elements_after,
                   py::arg("knots_removed") = f.knots_removed, py::arg("removals_undone") = f.removals_undone,
                   py::arg("passed") = r.reduced.report.passed);
  return py::make_tuple(py::cast(std::move(r.reduction.model)), figures);
}

std::vector<std::string> export_formats(const spline::MultiPatch& model, const std::vector<std::string>& formats,
                                        const std::string& base) {
  std::vector<exporter::Format> list;
  for (const auto& f : formats)
    for (exporter::Format x : exporter::parse_formats(f)) list.push_back(x);
  py::gil_scoped_release release;
  return exporter::export_model(model, base, list);
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("solve", &solve, py::arg("model"), py::arg("fix") = py::none(),
        py::arg("pressure") = std::map<std::string, double>{},
        py::arg("traction") = std::map<std::string, Eigen::Vector3d>{},
        py::arg("force") = std::map<std::string, Eigen::Vector3d>{},
        py::arg("body_force") = Eigen::Vector3d::Zero().eval(), py::arg("rotation") = py::none(),
        py::arg("refine") = 0, py::arg("solver") = "auto",
        "Linear elasticity on the model with its materials. fix: labels (all components) or {label: 'xz'};\n"
        "pressure: {label: p}; traction: {label: (tx, ty, tz)}; force: {label: (Fx, Fy, Fz)}, a total force\n"
        "spread over the label's sides; body_force per volume; rotation: {'density', 'angular_velocity',\n"
        "'axis', 'point'}, the centrifugal body force of a steady spin. Returns a dict with\n"
        "displacements (one (n_w, n_v, n_u, 3) array per patch of the refined model), strain_energy,\n"
        "max_displacement, unknowns, solver and the refined model carrying the displacement.");
  m.def("refine", &iga_check::refine_for_analysis, py::arg("model"), py::arg("elevate") = 0, py::arg("refine") = 1,
        py::call_guard<py::gil_scoped_release>(),
        "Degree elevation by `elevate`, then `refine` uniform bisections of every knot span (same geometry).");
  m.def("reduce", &reduce, py::arg("model"), py::arg("tolerance") = 0.0, py::arg("relative_tolerance") = 0.0,
        "Data reduction (docs/spline.md): knots removed per family while no point moves farther than `tolerance`\n"
        "(model units) or `relative_tolerance` (of the diagonal), give one; no element the model's check certified\n"
        "loses its certificate. Returns (reduced model, figures: tolerance, bound, measured, control points and\n"
        "elements before and after, knots_removed, removals_undone, passed = the reduced model's check).");
  m.def("export", &export_formats, py::arg("model"), py::arg("formats"), py::arg("base"),
        "Writes the model as base + .h5/.xml/.mesh/.vtu/.bext for formats hdf5, gismo, mfem, vtu, bext; returns the paths.");
}

}  // namespace igaprep::python
