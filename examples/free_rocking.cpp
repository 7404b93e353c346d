// Housner's block released from a tilt, then the same block under a one-sine pulse.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "flexrock/sim/simulate.hpp"

int main() {
  using namespace flexrock;
  const Body block(BodyParameters::rectangular_block(1000.0, 0.2, 1.0));
  SimulationOptions opt;
  opt.t_end = 5.0;
  InitialState init;
  init.theta = 0.8 * block.alpha1();
  const SimulationResult r = simulate(block, GroundMotion::none(opt.t_end), init, opt);
  std::printf("free rocking: %s, %ld impacts, energy lost %.3f J, residual %.2e J\n",
              to_string(r.status), r.extremes.impacts, r.energy.impact_loss, r.energy.residual);
  return 0;
}
