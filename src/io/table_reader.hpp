// SPDX-License-Identifier: BSD-3-Clause
// The TOML toolkit of the case-file and study-file loaders: checked reads of one table (every
// error names the file, the line and the full key, and says what was expected and what was
// found; unknown keys are rejected with the closest known one), parsing, paths relative to the
// file, acceleration units and record tables. Internal to flexrock::io.
#pragma once

#include <toml++/toml.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/sim/option_bounds.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/sim/solver_keys.hpp"

namespace flexrock::io::detail {

// a number for messages: 10 significant digits
inline std::string num(double v) { return format_number(v, 10); }

inline std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
  return s;
}

// what a TOML node holds, for "got ..."
inline std::string describe(const toml::node& n) {
  if (auto s = n.as_string()) return "\"" + s->get() + "\"";
  if (auto i = n.as_integer()) return std::to_string(i->get());
  if (auto f = n.as_floating_point()) return num(f->get());
  if (auto b = n.as_boolean()) return b->get() ? "true" : "false";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date or time";
}

inline std::size_t line_of(const toml::node& n) { return n.source().begin.line; }

// the keys of one TOML table, read with checks; every error names file, line and key
class TableReader {
 public:
  TableReader(std::string file, const toml::table& table, std::string prefix, std::size_t line = 0)
      : file_(std::move(file)), t_(table), prefix_(std::move(prefix)), line_(line) {
    if (line_ == 0) line_ = line_of(table);
  }

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  std::string full(std::string_view key) const { return prefix_ + std::string(key); }

  [[noreturn]] void fail_at(std::size_t line, std::string_view key, const std::string& msg) const {
    throw InputError(file_, line, full(key), msg);
  }
  [[noreturn]] void fail(std::string_view key, const std::string& msg) const {
    const toml::node* n = t_.get(key);
    fail_at(n ? line_of(*n) : line_, key, msg);
  }
  [[noreturn]] void expected(std::string_view key, const std::string& what) const {
    const toml::node* n = t_.get(key);
    fail(key, "expected " + what + ", got " + (n ? describe(*n) : std::string("nothing")));
  }

  bool has(std::string_view key) {
    known_.insert(std::string(key));
    return t_.contains(key);
  }
  const toml::node* node(std::string_view key) {
    known_.insert(std::string(key));
    return t_.get(key);
  }
  const toml::node& require(std::string_view key, const std::string& what) {
    const toml::node* n = node(key);
    if (!n) {
      // a misspelt key is the likelier cause than a forgotten one: name it first
      for (const auto& [k, v] : t_) {
        const std::string other(k.str());
        if (known_.count(other) || closest_key(other, {std::string(key)}).empty()) continue;
        const std::size_t at = k.source().begin.line ? k.source().begin.line : line_of(v);
        fail_at(at, other,
                "unknown key (did you mean '" + full(key) + "'?); '" + full(key) +
                    "' is required: " + what);
      }
      fail_at(line_, key, "missing; expected " + what);
    }
    return *n;
  }

  // any finite number (integers too); `allow_inf` admits +-inf
  std::optional<double> number_opt(std::string_view key, const std::string& what,
                                   bool allow_inf = false) {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    return to_number(*n, key, what, allow_inf);
  }
  double number(std::string_view key, const std::string& what) {
    return to_number(require(key, what), key, what, false);
  }
  double number_or(std::string_view key, double def, const std::string& what) {
    return number_opt(key, what).value_or(def);
  }
  double positive(std::string_view key, const std::string& unit) {
    const std::string what = "a number > 0 " + unit;
    const double v = number(key, what);
    if (!(v > 0.0)) expected(key, what);
    return v;
  }
  double positive_or(std::string_view key, double def, const std::string& unit) {
    return has(key) ? positive(key, unit) : def;
  }
  double nonnegative_or(std::string_view key, double def, const std::string& unit) {
    const std::string what = "a number >= 0 " + unit;
    const std::optional<double> v = number_opt(key, what);
    if (v && !(*v >= 0.0)) expected(key, what);
    return v.value_or(def);
  }
  // a number in the closed range of `b` (option_bounds.hpp), `b.key` being the key
  double bounded_or(const OptionBound& b, double def) {
    const std::string what = "a number in " + range_text(b) + " (" + b.why + ")";
    const std::optional<double> v = number_opt(b.key, what);
    if (v && !in_range(b, *v)) expected(b.key, what);
    return v.value_or(def);
  }
  long integer_or(std::string_view key, long def, long min, const std::string& what) {
    const toml::node* n = node(key);
    if (!n) return def;
    const auto* i = n->as_integer();
    if (!i || i->get() < min) expected(key, what);
    return static_cast<long>(i->get());
  }
  bool boolean_or(std::string_view key, bool def) {
    const toml::node* n = node(key);
    if (!n) return def;
    if (!n->is_boolean()) expected(key, "true or false");
    return n->as_boolean()->get();
  }
  std::optional<std::string> string_opt(std::string_view key, const std::string& what) {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    if (!n->is_string()) expected(key, what);
    return n->as_string()->get();
  }
  std::string string(std::string_view key, const std::string& what) {
    const toml::node& n = require(key, what);
    if (!n.is_string()) expected(key, what);
    return n.as_string()->get();
  }
  // one of `choices`; `def` empty: required
  std::string choice(std::string_view key, const std::vector<std::string>& choices,
                     const std::string& def = {}) {
    const std::string what = "one of: " + join(choices);
    std::optional<std::string> v;
    if (def.empty()) {
      v = string(key, "a string, " + what);
    } else {
      v = string_opt(key, "a string, " + what);
      if (!v) return def;
    }
    if (std::find(choices.begin(), choices.end(), *v) != choices.end()) return *v;
    const std::string hint = closest_key(*v, choices);
    fail(key, "expected " + what + ", got \"" + *v + "\"" +
                  (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)"));
  }
  // an array of finite numbers
  std::optional<std::vector<double>> vector_opt(std::string_view key, const std::string& what) {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a) expected(key, what);
    std::vector<double> v;
    for (const toml::node& e : *a) v.push_back(to_number(e, key, what, false));
    return v;
  }
  // an array of equally long arrays of finite numbers; `cols` < 0: any
  std::optional<MatrixX> matrix_opt(std::string_view key, const std::string& what) {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a) expected(key, what);
    MatrixX m;
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::array* row = (*a)[i].as_array();
      if (!row)
        fail_at(
            line_of((*a)[i]), key,
            "expected " + what + ", got row " + std::to_string(i + 1) + " = " + describe((*a)[i]));
      if (i == 0)
        m.resize(static_cast<Eigen::Index>(a->size()), static_cast<Eigen::Index>(row->size()));
      if (static_cast<Eigen::Index>(row->size()) != m.cols()) {
        fail_at(line_of((*a)[i]), key,
                "expected " + what + ": every row as long as the first (" +
                    std::to_string(m.cols()) + "), got row " + std::to_string(i + 1) + " with " +
                    std::to_string(row->size()));
      }
      for (std::size_t j = 0; j < row->size(); ++j) {
        m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
            to_number((*row)[j], key, what, false);
      }
    }
    return m;
  }
  std::optional<TableReader> table_opt(std::string_view key) {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    if (!n->is_table()) expected(key, "a table");
    return TableReader(file_, *n->as_table(), full(key) + ".", line_of(*n));
  }
  TableReader table(std::string_view key) {
    const toml::node* n = node(key);
    if (!n) {
      throw InputError(file_, line_, "",
                       "table [" + full(key) + "]: missing; expected a [" + full(key) +
                           "] table (see docs/case-file.md)");
    }
    if (!n->is_table()) expected(key, "a table");
    return TableReader(file_, *n->as_table(), full(key) + ".", line_of(*n));
  }

  // an array of tables ([[key]]), not empty
  std::vector<TableReader> tables(std::string_view key, const std::string& what) {
    const toml::node* n = node(key);
    if (!n) throw InputError(file_ + ": [[" + full(key) + "]]: missing; expected " + what);
    const toml::array* a = n->as_array();
    if (!a || a->empty()) expected(key, "[[" + full(key) + "]] tables: " + what);
    std::vector<TableReader> out;
    for (const toml::node& e : *a) {
      if (!e.is_table()) expected(key, "[[" + full(key) + "]] tables: " + what);
      out.emplace_back(file_, *e.as_table(), full(key) + ".", line_of(e));
    }
    return out;
  }

  // every key of the table must have been asked for; `context` explains the set
  void finish(const std::string& context = {}) const {
    std::vector<std::string> known(known_.begin(), known_.end());
    for (const auto& [k, v] : t_) {
      const std::string key(k.str());
      if (known_.count(key)) continue;
      const std::string hint = closest_key(key, known);
      std::string msg = "unknown key";
      if (!context.empty()) msg += " " + context;
      if (!hint.empty()) msg += " (did you mean '" + full(hint) + "'?)";
      msg += "; expected one of: " + join(known);
      const std::size_t line = k.source().begin.line ? k.source().begin.line : line_of(v);
      fail_at(line, key, msg);
    }
  }

  // a number node (integers too); `allow_inf` admits +-inf
  double to_number(const toml::node& n, std::string_view key, const std::string& what,
                   bool allow_inf = false) const {
    double v;
    if (auto i = n.as_integer()) {
      v = static_cast<double>(i->get());
    } else if (auto f = n.as_floating_point()) {
      v = f->get();
    } else {
      fail_at(line_of(n), key, "expected " + what + ", got " + describe(n));
    }
    if (std::isnan(v) || (std::isinf(v) && !allow_inf)) {
      fail_at(line_of(n), key, "expected " + what + " (finite), got " + num(v));
    }
    return v;
  }

 private:
  std::string file_;
  const toml::table& t_;
  std::string prefix_;
  std::size_t line_;
  std::set<std::string> known_;
};

// the rules among the compliant contact's keys of a [solver] table (docs/theory.md, "Compliant
// contact"), their values read
inline void read_compliant_rules(TableReader& r, SimulationOptions& o) {
  if (!r.has("contact_stiffness"))
    r.expected("contact_stiffness",
               "the spring of each tipping point [N/m, or N/m^p with hunt_crossley] with "
               "contact_model = \"compliant\", e.g. 1e8");
  const bool hc = o.contact_force_law == ContactForceLaw::kHuntCrossley;
  if (r.has("contact_exponent") && !hc)
    r.expected("contact_exponent",
               "no contact_exponent with contact_force_law = \"linear\" (p = 1; give "
               "contact_force_law = \"hunt_crossley\" for another exponent)");
  if (hc && !r.has("contact_exponent")) o.contact_exponent = 1.5;
  if (!(o.contact_exponent >= 1.0 && o.contact_exponent <= 3.0))
    r.expected("contact_exponent", "a number in [1, 3] (1.5: Hertz)");
  if (!in_range(kContactForceAt1mmBound,
                contact_force_at_1mm(o.contact_stiffness, o.contact_exponent)))
    r.expected("contact_stiffness", "a number in " + stiffness_range_text(o.contact_exponent));
  if (r.has("contact_damping_ratio") && (hc || r.has("contact_restitution")))
    r.expected("contact_damping_ratio",
               "either contact_damping_ratio or contact_restitution, not both, and no damping "
               "ratio with hunt_crossley (its damping follows from contact_restitution)");
  // hunt_crossley's damping needs a restitution above 0
  const std::string rw = "a number in (0, 1] (the restitution of a free bounce)";
  if (hc && r.has("contact_restitution") && !(o.contact_restitution > 0.0))
    r.expected("contact_restitution", rw);
  if (hc && !r.has("contact_restitution"))
    r.expected("contact_restitution", rw + " with contact_force_law = \"hunt_crossley\"");
}

// one [solver] key by its row of kSolverKeys (sim/solver_keys.hpp): its value, checked by the
// row's rule alone; the default is what `o` holds. read_solver_keys applies the rules among keys
inline void read_solver_key(TableReader& r, const SolverKey& k, SimulationOptions& o) {
  std::visit(
      [&](auto field) {
        using F = decltype(field);
        if constexpr (std::is_same_v<F, std::monostate>) {
          // a shorthand for other keys: checked here, applied by read_solver_keys
          const std::string what = solver_rule_text(k);
          const std::optional<double> v = r.number_opt(k.name, what);
          if (v && !solver_value_ok(k, *v)) r.expected(k.name, what);
        } else {
          using T = std::remove_reference_t<decltype(o.*field)>;
          if constexpr (std::is_same_v<T, double>) {
            const std::string what = solver_rule_text(k);
            const std::optional<double> v =
                r.number_opt(k.name, what, k.rule == SolverRule::kCoefficient);
            if (!v) return;
            if (!solver_value_ok(k, *v)) r.expected(k.name, what);
            o.*field = *v;
          } else if constexpr (std::is_integral_v<T>) {
            const std::string what = solver_rule_text(k);
            const long v = r.integer_or(k.name, o.*field, 1, what);
            if (!solver_value_ok(k, static_cast<double>(v))) r.expected(k.name, what);
            o.*field = static_cast<T>(v);
          } else {
            std::vector<std::string> names;
            for (const auto& c : solver_choices<T>()) names.emplace_back(c.first);
            const std::string v = r.choice(k.name, names, solver_choice_name(o.*field));
            for (const auto& c : solver_choices<T>())
              if (v == c.first) o.*field = c.second;
          }
        }
      },
      k.field);
}

// the keys of a [solver] table, by the table of solver keys (t_end only in a case file: a study
// sets each run's end itself), then the rules among them; the defaults are those already in `o`
// (a study starts from overturning at pi/2)
inline void read_solver_keys(TableReader& r, SimulationOptions& o, bool case_file = false) {
  auto ours = [&](const SolverKey& k) { return case_file || k.scope != SolverScope::kCaseFile; };
  for (const SolverKey& k : kSolverKeys)
    if (ours(k)) read_solver_key(r, k, o);
  // a key of another floor or impact law would be ignored: refused
  const std::string model = to_string(o.contact_model), law = to_string(o.impact_law);
  for (const SolverKey& k : kSolverKeys) {
    if (!ours(k) || !r.has(k.name) || solver_key_applies(k, o)) continue;
    const std::string no = std::string("no ") + k.name;
    if (k.scope == SolverScope::kRestitutionLaw && !takes_measured_ratio(o.impact_law))
      r.expected(k.name, no + ": it applies to impact_law = \"restitution\" (impact_law is \"" +
                             law + "\")");
    if (k.scope == SolverScope::kCompliant)
      r.expected(k.name, no +
                             ": it applies to contact_model = \"compliant\" (contact_model is "
                             "\"" +
                             model + "\")");
    r.expected(k.name, no + ": " + kImpulsiveOnlyWhy);
  }
  if (o.rtol < kMinRelativeTolerance) r.expected("rtol", "a number >= 1e-14 (double precision)");
  // the measured ratios theta_dot+/theta_dot- of the restitution law: one for both edges, or
  // one per landing edge
  const std::optional<double> both = r.number_opt("restitution_ratio", "");
  const bool edge1 = r.has("restitution_ratio_edge1"), edge2 = r.has("restitution_ratio_edge2");
  if (both && !edge1) o.restitution_ratio_edge1 = *both;
  if (both && !edge2) o.restitution_ratio_edge2 = *both;
  const bool restitution = takes_measured_ratio(o.impact_law);
  if (restitution && !both && !(edge1 && edge2))
    r.expected("restitution_ratio",
               "the measured theta_dot+/theta_dot- in [0, 1] with impact_law = \"restitution\" "
               "(restitution_ratio for both edges, or restitution_ratio_edge1 and _edge2)");
  if (restitution && o.restitution_factor != 1.0)
    r.expected("restitution_factor",
               "no restitution_factor with impact_law = \"restitution\" (give the measured "
               "ratio as restitution_ratio)");
  if (!kinetic_friction_coefficient_ok(o.kinetic_friction_coefficient, o.friction_coefficient))
    r.expected("kinetic_friction_coefficient",
               solver_rule_text(*find_solver_key("kinetic_friction_coefficient")));
  if (o.contact_model == ContactModel::kCompliant) read_compliant_rules(r, o);
}

// ---------------------------------------------------------------------------------------------
// the TOML toolkit of the case and study loaders: parsing, paths, units, record tables

// a TOML file, read through read_input_file; a syntax error names the file, line and column.
// `what` names the file for messages ("case", "spectrum", "sweep manifest")
inline toml::table parse_toml(const std::string& path, const std::string& what) {
  const std::string text = read_input_file(path, what, kMaxTomlFileBytes);
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw InputError(path + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
}

// a path written in `file`, relative to that file's directory (absolute paths as they are)
inline std::string resolve_path(const std::string& file, const std::string& p) {
  const std::filesystem::path path(p);
  if (path.is_absolute()) return p;
  return (std::filesystem::path(file).parent_path() / path).lexically_normal().string();
}

// the acceleration units a file may name, by their names in the files (records.hpp unit_name)
inline const std::vector<std::string>& accel_unit_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const AccelUnitInfo& u : kAccelUnits) v.emplace_back(u.name);
    return v;
  }();
  return names;
}

// the unit of a name of accel_unit_names(); the reader's choice() has checked it
inline AccelUnit accel_unit(const std::string& name) {
  for (const AccelUnitInfo& u : kAccelUnits) {
    if (name == u.name) return u.unit;
  }
  throw InputError("expected an acceleration unit, one of: " + join(accel_unit_names()) +
                   "; got \"" + name + "\"");
}

// the keys of a record table: file, format, units, dt (the caller reads its own: scale, name)
struct RecordKeys {
  std::string file;  // as written
  std::string path;  // resolved against the file that names it
  const RecordFormat* format = nullptr;
  std::optional<std::string> units;  // as written; AT2: optional, checked against the file
  double dt = 0.0;                   // [s] single_column only
  std::size_t line = 0;              // line of `file`
};

inline RecordKeys read_record_keys(TableReader& r, const std::string& file_what) {
  RecordKeys k;
  k.file = r.string("file", file_what);
  k.path = resolve_path(r.file(), k.file);
  k.line = line_of(*r.node("file"));
  std::vector<std::string> names;
  for (const RecordFormat& f : record_formats()) names.emplace_back(f.name);
  // the format the file name selects (the suffixes of record_formats()), else required
  const RecordFormat* by_name = record_format_for(k.file);
  const std::string format = r.choice("format", names, by_name != nullptr ? by_name->name : "");
  k.format = find_record_format(format);
  if (r.has("units")) k.units = r.choice("units", accel_unit_names());
  if (k.format->needs_dt) k.dt = r.positive("dt", "[s] (sample spacing)");
  if (k.format->units == RecordUnits::kGiven && !k.units) {
    r.fail_at(r.line(), "units",
              "missing; expected one of: " + join(accel_unit_names()) +
                  " (the units of the file's values)");
  }
  return k;
}

// the record a table names; errors of the file name the key and the place that named it
inline Record read_record_file(TableReader& r, const RecordKeys& k) {
  Record rec;
  try {
    const std::optional<AccelUnit> given =
        k.units ? std::optional<AccelUnit>(accel_unit(*k.units)) : std::nullopt;
    rec = k.format->read(k.path, k.dt, given);
    if (given && *given != rec.units) {
      r.fail("units", "expected the units the " + std::string(k.format->name) + " file states (" +
                          std::string(unit_name(rec.units)) + "), got \"" + *k.units + "\"");
    }
  } catch (const InputError& e) {
    // errors placed in this file pass through; the record's own get the key that named it
    if (e.file() == r.file()) throw;
    throw InputError(std::string(e.what()) + " (record named by key '" + r.full("file") + "' at " +
                     r.file() + ":" + std::to_string(k.line) + ")");
  }
  if (rec.npts() < 2) r.fail("file", "expected a record with at least 2 samples in " + k.path);
  return rec;
}

}  // namespace flexrock::io::detail
