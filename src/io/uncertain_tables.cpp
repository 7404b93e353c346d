// SPDX-License-Identifier: BSD-3-Clause
#include "uncertain_tables.hpp"

#include <limits>
#include <string>
#include <vector>

namespace flexrock::io::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// the keys of each distribution: its two numbers, and whether it may be truncated
struct DistributionKeys {
  study::Distribution distribution;
  const char* name;
  const char* a;
  const char* b;
  const char* what_b;
  bool truncated;
};

const DistributionKeys kDistributions[] = {
    {study::Distribution::kUniform, "uniform", "minimum", "maximum", "a number > minimum", false},
    {study::Distribution::kNormal, "normal", "mean", "standard_deviation", "a number > 0", true},
    {study::Distribution::kLognormal, "lognormal", "median", "beta",
     "a number > 0 (the standard deviation of ln x)", true},
};

study::UncertainParameter read_parameter(TableReader& t) {
  std::vector<std::string> kinds, dists;
  for (const study::UncertainKindInfo& k : study::uncertain_kinds()) kinds.emplace_back(k.name);
  for (const DistributionKeys& d : kDistributions) dists.emplace_back(d.name);
  study::UncertainParameter p;
  p.kind = study::find_uncertain_kind(t.choice("parameter", kinds))->kind;
  const std::string dist = t.choice("distribution", dists);
  const DistributionKeys* d = nullptr;
  for (const DistributionKeys& k : kDistributions) {
    if (dist == k.name) d = &k;
  }
  p.distribution = d->distribution;
  const std::string unit = std::string(" [") + study::uncertain_kind(p.kind).unit + "]";
  const std::string what_a =
      p.distribution == study::Distribution::kLognormal ? "a number > 0" + unit : "a number" + unit;
  p.a = t.number(d->a, what_a);
  if (p.distribution == study::Distribution::kLognormal && !(p.a > 0.0)) t.expected(d->a, what_a);
  p.b = t.number(d->b, d->what_b + unit);
  if (!(p.distribution == study::Distribution::kUniform ? p.b > p.a : p.b > 0.0))
    t.expected(d->b, d->what_b + unit);
  if (d->truncated) {
    p.lower = t.number_opt("lower", "a number" + unit + " (the truncation's lower end)", true)
                  .value_or(-kInf);
    p.upper =
        t.number_opt("upper", "a number > lower" + unit + " (the truncation's upper end)", true)
            .value_or(kInf);
    if (!(p.lower < p.upper)) t.expected("upper", "a number > lower" + unit);
  }
  t.finish(std::string("for a ") + d->name +
           " distribution in [[uncertain]] (see docs/studies.md)");
  // a truncation that keeps nothing, values outside the parameter's domain
  try {
    study::validate(p);
  } catch (const InputError& e) {
    const char* key = t.has("lower") ? "lower" : t.has("upper") ? "upper" : "distribution";
    t.fail(key, e.what());
  }
  return p;
}

}  // namespace

void read_uncertainty(TableReader& top, study::SweepSpec& spec) {
  if (!top.has("uncertain")) {
    if (top.has("sampling"))
      top.fail("sampling", "expected only with [[uncertain]] parameters to sample");
    return;
  }
  std::vector<TableReader> tables =
      top.tables("uncertain", "an uncertain parameter: { parameter, distribution, ... }");
  study::Uncertainty& u = spec.uncertainty;
  for (TableReader& t : tables) {
    const study::UncertainParameter p = read_parameter(t);
    for (const study::UncertainParameter& q : u.parameters) {
      if (q.kind == p.kind)
        t.fail("parameter", std::string("\"") + study::uncertain_kind(p.kind).name +
                                "\" given twice; expected one [[uncertain]] per parameter");
    }
    // the parameter against each body and the impact law, at its median
    const std::vector<double> median(1, study::quantile(p, 0.5));
    study::Uncertainty one;
    one.parameters = {p};
    for (const study::SweepBody& b : spec.bodies) {
      try {
        (void)study::apply(one, median, b.body);
      } catch (const InputError& e) {
        t.fail("parameter", "body '" + b.name + "': " + e.what());
      }
    }
    const bool restitution_law = takes_measured_ratio(spec.solver.impact_law);
    if (p.kind == study::UncertainKind::kRestitutionRatio && !restitution_law) {
      t.fail("parameter",
             "restitution_ratio is the ratio of impact_law = \"restitution\"; expected that law "
             "in [solver], or restitution_factor for the paper and rigid_body laws");
    }
    if (p.kind == study::UncertainKind::kRestitutionFactor && restitution_law) {
      t.fail("parameter",
             "impact_law = \"restitution\" takes restitution_ratio; restitution_factor is for the "
             "paper and rigid_body laws");
    }
    u.parameters.push_back(p);
  }
  if (auto s = top.table_opt("sampling")) {
    const long seed = s->integer_or("seed", 0, 0, "an integer >= 0");
    u.sampling.seed = static_cast<std::uint64_t>(seed);
    u.sampling.method = s->choice("method", {"random", "lhs"}, "random") == "lhs"
                            ? study::SamplingMethod::kLatinHypercube
                            : study::SamplingMethod::kRandom;
    u.sampling.scope = s->choice("per", {"run", "record"}, "run") == "record"
                           ? study::SamplingScope::kRecord
                           : study::SamplingScope::kRun;
    s->finish("in [sampling] (see docs/studies.md)");
  }
}

std::string uncertain_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of uncertain parameters "
      "(src/study/uncertain.cpp); edit the table, not these lines -->\n"
      "| parameter | column | unit | values | what a sampled value changes |\n"
      "|---|---|---|---|---|\n";
  for (const study::UncertainKindInfo& k : study::uncertain_kinds()) {
    s.append("| `").append(k.name).append("` | `").append(k.column).append("` | ").append(k.unit);
    s.append(" | ").append(k.domain).append(" | ").append(k.doc).append(" |\n");
  }
  return s + "<!-- end: written by `flexrock keys --markdown` -->\n";
}

}  // namespace flexrock::io::detail
