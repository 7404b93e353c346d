// SPDX-License-Identifier: BSD-3-Clause
// Bodies: the paper's parameters, the validated Body and the builders (model/body.hpp,
// model/builders.hpp).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "flexrock/model/assemblies.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/model/builders.hpp"

namespace py = pybind11;

namespace flexrock::python {

void bind_model(py::module_& m) {
  py::enum_<DampingKind>(m, "DampingKind")
      .value("none", DampingKind::kNone)
      .value("rayleigh", DampingKind::kRayleigh)
      .value("modal", DampingKind::kModal);

  py::class_<Damping>(m, "Damping", "Material damping of the deformation modes.")
      .def(py::init<>())
      .def_readwrite("kind", &Damping::kind)
      .def_readwrite("rayleigh_mass", &Damping::rayleigh_mass, "a [1/s], coefficient on mu")
      .def_readwrite("rayleigh_stiffness", &Damping::rayleigh_stiffness,
                     "b [s], coefficient on K = (g/h) kappa")
      .def_readwrite("modal_ratios", &Damping::modal_ratios,
                     "[-] one ratio per pinned-base mode, ascending frequency");

  py::class_<BodyParameters>(m, "BodyParameters",
                             "The paper's parameters of a deformable body on two tipping points "
                             "(SI units; mu, kappa, ... dimensionless).")
      .def(py::init<>())
      .def_readwrite("mass", &BodyParameters::mass, "M [kg]")
      .def_readwrite("height", &BodyParameters::height, "h [m], c.g. above the base")
      .def_readwrite("b1", &BodyParameters::b1, "[m] c.g. to tipping point 1 (left)")
      .def_readwrite("b2", &BodyParameters::b2, "[m] c.g. to tipping point 2 (right)")
      .def_readwrite("zeta2", &BodyParameters::zeta2, "I_zz/(M h^2) [-]")
      .def_readwrite("mu", &BodyParameters::mu)
      .def_readwrite("kappa", &BodyParameters::kappa)
      .def_readwrite("gamma", &BodyParameters::gamma)
      .def_readwrite("psi_x", &BodyParameters::psi_x)
      .def_readwrite("psi_y", &BodyParameters::psi_y)
      .def_readwrite("delta", &BodyParameters::delta)
      .def_readwrite("beta", &BodyParameters::beta)
      .def_readwrite("damping", &BodyParameters::damping)
      .def_readwrite("gravity", &BodyParameters::gravity, "g [m/s^2]")
      .def_property_readonly("modes", [](const BodyParameters& p) { return p.kappa.rows(); })
      .def_static("rigid", &BodyParameters::rigid, py::arg("mass"), py::arg("height"),
                  py::arg("b1"), py::arg("b2"), py::arg("zeta2"))
      .def_static("rectangular_block", &BodyParameters::rectangular_block, py::arg("mass"),
                  py::arg("half_width"), py::arg("half_height"))
      .def("__repr__", [](const BodyParameters& p) {
        std::ostringstream o;
        o.precision(4);
        o << "<BodyParameters M = " << p.mass << " kg, h = " << p.height << " m, b1 = " << p.b1
          << " m, b2 = " << p.b2 << " m, zeta2 = " << p.zeta2 << ", "
          << (p.kappa.rows() == 0 ? std::string("rigid")
                                  : std::to_string(p.kappa.rows()) + " mode(s)")
          << ">";
        return o.str();
      });

  py::class_<Body>(m, "Body", "A validated body; bad parameters raise InputError.")
      .def(py::init<BodyParameters>(), py::arg("params"))
      // a body is its parameters: pickled as them, rebuilt (and checked) by the constructor
      .def(py::pickle([](const Body& b) { return py::make_tuple(b.params()); },
                      [](const py::tuple& t) { return Body(t[0].cast<BodyParameters>()); }))
      .def_property_readonly("params", &Body::params)
      .def_property_readonly("modes", &Body::modes)
      .def_property_readonly("alpha1", &Body::alpha1)
      .def_property_readonly("alpha2", &Body::alpha2)
      .def_property_readonly("g", &Body::g)
      .def_property_readonly("mu_inverse", &Body::mu_inverse)
      .def_property_readonly("stiffness", &Body::stiffness, "K = (g/h) kappa [1/s^2]")
      .def_property_readonly("damping_matrix", &Body::damping_matrix, "C [1/s]")
      .def_property_readonly("natural_frequencies", &Body::natural_frequencies,
                             "pinned-base [rad/s], ascending")
      .def_property_readonly("damping_ratios", &Body::damping_ratios)
      .def_property_readonly("static_deformation", &Body::static_deformation)
      .def_property_readonly("rocking_frequency", &Body::rocking_frequency, "p [rad/s]")
      .def("tipping_angle", &Body::tipping_angle, py::arg("edge"),
           "static overturning angle about edge 1 or 2 [rad], positive")
      .def("__repr__", [](const Body& b) {
        const BodyParameters& p = b.params();
        std::ostringstream o;
        o.precision(4);
        o << "<Body M = " << p.mass << " kg, h = " << p.height << " m, b1 = " << p.b1
          << " m, b2 = " << p.b2 << " m, alpha1 = " << b.alpha1() << ", alpha2 = " << b.alpha2()
          << ", p = " << b.rocking_frequency() << " rad/s, ";
        if (b.modes() == 0) {
          o << "rigid";
        } else {
          o << b.modes() << " mode(s) at";
          const VectorX w = b.natural_frequencies();
          for (Eigen::Index i = 0; i < w.size(); ++i) {
            o << (i ? ", " : " ") << w(i) / (2.0 * std::numbers::pi);
          }
          o << " Hz";
        }
        o << ">";
        return o.str();
      });

  // the table of body types: the package makes a keyword function of every type with a builder
  // (flexrock.rigid_block, ...) from it
  py::enum_<BodyKeyValue>(m, "BodyKeyValue")
      .value("number", BodyKeyValue::kNumber)
      .value("integer", BodyKeyValue::kInteger)
      .value("array", BodyKeyValue::kArray)
      .value("matrix", BodyKeyValue::kMatrix)
      .value("path", BodyKeyValue::kPath);
  py::enum_<BodyKeyRule>(m, "BodyKeyRule")
      .value("finite", BodyKeyRule::kFinite)
      .value("positive", BodyKeyRule::kPositive)
      .value("nonnegative", BodyKeyRule::kNonnegative);
  py::class_<BodyKey>(m, "BodyKey", "One key of a body type.")
      .def_readonly("name", &BodyKey::name, "key in a case file and keyword in Python")
      .def_readonly("unit", &BodyKey::unit)
      .def_readonly("value", &BodyKey::value)
      .def_readonly("rule", &BodyKey::rule)
      .def_readonly("required", &BodyKey::required)
      .def_property_readonly(
          "default",
          [](const BodyKey& k) -> std::optional<double> {
            if (k.required || std::isnan(k.fixed)) return std::nullopt;
            return k.fixed;
          },
          "the default of a number that is not required (None: required, or not a number)")
      .def_property_readonly("default_text", [](const BodyKey& k) { return default_text(k); })
      .def_readonly("doc", &BodyKey::doc)
      .def("__repr__", [](const BodyKey& k) {
        return std::string("<BodyKey ") + k.name + " [" + k.unit + "]>";
      });
  py::class_<BodyKind>(m, "BodyKind", "One body type of the case file.")
      .def_readonly("name", &BodyKind::name, "body.type in case files")
      .def_readonly("function", &BodyKind::function, "the Python function that makes it (or \"\")")
      .def_readonly("keys", &BodyKind::keys)
      .def_property_readonly(
          "numbers", [](const BodyKind& k) { return k.make != nullptr; },
          "whether its keys are all numbers (make_body builds it)")
      .def_readonly("doc", &BodyKind::doc)
      .def("__repr__", [](const BodyKind& k) { return std::string("<BodyKind ") + k.name + ">"; });
  m.def("body_kinds", &body_kinds, py::return_value_policy::reference,
        R"doc(Every body type, in the order of the docs.

Returns
-------
list of BodyKind)doc");
  m.def(
      "make_body",
      [](const std::string& type, const std::map<std::string, double>& keys) {
        BodyArgs args;
        args.keys.insert(keys.begin(), keys.end());
        return make_body(body_kind(type), std::move(args));
      },
      py::arg("type"), py::arg("keys"),
      R"doc(A body of a type whose keys are all numbers, as a case file's [body] makes it.

Parameters
----------
type : str
    A body type (``body_kinds()``).
keys : dict of str to float
    Its keys, in the units of the table; keys not given take their defaults.

Returns
-------
BodyParameters)doc");

  m.def(
      "stack_uplift_bands",
      [](double bottom_width, double bottom_height, double bottom_mass, double top_width,
         double top_height, double top_mass) {
        const BlockStack s{bottom_width, bottom_height, bottom_mass,
                           top_width,    top_height,    top_mass};
        std::vector<std::tuple<std::string, double, double>> out;
        for (const StackBand& b : stack_uplift_bands(s))
          out.emplace_back(to_string(b.pattern), b.lo, b.hi);
        return out;
      },
      py::arg("bottom_width"), py::arg("bottom_height"), py::arg("bottom_mass"),
      py::arg("top_width"), py::arg("top_height"), py::arg("top_mass"),
      R"doc(How a uniform block standing centred on another starts to move from rest under a
constant horizontal floor acceleration lambda g (docs/theory.md §25): the band [lo, hi) of
lambda over which each pattern is the consistent one.

Parameters
----------
bottom_width, bottom_height : float
    [m] full width and height of the bottom block.
bottom_mass : float
    [kg]
top_width, top_height : float
    [m] of the top block, top_width <= bottom_width.
top_mass : float
    [kg]

Returns
-------
list of (str, float, float)
    (pattern, lo, hi) for "rest", "top_alone", "as_one", "separately" and
    "separately_opposite"; a pattern that never occurs has lo = hi = inf.)doc");

  py::class_<LumpedNode>(m, "LumpedNode")
      .def(py::init([](double x, double y, double mass, double rotary_inertia) {
             return LumpedNode{x, y, mass, rotary_inertia};
           }),
           py::arg("x"), py::arg("y"), py::arg("mass"), py::arg("rotary_inertia") = 0.0)
      .def_readwrite("x", &LumpedNode::x)
      .def_readwrite("y", &LumpedNode::y)
      .def_readwrite("mass", &LumpedNode::mass)
      .def_readwrite("rotary_inertia", &LumpedNode::rotary_inertia);

  py::class_<LumpedModel>(m, "LumpedModel",
                          "A lumped-mass modal model (pinned-base modes) from a finite-element "
                          "program.")
      .def(py::init<>())
      .def_readwrite("nodes", &LumpedModel::nodes)
      .def_readwrite("tip1_x", &LumpedModel::tip1_x)
      .def_readwrite("tip2_x", &LumpedModel::tip2_x)
      .def_readwrite("phi_x", &LumpedModel::phi_x, "[m] nodes x modes")
      .def_readwrite("phi_y", &LumpedModel::phi_y, "[m] nodes x modes")
      .def_readwrite("frequencies", &LumpedModel::frequencies, "[rad/s]")
      .def_readwrite("stiffness", &LumpedModel::stiffness, "[N m] modal stiffness")
      .def_readwrite("damping", &LumpedModel::damping)
      .def_readwrite("gravity", &LumpedModel::gravity);
  m.def("from_lumped_model", py::overload_cast<const LumpedModel&>(&from_lumped_model),
        py::arg("model"),
        R"doc(The paper's parameters of a lumped-mass modal model (e.g. from an FE program).

Parameters
----------
model : LumpedModel
    Nodes [m, kg], pinned-base mode shapes [m] and frequencies [rad/s] or stiffness [N m].

Returns
-------
BodyParameters)doc");
}

}  // namespace flexrock::python
