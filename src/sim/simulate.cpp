// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/sim/simulate.hpp"

#include <cmath>
#include <string>

#include "automaton.hpp"
#include "flexrock/core/error.hpp"
#include "simulator_instances.hpp"

namespace flexrock {

const char* to_string(Status s) {
  switch (s) {
    case Status::kCompleted:
      return "completed";
    case Status::kOverturned:
      return "overturned";
    case Status::kStopped:
      return "stopped";
  }
  return "?";
}

const char* to_string(EventKind k) {
  switch (k) {
    case EventKind::kUplift:
      return "uplift";
    case EventKind::kImpact:
      return "impact";
    case EventKind::kRockingEnded:
      return "rocking_ended";
    case EventKind::kChatterCutoff:
      return "chatter_cutoff";
    case EventKind::kPeak:
      return "peak";
    case EventKind::kOverturn:
      return "overturn";
    case EventKind::kLiftOff:
      return "lift_off";
    case EventKind::kLanding:
      return "landing";
    case EventKind::kTensileLanding:
      return "tensile_landing";
    case EventKind::kPivotTension:
      return "pivot_tension";
    case EventKind::kFrictionExceeded:
      return "friction_exceeded";
    case EventKind::kImpactGainedEnergy:
      return "impact_gained_energy";
    case EventKind::kStopped:
      return "stopped";
    case EventKind::kEnergyUnbalanced:
      return "energy_unbalanced";
    case EventKind::kSlipStart:
      return "slip_start";
    case EventKind::kStick:
      return "stick";
    case EventKind::kSlipReversal:
      return "slip_reversal";
  }
  return "?";
}

const char* to_string(ContactMode m) { return detail::mode_spec(m).name; }

namespace {

void check_options(const Body& body, const InitialState& init, const SimulationOptions& o) {
  auto positive = [](double v, const char* name, const char* hint) {
    FLEXROCK_THROW_UNLESS(std::isfinite(v) && v > 0.0, std::string("options: ") + name +
                                                           " must be positive and finite, got " +
                                                           std::to_string(v) + " (" + hint + ")");
  };
  positive(o.rtol, "rtol", "e.g. 1e-9");
  positive(o.atol, "atol", "e.g. 1e-11");
  positive(o.max_step, "max_step", "seconds, e.g. 0.01");
  FLEXROCK_THROW_UNLESS(o.rtol >= 1e-14,
                        "options: rtol = " + std::to_string(o.rtol) +
                            " is below what double precision can deliver; use >= 1e-14");
  FLEXROCK_THROW_UNLESS(o.event_samples >= 1 && o.event_samples <= detail::kMaxSamples,
                        "options: event_samples must be in [1, " +
                            std::to_string(detail::kMaxSamples) + "], got " +
                            std::to_string(o.event_samples));
  FLEXROCK_THROW_UNLESS(
      std::isfinite(o.output_dt) && o.output_dt >= 0.0,
      "options: output_dt must be >= 0 (0: no time history), got " + std::to_string(o.output_dt));
  FLEXROCK_THROW_UNLESS(std::isfinite(o.t_end), "options: t_end must be finite");
  FLEXROCK_THROW_UNLESS(
      std::isfinite(o.chatter_ratio) && o.chatter_ratio >= 0.0,
      "options: chatter_ratio must be >= 0, got " + std::to_string(o.chatter_ratio));
  FLEXROCK_THROW_UNLESS(
      std::isfinite(o.restitution_factor) && o.restitution_factor >= 0.0,
      "options: restitution_factor must be >= 0 (1: the paper's impact law), got " +
          std::to_string(o.restitution_factor));
  FLEXROCK_THROW_UNLESS(!(o.friction_coefficient <= 0.0) && !std::isnan(o.friction_coefficient),
                        "options: friction_coefficient must be > 0 (or infinite for none), got " +
                            std::to_string(o.friction_coefficient));
  FLEXROCK_THROW_UNLESS(
      !(o.kinetic_friction_coefficient <= 0.0) && !std::isnan(o.kinetic_friction_coefficient),
      "options: kinetic_friction_coefficient must be > 0 (or infinite: equal to "
      "the static one), got " +
          std::to_string(o.kinetic_friction_coefficient));
  FLEXROCK_THROW_UNLESS(!(o.kinetic_friction_coefficient > o.friction_coefficient) ||
                            std::isinf(o.kinetic_friction_coefficient),
                        "options: kinetic_friction_coefficient (" +
                            std::to_string(o.kinetic_friction_coefficient) +
                            ") must not exceed the static friction_coefficient (" +
                            std::to_string(o.friction_coefficient) + ")");
  FLEXROCK_THROW_UNLESS(o.max_steps > 0 && o.max_impacts > 0,
                        "options: max_steps and max_impacts must be positive");
  const int n = body.modes();
  FLEXROCK_THROW_UNLESS(init.q.size() == 0 || init.q.size() == n,
                        "initial state: q must have " + std::to_string(n) +
                            " entries (one per mode), got " + std::to_string(init.q.size()));
  FLEXROCK_THROW_UNLESS(init.q_dot.size() == 0 || init.q_dot.size() == n,
                        "initial state: q_dot must have " + std::to_string(n) +
                            " entries (one per mode), got " + std::to_string(init.q_dot.size()));
  FLEXROCK_THROW_UNLESS(std::isfinite(init.theta) && std::isfinite(init.theta_dot) &&
                            init.q.allFinite() && init.q_dot.allFinite(),
                        "initial state: values must be finite");
  const double limit = init.theta >= 0.0 ? body.tipping_angle(1) : body.tipping_angle(2);
  const double lim = o.overturn == OverturnCriterion::kHalfPi ? 1.5707963267948966 : limit;
  FLEXROCK_THROW_UNLESS(std::abs(init.theta) < lim,
                        "initial state: |theta| = " + std::to_string(std::abs(init.theta)) +
                            " rad is already past the overturning angle " + std::to_string(lim) +
                            " rad");
}

template <int N, int MaxN>
SimulationResult run(const Body& body, const GroundMotion& motion, const InitialState& init,
                     const SimulationOptions& opt) {
  detail::Simulator<N, MaxN> sim(body, motion, opt);
  SimulationResult r = sim.run(init);
  // no silent physics: a balance that does not close says so
  if (!(std::abs(r.energy.residual) <= energy_residual_bound(body, r.energy.scale))) {
    r.energy_unbalanced = true;
    Event ev;
    ev.time = r.t_end;
    ev.kind = EventKind::kEnergyUnbalanced;
    ev.energy_loss = r.energy.residual;
    r.events.push_back(ev);
  }
  return r;
}

}  // namespace

double energy_residual_bound(const Body& body, double scale) {
  const BodyParameters& p = body.params();
  return kEnergyResidualRelative * scale + kEnergyResidualFloor * p.mass * p.gravity * p.height;
}

void validate_options(const Body& body, const InitialState& init,
                      const SimulationOptions& options) {
  check_options(body, init, options);
}

SimulationResult simulate(const Body& body, const GroundMotion& motion, const InitialState& init,
                          const SimulationOptions& options) {
  check_options(body, init, options);
  // fixed sizes for the common small bodies, a stack-bounded size up to 16 modes, heap beyond
  switch (body.modes()) {
    case 0:
      return run<0, 0>(body, motion, init, options);
    case 1:
      return run<1, 1>(body, motion, init, options);
    case 2:
      return run<2, 2>(body, motion, init, options);
    case 3:
      return run<3, 3>(body, motion, init, options);
    case 4:
      return run<4, 4>(body, motion, init, options);
    default:
      if (body.modes() <= 16) return run<Eigen::Dynamic, 16>(body, motion, init, options);
      return run<Eigen::Dynamic, Eigen::Dynamic>(body, motion, init, options);
  }
}

}  // namespace flexrock
