#pragma once
// The parts of the igaprep Python module, each adding its functions.
#include <pybind11/pybind11.h>

namespace igaprep::python {

namespace py = pybind11;

void bind_model(py::module_& m);     // Model, Patch, read_model, write_model
void bind_pipeline(py::module_& m);  // read_surface, check_surface, run, check
void bind_analysis(py::module_& m);  // solve, refine, export

}  // namespace igaprep::python
