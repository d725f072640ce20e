// Surfaces in and out, the pipeline's run on a case, and the check.
#include <filesystem>

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "convert.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/models/builtin_models.h"
#include "igaprep/pipeline/run.h"

namespace igaprep::python {

namespace {

// Stage summaries go to a Python callable, with the GIL held while it runs.
class CallbackObserver : public pipeline::Observer {
 public:
  explicit CallbackObserver(py::object on_stage) : on_stage_(std::move(on_stage)) {}
  void stage_finished(const pipeline::StageSummary& s) override {
    if (on_stage_.is_none()) return;
    py::gil_scoped_acquire gil;
    on_stage_(py::dict(py::arg("stage") = s.stage, py::arg("seconds") = s.seconds, py::arg("headline") = s.headline,
                       py::arg("details") = s.details));
  }

 private:
  py::object on_stage_;
};

// A case from a path, a dict (relative paths against `folder`, default the
// working folder) or None (the built-in default model).
pipeline::Case case_of(const py::object& c, const std::string& folder) {
  if (c.is_none()) return pipeline::builtin_case(models::default_model_name());
  if (py::isinstance<py::dict>(c))
    return pipeline::parse_case(python_to_json(c), folder.empty() ? std::filesystem::current_path().string() : folder,
                                "case dict");
  return pipeline::read_case(py::str(c).cast<std::string>());
}

// report.json (of a report without a pipeline section) as Python objects,
// with the check's verdict at the top as "passed".
py::dict check_report_dict(const iga_check::CheckReport& r) {
  py::dict d = json_to_python(iga_check::report_json(r));
  d["passed"] = r.passed;
  return d;
}

py::tuple run(const py::object& c, const std::string& folder, const std::string& output_dir, bool write_outputs,
              const py::object& on_stage) {
  const pipeline::Case the_case = case_of(c, folder);
  CallbackObserver observer(on_stage);
  pipeline::RunOptions options;
  options.output_dir = output_dir;
  options.write_outputs = write_outputs;
  pipeline::RunResult r;
  {
    py::gil_scoped_release release;
    r = pipeline::run(the_case, observer, options);
  }
  // report.json once; its pipeline section goes beside the check's part.
  py::dict check = json_to_python(iga_check::report_json(r.report));
  py::dict report;
  report["passed"] = r.passed;
  report["pipeline"] = check.attr("pop")("pipeline");
  check["passed"] = r.report.passed;
  report["check"] = check;
  report["output_dir"] = write_outputs ? py::object(py::str(r.output_dir)) : py::object(py::none());
  if (r.load_case)
    report["load_case"] = py::dict(py::arg("unknowns") = r.load_case->unknowns,
                                   py::arg("strain_energy") = r.load_case->strain_energy,
                                   py::arg("max_displacement") = r.load_case->max_displacement);
  return py::make_tuple(py::cast(std::move(r.model)), report);
}

mesh::TriMesh tri_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  if (V.cols() != 3 || F.cols() != 3) throw bad_input("a surface is V (N, 3) and F (M, 3)");
  return {V, F};
}

py::dict check(const spline::MultiPatch& model, const std::vector<std::pair<Eigen::MatrixXd, Eigen::MatrixXi>>& surfaces,
               bool allow_degenerate, double fidelity_limit, double volume_limit) {
  std::vector<mesh::TriMesh> meshes;
  for (const auto& [V, F] : surfaces) meshes.push_back(tri_mesh(V, F));
  iga_check::CheckOptions options;
  options.allow_degenerate = allow_degenerate;
  options.fidelity_limit = fidelity_limit / 100.0;
  options.volume_limit = volume_limit / 100.0;
  iga_check::CheckReport r;
  {
    py::gil_scoped_release release;
    r = iga_check::build_check_report(model, meshes, model.labels, options, "model");
  }
  return check_report_dict(r);
}

py::dict surface_report(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& name) {
  const mesh::TriMesh m = tri_mesh(V, F);
  const mesh::SurfaceReport r = mesh::check_surface(m, name);
  return py::dict(py::arg("ok") = r.ok(), py::arg("errors") = r.errors, py::arg("vertices") = r.vertices,
                  py::arg("faces") = r.faces, py::arg("genus") = r.genus, py::arg("volume") = r.volume,
                  py::arg("text") = mesh::format_report(r));
}

}  // namespace

void bind_pipeline(py::module_& m) {
  m.def("read_surface", [](const std::string& path) {
    const mesh::TriMesh t = mesh::read_surface(path);
    return py::make_tuple(t.V, t.F);
  }, py::arg("path"), "Reads a closed triangle surface (STL, OBJ, OFF, PLY): (V (N, 3), F (M, 3)).");
  m.def("check_surface", &surface_report, py::arg("V"), py::arg("F"), py::arg("name") = "surface",
        "Validates a surface: a dict with ok, errors, vertices, faces, genus, volume and the text report.");
  m.def("run", &run, py::arg("case") = py::none(), py::arg("folder") = "", py::arg("output_dir") = "",
        py::arg("write_outputs") = true, py::arg("on_stage") = py::none(),
        "Runs the pipeline on a case (a case file's path, a dict as in docs/case-format.md, or None for the\n"
        "built-in default model) and returns (model, report). report['passed'] is the run's verdict,\n"
        "report['check'] the check's report.json, report['pipeline'] the run's figures. on_stage(dict) is\n"
        "called after each stage.");
  m.def("check", &check, py::arg("model"), py::arg("surfaces") = std::vector<std::pair<Eigen::MatrixXd, Eigen::MatrixXi>>{},
        py::arg("allow_degenerate") = false, py::arg("fidelity_limit") = 100.0 * iga_check::CheckOptions{}.fidelity_limit,
        py::arg("volume_limit") = 100.0 * iga_check::CheckOptions{}.volume_limit,
        "Certified Jacobians, quality, fidelity (to the surfaces (V, F), outermost first) and topology;\n"
        "report.json as a dict with 'passed' at the top. The limits are in percent (of the outer surface's\n"
        "diagonal, of each material's volume); summary['criteria'] says which criterion failed and where.");
}

}  // namespace igaprep::python
