// SPDX-License-Identifier: BSD-3-Clause
// Sweep manifests: the reader, the sweep CSV (a table of columns) and its lines read back from a
// journal.
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
#include "uncertain_tables.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;
using namespace study_detail;

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
      refuse_restraints(full, "a sweep");
      std::string body_type;
      sb.body = load_body(full, &body_type, &m.input_files);
      refuse_frame(body_type, full);
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
        "a measure that grows with the scale factor: pgd, arias, cav, "
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
        m.spec.measures.push_back({name->get(), 0.0, 0.05, ""});
      }
    }
    const double zeta = ik->number_or("sa_damping", 0.05, "a number in [0, 1) [-]");
    if (!(zeta >= 0.0 && zeta < 1.0)) ik->expected("sa_damping", "a number in [0, 1) [-]");
    const std::string periods_what =
        "an array of periods >= " + num(kMinSpectralPeriod) + " [s] (below it Sa is the PGA)";
    // Sa in the unit asked for, named in its column (sa_T1_z0.05_g); m/s^2 by default
    const bool sa_units_given = ik->has("sa_units");
    const std::string sa_units = ik->choice("sa_units", detail::accel_unit_names(), "m/s^2");
    if (const auto periods = ik->vector_opt("sa_periods", periods_what)) {
      for (std::size_t i = 0; i < periods->size(); ++i) {
        const double T = (*periods)[i];
        if (!(std::isfinite(T) && T >= kMinSpectralPeriod))
          ik->expected("sa_periods", periods_what);
        for (std::size_t j = 0; j < i; ++j) {
          if ((*periods)[j] == T) ik->fail("sa_periods", "period " + num(T) + " s given twice");
        }
        m.spec.measures.push_back({"sa", T, zeta, sa_units == "m/s^2" ? "" : sa_units});
      }
    } else if (ik->has("sa_damping")) {
      ik->fail("sa_damping", "expected only with sa_periods");
    } else if (sa_units_given) {
      ik->fail("sa_units", "expected only with sa_periods");
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
    {"record", "-",
     "name of the record (a `[[suite]]` pair: `<horizontal stem>+<vertical stem>`; two "
     "horizontal components: `<H1 stem>+<H2 stem>@<azimuth>`)",
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
        v.push_back({study::measure_column(m), study::measure_unit(m), ColumnType::kReal});
      }
      for (const study::UncertainParameter& p : spec.uncertainty.parameters) {
        const study::UncertainKindInfo& k = study::uncertain_kind(p.kind);
        v.push_back({k.column, k.unit, ColumnType::kReal});
      }
    }
  }
  if (study::has_friction(spec)) {
    for (const SlidingColumn& c : sliding_columns()) v.push_back({c.name, c.unit, c.type});
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
    for (const SlidingColumn& c : sliding_columns()) v.push_back(c.get(row.run));
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
                              (study::has_friction(spec) ? sliding_columns().size() : 0);
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
    for (const SlidingColumn& col : sliding_columns()) {
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

std::string study_detail::sweep_column_block() {
  return column_block<SweepColumn>("sweep", "src/io/study_sweep.cpp", kSweepColumns);
}

}  // namespace flexrock::io
