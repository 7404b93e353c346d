// SPDX-License-Identifier: BSD-3-Clause
// Study files: what their readers and writers share (grids, [solver], records, the sliding
// columns, field texts) and the column reference of docs/studies.md.
#include "flexrock/io/study_files.hpp"

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
#include "study_internal.hpp"
#include "table_reader.hpp"
#include "uncertain_tables.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;
using namespace study_detail;

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h) {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

namespace study_detail {

// shortest text that reads back to the same double (messages: "inf" and "nan" as such)
std::string num(double v) { return format_number(v); }
// a number field of a study CSV or journal: the shortest text that reads back to the same
// double, empty where there is no finite value (a run stopped because its results overflow
// double precision; a friction demand at a zero normal force), never "inf" or "nan"
std::string field(double v) { return std::isfinite(v) ? format_number(v) : std::string(); }

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

// a regular file's bytes (read_input_file refuses FIFOs and devices)
std::string file_bytes(const std::string& path) { return read_input_file(path, "input"); }

// a value of each type of a field
long long integer(const Value& v) { return std::get<long long>(v); }
double real(const Value& v) { return std::get<double>(v); }
const std::string& text(const Value& v) { return std::get<std::string>(v); }

std::optional<study::Outcome> outcome_named(std::string_view name) {
  return value_named(study::kOutcomeNames, name);
}

std::optional<Status> status_named(std::string_view name) {
  for (int k = 0; k < 64; ++k) {
    if (name == to_string(static_cast<Status>(k))) return static_cast<Status>(k);
  }
  return std::nullopt;
}

std::optional<study::Regime> regime_named(std::string_view name) {
  return value_named(study::kRegimeNames, name);
}

study::Outcome outcome_value(const Value& v) {
  const std::optional<study::Outcome> o = outcome_named(text(v));
  if (!o) throw InputError("unknown outcome \"" + text(v) + "\"");
  return *o;
}

Status status_value(const Value& v) {
  const std::optional<Status> o = status_named(text(v));
  if (!o) throw InputError("unknown status \"" + text(v) + "\"");
  return *o;
}

// a list of numbers: an array, or a table {start, stop, count[, spacing]} or {start, stop,
// step}
std::optional<std::vector<double>> grid_opt(Keys& r, std::string_view key,
                                            const std::string& unit) {
  const toml::node* n = r.node(key);
  if (!n) return std::nullopt;
  const std::string what = "an array of numbers " + unit +
                           " or a table {start, stop, count[, spacing = \"linear\"|\"log\"]} "
                           "or {start, stop, step}";
  std::vector<double> v;
  if (const toml::array* a = n->as_array()) {
    if (a->size() > kMaxGridPoints) {
      r.fail(key, "expected at most " + std::to_string(kMaxGridPoints) + " values, got " +
                      std::to_string(a->size()));
    }
    for (const toml::node& e : *a) v.push_back(r.to_number(e, key, what));
    if (v.empty()) r.expected(key, what + " (not empty)");
    return v;
  }
  const toml::table* t = n->as_table();
  if (!t) r.expected(key, what);
  Keys g(r.file(), *t, r.full(key) + ".", line_of(*n));
  const toml::node* s0 = g.node("start");
  const toml::node* s1 = g.node("stop");
  if (!s0 || !s1) r.fail(key, "expected " + what + ": 'start' and 'stop' are required");
  const double start = g.to_number(*s0, "start", "a number " + unit);
  const double stop = g.to_number(*s1, "stop", "a number " + unit);
  if (!(stop >= start)) g.fail("stop", "expected stop >= start (" + num(start) + ")");
  if (g.has("step")) {
    if (g.has("count")) g.fail("step", "expected 'step' or 'count', not both");
    const double step = g.positive_or("step", 1.0, unit);
    // integer multiples of the step, so that values do not drift; stop included to 1e-9 steps.
    // The count is checked as a double before it becomes an integer (1e-300 would overflow it)
    const double steps = std::floor((stop - start) / step + 1e-9);
    if (!(steps < static_cast<double>(kMaxGridPoints))) {
      g.fail("step", "expected a step that gives at most " + std::to_string(kMaxGridPoints) +
                         " grid points from " + num(start) + " to " + num(stop) + ", got " +
                         num(step) + " (" + num(steps + 1.0) + " points)");
    }
    const auto n_steps = static_cast<long>(steps);
    for (long i = 0; i <= n_steps; ++i) v.push_back(start + static_cast<double>(i) * step);
  } else {
    const long count = g.integer_or("count", 0, 1, "an integer >= 1 (grid points)");
    if (count == 0) g.fail("count", "missing; expected 'count' (an integer >= 1) or 'step'");
    if (count > static_cast<long>(kMaxGridPoints)) {
      g.fail("count", "expected at most " + std::to_string(kMaxGridPoints) + " grid points, got " +
                          std::to_string(count));
    }
    const std::string spacing = g.choice("spacing", {"linear", "log"}, "linear");
    if (spacing == "log" && !(start > 0.0)) g.fail("start", "expected start > 0 for a log grid");
    for (long i = 0; i < count; ++i) {
      const double f = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
      v.push_back(spacing == "log" ? start * std::pow(stop / start, f)
                                   : start + f * (stop - start));
    }
    if (count > 1) v.back() = stop;
  }
  g.finish();
  return v;
}

// [solver]: the keys of a case file's [solver] table that make sense for a study (no t_end),
// checked as simulate() will check them, here where the file and line are known
void read_solver(Keys& r, SimulationOptions& o, const BodyParameters& body) {
  detail::read_solver_keys(r, o);
  r.finish("in [solver] (see docs/studies.md)");
  try {
    validate_options(Body(body), {}, o);
  } catch (const InputError& e) {
    throw InputError(r.file(), r.line(), "", std::string("table [solver]: ") + e.what());
  }
}

// a record table {file, format, units, dt, name}; the record's bytes go into `hash`
Record read_record(Keys& r, std::string& name, std::uint64_t* hash,
                   std::vector<std::string>& files) {
  const detail::RecordKeys k =
      detail::read_record_keys(r, "a path to the record, relative to this file");
  const std::string& path = k.path;
  files.push_back(path);
  name = r.string_opt("name", "a string").value_or(fs::path(k.file).stem().string());
  r.finish("for a record");
  const Record rec = detail::read_record_file(r, k);
  if (hash) *hash = fnv1a(file_bytes(path), *hash);
  return rec;
}

void check_name(Keys& r, const std::string& key, const std::string& name) {
  if (name.empty() || name.find_first_of(",\"\n\r") != std::string::npos) {
    r.fail(key,
           "expected a non-empty name without commas, quotes or line ends, got \"" + name + "\"");
  }
}

// the sliding columns (study_internal.hpp)
const SlidingColumn kSlidingColumns[] = {
    {"regime", "-",
     "what the base did: `none`, `sliding` (slid, never uplifted), `rocking` (uplifted, never "
     "slid) or `sliding_rocking` (both); an overturned body keeps its outcome",
     ColumnType::kText,
     [](const study::RunSummary& r) -> Value { return study::to_string(r.regime); },
     [](study::RunSummary& r, const Value& v) {
       const std::optional<study::Regime> g = regime_named(text(v));
       if (!g) throw InputError("unknown regime \"" + text(v) + "\"");
       r.regime = *g;
     }},
    {"max_offset_m", "m", "peak \\|offset\\| of the base from where it stood", ColumnType::kReal,
     [](const study::RunSummary& r) -> Value { return r.max_offset; },
     [](study::RunSummary& r, const Value& v) { r.max_offset = real(v); }},
    {"final_offset_m", "m", "residual offset at the end (signed, along +I)", ColumnType::kReal,
     [](const study::RunSummary& r) -> Value { return r.final_offset; },
     [](study::RunSummary& r, const Value& v) { r.final_offset = real(v); }},
    {"sliding_time_s", "s", "time spent sliding", ColumnType::kReal,
     [](const study::RunSummary& r) -> Value { return r.sliding_time; },
     [](study::RunSummary& r, const Value& v) { r.sliding_time = real(v); }},
    {"slips", "-", "times sliding started", ColumnType::kInteger,
     [](const study::RunSummary& r) -> Value { return static_cast<long long>(r.slips); },
     [](study::RunSummary& r, const Value& v) { r.slips = static_cast<long>(integer(v)); }},
};

std::span<const SlidingColumn> sliding_columns() { return kSlidingColumns; }

void add_sliding_columns(std::vector<std::string>& v) {
  for (const SlidingColumn& c : kSlidingColumns) v.emplace_back(c.name);
}

void add_sliding_fields(std::string& s, const study::RunSummary& r) {
  for (const SlidingColumn& c : kSlidingColumns) s.append(",").append(format_field(c.get(r)));
}

std::string sliding_column_block() {
  return column_block<SlidingColumn>("sliding", "src/io/study_files.cpp", kSlidingColumns);
}

}  // namespace study_detail

std::string format_field(const FieldValue& v) {
  if (const auto* i = std::get_if<long long>(&v)) return std::to_string(*i);
  if (const auto* x = std::get_if<double>(&v)) return field(*x);
  return std::get<std::string>(v);
}

namespace {

// the table of intensity measures as a Markdown table between begin and end markers
std::string measure_block() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of intensity measures "
      "(src/excitation/intensity.cpp); edit the table, not these lines -->\n"
      "| name | column | unit | scales as | meaning |\n"
      "|---|---|---|---|---|\n";
  for (const IntensityMeasure& m : intensity_measures()) {
    const std::string column = m.needs_period ? std::string("sa_T<T>_z<zeta>_m_per_s2") : m.column;
    const std::string power = m.scale_power == 0   ? "1 (invariant)"
                              : m.scale_power == 1 ? "s"
                                                   : "s^" + std::to_string(m.scale_power);
    s.append("| `").append(m.name).append("` | `").append(column).append("` | ").append(m.unit);
    s.append(" | ").append(power).append(" | ").append(m.doc).append(" |\n");
  }
  return s + "<!-- end: written by `flexrock keys --markdown` -->\n";
}

}  // namespace

std::string study_column_reference() {
  return spectrum_column_block() + boundary_column_block() + sweep_column_block() +
         measure_block() + sliding_column_block() + detail::uncertain_reference() +
         fragility_column_block();
}

}  // namespace flexrock::io
