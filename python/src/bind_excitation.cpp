// SPDX-License-Identifier: BSD-3-Clause
// Ground motions in memory and the synthetic pulses (excitation/ground_motion.hpp, pulses.hpp).
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <sstream>

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
      .def("scaled", &GroundMotion::scaled, py::arg("factor"),
           "The motion with every acceleration times `factor` [-].")
      .def("__repr__", [](const GroundMotion& g) {
        std::ostringstream o;
        o.precision(4);
        o << "<GroundMotion ";
        if (g.is_sampled()) {
          double pga = 0.0;
          for (double a : g.horizontal()) pga = std::max(pga, std::abs(a));
          o << "sampled, " << g.samples() << " samples over " << g.duration() << " s, PGA = " << pga
            << " m/s^2 (" << pga / 9.80665 << " g)" << (g.has_vertical() ? ", with vertical" : "");
        } else {
          o << "analytic, " << g.duration() << " s" << (g.has_vertical() ? ", vertical" : "");
        }
        o << ">";
        return o.str();
      });

  py::enum_<Component>(m, "Component")
      .value("horizontal", Component::kHorizontal)
      .value("vertical", Component::kVertical);
  const auto h = Component::kHorizontal;

  m.def("harmonic", &harmonic, py::arg("amplitude"), py::arg("omega"), py::arg("duration"),
        py::arg("phase") = 0.0, py::arg("component") = h,
        R"doc(A steady harmonic base acceleration a sin(omega t + phase).

Parameters
----------
amplitude : float
    [m/s^2] peak acceleration.
omega : float
    [rad/s] circular frequency.
duration : float
    [s] length of the motion.
phase : float
    [rad] phase at t = 0.
component : Component
    horizontal (default) or vertical.

Returns
-------
GroundMotion)doc");
  m.def("harmonic_cycles", &harmonic_cycles, py::arg("amplitude"), py::arg("omega"),
        py::arg("cycles"), py::arg("duration"), py::arg("phase") = 0.0, py::arg("component") = h,
        R"doc(A harmonic base acceleration over a whole number of cycles, then zero.

Parameters
----------
amplitude : float
    [m/s^2] peak acceleration.
omega : float
    [rad/s] circular frequency.
cycles : float
    [-] cycles before the motion stops.
duration : float
    [s] length of the motion.
phase : float
    [rad] phase at t = 0.
component : Component

Returns
-------
GroundMotion)doc");
  m.def("one_sine_pulse", &one_sine_pulse, py::arg("a_p"), py::arg("omega_p"), py::arg("duration"),
        py::arg("component") = h, R"doc(One full sine cycle a_p sin(omega_p t).

Parameters
----------
a_p : float
    [m/s^2] peak acceleration (negative: reversed).
omega_p : float
    [rad/s] circular frequency of the pulse.
duration : float
    [s] length of the motion (zero after the pulse: free vibration).
component : Component
    horizontal (default) or vertical.

Returns
-------
GroundMotion
    Analytic. The package's ``flexrock.one_sine_pulse`` also takes the case file's keys
    (``amplitude=``, ``units=``, ``frequency_hz=`` or ``period=``).)doc");
  m.def("half_sine_pulse", &half_sine_pulse, py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), py::arg("component") = h, R"doc(Half a sine cycle a_p sin(omega_p t).

Parameters
----------
a_p : float
    [m/s^2] peak acceleration (negative: reversed).
omega_p : float
    [rad/s] circular frequency of the pulse.
duration : float
    [s] length of the motion (zero after the pulse: free vibration).
component : Component
    horizontal (default) or vertical.

Returns
-------
GroundMotion
    Analytic. The package's ``flexrock.half_sine_pulse`` also takes the case file's keys
    (``amplitude=``, ``units=``, ``frequency_hz=`` or ``period=``).)doc");
  m.def("cycloidal_pulse_a", &cycloidal_pulse_a, py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), py::arg("component") = h,
        R"doc(Makris & Roussos cycloidal pulse type A (= one-sine).

Parameters
----------
a_p : float
    [m/s^2] peak acceleration (negative: reversed).
omega_p : float
    [rad/s] circular frequency of the pulse.
duration : float
    [s] length of the motion (zero after the pulse: free vibration).
component : Component
    horizontal (default) or vertical.

Returns
-------
GroundMotion
    Analytic. The package's ``flexrock.cycloidal_pulse_a`` also takes the case file's keys
    (``amplitude=``, ``units=``, ``frequency_hz=`` or ``period=``).)doc");
  m.def("cycloidal_pulse_b", &cycloidal_pulse_b, py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), py::arg("component") = h,
        R"doc(Makris & Roussos cycloidal pulse type B: a_p cos(omega_p t) for one period.

Parameters
----------
a_p : float
    [m/s^2] peak acceleration (negative: reversed).
omega_p : float
    [rad/s] circular frequency of the pulse.
duration : float
    [s] length of the motion (zero after the pulse: free vibration).
component : Component
    horizontal (default) or vertical.

Returns
-------
GroundMotion
    Analytic. The package's ``flexrock.cycloidal_pulse_b`` also takes the case file's keys
    (``amplitude=``, ``units=``, ``frequency_hz=`` or ``period=``).)doc");
  m.def("cycloidal_c_phase", &cycloidal_c_phase, py::arg("n"),
        R"doc(The phase phi_n [rad] of the type-C_n cycloidal pulse.

Parameters
----------
n : int
    [-] the pulse's index, >= 1.

Returns
-------
float
    [rad])doc");
  m.def("cycloidal_pulse_c", &cycloidal_pulse_c, py::arg("a_p"), py::arg("omega_p"),
        py::arg("duration"), py::arg("n") = 1, py::arg("component") = h,
        R"doc(Makris & Roussos cycloidal pulse type C_n: a_p cos(omega_p t + phi_n).

Parameters
----------
a_p : float
    [m/s^2] peak acceleration.
omega_p : float
    [rad/s] circular frequency.
duration : float
    [s] length of the motion.
n : int
    [-] type index, >= 1.
component : Component

Returns
-------
GroundMotion)doc");
  m.def("ricker_wavelet", &ricker_wavelet, py::arg("a_p"), py::arg("omega_p"), py::arg("t_c"),
        py::arg("duration"), py::arg("component") = h, R"doc(A Ricker wavelet peaking at t_c.

Parameters
----------
a_p : float
    [m/s^2] peak acceleration.
omega_p : float
    [rad/s] circular peak frequency.
t_c : float
    [s] time of the peak (the case file's ``center``).
duration : float
    [s] length of the motion.
component : Component

Returns
-------
GroundMotion)doc");
  m.def("rectangular_pulse", &rectangular_pulse, py::arg("a_p"), py::arg("t_1"),
        py::arg("duration"), py::arg("component") = h,
        R"doc(A constant acceleration a_p for 0 <= t <= t_1, then zero.

Parameters
----------
a_p : float
    [m/s^2] acceleration.
t_1 : float
    [s] length of the pulse (the case file's ``length``).
duration : float
    [s] length of the motion.
component : Component

Returns
-------
GroundMotion)doc");
}

}  // namespace flexrock::python
