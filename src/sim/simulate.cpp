// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/sim/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "automaton.hpp"
#include "compliant.hpp"
#include "event_location.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/sim/option_bounds.hpp"
#include "flexrock/sim/solver_keys.hpp"
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
    case EventKind::kImpactLawFallback:
      return "impact_law_fallback";
  }
  return "?";
}

const char* to_string(ContactMode m) { return detail::mode_spec(m).name; }

namespace {

// the readers and the engine refuse more samples than the engine's buffers hold
static_assert(kEventSamplesBound.hi == detail::kMaxSamples);

void check_options(const Body& body, const InitialState& init, const SimulationOptions& o) {
  // each key's own rule and scope, as the readers apply them (solver_keys.hpp); a value at its
  // default stands for "not given" (contact_restitution = -1, ...) and is not checked
  const SimulationOptions defaults;
  for (const SolverKey& k : kSolverKeys) {
    if (k.scope == SolverScope::kCaseFile) continue;  // t_end < 0: the end of the motion
    std::visit(
        [&](auto field) {
          if constexpr (!std::is_same_v<decltype(field), std::monostate>) {
            if (o.*field == defaults.*field) return;
            using T = std::remove_cvref_t<decltype(o.*field)>;
            if constexpr (std::is_arithmetic_v<T>) {
              const auto v = static_cast<double>(o.*field);
              FLEXROCK_THROW_UNLESS(solver_value_ok(k, v), std::string("options: ") + k.name +
                                                               " must be " + solver_rule_text(k) +
                                                               ", got " + format_number(v));
            }
            // the engine takes a restitution ratio under any impulsive law (the paper's and
            // rigid_body leave it unused); the readers refuse the key there
            const bool applies = k.scope == SolverScope::kRestitutionLaw
                                     ? o.contact_model == ContactModel::kImpulsive
                                     : solver_key_applies(k, o);
            if (applies) return;
            FLEXROCK_THROW_UNLESS(k.scope != SolverScope::kCompliant,
                                  std::string("options: ") + k.name +
                                      " is set, but it applies to contact_model = compliant");
            FLEXROCK_THROW_UNLESS(false, std::string("options: ") + k.name +
                                             " is set with contact_model = compliant, but " +
                                             kImpulsiveOnlyWhy);
          }
        },
        k.field);
  }
  FLEXROCK_THROW_UNLESS(o.rtol >= kMinRelativeTolerance,
                        "options: rtol = " + format_number(o.rtol) +
                            " is below what double precision can deliver; use >= 1e-14");
  FLEXROCK_THROW_UNLESS(
      std::isfinite(o.output_dt) && o.output_dt >= 0.0,
      "options: output_dt must be >= 0 (0: no time history), got " + format_number(o.output_dt));
  FLEXROCK_THROW_UNLESS(std::isfinite(o.t_end), "options: t_end must be finite");
  FLEXROCK_THROW_UNLESS(!takes_measured_ratio(o.impact_law) || o.restitution_factor == 1.0,
                        "options: restitution_factor = " + format_number(o.restitution_factor) +
                            " with impact_law = restitution: give the measured ratio as "
                            "restitution_ratio instead (the factor applies to paper and "
                            "rigid_body)");
  FLEXROCK_THROW_UNLESS(
      std::isfinite(o.methods.stiff_switch_scale) && o.methods.stiff_switch_scale > 0.0,
      "options: stiff_switch_scale must be positive and finite, got " +
          format_number(o.methods.stiff_switch_scale) +
          " (a factor on the rate where the rocking integrator switches "
          "methods; 1 by default)");
  FLEXROCK_THROW_UNLESS(
      kinetic_friction_coefficient_ok(o.kinetic_friction_coefficient, o.friction_coefficient),
      "options: kinetic_friction_coefficient (" + format_number(o.kinetic_friction_coefficient) +
          ") must be > 0 and not exceed the static friction_coefficient (" +
          format_number(o.friction_coefficient) + "), or be infinite: equal to it");
  if (o.contact_model == ContactModel::kCompliant) {
    const bool hunt_crossley = o.contact_force_law == ContactForceLaw::kHuntCrossley;
    FLEXROCK_THROW_UNLESS(std::isfinite(o.contact_stiffness) && o.contact_stiffness > 0.0,
                          "options: contact_stiffness must be positive and finite, got " +
                              format_number(o.contact_stiffness) +
                              " (N/m^p: the spring at each tipping point, e.g. 1e8 for steel on "
                              "concrete under a few tonnes)");
    FLEXROCK_THROW_UNLESS(
        !hunt_crossley || (o.contact_exponent >= 1.0 && o.contact_exponent <= 3.0),
        "options: contact_exponent must be in [1, 3] (1.5: Hertz), got " +
            format_number(o.contact_exponent));
    FLEXROCK_THROW_UNLESS(hunt_crossley || o.contact_exponent == 1.0,
                          "options: contact_exponent applies to contact_force_law = "
                          "hunt_crossley (the linear law has p = 1)");
    FLEXROCK_THROW_UNLESS(in_range(kContactForceAt1mmBound,
                                   contact_force_at_1mm(o.contact_stiffness, o.contact_exponent)),
                          "options: contact_stiffness must be in " +
                              stiffness_range_text(o.contact_exponent) + ", got " +
                              format_number(o.contact_stiffness));
    FLEXROCK_THROW_UNLESS(!hunt_crossley || o.contact_restitution > 0.0,
                          "options: contact_force_law = hunt_crossley needs contact_restitution "
                          "in (0, 1] (its damping follows from it)");
  }
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
                        "initial state: |theta| = " + format_number(std::abs(init.theta)) +
                            " rad is already past the overturning angle " + format_number(lim) +
                            " rad");
}

// the first of `values` (a column of `n` rows, or one value) that is not finite, in words. `name`
// is a view: the message is built only for a value that is not finite (a string per check, built
// and freed on every run, cost a spectrum cell more than its free rocking did)
template <class Values>
bool first_bad(const Values& values, std::string_view name, bool inf_ok, std::string& what,
               const std::vector<double>* times = nullptr) {
  for (std::size_t i = 0; i < static_cast<std::size_t>(values.size()); ++i) {
    const double v = values[static_cast<Eigen::Index>(i)];
    if (std::isfinite(v) || (inf_ok && v > 0.0)) continue;
    what = std::string(name) + " = " + format_number(v);
    if (times) {
      what += " at t = " + format_number(i < times->size() ? (*times)[i] : -1.0, 6) + " s";
    } else if (values.size() > 1) {
      what = std::string(name) + "[" + std::to_string(i) + "] = " + format_number(v);
    }
    return true;
  }
  return false;
}

// a scalar as a one-element view
struct One {
  double v;
  Eigen::Index size() const { return 1; }
  double operator[](Eigen::Index) const { return v; }
};

// a std::vector<double> indexed as the Eigen vectors are
struct Column {
  const std::vector<double>& v;
  Eigen::Index size() const { return static_cast<Eigen::Index>(v.size()); }
  double operator[](Eigen::Index i) const { return v[static_cast<std::size_t>(i)]; }
};

// the checks every run's result passes, whichever model computed it
SimulationResult checked(const Body& body, SimulationResult r) {
  // no silent physics: a balance that does not close says so
  if (!(std::abs(r.energy.residual) <= energy_residual_bound(body, r.energy.scale))) {
    r.energy_unbalanced = true;
    Event ev;
    ev.time = r.t_end;
    ev.kind = EventKind::kEnergyUnbalanced;
    ev.energy_loss = r.energy.residual;
    r.events.push_back(ev);
  }
  // no garbage reported as a result: outputs that overflowed (sizes or motions beyond double
  // precision) end the run as stopped, naming the first of them
  if (const std::string bad = non_finite_output(r); !bad.empty()) {
    const std::string why = "the results are not finite (" + bad +
                            "): the body's sizes or the base motion overflow double precision; "
                            "give them in physical sizes";
    r.message = r.status == Status::kStopped ? r.message + "; " + why : why;
    r.status = Status::kStopped;
    Event ev;
    ev.time = std::isfinite(r.t_end) ? r.t_end : 0.0;
    ev.kind = EventKind::kStopped;
    r.events.push_back(ev);
  }
  return r;
}

template <int N, int MaxN>
SimulationResult run(const Body& body, const GroundMotion& motion, const InitialState& init,
                     const SimulationOptions& opt) {
  return checked(body, detail::run_event_loop<N, MaxN>(body, motion, opt, init));
}

// fixed sizes up to FLEXROCK_FIXED_MODES modes (8; the sanitizer builds compile fewer, each size
// being minutes of compiling there), a stack-bounded size up to 16, heap beyond
template <int N>
SimulationResult run_sized(const Body& body, const GroundMotion& motion, const InitialState& init,
                           const SimulationOptions& opt) {
  if constexpr (N <= FLEXROCK_FIXED_MODES) {
    if (body.modes() == N) return run<N, N>(body, motion, init, opt);
    return run_sized<N + 1>(body, motion, init, opt);
  } else {
    if (body.modes() <= 16) return run<Eigen::Dynamic, 16>(body, motion, init, opt);
    return run<Eigen::Dynamic, Eigen::Dynamic>(body, motion, init, opt);
  }
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

std::string non_finite_output(const SimulationResult& r) {
  std::string w;
  const Extremes& x = r.extremes;
  const EnergyBalance& e = r.energy;
  auto one = [&](double v, const char* name, bool inf_ok = false) {
    return first_bad(One{v}, name, inf_ok, w);
  };
  // the final state and the time reached
  if (one(r.t_end, "t_end") || one(r.final_theta, "final theta") ||
      one(r.final_theta_dot, "final theta_dot") || one(r.final_offset, "final offset") ||
      first_bad(r.final_q, "final q", false, w) ||
      first_bad(r.final_q_dot, "final q_dot", false, w))
    return w;
  // the extremes
  if (one(x.max_theta_edge1, "max theta on edge 1") ||
      one(x.max_theta_edge2, "max theta on edge 2") || one(x.max_uplift, "max uplift") ||
      one(x.max_impulse, "max impulse") ||
      one(x.max_impact_energy_loss, "max impact energy loss") ||
      first_bad(x.max_abs_q, "max |q|", false, w) || one(x.max_base_shear, "max base shear") ||
      one(x.max_overturning_moment, "max overturning moment") ||
      one(x.max_friction_demand, "max friction demand", true) ||
      one(x.first_uplift_time, "first uplift time") || one(x.overturn_time, "overturn time") ||
      one(x.flight_time, "flight time") || one(x.max_flight_height, "max flight height") ||
      one(x.max_offset, "max offset") || one(x.sliding_time, "sliding time"))
    return w;
  // the energy balance
  if (one(e.input_work, "energy.input_work") || one(e.kinetic_change, "energy.kinetic_change") ||
      one(e.potential_change, "energy.potential_change") ||
      one(e.damping_loss, "energy.damping_loss") || one(e.impact_loss, "energy.impact_loss") ||
      one(e.chatter_loss, "energy.chatter_loss") || one(e.friction_loss, "energy.friction_loss") ||
      one(e.residual, "energy.residual") || one(e.scale, "energy.scale"))
    return w;
  // the events: the name is built only for a value that is not finite (a run has hundreds of
  // events, and naming each field of each cost more than the run's rocking steps)
  for (std::size_t i = 0; i < r.events.size(); ++i) {
    const Event& ev = r.events[i];
    // x - x is 0 for a finite x and NaN for an infinite or NaN one: one sum settles an event
    // whose fields are all finite, as nearly all are, before any field is looked at by name
    if (std::isfinite((ev.time - ev.time) + (ev.theta - ev.theta) +
                      (ev.theta_dot_before - ev.theta_dot_before) +
                      (ev.theta_dot_after - ev.theta_dot_after) +
                      (ev.energy_loss - ev.energy_loss) + (ev.impulse_x - ev.impulse_x) +
                      (ev.impulse_y - ev.impulse_y) + (ev.offset - ev.offset)) &&
        (std::isfinite(ev.friction_demand) || ev.friction_demand > 0.0))
      continue;
    // an infinite friction demand (no vertical impulse) is a result, not an overflow
    const struct {
      double v;
      const char* name;
      bool inf_ok;
    } fields[] = {{ev.time, "time", false},
                  {ev.theta, "theta", false},
                  {ev.theta_dot_before, "theta_dot_before", false},
                  {ev.theta_dot_after, "theta_dot_after", false},
                  {ev.energy_loss, "energy_loss", false},
                  {ev.impulse_x, "impulse_x", false},
                  {ev.impulse_y, "impulse_y", false},
                  {ev.friction_demand, "friction_demand", true},
                  {ev.offset, "offset", false}};
    for (const auto& f : fields) {
      if (std::isfinite(f.v) || (f.inf_ok && f.v > 0.0)) continue;
      const std::string at =
          std::string("event ") + std::to_string(i + 1) + " (" + to_string(ev.kind) + ") ";
      one(f.v, (at + f.name).c_str(), f.inf_ok);
      return w;
    }
  }
  // the time history, column by column
  const History& h = r.history;
  const std::vector<double>* t = &h.time;
  for (const auto& [col, name] :
       std::initializer_list<std::pair<const std::vector<double>*, const char*>>{
           {&h.time, "time"},
           {&h.theta, "theta"},
           {&h.theta_dot, "theta_dot"},
           {&h.base_acc_x, "base_acc_x"},
           {&h.base_acc_y, "base_acc_y"},
           {&h.reaction_x, "reaction_x"},
           {&h.reaction_y, "reaction_y"},
           {&h.resultant, "resultant"},
           {&h.kinetic, "kinetic"},
           {&h.potential, "potential"},
           {&h.input_work, "input_work"},
           {&h.damping_loss, "damping_loss"},
           {&h.impact_loss, "impact_loss"},
           {&h.offset, "offset"},
           {&h.lift, "lift"}}) {
    if (first_bad(Column{*col}, name, false, w, t)) return w.insert(0, "time history ");
  }
  if (first_bad(Column{h.friction_demand}, "time history friction_demand", true, w, t)) return w;
  // q and q_dot: `modes` values a row
  const auto m = static_cast<std::size_t>(std::max(h.modes, 1));
  for (const auto& [col, name] : {std::pair{&h.q, "q"}, std::pair{&h.q_dot, "q_dot"}}) {
    for (std::size_t i = 0; i < col->size(); ++i) {
      if (std::isfinite((*col)[i])) continue;
      w = std::string("time history ") + name + "_" + std::to_string(i % m + 1) + " = " +
          format_number((*col)[i]) +
          " at t = " + format_number(i / m < t->size() ? (*t)[i / m] : -1.0, 6) + " s";
      return w;
    }
  }
  return w;
}

SimulationResult simulate(const Body& body, const GroundMotion& motion, const InitialState& init,
                          const SimulationOptions& options) {
  check_options(body, init, options);
  if (options.contact_model == ContactModel::kCompliant)
    return checked(body, detail::simulate_compliant(body, motion, init, options));
  return run_sized<0>(body, motion, init, options);
}

}  // namespace flexrock
