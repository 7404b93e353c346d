// SPDX-License-Identifier: BSD-3-Clause
// A rigid body of revolution in 3D and its engine (model/axisymmetric_body.hpp,
// sim/axisymmetric.hpp, docs/theory.md §27). Histories come out as numpy arrays; no physics here.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "bindings.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/io/rim_outputs.hpp"
#include "flexrock/model/axisymmetric_body.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/axisymmetric.hpp"

namespace py = pybind11;

namespace flexrock::python {

namespace {

// a copy of a column as a 1-D numpy array
template <class T>
py::array_t<T> column(const std::vector<T>& v) {
  return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
}

// inf (never happened) as None, as the summary JSON writes it
py::object finite_or_none(double v) {
  return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
}

// the body of a table type ("cylinder", "body_of_revolution") from its keys: checked and
// defaulted by make_body as a case file's [body] is, then built as itself
AxisymmetricBody from_type(const std::string& type, const std::map<std::string, double>& keys) {
  const BodyKind& kind = body_kind(type);
  BodyArgs args;
  args.keys.insert(keys.begin(), keys.end());
  (void)make_body(kind, args);  // unknown, missing or bad keys throw here, named
  for (const BodyKey& k : kind.keys) args.keys.emplace(k.name, k.fixed);
  const std::optional<AxisymmetricBody> b = axisymmetric_body(type, args);
  if (!b) {
    throw InputError("body type \"" + type +
                     "\" is not a body of revolution: expected cylinder or body_of_revolution");
  }
  return *b;
}

RimResult run_pair(const AxisymmetricBody& body, const GroundMotion& h1, const GroundMotion* h2,
                   const RimInitialState& initial, const SimulationOptions& options) {
  return simulate_axisymmetric(body, {&h1, h2}, initial, rim_options(options));
}

}  // namespace

void bind_axisymmetric(py::module_& m) {
  py::class_<AxisymmetricBody>(
      m, "AxisymmetricBody",
      "A rigid body of revolution standing on the circular rim of its flat base (docs/theory.md "
      "§27); the c.g. on the axis, inertia diag(A, A, C) about it.")
      .def(py::init([](double mass, double height, double radius, double inertia_diameter,
                       double inertia_axis, double gravity) {
             AxisymmetricBody b{mass, height, radius, inertia_diameter, inertia_axis, gravity};
             validate(b);
             return b;
           }),
           py::arg("mass"), py::arg("height"), py::arg("radius"), py::arg("inertia_diameter"),
           py::arg("inertia_axis"), py::arg("gravity") = kStandardGravity,
           R"doc(A body of revolution from its parameters.

Parameters
----------
mass : float
    M [kg].
height : float
    h [m], the c.g. above the base centre.
radius : float
    R [m], radius of the base rim.
inertia_diameter : float
    A [kg m^2], about a diameter through the c.g.
inertia_axis : float
    C [kg m^2], about the axis (C <= 2 A).
gravity : float
    g [m/s^2].

Raises
------
InputError
    A value that is not positive and finite, or C > 2 A.)doc")
      .def_readonly("mass", &AxisymmetricBody::mass, "M [kg]")
      .def_readonly("height", &AxisymmetricBody::height, "h [m] c.g. above the base centre")
      .def_readonly("radius", &AxisymmetricBody::radius, "R [m] base rim radius")
      .def_readonly("inertia_diameter", &AxisymmetricBody::inertia_diameter,
                    "A [kg m^2] about a diameter through the c.g.")
      .def_readonly("inertia_axis", &AxisymmetricBody::inertia_axis, "C [kg m^2] about the axis")
      .def_readonly("gravity", &AxisymmetricBody::gravity, "g [m/s^2]")
      .def_property_readonly(
          "alpha", [](const AxisymmetricBody& b) { return std::atan2(b.radius, b.height); },
          "[rad] slenderness atan(R / h): the static overturning tilt")
      .def_property_readonly("rocking_frequency", &rocking_frequency,
                             "p [rad/s] of rocking about a rim point")
      .def_property_readonly("planar_landing_ratio", &planar_landing_ratio,
                             "[-] theta_dot+ / theta_dot- of a landing in one plane")
      .def("planar_equivalent", &planar_equivalent,
           "The planar rigid body of the section through the axis (BodyParameters): M, I_cg = "
           "A, h, b1 = b2 = R, what the planar engine runs.")
      .def("__repr__", [](const AxisymmetricBody& b) {
        std::ostringstream o;
        o << "<AxisymmetricBody M = " << b.mass << " kg, h = " << b.height << " m, R = " << b.radius
          << " m, A = " << b.inertia_diameter << " kg m^2, C = " << b.inertia_axis << " kg m^2>";
        return o.str();
      });
  m.def("uniform_cylinder", &uniform_cylinder, py::arg("radius"), py::arg("height"),
        py::arg("mass"), py::arg("inner_radius") = 0.0,
        R"doc(A uniform solid or hollow circular cylinder as a body of revolution in 3D.

Parameters
----------
radius : float
    [m] outer radius of the base.
height : float
    [m] full height.
mass : float
    [kg].
inner_radius : float
    [m] bore of a hollow cylinder, < radius (0: solid).

Returns
-------
AxisymmetricBody
    h = height / 2, A = M (3 (R^2 + Ri^2) + H^2) / 12, C = M (R^2 + Ri^2) / 2.)doc");
  m.def("_axisymmetric_body", &from_type, py::arg("type"), py::arg("keys"));

  py::enum_<RimStatus>(m, "RimStatus", "How a 3D run ended.")
      .value("completed", RimStatus::kCompleted)
      .value("overturned", RimStatus::kOverturned)
      .value("unmodelled", RimStatus::kUnmodelled)
      .value("stopped", RimStatus::kStopped);
  py::enum_<RimMode>(m, "RimMode", "The contact modes of the 3D automaton.")
      .value("full_contact", RimMode::kFullContact)
      .value("rolling", RimMode::kRolling)
      .value("pivoting", RimMode::kPivoting);
  py::enum_<RimEventKind>(m, "RimEventKind")
      .value("uplift", RimEventKind::kUplift)
      .value("landing", RimEventKind::kLanding)
      .value("rest", RimEventKind::kRest)
      .value("overturn", RimEventKind::kOverturn)
      .value("lift_off", RimEventKind::kLiftOff)
      .value("rim_slip", RimEventKind::kRimSlip)
      .value("full_sliding", RimEventKind::kFullSliding)
      .value("stopped", RimEventKind::kStopped);

  py::class_<RimInitialState>(
      m, "RimInitialState",
      "Where a body of revolution starts: upright at rest by default; "
      "with a tilt or rates, rolling on the rim point toward `azimuth_deg`.")
      .def(py::init<>())
      .def_readwrite("tilt", &RimInitialState::tilt, "theta [rad]")
      .def_readwrite("azimuth_deg", &RimInitialState::azimuth_deg,
                     "phi [deg], from H1 (x) toward H2 (y)")
      .def_readwrite("tilt_rate", &RimInitialState::tilt_rate, "theta_dot [rad/s]")
      .def_readwrite("precession", &RimInitialState::precession, "phi_dot [rad/s]")
      .def_readwrite("spin", &RimInitialState::spin, "psi_dot [rad/s]");

  py::class_<RimEvent>(m, "RimEvent", "One event of a 3D run.")
      .def_readonly("time", &RimEvent::time, "[s]")
      .def_readonly("kind", &RimEvent::kind)
      .def_readonly("tilt", &RimEvent::tilt, "[rad]")
      .def_readonly("azimuth", &RimEvent::azimuth, "[rad] of the contact (the new one)")
      .def_readonly("rate_before", &RimEvent::rate_before, "[rad/s] |omega| before a landing")
      .def_readonly("rate_after", &RimEvent::rate_after, "[rad/s] |omega| after")
      .def_readonly("energy_loss", &RimEvent::energy_loss, "[J]")
      .def_readonly("value", &RimEvent::value,
                    "the magnitude: N / (M g) at lift-off, friction demand at slip, tilt [rad] at "
                    "overturning")
      .def("__repr__", [](const RimEvent& e) {
        std::ostringstream o;
        o << "<RimEvent " << to_string(e.kind) << " at " << e.time << " s>";
        return o.str();
      });

  using H = RimHistory;
  py::class_<H>(m, "RimHistory", "A 3D run's time history at the output times; each a numpy copy.")
      .def_property_readonly(
          "time", [](const H& h) { return column(h.time); }, "[s]")
      .def_property_readonly(
          "mode", [](const H& h) { return column(h.mode); }, "RimMode values")
      .def_property_readonly(
          "tilt", [](const H& h) { return column(h.tilt); }, "theta [rad]")
      .def_property_readonly(
          "azimuth", [](const H& h) { return column(h.azimuth); },
          "phi [rad], toward which the axis leans, unwrapped")
      .def_property_readonly(
          "contact_angle", [](const H& h) { return column(h.contact_angle); },
          "[rad] the contact on the base circle, body frame, unwrapped")
      .def_property_readonly(
          "x", [](const H& h) { return column(h.x); }, "[m] base centre's offset along H1")
      .def_property_readonly(
          "y", [](const H& h) { return column(h.y); }, "[m] along H2")
      .def_property_readonly(
          "reaction_x", [](const H& h) { return column(h.reaction_x); },
          "[N] floor on body along H1")
      .def_property_readonly(
          "reaction_y", [](const H& h) { return column(h.reaction_y); }, "[N] along H2")
      .def_property_readonly(
          "reaction_z", [](const H& h) { return column(h.reaction_z); },
          "[N] vertical (normal force)")
      .def_property_readonly(
          "friction_demand", [](const H& h) { return column(h.friction_demand); }, "|F_h| / F_z")
      .def_property_readonly(
          "kinetic", [](const H& h) { return column(h.kinetic); }, "[J]")
      .def_property_readonly(
          "potential", [](const H& h) { return column(h.potential); }, "[J]")
      .def_property_readonly(
          "input_work", [](const H& h) { return column(h.input_work); }, "[J] cumulative")
      .def_property_readonly(
          "impact_loss", [](const H& h) { return column(h.impact_loss); }, "[J] cumulative")
      .def(
          "columns",
          [](const H& h) {
            // the CSV's columns by their names and units (the one table, rim_columns())
            py::dict d;
            for (const io::RimColumn& c : io::rim_columns()) {
              py::array_t<double> a(static_cast<py::ssize_t>(h.size()));
              auto v = a.mutable_unchecked<1>();
              for (std::size_t i = 0; i < h.size(); ++i)
                v(static_cast<py::ssize_t>(i)) = c.value(h, i);
              d[py::str(c.name)] = a;
            }
            return d;
          },
          "The time-history CSV's columns (name with unit to numpy array), as `flexrock run` "
          "writes them.")
      .def("__len__", &H::size);

  py::class_<RimResult>(m, "RimResult",
                        "A 3D run of a body of revolution: outcome, extremes, events, energy.")
      .def_readonly("status", &RimResult::status)
      .def_readonly("message", &RimResult::message,
                    "why a run ended early, with the magnitude (\"\": completed)")
      .def_readonly("t_end", &RimResult::t_end, "[s]")
      .def_readonly("final_mode", &RimResult::final_mode)
      .def_readonly("final_tilt", &RimResult::final_tilt, "[rad]")
      .def_readonly("history", &RimResult::history)
      .def_readonly("events", &RimResult::events)
      .def_readonly("max_tilt", &RimResult::max_tilt, "[rad]")
      .def_readonly("max_tilt_azimuth", &RimResult::max_tilt_azimuth,
                    "[rad] azimuth of the contact at the largest tilt")
      .def_readonly("max_offset", &RimResult::max_offset, "[m] of the base centre")
      .def_readonly("max_friction_demand", &RimResult::max_friction_demand, "[-]")
      .def_property_readonly(
          "min_normal_force", [](const RimResult& r) { return finite_or_none(r.min_normal_force); },
          "[N] while rolling (None: never rolled)")
      .def_property_readonly(
          "closest_pass", [](const RimResult& r) { return finite_or_none(r.closest_pass); },
          "[rad] closest pass by upright without landing (None: none); the response after it is "
          "one sample, not converged (docs/theory.md §27)")
      .def_readonly("landings", &RimResult::landings)
      .def_readonly("uplifts", &RimResult::uplifts)
      .def_readonly("energy", &RimResult::energy, "EnergyBalance [J]")
      .def_readonly("steps", &RimResult::steps)
      .def_readonly("rhs_evaluations", &RimResult::rhs_evaluations)
      .def("__repr__", [](const RimResult& r) {
        std::ostringstream o;
        o << "<RimResult " << to_string(r.status) << ", max tilt " << r.max_tilt << " rad, "
          << r.uplifts << " uplift(s), " << r.landings << " landing(s)>";
        return o.str();
      });

  m.def("_simulate_axisymmetric", &run_pair, py::arg("body"), py::arg("h1"), py::arg("h2"),
        py::arg("initial"), py::arg("options"), py::call_guard<py::gil_scoped_release>());
  // a loaded case with a body of revolution and a record pair, as `flexrock run` runs it
  m.def(
      "_simulate_case_3d",
      [](const io::Case& c) {
        if (!c.body3d || !c.pair) throw std::logic_error("_simulate_case_3d: not a 3D case");
        const io::PairMotions pm = io::pair_motions(c);
        py::gil_scoped_release nogil;
        return simulate_axisymmetric(*c.body3d, {&pm.h1, &pm.h2}, {}, rim_options(c.options));
      },
      py::arg("case"));
  m.def(
      "_write_rim_outputs",
      [](const io::Case& c, const RimResult& r, const std::string& output_dir) {
        // as `flexrock run`: an output may not overwrite an input or another output
        const io::OutputPaths paths = io::output_paths(c, output_dir);
        io::check_output_paths(c, paths);
        io::write_rim_outputs(c, *c.body3d, r, paths);
      },
      py::arg("case"), py::arg("result"), py::arg("output_dir"));
  m.def(
      "_rim_summary_json",
      [](const io::Case& c, const RimResult& r, const std::string& output_dir) {
        return io::rim_summary_json(c, *c.body3d, r, io::output_paths(c, output_dir));
      },
      py::arg("case"), py::arg("result"), py::arg("output_dir"));
}

}  // namespace flexrock::python
