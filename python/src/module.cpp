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
  // bad user input is a ValueError carrying the same message as the command line prints
  pybind11::register_exception<flexrock::InputError>(m, "InputError", PyExc_ValueError);
  flexrock::python::bind_model(m);
  flexrock::python::bind_excitation(m);
  flexrock::python::bind_sim(m);
  flexrock::python::bind_io(m);
#ifdef FLEXROCK_PYTHON_STUDY
  flexrock::python::bind_study(m);
#endif
}
