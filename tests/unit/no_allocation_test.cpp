// SPDX-License-Identifier: BSD-3-Clause
// The step loop allocates nothing: a run ten times longer makes no more heap allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

// the replacements below pair malloc with free consistently; GCC cannot see that across the
// inlined gtest factory and warns of a mismatch
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace flexrock {
namespace {

long allocations_for(const Body& body, double duration, double amplitude) {
  const auto motion = GroundMotion::analytic(
      [=](double t) {
        return BaseAcceleration{amplitude * std::sin(7.0 * t), 0.0};
      },
      duration);
  SimulationOptions opt;
  const long before = g_allocations.load();
  const SimulationResult r = simulate(body, motion, {}, opt);
  EXPECT_EQ(r.extremes.impacts, 0);  // no events: only steps
  EXPECT_GT(r.steps, 100);
  return g_allocations.load() - before;
}

// the same under a sampled record, where a flexible body in full contact is propagated exactly
long allocations_for_record(const Body& body, double duration, double amplitude) {
  std::vector<double> ax;
  for (double t = 0.0; t < duration; t += 0.01) ax.push_back(amplitude * std::sin(7.0 * t));
  const auto motion = GroundMotion::uniform(0.01, ax);
  SimulationOptions opt;
  const long before = g_allocations.load();
  const SimulationResult r = simulate(body, motion, {}, opt);
  EXPECT_EQ(r.extremes.impacts, 0);
  EXPECT_GT(r.steps, 100);
  return g_allocations.load() - before;
}

TEST(InnerLoop, ExactFullContactAllocatesNothingPerStep) {
  for (int n : {1, 2, 4, 8}) {
    const Body body(uniform_cantilever(3.0, 1.0, 200.0, 2e7, n, 100.0, 0.02));
    const long short_run = allocations_for_record(body, 2.0, 0.5);
    const long long_run = allocations_for_record(body, 20.0, 0.5);
    EXPECT_EQ(long_run, short_run) << "n = " << n;
  }
}

TEST(InnerLoop, AllocatesNothingPerStepForFixedSizes) {
  for (int n : {0, 1, 2, 4, 8}) {
    const Body body(n == 0 ? rigid_block(1.0, 2.0, 100.0)
                           : uniform_cantilever(3.0, 1.0, 200.0, 2e7, n, 100.0, 0.02));
    const long short_run = allocations_for(body, 2.0, 0.5);
    const long long_run = allocations_for(body, 20.0, 0.5);
    EXPECT_EQ(long_run, short_run) << "n = " << n;
  }
}

TEST(InnerLoop, AllocatesNothingPerStepForBoundedSizes) {
  const Body body(uniform_cantilever(3.0, 1.0, 200.0, 2e7, 10, 100.0, 0.02));
  EXPECT_EQ(allocations_for(body, 10.0, 0.5), allocations_for(body, 1.0, 0.5));
}

}  // namespace
}  // namespace flexrock
