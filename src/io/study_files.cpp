// SPDX-License-Identifier: BSD-3-Clause
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
#include "table_reader.hpp"
#include "uncertain_tables.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h) {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

namespace {

// shortest text that reads back to the same double (messages: "inf" and "nan" as such)
std::string num(double v) { return format_number(v); }
// a number field of a study CSV or journal: the shortest text that reads back to the same
// double, empty where there is no finite value (a run stopped because its results overflow
// double precision; a friction demand at a zero normal force), never "inf" or "nan"
std::string field(double v) { return std::isfinite(v) ? format_number(v) : std::string(); }

std::string join(const std::vector<std::string>& v, const char* sep = ", ") {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

// a regular file's bytes (read_input_file refuses FIFOs and devices)
std::string file_bytes(const std::string& path) { return read_input_file(path, "input"); }

// a field's value by its column's type (the variant's alternative), and a value of each type
using Value = FieldValue;
long long integer(const Value& v) { return std::get<long long>(v); }
double real(const Value& v) { return std::get<double>(v); }
const std::string& text(const Value& v) { return std::get<std::string>(v); }

std::optional<study::Outcome> outcome_named(std::string_view name) {
  // every value of the enumeration, so that a new outcome needs no change here
  for (int k = 0; k < 64; ++k) {
    const auto o = static_cast<study::Outcome>(k);
    if (name == study::to_string(o)) return o;
  }
  return std::nullopt;
}

std::optional<Status> status_named(std::string_view name) {
  for (int k = 0; k < 64; ++k) {
    if (name == to_string(static_cast<Status>(k))) return static_cast<Status>(k);
  }
  return std::nullopt;
}

std::optional<study::Regime> regime_named(std::string_view name) {
  for (const auto r : {study::Regime::kNone, study::Regime::kSliding, study::Regime::kRocking,
                       study::Regime::kSlidingRocking}) {
    if (name == study::to_string(r)) return r;
  }
  return std::nullopt;
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

using detail::describe;
using detail::line_of;
// the checked reads of a table, shared with the case-file loader
using Keys = detail::TableReader;

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

// ---------------------------------------------------------------------------------------------
// record suites: [[suite]] tables whose horizontal (and vertical) components are globs or lists

// `name` matches `pattern`: '*' any run of characters, '?' any one, the rest literally
bool glob_match(std::string_view pattern, std::string_view name) {
  std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

// the files of one component of a suite, in the order the suite takes them
struct SuiteComponent {
  bool glob = false;               // a pattern (files sorted by name) or a list (as written)
  std::string pattern;             // the pattern as written (glob)
  std::vector<std::string> paths;  // resolved against the manifest
  std::vector<std::string> keys;   // glob with one '*': the text it matched (pairs by it)
  std::size_t line = 0;            // line of the key
};

SuiteComponent suite_component(Keys& r, const std::string& key) {
  const std::string what =
      "a glob (\"dir/*_H1.AT2\": '*' and '?' in the file name only) or an array of paths, "
      "relative to this file";
  const toml::node* n = r.node(key);
  SuiteComponent c;
  c.line = line_of(*n);
  if (const toml::array* a = n->as_array()) {
    if (a->empty()) r.expected(key, what + " (at least one file)");
    for (const toml::node& e : *a) {
      if (!e.is_string() || e.as_string()->get().empty()) r.expected(key, what);
      c.paths.push_back(detail::resolve_path(r.file(), e.as_string()->get()));
    }
    return c;
  }
  if (!n->is_string() || n->as_string()->get().empty()) r.expected(key, what);
  c.glob = true;
  c.pattern = n->as_string()->get();
  const fs::path written(c.pattern);
  const std::string dir_written = written.parent_path().string();
  const std::string name = written.filename().string();
  if (dir_written.find_first_of("*?") != std::string::npos)
    r.fail(key, "expected wildcards ('*', '?') in the file name only, got \"" + c.pattern + "\"");
  if (name.empty()) r.expected(key, what);
  const std::string dir =
      detail::resolve_path(r.file(), dir_written.empty() ? std::string(".") : dir_written);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    r.fail(key, "expected an existing directory in \"" + c.pattern + "\", got no directory " + dir);
  std::vector<std::string> names;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string f = it->path().filename().string();
    if (!glob_match(name, f)) continue;
    // a match that is no record file is named, never skipped: a record would vanish from the
    // study without a word
    std::error_code sec;
    const fs::file_status st = fs::status(it->path(), sec);
    std::string why;
    if (sec || st.type() == fs::file_type::not_found) {
      const std::string reason = sec.message();
      why = fs::is_symlink(fs::symlink_status(it->path(), sec))
                ? "a symbolic link to nothing (dangling)"
                : "unreadable (" + reason + ")";
    } else if (st.type() == fs::file_type::directory) {
      why = "a directory";
    } else if (st.type() == fs::file_type::fifo) {
      why = "a FIFO (named pipe)";
    } else if (st.type() != fs::file_type::regular) {
      why = "not a regular file";
    }
    if (!why.empty())
      r.fail(key, "the pattern \"" + c.pattern + "\" matches " +
                      (fs::path(dir) / f).lexically_normal().string() + ", " + why +
                      "; expected only record files (move it away, or narrow the pattern)");
    names.push_back(f);
  }
  if (ec) r.fail(key, "cannot list the directory " + dir + ": " + ec.message());
  if (names.empty())
    r.fail(key, "the pattern \"" + c.pattern + "\" matches no file in " + dir +
                    "; expected at least one record file");
  std::sort(names.begin(), names.end());  // by bytes: the same order on every machine and rank
  const std::size_t star = name.find('*');
  const bool keyed = star != std::string::npos && name.find('*', star + 1) == std::string::npos &&
                     name.find('?') == std::string::npos;
  for (const std::string& f : names) {
    c.paths.push_back((fs::path(dir) / f).lexically_normal().string());
    if (keyed) c.keys.push_back(f.substr(star, f.size() - (name.size() - 1)));
  }
  return c;
}

// one record of a suite (a component file), its errors placed at the key that named it
Record read_suite_file(Keys& r, const std::string& key, std::size_t line, const std::string& path,
                       const std::optional<std::string>& format,
                       const std::optional<std::string>& units, double dt) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string fmt = format.value_or(ext == ".at2" ? "at2" : "");
  if (fmt.empty())
    r.fail_at(line, key,
              "file " + path + " is no .AT2 file; expected 'format' in this [[suite]] (" +
                  "at2, single_column or time_series)");
  const detail::RecordFormat* rf = nullptr;
  for (const detail::RecordFormat& f : detail::record_formats()) {
    if (fmt == f.name) rf = &f;
  }
  if (rf->needs_dt && !(dt > 0.0))
    r.fail("dt", "missing; expected 'dt' [s] (sample spacing) for the single_column files");
  if (rf->needs_units && !units)
    r.fail("units", "missing; expected one of: " + join(detail::accel_unit_names()) +
                        " (the units of the files' values)");
  Record rec;
  try {
    rec = rf->read(path, dt, units ? detail::accel_unit(*units) : AccelUnit::kG);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (record matched by key '" + r.full(key) + "' at " +
                     r.file() + ":" + std::to_string(line) + ")");
  }
  if (units && detail::accel_unit(*units) != rec.units) {
    r.fail("units", "expected the units the AT2 file " + path + " states (" +
                        std::string(unit_name(rec.units)) + "), got \"" + *units + "\"");
  }
  if (rec.npts() < 2) r.fail_at(line, key, "expected a record with at least 2 samples in " + path);
  return rec;
}

// the records of a [[suite]]: each horizontal file with its vertical one (if the suite has
// verticals), paired by the text of a glob's '*' or by position in lists; file bytes go into
// `hash`, file paths into `files`
std::vector<study::SweepRecord> read_suite(Keys& r, std::uint64_t& hash,
                                           std::vector<std::string>& files) {
  r.require("horizontal", "a glob or an array of horizontal record files");
  const SuiteComponent h = suite_component(r, "horizontal");
  const bool has_v = r.has("vertical");
  SuiteComponent v;
  if (has_v) v = suite_component(r, "vertical");
  std::optional<std::string> format;
  if (r.has("format")) {
    std::vector<std::string> names;
    for (const detail::RecordFormat& f : detail::record_formats()) names.emplace_back(f.name);
    format = r.choice("format", names);
  }
  std::optional<std::string> units;
  if (r.has("units")) units = r.choice("units", detail::accel_unit_names());
  const double dt = r.positive_or("dt", 0.0, "[s] (sample spacing of single_column files)");
  r.finish("for a [[suite]] (see docs/studies.md)");

  // the vertical file of each horizontal one (index into v.paths)
  std::vector<std::size_t> pair(h.paths.size());
  if (has_v) {
    if (h.glob != v.glob)
      r.fail("vertical", "expected 'horizontal' and 'vertical' both globs or both arrays");
    std::set<std::string> hp(h.paths.begin(), h.paths.end());
    for (const std::string& p : v.paths) {
      if (hp.count(p))
        r.fail("vertical", "the file " + p + " is both a horizontal and a vertical component");
    }
    if (h.glob) {
      if (h.keys.empty() || v.keys.empty()) {
        r.fail(h.keys.empty() ? "horizontal" : "vertical",
               "expected exactly one '*' (and no '?') in the file name of a glob with a vertical "
               "pair: the text '*' matches pairs the components");
      }
      std::map<std::string, std::size_t> by_key;
      for (std::size_t j = 0; j < v.keys.size(); ++j) by_key.emplace(v.keys[j], j);
      std::set<std::size_t> used;
      for (std::size_t i = 0; i < h.paths.size(); ++i) {
        const auto it = by_key.find(h.keys[i]);
        if (it == by_key.end()) {
          r.fail("vertical", "the horizontal record " + h.paths[i] +
                                 " has no vertical one: expected a file matching \"" + v.pattern +
                                 "\" with '*' = \"" + h.keys[i] + "\"");
        }
        pair[i] = it->second;
        used.insert(it->second);
      }
      for (std::size_t j = 0; j < v.paths.size(); ++j) {
        if (!used.count(j)) {
          r.fail("horizontal", "the vertical record " + v.paths[j] +
                                   " has no horizontal one: expected a file matching \"" +
                                   h.pattern + "\" with '*' = \"" + v.keys[j] + "\"");
        }
      }
    } else {
      if (h.paths.size() != v.paths.size()) {
        r.fail("vertical", "expected as many vertical files as horizontal ones (" +
                               std::to_string(h.paths.size()) + "), got " +
                               std::to_string(v.paths.size()) + "; the lists pair by position");
      }
      for (std::size_t i = 0; i < pair.size(); ++i) pair[i] = i;
    }
  }

  std::vector<study::SweepRecord> out;
  for (std::size_t i = 0; i < h.paths.size(); ++i) {
    const Record hr = read_suite_file(r, "horizontal", h.line, h.paths[i], format, units, dt);
    files.push_back(h.paths[i]);
    hash = fnv1a(file_bytes(h.paths[i]), hash);
    study::SweepRecord sr;
    sr.name = fs::path(h.paths[i]).stem().string();
    if (!has_v) {
      check_name(r, "horizontal", sr.name);
      sr.motion = hr.to_motion();
      out.push_back(std::move(sr));
      continue;
    }
    const std::string& vp = v.paths[pair[i]];
    const Record vr = read_suite_file(r, "vertical", v.line, vp, format, units, dt);
    files.push_back(vp);
    hash = fnv1a(file_bytes(vp), hash);
    // the components of one station share a clock: a different one is refused, not resampled
    bool same = hr.npts() == vr.npts();
    const double tol =
        1e-9 * (hr.time.back() - hr.time.front()) / static_cast<double>(hr.npts() - 1);
    for (std::size_t k = 0; same && k < hr.npts(); ++k)
      same = std::abs(hr.time[k] - vr.time[k]) <= tol;
    if (!same) {
      r.fail_at(v.line, "vertical",
                "expected the vertical record " + vp + " on the time grid of its horizontal " +
                    h.paths[i] + " (" + std::to_string(hr.npts()) + " samples, dt " + num(hr.dt) +
                    " s), got " + std::to_string(vr.npts()) + " samples, dt " + num(vr.dt) +
                    " s (resample one of them first)");
    }
    sr.name += "+" + fs::path(vp).stem().string();
    check_name(r, "horizontal", sr.name);
    sr.motion = combine(hr, &vr);
    out.push_back(std::move(sr));
  }
  return out;
}

}  // namespace

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
  f.body = load_body(f.body_source, nullptr, &f.input_files);
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
    double a_factor = 1.0, w_factor = 1.0;
    if (f.pulse.normalized) {
      if (s.has("amplitude_units")) s.fail("amplitude_units", "only with axes = \"physical\"");
      if (s.has("frequency_units")) s.fail("frequency_units", "only with axes = \"physical\"");
    } else {
      a_factor = to_si_factor(
          detail::accel_unit(s.choice("amplitude_units", detail::accel_unit_names(), "m/s^2")));
      w_factor = s.choice("frequency_units", {"rad/s", "Hz"}, "rad/s") == "Hz"
                     ? 2.0 * std::numbers::pi
                     : 1.0;
    }
    const std::string au = f.pulse.normalized ? "[-] (a_p / (g tan alpha))" : "(amplitude_units)";
    const std::string wu = f.pulse.normalized ? "[-] (omega_p / p)" : "(frequency_units)";
    auto amps = grid_opt(s, "amplitudes", au);
    auto freqs = grid_opt(s, "frequencies", wu);
    if (!amps) s.fail("amplitudes", "missing; expected the grid of pulse amplitudes " + au);
    if (!freqs) s.fail("frequencies", "missing; expected the grid of pulse frequencies " + wu);
    for (double& a : *amps) a *= a_factor;
    for (double& w : *freqs) w *= w_factor;
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

// one column of what a study adds for a run with finite friction: name, unit, meaning and its
// field of a run. The same table ends the spectrum and the sweep rows (after their last column),
// only when friction is finite, so that a study without friction writes what it always did
struct SlidingColumn {
  const char* name;
  const char* unit;
  const char* doc;
  ColumnType type;
  Value (*get)(const study::RunSummary& r);
  void (*set)(study::RunSummary& r, const Value& v);
};

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

void add_sliding_columns(std::vector<std::string>& v) {
  for (const SlidingColumn& c : kSlidingColumns) v.emplace_back(c.name);
}

void add_sliding_fields(std::string& s, const study::RunSummary& r) {
  for (const SlidingColumn& c : kSlidingColumns) s.append(",").append(format_field(c.get(r)));
}

}  // namespace

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

}  // namespace

std::vector<std::string> spectrum_columns(bool sliding) {
  std::vector<std::string> v;
  for (const SpectrumColumn& c : kSpectrumColumns) v.emplace_back(c.name);
  if (sliding) add_sliding_columns(v);
  return v;
}

std::vector<ColumnInfo> spectrum_column_info(bool sliding) {
  std::vector<ColumnInfo> v;
  for (const SpectrumColumn& c : kSpectrumColumns) v.push_back({c.name, c.unit, c.type});
  if (sliding) {
    for (const SlidingColumn& c : kSlidingColumns) v.push_back({c.name, c.unit, c.type});
  }
  return v;
}

std::vector<FieldValue> spectrum_values(const study::SpectrumResult& res,
                                        const study::SpectrumCell& c, double g) {
  std::vector<FieldValue> v;
  for (const SpectrumColumn& col : kSpectrumColumns) v.push_back(col.get(res, c, g));
  if (res.sliding) {
    for (const SlidingColumn& col : kSlidingColumns) v.push_back(col.get(c.run));
  }
  return v;
}

std::string spectrum_row(const study::SpectrumResult& res, const study::SpectrumCell& c, double g) {
  std::string s;
  for (const SpectrumColumn& col : kSpectrumColumns) {
    if (&col != kSpectrumColumns) s += ',';
    s += format_field(col.get(res, c, g));
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
     "the column's frequency as the grid holds it: omega_p/p on normalized axes, rad/s on "
     "physical ones",
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
       for (const auto k :
            {Boundary::Kind::kFound, Boundary::Kind::kBelowGrid, Boundary::Kind::kNone}) {
         if (text(v) == study::to_string(k)) {
           b.kind = k;
           return;
         }
       }
       throw InputError("unknown kind \"" + text(v) + "\"");
     }},
    {"min_overturning", "grid",
     "the upper end of the bracket: an amplitude shown to overturn, as the grid holds it "
     "(a_p/(g tan alpha) on normalized axes, m/s^2 on physical ones, the factor on a record); "
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

// the context of a boundary row: the spec's units in SI
BoundaryContext boundary_context(const study::SpectrumResult& res, const study::OverturnBoundary& b,
                                 bool normalized, double g) {
  const bool record = res.cells.size() == 1 || (!res.cells.empty() && res.cells[0].omega_si == 0.0);
  // the spec's units to m/s^2 and rad/s
  double a_unit = normalized ? g * res.tan_alpha : 1.0;
  double omega = normalized ? b.frequency * res.p : b.frequency;
  if (record) {
    const study::SpectrumCell& c0 = res.cells.front();
    a_unit = c0.amplitude > 0.0 ? c0.amplitude_si / c0.amplitude : 0.0;  // the record's PGA
    omega = 0.0;
  }
  return {res, g, a_unit, omega};
}

}  // namespace

std::vector<std::string> boundary_columns() {
  std::vector<std::string> v;
  for (const BoundaryColumn& c : kBoundaryColumns) v.emplace_back(c.name);
  return v;
}

std::string boundary_row(const study::SpectrumResult& res, const study::OverturnBoundary& b,
                         bool normalized, double g) {
  const BoundaryContext x = boundary_context(res, b, normalized, g);
  std::string s;
  for (const BoundaryColumn& col : kBoundaryColumns) {
    if (&col != kBoundaryColumns) s += ',';
    s += format_field(col.get(x, b));
  }
  return s;
}

void write_spectrum_csv(std::ostream& out, const study::SpectrumResult& result, double g) {
  out << join(spectrum_columns(result.sliding), ",") << '\n';
  for (const study::SpectrumCell& c : result.cells) out << spectrum_row(result, c, g) << '\n';
}

void write_boundary_csv(std::ostream& out, const study::SpectrumResult& result, bool normalized,
                        double g) {
  out << join(boundary_columns(), ",") << '\n';
  for (const study::OverturnBoundary& b : result.boundary) {
    out << boundary_row(result, b, normalized, g) << '\n';
  }
}

// ---------------------------------------------------------------------------------------------
// sweep

SweepManifest load_sweep_manifest(const std::string& path) {
  const toml::table doc = detail::parse_toml(path, "sweep manifest");
  Keys top(path, doc, "");
  SweepManifest m;
  m.source = path;
  m.input_files.push_back(path);
  std::uint64_t h = fnv1a(file_bytes(path));
  top.string_opt("name", "a string");
  top.string_opt("description", "a string");
  m.spec.free_periods =
      top.nonnegative_or("free_periods", 2.0, "[-] (rocking periods 2 pi/p after the record)");
  std::set<std::string> names;
  for (Keys& b : top.tables("body", "a body: { name, file } (a case or body file)")) {
    study::SweepBody sb;
    const std::string file = b.string("file", "a path to a case or body file with a [body] table");
    const std::string full = detail::resolve_path(path, file);
    sb.name = b.string_opt("name", "a string").value_or(fs::path(file).stem().string());
    check_name(b, "name", sb.name);
    if (!names.insert("body:" + sb.name).second)
      b.fail("name", "expected a unique body name, got \"" + sb.name + "\" twice");
    // this body's Coulomb friction, in place of [solver]'s pair, by the same rules
    const std::string fw = solver_rule_text(*find_solver_key("friction_coefficient"));
    if (const auto mu = b.number_opt("friction_coefficient", fw, true)) {
      if (!friction_coefficient_ok(*mu)) b.expected("friction_coefficient", fw);
      sb.friction_coefficient = *mu;
    }
    const std::string kw =
        "a number > 0 [-], at most this body's friction_coefficient (or inf: equal to it)";
    if (const auto mu = b.number_opt("kinetic_friction_coefficient", kw, true)) {
      if (!sb.friction_coefficient) {
        b.fail("kinetic_friction_coefficient",
               "expected friction_coefficient in the same [[body]] (a body's kinetic coefficient "
               "goes with its static one)");
      }
      if (!kinetic_friction_coefficient_ok(*mu, *sb.friction_coefficient))
        b.expected("kinetic_friction_coefficient", kw);
      sb.kinetic_friction_coefficient = *mu;
    }
    b.finish("for a [[body]] (see docs/studies.md)");
    try {
      sb.body = load_body(full, nullptr, &m.input_files);
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + " (body named by [[body]] at " + path + ":" +
                       std::to_string(b.line()) + ")");
    }
    h = fnv1a(file_bytes(full), h);
    m.spec.bodies.push_back(std::move(sb));
  }
  // records come from [[record]] tables, [[suite]] tables or both
  std::vector<Keys> record_tables;
  if (top.has("record") || !top.has("suite")) {
    record_tables = top.tables("record",
                               "a record: { file, format, units, dt, name } (or a [[suite]] of "
                               "records: { horizontal, vertical })");
  }
  for (Keys& r : record_tables) {
    study::SweepRecord sr;
    const Record rec = read_record(r, sr.name, &h, m.input_files);
    check_name(r, "name", sr.name);
    if (!names.insert("record:" + sr.name).second)
      r.fail("name", "expected a unique record name, got \"" + sr.name + "\" twice");
    sr.motion = rec.to_motion();
    m.spec.records.push_back(std::move(sr));
  }
  std::vector<Keys> suite_tables;
  if (top.has("suite"))
    suite_tables =
        top.tables("suite", "a record suite: { horizontal, vertical, format, units, dt }");
  for (Keys& r : suite_tables) {
    for (study::SweepRecord& sr : read_suite(r, h, m.input_files)) {
      if (!names.insert("record:" + sr.name).second)
        r.fail("horizontal", "expected unique record names, got \"" + sr.name + "\" twice");
      m.spec.records.push_back(std::move(sr));
    }
  }
  auto sk = top.table_opt("scales");
  if (!sk)
    throw InputError(path +
                     ": table [scales]: missing; expected a [scales] table with 'factors' or "
                     "'target_pga' (see docs/studies.md)");
  const bool f = sk->has("factors");
  const bool t = sk->has("target_pga");
  const bool ti = sk->has("target_im");
  if (int(f) + int(t) + int(ti) != 1) {
    sk->fail(t    ? "target_pga"
             : ti ? "target_im"
                  : "factors",
             "expected exactly one of 'factors' [-], 'target_pga' or 'target_im' with 'targets'");
  }
  const char* grid_key = f ? "factors" : t ? "target_pga" : "targets";
  if (!ti && sk->has("targets")) sk->fail("targets", "only with 'target_im'");
  if (f) {
    m.spec.scale_kind = study::ScaleKind::kFactor;
    m.spec.scales = *grid_opt(*sk, "factors", "[-]");
    if (sk->has("units")) sk->fail("units", "only with 'target_pga' or an acceleration target_im");
  } else if (ti) {
    // stripes at levels of any measure that grows with the factor: sa:T[:zeta], pgv, pgd, ...
    const std::string what =
        "a measure that grows with the scale factor: pgv, pgd, arias, cav, "
        "sa:T or sa:T:zeta (T [s], zeta 0.05 by default)";
    const std::string name = *sk->string_opt("target_im", "a string, " + what);
    study::MeasureRequest r;
    try {
      r = study::measure_request(name);
    } catch (const InputError& e) {
      sk->fail("target_im", "expected " + what + ", got " + e.what());
    }
    const IntensityMeasure* im = find_intensity_measure(r.name);
    if (im->always_written || im->scale_power == 0) {
      sk->fail("target_im", "expected " + what + ", got \"" + name + "\"" +
                                (name == "pga" ? " (use target_pga)" : ""));
    }
    m.spec.scale_kind = study::ScaleKind::kTargetMeasure;
    m.spec.target = r;
    m.spec.scales = *grid_opt(*sk, "targets", "(units)");
    m.spec.levels = m.spec.scales;  // as written, for the CSV's level column
    if (r.name == "sa") {
      m.spec.level_units = sk->choice("units", detail::accel_unit_names(), "g");
      const double u = to_si_factor(detail::accel_unit(m.spec.level_units));
      for (double& v : m.spec.scales) v *= u;
    } else {
      if (sk->has("units"))
        sk->fail("units", "only for an acceleration target: " + name + " is in " +
                              find_intensity_measure(name)->unit);
      m.spec.level_units = find_intensity_measure(name)->unit;
    }
  } else {
    m.spec.scale_kind = study::ScaleKind::kTargetPga;
    m.spec.level_units = sk->choice("units", detail::accel_unit_names(), "g");
    const double u = to_si_factor(detail::accel_unit(m.spec.level_units));
    m.spec.scales = *grid_opt(*sk, "target_pga", "(units)");
    m.spec.levels = m.spec.scales;  // as written, for the CSV's level column
    for (double& v : m.spec.scales) v *= u;
  }
  for (std::size_t i = 0; i < m.spec.scales.size(); ++i) {
    if (!(m.spec.scales[i] > 0.0)) {
      sk->fail(grid_key, "expected values > 0, got " + num(m.spec.scales[i]) + " at position " +
                             std::to_string(i + 1));
    }
  }
  const double runs = static_cast<double>(m.spec.bodies.size()) *
                      static_cast<double>(m.spec.records.size()) *
                      static_cast<double>(m.spec.scales.size());
  if (runs > static_cast<double>(kMaxStudyRuns)) {
    sk->fail(f ? "factors" : "target_pga",
             "expected at most " + std::to_string(kMaxStudyRuns) + " runs, got " +
                 std::to_string(m.spec.bodies.size()) + " bodies x " +
                 std::to_string(m.spec.records.size()) + " records x " +
                 std::to_string(m.spec.scales.size()) + " scales");
  }
  sk->finish("in [scales] (see docs/studies.md)");
  if (auto ik = top.table_opt("intensity")) {
    // measures besides PGA and PGV, in the order given; Sa at each of sa_periods
    std::vector<std::string> im_names;
    for (const IntensityMeasure& im : intensity_measures()) {
      if (!im.always_written && !im.needs_period) im_names.emplace_back(im.name);
    }
    const std::string what = "an array of names, each one of: " + join(im_names);
    if (const toml::node* n = ik->node("measures")) {
      const toml::array* a = n->as_array();
      if (!a) ik->expected("measures", what);
      for (const toml::node& e : *a) {
        const auto* name = e.as_string();
        if (!name || std::find(im_names.begin(), im_names.end(), name->get()) == im_names.end()) {
          ik->fail_at(line_of(e), "measures",
                      "expected " + what + ", got " + describe(e) +
                          (!name || !find_intensity_measure(name->get()) ? ""
                           : find_intensity_measure(name->get())->needs_period
                               ? " (Sa: give its periods as sa_periods)"
                               : " (pga and pgv are always written)"));
        }
        for (const study::MeasureRequest& r : m.spec.measures) {
          if (r.name == name->get())
            ik->fail_at(line_of(e), "measures", "\"" + r.name + "\" given twice");
        }
        m.spec.measures.push_back({name->get(), 0.0, 0.05});
      }
    }
    const double zeta = ik->number_or("sa_damping", 0.05, "a number in [0, 1) [-]");
    if (!(zeta >= 0.0 && zeta < 1.0)) ik->expected("sa_damping", "a number in [0, 1) [-]");
    const std::string periods_what =
        "an array of periods >= " + num(kMinSpectralPeriod) + " [s] (below it Sa is the PGA)";
    if (const auto periods = ik->vector_opt("sa_periods", periods_what)) {
      for (std::size_t i = 0; i < periods->size(); ++i) {
        const double T = (*periods)[i];
        if (!(std::isfinite(T) && T >= kMinSpectralPeriod))
          ik->expected("sa_periods", periods_what);
        for (std::size_t j = 0; j < i; ++j) {
          if ((*periods)[j] == T) ik->fail("sa_periods", "period " + num(T) + " s given twice");
        }
        m.spec.measures.push_back({"sa", T, zeta});
      }
    } else if (ik->has("sa_damping")) {
      ik->fail("sa_damping", "expected only with sa_periods");
    }
    ik->finish("in [intensity] (see docs/studies.md)");
  }
  if (auto s = top.table_opt("solver")) {
    if (m.spec.bodies.empty()) throw InputError(path + ": expected at least one [[body]]");
    read_solver(*s, m.spec.solver, m.spec.bodies.front().body);
  }
  detail::read_uncertainty(top, m.spec);
  top.finish("at the top level of a sweep manifest");
  m.hash = h;
  return m;
}

namespace {

// one column of the sweep CSV: name, unit, meaning, type, its field of a row and (for what a run
// found) how a field read back sets it; the columns without `set` follow from the run index and
// the spec. The header, the rows, the reader, the Python arrays and the column reference of
// docs/studies.md are written from this table
struct SweepColumn {
  std::string_view name;
  const char* unit;
  const char* doc;
  ColumnType type;
  Value (*get)(const study::SweepSpec& spec, const study::SweepRow& row);
  void (*set)(study::SweepRow& row, const Value& v);
};

using Spec = study::SweepSpec;
using Row = study::SweepRow;

const SweepColumn kSweepColumns[] = {
    {"index", "-", "run index", ColumnType::kInteger,
     [](const Spec&, const Row& r) -> Value { return static_cast<long long>(r.index); }, nullptr},
    {"body", "-", "name of the body", ColumnType::kText,
     [](const Spec& s, const Row& r) -> Value { return s.bodies.at(r.body).name; }, nullptr},
    {"record", "-", "name of the record (a `[[suite]]` pair: `<horizontal stem>+<vertical stem>`)",
     ColumnType::kText,
     [](const Spec& s, const Row& r) -> Value { return s.records.at(r.record).name; }, nullptr},
    {"requested_level", "`requested_units`",
     "the level as `[scales]` gives it: the factor, the target PGA in `[scales] units`, or the "
     "target of `target_im`; the same number for every record at one level (`pga_g` is "
     "computed and differs in the last digits between records: group or pivot on "
     "`requested_level`; it is the stripe of `flexrock fragility --analysis msa`)",
     ColumnType::kReal,
     [](const Spec& s, const Row& r) -> Value {
       const std::vector<double>& levels = s.levels.empty() ? s.scales : s.levels;
       return levels.at(r.scale_index);
     },
     nullptr},
    {"requested_units", "-",
     "`-` for factors, else the `[scales] units` (`g`, `m/s^2`, `cm/s^2`), or the unit of a "
     "`target_im` that is no acceleration",
     ColumnType::kText,
     [](const Spec& s, const Row&) -> Value {
       if (s.scale_kind == study::ScaleKind::kFactor) return std::string("-");
       return s.level_units.empty() ? std::string("m/s^2") : s.level_units;
     },
     nullptr},
    {"scale", "-", "factor applied to the record", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.scale; },
     [](Row& r, const Value& v) { r.scale = real(v); }},
    {"pga_m_per_s2", "m/s^2",
     "scaled record's peak \\|abs\\| horizontal acceleration over its samples", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.pga; },
     [](Row& r, const Value& v) { r.pga = real(v); }},
    {"pga_g", "g", "the same in g", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.pga / kStandardGravity; }, nullptr},
    {"pgv_m_per_s", "m/s",
     "scaled record's peak \\|velocity\\|: the trapezoidal integral of the acceleration from 0 at "
     "the first sample, no baseline correction (the record's own processing is trusted); the "
     "factor times the unscaled record's PGV",
     ColumnType::kReal, [](const Spec&, const Row& r) -> Value { return r.pgv; },
     [](Row& r, const Value& v) { r.pgv = real(v); }},
    {"duration_s", "s", "simulated span: record + free motion", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.duration; },
     [](Row& r, const Value& v) { r.duration = real(v); }},
    {"outcome", "-", "outcome class", ColumnType::kText,
     [](const Spec&, const Row& r) -> Value { return study::to_string(r.run.outcome); },
     [](Row& r, const Value& v) { r.run.outcome = outcome_value(v); }},
    {"overturned", "0/1", "1 for an overturning class", ColumnType::kInteger,
     [](const Spec&, const Row& r) -> Value {
       return study::overturned(r.run.outcome) ? 1LL : 0LL;
     },
     nullptr},
    {"overturn_edge", "-", "1 or 2 (0: none)", ColumnType::kInteger,
     [](const Spec&, const Row& r) -> Value { return static_cast<long long>(r.run.overturn_edge); },
     [](Row& r, const Value& v) { r.run.overturn_edge = static_cast<int>(integer(v)); }},
    {"overturn_time_s", "s", "-1: none", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.overturn_time; },
     [](Row& r, const Value& v) { r.run.overturn_time = real(v); }},
    {"max_theta_rad", "rad", "largest tilt", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.max_theta; },
     [](Row& r, const Value& v) { r.run.max_theta = real(v); }},
    {"max_theta_over_alpha", "-", "largest tilt over the overturning angle", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.max_theta_over_alpha; },
     [](Row& r, const Value& v) { r.run.max_theta_over_alpha = real(v); }},
    {"impacts", "-", "impacts", ColumnType::kInteger,
     [](const Spec&, const Row& r) -> Value { return static_cast<long long>(r.run.impacts); },
     [](Row& r, const Value& v) { r.run.impacts = static_cast<long>(integer(v)); }},
    {"first_uplift_time_s", "s", "-1: never", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.first_uplift_time; },
     [](Row& r, const Value& v) { r.run.first_uplift_time = real(v); }},
    {"max_uplift_m", "m", "largest height of a lifted tipping point", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.max_uplift; },
     [](Row& r, const Value& v) { r.run.max_uplift = real(v); }},
    {"max_impulse_N_s", "N s", "largest vertical impact impulse", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.max_impulse; },
     [](Row& r, const Value& v) { r.run.max_impulse = real(v); }},
    {"energy_lost_J", "J", "impacts + chatter + damping", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.energy_lost; },
     [](Row& r, const Value& v) { r.run.energy_lost = real(v); }},
    {"max_friction_demand", "-", "largest \\|F_I\\|/F_J, impulses included", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.max_friction_demand; },
     [](Row& r, const Value& v) { r.run.max_friction_demand = real(v); }},
    // where the sticking contact breaks without a friction limit (a finite coefficient removes
    // them): docs/theory.md §15, §16
    {"pivot_tension_episodes", "-",
     "times the pivot force vanished where only sliding could free the pivot (`pivot_tension`): "
     "the floor was let pull",
     ColumnType::kInteger,
     [](const Spec&, const Row& r) -> Value {
       return static_cast<long long>(r.run.tension_episodes);
     },
     [](Row& r, const Value& v) { r.run.tension_episodes = static_cast<long>(integer(v)); }},
    {"max_pivot_pull_N", "N", "largest pull of the floor on a held pivot, -min F_J (0: none)",
     ColumnType::kReal, [](const Spec&, const Row& r) -> Value { return r.run.max_pivot_pull; },
     [](Row& r, const Value& v) { r.run.max_pivot_pull = real(v); }},
    {"tension_time_s", "s", "time the floor pulled on a held pivot", ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.tension_time; },
     [](Row& r, const Value& v) { r.run.tension_time = real(v); }},
    {"tensile_landings", "-", "landings that needed a pulling impulse (`tensile_landing`)",
     ColumnType::kInteger,
     [](const Spec&, const Row& r) -> Value {
       return static_cast<long long>(r.run.tensile_landings);
     },
     [](Row& r, const Value& v) { r.run.tensile_landings = static_cast<long>(integer(v)); }},
    {"max_tensile_impulse_N_s", "N s", "largest such pulling impulse, -min I_y (0: none)",
     ColumnType::kReal,
     [](const Spec&, const Row& r) -> Value { return r.run.max_tensile_impulse; },
     [](Row& r, const Value& v) { r.run.max_tensile_impulse = real(v); }},
    {"status", "-", "engine status", ColumnType::kText,
     [](const Spec&, const Row& r) -> Value { return to_string(r.run.status); },
     [](Row& r, const Value& v) { r.run.status = status_value(v); }},
    {"message", "-", "why a stopped run stopped (commas replaced by `;`)", ColumnType::kText,
     [](const Spec&, const Row& r) -> Value {
       std::string msg = r.message;
       for (char& c : msg) {
         if (c == ',' || c == '"') c = ';';
         if (c == '\n' || c == '\r') c = ' ';
       }
       return msg;
     },
     [](Row& r, const Value& v) { r.message = text(v); }},
};

}  // namespace

std::vector<std::string> sweep_columns(bool sliding) {
  std::vector<std::string> v;
  for (const SweepColumn& c : kSweepColumns) v.emplace_back(c.name);
  if (sliding) add_sliding_columns(v);
  return v;
}

// the requested intensity measures follow this column
constexpr std::string_view kMeasuresAfter = "pgv_m_per_s";

std::vector<std::string> sweep_columns(const study::SweepSpec& spec) {
  std::vector<std::string> v;
  for (const ColumnInfo& c : sweep_column_info(spec)) v.push_back(c.name);
  return v;
}

std::vector<ColumnInfo> sweep_column_info(const study::SweepSpec& spec) {
  std::vector<ColumnInfo> v;
  for (const SweepColumn& c : kSweepColumns) {
    v.push_back({std::string(c.name), c.unit, c.type});
    if (c.name == kMeasuresAfter) {
      for (const study::MeasureRequest& m : spec.measures) {
        v.push_back(
            {study::measure_column(m), find_intensity_measure(m.name)->unit, ColumnType::kReal});
      }
      for (const study::UncertainParameter& p : spec.uncertainty.parameters) {
        const study::UncertainKindInfo& k = study::uncertain_kind(p.kind);
        v.push_back({k.column, k.unit, ColumnType::kReal});
      }
    }
  }
  if (study::has_friction(spec)) {
    for (const SlidingColumn& c : kSlidingColumns) v.push_back({c.name, c.unit, c.type});
  }
  return v;
}

std::vector<FieldValue> sweep_values(const study::SweepSpec& spec, const study::SweepRow& row) {
  std::vector<FieldValue> v;
  for (const SweepColumn& col : kSweepColumns) {
    v.push_back(col.get(spec, row));
    if (col.name == kMeasuresAfter) {
      for (const double x : row.measures) v.emplace_back(x);
      for (const double x : row.sampled) v.emplace_back(x);
    }
  }
  if (study::has_friction(spec)) {
    for (const SlidingColumn& c : kSlidingColumns) v.push_back(c.get(row.run));
  }
  return v;
}

std::string sweep_row(const study::SweepSpec& spec, const study::SweepRow& row) {
  std::string s;
  for (const SweepColumn& col : kSweepColumns) {
    if (&col != kSweepColumns) s += ',';
    s += format_field(col.get(spec, row));
    if (col.name == kMeasuresAfter) {
      for (const double x : row.measures) s += ',' + field(x);
      for (const double x : row.sampled) s += ',' + field(x);
    }
  }
  if (study::has_friction(spec)) add_sliding_fields(s, row.run);
  return s;
}

std::string format_field(const FieldValue& v) {
  if (const auto* i = std::get_if<long long>(&v)) return std::to_string(*i);
  if (const auto* x = std::get_if<double>(&v)) return field(*x);
  return std::get<std::string>(v);
}

// ---------------------------------------------------------------------------------------------
// journal lines

namespace {

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t c = line.find(',', start);
    out.push_back(
        line.substr(start, c == std::string_view::npos ? std::string_view::npos : c - start));
    if (c == std::string_view::npos) return out;
    start = c + 1;
  }
}

// the text before the n-th comma: the first n fields
std::string_view first_fields(std::string_view line, std::size_t n) {
  std::size_t pos = 0;
  for (std::size_t k = 0; k < n; ++k) {
    pos = line.find(',', pos);
    if (pos == std::string_view::npos) return line;
    ++pos;
  }
  return line.substr(0, pos == 0 ? 0 : pos - 1);
}

// a finite number as field() writes it ("inf" and "nan" are never written)
bool is_number(std::string_view f) {
  double v = 0.0;
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
  return !f.empty() && r.ec == std::errc() && r.ptr == f.data() + f.size() && std::isfinite(v);
}

// a run's result figure: a finite number, or empty where the run has none (field())
bool is_figure(std::string_view f) { return f.empty() || is_number(f); }

bool is_count(std::string_view f) {
  long v = 0;
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
  return !f.empty() && r.ec == std::errc() && r.ptr == f.data() + f.size() && v >= 0;
}

bool is_status(std::string_view name) { return status_named(name).has_value(); }

// the fields of a run's outcome: a known name and the overturned flag that goes with it
std::string check_outcome(std::string_view outcome, std::string_view flag) {
  const std::optional<study::Outcome> o = outcome_named(outcome);
  if (!o) return "unknown outcome \"" + std::string(outcome) + "\"";
  if (flag != (study::overturned(*o) ? "1" : "0")) {
    return "overturned = " + std::string(flag) + " does not go with outcome " +
           std::string(outcome);
  }
  return "";
}

// the sliding fields from position `first` on: a known regime word, numbers, a count
std::string check_sliding_fields(const std::vector<std::string_view>& f, std::size_t first) {
  if (!regime_named(f[first])) return "unknown regime \"" + std::string(f[first]) + "\"";
  for (std::size_t k = first + 1; k + 1 < f.size(); ++k) {
    if (!is_figure(f[k]))
      return "field " + std::to_string(k + 1) + " is not a finite number or empty";
  }
  if (!is_count(f.back())) return "slips is not a count";
  return "";
}

std::string check_fields(const std::vector<std::string_view>& f, std::size_t expected) {
  if (f.size() != expected) {
    return std::to_string(f.size()) + " fields, expected " + std::to_string(expected);
  }
  return "";
}

}  // namespace

JournalCheck sweep_journal_check(const study::SweepSpec& spec) {
  // the bodies and record intensities, once: every run's input fields follow from them
  auto bodies = std::make_shared<std::vector<Body>>();
  for (const study::SweepBody& b : spec.bodies) bodies->emplace_back(b.body);
  auto im = std::make_shared<std::vector<study::Intensity>>();
  for (const study::SweepRecord& r : spec.records)
    im->push_back(study::record_intensity(spec, r.motion));
  auto runs = std::make_shared<std::vector<study::SweepRun>>(study::sweep_runs(spec));
  auto design = std::make_shared<study::SampleDesign>(study::sample_design(spec));
  // where the fields are, by column name
  const bool sliding = study::has_friction(spec);
  const std::vector<std::string> names = sweep_columns(spec);
  auto col = [&names](const char* name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const std::size_t columns = names.size();
  // the sliding columns end the row
  const std::size_t first_sliding =
      names.size() - (sliding ? sweep_columns(true).size() - sweep_columns(false).size() : 0);
  const std::size_t inputs = col("duration_s") + 1;  // the fields a run's inputs decide
  const std::size_t outcome = col("outcome"), edge = col("overturn_edge");
  const std::size_t impacts = col("impacts"), status = col("status");
  return [&spec, bodies, im, runs, design, columns, inputs, outcome, edge, impacts, status, sliding,
          first_sliding](std::size_t index, const std::string& line) -> std::string {
    if (index >= runs->size()) return "no such run";
    const study::SweepRun& run = (*runs)[index];
    const std::vector<std::string_view> f = fields_of(line);
    if (std::string why = check_fields(f, columns); !why.empty()) return why;
    // index, body, record, level, scale, PGA, PGV, sampled values, duration: as the manifest
    // makes this run
    const study::SweepRow row =
        study::sweep_inputs(spec, run, (*bodies)[run.body], (*im)[run.record], *design);
    const std::string expected(first_fields(sweep_row(spec, row), inputs));
    if (first_fields(line, inputs) != expected) {
      return "its first fields are not those of run " + std::to_string(index) + " (" + expected +
             ")";
    }
    if (std::string why = check_outcome(f[outcome], f[outcome + 1]); !why.empty()) return why;
    for (std::size_t k = edge + 1; k < status; ++k) {
      if (k != impacts && !is_figure(f[k])) {
        return "field " + std::to_string(k + 1) + " is not a finite number or empty";
      }
    }
    if (f[edge] != "0" && f[edge] != "1" && f[edge] != "2") return "overturn_edge is not 0, 1 or 2";
    if (!is_count(f[impacts])) return "impacts is not a count";
    if (!is_status(f[status])) return "unknown status \"" + std::string(f[status]) + "\"";
    if (sliding) return check_sliding_fields(f, first_sliding);
    return "";
  };
}

JournalCheck spectrum_journal_check(const study::SpectrumResult& grid, bool normalized, double g) {
  auto res = std::make_shared<study::SpectrumResult>(grid);
  // where the fields are, by column name
  struct Fields {
    std::size_t count, inputs, outcome, ratio, impacts, uplift, overturn, energy, status;
  };
  struct BoundaryFields {
    std::size_t count, inputs, kind, min, safe, min_si, min_norm, mode, runs;
  };
  auto at = [](const std::vector<std::string>& names, const char* name) {
    const auto it = std::find(names.begin(), names.end(), name);
    FLEXROCK_DEMAND(it != names.end());
    return static_cast<std::size_t>(it - names.begin());
  };
  const std::vector<std::string> cn = spectrum_columns(grid.sliding), bn = boundary_columns();
  const std::size_t first_sliding = spectrum_columns(false).size();
  // a cell's inputs: row, column, amplitudes, frequencies, scale: as the spec makes this cell
  const Fields c{cn.size(),
                 at(cn, "scale") + 1,
                 at(cn, "outcome"),
                 at(cn, "max_theta_over_alpha"),
                 at(cn, "impacts"),
                 at(cn, "first_uplift_time_s"),
                 at(cn, "overturn_time_s"),
                 at(cn, "energy_lost_J"),
                 at(cn, "status")};
  // a boundary's inputs: column and frequencies
  const BoundaryFields bf{bn.size(),
                          at(bn, "omega_p_over_p") + 1,
                          at(bn, "kind"),
                          at(bn, "min_overturning"),
                          at(bn, "safe_below"),
                          at(bn, "min_overturning_m_per_s2"),
                          at(bn, "min_overturning_over_g_tan_alpha"),
                          at(bn, "mode"),
                          at(bn, "bisection_runs")};
  return [res, normalized, g, c, bf, first_sliding](std::size_t index,
                                                    const std::string& line) -> std::string {
    const std::vector<std::string_view> f = fields_of(line);
    const std::size_t cells = res->cells.size();
    if (index < cells) {
      if (std::string why = check_fields(f, c.count); !why.empty()) return why;
      const std::string expected(first_fields(spectrum_row(*res, res->cells[index], g), c.inputs));
      if (first_fields(line, c.inputs) != expected) {
        return "its first fields are not those of cell " + std::to_string(index) + " (" + expected +
               ")";
      }
      if (std::string why = check_outcome(f[c.outcome], f[c.outcome + 1]); !why.empty()) return why;
      for (const std::size_t k : {c.ratio, c.uplift, c.overturn, c.energy}) {
        if (!is_figure(f[k]))
          return "field " + std::to_string(k + 1) + " is not a finite number or empty";
      }
      if (!is_count(f[c.impacts])) return "impacts is not a count";
      if (!is_status(f[c.status])) return "unknown status \"" + std::string(f[c.status]) + "\"";
      if (res->sliding) return check_sliding_fields(f, first_sliding);
      return "";
    }
    const std::size_t j = index - cells;
    if (j >= res->boundary.size()) return "no such cell or boundary";
    if (std::string why = check_fields(f, bf.count); !why.empty()) return why;
    const std::string expected(
        first_fields(boundary_row(*res, res->boundary[j], normalized, g), bf.inputs));
    if (first_fields(line, bf.inputs) != expected) {
      return "its first fields are not those of the boundary of column " + std::to_string(j) +
             " (" + expected + ")";
    }
    const std::string_view kind = f[bf.kind];
    const bool none = kind == "none";
    if (!none && kind != "found" && kind != "below_grid") {
      return "unknown kind \"" + std::string(kind) + "\"";
    }
    for (const std::size_t k : {bf.min, bf.safe, bf.min_si, bf.min_norm}) {
      const bool empty_ok = none || (k == bf.safe && kind == "below_grid");
      if (!(is_number(f[k]) || (empty_ok && f[k].empty()))) {
        return "field " + std::to_string(k + 1) + " is not a number";
      }
    }
    if (!none && (!outcome_named(f[bf.mode]) || !study::overturned(*outcome_named(f[bf.mode])))) {
      return "mode \"" + std::string(f[bf.mode]) + "\" is not an overturning outcome";
    }
    if (!is_count(f[bf.runs])) return "bisection_runs is not a count";
    return "";
  };
}

namespace {

// a field's text read back as a value of its column's type: what format_field wrote (a real
// left empty, a value the run did not have, is NaN)
Value parse_field(std::string_view f, ColumnType type) {
  switch (type) {
    case ColumnType::kInteger: {
      long long v = 0;
      const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
      if (f.empty() || r.ec != std::errc() || r.ptr != f.data() + f.size()) {
        throw InputError("\"" + std::string(f) + "\" is not an integer");
      }
      return v;
    }
    case ColumnType::kReal: {
      if (f.empty()) return std::numeric_limits<double>::quiet_NaN();
      if (!is_number(f)) throw InputError("\"" + std::string(f) + "\" is not a finite number");
      double v = 0.0;
      std::from_chars(f.data(), f.data() + f.size(), v);
      return v;
    }
    case ColumnType::kText:
      break;
  }
  return std::string(f);
}

// the first field where a line and the line written back from what was read of it differ: what
// does not follow from the others (an outcome and its overturned flag, a body's name)
std::string first_difference(const std::vector<std::string>& names, std::string_view line,
                             std::string_view again) {
  const std::vector<std::string_view> a = fields_of(line), b = fields_of(again);
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    if (a[k] != b[k]) {
      return "field " + std::to_string(k + 1) + " (" + (k < names.size() ? names[k] : "?") +
             ") is \"" + std::string(a[k]) + "\", expected \"" + std::string(b[k]) + "\"";
    }
  }
  return "its fields do not read back to the same line";
}

}  // namespace

void check_sweep_table(const CsvTable& t) {
  const auto where = [&t](const char* name) {
    return static_cast<std::size_t>(std::find(t.columns.begin(), t.columns.end(), name) -
                                    t.columns.begin());
  };
  const std::size_t none = t.columns.size();
  const std::size_t index = where("index"), outcome = where("outcome"), flag = where("overturned"),
                    edge = where("overturn_edge"), impacts = where("impacts"),
                    status = where("status"), first_figure = where("overturn_time_s"),
                    regime = where("regime"), slips = where("slips");
  std::map<std::size_t, std::size_t> seen;  // run index -> file line
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& f = t.rows[r];
    auto bad = [&](const std::string& what) {
      throw InputError(t.source + ":" + std::to_string(t.lines[r]) + ": " + what +
                       "; expected a row as flexrock sweep writes it (was the file edited?)");
    };
    auto column = [&](std::size_t c, const std::string& what) {
      bad("column '" + t.columns[c] + "': expected " + what + ", got \"" + f[c] + "\"");
    };
    if (index != none) {
      if (!is_count(f[index])) column(index, "a run index (an integer >= 0)");
      const std::size_t i = std::stoul(f[index]);
      if (const auto [it, fresh] = seen.emplace(i, t.lines[r]); !fresh) {
        bad("run index " + f[index] + " twice, first at line " + std::to_string(it->second));
      }
    }
    // `contact_lost`, as outcome and as status: rows written before the engine followed flight,
    // which fragility still reads (and leaves out unless the outcome says overturned)
    const bool legacy = outcome != none && f[outcome] == "contact_lost";
    if (outcome != none && flag != none && !(legacy && f[flag] == "0")) {
      if (std::string why = check_outcome(f[outcome], f[flag]); !why.empty()) bad(why);
    }
    if (edge != none && f[edge] != "0" && f[edge] != "1" && f[edge] != "2") {
      column(edge, "0, 1 or 2");
    }
    if (impacts != none && !is_count(f[impacts])) column(impacts, "a count (an integer >= 0)");
    if (status != none && !is_status(f[status]) && f[status] != "contact_lost") {
      column(status, "a status flexrock writes");
    }
    // the run's figures: from overturn_time_s up to the status, and the sliding ones
    for (std::size_t c = first_figure; c < std::min(status, none); ++c) {
      if (c != impacts && !is_figure(f[c])) column(c, "a finite number or empty");
    }
    if (regime != none) {
      if (!regime_named(f[regime])) column(regime, "a regime flexrock writes");
      for (std::size_t c = regime + 1; c < std::min(slips, none); ++c) {
        if (!is_figure(f[c])) column(c, "a finite number or empty");
      }
    }
    if (slips != none && !is_count(f[slips])) column(slips, "a count (an integer >= 0)");
  }
}

study::SweepRow read_sweep_row(const study::SweepSpec& spec, std::size_t index,
                               const std::string& line) {
  const std::size_t scales = spec.scales.size(), records = spec.records.size();
  const std::size_t runs = spec.bodies.size() * records * scales;
  FLEXROCK_THROW_UNLESS(index < runs, "run index " + std::to_string(index) + " out of range (" +
                                          std::to_string(runs) + " runs)");
  study::SweepRow row;
  row.index = index;
  row.scale_index = index % scales;
  row.record = (index / scales) % records;
  row.body = index / (scales * records);
  // the column names only for messages: a resume reads every journaled line through here
  const std::size_t columns = std::size(kSweepColumns) + spec.measures.size() +
                              spec.uncertainty.parameters.size() +
                              (study::has_friction(spec) ? std::size(kSlidingColumns) : 0);
  const std::vector<std::string_view> f = fields_of(line);
  FLEXROCK_THROW_UNLESS(f.size() == columns,
                        std::to_string(f.size()) + " fields, expected " + std::to_string(columns));
  std::size_t k = 0;
  auto next = [&](ColumnType type) {
    try {
      return parse_field(f[k], type);
    } catch (const InputError& e) {
      throw InputError("field " + std::to_string(k + 1) + " (" + sweep_columns(spec).at(k) +
                       "): " + e.what());
    }
  };
  for (const SweepColumn& col : kSweepColumns) {
    const Value v = next(col.type);
    if (col.set) col.set(row, v);
    ++k;
    if (col.name == kMeasuresAfter) {
      for (std::size_t m = 0; m < spec.measures.size(); ++m, ++k) {
        row.measures.push_back(real(next(ColumnType::kReal)));
      }
      for (std::size_t p = 0; p < spec.uncertainty.parameters.size(); ++p, ++k) {
        row.sampled.push_back(real(next(ColumnType::kReal)));
      }
    }
  }
  if (study::has_friction(spec)) {
    for (const SlidingColumn& col : kSlidingColumns) {
      col.set(row.run, next(col.type));
      ++k;
    }
  }
  // what the row writes must be the line: the fields that follow from others agree with them,
  // and the final file written from the rows is the bytes the runs wrote
  const std::string again = sweep_row(spec, row);
  if (again != line) throw InputError(first_difference(sweep_columns(spec), line, again));
  return row;
}

study::SpectrumCell read_spectrum_cell(const study::SpectrumResult& grid, std::size_t index,
                                       const std::string& line, double g) {
  FLEXROCK_THROW_UNLESS(index < grid.cells.size(),
                        "cell index " + std::to_string(index) + " out of range (" +
                            std::to_string(grid.cells.size()) + " cells)");
  study::SpectrumCell cell = grid.cells[index];
  const std::vector<std::string> names = spectrum_columns(grid.sliding);
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
  }
  if (grid.sliding) {
    for (const SlidingColumn& col : kSlidingColumns) {
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
  const std::vector<std::string> names = boundary_columns();
  const std::vector<std::string_view> f = fields_of(line);
  FLEXROCK_THROW_UNLESS(f.size() == names.size(), std::to_string(f.size()) + " fields, expected " +
                                                      std::to_string(names.size()));
  for (std::size_t k = 0; k < names.size(); ++k) {
    const BoundaryColumn& col = kBoundaryColumns[k];
    try {
      const Value v = parse_field(f[k], col.type);
      if (col.set) col.set(b, v);
    } catch (const InputError& e) {
      throw InputError("field " + std::to_string(k + 1) + " (" + names[k] + "): " + e.what());
    }
  }
  const std::string again = boundary_row(grid, b, normalized, g);
  if (again != line) throw InputError(first_difference(names, line, again));
  return b;
}

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

std::vector<std::string> fragility_measures() {
  std::vector<std::string> v = {"pga", "pga_g", "pgv", "scale", "requested_level"};
  for (const IntensityMeasure& m : intensity_measures()) {
    if (m.always_written) continue;
    v.push_back(m.needs_period ? std::string(m.name) + ":T[:zeta]" : std::string(m.name));
  }
  return v;
}

std::string fragility_im_column(const std::string& im) {
  static const std::pair<const char*, const char*> kFixed[] = {
      {"pga", "pga_m_per_s2"},
      {"pga_g", "pga_g"},
      {"pgv", "pgv_m_per_s"},
      {"scale", "scale"},
      {"requested_level", "requested_level"}};
  for (const auto& [name, column] : kFixed) {
    if (im == name) return column;
  }
  auto bad = [&](const std::string& why) -> std::string {
    throw InputError("fragility: intensity measure '" + im + "': " + why +
                     "expected one of: " + join(fragility_measures()));
  };
  study::MeasureRequest m;
  try {
    m = study::measure_request(im);
  } catch (const InputError& e) {
    bad(std::string(e.what()) + "; ");
  }
  const IntensityMeasure* k = find_intensity_measure(m.name);
  if (k->always_written) bad("");
  return study::measure_column(m);
}

std::vector<FragilityData> fragility_data(const CsvTable& t, const FragilityQuery& q) {
  check_sweep_table(t);
  const std::string im_col = fragility_im_column(q.im);
  if (std::find(t.columns.begin(), t.columns.end(), im_col) == t.columns.end()) {
    throw InputError(t.source + ":1: intensity measure '" + q.im + "' needs the column '" + im_col +
                     "', which this sweep did not write: name it in the manifest's [intensity] "
                     "table (docs/studies.md) and run the sweep again");
  }
  std::string out_col;
  if (q.outcome == "overturned") {
    out_col = "overturned";
  } else if (q.outcome == "uplift") {
    out_col = "outcome";
  } else if (q.outcome == "theta") {
    out_col = "max_theta_over_alpha";
  } else if (q.outcome == "energy") {
    out_col = "energy_lost_J";
  } else if (q.outcome == "offset" || q.outcome == "residual_offset") {
    out_col = q.outcome == "offset" ? "max_offset_m" : "final_offset_m";
    if (std::find(t.columns.begin(), t.columns.end(), out_col) == t.columns.end()) {
      throw InputError(t.source + ":1: outcome '" + q.outcome + "' needs the column '" + out_col +
                       "', which a sweep writes only with a finite friction coefficient "
                       "(docs/studies.md); this file has none");
    }
  } else {
    throw InputError(
        "fragility: outcome '" + q.outcome +
        "': expected one of: overturned, uplift, theta, energy, offset, residual_offset");
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
  std::vector<FragilityData> out;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::string& body = t.rows[r][cb];
    if (!q.body.empty() && body != q.body) continue;
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const FragilityData& d) { return d.body == body; });
    if (it == out.end()) {
      out.push_back({body, {}, {}, 0, {}});
      it = out.end() - 1;
    }
    // not classified: the run could not go on (`contact_lost`: rows written before the engine
    // followed flight)
    const std::string& outcome = t.rows[r][cs];
    if (outcome == "stopped" || outcome == "contact_lost") {
      ++it->excluded;
      continue;
    }
    const double x = number(r, ci);
    int y = 0;
    if (q.outcome == "overturned") {
      y = number(r, co) != 0.0 ? 1 : 0;
    } else if (q.outcome == "uplift") {
      // every class but no_uplift left full contact (rocked, or overturned)
      y = outcome != "no_uplift" ? 1 : 0;
    } else {
      // an overturned body exceeds every tilt, energy and offset level; a residual offset counts
      // either way
      y = (number(r, cv) != 0.0 || std::abs(number(r, co)) > q.level) ? 1 : 0;
    }
    it->im.push_back(x);
    it->failed.push_back(y);
    it->record.push_back(cr < t.columns.size() ? t.rows[r][cr] : std::string());
  }
  if (out.empty()) {
    throw InputError(
        t.source + ": " +
        (q.body.empty() ? std::string("no rows") : "no rows of body '" + q.body + "'"));
  }
  return out;
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
};

// the column reference of one table, as a Markdown table between begin and end markers
template <class Column, std::size_t N>
std::string column_block(const char* what, const Column (&columns)[N]) {
  std::string s = std::string(
                      "<!-- begin: written by `flexrock keys --markdown` from the table "
                      "of ") +
                  what +
                  " columns (src/io/study_files.cpp); edit the table, not these lines -->\n"
                  "| column | unit | meaning |\n"
                  "|---|---|---|\n";
  for (const Column& c : columns) {
    s.append("| `").append(c.name).append("` | ").append(c.unit).append(" | ").append(c.doc);
    s.append(" |\n");
  }
  return s + "<!-- end: written by `flexrock keys --markdown` -->\n";
}

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
  DamageState s;
  s.label = text;
  s.outcome = text.substr(0, colon);
  const bool levelled = s.outcome == "theta" || s.outcome == "energy" || s.outcome == "offset" ||
                        s.outcome == "residual_offset";
  const std::string expected =
      "expected overturned, uplift, theta:X (max theta/alpha > X), energy:X (energy lost > X J), "
      "offset:X (peak sliding offset > X m) or residual_offset:X (|residual offset| > X m), X a "
      "number > 0";
  if (!levelled && !(s.outcome == "overturned" || s.outcome == "uplift")) {
    throw InputError("--state '" + text + "': " + expected);
  }
  if (levelled != (colon != std::string::npos)) {
    throw InputError("--state '" + text +
                     "': " + (levelled ? "a level is missing; " : "takes no level; ") + expected);
  }
  if (levelled) {
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

std::string study_column_reference() {
  return column_block("spectrum", kSpectrumColumns) + column_block("boundary", kBoundaryColumns) +
         column_block("sweep", kSweepColumns) + measure_block() +
         column_block("sliding", kSlidingColumns) + detail::uncertain_reference() +
         column_block("fragility fit", kFragilityColumns);
}

}  // namespace flexrock::io
