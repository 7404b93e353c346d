// SPDX-License-Identifier: BSD-3-Clause
// The private extension `_flexrock`; the public API is the pure-Python package `flexrock`.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/version.hpp"

PYBIND11_MODULE(_flexrock, m) {
  m.doc() = "flexrock engine: rocking, impacts and overturning of deformable bodies";
  // the library's version (CMake's project(VERSION)); flexrock.__version__ is this
  m.attr("__version__") = flexrock::version();
  // bad user input is a ValueError carrying the same message as the command line prints, and
  // the place as attributes: file ("" when none), line (0: unknown), key ("" when none)
  static pybind11::exception<flexrock::InputError> input_error(m, "InputError", PyExc_ValueError);
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const flexrock::InputError& e) {
      pybind11::object error =
          pybind11::reinterpret_borrow<pybind11::object>(input_error)(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      error.attr("key") = e.key();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    }
  });
  flexrock::python::bind_model(m);
  flexrock::python::bind_excitation(m);
  flexrock::python::bind_sim(m);
  flexrock::python::bind_axisymmetric(m);
  flexrock::python::bind_restraints(m);
  flexrock::python::bind_support(m);
  flexrock::python::bind_io(m);
#ifdef FLEXROCK_PYTHON_STUDY
  flexrock::python::bind_uncertain(m);
  flexrock::python::bind_study(m);
#endif
}
