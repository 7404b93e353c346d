// SPDX-License-Identifier: BSD-3-Clause
// Overturning spectra: classification against closed forms and direct simulate() calls, the
// bisection bracket, and independence from the thread and process counts.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/study/spectrum.hpp"
#include "support/expect_error.hpp"

namespace flexrock::study {
namespace {

// b = 0.2 m, h = 1.0 m: tan alpha = 0.2
Body slender_block() { return Body(rigid_block(0.4, 2.0, 1000.0)); }

SpectrumSpec small_spec() {
  SpectrumSpec s;
  s.pulse = "one_sine";
  s.amplitudes = {1.5, 2.5, 3.5, 4.5, 6.0};
  s.frequencies = {1.5, 3.0, 6.0};
  return s;
}

void expect_same(const RunSummary& a, const RunSummary& b) {
  EXPECT_EQ(a.outcome, b.outcome);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.impacts, b.impacts);
  EXPECT_EQ(a.max_theta_over_alpha, b.max_theta_over_alpha);
  EXPECT_EQ(a.first_uplift_time, b.first_uplift_time);
  EXPECT_EQ(a.overturn_time, b.overturn_time);
  EXPECT_EQ(a.energy_lost, b.energy_lost);
}

TEST(StudySpectrum, RigidBlockBelowStaticThresholdNeverUplifts) {
  // a rigid block uplifts only when the base acceleration exceeds g tan alpha (Housner 1963);
  // a one-sine pulse peaks at a_p
  const Body body = slender_block();
  SpectrumSpec s;
  s.amplitudes = {0.3, 0.6, 0.9, 0.99};
  s.frequencies = {0.5, 2.0, 8.0};
  const SpectrumResult r = compute_spectrum(body, s, {.threads = 2});
  ASSERT_EQ(r.cells.size(), 12u);
  for (const SpectrumCell& c : r.cells) {
    EXPECT_EQ(c.run.outcome, Outcome::kNoUplift) << c.amplitude << " " << c.frequency;
    EXPECT_EQ(c.run.max_theta, 0.0);
    EXPECT_EQ(c.run.first_uplift_time, -1.0);
  }
  for (const OverturnBoundary& b : r.boundary) EXPECT_EQ(b.kind, OverturnBoundary::Kind::kNone);
}

TEST(StudySpectrum, RigidBlockAboveStaticThresholdUplifts) {
  // just above g tan alpha the block must lift off, at the time the pulse first exceeds it:
  // a_p sin(omega t) = g tan alpha
  const Body body = slender_block();
  SpectrumSpec s;
  s.amplitudes = {1.05};
  s.frequencies = {2.0};
  const SpectrumResult r = compute_spectrum(body, s, {.threads = 1});
  const SpectrumCell& c = r.cells.at(0);
  EXPECT_NE(c.run.outcome, Outcome::kNoUplift);
  EXPECT_GT(c.run.max_theta, 0.0);
  const double t_uplift = std::asin(1.0 / 1.05) / c.omega_si;
  EXPECT_NEAR(c.run.first_uplift_time, t_uplift, 1e-6);
  EXPECT_NEAR(c.amplitude_si, 1.05 * kStandardGravity * 0.2, 1e-12);
  EXPECT_NEAR(c.omega_si, 2.0 * body.rocking_frequency(), 1e-12);
}

TEST(StudySpectrum, CellOutcomeEqualsDirectSimulation) {
  // every cell against simulate() over the whole pulse + free motion, classified here from the
  // engine's status and impact count
  const Body body = slender_block();
  const SpectrumSpec s = small_spec();
  const SpectrumResult r = compute_spectrum(body, s, {.threads = 2});
  int overturned_cells = 0, rocking_cells = 0;
  for (const SpectrumCell& c : r.cells) {
    const double duration = pulse_length(s.pulse, c.omega_si) +
                            s.free_periods * 2.0 * std::numbers::pi / body.rocking_frequency();
    SimulationOptions o = s.solver;
    o.t_end = duration;
    const SimulationResult sim =
        simulate(body, one_sine_pulse(c.amplitude_si, c.omega_si, duration), {}, o);
    Outcome expected = Outcome::kNoUplift;
    if (sim.status == Status::kOverturned) {
      expected = sim.extremes.impacts == 0 ? Outcome::kOverturnedWithoutImpact
                                           : Outcome::kOverturnedAfterImpacts;
      ++overturned_cells;
    } else if (sim.extremes.first_uplift_time >= 0.0) {
      expected = Outcome::kRocking;
      ++rocking_cells;
    }
    EXPECT_EQ(c.run.outcome, expected) << c.amplitude << " " << c.frequency;
    EXPECT_EQ(c.run.impacts, sim.extremes.impacts);
    const double tilt = std::max(sim.extremes.max_theta_edge1, sim.extremes.max_theta_edge2);
    EXPECT_NEAR(c.run.max_theta_over_alpha, tilt / std::atan(0.2), 1e-12);
  }
  // the grid spans both sides of the boundary
  EXPECT_GT(overturned_cells, 0);
  EXPECT_GT(rocking_cells, 0);
}

TEST(StudySpectrum, ThreadCountDoesNotChangeAnyResult) {
  const Body body = slender_block();
  const SpectrumSpec s = small_spec();
  const SpectrumResult one = compute_spectrum(body, s, {.threads = 1});
  const SpectrumResult three = compute_spectrum(body, s, {.threads = 3});
  ASSERT_EQ(one.cells.size(), three.cells.size());
  for (std::size_t i = 0; i < one.cells.size(); ++i)
    expect_same(one.cells[i].run, three.cells[i].run);
  ASSERT_EQ(one.boundary.size(), three.boundary.size());
  for (std::size_t j = 0; j < one.boundary.size(); ++j) {
    EXPECT_EQ(one.boundary[j].kind, three.boundary[j].kind);
    EXPECT_EQ(one.boundary[j].safe, three.boundary[j].safe);
    EXPECT_EQ(one.boundary[j].overturning, three.boundary[j].overturning);
  }
}

TEST(StudySpectrum, RanksSplitTheColumnsAndTogetherGiveTheWhole) {
  const Body body = slender_block();
  const SpectrumSpec s = small_spec();
  const SpectrumResult all = compute_spectrum(body, s, {.threads = 2});
  const SpectrumResult r0 = compute_spectrum(body, s, {.threads = 1, .rank = 0, .ranks = 2});
  const SpectrumResult r1 = compute_spectrum(body, s, {.threads = 2, .rank = 1, .ranks = 2});
  for (std::size_t i = 0; i < all.cells.size(); ++i) {
    const bool even = all.cells[i].column % 2 == 0;
    EXPECT_EQ(r0.cells[i].computed, even);
    EXPECT_EQ(r1.cells[i].computed, !even);
    expect_same(all.cells[i].run, even ? r0.cells[i].run : r1.cells[i].run);
  }
}

TEST(StudySpectrum, BisectionBracketsTheMinimumOverturningAmplitude) {
  const Body body = slender_block();
  SpectrumSpec s = small_spec();
  s.bisection_tolerance = 1e-3;
  const SpectrumResult r = compute_spectrum(body, s, {.threads = 2});
  int found = 0;
  for (const OverturnBoundary& b : r.boundary) {
    if (b.kind != OverturnBoundary::Kind::kFound) continue;
    ++found;
    const double omega = s.frequencies[b.column] * body.rocking_frequency();
    const double unit = kStandardGravity * 0.2;
    // the bracket is tight, its ends are what they claim, and it lies between grid points
    EXPECT_LE(b.overturning - b.safe, s.bisection_tolerance * b.overturning);
    EXPECT_TRUE(overturned(run_pulse_cell(body, s, b.overturning * unit, omega).outcome));
    EXPECT_FALSE(overturned(run_pulse_cell(body, s, b.safe * unit, omega).outcome));
    std::size_t k = 0;
    while (!overturned(r.cells[k * s.frequencies.size() + b.column].run.outcome)) ++k;
    EXPECT_LE(b.overturning, s.amplitudes[k]);
    EXPECT_GE(b.safe, s.amplitudes[k - 1]);
    EXPECT_GT(b.bisection_runs, 0);
  }
  EXPECT_GT(found, 0);
}

TEST(StudySpectrum, OscillatorOnRockingBaseMatchesDirectSimulation) {
  // a flexible body is followed to the end (no shortcut): compare with simulate()
  const Body body(oscillator_on_slab(800.0, 2.0, 400.0, 2.0, 1.0, 0.02));
  SpectrumSpec s;
  s.amplitudes = {0.8, 2.0, 4.0};
  s.frequencies = {2.0, 5.0};
  s.free_periods = 2.0;
  const SpectrumResult r = compute_spectrum(body, s, {.threads = 2});
  for (const SpectrumCell& c : r.cells) {
    const double duration =
        pulse_length(s.pulse, c.omega_si) + 2.0 * 2.0 * std::numbers::pi / body.rocking_frequency();
    SimulationOptions o = s.solver;
    o.t_end = duration;
    const SimulationResult sim =
        simulate(body, one_sine_pulse(c.amplitude_si, c.omega_si, duration), {}, o);
    expect_same(c.run, summarize(body, sim));
  }
}

TEST(StudySpectrum, RecordSpectrumScalesTheRecord) {
  const Body body = slender_block();
  RecordSpectrumSpec s;
  s.motion = one_sine_pulse(1.0, 2.0 * body.rocking_frequency(), 2.0);
  s.scales = {0.5, 1.0, 3.0, 5.0, 8.0, 12.0};
  s.free_periods = 2.0;
  const SpectrumResult r = compute_record_spectrum(body, s, {.threads = 2});
  ASSERT_EQ(r.cells.size(), 6u);
  // below g tan alpha = 1.96 m/s^2 nothing happens
  EXPECT_EQ(r.cells[0].run.outcome, Outcome::kNoUplift);
  EXPECT_EQ(r.cells[1].run.outcome, Outcome::kNoUplift);
  for (const SpectrumCell& c : r.cells) {
    // PGA of the scaled pulse, the analytic motion sampled every 1 ms: relative error at most
    // (omega dt)^2 / 8
    const double w_dt = 2.0 * body.rocking_frequency() * 1e-3;
    EXPECT_NEAR(c.amplitude_si, c.amplitude, c.amplitude * w_dt * w_dt / 8.0);
    expect_same(c.run, run_record_cell(body, s, c.amplitude));
  }
  ASSERT_EQ(r.boundary.size(), 1u);
  if (r.boundary[0].kind == OverturnBoundary::Kind::kFound) {
    EXPECT_TRUE(overturned(run_record_cell(body, s, r.boundary[0].overturning).outcome));
    EXPECT_FALSE(overturned(run_record_cell(body, s, r.boundary[0].safe).outcome));
  }
}

TEST(StudySpectrum, BadSpecsAreInputErrors) {
  const Body body = slender_block();
  SpectrumSpec s = small_spec();
  s.amplitudes = {2.0, 1.0};
  test::expect_input_error([&] { compute_spectrum(body, s); }, {"amplitudes", "increasing"});
  s = small_spec();
  s.frequencies = {};
  test::expect_input_error([&] { compute_spectrum(body, s); }, {"frequencies", "at least one"});
  s = small_spec();
  s.bisection_tolerance = 0.0;
  test::expect_input_error([&] { compute_spectrum(body, s); }, {"bisection_tolerance"});
  s = small_spec();
  s.pulse = "one-sine";
  test::expect_input_error([&] { compute_spectrum(body, s); }, {"one_sine", "one-sine"});
  // a type without a length (harmonic over the whole duration) is not a spectrum family
  s.pulse = "harmonic";
  test::expect_input_error([&] { compute_spectrum(body, s); }, {"pulse type of spectra", "ricker"});
}

TEST(StudySpectrum, BisectionToleranceBelowTheMinimumIsRefused) {
  // 1e-16 once bisected forever: the midpoint of adjacent doubles is one of them
  const Body body = slender_block();
  SpectrumSpec s = small_spec();
  s.bisection_tolerance = 1e-16;
  test::expect_input_error([&] { compute_spectrum(body, s); }, {"bisection_tolerance", "1e-12"});
  RecordSpectrumSpec r;
  r.motion = one_sine_pulse(1.0, 2.0 * body.rocking_frequency(), 2.0);
  r.scales = {1.0, 2.0};
  r.bisection_tolerance = 0.5 * kMinBisectionTolerance;
  test::expect_input_error([&] { compute_record_spectrum(body, r); }, {"bisection_tolerance"});
}

TEST(StudySpectrum, BisectionAtTheMinimumToleranceEnds) {
  // the narrowest allowed bracket: about log2(grid spacing / 1e-12) = 40 runs, then it stops
  const Body body = slender_block();
  RecordSpectrumSpec s;
  s.motion = one_sine_pulse(1.0, 2.0 * body.rocking_frequency(), 2.0);
  s.scales = {0.5, 1.0, 3.0, 5.0, 8.0, 12.0};
  s.free_periods = 1.0;
  s.bisection_tolerance = kMinBisectionTolerance;
  const SpectrumResult r = compute_record_spectrum(body, s, {.threads = 2});
  ASSERT_EQ(r.boundary.size(), 1u);
  const OverturnBoundary& b = r.boundary[0];
  ASSERT_EQ(b.kind, OverturnBoundary::Kind::kFound);
  EXPECT_TRUE(b.computed);
  EXPECT_LE(b.overturning - b.safe, kMinBisectionTolerance * b.overturning);
  EXPECT_LT(b.safe, b.overturning);
  EXPECT_LE(b.bisection_runs, 45);
}

TEST(StudySpectrum, AStopRequestEndsTheBisectionUnfinished) {
  const Body body = slender_block();
  RecordSpectrumSpec s;
  s.motion = one_sine_pulse(1.0, 2.0 * body.rocking_frequency(), 2.0);
  s.scales = {0.5, 1.0, 3.0, 5.0, 8.0, 12.0};
  s.free_periods = 1.0;
  const SpectrumResult r = compute_record_spectrum(body, s, {.threads = 1});
  ASSERT_EQ(r.boundary.at(0).kind, OverturnBoundary::Kind::kFound);
  ASSERT_GT(r.boundary[0].bisection_runs, 0);
  const std::atomic<bool> stop{true};
  const OverturnBoundary b = record_boundary(body, s, r.cells, &stop);
  EXPECT_FALSE(b.computed);  // not a result: the bracket is the grid's
  EXPECT_EQ(b.bisection_runs, 0);
  // stopped before the first run: no cell computed, no boundary
  const SpectrumResult none = compute_record_spectrum(body, s, {.threads = 2, .cancel = &stop});
  for (const SpectrumCell& c : none.cells) EXPECT_FALSE(c.computed);
  EXPECT_FALSE(none.boundary.at(0).computed);
}

}  // namespace
}  // namespace flexrock::study
