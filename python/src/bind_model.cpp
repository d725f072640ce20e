// Model and Patch: the multipatch model's data as numpy arrays, read and
// written as the HDF5 format, points and Jacobians evaluated on a patch.
#include <algorithm>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "convert.h"
#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::python {

namespace {

Eigen::MatrixXd parameters(const Eigen::MatrixXd& uvw) {
  if (uvw.cols() != 3) throw bad_input("parameters must have shape (N, 3): u, v, w in [0, 1]");
  if ((uvw.array() < 0.0).any() || (uvw.array() > 1.0).any()) throw bad_input("parameters must lie in [0, 1]");
  return uvw;
}

py::array_t<double> jacobians(const spline::Patch& p, const Eigen::MatrixXd& uvw) {
  const Eigen::MatrixXd x = parameters(uvw);
  py::array_t<double> out({static_cast<py::ssize_t>(x.rows()), py::ssize_t{3}, py::ssize_t{3}});
  auto m = out.mutable_unchecked<3>();
  for (Eigen::Index r = 0; r < x.rows(); ++r) {
    const Eigen::Matrix3d J = spline::evaluate_jacobian(p, x.row(r).transpose());
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(r, i, j) = J(i, j);
  }
  return out;
}

py::array_t<int> interfaces_array(const spline::MultiPatch& m) {
  py::array_t<int> a({static_cast<py::ssize_t>(m.interfaces.size()), py::ssize_t{10}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < m.interfaces.size(); ++i) {
    const auto& f = m.interfaces[i];
    const int row[10] = {f.patch_a,  f.side_a,    f.patch_b,   f.side_b,    f.dirmap[0],
                         f.dirmap[1], f.dirmap[2], f.orient[0], f.orient[1], f.orient[2]};
    for (int k = 0; k < 10; ++k) v(static_cast<py::ssize_t>(i), k) = row[k];
  }
  return a;
}

py::array_t<int> boundaries_array(const spline::MultiPatch& m) {
  py::array_t<int> a({static_cast<py::ssize_t>(m.boundaries.size()), py::ssize_t{3}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < m.boundaries.size(); ++i) {
    v(static_cast<py::ssize_t>(i), 0) = m.boundaries[i].patch;
    v(static_cast<py::ssize_t>(i), 1) = m.boundaries[i].side;
    v(static_cast<py::ssize_t>(i), 2) = m.boundaries[i].label;
  }
  return a;
}

py::list materials_list(const spline::MultiPatch& m) {
  py::list out;
  for (const auto& mat : m.materials)
    out.append(py::dict(py::arg("name") = mat.name, py::arg("young_modulus") = mat.young_modulus,
                        py::arg("poisson_ratio") = mat.poisson_ratio));
  return out;
}

// A patch from degrees, knot vectors and control points (n_w, n_v, n_u, 3);
// the knot vectors are validated.
spline::Patch make_patch(const std::array<int, 3>& degrees, const std::array<std::vector<double>, 3>& knots,
                         const py::array_t<double>& control_points, const py::object& weights, int material) {
  spline::Patch p;
  p.degrees = degrees;
  p.knots = knots;
  p.material = material;
  for (int d = 0; d < 3; ++d) {
    if (p.count(d) <= p.degrees[d]) throw bad_input("knots: too few for the degree in direction " + std::to_string(d));
    spline::validate_knot_vector(p.knots[d], p.degrees[d], p.count(d), "knots[" + std::to_string(d) + "]");
  }
  p.control_points.resize(p.count(0) * p.count(1) * p.count(2), 3);
  set_control_points(p, control_points);
  if (!weights.is_none()) {
    const auto w = weights.cast<py::array_t<double>>();
    if (w.ndim() != 3 || w.shape(0) != p.count(2) || w.shape(1) != p.count(1) || w.shape(2) != p.count(0))
      throw bad_input("weights must have shape (n_w, n_v, n_u)");
    p.weights.resize(p.control_points.rows());
    auto m = w.unchecked<3>();
    for (int k = 0; k < p.count(2); ++k)
      for (int j = 0; j < p.count(1); ++j)
        for (int i = 0; i < p.count(0); ++i) p.weights(p.index(i, j, k)) = m(k, j, i);
  }
  return p;
}

void bind_patch(py::module_& m) {
  py::class_<spline::Patch>(m, "Patch", "One trivariate B-spline or NURBS patch (sides 1..6: u0, u1, v0, v1, w0, w1).")
      .def_property_readonly("degrees", [](const spline::Patch& p) { return p.degrees; })
      .def_property_readonly("knots", [](const spline::Patch& p) {
        py::list out;
        for (const auto& k : p.knots) out.append(py::array_t<double>(static_cast<py::ssize_t>(k.size()), k.data()));
        return out;
      }, "full open knot vectors u, v, w")
      .def_property("control_points", &control_points_array, &set_control_points,
                    "(n_w, n_v, n_u, 3), Cartesian, as in the HDF5 format")
      .def_property_readonly("weights", &weights_array, "(n_w, n_v, n_u), or None for a B-spline patch")
      .def_readwrite("material", &spline::Patch::material)
      .def_property_readonly("displacement", [](const spline::Patch& p) -> py::object {
        if (p.displacement.rows() == 0) return py::none();
        return per_control_point(p, p.displacement);
      }, "(n_w, n_v, n_u, 3) coefficients of a solve's displacement, or None")
      .def("evaluate", [](const spline::Patch& p, const Eigen::MatrixXd& uvw) {
        return spline::evaluate_points(p, parameters(uvw));
      }, py::arg("uvw"), "points (N, 3) at parameters (N, 3) in [0, 1]^3")
      .def("jacobian", &jacobians, py::arg("uvw"), "Jacobian matrices (N, 3, 3), d(x, y, z)/d(u, v, w)");
}

void bind_multipatch(py::module_& m) {
  py::class_<spline::MultiPatch>(m, "Model", "A multipatch trivariate spline model (docs/hdf5-format.md).")
      .def_property_readonly("patches", [](py::object self) {
        auto& mp = self.cast<spline::MultiPatch&>();
        py::list out;
        for (auto& p : mp.patches) out.append(py::cast(&p, py::return_value_policy::reference_internal, self));
        return out;
      })
      .def_property_readonly("interfaces", &interfaces_array,
                             "(N, 10): patch_a, side_a, patch_b, side_b, dirmap[3], orient[3] (G+Smo)")
      .def_property_readonly("interface_surfaces", [](const spline::MultiPatch& mp) {
        std::vector<int> s;
        for (const auto& f : mp.interfaces) s.push_back(f.surface);
        return py::array_t<int>(static_cast<py::ssize_t>(s.size()), s.data());
      }, "index into labels of the surface each interface lies on, or -1")
      .def_property_readonly("boundaries", &boundaries_array, "(N, 3): patch, side, label")
      .def_readwrite("labels", &spline::MultiPatch::labels)
      .def_property_readonly("materials", &materials_list)
      .def_property_readonly("provenance", [](const spline::MultiPatch& mp) {
        return py::dict(py::arg("generator") = mp.provenance_generator, py::arg("case") = mp.provenance_case,
                        py::arg("inputs") = mp.provenance_inputs);
      })
      .def_readonly("strain_energy", &spline::MultiPatch::strain_energy)
      .def_readonly("max_displacement", &spline::MultiPatch::max_displacement)
      .def("__len__", [](const spline::MultiPatch& mp) { return mp.patches.size(); })
      .def(py::init<>())
      .def("add_patch", [](spline::MultiPatch& mp, const std::array<int, 3>& degrees,
                           const std::array<std::vector<double>, 3>& knots, const py::array_t<double>& control_points,
                           const py::object& weights, int material) {
        mp.patches.push_back(make_patch(degrees, knots, control_points, weights, material));
        return static_cast<int>(mp.patches.size()) - 1;
      }, py::arg("degrees"), py::arg("knots"), py::arg("control_points"), py::arg("weights") = py::none(),
         py::arg("material") = 0, "Adds a patch; returns its index.")
      .def("add_material", [](spline::MultiPatch& mp, const std::string& name, double e, double nu) {
        mp.materials.push_back({name, e, nu});
      }, py::arg("name"), py::arg("young_modulus"), py::arg("poisson_ratio"))
      .def("add_boundary", [](spline::MultiPatch& mp, int patch, int side, const std::string& label) {
        if (patch < 0 || patch >= static_cast<int>(mp.patches.size()) || side < 1 || side > 6)
          throw bad_input("add_boundary: patch " + std::to_string(patch) + ", side " + std::to_string(side) +
                          " does not exist (sides 1..6)");
        auto it = std::find(mp.labels.begin(), mp.labels.end(), label);
        if (it == mp.labels.end()) it = mp.labels.insert(mp.labels.end(), label);
        mp.boundaries.push_back({patch, side, static_cast<int>(it - mp.labels.begin())});
      }, py::arg("patch"), py::arg("side"), py::arg("label"), "Labels a patch side (1..6: u0, u1, v0, v1, w0, w1).")
      .def("find_interfaces", [](spline::MultiPatch& mp, double tol) { spline::find_interfaces(mp, tol); },
           py::arg("tol"), "Finds the interfaces between patches from their matching sides' control points.");
}

}  // namespace

void bind_model(py::module_& m) {
  bind_patch(m);
  bind_multipatch(m);
  m.def("read_model", &exporter::read_hdf5_model, py::arg("path"), py::call_guard<py::gil_scoped_release>(),
        "Reads a model (or a solve result) from an igaprep HDF5 file.");
  m.def("write_model",
        static_cast<void (*)(const spline::MultiPatch&, const std::string&)>(&exporter::write_hdf5_model),
        py::arg("model"), py::arg("path"),
        py::call_guard<py::gil_scoped_release>(), "Writes a model as an igaprep HDF5 file (atomically).");
}

}  // namespace igaprep::python
