// SPDX-License-Identifier: BSD-3-Clause
// The cost of a rigid block on a linear support (docs/theory.md §24) against the same block on the
// rigid floor: bench case (c), the slender block under Kobe at 0.5 g, at the engine's default
// tolerances and at case (c)'s. Medians of the process's CPU time over repeated runs (the machine
// may be shared: wall time would measure the neighbours).
//   flexrock_support_cost [repeats = 21]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "cases.hpp"
#include "flexrock/sim/support.hpp"

using namespace flexrock;

namespace {

template <class F>
double median_seconds(int repeats, F&& run) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    timespec a{}, b{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &a);
    run();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &b);
    t.push_back(static_cast<double>(b.tv_sec - a.tv_sec) +
                1e-9 * static_cast<double>(b.tv_nsec - a.tv_nsec));
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 21;
  for (const double rtol : {1e-9, 1e-8}) {
    const bench::Case c = bench::case_c(rtol);
    SimulationOptions opt = c.opt;
    if (rtol == 1e-9) opt = SimulationOptions{};  // the engine's defaults
    SimulationResult floor;
    const double t_floor =
        median_seconds(repeats, [&] { floor = simulate(c.body, c.motion, c.init, opt); });
    std::printf("rtol %g: rigid floor: %.3f ms (%s, %ld impacts, %ld steps)\n", opt.rtol,
                1e3 * t_floor, to_string(floor.status), floor.extremes.impacts, floor.steps);
    for (const double f : {0.5, 1.0, 3.0, 10.0, 30.0}) {
      const SupportParameters s =
          SupportParameters::from_frequency(1000.0, c.body.params().mass, f, 0.05);
      SupportRunResult r;
      const double t =
          median_seconds(repeats, [&] { r = simulate(c.body, s, c.motion, c.init, opt); });
      std::printf(
          "  support m_s = M, %5.1f Hz, zeta 0.05: %8.3f ms = %5.2f x the floor (%s, %ld impacts, "
          "%ld steps, max |u| %.4g m)\n",
          f, 1e3 * t, t / t_floor, to_string(r.body.status), r.body.extremes.impacts, r.body.steps,
          r.support.max_displacement);
    }
  }
  return 0;
}
