// SPDX-License-Identifier: BSD-3-Clause
// A rigid block on a support that moves with it (sim/support.hpp, docs/theory.md §24).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <vector>

#include "bindings.hpp"
#include "flexrock/sim/support.hpp"

namespace py = pybind11;

namespace flexrock::python {

namespace {

py::array_t<double> column(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

}  // namespace

void bind_support(py::module_& m) {
  py::class_<SupportParameters>(
      m, "SupportParameters",
      "The support under a rigid block: a mass on a horizontal spring and dashpot to the ground "
      "(docs/theory.md §24).")
      .def(py::init<>())
      .def_readwrite("mass", &SupportParameters::mass, "m_s [kg], >= 0")
      .def_readwrite("stiffness", &SupportParameters::stiffness, "k [N/m], > 0")
      .def_readwrite("damping", &SupportParameters::damping, "c [N s/m], >= 0")
      .def_readwrite("displacement", &SupportParameters::displacement, "u(0) [m]")
      .def_readwrite("velocity", &SupportParameters::velocity, "u_dot(0) [m/s]")
      .def_static("from_frequency", &SupportParameters::from_frequency, py::arg("mass"),
                  py::arg("body_mass"), py::arg("frequency_hz"), py::arg("damping_ratio"),
                  "From the frequency [Hz] and damping ratio of the support with the body as a "
                  "rigid mass of `body_mass` [kg] on it.");
  py::class_<SupportRunResult>(m, "SupportRunResult",
                               "The block's result on the support and the support's own.")
      .def_readonly("body", &SupportRunResult::body, "SimulationResult of the block")
      .def_property_readonly(
          "support_displacement",
          [](const SupportRunResult& r) { return column(r.history.displacement); },
          "u [m] relative to the ground at the output times")
      .def_property_readonly(
          "support_velocity", [](const SupportRunResult& r) { return column(r.history.velocity); },
          "u_dot [m/s] at the output times")
      .def_property_readonly(
          "support_acceleration",
          [](const SupportRunResult& r) { return column(r.history.acceleration); },
          "the support's absolute acceleration [m/s^2] at the output times")
      .def_property_readonly(
          "support_force", [](const SupportRunResult& r) { return column(r.history.force); },
          "k u + c u_dot [N] at the output times")
      .def_property_readonly(
          "max_support_displacement",
          [](const SupportRunResult& r) { return r.support.max_displacement; }, "largest |u| [m]");
  m.def("simulate_on_support",
        py::overload_cast<const Body&, const SupportParameters&, const GroundMotion&,
                          const InitialState&, const SimulationOptions&>(&simulate),
        py::arg("body"), py::arg("support"), py::arg("motion"), py::arg("initial") = InitialState{},
        py::arg("options") = SimulationOptions{}, py::call_guard<py::gil_scoped_release>(),
        "Simulates a rigid block standing on a support that moves with it (docs/theory.md §24): "
        "full contact, rocking, impacts and overturning; sliding, flexible bodies and the "
        "compliant contact raise InputError, and a lift-off ends the run as stopped.");
}

}  // namespace flexrock::python
