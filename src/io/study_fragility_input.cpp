// SPDX-License-Identifier: BSD-3-Clause
// Fragility input: a sweep CSV read as a table, the observations of a damage state, the fit
// CSV's columns and the damage states of --state.
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <variant>

#include "flexrock/core/error.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/io/study_files.hpp"
#include "study_internal.hpp"
#include "table_reader.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;
using namespace study_detail;

// ---------------------------------------------------------------------------------------------
// fragility input

std::size_t CsvTable::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) {
    throw InputError(source + ":1: no column '" + name + "'; the columns are: " + join(columns));
  }
  return static_cast<std::size_t>(it - columns.begin());
}

CsvTable read_csv_table(const std::string& path) {
  std::istringstream in(read_input_file(path, "CSV"));
  CsvTable t;
  t.source = path;
  auto split = [](const std::string& line) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
      const std::size_t c = line.find(',', start);
      out.push_back(line.substr(start, c == std::string::npos ? std::string::npos : c - start));
      if (c == std::string::npos) break;
      start = c + 1;
    }
    return out;
  };
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (t.columns.empty()) {
      t.columns = split(line);
      continue;
    }
    std::vector<std::string> f = split(line);
    if (f.size() != t.columns.size()) {
      throw InputError(path + ":" + std::to_string(n) + ": expected " +
                       std::to_string(t.columns.size()) + " fields (as the header), got " +
                       std::to_string(f.size()));
    }
    t.rows.push_back(std::move(f));
    t.lines.push_back(n);
  }
  if (t.columns.empty()) throw InputError(path + ": empty CSV file, expected a header row");
  return t;
}

const FragilityOutcomeInfo& fragility_outcome(FragilityOutcome outcome) {
  for (const FragilityOutcomeInfo& o : kFragilityOutcomes) {
    if (o.outcome == outcome) return o;
  }
  FLEXROCK_DEMAND(false);
  return kFragilityOutcomes[0];
}

const FragilityOutcomeInfo* find_fragility_outcome(std::string_view name) {
  for (const FragilityOutcomeInfo& o : kFragilityOutcomes) {
    if (name == o.name) return &o;
  }
  return nullptr;
}

namespace {

// the measures every sweep writes: kind, name, column, unit
struct FixedMeasure {
  FragilityMeasureKind kind;
  const char* name;
  const char* column;
  const char* unit;
};
constexpr FixedMeasure kFixedMeasures[] = {
    {FragilityMeasureKind::kPga, "pga", "pga_m_per_s2", "m/s^2"},
    {FragilityMeasureKind::kPgaG, "pga_g", "pga_g", "g"},
    {FragilityMeasureKind::kPgv, "pgv", "pgv_m_per_s", "m/s"},
    {FragilityMeasureKind::kScale, "scale", "scale", "-"},
    {FragilityMeasureKind::kRequestedLevel, "requested_level", "requested_level", "-"},
};

}  // namespace

std::vector<std::string> fragility_measures() {
  std::vector<std::string> v;
  for (const FixedMeasure& m : kFixedMeasures) v.emplace_back(m.name);
  for (const IntensityMeasure& m : intensity_measures()) {
    if (m.always_written) continue;
    v.push_back(m.needs_period ? std::string(m.name) + ":T[:zeta]" : std::string(m.name));
  }
  return v;
}

FragilityMeasure fragility_measure(const std::string& im) {
  FragilityMeasure out;
  out.name = im;
  for (const FixedMeasure& m : kFixedMeasures) {
    if (im == m.name) {
      out.kind = m.kind;
      out.column = m.column;
      out.unit = m.unit;
      return out;
    }
  }
  auto bad = [&](const std::string& why) {
    throw InputError("fragility: intensity measure '" + im + "': " + why +
                     "expected one of: " + join(fragility_measures()));
  };
  try {
    out.request = study::measure_request(im);
  } catch (const InputError& e) {
    bad(std::string(e.what()) + "; ");
  }
  const IntensityMeasure* k = find_intensity_measure(out.request.name);
  if (k->always_written) bad("");
  out.kind = FragilityMeasureKind::kIntensity;
  out.column = study::measure_column(out.request);
  out.unit = k->unit;
  return out;
}

std::string fragility_im_column(const std::string& im) { return fragility_measure(im).column; }

namespace {

// the observations of a checked table: `outcome` null for a name no row of kFragilityOutcomes
// has (`outcome_name`), refused after the measure's column is found
std::vector<FragilityData> observations(const CsvTable& t, const FragilityMeasure& m,
                                        const FragilityOutcomeInfo* outcome,
                                        const std::string& outcome_name, double level,
                                        const std::string& body_name, bool worst_azimuth) {
  const std::string& im_col = m.column;
  if (std::find(t.columns.begin(), t.columns.end(), im_col) == t.columns.end()) {
    throw InputError(t.source + ":1: intensity measure '" + m.name + "' needs the column '" +
                     im_col +
                     "', which this sweep did not write: name it in the manifest's [intensity] "
                     "table (docs/studies.md) and run the sweep again");
  }
  if (!outcome) {
    std::vector<std::string> names;
    for (const FragilityOutcomeInfo& o : kFragilityOutcomes) names.emplace_back(o.name);
    throw InputError("fragility: outcome '" + outcome_name + "': expected one of: " + join(names));
  }
  const std::string out_col = outcome->column;
  if (outcome->sliding &&
      std::find(t.columns.begin(), t.columns.end(), out_col) == t.columns.end()) {
    throw InputError(t.source + ":1: outcome '" + outcome_name + "' needs the column '" + out_col +
                     "', which a sweep writes only with a finite friction coefficient "
                     "(docs/studies.md); this file has none");
  }
  const std::size_t cr = static_cast<std::size_t>(
      std::find(t.columns.begin(), t.columns.end(), "record") - t.columns.begin());
  const std::size_t ci = t.column(im_col), co = t.column(out_col), cb = t.column("body"),
                    cs = t.column("outcome"), cv = t.column("overturned");
  auto number = [&](std::size_t r, std::size_t c) {
    double v = 0.0;
    const std::string& s = t.rows[r][c];
    const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(v)) {
      throw InputError(t.source + ":" + std::to_string(t.lines[r]) + ": column '" + t.columns[c] +
                       "': expected a finite number, got \"" + s + "\"");
    }
    return v;
  };
  // the measure's unit: requested levels are in the sweep's requested_units
  std::string unit = m.unit;
  const std::size_t cu = static_cast<std::size_t>(
      std::find(t.columns.begin(), t.columns.end(), "requested_units") - t.columns.begin());
  if (m.kind == FragilityMeasureKind::kRequestedLevel && cu < t.columns.size() && !t.rows.empty()) {
    unit = t.rows.front()[cu];
  }
  // worst azimuth: the rows of one station (the record's name before '@', a [[suite]] pair) at one
  // requested level make one observation (below)
  const std::size_t cl = static_cast<std::size_t>(
      std::find(t.columns.begin(), t.columns.end(), "requested_level") - t.columns.begin());
  const std::size_t csc = static_cast<std::size_t>(
      std::find(t.columns.begin(), t.columns.end(), "scale") - t.columns.begin());
  struct Station {
    std::size_t data = 0;  // index into `out`
    std::string key;       // record before '@', requested level
    std::vector<double> im;
    std::string scale;  // the factor of every azimuth: the same, or the station is refused
    std::size_t line = 0;
    bool failed = false, stopped = false;
  };
  std::vector<Station> stations;
  std::map<std::string, std::size_t> station_of;
  if (worst_azimuth &&
      (cr >= t.columns.size() || cl >= t.columns.size() || csc >= t.columns.size())) {
    throw InputError(t.source +
                     ":1: --worst-azimuth needs the columns record, requested_level and scale "
                     "of a sweep CSV");
  }
  std::vector<FragilityData> out;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::string& body = t.rows[r][cb];
    if (!body_name.empty() && body != body_name) continue;
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const FragilityData& d) { return d.body == body; });
    if (it == out.end()) {
      out.push_back({body, {}, {}, 0, {}, worst_azimuth ? "rotd50:" + m.name : m.name, unit});
      it = out.end() - 1;
    }
    Station* st = nullptr;
    if (worst_azimuth) {
      const std::string& rec = t.rows[r][cr];
      const std::size_t at = rec.rfind('@');
      if (at == std::string::npos) {
        throw InputError(t.source + ":" + std::to_string(t.lines[r]) + ": record '" + rec +
                         "' is not one azimuth of a record pair (`<H1>+<H2>@<azimuth>`, a "
                         "[[suite]] with horizontal2): --worst-azimuth needs pairs");
      }
      const std::string key = body + "\n" + rec.substr(0, at) + "\n" + t.rows[r][cl];
      const auto [pos, fresh] = station_of.emplace(key, stations.size());
      if (fresh) {
        stations.push_back({static_cast<std::size_t>(it - out.begin()),
                            rec.substr(0, at),
                            {},
                            t.rows[r][csc],
                            t.lines[r]});
      }
      st = &stations[pos->second];
      if (t.rows[r][csc] != st->scale) {
        throw InputError(t.source + ":" + std::to_string(t.lines[r]) + ": the azimuths of '" +
                         st->key + "' at level " + t.rows[r][cl] + " were scaled by " + st->scale +
                         " and " + t.rows[r][csc] +
                         ": --worst-azimuth needs every azimuth of a station scaled alike "
                         "([scales] factors)");
      }
    }
    // not classified: the run could not go on (`contact_lost`: rows written before the engine
    // followed flight)
    const std::string& run_outcome = t.rows[r][cs];
    if (run_outcome == study::to_string(study::Outcome::kStopped) ||
        run_outcome == "contact_lost") {
      if (st) {
        st->stopped = true;
      } else {
        ++it->excluded;
      }
      continue;
    }
    const double x = number(r, ci);
    int y = 0;
    if (outcome->outcome == FragilityOutcome::kOverturned) {
      y = number(r, co) != 0.0 ? 1 : 0;
    } else if (outcome->outcome == FragilityOutcome::kUplift) {
      // every class but no_uplift left full contact (rocked, or overturned)
      y = run_outcome != study::to_string(study::Outcome::kNoUplift) ? 1 : 0;
    } else {
      // an overturned body exceeds every tilt, energy and offset level; a residual offset counts
      // either way
      y = (number(r, cv) != 0.0 || std::abs(number(r, co)) > level) ? 1 : 0;
    }
    if (st) {
      st->im.push_back(x);
      st->failed = st->failed || y != 0;
      continue;
    }
    it->im.push_back(x);
    it->failed.push_back(y);
    it->record.push_back(cr < t.columns.size() ? t.rows[r][cr] : std::string());
  }
  // a station fails if any azimuth fails; its measure is the median over the azimuths (RotD50 of
  // the measure on the grid: a measure at beta + 180 is the one at beta, so the median over [0,
  // 360) is the one over [0, 180)). A stopped azimuth leaves the station unknown unless another
  // failed
  for (Station& st : stations) {
    FragilityData& d = out[st.data];
    if (st.im.empty() || (st.stopped && !st.failed)) {
      ++d.excluded;
      continue;
    }
    std::sort(st.im.begin(), st.im.end());
    const std::size_t n = st.im.size();
    d.im.push_back(n % 2 ? st.im[n / 2] : 0.5 * (st.im[n / 2 - 1] + st.im[n / 2]));
    d.failed.push_back(st.failed ? 1 : 0);
    d.record.push_back(st.key);
  }
  if (out.empty()) {
    throw InputError(
        t.source + ": " +
        (body_name.empty() ? std::string("no rows") : "no rows of body '" + body_name + "'"));
  }
  return out;
}

}  // namespace

std::vector<FragilityData> fragility_data(const CsvTable& t, const FragilityQuery& q) {
  check_sweep_table(t);
  return observations(t, fragility_measure(q.im), find_fragility_outcome(q.outcome), q.outcome,
                      q.level, q.body, q.worst_azimuth);
}

std::vector<FragilityData> fragility_data(const CsvTable& t, const FragilityMeasure& measure,
                                          const DamageState& state, const std::string& body,
                                          bool worst_azimuth) {
  check_sweep_table(t);
  const FragilityOutcomeInfo& o = fragility_outcome(state.outcome);
  return observations(t, measure, &o, o.name, state.level, body, worst_azimuth);
}

namespace {

// one column of the fragility fit CSV: name, unit, meaning and its field of a body's fit. The
// header, the rows and the column reference of docs/studies.md are written from this table
struct FragilityColumn {
  const char* name;
  const char* unit;
  const char* doc;
  std::string (*field)(const FragilityData& d, const study::FragilityFit& f);
};

using Fit = study::FragilityFit;

const FragilityColumn kFragilityColumns[] = {
    {"body", "-", "name of the body", [](const FragilityData& d, const Fit&) { return d.body; }},
    {"samples", "-", "observations used",
     [](const FragilityData&, const Fit& f) { return std::to_string(f.samples); }},
    {"failures", "-", "of which failed",
     [](const FragilityData&, const Fit& f) { return std::to_string(f.failures); }},
    {"excluded", "-", "rows left out: outcome `stopped` or `contact_lost`",
     [](const FragilityData& d, const Fit&) { return std::to_string(d.excluded); }},
    {"theta", "IM", "median capacity, in the units of the intensity measure",
     [](const FragilityData&, const Fit& f) { return field(f.theta); }},
    {"beta", "-", "lognormal standard deviation",
     [](const FragilityData&, const Fit& f) { return field(f.beta); }},
    {"se_ln_theta", "-", "standard error of ln(theta)",
     [](const FragilityData&, const Fit& f) { return field(f.se_ln_theta); }},
    {"se_beta", "-", "standard error of beta",
     [](const FragilityData&, const Fit& f) { return field(f.se_beta); }},
    {"confidence", "-", "level of the bounds (two-sided)",
     [](const FragilityData&, const Fit& f) { return field(f.confidence); }},
    {"theta_lower", "IM", "lower bound on theta",
     [](const FragilityData&, const Fit& f) { return field(f.theta_lower); }},
    {"theta_upper", "IM", "upper bound on theta",
     [](const FragilityData&, const Fit& f) { return field(f.theta_upper); }},
    {"beta_lower", "-", "lower bound on beta (>= 0)",
     [](const FragilityData&, const Fit& f) { return field(f.beta_lower); }},
    {"beta_upper", "-", "upper bound on beta",
     [](const FragilityData&, const Fit& f) { return field(f.beta_upper); }},
    {"log_likelihood", "-", "at the maximum",
     [](const FragilityData&, const Fit& f) { return field(f.log_likelihood); }},
    {"im_name", "-",
     "the intensity measure fitted, as `--im` names it (`pga_g`, `sa:1`, `requested_level`, ...)",
     [](const FragilityData& d, const Fit&) { return d.im_name; }},
    {"im_unit", "-", "its unit: the unit of `theta`, `theta_lower` and `theta_upper`",
     [](const FragilityData& d, const Fit&) { return d.im_unit; }},
};

}  // namespace

std::vector<std::string> fragility_columns() {
  std::vector<std::string> v;
  for (const FragilityColumn& c : kFragilityColumns) v.emplace_back(c.name);
  return v;
}

std::string fragility_row(const FragilityData& d, const study::FragilityFit& f) {
  std::string s;
  for (const FragilityColumn& col : kFragilityColumns) {
    if (&col != kFragilityColumns) s += ',';
    s += col.field(d, f);
  }
  return s;
}

std::vector<std::string> fragility_state_columns() {
  std::vector<std::string> v = fragility_columns();
  v.insert(v.begin() + 1, "state");
  return v;
}

std::string fragility_state_row(const FragilityData& d, const study::FragilityFit& f,
                                const std::string& state) {
  const std::string row = fragility_row(d, f);
  // after the body field (body names hold no commas)
  const std::size_t comma = row.find(',');
  return row.substr(0, comma) + "," + state + row.substr(comma);
}

DamageState damage_state(const std::string& text) {
  const std::size_t colon = text.find(':');
  // "expected overturned, uplift, theta:X (...), ... or residual_offset:X (...), X a number > 0"
  std::string expected = "expected ";
  for (const FragilityOutcomeInfo& o : kFragilityOutcomes) {
    if (&o != kFragilityOutcomes)
      expected += &o == std::end(kFragilityOutcomes) - 1 ? " or " : ", ";
    expected += o.state_doc;
  }
  expected += ", X a number > 0";
  const FragilityOutcomeInfo* o = find_fragility_outcome(text.substr(0, colon));
  if (!o) throw InputError("--state '" + text + "': " + expected);
  DamageState s;
  s.label = text;
  s.outcome = o->outcome;
  if (o->levelled != (colon != std::string::npos)) {
    throw InputError("--state '" + text + "': " +
                     (o->levelled ? "a level is missing; " : "takes no level; ") + expected);
  }
  if (o->levelled) {
    const std::string level = text.substr(colon + 1);
    const auto r = std::from_chars(level.data(), level.data() + level.size(), s.level);
    if (level.empty() || r.ec != std::errc() || r.ptr != level.data() + level.size() ||
        !(s.level > 0.0) || !std::isfinite(s.level)) {
      throw InputError("--state '" + text + "': \"" + level + "\" is not a number > 0; " +
                       expected);
    }
  }
  return s;
}

std::string study_detail::fragility_column_block() {
  return column_block<FragilityColumn>("fragility fit", "src/io/study_fragility_input.cpp",
                                       kFragilityColumns);
}

}  // namespace flexrock::io
