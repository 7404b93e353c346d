// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/sweep.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <optional>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/excitation/intensity.hpp"

namespace flexrock::study {

namespace {

// the units an acceleration measure (sa) may be asked in: name, column suffix, SI value of one
struct AccelUnit {
  const char* name;
  const char* suffix;
  double si;
};
constexpr AccelUnit kAccelUnits[] = {
    {"m/s^2", "_m_per_s2", 1.0},
    {"g", "_g", kStandardGravity},
    {"cm/s^2", "_cm_per_s2", 0.01},
};

const AccelUnit& accel_unit_of(const MeasureRequest& m) {
  for (const AccelUnit& u : kAccelUnits) {
    if (m.unit == u.name || (m.unit.empty() && &u == kAccelUnits)) return u;
  }
  throw InputError("intensity measure " + m.name + ": unit \"" + m.unit +
                   "\": expected m/s^2, g or cm/s^2");
}

}  // namespace

std::string measure_column(const MeasureRequest& m) {
  const IntensityMeasure* im = find_intensity_measure(m.name);
  FLEXROCK_THROW_UNLESS(im != nullptr, "intensity measure '" + m.name + "': unknown");
  if (!im->needs_period) return std::string(im->column);
  // spectral_column names the SI column: its unit suffix replaced by the asked one's
  std::string c = spectral_column(m.period, m.zeta);
  const std::string si = kAccelUnits[0].suffix;
  if (c.ends_with(si)) c.resize(c.size() - si.size());
  return c + accel_unit_of(m).suffix;
}

std::string measure_unit(const MeasureRequest& m) {
  const IntensityMeasure* im = find_intensity_measure(m.name);
  FLEXROCK_THROW_UNLESS(im != nullptr, "intensity measure '" + m.name + "': unknown");
  return im->needs_period ? accel_unit_of(m).name : im->unit;
}

MeasureRequest measure_request(const std::string& text) {
  if (!text.starts_with("sa:")) {
    const IntensityMeasure* m = find_intensity_measure(text);
    FLEXROCK_THROW_UNLESS(m != nullptr, "unknown intensity measure \"" + text + "\"");
    FLEXROCK_THROW_UNLESS(!m->needs_period, "\"" + text + "\" needs its period: sa:T or sa:T:zeta");
    return {text, 0.0, 0.05, ""};
  }
  const std::string rest = text.substr(3);
  const std::size_t colon = rest.find(':');
  auto number = [&](const std::string& part) {
    double v = 0.0;
    const auto r = std::from_chars(part.data(), part.data() + part.size(), v);
    FLEXROCK_THROW_UNLESS(
        !part.empty() && r.ec == std::errc() && r.ptr == part.data() + part.size(),
        "\"" + part + "\" is not a number (in \"" + text + "\")");
    return v;
  };
  MeasureRequest m{"sa", number(rest.substr(0, colon)),
                   colon == std::string::npos ? 0.05 : number(rest.substr(colon + 1)), ""};
  require_spectral_period(m.period, "\"" + text + "\"");
  FLEXROCK_THROW_UNLESS(
      m.zeta >= 0.0 && m.zeta < 1.0,
      "\"" + text + "\": expected a damping ratio in [0, 1), got " + format_number(m.zeta));
  return m;
}

namespace {

void check_request(const MeasureRequest& m) {
  const IntensityMeasure* im = find_intensity_measure(m.name);
  std::string names;
  for (const IntensityMeasure& k : intensity_measures()) {
    if (!k.always_written) names += std::string(names.empty() ? "" : ", ") + k.name;
  }
  FLEXROCK_THROW_UNLESS(im != nullptr && !im->always_written,
                        "intensity measure '" + m.name + "': expected one of: " + names +
                            (im ? " (pga and pgv are always written)" : ""));
  FLEXROCK_THROW_UNLESS(m.unit.empty() || im->needs_period,
                        "intensity measure '" + m.name + "': a unit is only for sa (got \"" +
                            m.unit + "\"); it is in " + im->unit);
  if (im->needs_period) {
    accel_unit_of(m);  // a known unit
    require_spectral_period(m.period, "intensity measure sa");
    FLEXROCK_THROW_UNLESS(
        m.zeta >= 0.0 && m.zeta < 1.0,
        "intensity measure sa: expected a damping ratio in [0, 1), got " + format_number(m.zeta));
  }
}

}  // namespace

Intensity intensity(const GroundMotion& motion, double analytic_dt) {
  return intensity(motion, {}, analytic_dt);
}

Intensity intensity(const GroundMotion& motion, const std::vector<MeasureRequest>& measures,
                    double analytic_dt) {
  for (const MeasureRequest& m : measures) check_request(m);
  Intensity out;
  std::vector<double> t, a;
  if (motion.is_sampled()) {
    t = motion.times();
    a = motion.horizontal();
  } else {
    FLEXROCK_THROW_UNLESS(analytic_dt > 0.0, "intensity: analytic_dt must be > 0");
    // a uniform grid plus the breakpoints, where pulses jump or kink
    const double end = motion.duration();
    const auto n = static_cast<std::size_t>(std::ceil(end / analytic_dt));
    for (std::size_t i = 0; i <= n; ++i) {
      t.push_back(std::min(end, static_cast<double>(i) * analytic_dt));
    }
    GroundMotion::Cursor c;
    for (double b = motion.next_breakpoint(0.0, c); std::isfinite(b) && b <= end;
         b = motion.next_breakpoint(b, c)) {
      t.push_back(b);
    }
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    a.reserve(t.size());
    for (double ti : t) a.push_back(motion.at(ti).x);
  }
  double v = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    out.pga = std::max(out.pga, std::abs(a[i]));
    if (i > 0) v += 0.5 * (a[i] + a[i - 1]) * (t[i] - t[i - 1]);
    out.pgv = std::max(out.pgv, std::abs(v));
  }
  for (const MeasureRequest& m : measures) {
    // in the unit asked for (SI unless an sa asks for another)
    const double si = find_intensity_measure(m.name)->needs_period ? accel_unit_of(m).si : 1.0;
    out.measures.push_back(find_intensity_measure(m.name)->compute(t, a, m.period, m.zeta) / si);
  }
  return out;
}

Intensity record_intensity(const SweepSpec& spec, const GroundMotion& motion) {
  if (spec.scale_kind != ScaleKind::kTargetMeasure) return intensity(motion, spec.measures);
  check_request(spec.target);
  const int power = find_intensity_measure(spec.target.name)->scale_power;
  FLEXROCK_THROW_UNLESS(power == 1 || power == 2,
                        "sweep: target measure '" + spec.target.name +
                            "' does not grow with the scale factor: no factor reaches a target");
  std::vector<MeasureRequest> all = spec.measures;
  all.push_back(spec.target);
  Intensity im = intensity(motion, all);
  im.target = im.measures.back();
  im.measures.pop_back();
  return im;
}

namespace {

// the pair's RotD50 of the measure the spec's target scales (target_pga: the PGA; target_im:
// Sa, the only other measure with a RotD) [SI]
double pair_target(const SweepSpec& spec, const SweepRecord& r) {
  const RecordPairComponents& p = *r.pair;
  if (spec.scale_kind == ScaleKind::kTargetPga) return rotd_peak_acceleration(p.h1, p.h2).rotd50;
  if (spec.target.name == "sa") {
    return rotd_spectral_acceleration(p.t, p.h1, p.h2, spec.target.period, spec.target.zeta).rotd50;
  }
  throw InputError("sweep: record '" + r.name +
                   "': the azimuths of a record pair are scaled alike, by the pair's RotD50 of "
                   "the target measure: target_im takes sa for pairs, got '" +
                   spec.target.name + "'");
}

}  // namespace

Intensity record_intensity(const SweepSpec& spec, const SweepRecord& record) {
  Intensity im = record_intensity(spec, record.motion);
  if (record.pair && spec.scale_kind != ScaleKind::kFactor) im.target = pair_target(spec, record);
  return im;
}

std::vector<Intensity> record_intensities(const SweepSpec& spec) {
  std::vector<Intensity> out;
  out.reserve(spec.records.size());
  std::map<const RecordPairComponents*, double> done;  // a pair's target, once for its azimuths
  for (const SweepRecord& r : spec.records) {
    out.push_back(record_intensity(spec, r.motion));
    if (!r.pair || spec.scale_kind == ScaleKind::kFactor) continue;
    const auto it = done.find(r.pair.get());
    out.back().target = it != done.end() ? it->second : pair_target(spec, r);
    done.emplace(r.pair.get(), out.back().target);
  }
  return out;
}

bool has_friction(const SweepSpec& spec) {
  if (std::isfinite(spec.solver.friction_coefficient)) return true;
  for (const UncertainParameter& p : spec.uncertainty.parameters) {
    if (p.kind == UncertainKind::kFriction) return true;
  }
  return std::any_of(spec.bodies.begin(), spec.bodies.end(), [](const SweepBody& b) {
    return b.friction_coefficient && std::isfinite(*b.friction_coefficient);
  });
}

std::vector<SweepRun> sweep_runs(const SweepSpec& spec) {
  std::vector<SweepRun> runs;
  runs.reserve(spec.bodies.size() * spec.records.size() * spec.scales.size());
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    for (std::size_t r = 0; r < spec.records.size(); ++r) {
      for (std::size_t s = 0; s < spec.scales.size(); ++s) {
        runs.push_back({runs.size(), b, r, s});
      }
    }
  }
  return runs;
}

std::size_t sample_index(const SweepSpec& spec, const SweepRun& run) {
  return spec.uncertainty.sampling.scope == SamplingScope::kRecord
             ? run.record
             : run.record * spec.scales.size() + run.scale_index;
}

SampleDesign sample_design(const SweepSpec& spec) {
  if (spec.uncertainty.empty()) return {};
  const std::size_t n = spec.uncertainty.sampling.scope == SamplingScope::kRecord
                            ? spec.records.size()
                            : spec.records.size() * spec.scales.size();
  return SampleDesign(spec.uncertainty, n);
}

BodyParameters run_body(const SweepSpec& spec, const SweepRun& run,
                        const std::vector<double>& sample) {
  const BodyParameters& b = spec.bodies.at(run.body).body;
  if (sample.empty()) return b;
  return apply(spec.uncertainty, sample, b);
}

namespace {

bool changes_any_body(const SweepSpec& spec) {
  return std::any_of(spec.uncertainty.parameters.begin(), spec.uncertainty.parameters.end(),
                     [](const UncertainParameter& p) { return changes_body(p.kind); });
}

// checks the uncertainty against the solver: each restitution parameter goes with its laws
void check_uncertainty(const SweepSpec& spec) {
  try {
    validate(spec.uncertainty);
  } catch (const InputError& e) {
    throw InputError(std::string("sweep: ") + e.what());
  }
  for (const UncertainParameter& p : spec.uncertainty.parameters) {
    const bool restitution_law = takes_measured_ratio(spec.solver.impact_law);
    FLEXROCK_THROW_UNLESS(p.kind != UncertainKind::kRestitutionRatio || restitution_law,
                          "sweep: uncertain restitution_ratio: expected [solver] impact_law = "
                          "\"restitution\" (the ratio is that law's; other laws have "
                          "restitution_factor)");
    FLEXROCK_THROW_UNLESS(p.kind != UncertainKind::kRestitutionFactor || !restitution_law,
                          "sweep: uncertain restitution_factor: impact_law = \"restitution\" "
                          "takes restitution_ratio instead (the factor is for the paper and "
                          "rigid_body laws)");
  }
}

}  // namespace

void validate(const SweepSpec& spec) {
  FLEXROCK_THROW_UNLESS(!spec.bodies.empty(), "sweep: expected at least one body");
  FLEXROCK_THROW_UNLESS(!spec.records.empty(), "sweep: expected at least one record");
  FLEXROCK_THROW_UNLESS(!spec.scales.empty(), "sweep: expected at least one scale");
  for (std::size_t i = 0; i < spec.scales.size(); ++i) {
    FLEXROCK_THROW_UNLESS(std::isfinite(spec.scales[i]) && spec.scales[i] > 0.0,
                          "sweep: scales[" + std::to_string(i) +
                              "]: expected a finite number > 0, got " +
                              format_number(spec.scales[i]));
  }
  FLEXROCK_THROW_UNLESS(spec.levels.empty() || spec.levels.size() == spec.scales.size(),
                        "sweep: levels: expected one requested level per scale (" +
                            std::to_string(spec.scales.size()) + "), got " +
                            std::to_string(spec.levels.size()));
  FLEXROCK_THROW_UNLESS(std::isfinite(spec.free_periods) && spec.free_periods >= 0.0,
                        "sweep: free_periods: expected a number >= 0");
  std::vector<std::string> columns;
  for (const MeasureRequest& m : spec.measures) {
    check_request(m);
    const std::string c = measure_column(m);
    FLEXROCK_THROW_UNLESS(std::find(columns.begin(), columns.end(), c) == columns.end(),
                          "sweep: intensity measure column " + c + " asked for twice");
    columns.push_back(c);
  }
  std::vector<Body> bodies;
  for (const SweepBody& b : spec.bodies) {
    try {
      bodies.emplace_back(b.body);
    } catch (const InputError& e) {
      throw InputError("sweep: body '" + b.name + "': " + e.what());
    }
  }
  check_uncertainty(spec);
  const SampleDesign design = sample_design(spec);
  const bool sampled_body = changes_any_body(spec);
  std::vector<Intensity> im;
  std::vector<double> peak;  // [m/s^2] largest |sample| of either component
  for (const SweepRecord& r : spec.records) {
    FLEXROCK_THROW_UNLESS(r.motion.duration() > 0.0,
                          "sweep: record '" + r.name + "': expected a record lasting > 0 s");
  }
  im = record_intensities(spec);
  for (std::size_t k = 0; k < spec.records.size(); ++k) {
    const SweepRecord& r = spec.records[k];
    const BaseAcceleration p = peak_acceleration(r.motion);
    peak.push_back(std::max(p.x, p.y));
    if (spec.scale_kind == ScaleKind::kTargetPga) {
      FLEXROCK_THROW_UNLESS(
          (r.pair ? im[k].target : im[k].pga) > 0.0,
          "sweep: record '" + r.name + "': PGA is zero, it cannot be scaled to a target PGA");
    }
    if (spec.scale_kind == ScaleKind::kTargetMeasure) {
      FLEXROCK_THROW_UNLESS(im[k].target > 0.0, "sweep: record '" + r.name + "': its " +
                                                    measure_column(spec.target) +
                                                    " is zero, it cannot be scaled to a target");
    }
  }
  // every run as it will be made, before any is: a bad one found after others ran would leave
  // a journal of a study that cannot finish
  for (const SweepRun& run : sweep_runs(spec)) {
    const SweepRecord& rec = spec.records[run.record];
    const std::string where = "sweep: body '" + spec.bodies[run.body].name + "', record '" +
                              rec.name + "', scale " + format_number(spec.scales[run.scale_index]);
    // a sampled body is made and checked for every run, as the run will make it
    const std::vector<double> sample =
        design.dimensions() > 0 ? design.values(sample_index(spec, run)) : std::vector<double>{};
    std::optional<Body> own;
    if (sampled_body) {
      try {
        own.emplace(run_body(spec, run, sample));
      } catch (const InputError& e) {
        throw InputError(where + ": the sampled body: " + e.what());
      }
    }
    const Body& body = own ? *own : bodies[run.body];
    const SweepRow row = sweep_inputs(spec, run, body, im[run.record], sample);
    // the scaled record must stay finite: its peak times the factor
    FLEXROCK_THROW_UNLESS(
        std::isfinite(row.scale) && row.scale > 0.0 &&
            std::isfinite(row.scale * peak[run.record]) && std::isfinite(row.pgv) &&
            std::all_of(row.measures.begin(), row.measures.end(),
                        [](double x) { return std::isfinite(x); }),
        where + ": the scaled record overflows (factor " + format_number(row.scale) + ")");
    FLEXROCK_THROW_UNLESS(std::isfinite(row.duration),
                          where + ": free_periods x 2 pi/p gives a run of " +
                              format_number(row.duration) + " s; expected a finite duration");
    // the solver options do not depend on the scale (unless sampled): check them once per body
    // and record
    if (run.scale_index == 0 || !sample.empty()) {
      try {
        validate_options(body, {}, run_options(spec, row));
      } catch (const InputError& e) {
        throw InputError(where + ": [solver] " + e.what());
      }
    }
  }
}

SweepRow sweep_inputs(const SweepSpec& spec, const SweepRun& run, const Body& spec_body,
                      const Intensity& im, const SampleDesign& design) {
  if (design.dimensions() == 0) return sweep_inputs(spec, run, spec_body, im);
  const std::vector<double> sample = design.values(sample_index(spec, run));
  if (!changes_any_body(spec)) return sweep_inputs(spec, run, spec_body, im, sample);
  return sweep_inputs(spec, run, Body(run_body(spec, run, sample)), im, sample);
}

SweepRow sweep_inputs(const SweepSpec& spec, const SweepRun& run, const Body& body,
                      const Intensity& im, const std::vector<double>& sample) {
  FLEXROCK_DEMAND(sample.size() == spec.uncertainty.parameters.size());
  SweepRow row;
  row.sampled = sample;
  row.index = run.index;
  row.body = run.body;
  row.record = run.record;
  row.scale_index = run.scale_index;
  const double s = spec.scales.at(run.scale_index);
  // a pair's azimuth under target_pga: the pair's RotD50 PGA (record_intensity), else its own
  row.scale =
      spec.scale_kind == ScaleKind::kTargetPga ? s / (im.target > 0.0 ? im.target : im.pga) : s;
  if (spec.scale_kind == ScaleKind::kTargetMeasure) {
    // Arias intensity grows with the square of the factor
    const int power = find_intensity_measure(spec.target.name)->scale_power;
    row.scale = power == 2 ? std::sqrt(s / im.target) : s / im.target;
  }
  row.pga = row.scale * im.pga;
  row.pgv = row.scale * im.pgv;
  // each measure scales with the factor to its own power (Arias: squared; durations: not at all)
  FLEXROCK_DEMAND(im.measures.size() == spec.measures.size());
  for (std::size_t k = 0; k < spec.measures.size(); ++k) {
    const int power = find_intensity_measure(spec.measures[k].name)->scale_power;
    row.measures.push_back(power == 0   ? im.measures[k]
                           : power == 1 ? row.scale * im.measures[k]
                                        : row.scale * row.scale * im.measures[k]);
  }
  const GroundMotion& m = spec.records.at(run.record).motion;
  row.duration =
      m.duration() + spec.free_periods * 2.0 * std::numbers::pi / body.rocking_frequency();
  return row;
}

SimulationOptions run_options(const SweepSpec& spec, const SweepRow& row) {
  SimulationOptions o = spec.solver;
  const SweepBody& b = spec.bodies.at(row.body);
  if (b.friction_coefficient) {
    // the body's own coefficients replace the solver's pair: a kinetic one not given is the
    // static one, not a leftover of the solver's
    o.friction_coefficient = *b.friction_coefficient;
    o.kinetic_friction_coefficient =
        b.kinetic_friction_coefficient.value_or(std::numeric_limits<double>::infinity());
  }
  if (!row.sampled.empty()) apply(spec.uncertainty, row.sampled, o);
  o.t_end = row.duration;
  o.output_dt = 0.0;
  o.progress = nullptr;
  return o;
}

namespace {

SweepRow run_one(const SweepSpec& spec, const SweepRun& run, const Body& spec_body,
                 const Intensity& im, const SampleDesign& design) {
  std::vector<double> sample;
  if (design.dimensions() > 0) sample = design.values(sample_index(spec, run));
  // a run whose sample changes the body has a body of its own
  std::optional<Body> own;
  if (changes_any_body(spec)) own.emplace(run_body(spec, run, sample));
  const Body& body = own ? *own : spec_body;
  SweepRow row = sweep_inputs(spec, run, body, im, sample);
  const GroundMotion& m = spec.records[run.record].motion;
  const SimulationResult r = simulate(body, m.scaled(row.scale), {}, run_options(spec, row));
  row.run = summarize(body, r);
  if (r.status == Status::kStopped) row.message = r.message;
  return row;
}

}  // namespace

SweepRow run_sweep_one(const SweepSpec& spec, const SweepRun& run) {
  const Body body(spec.bodies.at(run.body).body);
  return run_one(spec, run, body, record_intensity(spec, spec.records.at(run.record)),
                 sample_design(spec));
}

std::vector<SweepRow> run_sweep(const SweepSpec& spec, const std::vector<std::size_t>& indices,
                                const RunOptions& options,
                                const std::function<void(const SweepRow&)>& on_row) {
  validate(spec);
  FLEXROCK_THROW_UNLESS(options.ranks >= 1 && options.rank >= 0 && options.rank < options.ranks,
                        "run options: expected 0 <= rank < ranks");
  const std::vector<SweepRun> all = sweep_runs(spec);
  std::vector<std::size_t> todo;
  const auto ranks = static_cast<std::size_t>(options.ranks);
  const auto rank = static_cast<std::size_t>(options.rank);
  auto take = [&](std::size_t i) {
    FLEXROCK_THROW_UNLESS(i < all.size(), "sweep: run index " + std::to_string(i) +
                                              " out of range (" + std::to_string(all.size()) +
                                              " runs)");
    if (i % ranks == rank) todo.push_back(i);
  };
  if (indices.empty()) {
    for (std::size_t i = 0; i < all.size(); ++i) take(i);
  } else {
    for (std::size_t i : indices) take(i);
    std::sort(todo.begin(), todo.end());
    todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
  }
  // shared, read-only across threads
  std::vector<Body> bodies;
  bodies.reserve(spec.bodies.size());
  for (const SweepBody& b : spec.bodies) bodies.emplace_back(b.body);
  const std::vector<Intensity> im = record_intensities(spec);
  const SampleDesign design = sample_design(spec);

  std::vector<SweepRow> rows(todo.size());
  std::mutex row_mutex;
  parallel_for(
      todo.size(), options.threads,
      [&](std::size_t k) {
        const SweepRun& run = all[todo[k]];
        rows[k] = run_one(spec, run, bodies[run.body], im[run.record], design);
        if (on_row) {
          const std::lock_guard lock(row_mutex);
          on_row(rows[k]);
        }
        if (options.completed) options.completed->fetch_add(1, std::memory_order_relaxed);
      },
      options.cancel);
  // with a cancel, unfinished rows are dropped (index 0 of a default row is ambiguous: keep by
  // position)
  if (options.cancel && options.cancel->load()) {
    std::vector<SweepRow> done;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (rows[k].duration > 0.0) done.push_back(std::move(rows[k]));
    }
    return done;
  }
  return rows;
}

}  // namespace flexrock::study
