// SPDX-License-Identifier: BSD-3-Clause
// Sweeps: rows equal direct runs, the thread count changes no byte, intensity measures against
// closed forms, target-PGA scaling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/study/sweep.hpp"
#include "support/expect_error.hpp"

namespace flexrock::study {
namespace {

SweepSpec small_sweep() {
  SweepSpec s;
  s.bodies.push_back({"block", rigid_block(0.4, 2.0, 1000.0)});
  s.bodies.push_back({"oscillator", oscillator_on_slab(800.0, 2.0, 400.0, 2.0, 1.0, 0.02)});
  s.records.push_back({"one_sine", one_sine_pulse(1.0, 5.0, 3.0)});
  // a sampled record: a few cycles of a decaying sine
  std::vector<double> a;
  for (int i = 0; i < 400; ++i) a.push_back(std::sin(0.1 * i) * std::exp(-0.005 * i));
  s.records.push_back({"sampled", GroundMotion::uniform(0.01, a)});
  s.scales = {1.0, 2.5, 4.0, 6.0};
  s.free_periods = 1.0;
  return s;
}

TEST(StudySweep, RunIndicesAreBodyMajor) {
  const SweepSpec s = small_sweep();
  const auto runs = sweep_runs(s);
  ASSERT_EQ(runs.size(), 16u);
  EXPECT_EQ(runs[5].index, 5u);
  EXPECT_EQ(runs[5].body, 0u);
  EXPECT_EQ(runs[5].record, 1u);
  EXPECT_EQ(runs[5].scale_index, 1u);
  EXPECT_EQ(runs[9].body, 1u);
}

TEST(StudySweep, ThreadCountChangesNoByteOfTheRows) {
  const SweepSpec s = small_sweep();
  const auto one = run_sweep(s, {}, {.threads = 1});
  const auto three = run_sweep(s, {}, {.threads = 3});
  ASSERT_EQ(one.size(), three.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(io::sweep_row(s, one[i]), io::sweep_row(s, three[i]));
  }
  // the rows span the outcome classes
  int over = 0, rock = 0;
  for (const SweepRow& r : one) {
    over += overturned(r.run.outcome);
    rock += r.run.outcome == Outcome::kRocking;
  }
  EXPECT_GT(over, 0);
  EXPECT_GT(rock, 0);
}

TEST(StudySweep, RowEqualsADirectSimulation) {
  const SweepSpec s = small_sweep();
  for (const SweepRun& run : sweep_runs(s)) {
    const SweepRow row = run_sweep_one(s, run);
    const Body body(s.bodies[run.body].body);
    const GroundMotion& m = s.records[run.record].motion;
    SimulationOptions o = s.solver;
    o.t_end = m.duration() + 2.0 * std::numbers::pi / body.rocking_frequency();
    const SimulationResult r = simulate(body, m.scaled(s.scales[run.scale_index]), {}, o);
    EXPECT_EQ(row.run.status, r.status);
    EXPECT_EQ(row.run.impacts, r.extremes.impacts);
    EXPECT_EQ(row.run.overturn_time, r.extremes.overturn_time);
    EXPECT_EQ(row.duration, o.t_end);
  }
}

TEST(StudySweep, SubsetsAndRanksComputeOnlyTheirRuns) {
  const SweepSpec s = small_sweep();
  const auto all = run_sweep(s, {}, {.threads = 2});
  const auto part = run_sweep(s, {3, 1, 12}, {.threads = 2});
  ASSERT_EQ(part.size(), 3u);
  EXPECT_EQ(part[0].index, 1u);
  EXPECT_EQ(io::sweep_row(s, part[2]), io::sweep_row(s, all[12]));
  const auto odd = run_sweep(s, {}, {.threads = 2, .rank = 1, .ranks = 2});
  ASSERT_EQ(odd.size(), 8u);
  for (const SweepRow& r : odd) {
    EXPECT_EQ(r.index % 2, 1u);
    EXPECT_EQ(io::sweep_row(s, r), io::sweep_row(s, all[r.index]));
  }
}

TEST(StudySweep, JournalCallbackSeesEveryRowOnce) {
  const SweepSpec s = small_sweep();
  std::vector<int> seen(16, 0);
  run_sweep(s, {}, {.threads = 3}, [&](const SweepRow& r) { ++seen[r.index]; });
  for (int n : seen) EXPECT_EQ(n, 1);
}

TEST(StudySweep, IntensityOfAOneSinePulseMatchesTheClosedForm) {
  // a(t) = a_p sin(w t): PGA = a_p, v(t) = a_p/w (1 - cos w t), PGV = 2 a_p / w at t = pi/w
  const double ap = 3.0, w = 4.0;
  const Intensity analytic = intensity(one_sine_pulse(ap, w, 5.0), 1e-4);
  EXPECT_NEAR(analytic.pga, ap, 1e-6);
  EXPECT_NEAR(analytic.pgv, 2.0 * ap / w, 1e-6);
  std::vector<double> a;
  const double dt = 1e-4;
  for (int i = 0; i * dt <= 2.0 * std::numbers::pi / w; ++i) a.push_back(ap * std::sin(w * i * dt));
  const Intensity sampled = intensity(GroundMotion::uniform(dt, a));
  EXPECT_NEAR(sampled.pgv, 2.0 * ap / w, 1e-6);
}

TEST(StudySweep, TargetPgaScalesEachRecordToIt) {
  SweepSpec s = small_sweep();
  s.scale_kind = ScaleKind::kTargetPga;
  s.scales = {0.5, 3.0};
  for (const SweepRun& run : sweep_runs(s)) {
    if (run.body != 0) continue;
    const SweepRow row = run_sweep_one(s, run);
    EXPECT_NEAR(row.pga, s.scales[run.scale_index], 1e-12);
  }
}

// the CSV's requested_level: the level as given, one value a level whatever the record (the
// computed pga_g differs between records in its last bits: no key for a pivot)
TEST(StudySweep, RequestedLevelIsTheSameNumberForEveryRecord) {
  SweepSpec s = small_sweep();
  s.bodies.resize(1);
  s.scale_kind = ScaleKind::kTargetPga;
  s.levels = {0.1, 0.3, 0.7};
  s.level_units = "g";
  s.scales.clear();
  for (double v : s.levels) s.scales.push_back(v * 9.80665);
  const auto cols = io::sweep_columns();
  const auto at = [&](const std::string& row, const std::string& name) {
    std::size_t k = std::find(cols.begin(), cols.end(), name) - cols.begin(), start = 0;
    for (std::size_t i = 0; i < k; ++i) start = row.find(',', start) + 1;
    return row.substr(start, row.find(',', start) - start);
  };
  for (const SweepRow& r : run_sweep(s, {}, {.threads = 2})) {
    const std::string line = io::sweep_row(s, r);
    EXPECT_EQ(at(line, "requested_level"),
              std::vector<std::string>({"0.1", "0.3", "0.7"})[r.scale_index]);
    EXPECT_EQ(at(line, "requested_units"), "g");
    EXPECT_NEAR(std::stod(at(line, "pga_g")), s.levels[r.scale_index], 1e-12);
  }
  // factors: the factor itself, unit "-"
  const SweepSpec f = small_sweep();
  const SweepRow r = run_sweep_one(f, sweep_runs(f)[2]);
  const std::string line = io::sweep_row(f, r);
  EXPECT_EQ(at(line, "requested_level"), "4");
  EXPECT_EQ(at(line, "requested_units"), "-");
  // one level a scale
  s.levels.pop_back();
  test::expect_input_error([&] { validate(s); }, {"levels", "one requested level per scale"});
}

TEST(StudySweep, BadSpecsAreInputErrors) {
  SweepSpec s = small_sweep();
  s.scales = {1.0, -1.0};
  test::expect_input_error([&] { validate(s); }, {"scales[1]", "> 0"});
  s = small_sweep();
  s.records.clear();
  test::expect_input_error([&] { validate(s); }, {"at least one record"});
}

}  // namespace
}  // namespace flexrock::study
