// The igaprep Python module: the library's errors become igaprep.Error (a
// RuntimeError) with the library's message; bad input raises
// igaprep.BadInputError, which is also a ValueError.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "igaprep/core/error.h"
#include "igaprep/pipeline/run.h"

namespace py = pybind11;

PYBIND11_MODULE(igaprep, m) {
  m.doc() = "igaprep: analysis-ready trivariate spline models from nested triangle meshes";
  m.attr("__version__") = igaprep::pipeline::generator_name();
  static py::exception<igaprep::Error> error(m, "Error", PyExc_RuntimeError);
  static py::object bad_input_error = py::reinterpret_steal<py::object>(PyErr_NewException(
      "igaprep.BadInputError", py::make_tuple(error, py::handle(PyExc_ValueError)).ptr(), nullptr));
  m.attr("BadInputError") = bad_input_error;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const igaprep::Error& e) {
      const bool bad = e.kind() == igaprep::ErrorKind::BadInput;
      PyErr_SetString(bad ? bad_input_error.ptr() : error.ptr(), e.what());
    }
  });
  igaprep::python::bind_model(m);
  igaprep::python::bind_pipeline(m);
  igaprep::python::bind_analysis(m);
}
