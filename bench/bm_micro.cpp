// SPDX-License-Identifier: BSD-3-Clause
// Micro-benchmarks for n = 0, 1, 2, 4, 8 and 10 modes (8 also on the dynamic size that bodies of 9
// to 16 modes run on): one right-hand side of the event loop's state (rocking), one DOPRI5 step,
// one event location on the dense output, one impact map.
#include <benchmark/benchmark.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>

#include "flexrock/contact/impact.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/model/dynamics.hpp"

namespace {

using namespace flexrock;

Body body_with(int n) {
  return Body(n == 0 ? rigid_block(0.4, 2.0, 1000.0)
                     : uniform_cantilever(3.0, 1.0, 500.0, 5e7, n, 200.0, 0.02));
}

// the rocking system on edge 1: x = (theta, q, theta_dot, q_dot), under a 1 Hz harmonic base
template <int N, int MaxN>
struct Rocking {
  using Dyn = Dynamics<N, MaxN>;
  using Vec = typename Dyn::Vec;
  static constexpr int S = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N + 2;
  static constexpr int MaxS = MaxN == Eigen::Dynamic ? Eigen::Dynamic : 2 * MaxN + 2;
  using State = Eigen::Matrix<double, S, 1, Eigen::ColMajor, MaxS, 1>;
  explicit Rocking(const Body& b) : dyn(b), n(b.modes()), q(n), qd(n), qdd(n) {}
  void operator()(double t, const State& x, State& dx) {
    q = x.segment(1, n);
    qd = x.segment(n + 2, n);
    double thdd = 0.0;
    const BaseAcceleration a{2.0 * std::sin(2.0 * std::numbers::pi * t), 0.0};
    dyn.rocking_acceleration(1, x(0), q, x(n + 1), qd, a, thdd, qdd);
    dx.resize(x.size());
    dx(0) = x(n + 1);
    dx.segment(1, n) = qd;
    dx(n + 1) = thdd;
    dx.segment(n + 2, n) = qdd;
  }
  State start() const {
    State x(2 * n + 2);
    x.setZero();
    x(0) = 0.05;
    x(n + 1) = 0.3;
    x.segment(1, n).setConstant(1e-4);
    return x;
  }
  Dyn dyn;
  int n;
  Vec q, qd, qdd;
};

template <int N, int MaxN = N>
int modes(const benchmark::State& state) {
  return N == Eigen::Dynamic ? static_cast<int>(state.range(0)) : N;
}

template <int N, int MaxN = N>
void BM_Rhs(benchmark::State& state) {
  Rocking<N, MaxN> sys(body_with(modes<N, MaxN>(state)));
  auto x = sys.start();
  auto dx = x;
  for (auto _ : state) {
    sys(0.1, x, dx);
    benchmark::DoNotOptimize(dx.data());
    benchmark::ClobberMemory();
  }
}

// one accepted step of the error-controlled DOPRI5 at rtol 1e-8, restarted from the same state
template <int N, int MaxN = N>
void BM_Dopri5Step(benchmark::State& state) {
  Rocking<N, MaxN> sys(body_with(modes<N, MaxN>(state)));
  const auto x = sys.start();
  StepControl ctl;
  ctl.rtol = 1e-8;
  ctl.atol = 1e-10;
  Dopri5<typename Rocking<N, MaxN>::State> integ;
  // the step the error control settles on from this state, so that no step is rejected
  integ.start(sys, ctl, 0.0, x);
  for (int i = 0; i < 3; ++i) integ.step(sys, 1.0);
  const double h = integ.t1() - integ.t0();
  for (auto _ : state) {
    integ.start(sys, ctl, 0.0, x, h);  // one rhs: the FSAL start
    benchmark::DoNotOptimize(integ.step(sys, 1.0));
  }
  state.counters["rhs_per_iter"] = benchmark::Counter(static_cast<double>(integ.rhs_evaluations()),
                                                      benchmark::Counter::kAvgIterations);
}

// one event location: theta = 0 on the dense output of a step that crosses it (TOMS 748)
template <int N, int MaxN = N>
void BM_EventLocation(benchmark::State& state) {
  Rocking<N, MaxN> sys(body_with(modes<N, MaxN>(state)));
  auto x = sys.start();
  x(0) = 1e-3;
  x(sys.n + 1) = -0.3;  // falling back: theta crosses 0 after ~3 ms
  StepControl ctl;
  ctl.rtol = 1e-8;
  ctl.atol = 1e-10;
  Dopri5<typename Rocking<N, MaxN>::State> integ;
  integ.start(sys, ctl, 0.0, x);
  while (integ.x1()(0) > 0.0) integ.step(sys, 1.0);  // the step in which theta crosses zero
  auto xr = x;
  for (auto _ : state) {
    auto g = [&](double t) {
      integ.dense(t, xr);
      return xr(0);
    };
    std::uintmax_t iters = 100;
    const auto tol = [](double a, double b) { return std::abs(b - a) <= 2e-15; };
    const auto r = boost::math::tools::toms748_solve(g, integ.t0(), integ.t1(), g(integ.t0()),
                                                     g(integ.t1()), tol, iters);
    benchmark::DoNotOptimize(r.second);
  }
}

// one impact map (landing on edge 2, the both-edges rule checked)
template <int N, int MaxN = N>
void BM_ImpactMap(benchmark::State& state) {
  const Body body = body_with(modes<N, MaxN>(state));
  const Dynamics<N, MaxN> dyn(body);
  typename Dynamics<N, MaxN>::Vec q(body.modes()), qd(body.modes());
  q.setConstant(1e-4);
  qd.setConstant(1e-2);
  for (auto _ : state) {
    const auto out = resolve_impact(dyn, 2, q, 0.3, qd);
    benchmark::DoNotOptimize(out.theta_dot);
  }
}

#define FLEXROCK_FOR_MODES(bm)        \
  BENCHMARK(bm<0>)->Name(#bm "/n:0"); \
  BENCHMARK(bm<1>)->Name(#bm "/n:1"); \
  BENCHMARK(bm<2>)->Name(#bm "/n:2"); \
  BENCHMARK(bm<4>)->Name(#bm "/n:4"); \
  BENCHMARK(bm<8>)->Name(#bm "/n:8"); \
  BENCHMARK(bm<Eigen::Dynamic, 16>)->Name(#bm "/n")->Arg(8)->Arg(10)

FLEXROCK_FOR_MODES(BM_Rhs);
FLEXROCK_FOR_MODES(BM_Dopri5Step);
FLEXROCK_FOR_MODES(BM_EventLocation);
FLEXROCK_FOR_MODES(BM_ImpactMap);

}  // namespace
