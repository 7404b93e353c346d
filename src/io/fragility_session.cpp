// SPDX-License-Identifier: BSD-3-Clause
// The fragility session: options checked in the order `flexrock fragility` reports them, the
// observations and fits of every damage state and body, the notes on the states' order and the
// fit CSV.
#include "flexrock/io/fragility_session.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <utility>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"

namespace flexrock::io {

namespace {

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + v[i];
  return s;
}

}  // namespace

FragilitySession::FragilitySession(const std::string& path, FragilityOptions options)
    : FragilitySession(read_csv_table(path), std::move(options)) {}

FragilitySession::FragilitySession(CsvTable table, FragilityOptions options)
    : table_(std::move(table)), options_(std::move(options)) {
  // the damage states: a family given least severe first, or the one of outcome and level
  several_ = !options_.states.empty();
  if (several_) {
    const std::vector<DamageState>& st = options_.states;
    for (std::size_t a = 0; a < st.size(); ++a) {
      const FragilityOutcomeInfo& o = fragility_outcome(st[a].outcome);
      if (o.levelled && !(st[a].level > 0.0 && std::isfinite(st[a].level))) {
        throw InputError("--state '" + st[a].label + "': expected a level > 0");
      }
      for (std::size_t b = 0; b < a; ++b) {
        if (st[a].outcome == st[b].outcome && st[a].level == st[b].level)
          throw InputError("--state '" + st[a].label + "': given twice");
      }
    }
    states_ = st;
  } else {
    const FragilityOutcomeInfo& o = fragility_outcome(options_.outcome);
    if (o.levelled && !(options_.level > 0.0)) {
      throw InputError("--level: expected a number > 0 with --outcome " + std::string(o.name));
    }
    states_.push_back({o.name, options_.outcome, options_.level});
  }
  if (!(options_.confidence > 0.0 && options_.confidence < 1.0)) {
    throw InputError("--confidence: expected a number in (0, 1), got " +
                     format_number(options_.confidence));
  }
  // a multiple-stripe analysis: the stripes are the sweep's levels
  if (options_.analysis == FragilityAnalysis::kStripes) {
    if (options_.im_given && options_.im != "requested_level") {
      throw InputError(
          "--analysis msa: the stripes are the sweep's requested levels (target "
          "intensity measures, or factors); --im " +
          options_.im + " is not one value per stripe: leave --im out");
    }
    options_.im = "requested_level";
  }
  // the table, then the measure (a measure it lacks is named with the file)
  check_sweep_table(table_);
  measure_ = fragility_measure(options_.im);
  // sa:T is in the unit the sweep wrote it in: the column of that unit (sa_T1_z0.05_g)
  if (measure_.kind == FragilityMeasureKind::kIntensity &&
      std::find(table_.columns.begin(), table_.columns.end(), measure_.column) ==
          table_.columns.end()) {
    for (const char* u : {"g", "cm/s^2"}) {
      study::MeasureRequest r = measure_.request;
      r.unit = u;
      try {
        const std::string c = study::measure_column(r);
        if (std::find(table_.columns.begin(), table_.columns.end(), c) != table_.columns.end()) {
          measure_.request = r;
          measure_.column = c;
          measure_.unit = u;
          break;
        }
      } catch (const InputError&) {
        break;  // a measure without units
      }
    }
  }
  unit_ = measure_.unit;
  if (measure_.kind == FragilityMeasureKind::kRequestedLevel && !table_.rows.empty()) {
    const auto c = static_cast<std::size_t>(
        std::find(table_.columns.begin(), table_.columns.end(), "requested_units") -
        table_.columns.begin());
    if (c < table_.columns.size()) unit_ = table_.rows.front()[c];
  }
  const double confidence = options_.confidence;
  auto fit_data = [&](const FragilityData& d) {
    switch (options_.analysis) {
      case FragilityAnalysis::kStripes:
        return study::fit_stripes(study::stripes_of(d.im, d.failed), confidence);
      case FragilityAnalysis::kCapacities:
        return study::fit_capacity_intervals(study::capacity_intervals(d.im, d.failed, d.record),
                                             confidence);
      case FragilityAnalysis::kRuns:
        break;
    }
    return study::fit_lognormal(d.im, d.failed, confidence);
  };
  // one body or state that cannot be fitted does not stop the others: its reason is kept
  std::vector<std::string> reasons;
  for (const DamageState& st : states_) {
    data_.push_back(fragility_data(table_, measure_, st, options_.body, options_.worst_azimuth));
    fits_.emplace_back();
    not_fitted_.emplace_back();
    for (const FragilityData& d : data_.back()) {
      try {
        fits_.back().push_back(fit_data(d));
        not_fitted_.back().emplace_back();
      } catch (const InputError& e) {
        fits_.back().emplace_back();
        not_fitted_.back().push_back(table_.source + ": body '" + d.body + "'" +
                                     (several_ ? ", state '" + st.label + "'" : std::string()) +
                                     ": " + e.what());
        reasons.push_back(not_fitted_.back().back());
      }
    }
  }
  if (fitted_count() == 0) {
    // the one reason as it is, or every one
    std::string all = reasons.front();
    if (reasons.size() > 1) {
      all = "nothing could be fitted:";
      for (const std::string& r : reasons) all += "\n  " + r;
    }
    throw InputError(all);
  }
}

bool FragilitySession::fitted(std::size_t state, std::size_t body) const {
  return not_fitted_.at(state).at(body).empty();
}

const std::string& FragilitySession::not_fitted(std::size_t state, std::size_t body) const {
  return not_fitted_.at(state).at(body);
}

std::size_t FragilitySession::fitted_count() const {
  std::size_t n = 0;
  for (const std::vector<std::string>& st : not_fitted_) {
    for (const std::string& r : st) n += r.empty() ? 1 : 0;
  }
  return n;
}

const FragilityData& FragilitySession::data(std::size_t state, std::size_t body) const {
  return data_.at(state).at(body);
}

const study::FragilityFit& FragilitySession::fit(std::size_t state, std::size_t body) const {
  if (!fitted(state, body)) throw InputError(not_fitted(state, body));
  return fits_.at(state).at(body);
}

std::vector<study::Stripe> FragilitySession::stripes(std::size_t state, std::size_t body) const {
  const FragilityData& d = data(state, body);
  return study::stripes_of(d.im, d.failed);
}

std::pair<double, double> FragilitySession::range(std::size_t body, std::size_t a,
                                                  std::size_t b) const {
  const std::vector<double>&x = data(a, body).im, &y = data(b, body).im;
  return {std::min(*std::min_element(x.begin(), x.end()), *std::min_element(y.begin(), y.end())),
          std::max(*std::max_element(x.begin(), x.end()), *std::max_element(y.begin(), y.end()))};
}

std::vector<FragilityOrderNote> FragilitySession::order_notes() const {
  // the states are given least severe first: a more severe state's curve must lie below
  std::vector<FragilityOrderNote> notes;
  for (std::size_t k = 0; k < bodies(); ++k) {
    for (std::size_t s = 1; s < states_.size(); ++s) {
      if (!fitted(s - 1, k) || !fitted(s, k)) continue;
      const study::FragilityFit &a = fit(s - 1, k), &b = fit(s, k);
      const auto [lo, hi] = range(k, s - 1, s);
      FragilityOrderNote n;
      n.body = k;
      n.state = s;
      n.medians_cross = b.theta < a.theta;
      const double x = study::crossing_intensity(a, b);
      n.crossing =
          std::isfinite(x) && x >= lo && x <= hi ? x : std::numeric_limits<double>::quiet_NaN();
      n.latter_likelier_above = a.beta < b.beta;
      if (n.medians_cross || !std::isnan(n.crossing)) notes.push_back(n);
    }
  }
  return notes;
}

void FragilitySession::write_fits(std::ostream& out) const {
  out << joined(several_ ? fragility_state_columns() : fragility_columns()) << '\n';
  for (std::size_t k = 0; k < bodies(); ++k) {
    for (std::size_t s = 0; s < states_.size(); ++s) {
      if (!fitted(s, k)) continue;
      out << (several_ ? fragility_state_row(data(s, k), fit(s, k), states_[s].label)
                       : fragility_row(data(s, k), fit(s, k)))
          << '\n';
    }
  }
}

}  // namespace flexrock::io
