// SPDX-License-Identifier: BSD-3-Clause
// Checks an installed flexrock::core against two closed forms for Housner's rigid block
// (half-width b, half-height h, slenderness alpha = atan(b/h)):
//  - uplift starts when the floor's acceleration reaches g b / h (Housner 1963): 1 % below it
//    the block stands, and a ramp lifts it at the instant it reaches the threshold;
//  - an impact of free rocking keeps the angular velocity ratio 1 - 3/2 sin^2(alpha) (Housner
//    1963, conservation of angular momentum about the landing corner).
// Exit 0 when both hold; prints what it found.
#include <cmath>
#include <cstdio>
#include <cstring>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/version.hpp"

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAIL", what);
  if (!ok) ++failures;
}

}  // namespace

int main() {
  using namespace flexrock;
  const double b = 0.2, h = 0.9, mass = 800.0;  // [m], [m], [kg]
  const Body body(BodyParameters::rectangular_block(mass, b, h));
  const double g = body.params().gravity;
  const double alpha = std::atan(b / h);

  // the library, the headers and the package found by CMake are one version
  std::printf("flexrock %s (headers %s, package %s)\n", version(), FLEXROCK_VERSION_STRING,
              PACKAGE_VERSION);
  check(std::strcmp(version(), FLEXROCK_VERSION_STRING) == 0 &&
            std::strcmp(version(), PACKAGE_VERSION) == 0,
        "library, header and package versions agree");

  // uplift threshold g b / h: a floor acceleration 1 % below it for 0.5 s leaves the block
  // standing; a ramp reaching it at t = 1 s lifts the block then
  const double threshold = g * b / h;
  SimulationOptions options;
  const SimulationResult below =
      simulate(body, rectangular_pulse(0.99 * threshold, 0.5, 0.5), {}, options);
  const double rate = threshold / 1.0;  // [m/s^3]
  const GroundMotion ramp = GroundMotion::analytic(
      [rate](double t) {
        return BaseAcceleration{rate * t, 0.0};
      },
      1.5);
  const SimulationResult ramped = simulate(body, ramp, {}, options);
  std::printf("uplift threshold g b/h = %.6f m/s^2: first uplift at 0.99x: %g s, ramp: %.12f s\n",
              threshold, below.extremes.first_uplift_time, ramped.extremes.first_uplift_time);
  check(below.extremes.first_uplift_time < 0.0, "no uplift 1 % below g b/h");
  check(std::abs(ramped.extremes.first_uplift_time - 1.0) < 1e-9,
        "the ramp lifts the block when it reaches g b/h (t = 1 s)");

  // free rocking from half the tipping angle: the first impact's velocity ratio
  InitialState tilted;
  tilted.theta = 0.5 * alpha;
  options.max_impacts = 1;
  const SimulationResult rocking = simulate(body, GroundMotion::none(5.0), tilted, options);
  const Event* impact = nullptr;
  for (const Event& e : rocking.events)
    if (e.kind == EventKind::kImpact) {
      impact = &e;
      break;
    }
  check(impact != nullptr, "free rocking reaches an impact");
  if (impact) {
    const double ratio = std::abs(impact->theta_dot_after / impact->theta_dot_before);
    const double housner = 1.0 - 1.5 * std::sin(alpha) * std::sin(alpha);
    std::printf("impact velocity ratio %.15f, Housner 1 - 3/2 sin^2(alpha) = %.15f\n", ratio,
                housner);
    check(std::abs(ratio - housner) < 1e-9, "impact ratio equals Housner's");
  }
  return failures == 0 ? 0 : 1;
}
