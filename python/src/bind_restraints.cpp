// SPDX-License-Identifier: BSD-3-Clause
// Restraints of a rigid body (sim/restraints.hpp, docs/theory.md §26): tendons and anchors, the
// restrained run and its statics. No physics here.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <vector>

#include "bindings.hpp"
#include "flexrock/sim/restraints.hpp"

namespace py = pybind11;

namespace flexrock::python {

namespace {

// a row-major history (`n` values a row) as a (rows, n) array
py::array_t<double> rows(const std::vector<double>& v, std::size_t n) {
  const auto cols = static_cast<py::ssize_t>(n);
  const auto count = static_cast<py::ssize_t>(n ? v.size() / n : 0);
  py::array_t<double> a({count, cols});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

}  // namespace

void bind_restraints(py::module_& m) {
  py::enum_<RestraintKind> kinds(m, "RestraintKind",
                                 "What a restraint is (one law, two defaults).");
  for (const RestraintKindInfo& k : kRestraintKinds) kinds.value(k.name, k.kind, k.description);
  py::enum_<RestraintEventKind>(m, "RestraintEventKind")
      .value("yield_", RestraintEventKind::kYield)
      .value("unload", RestraintEventKind::kUnload)
      .value("fracture", RestraintEventKind::kFracture);

  py::class_<Restraint>(m, "Restraint",
                        "A tie from the floor point (floor_x, floor_y) to the body point (body_x, "
                        "body_y) [m]: stiffness [N/m], prestress [N], slack [m], yield_force "
                        "[N], fracture_elongation [m] (docs/theory.md §26).")
      .def(py::init([](RestraintKind kind, double body_x, double body_y, double floor_x,
                       double floor_y, double stiffness, double prestress, double slack,
                       double yield_force, double fracture_elongation) {
             return Restraint{kind,      body_x,    body_y, floor_x,     floor_y,
                              stiffness, prestress, slack,  yield_force, fracture_elongation};
           }),
           py::kw_only(), py::arg("kind") = RestraintKind::kTendon, py::arg("body_x") = 0.0,
           py::arg("body_y") = 0.0, py::arg("floor_x") = 0.0, py::arg("floor_y") = 0.0,
           py::arg("stiffness") = 0.0, py::arg("prestress") = 0.0, py::arg("slack") = 0.0,
           py::arg("yield_force") = Restraint{}.yield_force,
           py::arg("fracture_elongation") = Restraint{}.fracture_elongation)
      .def_readwrite("kind", &Restraint::kind)
      .def_readwrite("body_x", &Restraint::body_x)
      .def_readwrite("body_y", &Restraint::body_y)
      .def_readwrite("floor_x", &Restraint::floor_x)
      .def_readwrite("floor_y", &Restraint::floor_y)
      .def_readwrite("stiffness", &Restraint::stiffness)
      .def_readwrite("prestress", &Restraint::prestress)
      .def_readwrite("slack", &Restraint::slack)
      .def_readwrite("yield_force", &Restraint::yield_force)
      .def_readwrite("fracture_elongation", &Restraint::fracture_elongation);

  py::class_<RestraintSummary>(m, "RestraintSummary", "What one restraint did over a run.")
      .def_readonly("max_force", &RestraintSummary::max_force)
      .def_readonly("max_elongation", &RestraintSummary::max_elongation)
      .def_readonly("final_force", &RestraintSummary::final_force)
      .def_readonly("plastic_elongation", &RestraintSummary::plastic_elongation)
      .def_readonly("plastic_work", &RestraintSummary::plastic_work)
      .def_readonly("fracture_work", &RestraintSummary::fracture_work)
      .def_readonly("yield_time", &RestraintSummary::yield_time)
      .def_readonly("fracture_time", &RestraintSummary::fracture_time)
      .def_readonly("yielded", &RestraintSummary::yielded)
      .def_readonly("fractured", &RestraintSummary::fractured);

  py::class_<RestraintEvent>(m, "RestraintEvent", "A restraint's yield, unloading or fracture.")
      .def_readonly("time", &RestraintEvent::time)
      .def_readonly("restraint", &RestraintEvent::restraint)
      .def_readonly("kind", &RestraintEvent::kind)
      .def_readonly("force", &RestraintEvent::force)
      .def_readonly("elongation", &RestraintEvent::elongation)
      .def_readonly("plastic_elongation", &RestraintEvent::plastic_elongation)
      .def_readonly("energy", &RestraintEvent::energy);

  py::class_<RestrainedResult>(m, "RestrainedResult",
                               "A restrained run: the body's result and the restraints'.")
      .def_readonly("result", &RestrainedResult::result)
      .def_readonly("restraints", &RestrainedResult::restraints)
      .def_readonly("events", &RestrainedResult::events)
      .def_property_readonly(
          "force", [](const RestrainedResult& r) { return rows(r.force, r.restraints.size()); })
      .def_property_readonly(
          "elongation",
          [](const RestrainedResult& r) { return rows(r.elongation, r.restraints.size()); })
      .def_property_readonly(
          "energy", [](const RestrainedResult& r) { return rows(r.energy, r.restraints.size()); })
      .def_readonly("stored_energy_change", &RestrainedResult::stored_energy_change)
      .def_readonly("plastic_work", &RestrainedResult::plastic_work)
      .def_readonly("fracture_work", &RestrainedResult::fracture_work);

  m.def("simulate_restrained", &simulate_restrained, py::arg("body"), py::arg("restraints"),
        py::arg("motion"), py::arg("initial") = InitialState{},
        py::arg("options") = SimulationOptions{}, py::call_guard<py::gil_scoped_release>(),
        "Simulates a rigid body tied down by restraints (docs/theory.md §26).");
  m.def("uplift_acceleration", &uplift_acceleration, py::arg("body"), py::arg("restraints"),
        py::arg("edge"), "The uplift threshold [m/s^2] onto `edge` with the restraints.");
  m.def("pushover_acceleration", &pushover_acceleration, py::arg("body"), py::arg("restraints"),
        py::arg("edge"), py::arg("theta"),
        "The base acceleration [m/s^2] that holds the body at theta (quasi-static pushover).");
  m.def("restoring_moment", &restoring_moment, py::arg("body"), py::arg("restraints"),
        py::arg("edge"), py::arg("theta"),
        "The restoring moment [N m] about the pivot of `edge` at theta, gravity and ties.");
  m.def("self_centring_stiffness", &self_centring_stiffness, py::arg("body"), py::arg("restraints"),
        py::arg("edge"), "The post-uplift rotational stiffness [N m/rad] (negative: softening).");
  m.def("critical_stiffness", &critical_stiffness, py::arg("body"), py::arg("restraints"),
        py::arg("which"), py::arg("edge"),
        "The stiffness [N/m] of restraint `which` at which the post-uplift branch stops "
        "softening.");
}

}  // namespace flexrock::python
