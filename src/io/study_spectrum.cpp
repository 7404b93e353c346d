// SPDX-License-Identifier: BSD-3-Clause
// Spectrum files: the spec reader, the cells and boundary CSVs (tables of columns) and their
// lines read back from a journal.
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
// spectrum

SpectrumFile load_spectrum_file(const std::string& path) {
  const toml::table doc = detail::parse_toml(path, "spectrum");
  Keys top(path, doc, "");
  SpectrumFile f;
  f.source = path;
  f.name = top.string_opt("name", "a string").value_or(fs::path(path).stem().string());
  top.string_opt("description", "a string");
  // the body: a path, or this file's own [body] table
  const bool inline_body = top.has("body") && doc.get("body")->is_table();
  if (inline_body) {
    f.body_source = path;
  } else {
    const std::string b = top.string("body",
                                     "a path to a case or body file with a [body] table, "
                                     "or a [body] table here");
    f.body_source = detail::resolve_path(path, b);
  }
  f.input_files.push_back(path);
  refuse_restraints(f.body_source, "a spectrum study");
  std::string body_type;
  f.body = load_body(f.body_source, &body_type, &f.input_files);
  refuse_frame(body_type, f.body_source);
  f.hash = fnv1a(file_bytes(path));
  if (!inline_body) f.hash = fnv1a(file_bytes(f.body_source), f.hash);
  SimulationOptions solver = study::study_solver_defaults();
  if (auto s = top.table_opt("solver")) read_solver(*s, solver, f.body);
  auto sp = top.table_opt("spectrum");
  if (!sp)
    throw InputError(
        path + ": table [spectrum]: missing; expected a [spectrum] table (see docs/studies.md)");
  Keys& s = *sp;
  const double free_periods = s.nonnegative_or("free_periods", 4.0, "[-] (rocking periods 2 pi/p)");
  const bool bisect = s.boolean_or("bisect", true);
  const double tol = s.positive_or("bisection_tolerance", 1e-3, "[-] (relative)");
  if (!(tol < 1.0) || tol < study::kMinBisectionTolerance) {
    s.expected("bisection_tolerance",
               "a number in [1e-12, 1) (relative; a narrower bracket is finer than the "
               "simulations resolve)");
  }
  if (s.has("record")) {
    f.is_record = true;
    for (const char* k :
         {"pulse", "axes", "amplitudes", "frequencies", "amplitude_units", "frequency_units"}) {
      if (s.has(k)) s.fail(k, "not allowed with 'record' (a record spectrum has 'scales')");
    }
    const toml::node* rn = s.node("record");
    if (!rn->is_table()) s.expected("record", "a table {file, format, units, dt, name}");
    Keys rk(path, *rn->as_table(), "spectrum.record.");
    const Record rec = read_record(rk, f.record_name, &f.hash, f.input_files);
    f.record.motion = rec.to_motion();
    const auto scales = grid_opt(s, "scales", "[-] (factors on the record)");
    if (!scales) s.fail("scales", "missing; expected the scale factors of the record");
    f.record.scales = *scales;
    f.record.free_periods = free_periods;
    f.record.bisect = bisect;
    f.record.bisection_tolerance = tol;
    f.record.solver = solver;
  } else {
    if (s.has("scales")) s.fail("scales", "only with 'record' (a pulse spectrum has 'amplitudes')");
    f.pulse.pulse = s.choice("pulse", spectrum_pulse_names(), "one_sine");
    const std::string axes = s.choice("axes", {"normalized", "physical"}, "normalized");
    f.pulse.normalized = axes == "normalized";
    if (f.pulse.normalized) {
      if (s.has("amplitude_units")) s.fail("amplitude_units", "only with axes = \"physical\"");
      if (s.has("frequency_units")) s.fail("frequency_units", "only with axes = \"physical\"");
    } else {
      // the grid stays in the units given: its cells, bisection and columns keep them
      const AccelUnit au =
          detail::accel_unit(s.choice("amplitude_units", detail::accel_unit_names(), "m/s^2"));
      const std::string wu = s.choice("frequency_units", {"rad/s", "Hz"}, "rad/s");
      f.pulse.units = {std::string(unit_name(au)), to_si_factor(au), wu,
                       wu == "Hz" ? 2.0 * std::numbers::pi : 1.0};
    }
    const std::string au = f.pulse.normalized ? "[-] (a_p / (g tan alpha))" : "(amplitude_units)";
    const std::string wu = f.pulse.normalized ? "[-] (omega_p / p)" : "(frequency_units)";
    auto amps = grid_opt(s, "amplitudes", au);
    auto freqs = grid_opt(s, "frequencies", wu);
    if (!amps) s.fail("amplitudes", "missing; expected the grid of pulse amplitudes " + au);
    if (!freqs) s.fail("frequencies", "missing; expected the grid of pulse frequencies " + wu);
    for (std::size_t i = 0; i < amps->size(); ++i) {
      if (!((*amps)[i] > 0.0) || (i > 0 && !((*amps)[i] > (*amps)[i - 1]))) {
        s.fail("amplitudes",
               "expected strictly increasing values > 0 (the bisection needs an "
               "ordered column), got " +
                   num((*amps)[i]) + " at position " + std::to_string(i + 1));
      }
    }
    for (std::size_t i = 0; i < freqs->size(); ++i) {
      if (!((*freqs)[i] > 0.0)) {
        s.fail("frequencies", "expected values > 0, got " + num((*freqs)[i]) + " at position " +
                                  std::to_string(i + 1));
      }
    }
    if (static_cast<double>(amps->size()) * static_cast<double>(freqs->size()) >
        static_cast<double>(kMaxStudyRuns)) {
      s.fail("amplitudes", "expected at most " + std::to_string(kMaxStudyRuns) +
                               " grid cells, got " + std::to_string(amps->size()) +
                               " amplitudes x " + std::to_string(freqs->size()) + " frequencies");
    }
    f.pulse.amplitudes = std::move(*amps);
    f.pulse.frequencies = std::move(*freqs);
    f.pulse.free_periods = free_periods;
    f.pulse.bisect = bisect;
    f.pulse.bisection_tolerance = tol;
    f.pulse.solver = solver;
  }
  if (f.is_record) {
    for (std::size_t i = 0; i < f.record.scales.size(); ++i) {
      const double v = f.record.scales[i];
      if (!(v > 0.0) || (i > 0 && !(v > f.record.scales[i - 1]))) {
        s.fail("scales", "expected strictly increasing values > 0, got " + num(v) +
                             " at position " + std::to_string(i + 1));
      }
    }
  }
  s.finish("in [spectrum] (see docs/studies.md)");
  top.finish("at the top level of a spectrum file");
  return f;
}

namespace {

// one column of the spectrum CSV: name, unit, meaning, type, its field of a cell and (for a
// result of the run) how a field read back sets it; the columns without `set` follow from the
// grid. The header, the rows, the reader and the column reference of docs/studies.md are
// written from this table
struct SpectrumColumn {
  const char* name;
  const char* unit;
  const char* doc;
  ColumnType type;
  Value (*get)(const study::SpectrumResult& res, const study::SpectrumCell& c, double g);
  void (*set)(study::SpectrumCell& c, const Value& v);
};

using Res = study::SpectrumResult;
using Cell = study::SpectrumCell;

const SpectrumColumn kSpectrumColumns[] = {
    {"row", "-", "grid index of the amplitude", ColumnType::kInteger,
     [](const Res&, const Cell& c, double) -> Value { return static_cast<long long>(c.row); },
     nullptr},
    {"column", "-", "grid index of the frequency", ColumnType::kInteger,
     [](const Res&, const Cell& c, double) -> Value { return static_cast<long long>(c.column); },
     nullptr},
    {"a_p_m_per_s2", "m/s^2", "pulse amplitude (record: the scaled record's PGA)",
     ColumnType::kReal, [](const Res&, const Cell& c, double) -> Value { return c.amplitude_si; },
     nullptr},
    {"a_p_over_g_tan_alpha", "-", "the same over g tan alpha", ColumnType::kReal,
     [](const Res& res, const Cell& c, double g) -> Value {
       return c.amplitude_si / (g * res.tan_alpha);
     },
     nullptr},
    {"omega_p_rad_per_s", "rad/s", "pulse frequency (record: 0)", ColumnType::kReal,
     [](const Res&, const Cell& c, double) -> Value { return c.omega_si; }, nullptr},
    {"omega_p_over_p", "-", "the same over p", ColumnType::kReal,
     [](const Res& res, const Cell& c, double) -> Value { return c.omega_si / res.p; }, nullptr},
    {"scale", "-", "record spectra: the factor (pulse spectra: empty)", ColumnType::kReal,
     [](const Res&, const Cell& c, double) -> Value {
       return c.omega_si == 0.0 ? c.amplitude : std::numeric_limits<double>::quiet_NaN();
     },
     nullptr},
    {"outcome", "-", "the outcome class above", ColumnType::kText,
     [](const Res&, const Cell& c, double) -> Value { return study::to_string(c.run.outcome); },
     [](Cell& c, const Value& v) { c.run.outcome = outcome_value(v); }},
    {"overturned", "0/1", "1 for an overturning class", ColumnType::kInteger,
     [](const Res&, const Cell& c, double) -> Value {
       return study::overturned(c.run.outcome) ? 1LL : 0LL;
     },
     nullptr},
    {"max_theta_over_alpha", "-", "largest tilt over the overturning angle", ColumnType::kReal,
     [](const Res&, const Cell& c, double) -> Value { return c.run.max_theta_over_alpha; },
     [](Cell& c, const Value& v) { c.run.max_theta_over_alpha = real(v); }},
    {"impacts", "-", "impacts during the run", ColumnType::kInteger,
     [](const Res&, const Cell& c, double) -> Value {
       return static_cast<long long>(c.run.impacts);
     },
     [](Cell& c, const Value& v) { c.run.impacts = static_cast<long>(integer(v)); }},
    {"first_uplift_time_s", "s", "-1: never", ColumnType::kReal,
     [](const Res&, const Cell& c, double) -> Value { return c.run.first_uplift_time; },
     [](Cell& c, const Value& v) { c.run.first_uplift_time = real(v); }},
    {"overturn_time_s", "s", "-1: never", ColumnType::kReal,
     [](const Res&, const Cell& c, double) -> Value { return c.run.overturn_time; },
     [](Cell& c, const Value& v) { c.run.overturn_time = real(v); }},
    {"energy_lost_J", "J", "impacts + chatter cut-offs + material damping", ColumnType::kReal,
     [](const Res&, const Cell& c, double) -> Value { return c.run.energy_lost; },
     [](Cell& c, const Value& v) { c.run.energy_lost = real(v); }},
    {"status", "-", "engine status: completed, overturned, stopped", ColumnType::kText,
     [](const Res&, const Cell& c, double) -> Value { return to_string(c.run.status); },
     [](Cell& c, const Value& v) { c.run.status = status_value(v); }},
};

// A column in the units a physical grid was given in, written right after the SI column it
// restates and only where that unit is not the SI one (a_p_g after a_p_m_per_s2, f_p_hz after
// omega_p_rad_per_s): the file keeps the units asked for, with the unit in the column's name, and
// its plot reads them back. Its value is the grid's own number, not the SI one divided back.
template <class Row>
struct GridUnitColumn {
  const char* after;   // the SI column it follows
  const char* prefix;  // its name before the unit's suffix
  bool frequency;      // in the grid's frequency unit, else in its amplitude unit
  const char* doc;
  Value (*get)(const Row& row);
};

// the suffix of a unit in a column's name, as the sweep's Sa columns end (sa_T1_z0.05_g)
std::string unit_suffix(const std::string& unit) {
  if (unit == "m/s^2") return "m_per_s2";
  if (unit == "cm/s^2") return "cm_per_s2";
  if (unit == "rad/s") return "rad_per_s";
  if (unit == "Hz") return "hz";
  return unit;  // g
}

template <class Row>
bool shown(const GridUnitColumn<Row>& c, const study::GridUnits& u) {
  return c.frequency ? u.frequency_differs() : u.amplitude_differs();
}

template <class Row>
std::string name_in(const GridUnitColumn<Row>& c, const study::GridUnits& u) {
  return std::string(c.prefix) + "_" + unit_suffix(c.frequency ? u.frequency : u.amplitude);
}

// calls f(column) for each column in the units `u` that follows the SI column `after`
template <class Row, std::size_t N, class F>
void each_unit_column(const GridUnitColumn<Row> (&table)[N], const char* after,
                      const study::GridUnits& u, F&& f) {
  for (const GridUnitColumn<Row>& c : table) {
    if (std::string_view(c.after) == after && shown(c, u)) f(c);
  }
}

// the reference rows of a table's unit columns, each after the row of its SI column
template <class Row, std::size_t N>
std::string with_unit_rows(std::string block, const GridUnitColumn<Row> (&table)[N]) {
  for (const GridUnitColumn<Row>& c : table) {
    const std::string row = std::string("| `") + c.after + "` |";
    const std::size_t at = block.find(row);
    FLEXROCK_DEMAND(at != std::string::npos);
    const std::size_t end = block.find('\n', at) + 1;
    block.insert(end, std::string("| `") + c.prefix + "_<unit>` | " +
                          (c.frequency ? "frequency_units" : "amplitude_units") + " | " + c.doc +
                          " |\n");
  }
  return block;
}

const GridUnitColumn<Cell> kSpectrumUnitColumns[] = {
    {"a_p_m_per_s2", "a_p", false,
     "pulse amplitude in the grid's amplitude_units (a_p_g, a_p_cm_per_s2; physical axes in "
     "those units only)",
     [](const Cell& c) -> Value { return c.amplitude; }},
    {"omega_p_rad_per_s", "f_p", true,
     "pulse frequency in the grid's frequency_units (f_p_hz; physical axes in Hz only)",
     [](const Cell& c) -> Value { return c.frequency; }},
};

}  // namespace

std::vector<std::string> spectrum_columns(bool sliding, const study::GridUnits& units) {
  std::vector<std::string> v;
  for (const SpectrumColumn& c : kSpectrumColumns) {
    v.emplace_back(c.name);
    each_unit_column(kSpectrumUnitColumns, c.name, units,
                     [&](const auto& u) { v.push_back(name_in(u, units)); });
  }
  if (sliding) add_sliding_columns(v);
  return v;
}

std::vector<ColumnInfo> spectrum_column_info(bool sliding, const study::GridUnits& units) {
  std::vector<ColumnInfo> v;
  for (const SpectrumColumn& c : kSpectrumColumns) {
    v.push_back({c.name, c.unit, c.type});
    each_unit_column(kSpectrumUnitColumns, c.name, units, [&](const auto& u) {
      v.push_back(
          {name_in(u, units), u.frequency ? units.frequency : units.amplitude, ColumnType::kReal});
    });
  }
  if (sliding) {
    for (const SlidingColumn& c : sliding_columns()) v.push_back({c.name, c.unit, c.type});
  }
  return v;
}

std::vector<FieldValue> spectrum_values(const study::SpectrumResult& res,
                                        const study::SpectrumCell& c, double g) {
  std::vector<FieldValue> v;
  for (const SpectrumColumn& col : kSpectrumColumns) {
    v.push_back(col.get(res, c, g));
    each_unit_column(kSpectrumUnitColumns, col.name, res.units,
                     [&](const auto& u) { v.push_back(u.get(c)); });
  }
  if (res.sliding) {
    for (const SlidingColumn& col : sliding_columns()) v.push_back(col.get(c.run));
  }
  return v;
}

std::string spectrum_row(const study::SpectrumResult& res, const study::SpectrumCell& c, double g) {
  std::string s;
  for (const SpectrumColumn& col : kSpectrumColumns) {
    if (&col != kSpectrumColumns) s += ',';
    s += format_field(col.get(res, c, g));
    each_unit_column(kSpectrumUnitColumns, col.name, res.units, [&](const auto& u) {
      s += ',';
      s += format_field(u.get(c));
    });
  }
  if (res.sliding) add_sliding_fields(s, c.run);
  return s;
}

namespace {

// what a boundary row is written from: the grid, g, and the spec's units in SI
struct BoundaryContext {
  const study::SpectrumResult& res;
  double g;       // [m/s^2]
  double a_unit;  // [m/s^2] one amplitude unit of the spec (record spectra: the record's PGA)
  double omega;   // [rad/s] the column's frequency (record spectra: 0)
};

using Boundary = study::OverturnBoundary;

bool found(const Boundary& b) { return b.kind != Boundary::Kind::kNone; }

// one column of the boundary CSV: name, unit, meaning, type, its field of a row and (for what the
// bisection found) how a field read back sets it; the columns without `set` follow from the grid
// and the others. The header, the rows, the reader and the column reference of docs/studies.md
// are written from this table
struct BoundaryColumn {
  const char* name;
  const char* unit;
  const char* doc;
  ColumnType type;
  Value (*get)(const BoundaryContext& x, const Boundary& b);
  void (*set)(Boundary& b, const Value& v);
};

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

const BoundaryColumn kBoundaryColumns[] = {
    {"column", "-", "grid index of the frequency", ColumnType::kInteger,
     [](const BoundaryContext&, const Boundary& b) -> Value {
       return static_cast<long long>(b.column);
     },
     nullptr},
    {"frequency", "grid",
     "the column's frequency as the grid holds it: omega_p/p on normalized axes, its "
     "frequency_units on physical ones",
     ColumnType::kReal,
     [](const BoundaryContext&, const Boundary& b) -> Value { return b.frequency; }, nullptr},
    {"omega_p_rad_per_s", "rad/s", "the same in rad/s (record: 0)", ColumnType::kReal,
     [](const BoundaryContext& x, const Boundary&) -> Value { return x.omega; }, nullptr},
    {"omega_p_over_p", "-", "the same over p", ColumnType::kReal,
     [](const BoundaryContext& x, const Boundary&) -> Value { return x.omega / x.res.p; }, nullptr},
    {"kind", "-",
     "`found`; `below_grid`: the smallest grid amplitude already overturns; `none`: no cell of "
     "the column overturns",
     ColumnType::kText,
     [](const BoundaryContext&, const Boundary& b) -> Value { return study::to_string(b.kind); },
     [](Boundary& b, const Value& v) {
       const std::optional<Boundary::Kind> k = value_named(study::kBoundaryKindNames, text(v));
       if (!k) throw InputError("unknown kind \"" + text(v) + "\"");
       b.kind = *k;
     }},
    {"min_overturning", "grid",
     "the upper end of the bracket: an amplitude shown to overturn, as the grid holds it "
     "(a_p/(g tan alpha) on normalized axes, its amplitude_units on physical ones, the factor "
     "on a record); "
     "empty for `none`",
     ColumnType::kReal,
     [](const BoundaryContext&, const Boundary& b) -> Value {
       return found(b) ? b.overturning : kNoValue;
     },
     [](Boundary& b, const Value& v) { b.overturning = real(v); }},
    {"safe_below", "grid", "the lower end: shown not to overturn (empty unless `found`)",
     ColumnType::kReal,
     [](const BoundaryContext&, const Boundary& b) -> Value {
       return b.kind == Boundary::Kind::kFound ? b.safe : kNoValue;
     },
     [](Boundary& b, const Value& v) { b.safe = real(v); }},
    {"min_overturning_m_per_s2", "m/s^2", "`min_overturning` in m/s^2", ColumnType::kReal,
     [](const BoundaryContext& x, const Boundary& b) -> Value {
       return found(b) ? b.overturning * x.a_unit : kNoValue;
     },
     nullptr},
    {"min_overturning_over_g_tan_alpha", "-", "`min_overturning` over g tan alpha",
     ColumnType::kReal,
     [](const BoundaryContext& x, const Boundary& b) -> Value {
       return found(b) ? b.overturning * x.a_unit / (x.g * x.res.tan_alpha) : kNoValue;
     },
     nullptr},
    {"mode", "-", "the outcome class at `min_overturning` (which overturning mode)",
     ColumnType::kText,
     [](const BoundaryContext&, const Boundary& b) -> Value {
       return std::string(found(b) ? study::to_string(b.mode) : "");
     },
     [](Boundary& b, const Value& v) {
       if (!text(v).empty()) b.mode = outcome_value(v);
     }},
    {"bisection_runs", "-", "simulations the bisection took", ColumnType::kInteger,
     [](const BoundaryContext&, const Boundary& b) -> Value {
       return static_cast<long long>(b.bisection_runs);
     },
     [](Boundary& b, const Value& v) { b.bisection_runs = static_cast<int>(integer(v)); }},
};

const GridUnitColumn<Boundary> kBoundaryUnitColumns[] = {
    {"omega_p_rad_per_s", "f_p", true,
     "the column's frequency in the grid's frequency_units (f_p_hz; physical axes in Hz only)",
     [](const Boundary& b) -> Value { return b.frequency; }},
    {"min_overturning_m_per_s2", "min_overturning", false,
     "`min_overturning` in the grid's amplitude_units (min_overturning_g, "
     "min_overturning_cm_per_s2; physical axes in those units only)",
     [](const Boundary& b) -> Value { return found(b) ? b.overturning : kNoValue; }},
};

// the context of a boundary row: the spec's units in SI
BoundaryContext boundary_context(const study::SpectrumResult& res, const study::OverturnBoundary& b,
                                 bool normalized, double g) {
  const bool record = res.cells.size() == 1 || (!res.cells.empty() && res.cells[0].omega_si == 0.0);
  // the spec's units to m/s^2 and rad/s
  double a_unit = normalized ? g * res.tan_alpha : res.units.amplitude_si;
  double omega = b.frequency * (normalized ? res.p : res.units.frequency_si);
  if (record) {
    const study::SpectrumCell& c0 = res.cells.front();
    a_unit = c0.amplitude > 0.0 ? c0.amplitude_si / c0.amplitude : 0.0;  // the record's PGA
    omega = 0.0;
  }
  return {res, g, a_unit, omega};
}

}  // namespace

std::vector<std::string> boundary_columns(const study::GridUnits& units) {
  std::vector<std::string> v;
  for (const BoundaryColumn& c : kBoundaryColumns) {
    v.emplace_back(c.name);
    each_unit_column(kBoundaryUnitColumns, c.name, units,
                     [&](const auto& u) { v.push_back(name_in(u, units)); });
  }
  return v;
}

std::vector<ColumnInfo> boundary_column_info(const study::GridUnits& units) {
  std::vector<ColumnInfo> v;
  for (const BoundaryColumn& c : kBoundaryColumns) {
    v.push_back({c.name, c.unit, c.type});
    each_unit_column(kBoundaryUnitColumns, c.name, units, [&](const auto& u) {
      v.push_back(
          {name_in(u, units), u.frequency ? units.frequency : units.amplitude, ColumnType::kReal});
    });
  }
  return v;
}

std::vector<FieldValue> boundary_values(const study::SpectrumResult& res,
                                        const study::OverturnBoundary& b, bool normalized,
                                        double g) {
  const BoundaryContext x = boundary_context(res, b, normalized, g);
  std::vector<FieldValue> v;
  for (const BoundaryColumn& col : kBoundaryColumns) {
    v.push_back(col.get(x, b));
    each_unit_column(kBoundaryUnitColumns, col.name, res.units,
                     [&](const auto& u) { v.push_back(u.get(b)); });
  }
  return v;
}

std::string boundary_row(const study::SpectrumResult& res, const study::OverturnBoundary& b,
                         bool normalized, double g) {
  const BoundaryContext x = boundary_context(res, b, normalized, g);
  std::string s;
  for (const BoundaryColumn& col : kBoundaryColumns) {
    if (&col != kBoundaryColumns) s += ',';
    s += format_field(col.get(x, b));
    each_unit_column(kBoundaryUnitColumns, col.name, res.units, [&](const auto& u) {
      s += ',';
      s += format_field(u.get(b));
    });
  }
  return s;
}

void write_spectrum_csv(std::ostream& out, const study::SpectrumResult& result, double g) {
  out << join(spectrum_columns(result.sliding, result.units), ",") << '\n';
  for (const study::SpectrumCell& c : result.cells) out << spectrum_row(result, c, g) << '\n';
}

void write_boundary_csv(std::ostream& out, const study::SpectrumResult& result, bool normalized,
                        double g) {
  out << join(boundary_columns(result.units), ",") << '\n';
  for (const study::OverturnBoundary& b : result.boundary) {
    out << boundary_row(result, b, normalized, g) << '\n';
  }
}

study::SpectrumCell read_spectrum_cell(const study::SpectrumResult& grid, std::size_t index,
                                       const std::string& line, double g) {
  FLEXROCK_THROW_UNLESS(index < grid.cells.size(),
                        "cell index " + std::to_string(index) + " out of range (" +
                            std::to_string(grid.cells.size()) + " cells)");
  study::SpectrumCell cell = grid.cells[index];
  const std::vector<std::string> names = spectrum_columns(grid.sliding, grid.units);
  const std::vector<std::string_view> f = fields_of(line);
  FLEXROCK_THROW_UNLESS(f.size() == names.size(), std::to_string(f.size()) + " fields, expected " +
                                                      std::to_string(names.size()));
  std::size_t k = 0;
  auto next = [&](ColumnType type) {
    try {
      return parse_field(f[k], type);
    } catch (const InputError& e) {
      throw InputError("field " + std::to_string(k + 1) + " (" + names[k] + "): " + e.what());
    }
  };
  for (const SpectrumColumn& col : kSpectrumColumns) {
    const Value v = next(col.type);
    if (col.set) col.set(cell, v);
    ++k;
    // the grid's own units: follow from the grid, checked with the whole line below
    each_unit_column(kSpectrumUnitColumns, col.name, grid.units, [&](const auto&) {
      next(ColumnType::kReal);
      ++k;
    });
  }
  if (grid.sliding) {
    for (const SlidingColumn& col : sliding_columns()) {
      col.set(cell.run, next(col.type));
      ++k;
    }
  }
  const std::string again = spectrum_row(grid, cell, g);
  if (again != line) throw InputError(first_difference(names, line, again));
  return cell;
}

study::OverturnBoundary read_boundary(const study::SpectrumResult& grid, std::size_t column,
                                      const std::string& line, bool normalized, double g) {
  FLEXROCK_THROW_UNLESS(column < grid.boundary.size(),
                        "boundary " + std::to_string(column) + " out of range (" +
                            std::to_string(grid.boundary.size()) + " columns)");
  study::OverturnBoundary b = grid.boundary[column];
  b.column = column;
  b.computed = true;
  const std::vector<std::string> names = boundary_columns(grid.units);
  const std::vector<std::string_view> f = fields_of(line);
  FLEXROCK_THROW_UNLESS(f.size() == names.size(), std::to_string(f.size()) + " fields, expected " +
                                                      std::to_string(names.size()));
  std::size_t k = 0;
  auto next = [&](ColumnType type) {
    try {
      return parse_field(f[k], type);
    } catch (const InputError& e) {
      throw InputError("field " + std::to_string(k + 1) + " (" + names[k] + "): " + e.what());
    }
  };
  for (const BoundaryColumn& col : kBoundaryColumns) {
    const Value v = next(col.type);
    if (col.set) {
      try {
        col.set(b, v);
      } catch (const InputError& e) {
        throw InputError("field " + std::to_string(k + 1) + " (" + names[k] + "): " + e.what());
      }
    }
    ++k;
    // the grid's own units: as the columns before them say, checked with the whole line below
    each_unit_column(kBoundaryUnitColumns, col.name, grid.units, [&](const auto&) {
      next(ColumnType::kReal);
      ++k;
    });
  }
  const std::string again = boundary_row(grid, b, normalized, g);
  if (again != line) throw InputError(first_difference(names, line, again));
  return b;
}

std::string study_detail::spectrum_column_block() {
  return with_unit_rows(
      column_block<SpectrumColumn>("spectrum", "src/io/study_spectrum.cpp", kSpectrumColumns),
      kSpectrumUnitColumns);
}

std::string study_detail::boundary_column_block() {
  return with_unit_rows(
      column_block<BoundaryColumn>("boundary", "src/io/study_spectrum.cpp", kBoundaryColumns),
      kBoundaryUnitColumns);
}

}  // namespace flexrock::io
