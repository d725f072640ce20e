#pragma once
// Conversions between the library's plain structs and Python objects:
// numpy arrays (control points shaped as in the HDF5 format), lists, dicts.
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "igaprep/spline/multipatch.h"

namespace igaprep::python {

namespace py = pybind11;

// Control points (n_w, n_v, n_u, 3) of a patch, and back (shape checked).
py::array_t<double> control_points_array(const spline::Patch& p);
void set_control_points(spline::Patch& p, const py::array_t<double>& a);
// Weights (n_w, n_v, n_u), or None for a B-spline patch.
py::object weights_array(const spline::Patch& p);
// Per-patch coefficients (n_w, n_v, n_u, 3) of a matrix with a row per control point.
py::array_t<double> per_control_point(const spline::Patch& p, const Eigen::MatrixXd& rows);

// JSON text as Python objects (through the json module).
py::object json_to_python(const std::string& text);
// Python dict/list as JSON text.
std::string python_to_json(const py::object& value);

}  // namespace igaprep::python
