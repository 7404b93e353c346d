// SPDX-License-Identifier: BSD-3-Clause
// The event loop as a hybrid automaton: the loop integrates the current contact mode, locates the
// earliest guard crossing and applies its reset. Which modes exist and which guard leads where is
// the table in automaton.hpp (docs/theory.md, "Contact modes and transitions"); the modes'
// equations, guards and observation are one unit, ModeEquations (mode_equations.hpp), which every
// stepper calls; event location and recording are ordinary code (event_location.cpp,
// recorder.cpp). This file holds the loop's class; its members are defined in the parts included
// at the end: the loop, its dispatch to the steppers and its outputs (event_loop.hpp,
// steppers.hpp), a rigid body's steppers (rigid_steppers.hpp), a flexible body's record walk
// (record_walk.hpp) and the resets (resets.hpp). Internal header; the entry points are
// instantiated in simulator_n*.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <type_traits>
#include <variant>

#include "automaton.hpp"
#include "contact_propagator.hpp"
#include "event_location.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/core/sin_cos.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/integrate/stiff_switching.hpp"
#include "flexrock/model/dynamics.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/sim/step_cost.hpp"
#include "free_rocking_arc.hpp"
#include "mode_equations.hpp"
#include "recorder.hpp"
#include "rocking_series.hpp"
#include "series_guards.hpp"
#include "simulator_instances.hpp"
#include "step_extremes.hpp"
#include "steppers.hpp"

namespace flexrock::detail {

// a number for a message: 6 significant digits, no trailing zeros (std::to_string prints 1e-13 as
// "0.000000")
inline std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A landing is tensile (the sticking corner would need the floor to pull) when its vertical
// impulse is below -kTensileRounding M (|v_c-| + |v_c+|): beyond the rounding of M (v+ - v-). On
// bench/pulls_grid the grazing landings, whose impulse vanishes, left at most 2e-12 N s of either
// sign, and the smallest tensile impulse beyond this bound was 7e-5 N s
inline constexpr double kTensileRounding = 1e-12;

// The stepper interface the loop uses (Dopri5 and ContactPropagator both provide it):
//   step(sys, t_stop) -> Status       one accepted step from t1() toward t_stop (ends on it)
//   restep_to(sys, t)                 redo the last step from t0() to t (an event time)
//   dense(t, x)                       the state at t in [t0(), t1()]
//   refresh_derivative(sys, t)        restart from the right-hand limit of a jump at t
//   t0(), t1(), x0(), x1()            the last step's ends

template <int N, int MaxN>
class Simulator final : private GuardProbe {
 public:
  using Eq = ModeEquations<N, MaxN>;
  using Dyn = typename Eq::Dyn;
  using Vec = typename Eq::Vec;
  using Mat = typename Eq::Mat;
  using State = typename Eq::State;
  using ContactState = typename Eq::ContactState;
  using FlightState = typename Eq::FlightState;
  using SlideState = typename Eq::SlideState;
  template <ContactMode M, Guard G>
  static constexpr std::size_t kSlot = Eq::template kSlot<M, G>;

  Simulator(const Body& body, const GroundMotion& motion, const SimulationOptions& opt);
  SimulationResult run(const InitialState& init);

 private:
  // the steppers step through the loop's equations, guards and recorder (steppers.hpp)
  template <class>
  friend struct StillStepper;
  template <int, int, class>
  friend struct ExactStepper;
  template <class>
  friend struct SeriesStepper;
  template <class>
  friend struct ArcStepper;
  template <class>
  friend struct RockingStepper;
  template <class, int>
  friend struct OdeStepper;

  // ---- state layout and the current mode (the equations')
  int iq() const { return eq_.iq(); }
  int ithd() const { return eq_.ithd(); }
  int iqd() const { return eq_.iqd(); }
  int iw() const { return eq_.iw(); }
  int id() const { return eq_.id(); }
  int ixc() const { return eq_.ixc(); }
  int isd() const { return eq_.isd(); }
  int isv() const { return eq_.isv(); }
  int ifr() const { return eq_.ifr(); }
  int edge() const { return eq_.edge(); }
  bool rocking() const { return eq_.rocking(); }
  bool full_contact() const { return eq_.full_contact(); }
  bool flying() const { return eq_.flying(); }
  int slip() const { return eq_.slip(); }
  bool sliding() const { return eq_.sliding(); }
  template <class X>
  void put(const X& from, State& to) const {
    eq_.put(from, to);
  }

  double guard_value(int slot, double t) override;
  double crossing(int slot, double tl, double tr, double gl, double gr) override;

  // ---- the loop
  // Same-instant transitions are a loop, not a recursion: a reset changes the mode and asks for
  // its entry (request_entry), and enter_mode starts the new mode, whose entry state may call for
  // another reset at once, until none does. The chain is bounded: more than kSameInstantEntries
  // entries within 1e-9 s of each other stop the run (Zeno behaviour).
  static constexpr int kSameInstantEntries = 64;
  bool enter_mode(double t, State& x);
  bool start_mode(double t, State& x);  // one entry: the mode's stepper, then its guards at t
  bool request_entry() {
    latch_.entry_pending = true;
    return true;
  }
  void configure_rocking_integrator();
  bool advance(double& t, State& x);
  // the steppers' starts and steps (steppers.hpp calls them through the dispatch)
  // inlined into the mode's entry, as choose_stepper: out of line, the two calls per impact cost
  // a rigid block's run 1.6 % more instructions (bench case (a), callgrind)
  [[gnu::always_inline]] inline void start_series(double t, const State& x) requires(N == 0);
  void start_rocking(double t, const State& x);
  template <class Ode>
  void start_ode(Ode& ode, double t, const State& x);
  template <class Ode>
  StepEnd advance_ode(Ode& ode, double& t, State& x);
  template <class Ode>
  auto ode_rhs(Ode& ode);
  StepEnd advance_rocking(double& t, State& x);
  StepEnd advance_exact(double& t, State& x) requires(N != 0);
  StepEnd advance_series_step(double& t, State& x) requires(N == 0);
  // `buf`: scratch for the stepper's dense output (a vector of the stepper's state)
  template <class Stepper, class System, class Buffer>
  StepEnd advance_with(Stepper& integ, System&& sys, Buffer& buf, double& t, State& x);
  template <class Stepper, class System>
  StepEnd end_step(Stepper& integ, System&& sys, int slot_hit, double t_hit,
                   const GuardSample& s_end, double& t, State& x);
  StepEnd advance_still(double& t, State& x) requires(N == 0);
  // a rigid body's rocking by its series with the guards bounded over the whole step
  bool series_bounded() const requires(N == 0);
  StepEnd advance_series(double& t, State& x) requires(N == 0);
  // a rigid body rocking freely on a floor at rest, by its closed form (arc_): true where it
  // applies at (t, x) and the arc has started
  bool start_arc(double t, const ContactState& x) requires(N == 0);
  StepEnd advance_arc(double& t, State& x) requires(N == 0);
  // the shear's, the moment's and the friction demand's extremes over the arc's last step
  void arc_extremes(double t0, double t1) requires(N == 0);
  // the series' reaction polynomials series_.sp_fi, series_.sp_fj, series_.sp_moment on a step of
  // length h
  void reaction_polynomials(double h) requires(N == 0);
  // `reaction`: whether reaction_polynomials ran on this step (it runs here where needed)
  // `range`: the reaction's enclosure over the whole step
  void series_extremes(double t0, double tau_end, bool event, const ReactionRange& range,
                       bool& reaction) requires(N == 0);
  // counts a step toward max_steps: false (the run stops) past them
  bool count_step(double t);
  // the stepper could not take a step from t: the run stops, saying why
  bool step_collapsed(double t);
  double scan_record(double t) requires(N == 0);
  bool can_walk(double t) const requires(N != 0);
  bool advance_walk(double& t, State& x) requires(N != 0);
  using Excursion = typename ContactPropagator<N, MaxN, State>::Excursion;
  Excursion walk_excursion(double w) const requires(N != 0);
  bool guards_clear(const GuardSample& sa, const GuardSample& sb, const Excursion& e) const
      requires(N != 0);
  bool walk_quiet(double ax, double ay0, double ay1) const requires(N != 0);
  struct ReactionReach {
    bool shear = false, moment = false, demand = false;
    bool pull = false;  // the floor's pull on a held pivot (latch_.tension)
  };
  ReactionReach reaction_reach(double fi_top, double moment_top, double fj_lo, double fj_hi) const;
  int walk_search(double tp0, double a, double b, const GuardSample& sa, const GuardSample& sb,
                  int depth, double& a_out, double& b_out) requires(N != 0);
  void emit_walk_rows(double tp0, double tp1) requires(N != 0);
  void locate_extremes(double tp0, double h, const GuardSample& sa, const GuardSample& sb,
                       const Excursion& e) requires(N != 0);
  template <class Jet>
  double largest_near(Jet&& jet, double tau, double lo, double hi);
  // the quantities of locate_extremes at the last step's observed point p (time t, guards s, u the
  // deformation there), into points_.t and points_.vals
  void keep_point(int p, double t, const GuardSample& s, const Vec& u);
  // the extremes of those quantities between the step's observed points 0..points-1, located
  // where the parabola through three neighbouring points peaks above the extreme so far
  void locate_step_extremes(int points);
  double step_quantity(int k, double t);  // quantity k at t within the last step
  // quantity k of locate_extremes at a point: |u_k| (k < n) from its state x, else from its guards
  double point_quantity(int k, const GuardSample& s, const State& x) const;
  // |F_I|/F_J where the floor presses with at least kPressingFraction of the weight, else 0
  static double friction_demand(const GuardSample& s) {
    return detail::friction_demand(s.fi, s.fj);
  }
  std::array<double, 3> guard_jet(int k, double tau) requires(N != 0);
  bool step_guards(int samples, double t1, double& t_hit, int& slot_hit);
  void state_at(double t, State& out) const;

  // ---- resets (the automaton's edges)
  bool fire(int slot, double t, State& x);
  bool uplift(double t, State& x, int e);
  bool impact(double t, State& x);
  bool lift_off(double t, State& x);
  bool land(double t, State& x, int e);
  bool overturned(double t, State& x);
  // `momentum` [N s]: M (|v_c| before + after), the scale of the impulse's rounding
  bool after_impulse(double t, const Event& ev, double th, double momentum);
  bool start_slip(double t, State& x);
  // an uplift onto e from sticking full contact at t (state in the equations' scratch) has a
  // continuation: the pivot's friction holds, or with the pivot sliding the body still turns up
  // (theory §20)
  bool uplift_holds(double t, int e);
  bool stick(double t, State& x);
  // the mode changes to m at t: the slip's bookkeeping (offset, time sliding)
  void switch_mode(ContactMode m, double t, State& x);
  // the plastic impact with Coulomb friction (theory §19) of the case `c` at the c.g. velocity
  // v_c, recorded as `kind`; false when the run ends
  bool impact_with_friction(double t, State& x, const CornerImpactCase& c,
                            const Eigen::Vector2d& v_c, EventKind kind);
  // rigid_body would have added energy at t: the paper's law takes the impact, said in an event
  void law_fallback(double t, int e);
  bool stop(double t, std::string why);
  void record(double t);                                     // a peak
  void record_sample(const GuardSample& s, const State& x);  // a peak evaluated at s.t
  void count_impact(const Event& ev, double impulse_y, double loss, bool chatter);
  // after a step with no event: a pressing floor ends the pivot-tension hold
  void release_latches(const GuardSample& s) {
    latch_.hold_tension = false;
    const int lift = guard_slot(eq_.mode, Guard::kLiftOff);
    if (lift >= 0 && s.v[static_cast<std::size_t>(lift)] > 0.0) latch_.tension = false;
  }
  // an event at t on edge `e` (0: none) with the base centre's offset in contact
  Event make_event(double t, EventKind kind, int e) const {
    Event ev;
    ev.time = t;
    ev.kind = kind;
    ev.edge = e;
    ev.offset = ledger_.offset;
    return ev;
  }

  // ---- outputs
  double offset_of(const State& x) { return eq_.offset_of(x, ledger_.offset); }
  void observe(const GuardSample& s, const State& x) {
    rec_.observe(eq_.observation(s.t, x, s, ledger_.offset));
    if (s.fj < 0.0 && latch_.tension) fold_pull(s.fj);
  }
  // the floor pulls on a held pivot (F_J over M g, < 0): into the run's largest pull and the
  // episode's pivot_tension event
  void fold_pull(double fj) {
    const double f = fj * eq_.dyn.mass() * eq_.dyn.g();
    res_.extremes.max_pivot_pull = std::max(res_.extremes.max_pivot_pull, -f);
    if (latch_.tension_event >= 0) {
      Event& ev = res_.events[static_cast<std::size_t>(latch_.tension_event)];
      ev.force_estimate = std::min(ev.force_estimate, f);
    }
  }
  // the pull of a sample while the pivot is held (over M g, >= 0): a located quantity
  double pull_of(const GuardSample& s) const { return latch_.tension && s.fj < 0.0 ? -s.fj : 0.0; }
  // the state at t within the last step, evaluated and observed (an extreme located there)
  void observe_at(double t) {
    GuardSample s;
    state_at(t, scratch_.xr);
    eq_.evaluate(t, scratch_.xr, s);
    observe(s, scratch_.xr);
  }
  void emit_rows_until(double t_cut);
  void emit_row(double t, const State& x);
  void finish(double t, const State& x);

  // the body in its pinned-base modal coordinates q, which the state carries; the deformation
  // it reports is the given body's, u = Phi q (docs/theory.md, "Modal coordinates")
  const Body body_;
  Mat from_user_;  // Phi^-1 = Phi^T mu
  // the modes' equations, guards and observation, and the current mode: every stepper's one way
  // to them
  Eq eq_;
  SimulationOptions opt_;
  int n_;
  StepControl ctl_;
  int samples_ = 4;
  SimulationResult res_;
  Recorder rec_;
  // what steps the current mode's motion, chosen once in enter_mode (steppers.hpp): a loop holds
  // the steppers its body size can run, and no other
  using Rocking = RockingStepper<ContactState>;
  using Flight = OdeStepper<FlightState, 0>;
  using Slide = OdeStepper<SlideState, 1>;
  using Still = std::conditional_t<N == 0, StillStepper<State>, AbsentStepper>;
  using Series = std::conditional_t<N == 0, SeriesStepper<ContactState>, AbsentStepper>;
  using Arc = std::conditional_t<N == 0, ArcStepper<ContactState>, AbsentStepper>;
  using Exact = std::conditional_t<N == 0, AbsentStepper, ExactStepper<N, MaxN, State>>;
  using ActiveStepper =
      std::conditional_t<N == 0, std::variant<Still*, Series*, Arc*, Rocking*, Flight*, Slide*>,
                         std::variant<Exact*, Rocking*, Flight*, Slide*>>;
  Rocking rocking_;
  Flight flight_;
  Slide slide_;
  [[no_unique_address]] Still still_;
  [[no_unique_address]] Series series_;
  [[no_unique_address]] Arc arc_;
  [[no_unique_address]] Exact exact_;
  ActiveStepper stepper_;
  // the one dispatch to the current mode's stepper
  template <class F>
  decltype(auto) on_stepper(F&& f) {
    return std::visit([&](auto* s) -> decltype(auto) { return f(*s); }, stepper_);
  }
  template <class F>
  decltype(auto) on_stepper(F&& f) const {
    return std::visit([&](const auto* s) -> decltype(auto) { return f(*s); }, stepper_);
  }
  [[gnu::always_inline]] inline ActiveStepper choose_stepper();  // see start_series
  double stepped_until() const;  // [s] the end of the last step taken (of the still span)
  struct Scratch {
    State xr;  // a state within the last step (sized once)
  } scratch_;
  GuardSample s0_;  // the guards at the current step's start
  // the guards and states at a step's samples, and the step's observed points (its start, its
  // samples before any event, the event) with the quantities of locate_extremes there (|u_j|,
  // |F_I|, |moment|, friction demand, pull)
  static constexpr int NQ = N == Eigen::Dynamic ? Eigen::Dynamic : N + 4;
  static constexpr int MaxNQ = MaxN == Eigen::Dynamic ? Eigen::Dynamic : MaxN + 4;
  using Quantities = Eigen::Array<double, NQ, 1, Eigen::ColMajor, MaxNQ, 1>;
  struct StepPoints {
    std::array<GuardSample, kMaxSamples + 1> samples;  // guards at this step's samples
    std::array<State, kMaxSamples + 1> states;         // the states there (sized once)
    std::array<double, kMaxSamples + 2> t{};
    std::array<Quantities, kMaxSamples + 2> vals;
    std::array<bool, kMaxSamples + 2> pressing{};  // F_J >= kPressingFraction at the points
    std::array<double, kMaxSamples + 2> fj{};      // F_J over M g at the points
    Quantities extreme;                            // scratch: the extremes so far, same units
  } points_;
  // where the record scans (the still path and the walk) have got to
  struct RecordScan {
    std::size_t index = 0;  // the record sample the last scan stopped at
    double from = 0.0;      // [s] the last sample the scan passed with no event
  } scan_;
  // [s] the stepped propagation's next step ends here: a bracket the walk found a crossing in
  double step_stop_ = std::numeric_limits<double>::infinity();
  // what the run derives once from the body, the options and the motion
  struct Setup {
    ImpactRule rule;                // the impact law and its parameters
    double chatter_interval = 0.0;  // [s]
    double t_end = 0.0;             // [s]
  } setup_;
  // the latches: what a mode's entry or a reset leaves for the steps after it
  struct Latches {
    std::array<bool, kMaxGuards> zero_start{};  // guards known to turn positive from zero
    bool tension = false;     // the floor pulls (pivot_tension): lift-off disarmed until it presses
    long tension_event = -1;  // the index of the episode's pivot_tension event (-1: none)
    // after a grazing landing with friction the floor is let pull through the modes entered at
    // that instant (a slip that starts where the pivot force vanishes) until a step ends: else the
    // body would lift off and land again without end
    bool hold_tension = false;
    bool suppress_uplift_at_start = false;
    // a slide that could not grow ended where it began, the margin m_s = 0 to rounding (a tie):
    // the sticking mode's friction limit starts at zero, whatever the sign its rounding gives
    bool friction_tie = false;
    bool entry_pending = false;  // a reset changed the mode at t: enter_mode starts it next
  } latch_;
  // the run's account: where the base is, when contact last changed, the energies, the outputs
  struct Ledger {
    double offset = 0.0;       // [m] horizontal offset of the base centre while in contact
    double slide_start = 0.0;  // [s] when the current slide began
    double last_contact_change = 0.0;
    double flight_start = 0.0;
    long next_output = 0;
    double energy0 = 0.0, kinetic0 = 0.0;
    double impact_loss = 0.0, chatter_loss = 0.0;
    double zeno_time = -1.0;
    int same_time_events = 0;
  } ledger_;
};

template <int N, int MaxN>
Simulator<N, MaxN>::Simulator(const Body& body, const GroundMotion& motion,
                              const SimulationOptions& opt)
    : body_(body.in_modal_coordinates()),
      from_user_(body.pinned_base_modes().transpose() * body.params().mu),
      eq_(body_, body, motion, opt),
      opt_(opt),
      n_(body.modes()),
      samples_(std::clamp(opt.event_samples, 1, kMaxSamples)),
      rec_(res_, body.params().mass, body.g(), body.params().height, body.modes()),
      series_(motion),
      exact_(eq_.dyn, motion, samples_, opt.max_step, opt.methods.exact_full_contact) {
  setup_.rule.law = opt.impact_law;
  setup_.rule.restitution_factor = opt.restitution_factor;
  setup_.rule.ratio_edge1 = opt.restitution_ratio_edge1;
  setup_.rule.ratio_edge2 = opt.restitution_ratio_edge2;
  // shortest period among the pinned-base modes and the rigid rocking motion
  double shortest = 2.0 * std::numbers::pi / body.rocking_frequency();
  if (n_ > 0)
    shortest = std::min(shortest, 2.0 * std::numbers::pi / body.natural_frequencies().maxCoeff());
  setup_.chatter_interval = opt.chatter_ratio * shortest;
  ctl_.rtol = opt.rtol;
  ctl_.atol = opt.atol;
  ctl_.max_step = opt.max_step;
  for (State& xk : points_.states) xk.setZero(2 * n_ + 11);
  rocking_.buf.setZero(2 * n_ + 4);
  if constexpr (N == 0) {
    series_.buf.setZero(2 * n_ + 4);
    arc_.buf.setZero(2 * n_ + 4);
  }
  slide_.buf.setZero(2 * n_ + 7);
  scratch_.xr.setZero(2 * n_ + 11);  // written through put(): sized once, as on the heap path
  flight_.buf.setZero(2 * n_ + 8);
  if constexpr (N != 0) {
    exact_.prop.output_basis(eq_.to_user);
    exact_.ua.resize(n_);
    exact_.ub.resize(n_);
    for (Vec& v : exact_.qjet) v.setZero(n_);
    exact_.buf.setZero(2 * n_ + 11);
    exact_.xw.setZero(2 * n_ + 11);
    exact_.xe.setZero(2 * n_ + 11);
    exact_.wanted.assign(static_cast<std::size_t>(n_ + 4), 0);
    exact_.best.assign(static_cast<std::size_t>(n_ + 4), 0.0);
    exact_.best_at.assign(static_cast<std::size_t>(n_ + 4), 0.0);
  }
  for (Quantities& v : points_.vals) v.setZero(n_ + 4);
  points_.extreme.setZero(n_ + 4);
}

template <int N, int MaxN>
SimulationResult Simulator<N, MaxN>::run(const InitialState& init) {
  State x(2 * n_ + 11);
  x.setZero();
  x(0) = init.theta;
  x(ithd()) = init.theta_dot;
  x.segment(iq(), n_) =
      init.q.size() == n_ ? Vec(from_user_ * init.q) : Vec(body_.static_deformation());
  if (init.q_dot.size() == n_) x.segment(iqd(), n_) = from_user_ * init.q_dot;
  if (init.theta > 0.0 || (init.theta == 0.0 && init.theta_dot > 0.0)) {
    eq_.mode = ContactMode::kRockingEdge1;
  } else if (init.theta < 0.0 || init.theta_dot < 0.0) {
    eq_.mode = ContactMode::kRockingEdge2;
  }
  setup_.t_end = opt_.t_end >= 0.0 ? opt_.t_end : eq_.motion.duration();
  ledger_.energy0 = eq_.kinetic_energy(x) + eq_.potential_energy(x);
  ledger_.kinetic0 = eq_.kinetic_energy(x);
  ledger_.last_contact_change = -std::numeric_limits<double>::infinity();

  // a rocking run records two events an impact (the impact, the next peak): room for the first
  // 32 impacts spares the run the vector's first six reallocations
  res_.events.reserve(64);
  double t = 0.0;
  bool running = enter_mode(t, x);
  if (opt_.output_dt > 0.0) emit_row(t, x);
  ledger_.next_output = 1;
  while (running && t < setup_.t_end) {
    running = advance(t, x);
    if (running && latch_.entry_pending)
      running = enter_mode(t, x);  // an event fired: its new mode
  }
  finish(t, x);
  return std::move(res_);
}

}  // namespace flexrock::detail

// the members, by part
#include "event_loop.hpp"      // IWYU pragma: keep
#include "record_walk.hpp"     // IWYU pragma: keep
#include "resets.hpp"          // IWYU pragma: keep
#include "rigid_steppers.hpp"  // IWYU pragma: keep

namespace flexrock::detail {

// the entry point each size's file instantiates (simulator_instances.hpp)
template <int N, int MaxN>
SimulationResult run_event_loop(const Body& body, const GroundMotion& motion,
                                const SimulationOptions& opt, const InitialState& init) {
  Simulator<N, MaxN> sim(body, motion, opt);
  return sim.run(init);
}

}  // namespace flexrock::detail
