// SPDX-License-Identifier: BSD-3-Clause
// One right-hand-side evaluation of the rocking equations for n modes.
#include <benchmark/benchmark.h>

#include "flexrock/model/builders.hpp"
#include "flexrock/model/dynamics.hpp"

namespace {

using namespace flexrock;

template <int N, int MaxN = N>
void BM_RockingAcceleration(benchmark::State& state) {
  const int n = N == Eigen::Dynamic ? static_cast<int>(state.range(0)) : N;
  const Body body(n == 0 ? rigid_block(0.4, 2.0, 1000.0)
                         : uniform_cantilever(3.0, 1.0, 500.0, 5e7, n, 200.0, 0.02));
  const Dynamics<N, MaxN> dyn(body);
  typename Dynamics<N, MaxN>::Vec q(n), qd(n), qdd(n);
  q.setConstant(1e-3);
  qd.setConstant(1e-2);
  double thdd = 0.0, theta = 0.05;
  for (auto _ : state) {
    dyn.rocking_acceleration(1, theta, q, 0.3, qd, BaseAcceleration{1.0, 0.5}, thdd, qdd);
    benchmark::DoNotOptimize(thdd);
    benchmark::DoNotOptimize(qdd.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_RockingAcceleration<0>)->Name("BM_RockingAcceleration/n:0");
BENCHMARK(BM_RockingAcceleration<1>)->Name("BM_RockingAcceleration/n:1");
BENCHMARK(BM_RockingAcceleration<2>)->Name("BM_RockingAcceleration/n:2");
BENCHMARK(BM_RockingAcceleration<4>)->Name("BM_RockingAcceleration/n:4");
BENCHMARK(BM_RockingAcceleration<8>)->Name("BM_RockingAcceleration/n:8");
BENCHMARK(BM_RockingAcceleration<Eigen::Dynamic, 16>)
    ->Name("BM_RockingAcceleration/n")
    ->Arg(8)
    ->Arg(10);

}  // namespace
