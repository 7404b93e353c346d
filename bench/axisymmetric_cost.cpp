// SPDX-License-Identifier: BSD-3-Clause
// The cost of a body of revolution in 3D next to the planar rigid block on the same record
// (docs/theory.md §27): `flexrock_axisymmetric_cost BLOCK.toml CYLINDER.toml [REPEATS]`, where
// BLOCK.toml is a rigid_block with a record pair and azimuth_deg = 0 (it runs H1) and
// CYLINDER.toml the cylinder under the same pair. Prints the engine's time per run of each (the
// records read once, no outputs), the planar section of the cylinder under H1 alone, and the ratio.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "flexrock/io/case_file.hpp"
#include "flexrock/io/rim_outputs.hpp"
#include "flexrock/sim/axisymmetric.hpp"

using namespace flexrock;

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s BLOCK.toml CYLINDER.toml [REPEATS]\n", argv[0]);
    return 2;
  }
  const io::Case blk = io::load_case(argv[1]);
  const io::Case cyl = io::load_case(argv[2]);
  if (!cyl.body3d || !cyl.pair) {
    std::fprintf(stderr, "%s: expected a body of revolution with a record pair\n", argv[2]);
    return 2;
  }
  const int n = argc > 3 ? std::atoi(argv[3]) : 20;
  using Clock = std::chrono::steady_clock;
  auto ms = [n](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count() / n * 1e3;
  };
  SimulationOptions po = blk.options;
  po.output_dt = 0.0;
  const Body block(blk.body);
  SimulationResult p;
  const auto t0 = Clock::now();
  for (int i = 0; i < n; ++i) p = simulate(block, blk.motion, blk.initial, po);
  const auto t1 = Clock::now();
  const io::PairMotions m = io::pair_motions(cyl);
  RimOptions o;
  o.rtol = cyl.options.rtol;
  o.atol = cyl.options.atol;
  o.max_step = cyl.options.max_step;
  o.overturn = cyl.options.overturn;
  RimResult r;
  const auto t2 = Clock::now();
  for (int i = 0; i < n; ++i) r = simulate_axisymmetric(*cyl.body3d, {&m.h1, &m.h2}, {}, o);
  const auto t3 = Clock::now();
  const Body section(cyl.body);
  SimulationOptions so = cyl.options;
  so.output_dt = 0.0;
  SimulationResult s;
  const auto t4 = Clock::now();
  for (int i = 0; i < n; ++i) s = simulate(section, m.h1, {}, so);
  const auto t5 = Clock::now();
  std::printf(
      "planar block %.3f ms (%ld steps, %s) | planar section under H1 %.3f ms (%s) | 3D cylinder "
      "%.3f ms (%ld steps, %ld rhs, %s, %ld uplifts, %ld landings) | 3D / block %.1f\n",
      ms(t0, t1), p.steps, to_string(p.status), ms(t4, t5), to_string(s.status), ms(t2, t3),
      r.steps, r.rhs_evaluations, to_string(r.status), r.uplifts, r.landings,
      ms(t2, t3) / ms(t0, t1));
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
