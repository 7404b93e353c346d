// SPDX-License-Identifier: BSD-3-Clause
// Ground motions in memory and the synthetic pulses (excitation/ground_motion.hpp, pulses.hpp).
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/excitation/pulses.hpp"

namespace py = pybind11;

namespace flexrock::python {

namespace {}  // namespace

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
        // has_vertical() is true for every analytic motion (its function may shake vertically):
        // whether it does is told by the vertical peak
        const auto [px, py] = peak_acceleration(g);
        std::ostringstream o;
        o.precision(4);
        o << "<GroundMotion ";
        if (g.is_sampled()) {
          o << "sampled, " << g.samples() << " samples over " << g.duration() << " s";
        } else {
          o << "analytic, " << g.duration() << " s";
        }
        o << ", PGA = " << px << " m/s^2 (" << px / kStandardGravity << " g)";
        if (py > 0.0) {
          o << ", with vertical: peak " << py << " m/s^2 (" << py / kStandardGravity << " g)";
        } else {
          o << ", no vertical";
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
  // the table of pulse types: the package builds its keyword functions from it
  py::enum_<PulseKeyRule>(m, "PulseKeyRule")
      .value("finite", PulseKeyRule::kFinite)
      .value("positive", PulseKeyRule::kPositive)
      .value("nonnegative", PulseKeyRule::kNonnegative)
      .value("count", PulseKeyRule::kCount);
  py::class_<PulseKey>(m, "PulseKey", "One key of a pulse type besides amplitude and frequency.")
      .def_readonly("name", &PulseKey::name, "key in a case file and keyword in Python")
      .def_readonly("argument", &PulseKey::argument, "the pulse function's argument")
      .def_readonly("unit", &PulseKey::unit)
      .def_readonly("rule", &PulseKey::rule)
      .def_readonly("required", &PulseKey::required)
      .def_property_readonly(
          "default",
          [](const PulseKey& k) -> std::optional<double> {
            if (k.required || std::isnan(k.fixed)) return std::nullopt;
            return k.fixed;
          },
          "the fixed default, or None (required, or the function decides)")
      .def_readonly("default_text", &PulseKey::default_text)
      .def_readonly("doc", &PulseKey::doc)
      .def("__repr__", [](const PulseKey& k) {
        return std::string("<PulseKey ") + k.name + " [" + k.unit + "]>";
      });
  py::class_<PulseKind>(m, "PulseKind", "One synthetic motion type of the case file.")
      .def_readonly("name", &PulseKind::name, "type name in case files and spectrum specs")
      .def_readonly("function", &PulseKind::function, "the function that makes it")
      .def_readonly("frequency", &PulseKind::frequency, "takes frequency_hz or period")
      .def_readonly("keys", &PulseKind::keys)
      .def_property_readonly(
          "spectrum", [](const PulseKind& k) { return k.length != nullptr; },
          "a spectrum family (it has a length)")
      .def_readonly("ends", &PulseKind::ends)
      .def_readonly("doc", &PulseKind::doc)
      .def("__repr__",
           [](const PulseKind& k) { return std::string("<PulseKind ") + k.name + ">"; });
  m.def("pulse_kinds", &pulse_kinds, py::return_value_policy::reference,
        R"doc(Every synthetic motion type, in the order of the docs.

Returns
-------
list of PulseKind)doc");
  m.def("spectrum_pulse_names", &spectrum_pulse_names,
        R"doc(The pulse types that spectra sweep.

Returns
-------
list of str)doc");
  m.def(
      "make_pulse",
      [](const std::string& type, double a_p, double omega_p, double duration, Component component,
         const std::map<std::string, double>& keys) {
        PulseArgs args{a_p, omega_p, duration, component, {}};
        for (const auto& [k, v] : keys) args.keys.emplace(k, v);
        return make_pulse(pulse_kind(type), std::move(args));
      },
      py::arg("type"), py::arg("a_p"), py::arg("omega_p"), py::arg("duration"),
      py::arg("component") = h, py::arg("keys") = std::map<std::string, double>{},
      R"doc(A motion of any pulse type, in SI units.

Parameters
----------
type : str
    A pulse type (``pulse_kinds()``).
a_p : float
    [m/s^2] peak acceleration.
omega_p : float
    [rad/s] circular frequency (ignored by a type without one).
duration : float
    [s] length of the motion.
component : Component
keys : dict
    The type's other keys by their case-file names, in their units; absent keys take their
    defaults.

Returns
-------
GroundMotion)doc");
}

}  // namespace flexrock::python
