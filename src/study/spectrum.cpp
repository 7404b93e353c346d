// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <string>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/study/sweep.hpp"

namespace flexrock::study {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// the free-vibration span after the excitation [s]
double free_span(const Body& body, double free_periods) {
  return free_periods * kTwoPi / body.rocking_frequency();
}

void check_grid(const std::vector<double>& v, const char* name, bool increasing) {
  FLEXROCK_THROW_UNLESS(!v.empty(),
                        std::string("spectrum: ") + name + ": expected at least one value");
  for (std::size_t i = 0; i < v.size(); ++i) {
    FLEXROCK_THROW_UNLESS(std::isfinite(v[i]) && v[i] > 0.0,
                          std::string("spectrum: ") + name + "[" + std::to_string(i) +
                              "]: expected a finite number > 0, got " + format_number(v[i]));
    if (increasing && i > 0) {
      FLEXROCK_THROW_UNLESS(v[i] > v[i - 1], std::string("spectrum: ") + name +
                                                 ": expected strictly increasing values (at " +
                                                 std::to_string(i) + ")");
    }
  }
}

void check_common(double free_periods, double tolerance) {
  FLEXROCK_THROW_UNLESS(std::isfinite(free_periods) && free_periods >= 0.0,
                        "spectrum: free_periods: expected a number >= 0");
  FLEXROCK_THROW_UNLESS(
      std::isfinite(tolerance) && tolerance >= kMinBisectionTolerance && tolerance < 1.0,
      "spectrum: bisection_tolerance: expected a number in [1e-12, 1), got " +
          format_number(tolerance) +
          " (a narrower bracket is below what the simulations resolve and than doubles hold)");
}

SimulationOptions run_options(const SimulationOptions& solver, double t_end) {
  SimulationOptions o = solver;
  o.t_end = t_end;
  o.output_dt = 0.0;
  o.progress = nullptr;
  return o;
}

bool cancelled(const std::atomic<bool>* cancel) {
  return cancel && cancel->load(std::memory_order_relaxed);
}

// one column's boundary: bisection between the last safe and the first overturning grid row.
// A stop request ends it between runs with computed = false (an unfinished bracket).
template <class Run>
OverturnBoundary bisect_column(const std::vector<double>& rows,
                               const std::vector<SpectrumCell>& cells, std::size_t columns,
                               std::size_t column, double frequency, bool bisect, double tol,
                               const std::atomic<bool>* cancel, const Run& run) {
  OverturnBoundary b;
  b.column = column;
  b.frequency = frequency;
  b.computed = true;
  std::size_t k = rows.size();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (overturned(cells[i * columns + column].run.outcome)) {
      k = i;
      break;
    }
  }
  if (k == rows.size()) return b;  // kNone
  b.mode = cells[k * columns + column].run.outcome;
  b.overturning = rows[k];
  if (k == 0) {
    b.kind = OverturnBoundary::Kind::kBelowGrid;
    return b;
  }
  b.kind = OverturnBoundary::Kind::kFound;
  b.safe = rows[k - 1];
  if (!bisect) return b;
  while (b.overturning - b.safe > tol * b.overturning) {
    const double mid = 0.5 * (b.safe + b.overturning);
    // adjacent doubles: the bracket cannot narrow further, whatever the tolerance
    if (!(mid > b.safe && mid < b.overturning)) break;
    if (cancelled(cancel)) {
      b.computed = false;
      return b;
    }
    const RunSummary s = run(mid);
    ++b.bisection_runs;
    if (overturned(s.outcome)) {
      b.overturning = mid;
      b.mode = s.outcome;
    } else {
      b.safe = mid;
    }
  }
  return b;
}

bool mine(std::size_t index, const RunOptions& o) {
  return o.ranks <= 1 ||
         index % static_cast<std::size_t>(o.ranks) == static_cast<std::size_t>(o.rank);
}

void check_ranks(const RunOptions& o) {
  FLEXROCK_THROW_UNLESS(o.ranks >= 1 && o.rank >= 0 && o.rank < o.ranks,
                        "run options: expected 0 <= rank < ranks");
}

}  // namespace

namespace {
// a pulse type that spectra sweep: one with a length
const PulseKind& spectrum_kind(const std::string& type) {
  const PulseKind& k = pulse_kind(type);
  if (!k.length) {
    std::string names;
    for (const std::string& n : spectrum_pulse_names()) names += (names.empty() ? "" : ", ") + n;
    throw InputError("expected a pulse type of spectra, one of: " + names + "; got \"" + type +
                     "\"");
  }
  return k;
}
}  // namespace

double pulse_length(const std::string& type, double omega_p) {
  return spectrum_kind(type).length(omega_p);
}

GroundMotion pulse_motion(const std::string& type, double a_p, double omega_p, double duration) {
  return make_pulse(spectrum_kind(type), {a_p, omega_p, duration, Component::kHorizontal, {}});
}

RunSummary run_pulse_cell(const Body& body, const SpectrumSpec& spec, double a_p, double omega_p) {
  const double duration = pulse_length(spec.pulse, omega_p) + free_span(body, spec.free_periods);
  // one run over the pulse and the free motion: a rigid body at rest once a pulse has ended costs
  // the engine one step to the end (GroundMotion::quiet_from), so no run is cut short and redone
  return summarize(body, simulate(body, pulse_motion(spec.pulse, a_p, omega_p, duration), {},
                                  run_options(spec.solver, duration)));
}

RunSummary run_record_cell(const Body& body, const RecordSpectrumSpec& spec, double scale) {
  const double duration = spec.motion.duration() + free_span(body, spec.free_periods);
  return summarize(
      body, simulate(body, spec.motion.scaled(scale), {}, run_options(spec.solver, duration)));
}

SpectrumResult spectrum_grid(const Body& body, const SpectrumSpec& spec) {
  check_grid(spec.amplitudes, "amplitudes", true);
  check_grid(spec.frequencies, "frequencies", false);
  check_common(spec.free_periods, spec.bisection_tolerance);
  SpectrumResult res;
  res.tan_alpha = body.alpha1();
  res.alpha = body.tipping_angle(1);
  res.p = body.rocking_frequency();
  res.sliding = std::isfinite(spec.solver.friction_coefficient);
  if (!spec.normalized) {
    const GridUnits& u = spec.units;
    FLEXROCK_THROW_UNLESS(
        (u.amplitude == "m/s^2" || u.amplitude == "g" || u.amplitude == "cm/s^2") &&
            std::isfinite(u.amplitude_si) && u.amplitude_si > 0.0,
        "spectrum: amplitude unit \"" + u.amplitude + "\" of " + format_number(u.amplitude_si) +
            " m/s^2; expected m/s^2, g or cm/s^2 with a factor > 0");
    FLEXROCK_THROW_UNLESS((u.frequency == "rad/s" || u.frequency == "Hz") &&
                              std::isfinite(u.frequency_si) && u.frequency_si > 0.0,
                          "spectrum: frequency unit \"" + u.frequency + "\" of " +
                              format_number(u.frequency_si) +
                              " rad/s; expected rad/s or Hz with a factor > 0");
    res.units = u;
  }
  const double a_unit = spec.normalized ? body.g() * body.alpha1() : spec.units.amplitude_si;
  const double w_unit = spec.normalized ? res.p : spec.units.frequency_si;
  const std::size_t rows = spec.amplitudes.size();
  const std::size_t cols = spec.frequencies.size();
  // every run as it will be made, before any is
  for (std::size_t j = 0; j < cols; ++j) {
    const double omega = spec.frequencies[j] * w_unit;
    const double duration = pulse_length(spec.pulse, omega) + free_span(body, spec.free_periods);
    const std::string where = "spectrum: frequency " + format_number(spec.frequencies[j]);
    FLEXROCK_THROW_UNLESS(std::isfinite(omega) && std::isfinite(duration),
                          where + ": the pulse and free motion last " + format_number(duration) +
                              " s; expected a finite duration");
    try {
      validate_options(body, {}, run_options(spec.solver, duration));
    } catch (const InputError& e) {
      throw InputError(where + ": [solver] " + e.what());
    }
  }
  FLEXROCK_THROW_UNLESS(std::isfinite(spec.amplitudes.back() * a_unit),
                        "spectrum: amplitudes: the largest one overflows in m/s^2");
  res.cells.resize(rows * cols);
  if (spec.bisect) res.boundary.resize(cols);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) {
      SpectrumCell& c = res.cells[i * cols + j];
      c.row = i;
      c.column = j;
      c.amplitude = spec.amplitudes[i];
      c.frequency = spec.frequencies[j];
      c.amplitude_si = c.amplitude * a_unit;
      c.omega_si = c.frequency * w_unit;
    }
  }
  for (std::size_t j = 0; j < res.boundary.size(); ++j) {
    res.boundary[j].column = j;
    res.boundary[j].frequency = spec.frequencies[j];
  }
  return res;
}

SpectrumResult record_spectrum_grid(const Body& body, const RecordSpectrumSpec& spec) {
  check_grid(spec.scales, "scales", true);
  check_common(spec.free_periods, spec.bisection_tolerance);
  FLEXROCK_THROW_UNLESS(spec.motion.duration() > 0.0, "spectrum: the record is empty");
  const double duration = spec.motion.duration() + free_span(body, spec.free_periods);
  FLEXROCK_THROW_UNLESS(std::isfinite(duration), "spectrum: the record and free motion last " +
                                                     format_number(duration) +
                                                     " s; expected a finite duration");
  try {
    validate_options(body, {}, run_options(spec.solver, duration));
  } catch (const InputError& e) {
    throw InputError(std::string("spectrum: [solver] ") + e.what());
  }
  // the scaled record must stay finite
  const BaseAcceleration pk = peak_acceleration(spec.motion);
  const double peak = std::max(pk.x, pk.y);
  FLEXROCK_THROW_UNLESS(
      std::isfinite(peak * spec.scales.back()),
      "spectrum: scales: the record scaled by " + format_number(spec.scales.back()) + " overflows");
  SpectrumResult res;
  res.tan_alpha = body.alpha1();
  res.alpha = body.tipping_angle(1);
  res.p = body.rocking_frequency();
  res.sliding = std::isfinite(spec.solver.friction_coefficient);
  const double pga = intensity(spec.motion).pga;  // sampled or analytic
  const std::size_t rows = spec.scales.size();
  res.cells.resize(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    SpectrumCell& c = res.cells[i];
    c.row = i;
    c.amplitude = spec.scales[i];
    c.amplitude_si = spec.scales[i] * pga;
  }
  if (spec.bisect) res.boundary.resize(1);
  return res;
}

namespace {

// cells and boundaries already known from `resume`: marked, not run again
void apply_resume(SpectrumResult& res, const SpectrumResume* resume) {
  if (!resume) return;
  for (const auto& [i, outcome] : resume->cells) {
    FLEXROCK_THROW_UNLESS(i < res.cells.size(),
                          "spectrum resume: cell index " + std::to_string(i) + " out of range");
    res.cells[i].run.outcome = outcome;
    res.cells[i].resumed = true;
  }
  for (const std::size_t j : resume->boundaries) {
    FLEXROCK_THROW_UNLESS(j < res.boundary.size(),
                          "spectrum resume: boundary index " + std::to_string(j) + " out of range");
    res.boundary[j].resumed = true;
  }
}

}  // namespace

SpectrumResult compute_spectrum(const Body& body, const SpectrumSpec& spec,
                                const RunOptions& options, const SpectrumResume* resume) {
  check_ranks(options);
  SpectrumResult res = spectrum_grid(body, spec);
  apply_resume(res, resume);
  const double a_unit = spec.normalized ? body.g() * body.alpha1() : spec.units.amplitude_si;
  const std::size_t rows = spec.amplitudes.size();
  const std::size_t cols = spec.frequencies.size();
  // the columns this process computes, and that have something left to compute
  std::vector<std::size_t> todo;
  for (std::size_t j = 0; j < cols; ++j) {
    if (!mine(j, options)) continue;
    bool left = spec.bisect && !res.boundary[j].resumed;
    for (std::size_t i = 0; i < rows && !left; ++i) left = !res.cells[i * cols + j].resumed;
    if (left) todo.push_back(j);
  }
  std::mutex report;  // the callbacks are called one at a time
  parallel_for(
      todo.size(), options.threads,
      [&](std::size_t k) {
        const std::size_t j = todo[k];
        const double omega = res.cells[j].omega_si;
        for (std::size_t i = 0; i < rows; ++i) {
          if (cancelled(options.cancel)) return;  // a column can take long: stop between cells
          SpectrumCell& c = res.cells[i * cols + j];
          if (c.resumed) continue;
          c.run = run_pulse_cell(body, spec, c.amplitude_si, omega);
          c.computed = true;
          if (resume && resume->on_cell) {
            const std::lock_guard lock(report);
            resume->on_cell(c);
          }
          if (options.completed) options.completed->fetch_add(1, std::memory_order_relaxed);
        }
        if (spec.bisect && !res.boundary[j].resumed) {
          OverturnBoundary b = bisect_column(
              spec.amplitudes, res.cells, cols, j, spec.frequencies[j], true,
              spec.bisection_tolerance, options.cancel,
              [&](double a) { return run_pulse_cell(body, spec, a * a_unit, omega); });
          if (b.computed && resume && resume->on_boundary) {
            const std::lock_guard lock(report);
            resume->on_boundary(b);
          }
          res.boundary[j] = b;
        }
      },
      options.cancel);
  return res;
}

SpectrumResult compute_record_spectrum(const Body& body, const RecordSpectrumSpec& spec,
                                       const RunOptions& options, const SpectrumResume* resume) {
  check_ranks(options);
  SpectrumResult res = record_spectrum_grid(body, spec);
  apply_resume(res, resume);
  const std::size_t rows = spec.scales.size();
  // rows spread over ranks and threads; the bisection (one column) runs on rank 0 afterwards
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < rows; ++i) {
    if (mine(i, options) && !res.cells[i].resumed) todo.push_back(i);
  }
  std::mutex report;
  parallel_for(
      todo.size(), options.threads,
      [&](std::size_t k) {
        SpectrumCell& c = res.cells[todo[k]];
        c.run = run_record_cell(body, spec, c.amplitude);
        c.computed = true;
        if (resume && resume->on_cell) {
          const std::lock_guard lock(report);
          resume->on_cell(c);
        }
        if (options.completed) options.completed->fetch_add(1, std::memory_order_relaxed);
      },
      options.cancel);
  if (options.ranks == 1 && spec.bisect && !res.boundary[0].resumed && !cancelled(options.cancel)) {
    res.boundary[0] = record_boundary(body, spec, res.cells, options.cancel);
    if (res.boundary[0].computed && resume && resume->on_boundary) {
      resume->on_boundary(res.boundary[0]);
    }
  }
  return res;
}

OverturnBoundary record_boundary(const Body& body, const RecordSpectrumSpec& spec,
                                 const std::vector<SpectrumCell>& cells,
                                 const std::atomic<bool>* cancel) {
  return bisect_column(spec.scales, cells, 1, 0, 0.0, spec.bisect, spec.bisection_tolerance, cancel,
                       [&](double s) { return run_record_cell(body, spec, s); });
}

}  // namespace flexrock::study
