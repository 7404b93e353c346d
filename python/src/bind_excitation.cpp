// SPDX-License-Identifier: BSD-3-Clause
// Ground motions in memory and the synthetic pulses (excitation/ground_motion.hpp, pulses.hpp).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/excitation/pulses.hpp"

namespace py = pybind11;

namespace flexrock::python {

void bind_excitation(py::module_& m) {
  // dynamic_attr: the Python package notes how a motion was made, for the summary
  py::class_<GroundMotion>(m, "GroundMotion", py::dynamic_attr(),
                           "Base accelerations [m/s^2]: sampled (linear between samples) or "
                           "analytic.")
      .def_static("sampled", &GroundMotion::sampled, py::arg("time"), py::arg("horizontal"),
                  py::arg("vertical") = std::vector<double>{})
      .def_static("uniform", &GroundMotion::uniform, py::arg("dt"), py::arg("horizontal"),
                  py::arg("vertical") = std::vector<double>{}, py::arg("start") = 0.0)
      .def_static("none", &GroundMotion::none, py::arg("duration"))
      .def(
          "at",
          [](const GroundMotion& g, double t) {
            const BaseAcceleration a = g.at(t);
            return py::make_tuple(a.x, a.y);
          },
          py::arg("t"), "(x, y) base acceleration at time t [m/s^2]")
      .def_property_readonly("duration", &GroundMotion::duration)
      .def_property_readonly("samples", &GroundMotion::samples)
      .def_property_readonly("is_sampled", &GroundMotion::is_sampled)
      .def_property_readonly("has_vertical", &GroundMotion::has_vertical)
      .def_property_readonly("times", &GroundMotion::times)
      .def_property_readonly("horizontal", &GroundMotion::horizontal)
      .def_property_readonly("vertical", &GroundMotion::vertical)
      .def("scaled", &GroundMotion::scaled, py::arg("factor"));

  py::enum_<Component>(m, "Component")
      .value("horizontal", Component::kHorizontal)
      .value("vertical", Component::kVertical);
  const auto h = Component::kHorizontal;

  m.def("harmonic", &harmonic, py::arg("amplitude"), py::arg("omega"), py::arg("duration"),
        py::arg("phase") = 0.0, py::arg("component") = h);
  m.def("harmonic_cycles", &harmonic_cycles, py::arg("amplitude"), py::arg("omega"),
        py::arg("cycles"), py::arg("duration"), py::arg("phase") = 0.0, py::arg("component") = h);
  m.def("one_sine_pulse", &one_sine_pulse, py::arg("a_p"), py::arg("omega_p"), py::arg("duration"),
        py::arg("component") = h);
  m.def("half_sine_pulse", &half_sine_pulse, py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), py::arg("component") = h);
  m.def("cycloidal_pulse_a", &cycloidal_pulse_a, py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), py::arg("component") = h);
  m.def("cycloidal_pulse_b", &cycloidal_pulse_b, py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), py::arg("component") = h);
  m.def("cycloidal_c_phase", &cycloidal_c_phase, py::arg("n"));
  m.def("cycloidal_pulse_c", &cycloidal_pulse_c, py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), py::arg("n") = 1, py::arg("component") = h);
  m.def("ricker_wavelet", &ricker_wavelet, py::arg("a_p"), py::arg("omega_p"), py::arg("t_c"),
        py::arg("duration"), py::arg("component") = h);
  m.def("rectangular_pulse", &rectangular_pulse, py::arg("a_p"), py::arg("t_1"),
        py::arg("duration"), py::arg("component") = h);
}

}  // namespace flexrock::python
