// SPDX-License-Identifier: BSD-3-Clause
// The benchmark cases of docs/performance.md (a-d), shared by the Google Benchmark binary and
// the case runner the peer comparison calls.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock::bench {

inline constexpr double kPi = std::numbers::pi;

struct Case {
  Body body;
  GroundMotion motion;
  InitialState init;
  SimulationOptions opt;
};

// the slender block of all rigid cases: b = 0.2 m, h = 1.0 m (half-width, half-height)
inline Body slender_block() { return Body(BodyParameters::rectangular_block(1000.0, 0.2, 1.0)); }

// the Kobe 1995 Nishi-Akashi 090 record, scaled to a PGA of `pga_g` [g]
inline GroundMotion kobe(double pga_g) {
  const std::string dir = std::getenv("FLEXROCK_DATA") ? std::getenv("FLEXROCK_DATA")
                                                       : FLEXROCK_SOURCE_DIR "/../shared/data";
  const io::Record r = io::read_at2(dir + "/kobe_1995_nishi_akashi_090.AT2");
  double pga = 0.0;
  for (double v : r.values) pga = std::max(pga, std::abs(v));
  return r.to_motion(pga_g / pga);
}
inline GroundMotion kobe_05g() { return kobe(0.5); }

// (a) free rocking from 0.8 alpha, 20 s
inline Case case_a(double rtol = 1e-8) {
  Body b = slender_block();
  InitialState init;
  init.theta = 0.8 * b.tipping_angle(1);  // alpha = atan(b/h)
  SimulationOptions opt;
  opt.t_end = 20.0;
  opt.max_step = 1.0;  // no record to follow: let the error control pick the step
  opt.rtol = rtol;
  opt.atol = 1e-2 * rtol;
  return {b, GroundMotion::none(20.0), init, opt};
}

// (b) at rest under a one-sine pulse with a_p = 3 g tan(alpha), 10 s
inline Case case_b(double omega_p, double rtol = 1e-8) {
  Body b = slender_block();
  const double a_p = 3.0 * b.g() * std::tan(b.tipping_angle(1));
  SimulationOptions opt;
  opt.t_end = 10.0;
  opt.rtol = rtol;
  opt.atol = 1e-2 * rtol;
  return {b, one_sine_pulse(a_p, omega_p, 10.0), InitialState{}, opt};
}

// (c) at rest under Kobe at PGA 0.5 g, full duration
inline Case case_c(double rtol = 1e-8) {
  SimulationOptions opt;
  opt.rtol = rtol;
  opt.atol = 1e-2 * rtol;
  return {slender_block(), kobe_05g(), InitialState{}, opt};
}

// (d) an elastic oscillator (2 Hz, 5 % damping) on a rocking slab, n = 1, under (c)'s record
inline Case case_d_oscillator(double rtol = 1e-8) {
  SimulationOptions opt;
  opt.rtol = rtol;
  opt.atol = 1e-2 * rtol;
  return {Body(oscillator_on_slab(1000.0, 2.0, 500.0, 2.0, 0.8, 0.05)), kobe_05g(), InitialState{},
          opt};
}

// (d) an n-mode cantilever (6 m tall, 1.2 m wide, first mode 2 Hz, 2 % damping) under (c)'s
// record; n = 0 is the same body taken as rigid (as a case file's `rigid = true` does): the cost
// against the number of modes
inline Case case_d_cantilever(int n = 4, double rtol = 1e-8) {
  SimulationOptions opt;
  opt.rtol = rtol;
  opt.atol = 1e-2 * rtol;
  BodyParameters p = uniform_cantilever(6.0, 1.2, 800.0, 1.3e7, std::max(n, 1), 2000.0, 0.02);
  if (n == 0) p = taken_rigid(p);
  return {Body(p), kobe_05g(), InitialState{}, opt};
}

// (e) stiff rocking: a slab of b/h = 0.01 (1 t, 4 m tall) carrying a 1 t oscillator of 980 Hz with
// 5 % damping, which rocks with a coupled motion near 128 kHz (docs/theory.md, "Stiff rocking"),
// under the Kobe record scaled to a PGA of 0.02 g (twice the uplift threshold g b/h): it rocks
// with impacts from 7 s on and stands at the end
inline Case case_e_stiff_slab(double rtol = 1e-8) {
  SimulationOptions opt;
  opt.rtol = rtol;
  opt.atol = 1e-2 * rtol;
  return {Body(oscillator_on_slab(1000.0, 980.0, 1000.0, 4.0, 0.04, 0.05)), kobe(0.02),
          InitialState{}, opt};
}

}  // namespace flexrock::bench
