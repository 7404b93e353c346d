// SPDX-License-Identifier: BSD-3-Clause
// Uncertain parameters of studies (study/uncertain.hpp): distributions, sampling, the design.
#include <pybind11/stl.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/study/uncertain.hpp"

namespace py = pybind11;

namespace flexrock::python {

namespace {

using study::Distribution;
using study::UncertainParameter;

// a parameter from the keys of a manifest's [[uncertain]] table: the distribution's own two
// numbers, and a truncation for normal and lognormal
UncertainParameter make_parameter(const std::string& parameter, const std::string& distribution,
                                  std::optional<double> minimum, std::optional<double> maximum,
                                  std::optional<double> mean,
                                  std::optional<double> standard_deviation,
                                  std::optional<double> median, std::optional<double> beta,
                                  std::optional<double> lower, std::optional<double> upper) {
  const study::UncertainKindInfo* k = study::find_uncertain_kind(parameter);
  std::string names;
  for (const study::UncertainKindInfo& i : study::uncertain_kinds())
    names += std::string(names.empty() ? "" : ", ") + i.name;
  FLEXROCK_THROW_UNLESS(k != nullptr, "uncertain parameter: expected one of: " + names +
                                          ", got \"" + parameter + "\"");
  UncertainParameter p;
  p.kind = k->kind;
  // the keys a distribution takes, and those it refuses
  auto take = [&](const char* what, std::optional<double>& a, const char* a_name,
                  std::optional<double>& b, const char* b_name,
                  std::initializer_list<std::pair<const char*, std::optional<double>*>> others) {
    FLEXROCK_THROW_UNLESS(a && b, std::string("uncertain ") + parameter + ": a " + what +
                                      " distribution needs " + a_name + " and " + b_name);
    for (const auto& [name, v] : others) {
      FLEXROCK_THROW_UNLESS(!v->has_value(), std::string("uncertain ") + parameter + ": " + name +
                                                 " is not a key of a " + what + " distribution");
    }
    p.a = *a;
    p.b = *b;
  };
  if (distribution == "uniform") {
    p.distribution = Distribution::kUniform;
    take("uniform", minimum, "minimum", maximum, "maximum",
         {{"mean", &mean},
          {"standard_deviation", &standard_deviation},
          {"median", &median},
          {"beta", &beta},
          {"lower", &lower},
          {"upper", &upper}});
  } else if (distribution == "normal") {
    p.distribution = Distribution::kNormal;
    take("normal", mean, "mean", standard_deviation, "standard_deviation",
         {{"minimum", &minimum}, {"maximum", &maximum}, {"median", &median}, {"beta", &beta}});
  } else if (distribution == "lognormal") {
    p.distribution = Distribution::kLognormal;
    take("lognormal", median, "median", beta, "beta",
         {{"minimum", &minimum},
          {"maximum", &maximum},
          {"mean", &mean},
          {"standard_deviation", &standard_deviation}});
  } else {
    throw InputError("uncertain " + parameter +
                     ": distribution: expected one of: uniform, normal, lognormal, got \"" +
                     distribution + "\"");
  }
  p.lower = lower.value_or(-std::numeric_limits<double>::infinity());
  p.upper = upper.value_or(std::numeric_limits<double>::infinity());
  study::validate(p);
  return p;
}

void check_sample(const study::SampleDesign& d, std::size_t i) {
  if (i >= d.samples()) throw py::index_error("sample index out of range");
}

}  // namespace

void bind_uncertain(py::module_& m) {
  using namespace flexrock::study;

  py::enum_<UncertainKind>(m, "UncertainKind", "What an uncertain parameter varies.")
      .value("friction", UncertainKind::kFriction)
      .value("restitution_factor", UncertainKind::kRestitutionFactor)
      .value("restitution_ratio", UncertainKind::kRestitutionRatio)
      .value("size_scale", UncertainKind::kSizeScale)
      .value("base_width_scale", UncertainKind::kBaseWidthScale)
      .value("cg_height_scale", UncertainKind::kCgHeightScale)
      .value("mass_scale", UncertainKind::kMassScale)
      .value("frequency_scale", UncertainKind::kFrequencyScale)
      .value("damping_ratio", UncertainKind::kDampingRatio);
  py::enum_<Distribution>(m, "Distribution")
      .value("uniform", Distribution::kUniform)
      .value("normal", Distribution::kNormal)
      .value("lognormal", Distribution::kLognormal);
  py::enum_<SamplingMethod>(m, "SamplingMethod")
      .value("random", SamplingMethod::kRandom)
      .value("lhs", SamplingMethod::kLatinHypercube);
  py::enum_<SamplingScope>(m, "SamplingScope",
                           "Which runs share a realisation: each (record, level) run its own, or "
                           "one per record at every level.")
      .value("run", SamplingScope::kRun)
      .value("record", SamplingScope::kRecord);

  py::class_<UncertainParameter>(m, "UncertainParameter",
                                 "A distribution of an uncertain parameter, as a manifest's "
                                 "[[uncertain]] table gives it.")
      .def(py::init(&make_parameter), py::arg("parameter"), py::arg("distribution"), py::kw_only(),
           py::arg("minimum") = py::none(), py::arg("maximum") = py::none(),
           py::arg("mean") = py::none(), py::arg("standard_deviation") = py::none(),
           py::arg("median") = py::none(), py::arg("beta") = py::none(),
           py::arg("lower") = py::none(), py::arg("upper") = py::none(),
           R"doc(A distribution of a parameter, checked as the manifest's are.

Parameters
----------
parameter : str
    A name of ``uncertain_parameters()``: "friction", "size_scale", ...
distribution : str
    "uniform" (``minimum``, ``maximum``), "normal" (``mean``, ``standard_deviation``) or
    "lognormal" (``median``, ``beta``: the standard deviation of ln x).
lower, upper : float, optional
    Truncation of a normal or lognormal distribution.

Raises
------
ValueError
    A bad number, a key the distribution does not take, or values outside the parameter's
    domain (a normal friction without ``lower`` > 0).)doc")
      .def_readonly("kind", &UncertainParameter::kind)
      .def_readonly("distribution", &UncertainParameter::distribution)
      .def_readonly("a", &UncertainParameter::a, "minimum, mean or median")
      .def_readonly("b", &UncertainParameter::b, "maximum, standard deviation or beta")
      .def_readonly("lower", &UncertainParameter::lower)
      .def_readonly("upper", &UncertainParameter::upper);
  py::class_<Sampling>(m, "Sampling", "How a study samples its uncertain parameters.")
      .def(py::init([](std::uint64_t seed, SamplingMethod method, SamplingScope scope) {
             return Sampling{seed, method, scope};
           }),
           py::arg("seed") = 0, py::arg("method") = SamplingMethod::kRandom,
           py::arg("scope") = SamplingScope::kRun)
      .def_readwrite("seed", &Sampling::seed)
      .def_readwrite("method", &Sampling::method)
      .def_readwrite("scope", &Sampling::scope);
  py::class_<Uncertainty>(m, "Uncertainty",
                          "The uncertain parameters of a study (SweepSpec.uncertainty).")
      .def(py::init([](std::vector<UncertainParameter> parameters, Sampling sampling) {
             Uncertainty u{std::move(parameters), sampling};
             validate(u);
             return u;
           }),
           py::arg("parameters") = std::vector<UncertainParameter>{},
           py::arg("sampling") = Sampling{})
      .def_readwrite("parameters", &Uncertainty::parameters)
      .def_readwrite("sampling", &Uncertainty::sampling);
  py::class_<SampleDesign>(m, "SampleDesign",
                           "The samples of a study: each a pure function of the seed and its "
                           "index.")
      .def(py::init<const Uncertainty&, std::size_t>(), py::arg("uncertainty"), py::arg("samples"))
      .def_property_readonly("samples", &SampleDesign::samples)
      .def_property_readonly("dimensions", &SampleDesign::dimensions)
      .def(
          "uniform",
          [](const SampleDesign& d, std::size_t i, std::size_t k) {
            check_sample(d, i);
            if (k >= d.dimensions()) throw py::index_error("parameter index out of range");
            return d.uniform(i, k);
          },
          py::arg("sample"), py::arg("parameter"),
          "The uniform in (0, 1) of a sample and parameter (Latin hypercube: inside its stratum).")
      .def(
          "values",
          [](const SampleDesign& d, std::size_t i) {
            check_sample(d, i);
            return d.values(i);
          },
          py::arg("sample"), "The values of a sample, one per parameter.");
  m.def(
      "uncertain_quantile",
      [](const UncertainParameter& p, double u) {
        FLEXROCK_THROW_UNLESS(u > 0.0 && u < 1.0, "uncertain_quantile: expected u in (0, 1)");
        return quantile(p, u);
      },
      py::arg("parameter"), py::arg("u"),
      "The value of a parameter at probability u in (0, 1) (its truncated inverse CDF).");
  m.def(
      "uncertain_parameters",
      [] {
        py::list out;
        for (const UncertainKindInfo& k : uncertain_kinds()) {
          py::dict d;
          d["name"] = k.name;
          d["column"] = k.column;
          d["unit"] = k.unit;
          d["domain"] = k.domain;
          d["doc"] = k.doc;
          out.append(d);
        }
        return out;
      },
      R"doc(The table of uncertain parameters (the one manifests, the sweep columns and the docs
are written from).

Returns
-------
list of dict
    name, column, unit, domain, doc.)doc");
}

}  // namespace flexrock::python
