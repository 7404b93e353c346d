// Whole runs: CPU time per simulation, with steps, right-hand sides and events as counters.
#include <benchmark/benchmark.h>

#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace {

using namespace flexrock;

void run_and_count(benchmark::State& state, const Body& body, const InitialState& init,
                   const SimulationOptions& opt) {
  const GroundMotion none = GroundMotion::none(opt.t_end);
  SimulationResult r;
  for (auto _ : state) {
    r = simulate(body, none, init, opt);
    benchmark::DoNotOptimize(r.extremes.impacts);
  }
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["rhs"] = static_cast<double>(r.rhs_evaluations);
  state.counters["events"] = static_cast<double>(r.events.size());
  state.counters["impacts"] = static_cast<double>(r.extremes.impacts);
}

// Housner's block, b = 0.2 m, h = 1.0 m (half-width, half-height), from 0.8 alpha, 20 s
void BM_RigidBlockFreeRocking20s(benchmark::State& state) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 1.0));
  InitialState init;
  init.theta = 0.8 * body.alpha1();
  SimulationOptions opt;
  opt.t_end = 20.0;
  run_and_count(state, body, init, opt);
}
BENCHMARK(BM_RigidBlockFreeRocking20s)->Unit(benchmark::kMicrosecond);

// a 1 Hz oscillator on a rocking slab (n = 1) from half its overturning angle, 20 s
void BM_OscillatorFreeRocking20s(benchmark::State& state) {
  const Body body(oscillator_on_slab(1000.0, 1.0, 500.0, 2.0, 1.0, 0.0));
  InitialState init;
  init.theta = 0.5 * body.tipping_angle(1);
  SimulationOptions opt;
  opt.t_end = 20.0;
  run_and_count(state, body, init, opt);
}
BENCHMARK(BM_OscillatorFreeRocking20s)->Unit(benchmark::kMicrosecond);

}  // namespace
