// SPDX-License-Identifier: BSD-3-Clause
// Whole runs (docs/performance.md, cases a-d): CPU time per simulation, with steps, right-hand
// sides and events as counters, and the accuracy of each case's tolerance against a run at
// rtol = 1e-13 (counters err_*, relative).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "cases.hpp"

namespace {

using namespace flexrock;
using namespace flexrock::bench;

// relative difference of two times (or angles), guarding zero
double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// the robust quantities of a run under a record: first uplift, first impacts, overturning
double robust_error(const SimulationResult& r, const SimulationResult& ref, int impacts) {
  double e = rel(r.extremes.first_uplift_time, ref.extremes.first_uplift_time);
  int k = 0;
  for (std::size_t i = 0, j = 0; i < r.events.size() && j < ref.events.size() && k < impacts;) {
    if (r.events[i].kind != EventKind::kImpact) {
      ++i;
      continue;
    }
    if (ref.events[j].kind != EventKind::kImpact) {
      ++j;
      continue;
    }
    e = std::max(e, rel(r.events[i].time, ref.events[j].time));
    ++i, ++j, ++k;
  }
  if (r.status != ref.status || r.extremes.overturn_edge != ref.extremes.overturn_edge) e = 1.0;
  return e;
}

void run_case(benchmark::State& state, const Case& c) {
  SimulationResult r;
  for (auto _ : state) {
    r = simulate(c.body, c.motion, c.init, c.opt);
    benchmark::DoNotOptimize(r.extremes.impacts);
  }
  SimulationOptions tight = c.opt;
  tight.rtol = 1e-13;
  tight.atol = 1e-15;
  const SimulationResult ref = simulate(c.body, c.motion, c.init, tight);
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["rhs"] = static_cast<double>(r.rhs_evaluations);
  state.counters["events"] = static_cast<double>(r.events.size());
  state.counters["impacts"] = static_cast<double>(r.extremes.impacts);
  state.counters["slips"] = static_cast<double>(r.extremes.slips);
  state.counters["overturned"] = r.status == Status::kOverturned ? 1.0 : 0.0;
  const double mt = std::max(r.extremes.max_theta_edge1, r.extremes.max_theta_edge2);
  const double mt_ref = std::max(ref.extremes.max_theta_edge1, ref.extremes.max_theta_edge2);
  state.counters["max_theta"] = mt;
  state.counters["err_max_theta"] = rel(mt, mt_ref);
  state.counters["err_robust"] = robust_error(r, ref, 5);
  state.counters["first_uplift"] = r.extremes.first_uplift_time;
}

void BM_A_RigidFreeRocking(benchmark::State& s) { run_case(s, case_a()); }
void BM_B_RigidPulse2pi(benchmark::State& s) { run_case(s, case_b(2.0 * kPi)); }
void BM_B_RigidPulse6pi(benchmark::State& s) { run_case(s, case_b(6.0 * kPi)); }
void BM_C_RigidKobe(benchmark::State& s) { run_case(s, case_c()); }
void BM_D_OscillatorKobe(benchmark::State& s) { run_case(s, case_d_oscillator()); }
void BM_D_Cantilever4Kobe(benchmark::State& s) { run_case(s, case_d_cantilever()); }
void BM_D_Cantilever8Kobe(benchmark::State& s) { run_case(s, case_d_cantilever(8)); }
// the same cantilever with n = 0 (rigid), 1, 2, 4 and 8 modes: the cost against n, per record
// interval (CPU per run / intervals) and per right-hand side (CPU per run / rhs)
void BM_ModesKobe(benchmark::State& s) {
  const Case c = case_d_cantilever(static_cast<int>(s.range(0)));
  run_case(s, c);
  s.counters["intervals"] = static_cast<double>(c.motion.times().size() - 1);
}

// (e) the stiff slab: steps, right-hand sides, how far it got and its outcome (no reference run at
// rtol 1e-13: the explicit method alone cannot reach the end). _Explicit forces DOPRI5 alone, the
// engine before the stiff rocking integrator (and before DOP853): it stops at max_steps (5e7)
// half-way through, so it runs once
void run_stiff(benchmark::State& state, const Case& c) {
  SimulationResult r;
  for (auto _ : state) {
    r = simulate(c.body, c.motion, c.init, c.opt);
    benchmark::DoNotOptimize(r.extremes.impacts);
  }
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["rhs"] = static_cast<double>(r.rhs_evaluations);
  state.counters["impacts"] = static_cast<double>(r.extremes.impacts);
  state.counters["t_reached"] = r.t_end;
  state.counters["completed"] = r.status == Status::kCompleted ? 1.0 : 0.0;
  state.counters["max_theta"] = std::max(r.extremes.max_theta_edge1, r.extremes.max_theta_edge2);
}
void BM_E_StiffSlabKobe(benchmark::State& s) { run_stiff(s, case_e_stiff_slab()); }
void BM_E_StiffSlabKobe_Explicit(benchmark::State& s) {
  Case c = case_e_stiff_slab();
  c.opt.methods.rocking_integrator = ContactIntegrator::kExplicit;
  c.opt.methods.high_order_rocking = false;
  run_stiff(s, c);
}

// the same cases with the options the engine had before it followed flight (chatter_ratio 0.01,
// overturning at the static angle): the event loop's cost at equal work, against the old engine
Case pre_flight_options(Case c) {
  c.opt.chatter_ratio = 0.01;
  c.opt.overturn = OverturnCriterion::kStaticInstability;
  return c;
}
void BM_A_RigidFreeRocking_OldOptions(benchmark::State& s) {
  run_case(s, pre_flight_options(case_a()));
}
void BM_B_RigidPulse2pi_OldOptions(benchmark::State& s) {
  run_case(s, pre_flight_options(case_b(2.0 * kPi)));
}
void BM_C_RigidKobe_OldOptions(benchmark::State& s) { run_case(s, pre_flight_options(case_c())); }
void BM_B_RigidPulse6pi_OldOptions(benchmark::State& s) {
  run_case(s, pre_flight_options(case_b(6.0 * kPi)));
}
void BM_D_OscillatorKobe_OldOptions(benchmark::State& s) {
  run_case(s, pre_flight_options(case_d_oscillator()));
}
void BM_D_Cantilever4Kobe_OldOptions(benchmark::State& s) {
  run_case(s, pre_flight_options(case_d_cantilever()));
}

// the same cases on a floor with Coulomb friction mu = 0.3 (below the records' peaks): the cost of
// sliding against the default, where the floor holds
Case with_friction(Case c) {
  c.opt.friction_coefficient = 0.3;
  return c;
}
void BM_B_RigidPulse2pi_Mu0p3(benchmark::State& s) {
  run_case(s, with_friction(case_b(2.0 * kPi)));
}
void BM_C_RigidKobe_Mu0p3(benchmark::State& s) { run_case(s, with_friction(case_c())); }
void BM_D_OscillatorKobe_Mu0p3(benchmark::State& s) {
  run_case(s, with_friction(case_d_oscillator()));
}
void BM_D_Cantilever4Kobe_Mu0p3(benchmark::State& s) {
  run_case(s, with_friction(case_d_cantilever()));
}

// medians over repetitions: the machine is shared, single runs are noisy
#define FLEXROCK_WHOLE_RUN(fn)                                      \
  BENCHMARK(fn)                                                     \
      ->Unit(benchmark::kMicrosecond)                               \
      ->Repetitions(7)                                              \
      ->ReportAggregatesOnly(true)                                  \
      ->ComputeStatistics("min", [](const std::vector<double>& v) { \
        return *std::min_element(v.begin(), v.end());               \
      })
FLEXROCK_WHOLE_RUN(BM_A_RigidFreeRocking);
FLEXROCK_WHOLE_RUN(BM_B_RigidPulse2pi);
FLEXROCK_WHOLE_RUN(BM_B_RigidPulse6pi);
FLEXROCK_WHOLE_RUN(BM_C_RigidKobe);
FLEXROCK_WHOLE_RUN(BM_D_OscillatorKobe);
FLEXROCK_WHOLE_RUN(BM_D_Cantilever4Kobe);
FLEXROCK_WHOLE_RUN(BM_D_Cantilever8Kobe);
FLEXROCK_WHOLE_RUN(BM_E_StiffSlabKobe);
BENCHMARK(BM_E_StiffSlabKobe_Explicit)->Unit(benchmark::kMillisecond)->Iterations(1);
FLEXROCK_WHOLE_RUN(BM_ModesKobe)->ArgName("n")->Arg(0)->Arg(1)->Arg(2)->Arg(4)->Arg(8);
FLEXROCK_WHOLE_RUN(BM_A_RigidFreeRocking_OldOptions);
FLEXROCK_WHOLE_RUN(BM_B_RigidPulse2pi_OldOptions);
FLEXROCK_WHOLE_RUN(BM_C_RigidKobe_OldOptions);
FLEXROCK_WHOLE_RUN(BM_B_RigidPulse6pi_OldOptions);
FLEXROCK_WHOLE_RUN(BM_D_OscillatorKobe_OldOptions);
FLEXROCK_WHOLE_RUN(BM_D_Cantilever4Kobe_OldOptions);
FLEXROCK_WHOLE_RUN(BM_B_RigidPulse2pi_Mu0p3);
FLEXROCK_WHOLE_RUN(BM_C_RigidKobe_Mu0p3);
FLEXROCK_WHOLE_RUN(BM_D_OscillatorKobe_Mu0p3);
FLEXROCK_WHOLE_RUN(BM_D_Cantilever4Kobe_Mu0p3);

}  // namespace
