#include "convert.h"

#include "igaprep/core/error.h"

namespace igaprep::python {

py::array_t<double> per_control_point(const spline::Patch& p, const Eigen::MatrixXd& rows) {
  const py::ssize_t nu = p.count(0), nv = p.count(1), nw = p.count(2);
  py::array_t<double> a({nw, nv, nu, py::ssize_t{3}});
  auto m = a.mutable_unchecked<4>();
  for (py::ssize_t k = 0; k < nw; ++k)
    for (py::ssize_t j = 0; j < nv; ++j)
      for (py::ssize_t i = 0; i < nu; ++i)
        for (int d = 0; d < 3; ++d) m(k, j, i, d) = rows(p.index(int(i), int(j), int(k)), d);
  return a;
}

py::array_t<double> control_points_array(const spline::Patch& p) { return per_control_point(p, p.control_points); }

void set_control_points(spline::Patch& p, const py::array_t<double>& a) {
  const py::ssize_t nu = p.count(0), nv = p.count(1), nw = p.count(2);
  if (a.ndim() != 4 || a.shape(0) != nw || a.shape(1) != nv || a.shape(2) != nu || a.shape(3) != 3)
    throw bad_input("control_points must have shape (" + std::to_string(nw) + ", " + std::to_string(nv) + ", " +
                    std::to_string(nu) + ", 3)");
  auto m = a.unchecked<4>();
  for (py::ssize_t k = 0; k < nw; ++k)
    for (py::ssize_t j = 0; j < nv; ++j)
      for (py::ssize_t i = 0; i < nu; ++i)
        for (int d = 0; d < 3; ++d) p.control_points(p.index(int(i), int(j), int(k)), d) = m(k, j, i, d);
}

py::object weights_array(const spline::Patch& p) {
  if (!p.rational()) return py::none();
  const py::ssize_t nu = p.count(0), nv = p.count(1), nw = p.count(2);
  py::array_t<double> a({nw, nv, nu});
  auto m = a.mutable_unchecked<3>();
  for (py::ssize_t k = 0; k < nw; ++k)
    for (py::ssize_t j = 0; j < nv; ++j)
      for (py::ssize_t i = 0; i < nu; ++i) m(k, j, i) = p.weights(p.index(int(i), int(j), int(k)));
  return std::move(a);
}

py::object json_to_python(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

std::string python_to_json(const py::object& value) {
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

}  // namespace igaprep::python
