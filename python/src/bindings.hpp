// SPDX-License-Identifier: BSD-3-Clause
// One bind_<area>.cpp per header group; each only exposes the C++ API (no physics here).
#pragma once

#include <pybind11/pybind11.h>

namespace flexrock::python {

void bind_model(pybind11::module_& m);         // BodyParameters, Body, builders
void bind_excitation(pybind11::module_& m);    // GroundMotion, pulses
void bind_sim(pybind11::module_& m);           // simulate and its result
void bind_axisymmetric(pybind11::module_& m);  // a body of revolution in 3D and its run
void bind_support(pybind11::module_& m);       // a block on a moving support
void bind_io(pybind11::module_& m);            // records, case files, outputs
void bind_restraints(pybind11::module_& m);    // tendons, anchors, the restrained run
#ifdef FLEXROCK_PYTHON_STUDY
void bind_study(pybind11::module_& m);      // spectrum, sweep, fragility
void bind_uncertain(pybind11::module_& m);  // uncertain parameters of studies
#endif

}  // namespace flexrock::python
