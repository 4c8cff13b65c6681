// The compiled part of the Python package `dynpos` (python/dynpos/__init__.py wraps it): logs as
// numpy arrays without copying, the requests of the application layer with the CLI's option
// names, and one run function per analysis that returns the report's JSON text (the CLI's
// --json). Bad input raises InputError (a ValueError) with the CLI's message.

#include <pybind11/pybind11.h>

#include <exception>

#include "bind.hpp"
#include "dynpos/analysis/option_spelling.hpp"
#include "dynpos/core/error.hpp"

namespace py = pybind11;

namespace {

// The InputError instance: the CLI's message, and where (file, line, column, option) as
// attributes; None where not known.
void raise_input_error(const py::object& type, const dynpos::core::InputError& e) {
  py::object error = type(dynpos::analysis::python_message(e));
  const auto& where = e.where();
  error.attr("file") = where.file.empty() ? py::object(py::none()) : py::str(where.file);
  error.attr("line") = where.line ? py::object(py::int_(*where.line)) : py::none();
  error.attr("column") = where.column ? py::object(py::int_(*where.column)) : py::none();
  error.attr("option") = e.option().empty() ? py::object(py::none()) : py::str(e.option());
  PyErr_SetObject(type.ptr(), error.ptr());
}

}  // namespace

PYBIND11_MODULE(_dynpos, m) {
  m.doc() = "dynpos: dynamic positioning of ships (compiled part; use the package dynpos)";
  m.attr("__version__") = DYNPOS_VERSION;  // the CLI's --version
  static py::exception<dynpos::core::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const dynpos::core::InputError& e) {
      raise_input_error(input_error, e);
    }
  });
  dynpos::python::bind_log(m);
  dynpos::python::bind_identify(m);
  dynpos::python::bind_calib(m);
  dynpos::python::bind_control(m);
  dynpos::python::bind_estimate(m);
}
