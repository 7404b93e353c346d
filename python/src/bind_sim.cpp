// SPDX-License-Identifier: BSD-3-Clause
// One simulation and its result (sim/simulate.hpp). Time histories come out as numpy arrays;
// the GIL is released while the engine runs, so Python threads simulate in parallel.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <type_traits>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "field_pickle.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/sim/solver_keys.hpp"

namespace py = pybind11;

namespace flexrock::python {

namespace {

// a copy of a column as a 1-D numpy array
template <class T>
py::array_t<T> column(const std::vector<T>& v) {
  return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
}

// q or q_dot (row-major, `modes` values a row) as a (rows, modes) array
py::array_t<double> modal(const std::vector<double>& v, const History& h) {
  const auto n = static_cast<py::ssize_t>(h.modes);
  const auto rows = static_cast<py::ssize_t>(h.size());
  py::array_t<double> a({rows, n});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

}  // namespace

void bind_sim(py::module_& m) {
  // enum value names are the C++ to_string() names (the CSV and JSON words): use `.name`
  py::enum_<Phase>(m, "Phase")
      .value("full_contact", Phase::kFullContact)
      .value("rocking_edge1", Phase::kRockingEdge1)
      .value("rocking_edge2", Phase::kRockingEdge2)
      .value("flight", Phase::kFlight)
      .value("sliding_plus", Phase::kSlidingPlus)
      .value("sliding_minus", Phase::kSlidingMinus)
      .value("rocking_edge1_sliding_plus", Phase::kRockingEdge1SlidingPlus)
      .value("rocking_edge1_sliding_minus", Phase::kRockingEdge1SlidingMinus)
      .value("rocking_edge2_sliding_plus", Phase::kRockingEdge2SlidingPlus)
      .value("rocking_edge2_sliding_minus", Phase::kRockingEdge2SlidingMinus);
  py::enum_<Status>(m, "Status")
      .value("completed", Status::kCompleted)
      .value("overturned", Status::kOverturned)
      .value("stopped", Status::kStopped);
  py::enum_<EventKind>(m, "EventKind")
      .value("uplift", EventKind::kUplift)
      .value("impact", EventKind::kImpact)
      .value("rocking_ended", EventKind::kRockingEnded)
      .value("chatter_cutoff", EventKind::kChatterCutoff)
      .value("peak", EventKind::kPeak)
      .value("overturn", EventKind::kOverturn)
      .value("lift_off", EventKind::kLiftOff)
      .value("landing", EventKind::kLanding)
      .value("tensile_landing", EventKind::kTensileLanding)
      .value("pivot_tension", EventKind::kPivotTension)
      .value("friction_exceeded", EventKind::kFrictionExceeded)
      .value("impact_gained_energy", EventKind::kImpactGainedEnergy)
      .value("stopped", EventKind::kStopped)
      .value("energy_unbalanced", EventKind::kEnergyUnbalanced)
      .value("slip_start", EventKind::kSlipStart)
      .value("stick", EventKind::kStick)
      .value("slip_reversal", EventKind::kSlipReversal)
      .value("impact_law_fallback", EventKind::kImpactLawFallback);
  {
    // the impact laws, from the engine's table
    py::enum_<ImpactLaw> laws(m, "ImpactLaw", "How impacts and landings are resolved.");
    for (const ImpactLawInfo& l : kImpactLaws) laws.value(l.name, l.law, l.description);
    // the contact models and the compliant contact's force laws, from the engine's tables
    py::enum_<ContactModel> models(m, "ContactModel", "How the floor acts on the body.");
    for (const ContactModelInfo& c : kContactModels) models.value(c.name, c.model, c.description);
    py::enum_<ContactForceLaw> forces(m, "ContactForceLaw",
                                      "The normal force law of the compliant contact.");
    for (const ContactForceLawInfo& f : kContactForceLaws)
      forces.value(f.name, f.law, f.description);
  }
  py::enum_<OverturnCriterion>(m, "OverturnCriterion")
      .value("static_instability", OverturnCriterion::kStaticInstability)
      .value("half_pi", OverturnCriterion::kHalfPi);

  py::class_<InitialState>(m, "InitialState", "Where the body starts.")
      .def(py::init([](double theta, double theta_dot, VectorX q, VectorX q_dot) {
             return InitialState{theta, theta_dot, std::move(q), std::move(q_dot)};
           }),
           py::arg("theta") = 0.0, py::arg("theta_dot") = 0.0, py::arg("q") = VectorX(),
           py::arg("q_dot") = VectorX())
      .def_readwrite("theta", &InitialState::theta, "[rad]")
      .def_readwrite("theta_dot", &InitialState::theta_dot, "[rad/s]")
      .def_readwrite("q", &InitialState::q, "[-] empty: the static deformation under gravity")
      .def_readwrite("q_dot", &InitialState::q_dot, "[1/s] empty: zero");

  py::enum_<ContactIntegrator>(m, "ContactIntegrator",
                               "How a stiff motion is integrated (SimulationMethods).")
      .value("auto", ContactIntegrator::kAuto,
             "DOPRI5 while accuracy sets the step, Rosenbrock "
             "while stability would")
      .value("explicit", ContactIntegrator::kExplicit, "DOPRI5 only")
      .value("implicit", ContactIntegrator::kImplicit, "the Rosenbrock method only");
  py::class_<SimulationMethods>(
      m, "SimulationMethods",
      "How the engine steps, for tests and comparisons only: each switch picks between two "
      "methods that give the same answer within the tolerances, at different cost.")
      .def(py::init<>())
      .def_readwrite("exact_full_contact", &SimulationMethods::exact_full_contact,
                     "a flexible body in full contact under a record: exact propagation; False: "
                     "DOPRI5")
      .def_readwrite("contact_integrator", &SimulationMethods::contact_integrator,
                     "the compliant contact's integrator")
      .def_readwrite("rocking_integrator", &SimulationMethods::rocking_integrator,
                     "a flexible body's rocking integrator")
      .def_readwrite("stiff_switch_scale", &SimulationMethods::stiff_switch_scale,
                     "factor on the rate where the rocking integrator switches methods")
      .def_readwrite("full_contact_walk", &SimulationMethods::full_contact_walk,
                     "the exact full contact walks the record; False: sampled steps")
      .def_readwrite("series_rocking", &SimulationMethods::series_rocking,
                     "a rigid body's rocking by its Taylor series; False: DOPRI5")
      .def_readwrite("high_order_rocking", &SimulationMethods::high_order_rocking,
                     "a flexible body's rocking by DOP853; False: DOPRI5")
      .def_readwrite("closed_form_free_rocking", &SimulationMethods::closed_form_free_rocking,
                     "a rigid body's free rocking by the closed form of its arcs; False: its "
                     "Taylor series");

  {
    // every [solver] key with an option of its own, from the table of solver keys
    py::class_<SimulationOptions> options(m, "SimulationOptions", "Solver options (SI units).");
    options.def(py::init<>())
        .def_readwrite("output_dt", &SimulationOptions::output_dt, "[s] 0: no time history")
        .def_readwrite("methods", &SimulationOptions::methods,
                       "how the engine steps, for tests and comparisons only");
    for (const SolverKey& k : kSolverKeys) {
      std::visit(
          [&](auto field) {
            if constexpr (!std::is_same_v<decltype(field), std::monostate>)
              options.def_readwrite(k.name, field, solver_key_doc(k).c_str());
          },
          k.field);
    }
  }

  FieldPickle<Event>(
      py::class_<Event>(m, "Event", "Something that happened; fields not meaningful are zero."))
      .def_readonly("time", &Event::time)
      .def_readonly("kind", &Event::kind)
      .def_readonly("edge", &Event::edge)
      .def_readonly("theta", &Event::theta)
      .def_readonly("theta_dot_before", &Event::theta_dot_before)
      .def_readonly("theta_dot_after", &Event::theta_dot_after)
      .def_readonly("energy_loss", &Event::energy_loss)
      .def_readonly("impulse_x", &Event::impulse_x)
      .def_readonly("impulse_y", &Event::impulse_y)
      .def_readonly("friction_demand", &Event::friction_demand)
      .def_readonly("offset", &Event::offset, "[m] horizontal offset of the base centre")
      .def_readonly("force_estimate", &Event::force_estimate,
                    "[N] pi |impulse| / (2 impact_duration); compliant: the resolved peak")
      .def("__repr__",
           [](const Event& e) {
             return "<Event " + std::string(to_string(e.kind)) + " t=" + std::to_string(e.time) +
                    ">";
           })
      .pickled();

  FieldPickle<History>(
      py::class_<History>(m, "History", "Time history at the output times; each a numpy copy."))
      .def_readonly("modes", &History::modes)
      .def("__len__", &History::size)
      .def_property_readonly("time", [](const History& h) { return column(h.time); })
      .def_property_readonly("phase", [](const History& h) { return column(h.phase); })
      .def_property_readonly("theta", [](const History& h) { return column(h.theta); })
      .def_property_readonly("theta_dot", [](const History& h) { return column(h.theta_dot); })
      .def_property_readonly("q", [](const History& h) { return modal(h.q, h); })
      .def_property_readonly("q_dot", [](const History& h) { return modal(h.q_dot, h); })
      .def_property_readonly("base_acc_x", [](const History& h) { return column(h.base_acc_x); })
      .def_property_readonly("base_acc_y", [](const History& h) { return column(h.base_acc_y); })
      .def_property_readonly("reaction_x", [](const History& h) { return column(h.reaction_x); })
      .def_property_readonly("reaction_y", [](const History& h) { return column(h.reaction_y); })
      .def_property_readonly("resultant", [](const History& h) { return column(h.resultant); })
      .def_property_readonly("friction_demand",
                             [](const History& h) { return column(h.friction_demand); })
      .def_property_readonly("kinetic", [](const History& h) { return column(h.kinetic); })
      .def_property_readonly("potential", [](const History& h) { return column(h.potential); })
      .def_property_readonly("input_work", [](const History& h) { return column(h.input_work); })
      .def_property_readonly("damping_loss",
                             [](const History& h) { return column(h.damping_loss); })
      .def_property_readonly("impact_loss", [](const History& h) { return column(h.impact_loss); })
      .def_property_readonly("offset", [](const History& h) { return column(h.offset); })
      .def_property_readonly("lift", [](const History& h) { return column(h.lift); })
      .field("time", &History::time)
      .field("phase", &History::phase)
      .field("theta", &History::theta)
      .field("theta_dot", &History::theta_dot)
      .field("q", &History::q)
      .field("q_dot", &History::q_dot)
      .field("base_acc_x", &History::base_acc_x)
      .field("base_acc_y", &History::base_acc_y)
      .field("reaction_x", &History::reaction_x)
      .field("reaction_y", &History::reaction_y)
      .field("resultant", &History::resultant)
      .field("friction_demand", &History::friction_demand)
      .field("kinetic", &History::kinetic)
      .field("potential", &History::potential)
      .field("input_work", &History::input_work)
      .field("damping_loss", &History::damping_loss)
      .field("impact_loss", &History::impact_loss)
      .field("offset", &History::offset)
      .field("lift", &History::lift)
      .pickled();

  FieldPickle<Extremes>(py::class_<Extremes>(m, "Extremes"))
      .def_readonly("max_theta_edge1", &Extremes::max_theta_edge1)
      .def_readonly("max_theta_edge2", &Extremes::max_theta_edge2)
      .def_readonly("max_uplift", &Extremes::max_uplift)
      .def_readonly("impacts", &Extremes::impacts)
      .def_readonly("max_impulse", &Extremes::max_impulse)
      .def_readonly("max_impact_energy_loss", &Extremes::max_impact_energy_loss)
      .def_readonly("max_abs_q", &Extremes::max_abs_q)
      .def_readonly("max_base_shear", &Extremes::max_base_shear)
      .def_readonly("max_overturning_moment", &Extremes::max_overturning_moment)
      .def_readonly("max_friction_demand", &Extremes::max_friction_demand)
      .def_readonly("first_uplift_time", &Extremes::first_uplift_time)
      .def_readonly("first_uplift_edge", &Extremes::first_uplift_edge)
      .def_readonly("overturn_time", &Extremes::overturn_time)
      .def_readonly("overturn_edge", &Extremes::overturn_edge)
      .def_readonly("chatter_cutoffs", &Extremes::chatter_cutoffs)
      .def_readonly("lift_offs", &Extremes::lift_offs)
      .def_readonly("flight_time", &Extremes::flight_time, "[s]")
      .def_readonly("max_flight_height", &Extremes::max_flight_height, "[m]")
      .def_readonly("max_offset", &Extremes::max_offset, "[m]")
      .def_readonly("sliding_time", &Extremes::sliding_time, "[s] total time sliding")
      .def_readonly("slips", &Extremes::slips, "times sliding started")
      .def_readonly("max_impact_force", &Extremes::max_impact_force,
                    "[N] largest impact force estimate (impact_duration)")
      .def_readonly("max_contact_force", &Extremes::max_contact_force,
                    "[N] compliant contact: the largest normal force of a tipping point")
      .def_readonly("impact_law_fallbacks", &Extremes::impact_law_fallbacks,
                    "impacts where the chosen law would have added energy (impact_law_fallback)")
      .def_readonly("tension_episodes", &Extremes::tension_episodes,
                    "pivot_tension events: the pivot force vanished where only sliding could free "
                    "the pivot, and the floor was let pull (no friction limit)")
      .def_readonly("max_pivot_pull", &Extremes::max_pivot_pull,
                    "[N] largest pull of the floor on a held pivot, -min F_J (0: none)")
      .def_readonly("tension_time", &Extremes::tension_time,
                    "[s] total time the floor pulled on a held pivot")
      .def_readonly("tensile_landings", &Extremes::tensile_landings,
                    "landings/impacts that needed a pulling impulse (tensile_landing events)")
      .def_readonly("max_tensile_impulse", &Extremes::max_tensile_impulse,
                    "[N s] largest pulling vertical impulse of such a landing, -min I_y (0: none)")
      .pickled();

  FieldPickle<EnergyBalance>(py::class_<EnergyBalance>(m, "EnergyBalance"))
      .def_readonly("input_work", &EnergyBalance::input_work)
      .def_readonly("kinetic_change", &EnergyBalance::kinetic_change)
      .def_readonly("potential_change", &EnergyBalance::potential_change)
      .def_readonly("damping_loss", &EnergyBalance::damping_loss)
      .def_readonly("impact_loss", &EnergyBalance::impact_loss)
      .def_readonly("chatter_loss", &EnergyBalance::chatter_loss)
      .def_readonly("friction_loss", &EnergyBalance::friction_loss, "[J] work of friction")
      .def_readonly("residual", &EnergyBalance::residual)
      .def_readonly("scale", &EnergyBalance::scale)
      .pickled();

  FieldPickle<SimulationResult>(py::class_<SimulationResult>(m, "SimulationResult"))
      .def_readonly("status", &SimulationResult::status)
      .def_readonly("message", &SimulationResult::message)
      .def_readonly("t_end", &SimulationResult::t_end)
      .def_readonly("final_phase", &SimulationResult::final_phase)
      .def_readonly("final_theta", &SimulationResult::final_theta)
      .def_readonly("final_theta_dot", &SimulationResult::final_theta_dot)
      .def_readonly("final_q", &SimulationResult::final_q)
      .def_readonly("final_q_dot", &SimulationResult::final_q_dot)
      .def_readonly("friction_exceeded", &SimulationResult::friction_exceeded)
      .def_readonly("chatter_cut_off", &SimulationResult::chatter_cut_off)
      .def_readonly("impact_gained_energy", &SimulationResult::impact_gained_energy)
      .def_readonly("energy_unbalanced", &SimulationResult::energy_unbalanced)
      .def_readonly("pivot_tension", &SimulationResult::pivot_tension)
      .def_readonly("final_offset", &SimulationResult::final_offset, "[m]")
      .def_readonly("history", &SimulationResult::history)
      .def_readonly("extremes", &SimulationResult::extremes)
      .def_readonly("energy", &SimulationResult::energy)
      .def_readonly("events", &SimulationResult::events)
      .def_readonly("steps", &SimulationResult::steps)
      .def_readonly("rejected_steps", &SimulationResult::rejected_steps)
      .def_readonly("rhs_evaluations", &SimulationResult::rhs_evaluations)
      .pickled();

  m.def("simulate", &simulate, py::arg("body"), py::arg("motion"),
        py::arg("initial") = InitialState{}, py::arg("options") = SimulationOptions{},
        py::call_guard<py::gil_scoped_release>(),
        R"doc(Simulates a body on a base moving with a ground motion.

Parameters
----------
body : Body
motion : GroundMotion
    Base accelerations [m/s^2].
initial : InitialState
    theta [rad], theta_dot [rad/s], q, q_dot; default at rest.
options : SimulationOptions
    Solver options (SI).

Returns
-------
SimulationResult
    Overturning, loss of contact and a stopped run are its ``status``, not exceptions. The
    GIL is released while it runs.)doc");
}

}  // namespace flexrock::python
