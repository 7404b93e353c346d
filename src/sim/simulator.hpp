// SPDX-License-Identifier: BSD-3-Clause
// The event loop as a hybrid automaton: each contact mode's equations of motion and guard
// functions, the reset maps between modes, and the loop that integrates the current mode, locates
// the earliest guard crossing and applies its reset. Which modes exist and which guard leads where
// is the table in automaton.hpp (docs/theory.md, "Contact modes and transitions"); event location
// and recording are ordinary code (event_location.cpp, recorder.cpp). Internal header; explicit
// instantiations in simulator_n*.cpp.
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
#include "recorder.hpp"
#include "rocking_series.hpp"
#include "series_guards.hpp"
#include "step_extremes.hpp"

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
  static constexpr int S = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N + 11;
  static constexpr int MaxS = MaxN == Eigen::Dynamic ? Eigen::Dynamic : 2 * MaxN + 11;
  static constexpr int SC = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N + 4;
  static constexpr int MaxSC = MaxN == Eigen::Dynamic ? Eigen::Dynamic : 2 * MaxN + 4;
  static constexpr int SF = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N + 8;
  static constexpr int MaxSF = MaxN == Eigen::Dynamic ? Eigen::Dynamic : 2 * MaxN + 8;
  static constexpr int SL = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N + 7;
  static constexpr int MaxSL = MaxN == Eigen::Dynamic ? Eigen::Dynamic : 2 * MaxN + 7;
  using Dyn = Dynamics<N, MaxN>;
  using Vec = typename Dyn::Vec;
  using Mat = typename Dyn::Mat;
  // theta, q[n], theta_dot, q_dot[n], input work, damping loss, then the flight coordinates x_c,
  // y_c, xc_dot, yc_dot of the c.g. relative to the base (in flight only), then the slip d, d_dot
  // of the base and the friction work (theory §18; d and d_dot meaningful while sliding)
  using State = Eigen::Matrix<double, S, 1, Eigen::ColMajor, MaxS, 1>;
  // the first 2n + 4 entries of State, which is all the contact modes integrate: a rocking step
  // on it costs markedly less than on the whole State
  using ContactState = Eigen::Matrix<double, SC, 1, Eigen::ColMajor, MaxSC, 1>;
  // the first 2n + 8 entries of State: what flight integrates (the slip's entries mean nothing
  // there, and a flight step on them alone costs less)
  using FlightState = Eigen::Matrix<double, SF, 1, Eigen::ColMajor, MaxSF, 1>;
  // what the sliding modes integrate: the first 2n + 4 entries of State, then d, d_dot and the
  // friction work
  using SlideState = Eigen::Matrix<double, SL, 1, Eigen::ColMajor, MaxSL, 1>;
  // slot of guard G in mode M's list (the automaton table), as a compile-time constant
  template <ContactMode M, Guard G>
  static constexpr std::size_t kSlot = [] {
    constexpr int j = guard_slot(M, G);
    static_assert(j >= 0, "the mode does not watch this guard");
    return static_cast<std::size_t>(j);
  }();

  Simulator(const Body& body, const GroundMotion& motion, const SimulationOptions& opt);
  SimulationResult run(const InitialState& init);

 private:
  // ---- state layout
  int iq() const { return 1; }
  int ithd() const { return n_ + 1; }
  int iqd() const { return n_ + 2; }
  int iw() const { return 2 * n_ + 2; }
  int id() const { return 2 * n_ + 3; }
  int ixc() const { return 2 * n_ + 4; }   // x_c, y_c, then their rates
  int isd() const { return 2 * n_ + 8; }   // d [m]: the base's slip along I
  int isv() const { return 2 * n_ + 9; }   // d_dot [m/s]
  int ifr() const { return 2 * n_ + 10; }  // friction work while sliding [J]
  // the same three in a SlideState, after its first 2n + 4 entries
  int jsd() const { return 2 * n_ + 4; }
  // the current mode's pivot and slip (the automaton table)
  int edge() const { return mode_spec(mode_).pivot == 2 ? 2 : 1; }
  bool rocking() const { return mode_spec(mode_).pivot > 0; }
  bool full_contact() const { return mode_spec(mode_).pivot == 0; }
  bool flying() const { return mode_ == ContactMode::kFlight; }
  int slip() const { return mode_spec(mode_).slip; }
  bool sliding() const { return mode_spec(mode_).slip != 0; }
  template <class X>
  Eigen::Vector2d cg_velocity(const X& x) const {
    return {x(ixc() + 2), x(ixc() + 3)};
  }

  template <class X>
  void unpack(const X& x) {
    q_ = x.segment(iq(), n_);
    qd_ = x.segment(iqd(), n_);
  }
  // a stepper's state into a State: contact and flight states are its head; a slide state is its
  // head of 2n + 4 and the slip's three entries
  template <class X>
  void put(const X& from, State& to) const {
    if constexpr (X::RowsAtCompileTime != Eigen::Dynamic) {
      if constexpr (X::RowsAtCompileTime == SL) {
        to.template head<SC>() = from.template head<SC>();
        to.template segment<3>(isd()) = from.template tail<3>();
      } else {
        to.template head<X::RowsAtCompileTime>() = from;
      }
    } else if (from.size() == 2 * n_ + 7) {
      to.head(2 * n_ + 4) = from.head(2 * n_ + 4);
      to.segment(isd(), 3) = from.tail(3);
    } else {
      to.head(from.size()) = from;
    }
  }

  // ---- equations of motion: full contact and rocking, and flight
  void contact_rhs(double t, const ContactState& x, ContactState& dx);
  void flight_rhs(double t, const FlightState& x, FlightState& dx);
  void slide_rhs(double t, const SlideState& x, SlideState& dx);
  // d_ddot [m/s^2] of the current sliding mode at (q_, qd_), with theta_ddot, q_ddot (in qdd_) and
  // the reaction over M g; a' = a + d_ddot I is the sliding frame's acceleration (theory §18)
  double slide_acceleration(double sn, double cs, double theta_dot, BaseAcceleration a,
                            double& theta_ddot, Eigen::Vector2d& reaction);
  // ---- guard functions of the current mode, in its slot order, with the floor reaction
  void evaluate(double t, const State& x, GuardSample& s);
  // the rocking modes' guard values from the state and the sample's F_J
  void rocking_guards(int e, const State& x, GuardSample& s) const;
  // evaluate() on the closed-form arc where sin(phi), cos(phi) are known (the peak, the floor):
  // the reaction as the arc's function of phi, with no sincos of theta
  void arc_sample(double t, const State& x, double sp, double cp, GuardSample& s) const;
  double guard_value(int slot, double t) override;
  double crossing(int slot, double tl, double tr, double gl, double gr) override;

  // ---- the loop
  bool enter_mode(double t, State& x);
  void configure_rocking_integrator();
  bool advance(double& t, State& x);
  // `buf`: scratch for the stepper's dense output (a vector of the stepper's state)
  template <class Stepper, class System, class Buffer>
  bool advance_with(Stepper& integ, System&& sys, Buffer& buf, double& t, State& x);
  template <class Stepper, class System>
  bool end_step(Stepper& integ, System&& sys, int slot_hit, double t_hit, const GuardSample& s_end,
                double& t, State& x);
  bool advance_still(double& t, State& x);
  // a rigid body's rocking by its series with the guards bounded over the whole step
  bool series_bounded() const;
  bool advance_series(double& t, State& x);
  // a rigid body rocking freely on a floor at rest, by its closed form (arc_): true where it
  // applies at (t, x) and the arc has started
  bool start_arc(double t, const ContactState& x);
  bool advance_arc(double& t, State& x);
  // the shear's, the moment's and the friction demand's extremes over the arc's last step
  void arc_extremes(double t0, double t1);
  // the series' reaction polynomials sp_fi_, sp_fj_, sp_moment_ on a step of length h
  void reaction_polynomials(double h);
  // `reaction`: whether reaction_polynomials ran on this step (it runs here where needed)
  // `range`: the reaction's enclosure over the whole step
  void series_extremes(double t0, double tau_end, bool event, const ReactionRange& range,
                       bool& reaction);
  // counts a step toward max_steps: false (the run stops) past them
  bool count_step(double t);
  // the stepper could not take a step from t: the run stops, saying why
  bool step_collapsed(double t);
  double scan_record(double t);
  bool can_walk(double t) const;
  bool advance_walk(double& t, State& x);
  using Excursion = typename ContactPropagator<N, MaxN, State>::Excursion;
  Excursion walk_excursion(double w) const;
  bool guards_clear(const GuardSample& sa, const GuardSample& sb, const Excursion& e) const;
  bool walk_quiet(double ax, double ay0, double ay1) const;
  struct ReactionReach {
    bool shear = false, moment = false, demand = false;
    bool pull = false;  // the floor's pull on a held pivot (tension_)
  };
  ReactionReach reaction_reach(double fi_top, double moment_top, double fj_lo, double fj_hi) const;
  int walk_search(double tp0, double a, double b, const GuardSample& sa, const GuardSample& sb,
                  int depth, double& a_out, double& b_out);
  void emit_walk_rows(double tp0, double tp1);
  void locate_extremes(double tp0, double h, const GuardSample& sa, const GuardSample& sb,
                       const Excursion& e);
  template <class Jet>
  double largest_near(Jet&& jet, double tau, double lo, double hi);
  // the quantities of locate_extremes at the last step's observed point p (time t, guards s, u the
  // deformation there), into point_t_ and point_vals_
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
  std::array<double, 3> guard_jet(int k, double tau);
  bool step_guards(int samples, double t1, double& t_hit, int& slot_hit);
  void state_at(double t, State& out) const;

  // ---- resets (the automaton's edges)
  bool fire(int slot, double t, State& x);
  bool uplift(double t, State& x, int e);
  bool impact(double t, State& x);
  bool lift_off(double t, State& x);
  // `rigid`: the rigid_body law (false: the paper's, also when rigid_body would add energy)
  bool land(double t, State& x, int e, bool rigid);
  bool overturned(double t, State& x);
  // `momentum` [N s]: M (|v_c| before + after), the scale of the impulse's rounding
  bool after_impulse(double t, State& x, const Event& ev, double th, double momentum);
  bool start_slip(double t, State& x);
  // an uplift onto e from sticking full contact at t (state in q_, qd_) has a continuation: the
  // pivot's friction holds, or with the pivot sliding the body still turns up (theory §20)
  bool uplift_holds(double t, int e);
  bool stick(double t, State& x);
  // the mode changes to m at t: the slip's bookkeeping (offset, time sliding)
  void switch_mode(ContactMode m, double t, State& x);
  // the plastic impact of tipping point e with Coulomb friction (theory §19); false when the run
  // ends. `from_flight`: a landing (the other tipping point may take over at theta = 0);
  // `flat`: both edges land whatever the single-point map gives (chatter)
  bool friction_impact(double t, State& x, int e, const Eigen::Vector2d& v_c, bool from_flight,
                       bool flat, EventKind kind, bool chatter, bool rigid);
  // rigid_body would have added energy at t: the paper's law takes the impact, said in an event
  void law_fallback(double t, int e);
  bool stop(double t, std::string why);
  void record(double t);                                     // a peak
  void record_sample(const GuardSample& s, const State& x);  // a peak evaluated at s.t
  void count_impact(const Event& ev, double impulse_y, double loss, bool chatter);
  // after a step with no event: a pressing floor ends the pivot-tension hold
  void release_latches(const GuardSample& s) {
    hold_tension_ = false;
    const int lift = guard_slot(mode_, Guard::kLiftOff);
    if (lift >= 0 && s.v[static_cast<std::size_t>(lift)] > 0.0) tension_ = false;
  }
  // an event at t on edge `e` (0: none) with the base centre's offset in contact
  Event make_event(double t, EventKind kind, int e) const {
    Event ev;
    ev.time = t;
    ev.kind = kind;
    ev.edge = e;
    ev.offset = offset_;
    return ev;
  }

  // ---- outputs
  Observation observation(double t, const State& x, const GuardSample& s);
  void flight_heights(const State& x, Observation& o);  // the tipping points' heights, offset
  double kinetic_energy(const State& x);
  double potential_energy(const State& x);
  double offset_of(const State& x);
  void observe(const GuardSample& s, const State& x) {
    rec_.observe(observation(s.t, x, s));
    if (s.fj < 0.0 && tension_) fold_pull(s.fj);
  }
  // the floor pulls on a held pivot (F_J over M g, < 0): into the run's largest pull and the
  // episode's pivot_tension event
  void fold_pull(double fj) {
    const double f = fj * dyn_.mass() * dyn_.g();
    res_.extremes.max_pivot_pull = std::max(res_.extremes.max_pivot_pull, -f);
    if (tension_event_ >= 0) {
      Event& ev = res_.events[static_cast<std::size_t>(tension_event_)];
      ev.force_estimate = std::min(ev.force_estimate, f);
    }
  }
  // the pull of a sample while the pivot is held (over M g, >= 0): a located quantity
  double pull_of(const GuardSample& s) const { return tension_ && s.fj < 0.0 ? -s.fj : 0.0; }
  // the state at t within the last step, evaluated and observed (an extreme located there)
  void observe_at(double t) {
    GuardSample s;
    state_at(t, xr_);
    evaluate(t, xr_, s);
    observe(s, xr_);
  }
  void emit_rows_until(double t_cut);
  void emit_row(double t, const State& x);
  void finish(double t, const State& x);

  // the body in its pinned-base modal coordinates q, which the state carries; the deformation
  // it reports is the given body's, u = to_user_ q (docs/theory.md, "Modal coordinates")
  const Body body_;
  Mat to_user_, from_user_;  // Phi and Phi^-1 = Phi^T mu
  mutable Vec qu_, qdu_;     // u of the last observation, u_dot of the last history row
  Vec ua_, ub_;              // scratch: u at a walk's piece's start and end
  std::array<Vec, 5> qjet_;  // scratch: q and its first four derivatives in a walk's piece
  Dyn dyn_;
  const GroundMotion& motion_;
  SimulationOptions opt_;
  int n_;
  StepControl ctl_;
  int samples_ = 4;
  // rocking, and full contact when not stepped exactly: DOPRI5, and the Rosenbrock method while a
  // flexible body's stiffest rocking motion would hold the explicit step (theory, "Stiff rocking")
  StiffSwitching<ContactState> integ_;
  std::array<double, 2> rocking_h_stable_{-1.0, -1.0};  // [s] per edge, once known (< 0: not yet)
  RockingSeries<ContactState> series_integ_;  // a rigid body's rocking under a record or none
  FreeRockingArc<ContactState> arc_;          // the same on a floor at rest, in closed form
  Dopri5<FlightState> flight_integ_;
  Dopri5<SlideState> slide_integ_;
  mutable SlideState slide_buf_;
  Vec qdd1_;  // scratch: q_ddot at a unit slip acceleration
  mutable ContactState dense_buf_;
  mutable FlightState flight_buf_;
  State prop_buf_;  // scratch: the exact propagator's dense output
  ContactPropagator<N, MaxN, State> prop_;
  SimulationResult res_;
  Recorder rec_;
  ContactMode mode_ = ContactMode::kFullContact;
  // what steps the current mode's motion, chosen once in enter_mode
  enum class Stepping {
    kStill,    // a rigid body in full contact: the state is x_still_, nothing integrates
    kExact,    // a flexible body in full contact under a record or none: prop_
    kSeries,   // a rigid body rocking under a record or none: series_integ_
    kArc,      // a rigid body rocking freely on a floor at rest: arc_, in closed form
    kRocking,  // any other sticking contact mode (rocking, or full contact under pulses): integ_
    kFlight,   // flight_integ_
    kSlide,    // a sliding mode: slide_integ_
  };
  Stepping stepping_ = Stepping::kRocking;
  Stepping choose_stepping() const;
  double stepped_until() const;  // [s] the end of the last step taken (of the still span)
  GroundMotion::Cursor rhs_cursor_, event_cursor_, break_cursor_;
  Vec q_, qd_, qdd_;
  State xr_;
  // the series step's guards and observed quantities as polynomials in tau (advance_series)
  StepPolynomial sp_impact_, sp_overturn_, sp_peak_, sp_fi_, sp_fj_, sp_moment_, sp_work_;
  std::array<GuardSample, kMaxSamples + 1> samples_buf_;  // guards at this step's samples
  std::array<State, kMaxSamples + 1> sample_states_;      // the states there (sized once)
  GuardSample s0_;
  std::size_t scan_index_ = 0;  // the record sample the last scan stopped at
  double scan_from_ = 0.0;      // [s] the last sample the scan passed with no event
  State x_still_;
  State xw_, xe_;             // the walk's state at its piece's start and end
  double fine_until_ = -1.0;  // [s] the walk resumes once the stepped propagation reaches it
  // [s] the stepped propagation's next step ends here: a bracket the walk found a crossing in
  double step_stop_ = std::numeric_limits<double>::infinity();
  std::vector<int> wanted_;             // the walk's extremes search: the quantities sought
  std::vector<double> best_, best_at_;  // their largest values found, and where [s]
  // a step's observed points (its start, its samples before any event, the event) and the
  // quantities of locate_extremes there (|u_j|, |F_I|, |moment|, friction demand, pull)
  static constexpr int NQ = N == Eigen::Dynamic ? Eigen::Dynamic : N + 4;
  static constexpr int MaxNQ = MaxN == Eigen::Dynamic ? Eigen::Dynamic : MaxN + 4;
  using Quantities = Eigen::Array<double, NQ, 1, Eigen::ColMajor, MaxNQ, 1>;
  std::array<double, kMaxSamples + 2> point_t_{};
  std::array<Quantities, kMaxSamples + 2> point_vals_;
  std::array<bool, kMaxSamples + 2> point_pressing_{};  // F_J >= kPressingFraction at the points
  std::array<double, kMaxSamples + 2> point_fj_{};      // F_J over M g at the points
  Quantities point_extreme_;                   // scratch: the extremes so far, in the same units
  std::array<double, 4> walk_forcing_{};       // the piece's max |a_x|, |a_y|, |a_x'|, |a_y'|
  double still_t1_ = 0.0;                      // [s] end of the span checked last while still
  std::array<bool, kMaxGuards> zero_start_{};  // guards known to turn positive from zero
  std::array<double, 2> overturn_limit_{};     // [rad] on edge 1 (theta > 0) and edge 2
  double offset_ = 0.0;              // [m] horizontal offset of the base centre while in contact
  ImpactRule rule_;                  // the impact law and its parameters
  bool rigid_law_ = false;           // rule_ is rigid_body
  double mu_s_ = 0.0, mu_k_ = 0.0;   // static and kinetic friction coefficients (inf: no limit)
  double slide_start_ = 0.0;         // [s] when the current slide began
  bool slide_inconsistent_ = false;  // a sliding mode had no consistent slip acceleration
  bool tension_ = false;     // the floor pulls (pivot_tension): lift-off disarmed until it presses
  long tension_event_ = -1;  // the index of the episode's pivot_tension event (-1: none)
  // after a grazing landing with friction the floor is let pull through the modes entered at that
  // instant (a slip that starts where the pivot force vanishes) until a step ends: else the body
  // would lift off and land again without end
  bool hold_tension_ = false;
  bool suppress_uplift_at_start_ = false;
  double chatter_interval_ = 0.0;
  double base_width_ = 0.0;  // [m] b1 + b2
  double last_contact_change_ = 0.0;
  double flight_start_ = 0.0;
  double t_end_ = 0.0;
  double quiet_from_ = 0.0;  // the base acceleration is zero after this [s]
  long next_output_ = 0;
  double energy0_ = 0.0, kinetic0_ = 0.0;
  double impact_loss_ = 0.0, chatter_loss_ = 0.0;
  double zeno_time_ = -1.0;
  int same_time_events_ = 0;
};

// ------------------------------------------------------------------------------------------------

template <int N, int MaxN>
Simulator<N, MaxN>::Simulator(const Body& body, const GroundMotion& motion,
                              const SimulationOptions& opt)
    : body_(body.in_modal_coordinates()),
      to_user_(body.pinned_base_modes()),
      from_user_(body.pinned_base_modes().transpose() * body.params().mu),
      dyn_(body_),
      motion_(motion),
      opt_(opt),
      n_(body.modes()),
      samples_(std::clamp(opt.event_samples, 1, kMaxSamples)),
      series_integ_(motion),
      prop_(dyn_, motion, samples_, opt.max_step, opt.methods.exact_full_contact),
      rec_(res_, body.params().mass, body.g(), body.params().height, body.modes()) {
  prop_.output_basis(to_user_);
  qu_.resize(n_);
  qdu_.resize(n_);
  ua_.resize(n_);
  ub_.resize(n_);
  for (Vec& v : qjet_) v.setZero(n_);
  q_.resize(n_);
  qd_.resize(n_);
  qdd_.resize(n_);
  qdd1_.resize(n_);
  rule_.law = opt.impact_law;
  rule_.restitution_factor = opt.restitution_factor;
  rule_.ratio_edge1 = opt.restitution_ratio_edge1;
  rule_.ratio_edge2 = opt.restitution_ratio_edge2;
  rigid_law_ = opt.impact_law == ImpactLaw::kRigidBody;
  mu_s_ = opt.friction_coefficient;
  mu_k_ = std::min(opt.kinetic_friction_coefficient, opt.friction_coefficient);
  // shortest period among the pinned-base modes and the rigid rocking motion
  double shortest = 2.0 * std::numbers::pi / body.rocking_frequency();
  if (n_ > 0)
    shortest = std::min(shortest, 2.0 * std::numbers::pi / body.natural_frequencies().maxCoeff());
  chatter_interval_ = opt.chatter_ratio * shortest;
  base_width_ = body.params().b1 + body.params().b2;
  const bool half_pi = opt.overturn == OverturnCriterion::kHalfPi;
  overturn_limit_[0] = half_pi ? 0.5 * std::numbers::pi : body.tipping_angle(1);
  overturn_limit_[1] = half_pi ? 0.5 * std::numbers::pi : body.tipping_angle(2);
  ctl_.rtol = opt.rtol;
  ctl_.atol = opt.atol;
  ctl_.max_step = opt.max_step;
  for (State& xk : sample_states_) xk.setZero(2 * n_ + 11);
  dense_buf_.setZero(2 * n_ + 4);
  slide_buf_.setZero(2 * n_ + 7);
  xr_.setZero(2 * n_ + 11);  // written through put(): sized once, as on the heap path
  flight_buf_.setZero(2 * n_ + 8);
  prop_buf_.setZero(2 * n_ + 11);
  xw_.setZero(2 * n_ + 11);
  xe_.setZero(2 * n_ + 11);
  wanted_.assign(static_cast<std::size_t>(n_ + 4), 0);
  best_.assign(static_cast<std::size_t>(n_ + 4), 0.0);
  best_at_.assign(static_cast<std::size_t>(n_ + 4), 0.0);
  for (Quantities& v : point_vals_) v.setZero(n_ + 4);
  point_extreme_.setZero(n_ + 4);
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
    mode_ = ContactMode::kRockingEdge1;
  } else if (init.theta < 0.0 || init.theta_dot < 0.0) {
    mode_ = ContactMode::kRockingEdge2;
  }
  t_end_ = opt_.t_end >= 0.0 ? opt_.t_end : motion_.duration();
  quiet_from_ = motion_.quiet_from();
  energy0_ = kinetic_energy(x) + potential_energy(x);
  kinetic0_ = kinetic_energy(x);
  last_contact_change_ = -std::numeric_limits<double>::infinity();

  // a rocking run records two events an impact (the impact, the next peak): room for the first
  // 32 impacts spares the run the vector's first six reallocations
  res_.events.reserve(64);
  double t = 0.0;
  bool running = enter_mode(t, x);
  if (opt_.output_dt > 0.0) emit_row(t, x);
  next_output_ = 1;
  while (running && t < t_end_) running = advance(t, x);
  finish(t, x);
  return std::move(res_);
}

// ---- equations of motion
// -------------------------------------------------------------------------

// full contact (theory §4, theta = 0) and rocking (theory §4); writes every entry
template <int N, int MaxN>
void Simulator<N, MaxN>::contact_rhs(double t, const ContactState& x, ContactState& dx) {
  const BaseAcceleration a = motion_.at(t, rhs_cursor_);
  dx.resize(x.size());
  if (rocking()) {
    // from the state to its derivative in place, every shared sum formed once
    double sn = 0.0, cs = 0.0;
    sin_cos(x(0), sn, cs);
    typename Dyn::RockingRates r;
    dyn_.rocking_rates_sc(edge(), sn, cs, x.data() + iq(), x(ithd()), x.data() + iqd(), a,
                          dx.data() + iqd(), r);
    dx(0) = x(ithd());
    dx.segment(iq(), n_) = x.segment(iqd(), n_);
    dx(ithd()) = r.theta_ddot;
    dx(iw()) = r.input_power;
    dx(id()) = r.damping_power;
    return;
  }
  unpack(x);
  dyn_.full_contact_acceleration(q_, qd_, a, qdd_);
  dx(0) = 0.0;
  dx.segment(iq(), n_) = qd_;
  dx(ithd()) = 0.0;
  dx.segment(iqd(), n_) = qdd_;
  dx(iw()) = dyn_.input_power(0.0, 0.0, q_, 0.0, qd_, a);
  dx(id()) = dyn_.damping_power(qd_);
}

// theory "Flight": the c.g. is ballistic relative to the base, the rest feels no gravity
template <int N, int MaxN>
void Simulator<N, MaxN>::flight_rhs(double t, const FlightState& x, FlightState& dx) {
  const BaseAcceleration a = motion_.at(t, rhs_cursor_);
  unpack(x);
  dx.resize(x.size());
  double thdd = 0.0;
  dyn_.flight_acceleration(q_, x(ithd()), qd_, thdd, qdd_);
  dx(0) = x(ithd());
  dx.segment(iq(), n_) = qd_;
  dx(ithd()) = thdd;
  dx.segment(iqd(), n_) = qdd_;
  dx(iw()) = dyn_.flight_input_power(cg_velocity(x), a);
  dx(id()) = dyn_.damping_power(qd_);
  dx(ixc()) = x(ixc() + 2);
  dx(ixc() + 1) = x(ixc() + 3);
  dx(ixc() + 2) = -a.x;
  dx(ixc() + 3) = -dyn_.g() - a.y;
}

// theory §18: with the base sliding, the body moves as in the mode without slip on a base that
// accelerates at a + d_ddot I, so the accelerations and the floor reaction are affine in d_ddot,
// and Coulomb's F_I = -s mu_k F_J is one linear equation for it
template <int N, int MaxN>
double Simulator<N, MaxN>::slide_acceleration(double sn, double cs, double theta_dot,
                                              BaseAcceleration a, double& theta_ddot,
                                              Eigen::Vector2d& reaction) {
  const BaseAcceleration a1{a.x + 1.0, a.y};  // a unit slip acceleration [m/s^2]
  Eigen::Vector2d r0, r1;
  double thdd0 = 0.0, thdd1 = 0.0;
  if (rocking()) {
    const int e = edge();
    dyn_.rocking_acceleration_sc(e, sn, cs, q_, theta_dot, qd_, a, thdd0, qdd_);
    r0 = dyn_.rocking_reaction_sc(e, sn, cs, q_, theta_dot, qd_, thdd0, qdd_, a);
    dyn_.rocking_acceleration_sc(e, sn, cs, q_, theta_dot, qd_, a1, thdd1, qdd1_);
    r1 = dyn_.rocking_reaction_sc(e, sn, cs, q_, theta_dot, qd_, thdd1, qdd1_, a1);
  } else {
    dyn_.full_contact_acceleration(q_, qd_, a, qdd_);
    r0 = dyn_.full_contact_reaction(qdd_, a);
    dyn_.full_contact_acceleration(q_, qd_, a1, qdd1_);
    r1 = dyn_.full_contact_reaction(qdd1_, a1);
  }
  const double s = slip();
  const Eigen::Vector2d dr = r1 - r0;  // the reaction's change per m/s^2 of d_ddot
  // k > 0: friction opposing the slip decelerates it; k <= 0 has no consistent slide (Painleve)
  const double k = dr(0) + s * mu_k_ * dr(1);
  if (!(k > 0.0)) slide_inconsistent_ = true;
  const double dd = -(r0(0) + s * mu_k_ * r0(1)) / k;
  theta_ddot = thdd0 + dd * (thdd1 - thdd0);
  qdd_ += dd * (qdd1_ - qdd_);
  reaction = r0 + dd * dr;
  return dd;
}

// the sliding modes (theory §18): the contact mode's equations in the sliding frame, the slip, and
// the powers relative to the base: input -M a.(v_cm + d_dot I), friction dissipation -F_I d_dot
template <int N, int MaxN>
void Simulator<N, MaxN>::slide_rhs(double t, const SlideState& x, SlideState& dx) {
  const BaseAcceleration a = motion_.at(t, rhs_cursor_);
  unpack(x);
  dx.resize(x.size());
  double sn = 0.0, cs = 0.0;
  sin_cos(x(0), sn, cs);
  const double v = x(jsd() + 1);
  double thdd = 0.0;
  Eigen::Vector2d r;
  const double dd = slide_acceleration(sn, cs, x(ithd()), a, thdd, r);
  const double al = rocking() ? dyn_.alpha(edge()) : 0.0;
  dx(0) = rocking() ? x(ithd()) : 0.0;
  dx.segment(iq(), n_) = qd_;
  dx(ithd()) = thdd;
  dx.segment(iqd(), n_) = qdd_;
  dx(iw()) = dyn_.input_power_sc(al, sn, cs, q_, x(ithd()), qd_, a) - dyn_.mass() * a.x * v;
  dx(id()) = dyn_.damping_power(qd_);
  dx(jsd()) = v;
  dx(jsd() + 1) = dd;
  dx(jsd() + 2) = -dyn_.mass() * dyn_.g() * r(0) * v;
}

// ---- guard functions
// -----------------------------------------------------------------------------

template <int N, int MaxN>
void Simulator<N, MaxN>::evaluate(double t, const State& x, GuardSample& s) {
  // after the motion's end (GroundMotion::quiet_from) the floor is at rest
  const BaseAcceleration a = t > quiet_from_ ? BaseAcceleration{} : motion_.at(t, event_cursor_);
  unpack(x);
  s.t = t;
  // each value goes to its guard's slot in the mode's list, which the table fixes at compile time
  auto& v = s.v;
  const double mu = opt_.friction_coefficient;
  switch (mode_) {
    case ContactMode::kFullContact: {
      constexpr ContactMode m = ContactMode::kFullContact;
      dyn_.full_contact_acceleration(q_, qd_, a, qdd_);
      const Eigen::Vector2d r = dyn_.full_contact_reaction(qdd_, a);
      Eigen::Vector2d u;
      s.fi = r(0);
      s.fj = r(1);
      s.moment = dyn_.contact_moments(q_, qdd_, a, u);
      v[kSlot<m, Guard::kUpliftEdge1>] = u(0);
      v[kSlot<m, Guard::kUpliftEdge2>] = u(1);
      v[kSlot<m, Guard::kLiftOff>] = s.fj;
      v[kSlot<m, Guard::kFrictionLimit>] = std::isfinite(mu) ? mu * s.fj - std::abs(s.fi) : 1.0;
      break;
    }
    case ContactMode::kRockingEdge1:
    case ContactMode::kRockingEdge2: {
      const int e = edge();
      double thdd = 0.0;
      double sn = 0.0, cs = 0.0;
      sin_cos(x(0), sn, cs);
      dyn_.rocking_acceleration_sc(e, sn, cs, q_, x(ithd()), qd_, a, thdd, qdd_);
      const Eigen::Vector2d r =
          dyn_.rocking_reaction_sc(e, sn, cs, q_, x(ithd()), qd_, thdd, qdd_, a);
      s.fi = r(0);
      s.fj = r(1);
      // reaction at the pivot, moment about the c.g. projection: alpha h F_j(body)
      s.moment = dyn_.alpha(e) * (-r(0) * sn + r(1) * cs);
      rocking_guards(e, x, s);
      break;
    }
    case ContactMode::kSlidingPlus:
    case ContactMode::kSlidingMinus: {
      constexpr ContactMode m = ContactMode::kSlidingPlus;  // both directions list the same guards
      static_assert(mode_spec(ContactMode::kSlidingPlus).guards ==
                    mode_spec(ContactMode::kSlidingMinus).guards);
      double thdd = 0.0;
      Eigen::Vector2d r;
      const double dd = slide_acceleration(0.0, 1.0, 0.0, a, thdd, r);
      const BaseAcceleration as{a.x + dd, a.y};  // the sliding base's acceleration
      Eigen::Vector2d u;
      s.fi = r(0);
      s.fj = r(1);
      s.moment = dyn_.contact_moments(q_, qdd_, as, u);
      v[kSlot<m, Guard::kUpliftEdge1>] = u(0);
      v[kSlot<m, Guard::kUpliftEdge2>] = u(1);
      v[kSlot<m, Guard::kLiftOff>] = s.fj;
      v[kSlot<m, Guard::kSlipStop>] = slip() * x(isv());
      break;
    }
    case ContactMode::kRockingEdge1SlidingPlus:
    case ContactMode::kRockingEdge1SlidingMinus:
    case ContactMode::kRockingEdge2SlidingPlus:
    case ContactMode::kRockingEdge2SlidingMinus: {
      constexpr ContactMode m = ContactMode::kRockingEdge1SlidingPlus;
      static_assert(
          mode_spec(m).guards == mode_spec(ContactMode::kRockingEdge2SlidingMinus).guards &&
          mode_spec(m).guards == mode_spec(ContactMode::kRockingEdge1SlidingMinus).guards &&
          mode_spec(m).guards == mode_spec(ContactMode::kRockingEdge2SlidingPlus).guards);
      const int e = edge();
      const double sg = edge_sign(e);
      double sn = 0.0, cs = 0.0;
      sin_cos(x(0), sn, cs);
      double thdd = 0.0;
      Eigen::Vector2d r;
      slide_acceleration(sn, cs, x(ithd()), a, thdd, r);
      s.fi = r(0);
      s.fj = r(1);
      s.moment = dyn_.alpha(e) * (-r(0) * sn + r(1) * cs);
      v[kSlot<m, Guard::kImpact>] = sg * x(0);
      v[kSlot<m, Guard::kOverturn>] = overturn_limit_[static_cast<std::size_t>(e - 1)] - sg * x(0);
      v[kSlot<m, Guard::kLiftOff>] = s.fj;
      v[kSlot<m, Guard::kSlipStop>] = slip() * x(isv());
      v[kSlot<m, Guard::kPeak>] = sg * x(ithd());
      break;
    }
    case ContactMode::kFlight: {
      constexpr ContactMode m = ContactMode::kFlight;
      double sn = 0.0, cs = 0.0;
      sin_cos(x(0), sn, cs);
      const double h = dyn_.height();
      s.fi = s.fj = s.moment = 0.0;
      v[kSlot<m, Guard::kLandingEdge1>] = dyn_.corner_height(1, sn, cs, q_, x(ixc() + 1)) / h;
      v[kSlot<m, Guard::kLandingEdge2>] = dyn_.corner_height(2, sn, cs, q_, x(ixc() + 1)) / h;
      v[kSlot<m, Guard::kOverturn>] =
          std::min(overturn_limit_[0] - x(0), overturn_limit_[1] + x(0));
      break;
    }
  }
}

template <int N, int MaxN>
void Simulator<N, MaxN>::rocking_guards(int e, const State& x, GuardSample& s) const {
  constexpr ContactMode m = ContactMode::kRockingEdge1;  // both edges list the same guards
  static_assert(mode_spec(ContactMode::kRockingEdge1).guards ==
                mode_spec(ContactMode::kRockingEdge2).guards);
  const double sg = edge_sign(e), mu = opt_.friction_coefficient;
  auto& v = s.v;
  v[kSlot<m, Guard::kImpact>] = sg * x(0);
  v[kSlot<m, Guard::kOverturn>] = overturn_limit_[static_cast<std::size_t>(e - 1)] - sg * x(0);
  v[kSlot<m, Guard::kLiftOff>] = s.fj;
  v[kSlot<m, Guard::kFrictionLimit>] = std::isfinite(mu) ? mu * s.fj - std::abs(s.fi) : 1.0;
  v[kSlot<m, Guard::kPeak>] = sg * x(ithd());
}

template <int N, int MaxN>
void Simulator<N, MaxN>::arc_sample(double t, const State& x, double sp, double cp,
                                    GuardSample& s) const {
  s.t = t;
  s.fi = arc_.fi(sp, cp);
  s.fj = arc_.press(cp);
  s.moment = arc_.signed_moment(sp, cp);
  rocking_guards(edge(), x, s);
}

template <int N, int MaxN>
double Simulator<N, MaxN>::guard_value(int slot, double t) {
  GuardSample s;
  state_at(t, xr_);
  evaluate(t, xr_, s);
  return s.v[static_cast<std::size_t>(slot)];
}

// the rocking series' impact guard (s theta) and peak guard (s theta_dot) are polynomials on the
// step: their crossings are found on the polynomial; every other guard by TOMS 748
template <int N, int MaxN>
double Simulator<N, MaxN>::crossing(int slot, double tl, double tr, double gl, double gr) {
  if (stepping_ == Stepping::kSeries) {
    const Guard g = mode_spec(mode_).guards[static_cast<std::size_t>(slot)];
    const double sg = edge_sign(edge());
    const double* c = series_integ_.theta_coefficients();
    const double* dc = series_integ_.theta_rate_coefficients();  // k c[k]
    const int degree = series_integ_.order();                    // theta's; theta_dot's is one less
    if (g == Guard::kImpact)
      return polynomial_crossing(c, dc, degree, sg, series_integ_.t0(), tl, tr, gl, gr);
    if (g == Guard::kPeak) {
      // theta_dot's coefficients d[k] = dc[k + 1], and k d[k]
      const double* d = dc + 1;
      std::array<double, RockingSeries<ContactState>::kMaxOrder + 2> dd;
      for (int k = 1; k < degree; ++k) dd[static_cast<std::size_t>(k)] = k * d[k];
      return polynomial_crossing(d, dd.data(), degree - 1, sg, series_integ_.t0(), tl, tr, gl, gr);
    }
  }
  return locate_crossing(slot, tl, tr, gl, gr, *this);
}

// ---- the loop
// ------------------------------------------------------------------------------------

// starts the current mode at (t, x); false when the run ends here. A guard already at or below
// zero on entry fires at once (an uplift or lift-off that the entry state already calls for).
template <int N, int MaxN>
bool Simulator<N, MaxN>::enter_mode(double t, State& x) {
  // every reset ends here, those a mode's entry state calls for at once included: contact
  // changes piling up at one instant would loop forever, so they stop the run
  if (t - zeno_time_ < 1e-9 * std::max(1.0, t)) {
    if (++same_time_events_ > 64) {
      return stop(t, "contact changes accumulate at t = " + short_number(t) +
                         " s without time advancing (Zeno behaviour) in " + to_string(mode_) +
                         (opt_.chatter_ratio <= 0.0 ? " with the chatter cut-off disabled "
                                                      "(chatter_ratio = 0); set chatter_ratio > 0"
                                                    : ""));
    }
  } else {
    zeno_time_ = t;
    same_time_events_ = 0;
  }
  if (full_contact()) {
    x(0) = 0.0;
    x(ithd()) = 0.0;
  }
  step_stop_ = std::numeric_limits<double>::infinity();
  stepping_ = choose_stepping();
  // quadratures steer no step of a sticking contact mode; a slide's d, d_dot come after them
  ctl_.controlled = flying() ? 2 * n_ + 8 : (sliding() ? -1 : 2 * n_ + 2);
  switch (stepping_) {
    case Stepping::kStill:
      x_still_ = x;
      still_t1_ = t;
      break;
    case Stepping::kExact:
      prop_.start(t, x);
      break;
    case Stepping::kFlight:
      flight_buf_ = x.head(2 * n_ + 8);
      flight_integ_.start(
          [this](double tt, const FlightState& xx, FlightState& dd) { flight_rhs(tt, xx, dd); },
          ctl_, t, flight_buf_);
      break;
    case Stepping::kSlide:
      slide_buf_.head(2 * n_ + 4) = x.head(2 * n_ + 4);
      slide_buf_.tail(3) = x.segment(isd(), 3);
      slide_integ_.start(
          [this](double tt, const SlideState& xx, SlideState& dd) { slide_rhs(tt, xx, dd); }, ctl_,
          t, slide_buf_);
      break;
    case Stepping::kSeries: {
      dense_buf_ = x.head(2 * n_ + 4);
      if (start_arc(t, dense_buf_)) break;  // the arc needs no series
      const int e = edge();
      const double a = dyn_.alpha(e);
      series_integ_.set_pivot(a, dyn_.g_over_h() / dyn_.inertia(a, q_),
                              dyn_.mass() * dyn_.height() * dyn_.g(), dyn_.g());
      series_integ_.start([](double, const ContactState&, ContactState&) {}, ctl_, t, dense_buf_);
      break;
    }
    case Stepping::kArc:
      break;  // chosen above, from kSeries
    case Stepping::kRocking:
      dense_buf_ = x.head(2 * n_ + 4);
      configure_rocking_integrator();
      integ_.start(
          [this](double tt, const ContactState& xx, ContactState& dd) { contact_rhs(tt, xx, dd); },
          ctl_, t, dense_buf_);
      break;
  }
  // an arc from the floor (after an impact) knows its reaction there
  if (stepping_ == Stepping::kArc && x(0) == 0.0)
    arc_sample(t, x, arc_.floor_sin(), arc_.floor_cos(), s0_);
  else
    evaluate(t, x, s0_);
  observe(s0_, x);
  const ModeSpec& spec = mode_spec(mode_);
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    if (zero_start_[k] && s0_.v[k] != 0.0) zero_start_[k] = false;
  }
  auto at_or_below = [&](Guard g) {
    const int j = guard_slot(mode_, g);
    return j >= 0 && !zero_start_[static_cast<std::size_t>(j)] &&
           s0_.v[static_cast<std::size_t>(j)] <= 0.0;
  };
  const int lift = guard_slot(mode_, Guard::kLiftOff);
  if (lift < 0) hold_tension_ = false;
  if (lift < 0 || (s0_.v[static_cast<std::size_t>(lift)] > 0.0 && !hold_tension_)) tension_ = false;
  if (at_or_below(Guard::kOverturn)) return overturned(t, x);
  if (!tension_ && at_or_below(Guard::kLiftOff)) return lift_off(t, x);
  // an uplift is tried before a slip (theory §20): rocking on a sticking pivot if its friction
  // holds, else rocking with the pivot sliding if that turns the body up, else sliding flat
  if (full_contact() && !suppress_uplift_at_start_) {
    const bool up1 = at_or_below(Guard::kUpliftEdge1), up2 = at_or_below(Guard::kUpliftEdge2);
    if (up1 || up2) {
      const int e = up1 && (!up2 || s0_.v[0] <= s0_.v[1]) ? 1 : 2;
      if (!sliding() && !uplift_holds(t, e)) {
        suppress_uplift_at_start_ = true;  // the body slides flat instead
        return start_slip(t, x);
      }
      return uplift(t, x, e);
    }
  }
  suppress_uplift_at_start_ = false;
  if (at_or_below(Guard::kFrictionLimit)) return start_slip(t, x);
  if (at_or_below(Guard::kSlipStop)) return stick(t, x);
  if (flying()) {
    for (int e : {1, 2}) {
      if (at_or_below(e == 1 ? Guard::kLandingEdge1 : Guard::kLandingEdge2))
        return land(t, x, e, rigid_law_);
    }
  }
  return true;
}

// the stepper of mode_: the cheapest that is exact or accurate for its equations
template <int N, int MaxN>
auto Simulator<N, MaxN>::choose_stepping() const -> Stepping {
  if (flying()) return Stepping::kFlight;
  if (sliding()) return Stepping::kSlide;
  if (mode_ == ContactMode::kFullContact) {
    // a rigid body in full contact does not move: no integration until it uplifts
    if (n_ == 0) return Stepping::kStill;
    // a flexible body in full contact under a record or none: exact steps between its samples
    if (prop_.available()) return Stepping::kExact;
    return Stepping::kRocking;
  }
  // the series needs a base acceleration it can expand between the steps' ends: a record's
  // (linear), sinusoids' (a pulse's), or none
  if (N == 0 && opt_.methods.series_rocking &&
      (motion_.is_sampled() || motion_.is_none() || motion_.is_sinusoidal()))
    return Stepping::kSeries;
  return Stepping::kRocking;
}

template <int N, int MaxN>
double Simulator<N, MaxN>::stepped_until() const {
  switch (stepping_) {
    case Stepping::kStill:
      return still_t1_;
    case Stepping::kExact:
      return prop_.t1();
    case Stepping::kFlight:
      return flight_integ_.t1();
    case Stepping::kSlide:
      return slide_integ_.t1();
    case Stepping::kSeries:
      return series_integ_.t1();
    case Stepping::kArc:
      return arc_.t1();
    case Stepping::kRocking:
      break;
  }
  return integ_.t1();
}

// a flexible body's rocking may be stiff: the explicit method's stability bound on the rocking
// equations about the pivot (once per edge and run) lets the stepper see when stability, not
// accuracy, holds its step. Its explicit method is DOP853 (high_order_rocking): the modes'
// oscillation, resolved to rtol, sets the step, and the 8th order takes about a quarter of
// DOPRI5's steps for that. Full contact and a rigid body keep DOPRI5.
template <int N, int MaxN>
void Simulator<N, MaxN>::configure_rocking_integrator() {
  const auto method = static_cast<StiffMethod>(opt_.methods.rocking_integrator);
  if (n_ == 0 || !rocking()) {
    integ_.configure(std::numeric_limits<double>::infinity(), StiffMethod::kExplicit);
    return;
  }
  const ExplicitMethod explicit_method =
      opt_.methods.high_order_rocking ? ExplicitMethod::kDop853 : ExplicitMethod::kDopri5;
  double& h = rocking_h_stable_[static_cast<std::size_t>(edge() - 1)];
  if (h < 0.0 && method == StiffMethod::kAuto)
    h = rocking_stable_step(body_, edge(), explicit_method) / opt_.methods.stiff_switch_scale;
  integ_.configure(h, method, explicit_method);
}

// one accepted step plus whatever happens in it; false when the run ends
template <int N, int MaxN>
bool Simulator<N, MaxN>::advance(double& t, State& x) {
  switch (stepping_) {
    case Stepping::kStill:
      return advance_still(t, x);
    case Stepping::kExact:
      // the exact propagator takes no right-hand side
      if (t >= step_stop_) step_stop_ = std::numeric_limits<double>::infinity();
      if (can_walk(t)) return advance_walk(t, x);
      return advance_with(
          prop_, [](double, const State&, State&) {}, prop_buf_, t, x);
    case Stepping::kFlight: {
      auto sys = [this](double tt, const FlightState& xx, FlightState& dd) {
        flight_rhs(tt, xx, dd);
      };
      return advance_with(flight_integ_, sys, flight_buf_, t, x);
    }
    case Stepping::kSlide: {
      auto sys = [this](double tt, const SlideState& xx, SlideState& dd) { slide_rhs(tt, xx, dd); };
      return advance_with(slide_integ_, sys, slide_buf_, t, x);
    }
    case Stepping::kArc:
      return advance_arc(t, x);
    case Stepping::kSeries:
      if (series_bounded()) return advance_series(t, x);
      series_integ_.set_max_step(ctl_.max_step);
      return advance_with(
          series_integ_, [](double, const ContactState&, ContactState&) {}, dense_buf_, t, x);
    case Stepping::kRocking:
      break;
  }
  auto sys = [this](double tt, const ContactState& xx, ContactState& dd) {
    contact_rhs(tt, xx, dd);
  };
  return advance_with(integ_, sys, dense_buf_, t, x);
}

// the earliest crossing of a resetting guard among the step's samples, after recording the
// non-resetting ones before it; false when none
template <int N, int MaxN>
bool Simulator<N, MaxN>::step_guards(int samples, double t1, double& t_hit, int& slot_hit) {
  const ModeSpec& spec = mode_spec(mode_);
  t_hit = std::numeric_limits<double>::infinity();
  slot_hit = -1;
  std::array<double, kMaxGuards> when;
  when.fill(std::numeric_limits<double>::infinity());
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const GuardSpec& g = guard_spec(spec.guards[k]);
    if (g.guard == Guard::kPeak && !rocking()) continue;
    if (g.guard == Guard::kLiftOff && tension_) continue;
    // without a friction limit its guard is the constant 1 (evaluate): it never crosses
    if (g.guard == Guard::kFrictionLimit && !std::isfinite(opt_.friction_coefficient)) continue;
    when[k] = first_crossing(j, samples_buf_.data(), samples, zero_start_[k], g.fires_if_unresolved,
                             *this);
    if (g.reset != Reset::kRecord && when[k] < t_hit) {
      t_hit = when[k];
      slot_hit = j;
    }
  }
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    if (guard_spec(spec.guards[k]).reset == Reset::kRecord && when[k] <= std::min(t_hit, t1))
      record(when[k]);
  }
  return slot_hit >= 0;
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::count_step(double t) {
  if (++res_.steps <= opt_.max_steps) return true;
  return stop(t,
              "step limit reached (" + std::to_string(opt_.max_steps) + " steps; raise max_steps)");
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::step_collapsed(double t) {
  // the step limit is relative (min_step x max(1 s, t)); while rocking the usual cause is
  // impacts accumulating with the chatter cut-off disabled, so the message says so
  const double h_min = ctl_.min_step * std::max(1.0, std::abs(t));
  const std::string cause =
      rocking() && opt_.chatter_ratio <= 0.0
          ? "impacts accumulating while rocking with the chatter cut-off disabled "
            "(chatter_ratio = 0); set chatter_ratio > 0"
          : "the equations became too stiff or singular; loosen rtol/atol or check the body";
  return stop(t, "integration step collapsed below " + short_number(h_min) + " s near t = " +
                     short_number(t) + " s in " + to_string(mode_) + " (" + cause + ")");
}

// the step of `integ` (the integrator, or the exact propagator in full contact)
template <int N, int MaxN>
template <class Stepper, class System, class Buffer>
bool Simulator<N, MaxN>::advance_with(Stepper& integ, System&& sys, Buffer& buf, double& t,
                                      State& x) {
  const double t_stop = std::min({t_end_, motion_.next_breakpoint(t, break_cursor_), step_stop_});
  if (!count_step(t)) return false;
  const auto status = integ.step(sys, t_stop);
  if (status != std::remove_cv_t<decltype(status)>::kAccepted) return step_collapsed(t);
  if (slide_inconsistent_)
    return stop(t, "no consistent slide near t = " + short_number(t) + " s in " + to_string(mode_) +
                       ": Coulomb friction with this coefficient would need the floor to push the "
                       "slip forward (Painleve's paradox; docs/theory.md, \"Sliding\")");
  const double t0 = integ.t0(), t1 = integ.t1();
  if (opt_.progress) opt_.progress->store(t1, std::memory_order_relaxed);
  // sample the guards across the step, keeping the states for the extremes
  auto& smp = samples_buf_;
  smp[0] = s0_;
  for (int k = 1; k <= samples_; ++k) {
    const double tk = k == samples_ ? t1 : t0 + (t1 - t0) * k / samples_;
    State& xk = sample_states_[static_cast<std::size_t>(k)];
    if (k == samples_) {
      put(integ.x1(), xk);
    } else {
      integ.dense(tk, buf);
      put(buf, xk);
    }
    evaluate(tk, xk, smp[static_cast<std::size_t>(k)]);
  }
  double t_hit = 0.0;
  int slot_hit = -1;
  const bool hit = step_guards(samples_, t1, t_hit, slot_hit);
  // extremes from the samples that precede any state change and from the state just before it,
  // then located between them
  if (n_ > 0) qu_.noalias() = Dyn::mv(to_user_, x.segment(iq(), n_));
  keep_point(0, t0, s0_, qu_);
  int points = 1;
  for (int k = 1; k <= samples_; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    if (smp[kk].t >= t_hit) break;
    observe(smp[kk], sample_states_[kk]);  // leaves u in qu_
    keep_point(points++, smp[kk].t, smp[kk], qu_);
  }
  if (hit && t_hit > point_t_[static_cast<std::size_t>(points - 1)]) {
    GuardSample before;
    state_at(t_hit, xr_);
    evaluate(t_hit, xr_, before);
    observe(before, xr_);
    keep_point(points++, t_hit, before, qu_);
  }
  locate_step_extremes(points);
  // an analytic motion may jump at a breakpoint: start the next step from its right limit
  if (!hit && t1 == t_stop && t1 < t_end_ && !motion_.is_sampled())
    integ.refresh_derivative(sys, std::nextafter(t1, t_end_));
  return end_step(integ, sys, slot_hit, t_hit, smp[static_cast<std::size_t>(samples_)], t, x);
}

// a step's end: with no event (slot_hit < 0) the state moves to the step's end, whose guards are
// s_end; else the step is cut at the event, which fires
template <int N, int MaxN>
template <class Stepper, class System>
bool Simulator<N, MaxN>::end_step(Stepper& integ, System&& sys, int slot_hit, double t_hit,
                                  const GuardSample& s_end, double& t, State& x) {
  if (slot_hit < 0) {
    emit_rows_until(integ.t1());
    t = integ.t1();
    put(integ.x1(), x);
    s0_ = s_end;
    zero_start_.fill(false);
    release_latches(s0_);
    return true;
  }
  // land exactly on the event and act on it
  const bool inside = t_hit > integ.t0();
  if (inside) integ.restep_to(sys, t_hit);
  emit_rows_until(t_hit);
  t = t_hit;
  put(inside ? integ.x1() : integ.x0(), x);
  return fire(slot_hit, t, x);
}

// A rigid body rocking on its series takes steps as long as the series' tolerance allows, with no
// guard samples: every guard of the mode is a polynomial on the step (theta's and theta_dot's, or
// the reaction's series within its truncation), so a bound over the step rules a crossing out, and
// a guard that could cross is halved in its Bernstein form until a single crossing is bracketed
// (series_guards.hpp; docs/theory.md, "Guards of the series step by bounds"). A friction limit
// makes |F_I| a guard, which is not a polynomial: such a run keeps the sampled steps, as does a
// lift-off function that does not start armed (and a step whose lift-off the bound cannot rule out
// is taken again with samples).
template <int N, int MaxN>
bool Simulator<N, MaxN>::series_bounded() const {
  if (std::isfinite(opt_.friction_coefficient) || hold_tension_) return false;
  const auto lift = static_cast<std::size_t>(guard_slot(mode_, Guard::kLiftOff));
  return tension_ || (!zero_start_[lift] && s0_.v[lift] > 0.0);
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::advance_series(double& t, State& x) {
  const double t_stop = std::min({t_end_, motion_.next_breakpoint(t, break_cursor_), step_stop_});
  if (!count_step(t)) return false;
  auto none = [](double, const ContactState&, ContactState&) {};
  series_integ_.set_max_step(std::numeric_limits<double>::infinity());
  if (series_integ_.step(none, t_stop) != RockingSeries<ContactState>::Status::kAccepted)
    return step_collapsed(t);
  const double t0 = series_integ_.t0(), t1 = series_integ_.t1(), h = t1 - t0;
  if (opt_.progress) opt_.progress->store(t1, std::memory_order_relaxed);
  const int e = edge();
  const double sg = edge_sign(e);
  // the guards' polynomials: s theta (impact), limit - s theta (overturn), s theta_dot (peak);
  // lift-off's, F_J, below
  const double* th = series_integ_.theta_coefficients();
  const double* dth = series_integ_.theta_rate_coefficients();  // k c[k]
  const int degree = series_integ_.order();
  sp_impact_.degree = sp_overturn_.degree = degree;
  sp_peak_.degree = degree - 1;
  for (int k = 0; k <= degree; ++k) {
    const auto i = static_cast<std::size_t>(k);
    sp_impact_.c[i] = sg * th[k];
    sp_overturn_.c[i] = -sg * th[k];
    if (k < degree) sp_peak_.c[i] = sg * dth[k + 1];
  }
  sp_overturn_.c[0] += overturn_limit_[static_cast<std::size_t>(e - 1)];
  // where the floor's pressing cannot be shown to hold throughout (a lift-off may come), the
  // step is taken again with the guards sampled, as any step of a friction-limited run: the
  // reaction's enclosure settles most steps; its series (O(order^2)) only the rest
  bool reaction = false;  // the reaction's series formed on this step (reaction_polynomials)
  const ReactionRange range = series_integ_.reaction_range(dyn_.g_over_h(), h);
  if (!tension_ && !(range.fj_lo > 0.0)) {
    reaction_polynomials(h);
    reaction = true;
    if (!(sp_fj_.c[0] - sp_fj_.excursion(h) > sp_fj_.margin) &&
        !(bernstein_piece(sp_fj_, 0.0, h, sp_fj_.c[0]).min() > sp_fj_.margin)) {
      --res_.steps;
      dense_buf_ = series_integ_.x0();
      series_integ_.start(none, ctl_, t0, dense_buf_);
      series_integ_.set_max_step(ctl_.max_step);
      return advance_with(series_integ_, none, dense_buf_, t, x);
    }
  }
  // the guards at the step's end, exactly (the next step's start)
  GuardSample& se = samples_buf_[1];
  State& xe = sample_states_[1];
  put(series_integ_.x1(), xe);
  evaluate(t1, xe, se);
  // how guard k stands at the step's start
  auto start_of = [&](std::size_t k) {
    return zero_start_[k]   ? GuardStart::kZero
           : s0_.v[k] > 0.0 ? GuardStart::kArmed
                            : GuardStart::kDisarmed;
  };
  // the first crossing of each resetting guard
  const ModeSpec& spec = mode_spec(mode_);
  double t_hit = std::numeric_limits<double>::infinity();
  int slot_hit = -1, peak_slot = -1;
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const Guard guard = spec.guards[k];
    const GuardStart start = start_of(k);
    CrossingBracket b;
    int found = 0;
    switch (guard) {
      case Guard::kImpact:
        found = polynomial_bracket(sp_impact_, 0.0, h, start, b);
        break;
      case Guard::kOverturn:
        found = polynomial_bracket(sp_overturn_, 0.0, h, start, b);
        break;
      case Guard::kLiftOff:
        // lift-off needs the floor to stop pressing: ruled out where the reaction's Bernstein
        // bound keeps F_J above its truncation (it is near 1 while rocking); checked beforehand
        continue;
      case Guard::kPeak:
        peak_slot = j;  // records only: after the first resetting crossing is known
        continue;
      default:
        continue;  // the friction margin is the constant 1 without a friction limit
    }
    double when = std::numeric_limits<double>::infinity();
    if (found < 0 && guard_spec(guard).fires_if_unresolved) when = t0;
    if (found > 0) when = crossing(j, t0 + b.tl, t0 + b.tr, b.gl, b.gr);
    if (when < t_hit) {
      t_hit = when;
      slot_hit = j;
    }
  }
  const double tau_end = slot_hit >= 0 ? t_hit - t0 : h;
  // every peak up to the first resetting crossing (a long step may hold more than one)
  if (peak_slot >= 0) {
    GuardStart start = start_of(static_cast<std::size_t>(peak_slot));
    double a = 0.0;
    CrossingBracket b;
    while (a < tau_end && polynomial_bracket(sp_peak_, a, tau_end, start, b) > 0) {
      const double tp = crossing(peak_slot, t0 + b.tl, t0 + b.tr, b.gl, b.gr);
      if (!(tp - t0 > a) || tp > t0 + tau_end) break;
      record(tp);
      a = tp - t0;
      start = GuardStart::kCrossed;
    }
  }
  series_extremes(t0, tau_end, slot_hit >= 0, range, reaction);
  if (slot_hit < 0) observe(se, xe);
  if (!end_step(series_integ_, none, slot_hit, t_hit, se, t, x)) return false;
  // where the floor has come to rest (a record's or a pulse's end, start_arc), the rest of the arc
  // in closed form
  if (slot_hit < 0) {
    dense_buf_ = x.head(2 * n_ + 4);
    start_arc(t, dense_buf_);
  }
  return true;
}

// The closed form takes a rigid body's rocking (docs/theory.md, "Free rocking in closed form")
// where the floor is at rest from t on, no friction limit can make it slide, and the arc stays
// within what the rocking mode assumes: below the upright energy (no overturn), the floor pressing
// with at least kPressingFraction of the weight throughout (no lift-off; F_J is a quadratic in
// cos(phi) on the arc). Elsewhere the series steps it, as it does near those limits.
template <int N, int MaxN>
bool Simulator<N, MaxN>::start_arc(double t, const ContactState& x) {
  if (n_ != 0 || !opt_.methods.closed_form_free_rocking || t < quiet_from_ ||
      std::isfinite(opt_.friction_coefficient) || hold_tension_)
    return false;
  const int e = edge();
  const double a = dyn_.alpha(e);
  arc_.set_pivot(a, dyn_.inertia(a, q_), dyn_.g_over_h());
  if (!arc_.start(t, x, edge_sign(e))) return false;
  // F_J over the whole arc, cos(phi) from cos(alpha_t) = 1/c to cos(phi_m) = cm
  if (!(arc_.least_press(arc_.floor_cos(), arc_.energy_cosine()) >= kPressingFraction))
    return false;
  stepping_ = Stepping::kArc;
  return true;
}

// One step of the closed form: to the impact, or to the run's end. The peak inside is recorded;
// the extremes are the step's ends' and its interior critical points' (arc_extremes).
template <int N, int MaxN>
bool Simulator<N, MaxN>::advance_arc(double& t, State& x) {
  const double t_stop = std::min({t_end_, motion_.next_breakpoint(t, break_cursor_), step_stop_});
  if (!count_step(t)) return false;
  arc_.step(t_stop);
  const double t0 = arc_.t0(), t1 = arc_.t1();
  if (opt_.progress) opt_.progress->store(t1, std::memory_order_relaxed);
  const double tp = arc_.peak_time();
  if (tp > t0 && tp <= t1 && guard_slot(mode_, Guard::kPeak) >= 0) {
    GuardSample s;
    state_at(tp, xr_);
    arc_sample(tp, xr_, arc_.sin_phi_m(), arc_.energy_cosine(), s);
    record_sample(s, xr_);
  }
  // the step's end, before the reset where the impact ends it (a point of the motion too)
  GuardSample& se = samples_buf_[1];
  State& xe = sample_states_[1];
  put(arc_.x1(), xe);
  const bool impact = t1 == arc_.impact_time();
  if (impact)
    arc_sample(t1, xe, arc_.floor_sin(), arc_.floor_cos(), se);
  else
    evaluate(t1, xe, se);
  observe(se, xe);
  arc_extremes(t0, t1);
  auto none = [](double, const ContactState&, ContactState&) {};
  return end_step(arc_, none, impact ? guard_slot(mode_, Guard::kImpact) : -1, t1, se, t, x);
}

// On the arc the reaction depends on phi = alpha_t - |theta| alone (theta_dot^2 by the energy):
// F_I = sin(phi) (3 cos(phi) - 2 cm)/kappa, F_J = 1 - (1 - 3 cos^2 + 2 cm cos)/kappa and the
// moment alpha (cos(theta) - lambda (beta sin(phi) + 2 (cm - cos(phi)))), kappa = m/c^2,
// lambda = c/m, c^2 = 1 + alpha^2 (tools/derive/derive.py, derive_free_rocking_arc). The step
// spans phi over [lo, hi] (lo = phi_m where the peak is inside); its ends are observed, and
// within it F_I's and the moment's one critical point each, where the value there could raise the
// extreme. The friction demand |F_I|/F_J is bounded by max |F_I| over min F_J and searched in phi
// only where that bound could raise it.
template <int N, int MaxN>
void Simulator<N, MaxN>::arc_extremes(double t0, double t1) {
  if (!(t1 > t0)) return;
  const Extremes& ex = res_.extremes;
  const double sg = edge_sign(edge());
  const double cm = arc_.energy_cosine(), at = arc_.alpha_t();
  const double ph0 = at - sg * arc_.x0()(0), ph1 = at - sg * arc_.x1()(0);
  const double tp = arc_.peak_time();
  const bool peak = tp > t0 && tp < t1;
  const double lo = peak ? at - arc_.peak_tilt() : std::min(ph0, ph1);
  const double hi = std::max(ph0, ph1);
  const double mg = dyn_.mass() * dyn_.g(), mgh = mg * dyn_.height();
  // sin(phi) and cos(phi) at the ends: at the peak and on the floor these are known
  // (sin(phi_m) = 2 s k, cos(phi_m) = cm; beta/c and 1/c), elsewhere one sincos
  struct Trig {
    double s, c;
  };
  auto trig = [](double ph) { return Trig{std::sin(ph), std::cos(ph)}; };
  const Trig tlo = peak ? Trig{arc_.sin_phi_m(), cm} : trig(lo);
  const Trig thi = hi == at ? Trig{arc_.floor_sin(), arc_.floor_cos()} : trig(hi);
  auto at_phi = [&](double ph) { observe_at(arc_.time_of(ph)); };
  // phi within (lo, hi), by its cosine: cos falls on (0, pi/2)
  auto inside = [&](double cp) { return cp < tlo.c && cp > thi.c; };
  // F_I: d/dphi sin (3 cos - 2 cm) = 6 cos^2 - 2 cm cos - 3, one root in (0, pi/2)
  double fi_max = std::max(arc_.shear(tlo.s, tlo.c), arc_.shear(thi.s, thi.c));
  const double c_fi = (cm + std::sqrt(cm * cm + 18.0)) / 6.0;
  if (inside(c_fi)) {
    const double fi = arc_.shear(std::sqrt(1.0 - c_fi * c_fi), c_fi);
    fi_max = std::max(fi_max, fi);
    if (mg * fi > ex.max_base_shear) at_phi(std::acos(c_fi));
  }
  // the moment: its derivative cos (beta/c - lambda beta) - sin (1/c + 2 lambda) vanishes once
  const double ph_mo = arc_.phi_moment();
  if (ph_mo > lo && ph_mo < hi) {
    const Trig t = trig(ph_mo);
    if (mgh * arc_.moment(t.s, t.c) > ex.max_overturning_moment) at_phi(ph_mo);
  }
  // the friction demand
  const double fj_min = arc_.least_press(thi.c, tlo.c);
  const double r = ex.max_friction_demand;
  if (fj_min >= kPressingFraction && fi_max / fj_min <= r) return;
  auto demand = [&](double ph) {
    const Trig t = trig(ph);
    const double f = arc_.press(t.c);
    return f >= kPressingFraction ? arc_.shear(t.s, t.c) / f : 0.0;
  };
  const double ph_r = lo + polynomial_argmax([&](double d) { return demand(lo + d); }, hi - lo);
  if (demand(ph_r) > r) at_phi(ph_r);
}

// the floor reaction's and the overturning moment's series on a series step of length h
template <int N, int MaxN>
void Simulator<N, MaxN>::reaction_polynomials(double h) {
  series_integ_.reaction_series(dyn_.g_over_h(), sp_fi_.c.data(), sp_fj_.c.data(),
                                sp_moment_.c.data());
  // the reaction's series is known to theta's power: its last two terms at h, doubled, stand for
  // the rest
  for (StepPolynomial* p : {&sp_fi_, &sp_fj_, &sp_moment_}) {
    p->degree = series_integ_.order();
    double hk = 1.0, tail = 0.0;
    for (int k = 0; k <= p->degree; ++k, hk *= h)
      if (k + 1 >= p->degree) tail += std::abs(p->c[static_cast<std::size_t>(k)]) * hk;
    p->margin = 2.0 * tail;
  }
}

// the extremes over [t0, t0 + tau_end] of a series step: a quantity whose bound there could
// exceed its extreme so far (the shear, the overturning moment, F_I over F_J for the friction
// demand, the input work for the energy scale) is located on its polynomial and observed from the
// exact state there; theta's are the peaks'. The end of a step without an event is observed by the
// loop; where an event ends it, the state just before the reset is one of the motion's too.
template <int N, int MaxN>
void Simulator<N, MaxN>::series_extremes(double t0, double tau_end, bool event,
                                         const ReactionRange& range, bool& reaction) {
  if (!(tau_end > 0.0)) return;
  const Extremes& ex = res_.extremes;
  const double mg = dyn_.mass() * dyn_.g(), mgh = mg * dyn_.height();
  double seen = -1.0;  // the last point observed here: quantities largest at one point share it
  auto at = [&](double tau) {
    if (tau == tau_end && !event) return;  // the step's end: the loop observes it
    if (tau == seen) return;
    seen = tau;
    observe_at(t0 + tau);
  };
  // bounds over [0, tau_end] by the Bernstein form (within the reaction series' truncation)
  // (the coefficients' bound first: it settles most steps for less)
  auto exceeds = [&](const StepPolynomial& p, double scale, double extreme) {
    return scale * p.abs_bound(tau_end) > extreme &&
           scale * (bernstein_piece(p, 0.0, tau_end, p.c[0]).max_abs() + p.margin) > extreme;
  };
  const double r = ex.max_friction_demand;
  // the reaction's enclosure over the step first (O(order)): where it keeps the shear, the moment
  // and the friction demand within their extremes so far, as on most steps, its series is not
  // needed
  const ReactionReach reach = reaction_reach(std::max(std::abs(range.fi_lo), std::abs(range.fi_hi)),
                                             range.moment_abs, range.fj_lo, range.fj_hi);
  if (tension_) {
    // the floor pulls on the held pivot: its largest pull and the time it pulls, on F_J's series
    if (!reaction) {
      reaction_polynomials(series_integ_.t1() - series_integ_.t0());
      reaction = true;
    }
    constexpr int kParts = 16;
    std::array<double, kParts + 1> ts{}, fs{};
    for (int k = 0; k <= kParts; ++k) {
      ts[static_cast<std::size_t>(k)] = tau_end * k / kParts;
      fs[static_cast<std::size_t>(k)] = sp_fj_.value(ts[static_cast<std::size_t>(k)]);
    }
    res_.extremes.tension_time += time_negative(ts.data(), fs.data(), kParts + 1,
                                                [&](double tau) { return sp_fj_.value(tau); });
    if (reach.pull) at(polynomial_argmax([&](double tau) { return -sp_fj_.value(tau); }, tau_end));
  }
  if (reach.shear || reach.moment || reach.demand) {
    if (!reaction) {
      reaction_polynomials(series_integ_.t1() - series_integ_.t0());
      reaction = true;
    }
    // F_I's and F_J's Bernstein forms serve the shear and the friction demand: formed once, where
    // the coefficients' bounds do not settle either
    BernsteinPiece bi, bj;
    bool formed = false;
    auto form = [&] {
      if (formed) return;
      bi = bernstein_piece(sp_fi_, 0.0, tau_end, sp_fi_.c[0]);
      bj = bernstein_piece(sp_fj_, 0.0, tau_end, sp_fj_.c[0]);
      formed = true;
    };
    if (mg * sp_fi_.abs_bound(tau_end) > ex.max_base_shear) {
      form();
      if (mg * (bi.max_abs() + sp_fi_.margin) > ex.max_base_shear)
        at(polynomial_argmax([&](double tau) { return std::abs(sp_fi_.value(tau)); }, tau_end));
    }
    if (exceeds(sp_moment_, mgh, ex.max_overturning_moment))
      at(polynomial_argmax([&](double tau) { return std::abs(sp_moment_.value(tau)); }, tau_end));
    // F_I over F_J within the largest demand r so far: by the coefficients' bounds, else where
    // |F_I| - r F_J <= 0 throughout by Bernstein's (linear in the coefficients)
    const double fj_swing = sp_fj_.excursion(tau_end) + sp_fj_.margin;
    const double fj_lo = sp_fj_.c[0] - fj_swing, fj_hi = sp_fj_.c[0] + fj_swing;
    bool within = fj_hi < kPressingFraction ||
                  (fj_lo >= kPressingFraction && sp_fi_.abs_bound(tau_end) / fj_lo <= r);
    if (!within) {
      form();
      double worst = -std::numeric_limits<double>::infinity();
      for (int i = 0; i <= bi.degree; ++i) {
        const auto k = static_cast<std::size_t>(i);
        worst = std::max(worst, std::abs(bi.b[k]) - r * bj.b[k]);
      }
      within = worst + sp_fi_.margin + r * sp_fj_.margin <= 0.0;
    }
    if (!within)
      at(polynomial_argmax(
          [&](double tau) {
            const double f = sp_fj_.value(tau);
            return f >= kPressingFraction ? std::abs(sp_fi_.value(tau)) / f : 0.0;
          },
          tau_end));
  }
  sp_work_.degree = series_integ_.order() - 1;
  const double* w = series_integ_.work_coefficients();
  for (int k = 0; k <= sp_work_.degree; ++k) sp_work_.c[static_cast<std::size_t>(k)] = w[k];
  if (exceeds(sp_work_, 1.0, rec_.energy_scale()))
    at(polynomial_argmax([&](double tau) { return std::abs(sp_work_.value(tau)); }, tau_end));
}

// a flexible body in full contact under a sampled record, walked piece by piece from a record
// sample (docs/theory.md, "Exact propagation in full contact"): true when the walk can start at t
template <int N, int MaxN>
bool Simulator<N, MaxN>::can_walk(double t) const {
  if (stepping_ != Stepping::kExact || !opt_.methods.full_contact_walk || !motion_.is_sampled())
    return false;
  if (t < fine_until_ - 1e-12 * std::max(1.0, t)) return false;
  if (tension_ || hold_tension_) return false;
  const ModeSpec& spec = mode_spec(mode_);
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    if (zero_start_[k] || !(s0_.v[k] > 0.0)) return false;
  }
  const std::vector<double>& ts = motion_.times();
  return t >= ts.front() && t < ts.back();
}

// The walk: one exact update per piece (a record interval, or an equal part of it within
// ContactPropagator::kWalkPhase of the fastest mode), with the guards at its ends from
// evaluate(). The guards are quadratic in the modal state and linear in the base acceleration,
// and the piece bounds their excursion E from the chord between its ends
// (ContactPropagator::walk_excursion), so f >= min(f(0), f(h)) - E throughout. Where that stays
// positive for every guard no crossing lies in the piece; else the piece is halved until the
// bound clears or a guard is found <= 0, and the stepped propagation locates the crossing there.
// The extremes are located the same way: a piece whose bound could raise one is searched
// (locate_extremes). A quiet piece (walk_quiet: bounds on the values themselves clear every guard
// and extreme) is not evaluated at its end at all.
template <int N, int MaxN>
bool Simulator<N, MaxN>::advance_walk(double& t, State& x) {
  const std::vector<double>& ts = motion_.times();
  const std::vector<double>& hx = motion_.horizontal();
  const std::vector<double>& vy = motion_.vertical();
  const bool vertical = vy.size() == ts.size();
  const double g = dyn_.g();
  std::size_t i = scan_index_;
  if (i >= ts.size()) i = ts.size() - 1;
  while (i > 0 && ts[i] > t) --i;
  while (i + 1 < ts.size() && ts[i + 1] <= t) ++i;
  prop_.walk_start(x);
  xw_ = x;
  GuardSample& sa = samples_buf_[0];
  GuardSample& sb = samples_buf_[1];
  sa = s0_;
  bool sa_due = false;  // sa is not yet evaluated at the piece's start (after a quiet piece)
  const double cap = prop_.walk_cap();
  for (; i + 1 < ts.size() && ts[i + 1] <= t_end_; ++i) {
    if (!count_step(t)) {
      x = xw_;
      return false;
    }
    const double tb = ts[i + 1], span = ts[i + 1] - ts[i];
    const BaseAcceleration slope{(hx[i + 1] - hx[i]) / span,
                                 vertical ? (vy[i + 1] - vy[i]) / span : 0.0};
    // most intervals are one piece: std::ceil is a libm call without SSE4.1 (above one span,
    // spans - 1e-9 > 0, so the ceiling is at least 1)
    const double spans = (tb - t) / cap;
    const double pieces = spans <= 1.0 ? 1.0 : std::ceil(spans - 1e-9);
    const double hp = (tb - t) / pieces;
    const double ti = t;
    for (int k = 0; k < static_cast<int>(pieces); ++k) {
      const double tp0 = t, tp1 = k + 1 == static_cast<int>(pieces) ? tb : ti + hp * (k + 1);
      const double h = tp1 - tp0;
      const BaseAcceleration a0{hx[i] + slope.x * (tp0 - ts[i]),
                                vertical ? vy[i] + slope.y * (tp0 - ts[i]) : 0.0};
      prop_.walk_piece(h, a0, slope);
      xe_ = xw_;
      prop_.walk_state(xe_);
      // the forcing over the piece (over g; a_y = 1 + Y''/g): max |a_x|, a_y at its ends
      const double ax = std::max(std::abs(a0.x), std::abs(a0.x + slope.x * h)) / g;
      const double ay0 = 1.0 + a0.y / g, ay1 = 1.0 + (a0.y + slope.y * h) / g;
      if (walk_quiet(ax, ay0, ay1)) {
        // no guard near zero and no extreme within reach anywhere in the piece: its end is not
        // evaluated (the energies' scale still follows the ends)
        rec_.observe_energy(xe_(iw()), xe_(id()));
        emit_walk_rows(tp0, tp1);
        xw_ = xe_;
        sa_due = true;
        t = tp1;
        if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
        continue;
      }
      if (sa_due) {
        evaluate(tp0, xw_, sa);
        sa_due = false;
      }
      evaluate(tp1, xe_, sb);
      // the guards' excursion between the piece's ends
      walk_forcing_ = {ax, std::max(std::abs(ay0), std::abs(ay1)), std::abs(slope.x) / g,
                       std::abs(slope.y) / g};
      const Excursion c = walk_excursion(h);
      if (!guards_clear(sa, sb, c)) {
        // a crossing may lie in this piece: halve it until the bound clears every part or a
        // guard is found <= 0 at a part's end
        double ba = 0.0, bb = h;
        const int found = walk_search(tp0, 0.0, h, sa, sb, 40, ba, bb);
        if (found != 0) {
          scan_index_ = i;
          fine_until_ = tb;
          if (found == 1 && ba > 0.0) {
            // the stepped propagation from the bracket's start, its first step ending at the
            // bracket's end (where a guard is <= 0): it locates the crossing there
            prop_.walk_start(xw_);
            prop_.walk_piece(ba, a0, slope, false);
            x = xw_;
            prop_.walk_state(x);
            t = tp0 + ba;
            evaluate(t, x, s0_);
            // the extremes before the bracket, located as in a whole piece
            xe_ = x;
            locate_extremes(tp0, ba, sa, s0_, walk_excursion(ba));
          } else {
            x = xw_;
            s0_ = sa;
          }
          if (found == 1) step_stop_ = tp0 + bb;
          prop_.start(t, x);
          return true;
        }
      }
      locate_extremes(tp0, h, sa, sb, c);
      emit_walk_rows(tp0, tp1);
      observe(sb, xe_);
      xw_ = xe_;
      sa = sb;
      t = tp1;
      if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
    }
  }
  scan_index_ = i;
  x = xw_;
  if (sa_due) evaluate(t, xw_, sa);
  s0_ = sa;
  release_latches(s0_);
  prop_.start(t, x);
  // the rest (past the record's last sample within t_end) goes to the stepped propagation
  fine_until_ = t_end_;
  return true;
}

// the excursion bounds over any part of length w of the walk's piece, under its forcing
template <int N, int MaxN>
typename Simulator<N, MaxN>::Excursion Simulator<N, MaxN>::walk_excursion(double w) const {
  const auto& f = walk_forcing_;
  return prop_.walk_excursion(w, f[0], f[1], f[2], f[3]);
}

// the full-contact guards over a part of the walk's piece with values sa, sb at its ends cannot
// cross there: each stays above min(f(a), f(b)) - E > 0 (E: its excursion bound on that part)
template <int N, int MaxN>
bool Simulator<N, MaxN>::guards_clear(const GuardSample& sa, const GuardSample& sb,
                                      const Excursion& e) const {
  constexpr ContactMode m = ContactMode::kFullContact;
  const double mu = opt_.friction_coefficient;
  auto clear = [&](std::size_t j, double excursion) {
    const double lo = std::min(sa.v[j], sb.v[j]) - excursion;
    return lo > 1e-12 * (1.0 + std::abs(sa.v[j]) + std::abs(sb.v[j]));
  };
  return clear(kSlot<m, Guard::kUpliftEdge1>, e.u1) && clear(kSlot<m, Guard::kUpliftEdge2>, e.u2) &&
         clear(kSlot<m, Guard::kLiftOff>, e.fj) &&
         (!std::isfinite(mu) || clear(kSlot<m, Guard::kFrictionLimit>, mu * e.fj + e.fi));
}

// the walk's last piece (max |a_x| = ax, a_y from ay0 to ay1, over g) can neither cross a
// full-contact guard nor raise an extreme anywhere: the bounds on the values themselves over the
// piece (ContactPropagator::walk_reach) keep every guard above zero (U_1 = R(0) + alpha_1 F_J and
// U_2 = alpha_2 F_J - R(0) are >= alpha_k min F_J - max|R(0)|), and every reported quantity
// within its extreme so far
template <int N, int MaxN>
bool Simulator<N, MaxN>::walk_quiet(double ax, double ay0, double ay1) const {
  const auto r = prop_.walk_reach(ax, std::min(ay0, ay1), std::max(ay0, ay1));
  const double margin = 1e-12 * (1.0 + r.fj_hi + r.moment);
  if (!(r.fj_lo > margin && dyn_.alpha1() * r.fj_lo - r.moment > margin &&
        dyn_.alpha2() * r.fj_lo - r.moment > margin))
    return false;
  const double mu = opt_.friction_coefficient;
  if (std::isfinite(mu) && !(mu * r.fj_lo - r.fi > margin)) return false;
  const ReactionReach reach = reaction_reach(r.fi, r.moment, r.fj_lo, r.fj_hi);
  if (reach.shear || reach.moment || reach.demand || reach.pull) return false;
  const Extremes& ex = res_.extremes;
  for (int j = 0; j < n_; ++j)
    if (prop_.walk_q_reach(j) > ex.max_abs_q(j)) return false;
  return true;
}

// which reported reaction quantities (the shear, the overturning moment, the friction demand as
// Recorder::observe forms it) could exceed their extremes so far, for values within |F_I| <=
// fi_top, |R(0)| <= moment_top and fj_lo <= F_J <= fj_hi (evaluate()'s units)
template <int N, int MaxN>
typename Simulator<N, MaxN>::ReactionReach Simulator<N, MaxN>::reaction_reach(double fi_top,
                                                                              double moment_top,
                                                                              double fj_lo,
                                                                              double fj_hi) const {
  const Extremes& ex = res_.extremes;
  const double mg = dyn_.mass() * dyn_.g();
  return {mg * fi_top > ex.max_base_shear,
          mg * dyn_.height() * moment_top > ex.max_overturning_moment,
          fj_hi >= kPressingFraction &&
              !(fj_lo >= kPressingFraction && fi_top / fj_lo <= ex.max_friction_demand),
          tension_ && -mg * fj_lo > ex.max_pivot_pull};
}

// [a, b] of the walk's piece from tp0 (guards sa, sb at its ends, every one > 0 at a), halved
// until the bound clears each part (0), a guard is <= 0 at a part's end b_out with all > 0 at
// its start a_out (1), or `depth` halvings leave a part unresolved (2, a grazing guard)
template <int N, int MaxN>
int Simulator<N, MaxN>::walk_search(double tp0, double a, double b, const GuardSample& sa,
                                    const GuardSample& sb, int depth, double& a_out,
                                    double& b_out) {
  if (guards_clear(sa, sb, walk_excursion(b - a))) return 0;
  const ModeSpec& spec = mode_spec(mode_);
  for (int j = 0; j < spec.count; ++j) {
    if (!(sb.v[static_cast<std::size_t>(j)] > 0.0)) {
      a_out = a;
      b_out = b;
      return 1;
    }
  }
  if (depth == 0) {
    a_out = a;
    b_out = b;
    return 2;
  }
  const double mid = 0.5 * (a + b);
  GuardSample sm;
  xr_ = xw_;
  prop_.walk_dense(mid, xr_);
  evaluate(tp0 + mid, xr_, sm);
  const int left = walk_search(tp0, a, mid, sa, sm, depth - 1, a_out, b_out);
  if (left != 0) return left;
  return walk_search(tp0, mid, b, sm, sb, depth - 1, a_out, b_out);
}

// the rows due in the walk's piece [tp0, tp1] (state xw_ at tp0, xe_ at tp1): one at the piece's
// end from its state, others from the propagator's exact steps over the piece
template <int N, int MaxN>
void Simulator<N, MaxN>::emit_walk_rows(double tp0, double tp1) {
  if (opt_.output_dt <= 0.0) return;
  const double to = static_cast<double>(next_output_) * opt_.output_dt;
  if (to > tp1 || to > t_end_ * (1.0 + 1e-14)) return;
  if (to >= tp1 - 1e-12 * std::max(1.0, tp1)) {
    emit_row(to, xe_);
    ++next_output_;
    return;
  }
  prop_.start(tp0, xw_);
  auto none = [](double, const State&, State&) {};
  while (prop_.t1() < tp1) {
    prop_.step(none, tp1);
    emit_rows_until(prop_.t1());
  }
}

// the extremes the piece [tp0, tp0 + h] could raise between its ends (by the excursion bounds
// `e`), located: the exact solution at the piece's kept points, then Brent's search about the
// largest of each such quantity; every point searched is observed (by a deformation's search,
// its own value), so the extremes stay values the motion reaches
template <int N, int MaxN>
void Simulator<N, MaxN>::locate_extremes(double tp0, double h, const GuardSample& sa,
                                         const GuardSample& sb, const Excursion& e) {
  const Extremes& ex = res_.extremes;
  // which quantities might exceed their extreme within the piece: -1 none, j < n: q_j,
  // n: shear, n + 1: moment, n + 2: friction demand, n + 3: the floor's pull on a held pivot
  std::vector<int>& wanted = wanted_;
  int count = 0;
  // u_j could exceed its extreme within the excursion bound over a length w of a value `top`
  auto deformation_reach = [&](int j, double top, double w) {
    return top + prop_.walk_q_excursion(j, w) > ex.max_abs_q(j);
  };
  // the reaction's range over the points seen: the piece's ends, then its kept points too
  double fi_top = std::max(std::abs(sa.fi), std::abs(sb.fi));
  double moment_top = std::max(std::abs(sa.moment), std::abs(sb.moment));
  double fj_lo = std::min(sa.fj, sb.fj), fj_hi = std::max(sa.fj, sb.fj);
  // which reaction quantities could exceed their extremes within excursion bounds r of that range
  auto range_reach = [&](const Excursion& r) {
    return reaction_reach(fi_top + r.fi, moment_top + r.moment, fj_lo - r.fj, fj_hi + r.fj);
  };
  ua_.noalias() = Dyn::mv(to_user_, xw_.segment(iq(), n_));
  ub_.noalias() = Dyn::mv(to_user_, xe_.segment(iq(), n_));
  for (int j = 0; j < n_; ++j)
    if (deformation_reach(j, std::max(std::abs(ua_(j)), std::abs(ub_(j))), h))
      wanted[static_cast<std::size_t>(count++)] = j;
  const ReactionReach reach = range_reach(e);
  if (reach.shear) wanted[static_cast<std::size_t>(count++)] = n_;
  if (reach.moment) wanted[static_cast<std::size_t>(count++)] = n_ + 1;
  if (reach.demand) wanted[static_cast<std::size_t>(count++)] = n_ + 2;
  if (reach.pull) wanted[static_cast<std::size_t>(count++)] = n_ + 3;
  if (count == 0) return;
  // the state at tau in the piece, and the guards where a reaction's extreme is sought (they
  // come after the deformations in `wanted`), observed on the way
  const bool guards = wanted[static_cast<std::size_t>(count - 1)] >= n_;
  GuardSample s;
  auto visit = [&](double tau) {
    prop_.walk_dense(tau, xr_);
    if (!guards) return;
    evaluate(tp0 + tau, xr_, s);
    observe(s, xr_);
  };
  // the quantity `k` of the point visited last
  auto quantity = [&](int k) { return point_quantity(k, s, xr_); };
  xr_ = xw_;
  constexpr int kPoints = ContactPropagator<N, MaxN, State>::kPoints;
  std::vector<double>& best = best_;
  std::vector<double>& at = best_at_;
  std::fill(best.begin(), best.end(), -1.0);
  for (int p = 1; p < kPoints; ++p) {
    const double tau = h * p / kPoints;
    visit(tau);
    if (guards) {
      fi_top = std::max(fi_top, std::abs(s.fi));
      moment_top = std::max(moment_top, std::abs(s.moment));
      fj_lo = std::min(fj_lo, s.fj);
      fj_hi = std::max(fj_hi, s.fj);
    }
    for (int q = 0; q < count; ++q) {
      const double v = quantity(wanted[static_cast<std::size_t>(q)]);
      if (v > best[static_cast<std::size_t>(q)]) {
        best[static_cast<std::size_t>(q)] = v;
        at[static_cast<std::size_t>(q)] = tau;
      }
    }
  }
  // a quantity is searched further only where a part between two neighbouring points (the ends
  // and the kept points, all observed) could still raise its extreme: the largest value at the
  // points plus the excursion bound over a part of length h / kPoints, whose curvature term
  // (w^2/8 max|f''|) is 64 times smaller than the one over the whole piece that asked for it
  const double part = h / kPoints;
  ReactionReach part_reach;
  if (guards) part_reach = range_reach(walk_excursion(part));
  // the largest value of each about its best kept point, from its jet: a deformation u_j from its
  // own (ContactPropagator::walk_q_jet), each point observed; a reaction from q's derivatives
  // (guard_jet), the point found then observed through evaluate() as every other sample
  for (int q = 0; q < count; ++q) {
    const int k = wanted[static_cast<std::size_t>(q)];
    const double tau = at[static_cast<std::size_t>(q)];
    const double lo = std::max(0.0, tau - h / kPoints), hi = std::min(h, tau + h / kPoints);
    if (k < n_) {
      rec_.observe_deformation(k, best[static_cast<std::size_t>(q)]);
      if (!deformation_reach(
              k, std::max({best[static_cast<std::size_t>(q)], std::abs(ua_(k)), std::abs(ub_(k))}),
              part))
        continue;
      auto jet = [&](double t) {
        const std::array<double, 3> u = prop_.walk_q_jet(t, k);
        rec_.observe_deformation(k, std::abs(u[0]));
        return u;
      };
      largest_near(jet, tau, lo, hi);
    } else if (k == n_       ? part_reach.shear
               : k == n_ + 1 ? part_reach.moment
               : k == n_ + 2 ? part_reach.demand
                             : part_reach.pull) {
      visit(largest_near([&](double t) { return guard_jet(k, t); }, tau, lo, hi));
    }
  }
}

template <int N, int MaxN>
void Simulator<N, MaxN>::keep_point(int p, double t, const GuardSample& s, const Vec& u) {
  const auto pp = static_cast<std::size_t>(p);
  point_t_[pp] = t;
  Quantities& v = point_vals_[pp];
  if constexpr (N == Eigen::Dynamic)
    v.head(n_) = u.array().abs();
  else if constexpr (N != 0)
    v.template head<N>() = u.array().abs();
  v(n_) = std::abs(s.fi);
  v(n_ + 1) = std::abs(s.moment);
  v(n_ + 2) = friction_demand(s);
  v(n_ + 3) = pull_of(s);
  point_pressing_[pp] = s.fj >= kPressingFraction;
  point_fj_[pp] = s.fj;
}

template <int N, int MaxN>
inline double Simulator<N, MaxN>::point_quantity(int k, const GuardSample& s,
                                                 const State& x) const {
  if (k < n_) {
    if constexpr (N != 0) return std::abs(to_user_.row(k).dot(x.segment(iq(), n_)));
  }
  if (k == n_) return std::abs(s.fi);
  if (k == n_ + 1) return std::abs(s.moment);
  if (k == n_ + 2) return friction_demand(s);
  return pull_of(s);
}

template <int N, int MaxN>
double Simulator<N, MaxN>::step_quantity(int k, double t) {
  state_at(t, xr_);
  GuardSample s;
  if (k >= n_) evaluate(t, xr_, s);  // a deformation needs the state alone
  return point_quantity(k, s, xr_);
}

// A step's quantities (|u_j|, |F_I|, |moment|, friction demand) peak between its observed points:
// located by locate_peaks_between (step_extremes.hpp), each value through the guards' own
// evaluation and each peak observed (evaluate() there, every quantity folded)
template <int N, int MaxN>
void Simulator<N, MaxN>::locate_step_extremes(int points) {
  // the time the floor pulls on the held pivot, its sign changes between the points located
  if (tension_) {
    GuardSample s;
    res_.extremes.tension_time +=
        time_negative(point_t_.data(), point_fj_.data(), points, [&](double t) {
          state_at(t, xr_);
          evaluate(t, xr_, s);
          return s.fj;
        });
  }
  // the friction demand counts only while the floor presses with kPressingFraction of the weight,
  // and rises toward that limit before the floor lets go: its peak lies at the switch
  for (int p = 1; p < points; ++p) {
    const auto pp = static_cast<std::size_t>(p);
    const bool pressed_before = point_pressing_[pp - 1];
    if (pressed_before == point_pressing_[pp]) continue;
    GuardSample s;
    observe_at(bisect_switch(point_t_[pp - 1], point_t_[pp], pressed_before, [&](double t) {
      state_at(t, xr_);
      evaluate(t, xr_, s);
      return s.fj >= kPressingFraction;
    }));
  }
  if (points < 3) return;
  const Extremes& ex = res_.extremes;
  const double mg = dyn_.mass() * dyn_.g(), mgh = mg * dyn_.height();
  if constexpr (N != 0) point_extreme_.head(n_) = ex.max_abs_q.array();
  point_extreme_(n_) = ex.max_base_shear / mg;
  point_extreme_(n_ + 1) = ex.max_overturning_moment / mgh;
  point_extreme_(n_ + 2) = ex.max_friction_demand;
  point_extreme_(n_ + 3) = ex.max_pivot_pull / mg;
  locate_peaks_between(
      point_t_.data(), point_vals_.data(), points, point_extreme_,
      [this](int k, double t) { return step_quantity(k, t); }, [this](double t) { observe_at(t); });
}

// The largest |f| in [lo, hi] about tau, the kept point of the walk's piece where |f| is largest
// of the kept points, from f's jet (f, f', f'') at any point of the piece: a root of s f'
// (s = sign f(tau)) from + to -, bracketed by tau and the end of [lo, hi] that s f'(tau) points
// to, found by Newton's method safeguarded by bisection. Where s f' keeps its sign to that end,
// |f| rises to it where it is larger there (a piece's end); else it rose and fell back in
// between, where Brent's search finds that maximum. Newton's method stops when a step is within
// 16 bits of [lo, hi], Brent's tolerance, so |f| there is within |f''| (2^-16 (hi - lo))^2 / 2 of
// the maximum: about three jets where Brent's search took a dozen values. Returns where it
// ended: the maximum found, or the end |f| rises to.
template <int N, int MaxN>
template <class Jet>
double Simulator<N, MaxN>::largest_near(Jet&& jet, double tau, double lo, double hi) {
  std::array<double, 3> f = jet(tau);
  const double s = f[0] < 0.0 ? -1.0 : 1.0;
  if (s * f[1] == 0.0) return tau;                      // stationary at the kept point
  const bool rising = s * f[1] > 0.0;                   // the maximum lies toward hi
  double a = rising ? tau : lo, b = rising ? hi : tau;  // s f' > 0 at a, < 0 at b
  const double end_at = rising ? hi : lo;
  const std::array<double, 3> end = jet(end_at);
  if (rising ? !(s * end[1] < 0.0) : !(s * end[1] > 0.0)) {
    if (s * end[0] >= s * f[0]) return end_at;
    std::uintmax_t iterations = 40;
    return boost::math::tools::brent_find_minima([&](double t) { return -std::abs(jet(t)[0]); }, lo,
                                                 hi, 16, iterations)
        .first;
  }
  const double tol = std::ldexp(hi - lo, -16);
  for (int it = 0; it < 64; ++it) {
    const double newton = tau - f[1] / f[2];
    const bool inside = s * f[2] < 0.0 && newton > a && newton < b;
    const double next = inside ? newton : 0.5 * (a + b);
    if (std::abs(next - tau) <= tol) break;
    tau = next;
    f = jet(tau);
    if (s * f[1] > 0.0) {
      a = tau;
    } else {
      b = tau;
    }
  }
  return tau;
}

// The reaction quantity k of locate_extremes (n: F_I, n + 1: the moment R(0) about the c.g.
// projection, n + 2: F_I/F_J) and its first two time derivatives at tau within the walk's piece,
// in evaluate()'s units: Dynamics::full_contact_reaction_rates along q's exact derivatives
// (ContactPropagator::walk_q_derivatives), the base acceleration linear in the piece, and F_I/F_J
// by the quotient rule.
template <int N, int MaxN>
std::array<double, 3> Simulator<N, MaxN>::guard_jet(int k, double tau) {
  prop_.walk_q_derivatives(tau, qjet_);
  const auto r = dyn_.full_contact_reaction_rates(qjet_, prop_.walk_base(tau), prop_.walk_slope());
  if (k == n_) return r.fi;
  if (k == n_ + 1) return r.moment;
  if (k == n_ + 3) return {-r.fj[0], -r.fj[1], -r.fj[2]};
  const std::array<double, 3>&fi = r.fi, &fj = r.fj;
  const double d = fi[0] / fj[0], d1 = (fi[1] - d * fj[1]) / fj[0];
  return {d, d1, (fi[2] - d * fj[2] - 2.0 * d1 * fj[1]) / fj[0]};
}

// a rigid body in full contact does not move, and its guards (uplift about either edge, lift-off,
// friction margin) depend on the base acceleration alone, linearly (docs/theory.md, "A rigid body
// in full contact"). Under a sampled record they are linear between samples, so a sign check at
// each sample finds every crossing and the state jumps from sample to sample; an analytic motion
// is checked at event_samples points per max_step.
template <int N, int MaxN>
bool Simulator<N, MaxN>::advance_still(double& t, State& x) {
  // each span checked counts as a step toward max_steps
  if (!count_step(t)) return false;
  double ta = t, tb = t;
  int samples = 1;
  if (motion_.is_sampled()) {
    tb = scan_record(t);
  } else if (t >= quiet_from_) {
    // the base acceleration is zero from here on (a pulse has ended): the body at rest stays so,
    // every guard constant and positive, so nothing can change any more
    tb = t_end_;
  } else {
    tb = std::min({t_end_, motion_.next_breakpoint(t, break_cursor_), t + opt_.max_step});
    samples = samples_;
  }
  auto& smp = samples_buf_;
  smp[0] = s0_;
  if (motion_.is_sampled() && scan_from_ > ta) {
    // the scan passed samples with no event on them: start from the last of them
    ta = scan_from_;
    evaluate(ta, x_still_, smp[0]);
  }
  for (int k = 1; k <= samples; ++k) {
    const double tk = k == samples ? tb : ta + (tb - ta) * k / samples;
    evaluate(tk, x_still_, smp[static_cast<std::size_t>(k)]);
  }
  still_t1_ = tb;
  if (opt_.progress) opt_.progress->store(tb, std::memory_order_relaxed);
  double t_hit = 0.0;
  int slot_hit = -1;
  const bool hit = step_guards(samples, tb, t_hit, slot_hit);
  int points = 1;
  for (int k = 1; k <= samples; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    if (smp[kk].t >= t_hit) break;
    observe(smp[kk], x_still_);
    ++points;
  }
  if (tension_) {
    // the time the floor pulls on the held body, to the last sample before any event and on to it
    std::array<double, kMaxSamples + 2> ts{}, fs{};
    GuardSample s;
    auto fj_at = [&](double tt) {
      evaluate(tt, x_still_, s);
      return s.fj;
    };
    for (int p = 0; p < points; ++p) {
      ts[static_cast<std::size_t>(p)] = smp[static_cast<std::size_t>(p)].t;
      fs[static_cast<std::size_t>(p)] = smp[static_cast<std::size_t>(p)].fj;
    }
    if (hit && t_hit > ts[static_cast<std::size_t>(points - 1)]) {
      ts[static_cast<std::size_t>(points)] = t_hit;
      fs[static_cast<std::size_t>(points)] = fj_at(t_hit);
      ++points;
    }
    res_.extremes.tension_time += time_negative(ts.data(), fs.data(), points, fj_at);
  }
  if (!hit) {
    emit_rows_until(tb);
    t = tb;
    s0_ = smp[static_cast<std::size_t>(samples)];
    release_latches(s0_);
    return true;
  }
  emit_rows_until(t_hit);
  t = t_hit;
  x = x_still_;
  return fire(slot_hit, t, x);
}

// walks the record's samples after t while every guard stays positive there, folding their
// reactions into the extremes; returns the end of the first span that may hold a crossing (a
// sample where some guard is <= 0), or the end time. scan_from_ is the span's start.
template <int N, int MaxN>
double Simulator<N, MaxN>::scan_record(double t) {
  const std::vector<double>& ts = motion_.times();
  const std::vector<double>& hx = motion_.horizontal();
  const std::vector<double>& vy = motion_.vertical();
  const bool vertical = vy.size() == ts.size();
  const double g = dyn_.g();
  const double a1 = dyn_.alpha1(), a2 = dyn_.alpha2();
  const double fc = opt_.friction_coefficient;
  const bool friction = std::isfinite(fc);
  std::size_t i = scan_index_;
  while (i > 0 && ts[i - 1] > t) --i;
  while (i < ts.size() && ts[i] <= t) ++i;
  scan_from_ = t;
  double shear = 0.0, demand = 0.0;
  // uplift about edge 1 / edge 2, lift-off, friction margin, over M g (rigid body)
  for (; i < ts.size() && ts[i] < t_end_; ++i) {
    const double ax = hx[i] / g, ay = 1.0 + (vertical ? vy[i] / g : 0.0);
    const double u1 = a1 * ay - ax, u2 = a2 * ay + ax;
    if (!(u1 > 0.0 && u2 > 0.0 && ay > 0.0)) break;
    if (friction && !(fc * ay - std::abs(ax) > 0.0)) break;  // the base starts to slide
    shear = std::max(shear, std::abs(ax));
    if (ay >= kPressingFraction) demand = std::max(demand, std::abs(ax) / ay);
    scan_from_ = ts[i];
  }
  scan_index_ = i;
  Extremes& ex = res_.extremes;
  const double mg = dyn_.mass() * g;
  ex.max_base_shear = std::max(ex.max_base_shear, mg * shear);
  ex.max_overturning_moment = std::max(ex.max_overturning_moment, mg * dyn_.height() * shear);
  ex.max_friction_demand = std::max(ex.max_friction_demand, demand);
  return i < ts.size() ? std::min(ts[i], t_end_) : t_end_;
}

// the state at t within the last step (or the still state)
template <int N, int MaxN>
void Simulator<N, MaxN>::state_at(double t, State& out) const {
  switch (stepping_) {
    case Stepping::kStill:
      out = x_still_;
      return;
    case Stepping::kExact:
      prop_.dense(t, out);
      return;
    case Stepping::kFlight:
      flight_integ_.dense(t, flight_buf_);
      put(flight_buf_, out);
      return;
    case Stepping::kSlide:
      slide_integ_.dense(t, slide_buf_);
      put(slide_buf_, out);
      return;
    case Stepping::kSeries:
      series_integ_.dense(t, dense_buf_);
      put(dense_buf_, out);
      return;
    case Stepping::kArc:
      arc_.dense(t, dense_buf_);
      put(dense_buf_, out);
      return;
    case Stepping::kRocking:
      integ_.dense(t, dense_buf_);
      put(dense_buf_, out);
      return;
  }
}

// ---- resets
// --------------------------------------------------------------------------------------

// a resetting guard of the current mode fired at (t, x); false when the run ends
template <int N, int MaxN>
bool Simulator<N, MaxN>::fire(int slot, double t, State& x) {
  if (sliding()) offset_ = x(isd());  // events name where the base is
  const GuardSpec& g = guard_spec(mode_spec(mode_).guards[static_cast<std::size_t>(slot)]);
  switch (g.reset) {
    case Reset::kUplift: {
      // U1 + U2 = (alpha1 + alpha2) F_J / M g: when the floor also stops pressing, both uplift
      // guards and the lift-off guard cross together, and the body flies (theory §15)
      GuardSample now;
      evaluate(t, x, now);
      const int lift = guard_slot(mode_, Guard::kLiftOff);
      if (!tension_ && lift >= 0 && now.v[static_cast<std::size_t>(lift)] <= 0.0)
        return lift_off(t, x);
      return uplift(t, x, g.edge);
    }
    case Reset::kLiftOff:
      return lift_off(t, x);
    case Reset::kImpact:
      return impact(t, x);
    case Reset::kOverturn:
      return overturned(t, x);
    case Reset::kLanding:
      return land(t, x, g.edge, rigid_law_);
    case Reset::kSlip:
      return start_slip(t, x);
    case Reset::kStick:
      return stick(t, x);
    case Reset::kRecord:
      break;
  }
  return true;
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::uplift(double t, State& x, int e) {
  Event ev = make_event(t, EventKind::kUplift, e);
  rec_.event(ev);
  if (res_.extremes.first_uplift_time < 0.0) {
    res_.extremes.first_uplift_time = t;
    res_.extremes.first_uplift_edge = e;
  }
  // a sliding base goes on sliding under the new pivot (no impulse: d_dot is continuous)
  switch_mode(contact_mode(e, slip()), t, x);
  x(0) = 0.0;
  x(ithd()) = 0.0;
  last_contact_change_ = t;
  // theta = 0 and it must grow: the impact and peak functions start at zero, known to turn
  // positive
  zero_start_.fill(false);
  zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
  zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kPeak))] = true;
  // a slide that began at this instant has not yet any slip velocity: it too starts at zero
  if (sliding() && x(isv()) == 0.0)
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kSlipStop))] = true;
  return enter_mode(t, x);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::law_fallback(double t, int e) {
  ++res_.extremes.impact_law_fallbacks;
  rec_.event(make_event(t, EventKind::kImpactLawFallback, e));
}

template <int N, int MaxN>
void Simulator<N, MaxN>::count_impact(const Event& impact, double impulse_y, double loss,
                                      bool chatter) {
  // the force a contact of the assumed duration would carry: a half-sine pulse of this impulse
  Event ev = impact;
  // (the impulse's size by sqrt, not hypot: no impulse comes near the range where x^2 overflows)
  ev.force_estimate = 0.5 * std::numbers::pi *
                      std::sqrt(ev.impulse_x * ev.impulse_x + ev.impulse_y * ev.impulse_y) /
                      opt_.impact_duration;
  rec_.event(ev);
  Extremes& ex = res_.extremes;
  ex.max_impact_force = std::max(ex.max_impact_force, ev.force_estimate);
  ++ex.impacts;
  if (chatter) {
    ++ex.chatter_cutoffs;
    res_.chatter_cut_off = true;
    chatter_loss_ += loss;
  } else {
    impact_loss_ += loss;
  }
  ex.max_impulse = std::max(ex.max_impulse, impulse_y);
  ex.max_impact_energy_loss = std::max(ex.max_impact_energy_loss, loss);
  // the cut-off is a numerical device on a vanishing impulse (its ratio is 1/alpha for a rigid
  // block whatever the speed): it sets no friction demand
  if (!chatter && impulse_y > 0.0)
    ex.max_friction_demand = std::max(ex.max_friction_demand, ev.friction_demand);
  if (loss < -1e-12 * std::max(1.0, rec_.energy_scale())) {
    res_.impact_gained_energy = true;
    Event ge = ev;
    ge.kind = EventKind::kImpactGainedEnergy;
    rec_.event(ge);
  }
}

// rocking reaches theta = 0: the impact law of theory §8-§10
template <int N, int MaxN>
bool Simulator<N, MaxN>::impact(double t, State& x) {
  const int landing = edge() == 1 ? 2 : 1;
  unpack(x);
  const double thd_minus = x(ithd());
  const bool chatter = t - last_contact_change_ < chatter_interval_;
  const auto out = resolve_impact(dyn_, landing, q_, thd_minus, qd_, rule_, chatter);
  // with friction: a sliding pivot, or an impulse outside the friction cone, needs the impact law
  // with Coulomb friction (theory §19); the paper's law is its sticking case. A chatter cut-off of
  // a sticking pivot is a numerical device on a vanishing impulse whose ratio |I_x|/I_y says
  // nothing about sliding (§10): it stays the sticking both-edges stop.
  if (std::isfinite(mu_s_) &&
      (sliding() || (!chatter && !(out.impulse(1) > 0.0 &&
                                   std::abs(out.impulse(0)) <= mu_s_ * out.impulse(1))))) {
    Eigen::Vector2d r, v_c;
    dyn_.cg_from_pivot(edge(), 0.0, 1.0, q_, thd_minus, qd_, r, v_c);
    if (sliding()) v_c(0) += x(isv());
    return friction_impact(t, x, landing, v_c, false, chatter,
                           chatter ? EventKind::kChatterCutoff : EventKind::kImpact, chatter,
                           rigid_law_);
  }
  if (out.law_fallback) law_fallback(t, landing);
  Event ev = make_event(t,
                        chatter ? EventKind::kChatterCutoff
                                : (out.both_edges ? EventKind::kRockingEnded : EventKind::kImpact),
                        landing);
  ev.theta_dot_before = thd_minus;
  ev.theta_dot_after = out.theta_dot;
  ev.energy_loss = out.energy_loss;
  ev.impulse_x = out.impulse(0);
  ev.impulse_y = out.impulse(1);
  ev.friction_demand = out.impulse(1) > 0.0 ? std::abs(out.impulse(0)) / out.impulse(1)
                                            : std::numeric_limits<double>::infinity();
  count_impact(ev, out.impulse(1), out.energy_loss, chatter);
  x(0) = 0.0;
  x(ithd()) = out.theta_dot;
  x.segment(iqd(), n_) = out.q_dot;
  switch_mode(out.both_edges
                  ? ContactMode::kFullContact
                  : (landing == 1 ? ContactMode::kRockingEdge1 : ContactMode::kRockingEdge2),
              t, x);
  // a degenerate excursion (no time since uplift) must not uplift again at once
  if (out.both_edges && t == last_contact_change_) suppress_uplift_at_start_ = true;
  last_contact_change_ = t;
  zero_start_.fill(false);
  if (!out.both_edges)
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
  if (res_.extremes.impacts > opt_.max_impacts)
    return stop(t, "impact limit reached (" + std::to_string(opt_.max_impacts) + ")");
  return enter_mode(t, x);
}

// the floor stops pressing: the body flies, with no impulse (theory "Flight", lift-off map)
template <int N, int MaxN>
bool Simulator<N, MaxN>::lift_off(double t, State& x) {
  unpack(x);
  const int e = edge();  // in full contact theta = 0 and either edge gives the same c.g.
  const double sn = std::sin(x(0)), cs = std::cos(x(0));
  // a free body must move its touching tipping points up: otherwise the sticking pivot is pulled
  // sideways as its force vanishes and the body could only leave it by sliding, which is not
  // modelled here; the floor is let pull (flagged) until it presses again (theory "Lift-off")
  const BaseAcceleration a = motion_.at(t, event_cursor_);
  const int pivot = mode_spec(mode_).pivot;
  // (a sliding pivot's friction vanishes with F_J: no such case, theory "Lift-off from a sliding
  // mode"; there the corner's free acceleration is zero to rounding and its sign says nothing)
  const bool dives =
      !sliding() &&
      ((pivot != 2 && dyn_.free_corner_acceleration(1, sn, cs, q_, x(ithd()), qd_, a) < 0.0) ||
       (pivot != 1 && dyn_.free_corner_acceleration(2, sn, cs, q_, x(ithd()), qd_, a) < 0.0));
  if (dives) {
    tension_ = true;
    res_.pivot_tension = true;
    Event ev = make_event(t, EventKind::kPivotTension, rocking() ? e : 0);
    ev.theta = x(0);
    ev.theta_dot_before = ev.theta_dot_after = x(ithd());
    rec_.event(ev);
    // the episode's largest pull goes into this event as the floor pulls (fold_pull)
    tension_event_ = static_cast<long>(res_.events.size()) - 1;
    ++res_.extremes.tension_episodes;
    return enter_mode(t, x);
  }
  Eigen::Vector2d r, v;
  dyn_.cg_from_pivot(e, sn, cs, q_, x(ithd()), qd_, r, v);
  const double d = offset_of(x);
  if (sliding()) v(0) += x(isv());  // the pivot's slip carries the c.g.
  x(ixc()) = d + dyn_.height() * dyn_.alpha(e) + r(0);
  x(ixc() + 1) = r(1);
  x(ixc() + 2) = v(0);
  x(ixc() + 3) = v(1);
  Event ev = make_event(t, EventKind::kLiftOff, full_contact() ? 0 : e);
  ev.theta = x(0);
  ev.theta_dot_before = ev.theta_dot_after = x(ithd());
  rec_.event(ev);
  ++res_.extremes.lift_offs;
  const ContactMode from = mode_;
  switch_mode(ContactMode::kFlight, t, x);
  flight_start_ = t;
  last_contact_change_ = t;
  // the tipping points that touched the floor start at zero height and rise
  zero_start_.fill(false);
  if (mode_spec(from).pivot != 2)
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kLandingEdge1))] = true;
  if (mode_spec(from).pivot != 1)
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kLandingEdge2))] = true;
  return enter_mode(t, x);
}

// tipping point e lands after a flight: the plastic corner impact (theory "Landing"); at theta = 0
// with the body turning into the floor about e, both edges land (flat)
template <int N, int MaxN>
bool Simulator<N, MaxN>::land(double t, State& x, int e, bool rigid) {
  unpack(x);
  const double th = x(0), thd_minus = x(ithd());
  const double sn = std::sin(th), cs = std::cos(th), h = dyn_.height();
  const Eigen::Vector2d v_c = cg_velocity(x);
  if (std::isfinite(mu_s_)) {
    res_.extremes.flight_time += t - flight_start_;
    const bool chatter = t - last_contact_change_ < chatter_interval_;
    if (chatter) {
      tension_ = hold_tension_ = true;  // as below: grazing hops cannot accumulate
      tension_event_ = -1;
    }
    return friction_impact(t, x, e, v_c, true, false,
                           chatter ? EventKind::kChatterCutoff : EventKind::kLanding, chatter,
                           rigid);
  }
  const int e_in = e;
  const Eigen::Vector2d v_corner = dyn_.corner_velocity_body(e, sn, cs, q_, thd_minus, qd_, v_c);
  double thd_plus = 0.0;
  Vec qd_plus(n_);
  dyn_.corner_impact(e, q_, thd_minus, qd_, v_corner, thd_plus, qd_plus, rigid);
  bool flat = false;
  if (th == 0.0 && edge_sign(e) * thd_plus <= 0.0) {
    // level: the body rocks on the other tipping point if its map turns it up about that one,
    // else both land (both vertical impulses are then compressive; theory "Landing")
    const int o = e == 1 ? 2 : 1;
    const Eigen::Vector2d v_other = dyn_.corner_velocity_body(o, sn, cs, q_, thd_minus, qd_, v_c);
    double thd_o = 0.0;
    Vec qd_o(n_);
    dyn_.corner_impact(o, q_, thd_minus, qd_, v_other, thd_o, qd_o, rigid);
    if (edge_sign(o) * thd_o > 0.0) {
      e = o;
      thd_plus = thd_o;
      qd_plus = qd_o;
    } else {
      flat = true;
    }
  }
  const double x_corner = dyn_.corner_x(e, sn, cs, q_, x(ixc()));
  if (flat) {
    // both edges on the floor: theta_dot = 0, the modal momenta are conserved (rigid_body: the
    // modal velocities)
    thd_plus = 0.0;
    if (rigid) {
      qd_plus = qd_;
    } else {
      const Vec p = dyn_.flight_modal_momenta(e, q_, thd_minus, qd_, v_corner);
      qd_plus = dyn_.mu_inverse() * p;
    }
  }
  // the c.g. velocity after, for the impulse
  Eigen::Vector2d r, v_after;
  dyn_.cg_from_pivot(e, sn, cs, q_, thd_plus, qd_plus, r, v_after);
  if (flat)
    v_after = dyn_.height() * Eigen::Vector2d(dyn_.psi_x().dot(qd_plus), dyn_.psi_y().dot(qd_plus));
  const Eigen::Vector2d impulse = dyn_.mass() * (v_after - v_c);
  // a plastic impact loses the kinetic energy of the velocity jump (Carnot), which is >= 0 by
  // construction: the jump's c.g. velocity and its motion about the c.g. (theory §16). The
  // rigid_body law is no projection: its loss is the difference of the energies, and where that
  // is a gain the paper's law takes the landing
  const Vec dqd = qd_plus - qd_;
  double loss = dyn_.flight_kinetic_energy(q_, thd_plus - thd_minus, dqd, v_after - v_c);
  if (rigid) {
    const double before = dyn_.flight_kinetic_energy(q_, thd_minus, qd_, v_c);
    loss = before - dyn_.flight_kinetic_energy(q_, thd_plus, qd_plus, v_after);
    if (loss < -kImpactEnergyRounding * before) {
      law_fallback(t, e_in);
      return land(t, x, e_in, false);
    }
  }
  x(ithd()) = thd_plus;
  x.segment(iqd(), n_) = qd_plus;
  offset_ = x_corner - h * dyn_.alpha(e);
  switch_mode(flat ? ContactMode::kFullContact
                   : (e == 1 ? ContactMode::kRockingEdge1 : ContactMode::kRockingEdge2),
              t, x);
  Event ev = make_event(t, EventKind::kLanding, flat ? 0 : e);
  ev.theta = th;
  ev.theta_dot_before = thd_minus;
  ev.theta_dot_after = thd_plus;
  ev.energy_loss = loss;
  ev.impulse_x = impulse(0);
  ev.impulse_y = impulse(1);
  ev.friction_demand = impulse(1) > 0.0 ? std::abs(impulse(0)) / impulse(1)
                                        : std::numeric_limits<double>::infinity();
  res_.extremes.flight_time += t - flight_start_;
  // a flight shorter than the chatter interval is below what the model resolves (a tipping point
  // grazing the floor): the landing is a chatter cut-off, and the floor may pull until it presses
  // again, so that such hops cannot accumulate without end
  const bool chatter = t - last_contact_change_ < chatter_interval_;
  if (chatter) {
    ev.kind = EventKind::kChatterCutoff;
    tension_ = true;
    tension_event_ = -1;
  }
  count_impact(ev, impulse(1), ev.energy_loss, chatter);
  return after_impulse(t, x, ev, th, dyn_.mass() * (v_c.norm() + v_after.norm()));
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::overturned(double t, State& x) {
  const int side = flying() ? (x(0) >= 0.0 ? 1 : 2) : edge();
  res_.status = Status::kOverturned;
  // the run ends here: every extreme (tilt, uplift, reaction, modes) takes this state too, not
  // only the samples before it
  GuardSample now;
  evaluate(t, x, now);
  observe(now, x);
  res_.extremes.overturn_time = t;
  res_.extremes.overturn_edge = side;
  if (sliding()) res_.extremes.sliding_time += t - slide_start_;
  if (flying()) res_.extremes.flight_time += t - flight_start_;
  Event ev = make_event(t, EventKind::kOverturn, side);
  ev.theta = x(0);
  ev.offset = offset_of(x);
  rec_.event(ev);
  res_.message = std::string("overturned about edge ") + std::to_string(side) +
                 " at t = " + short_number(t) + " s" + (flying() ? " (in flight)" : "");
  return false;
}

template <int N, int MaxN>
void Simulator<N, MaxN>::switch_mode(ContactMode m, double t, State& x) {
  const bool was = sliding(), flew = flying();
  mode_ = m;
  if (was && !sliding()) {
    res_.extremes.sliding_time += t - slide_start_;
    offset_ = x(isd());
    x(isv()) = 0.0;
  } else if (!was && sliding()) {
    slide_start_ = t;
    if (!flew) x(isd()) = offset_;  // a landing sets offset_ first
  }
  if (flew && sliding()) x(isd()) = offset_;
}

// the friction limit of a sticking contact mode is reached: the base slides the way the floor
// cannot hold it, starting from rest (theory §18)
template <int N, int MaxN>
bool Simulator<N, MaxN>::start_slip(double t, State& x) {
  GuardSample now;
  evaluate(t, x, now);
  // the floor cannot push along F_I as hard as sticking needs: the base slips the other way
  const int s = now.fi > 0.0 ? -1 : 1;
  Event ev = make_event(t, EventKind::kSlipStart, rocking() ? edge() : 0);
  ev.theta = x(0);
  ev.friction_demand =
      now.fj > 0.0 ? std::abs(now.fi) / now.fj : std::numeric_limits<double>::infinity();
  rec_.event(ev);
  res_.friction_exceeded = true;
  ++res_.extremes.slips;
  x(isv()) = 0.0;
  switch_mode(contact_mode(mode_spec(mode_).pivot, s), t, x);
  last_contact_change_ = t;
  if (rocking() && x(0) == 0.0 && x(ithd()) == 0.0) {
    // just uplifted: with its pivot sliding the body must still turn up, else it slides flat
    unpack(x);
    double thdd = 0.0;
    Eigen::Vector2d r;
    slide_acceleration(0.0, 1.0, 0.0, motion_.at(t, event_cursor_), thdd, r);
    if (!(edge_sign(edge()) * thdd > 0.0)) {
      switch_mode(contact_mode(0, s), t, x);
      suppress_uplift_at_start_ = true;
    }
  }
  // the slip velocity starts at zero and grows; an uplift at this instant leaves theta = 0
  zero_start_.fill(false);
  zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kSlipStop))] = true;
  if (rocking() && x(0) == 0.0) {
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kPeak))] = true;
  }
  return enter_mode(t, x);
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::uplift_holds(double t, int e) {
  if (!std::isfinite(mu_s_)) return true;
  const ContactMode was = mode_;
  const BaseAcceleration a = motion_.at(t, event_cursor_);
  double thdd = 0.0;
  dyn_.rocking_acceleration_sc(e, 0.0, 1.0, q_, 0.0, qd_, a, thdd, qdd_);
  const Eigen::Vector2d r = dyn_.rocking_reaction_sc(e, 0.0, 1.0, q_, 0.0, qd_, thdd, qdd_, a);
  if (mu_s_ * r(1) - std::abs(r(0)) > 0.0) return true;
  mode_ = contact_mode(e, r(0) > 0.0 ? -1 : 1);
  Eigen::Vector2d rs;
  const bool inconsistent = slide_inconsistent_;
  slide_acceleration(0.0, 1.0, 0.0, a, thdd, rs);
  slide_inconsistent_ = inconsistent;  // a probe, not the motion
  mode_ = was;
  return edge_sign(e) * thdd > 0.0;
}

// the slip velocity reached zero: the base sticks if static friction can hold it (a strictly
// positive margin), else it slides the way the floor cannot hold (theory §18)
template <int N, int MaxN>
bool Simulator<N, MaxN>::stick(double t, State& x) {
  offset_ = x(isd());
  x(isv()) = 0.0;
  const int pivot = mode_spec(mode_).pivot, was = slip();
  const double th = x(0);
  switch_mode(contact_mode(pivot, 0), t, x);
  GuardSample now;
  evaluate(t, x, now);
  const double margin = now.v[static_cast<std::size_t>(guard_slot(mode_, Guard::kFrictionLimit))];
  const int s = now.fi > 0.0 ? -1 : 1;
  Event ev = make_event(t, margin > 0.0 ? EventKind::kStick : EventKind::kSlipReversal,
                        rocking() ? edge() : 0);
  ev.theta = th;
  ev.friction_demand =
      now.fj > 0.0 ? std::abs(now.fi) / now.fj : std::numeric_limits<double>::infinity();
  rec_.event(ev);
  zero_start_.fill(false);
  if (margin <= 0.0) {
    if (s != was) ++res_.extremes.slips;
    switch_mode(contact_mode(pivot, s), t, x);
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kSlipStop))] = true;
  }
  if (rocking() && th == 0.0) {
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kPeak))] = true;
  }
  return enter_mode(t, x);
}

// Moreau's impact law for one contact, plastic normally, with Coulomb friction on the impulse
// (theory §19): the moment of momentum about tipping point e and the modal momenta are conserved;
// after the impact e rests on the floor (stick) or slides along it at d_dot+ (slip), and every
// post-impact quantity is affine in d_dot+. The sticking impulse is taken if it lies in the
// friction cone; else the slip direction is the one the cone cannot hold, and d_dot+ puts the
// impulse on the cone's edge. At theta = 0 a map that turns the body into the floor about e lands
// both edges (theta_dot+ = 0, the modal momenta conserved), with the same friction rule.
template <int N, int MaxN>
bool Simulator<N, MaxN>::friction_impact(double t, State& x, int e, const Eigen::Vector2d& v_c,
                                         bool from_flight, bool flat, EventKind kind, bool chatter,
                                         bool rigid) {
  unpack(x);
  if (!from_flight) x(0) = 0.0;  // a rocking impact is located at theta = 0 up to rounding
  const double th = x(0), thd_minus = x(ithd());
  const double sn = std::sin(th), cs = std::cos(th), h = dyn_.height(), m = dyn_.mass();
  const double kinetic_before = dyn_.flight_kinetic_energy(q_, thd_minus, qd_, v_c);
  const Eigen::Vector2d unit_body(cs, -sn);  // I in body components
  // one candidate: the post-impact rates and c.g. velocity at d_dot+ = 0 and per unit d_dot+
  struct Candidate {
    double thd0 = 0.0, thd1 = 0.0;
    Vec qd0, qd1;
    Eigen::Vector2d vc0, vc1;
  };
  auto single = [&](int c, Candidate& k) {
    const Eigen::Vector2d v_corner = dyn_.corner_velocity_body(c, sn, cs, q_, thd_minus, qd_, v_c);
    k.qd0.resize(n_);
    k.qd1.resize(n_);
    dyn_.corner_impact(c, q_, thd_minus, qd_, v_corner, k.thd0, k.qd0, rigid);
    dyn_.corner_impact(c, q_, 0.0, Vec::Zero(n_), -unit_body, k.thd1, k.qd1, rigid);
    Eigen::Vector2d r;
    dyn_.cg_from_pivot(c, sn, cs, q_, k.thd0, k.qd0, r, k.vc0);
    dyn_.cg_from_pivot(c, sn, cs, q_, k.thd1, k.qd1, r, k.vc1);
    k.vc1(0) += 1.0;
  };
  auto both = [&](Candidate& k) {
    // theta = 0: the modal momenta p = mu q_dot + psi_x d_dot / h (over M h^2) are conserved
    const Eigen::Vector2d v_corner = dyn_.corner_velocity_body(e, sn, cs, q_, thd_minus, qd_, v_c);
    const Vec p = dyn_.flight_modal_momenta(e, q_, thd_minus, qd_, v_corner);
    k.thd0 = k.thd1 = 0.0;
    k.qd0 = rigid ? qd_ : Vec(dyn_.mu_inverse() * p);
    // rigid_body: the slip carries the body as a whole, the modes keep their rates
    k.qd1 = rigid ? Vec(Vec::Zero(n_)) : Vec(-(dyn_.mu_inverse() * dyn_.psi_x()) / h);
    k.vc0 = h * Eigen::Vector2d(dyn_.psi_x().dot(k.qd0), dyn_.psi_y().dot(k.qd0));
    k.vc1 = Eigen::Vector2d(1.0 + h * dyn_.psi_x().dot(k.qd1), h * dyn_.psi_y().dot(k.qd1));
  };
  // Coulomb on the impulse M (v_c+ - v_c-) = L0 + d_dot+ L1: d_dot+ = 0 inside the cone, else on
  // its edge; `ok` false when the slide has no consistent solution (k_s <= 0)
  struct Resolved {
    double v = 0.0;       // d_dot+
    double demand = 0.0;  // |L0_I| / L0_J: the friction the sticking impulse needs
    bool slid = false, ok = true;
  };
  auto coulomb = [&](const Candidate& c) {
    Resolved z;
    const Eigen::Vector2d l0 = m * (c.vc0 - v_c), l1 = m * c.vc1;
    z.demand = l0(1) > 0.0 ? std::abs(l0(0)) / l0(1) : std::numeric_limits<double>::infinity();
    if (l0(1) > 0.0 && std::abs(l0(0)) <= mu_s_ * l0(1)) return z;
    const double sg = l0(0) > 0.0 ? -1.0 : 1.0;
    const double k_s = l1(0) + sg * mu_k_ * l1(1);
    z.v = -(l0(0) + sg * mu_k_ * l0(1)) / k_s;
    z.slid = true;
    z.ok = k_s > 0.0;
    return z;
  };
  auto turn = [](const Candidate& c, double v) { return c.thd0 + v * c.thd1; };
  Candidate k;
  Resolved z;
  int lands = e;
  if (flat) {
    both(k);
    z = coulomb(k);
  } else if (th != 0.0) {
    single(e, k);
    z = coulomb(k);
  } else {
    // theta = 0 (theory §19): corner 1, corner 2 and flat, each resolved with friction; the one
    // that is consistent (the body turns away from the other corner; flat: both corners press),
    // and where two are, the one the sticking rule of §16 names
    std::array<Candidate, 3> c;  // corner 1, corner 2, flat
    single(1, c[0]);
    single(2, c[1]);
    both(c[2]);
    std::array<Resolved, 3> r = {coulomb(c[0]), coulomb(c[1]), coulomb(c[2])};
    std::array<bool, 3> fits = {r[0].ok && turn(c[0], r[0].v) > 0.0,
                                r[1].ok && -turn(c[1], r[1].v) > 0.0,
                                r[2].ok && turn(c[0], r[2].v) <= 0.0 && -turn(c[1], r[2].v) <= 0.0};
    // the sticking rule: the landing corner if it turns the body up about itself, else (landing
    // from flight) the other one, else flat
    const int o = e == 1 ? 2 : 1;
    int pick = 2;
    if (edge_sign(e) * c[static_cast<std::size_t>(e - 1)].thd0 > 0.0) {
      pick = e - 1;
    } else if (from_flight && edge_sign(o) * c[static_cast<std::size_t>(o - 1)].thd0 > 0.0) {
      pick = o - 1;
    }
    if (!fits[static_cast<std::size_t>(pick)]) {
      for (int j = 0; j < 3; ++j)
        if (fits[static_cast<std::size_t>(j)]) pick = j;
    }
    const auto pk = static_cast<std::size_t>(pick);
    k = c[pk];
    z = r[pk];
    z.ok = z.ok && fits[pk];
    flat = pick == 2;
    lands = flat ? e : pick + 1;
  }
  if (chatter && z.slid && !((k.vc0 + z.v * k.vc1 - v_c)(1) > 0.0)) {
    // a grazing landing (below the chatter interval) whose sliding impulse would pull: the
    // sticking one, as without friction (§16: Carnot's loss, a tensile_landing said)
    z = Resolved{};
  }
  const bool ok = z.ok;
  const double v_plus = z.v;
  const bool slid = z.slid;
  const double sticking_demand = z.demand;
  if (!ok)
    return stop(t, "no consistent impact with friction at t = " + short_number(t) +
                       " s (no outcome of the impact law with Coulomb friction fits; "
                       "docs/theory.md, \"Impacts with friction\")");
  const double thd_plus = k.thd0 + v_plus * k.thd1;
  const Vec qd_plus = k.qd0 + v_plus * k.qd1;
  const Eigen::Vector2d v_after = k.vc0 + v_plus * k.vc1;
  const Eigen::Vector2d impulse = m * (v_after - v_c);
  const double loss = kinetic_before - dyn_.flight_kinetic_energy(q_, thd_plus, qd_plus, v_after);
  if (rigid && loss < -kImpactEnergyRounding * kinetic_before) {
    law_fallback(t, e);
    return friction_impact(t, x, e, v_c, from_flight, flat, kind, chatter, false);
  }
  // the contact point's place: the landing tipping point, or the base centre when flat
  const double d_now = offset_of(x);
  if (from_flight) {
    const double x_corner = dyn_.corner_x(lands, sn, cs, q_, x(ixc()));
    offset_ = x_corner - h * dyn_.alpha(lands);
  } else {
    offset_ = d_now;
  }
  x(ithd()) = flat ? 0.0 : thd_plus;
  x.segment(iqd(), n_) = qd_plus;
  const int pivot = flat ? 0 : lands;
  const int s = !slid || v_plus == 0.0 ? 0 : (v_plus > 0.0 ? 1 : -1);
  switch_mode(contact_mode(pivot, s), t, x);
  x(isd()) = offset_;
  x(isv()) = s != 0 ? v_plus : 0.0;
  Event ev = make_event(t, flat && kind == EventKind::kImpact ? EventKind::kRockingEnded : kind,
                        from_flight && flat ? 0 : lands);
  ev.theta = th;
  ev.theta_dot_before = thd_minus;
  ev.theta_dot_after = x(ithd());
  ev.energy_loss = loss;
  ev.impulse_x = impulse(0);
  ev.impulse_y = impulse(1);
  ev.friction_demand = impulse(1) > 0.0 ? std::abs(impulse(0)) / impulse(1)
                                        : std::numeric_limits<double>::infinity();
  count_impact(ev, impulse(1), loss, chatter);
  if (slid) {
    // the impulse needed more friction than the floor has: a sliding impact
    res_.friction_exceeded = true;
    ++res_.extremes.slips;
    Event fe = ev;
    fe.kind = EventKind::kFrictionExceeded;
    fe.friction_demand = sticking_demand;
    rec_.event(fe);
  }
  return after_impulse(t, x, ev, th, m * (v_c.norm() + v_after.norm()));
}

// the end of a landing or an impact with friction, recorded as `ev` at tilt th: a tensile impulse
// is said, and the new mode starts (theta = 0 and rocking: the impact guard starts at zero)
template <int N, int MaxN>
bool Simulator<N, MaxN>::after_impulse(double t, State& x, const Event& ev, double th,
                                       double momentum) {
  // (a grazing landing's impulse vanishes: its sign within the rounding of M (v+ - v-) says
  // nothing, and such a landing pulls on nothing)
  if (ev.impulse_y < -kTensileRounding * momentum) {
    // the sticking tipping point would need the floor to pull: say so
    Event te = ev;
    te.kind = EventKind::kTensileLanding;
    rec_.event(te);
    Extremes& ex = res_.extremes;
    ++ex.tensile_landings;
    ex.max_tensile_impulse = std::max(ex.max_tensile_impulse, -ev.impulse_y);
  }
  last_contact_change_ = t;
  zero_start_.fill(false);
  if (rocking() && th == 0.0)
    zero_start_[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
  if (res_.extremes.impacts > opt_.max_impacts)
    return stop(t, "impact limit reached (" + std::to_string(opt_.max_impacts) + ")");
  return enter_mode(t, x);
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::stop(double t, std::string why) {
  res_.status = Status::kStopped;
  Event ev;
  ev.time = t;
  ev.kind = EventKind::kStopped;
  rec_.event(ev);
  res_.message = std::move(why);
  return false;
}

// a non-resetting guard crossed at t: record it
template <int N, int MaxN>
void Simulator<N, MaxN>::record(double t) {
  state_at(t, xr_);
  GuardSample s;
  evaluate(t, xr_, s);
  record_sample(s, xr_);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::record_sample(const GuardSample& s, const State& x) {
  // the only recording guard is the peak (the friction limit resets: the base slides)
  Event e = make_event(s.t, EventKind::kPeak, edge());
  e.theta = x(0);
  e.offset = offset_of(x);
  rec_.event(e);
  observe(s, x);
}

// ---- outputs
// -------------------------------------------------------------------------------------

template <int N, int MaxN>
double Simulator<N, MaxN>::kinetic_energy(const State& x) {
  unpack(x);
  if (flying()) return dyn_.flight_kinetic_energy(q_, x(ithd()), qd_, cg_velocity(x));
  const double a = rocking() ? dyn_.alpha(edge()) : 0.0;
  const double t_pivot = dyn_.kinetic_energy(a, q_, x(ithd()), qd_);
  if (!sliding()) return t_pivot;
  // theory §18: T = T_pivot + M d_dot v_cm,x + 1/2 M d_dot^2
  Eigen::Vector2d r, v;
  dyn_.cg_from_pivot(edge(), std::sin(x(0)), std::cos(x(0)), q_, x(ithd()), qd_, r, v);
  const double vd = x(isv());
  return t_pivot + dyn_.mass() * vd * (v(0) + 0.5 * vd);
}

template <int N, int MaxN>
double Simulator<N, MaxN>::potential_energy(const State& x) {
  unpack(x);
  if (flying()) return dyn_.flight_potential_energy(x(ixc() + 1), q_);
  const double a = rocking() ? dyn_.alpha(edge()) : 0.0;
  return dyn_.potential_energy(a, x(0), q_);
}

// the horizontal offset of the base centre from where the body stood [m]
template <int N, int MaxN>
double Simulator<N, MaxN>::offset_of(const State& x) {
  if (sliding()) return x(isd());
  if (!flying()) return offset_;
  unpack(x);
  // the base centre is the tipping-point line's point at alpha = 0
  const double sn = std::sin(x(0)), cs = std::cos(x(0)), h = dyn_.height();
  return x(ixc()) + h * (-cs * dyn_.psi_x().dot(q_) + sn * (1.0 + dyn_.psi_y().dot(q_)));
}

template <int N, int MaxN>
inline Observation Simulator<N, MaxN>::observation(double t, const State& x, const GuardSample& s) {
  Observation o;
  o.t = t;
  o.mode = mode_;
  o.theta = x(0);
  o.theta_dot = x(ithd());
  // u only: the extremes need no u_dot, which emit_row adds for a history row
  if (n_ > 0) qu_.noalias() = Dyn::mv(to_user_, x.segment(iq(), n_));
  o.q = qu_.data();
  o.fi = s.fi;
  o.fj = s.fj;
  o.moment = s.moment;
  o.input_work = x(iw());
  o.damping_loss = x(id());
  if (flying()) {
    flight_heights(x, o);
  } else {
    o.high = base_width_ * std::sin(std::abs(x(0)));
    o.offset = sliding() ? x(isd()) : offset_;
  }
  return o;
}

template <int N, int MaxN>
void Simulator<N, MaxN>::flight_heights(const State& x, Observation& o) {
  unpack(x);
  const double sn = std::sin(x(0)), cs = std::cos(x(0));
  const double y1 = dyn_.corner_height(1, sn, cs, q_, x(ixc() + 1));
  const double y2 = dyn_.corner_height(2, sn, cs, q_, x(ixc() + 1));
  o.lift = std::min(y1, y2);
  o.high = std::max(y1, y2);
  o.offset = offset_of(x);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::emit_rows_until(double t_cut) {
  if (opt_.output_dt <= 0.0) return;
  for (;;) {
    const double to = static_cast<double>(next_output_) * opt_.output_dt;
    if (to > t_cut || to > t_end_ * (1.0 + 1e-14)) break;
    state_at(std::min(to, stepped_until()), xr_);
    emit_row(to, xr_);
    ++next_output_;
  }
}

template <int N, int MaxN>
void Simulator<N, MaxN>::emit_row(double t, const State& x) {
  GuardSample s;
  evaluate(t, x, s);
  const BaseAcceleration a = motion_.at(t, event_cursor_);
  Observation o = observation(t, x, s);
  if (n_ > 0) qdu_.noalias() = Dyn::mv(to_user_, x.segment(iqd(), n_));
  o.q_dot = qdu_.data();
  // the resultant's distance from the c.g. projection [m]: at the pivot while rocking
  double resultant = 0.0;
  if (rocking()) {
    resultant = dyn_.height() * dyn_.alpha(edge());
  } else if (full_contact()) {
    resultant = dyn_.height() * s.moment / s.fj;
  }
  rec_.row(o, a, kinetic_energy(x), potential_energy(x), resultant, impact_loss_ + chatter_loss_);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::finish(double t, const State& x) {
  res_.t_end = t;
  if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
  if (opt_.output_dt > 0.0 && (res_.history.time.empty() || res_.history.time.back() < t - 1e-12)) {
    emit_row(t, x);
  }
  if (flying() && res_.status != Status::kOverturned)
    res_.extremes.flight_time += t - flight_start_;
  if (sliding() && res_.status != Status::kOverturned)
    res_.extremes.sliding_time += t - slide_start_;
  res_.final_phase = mode_;
  res_.final_theta = x(0);
  res_.final_theta_dot = x(ithd());
  res_.final_q = to_user_ * x.segment(iq(), n_);
  res_.final_q_dot = to_user_ * x.segment(iqd(), n_);
  res_.final_offset = offset_of(x);
  EnergyBalance& e = res_.energy;
  const double kin = kinetic_energy(x);
  const double pot = potential_energy(x);
  e.input_work = x(iw());
  e.damping_loss = x(id());
  e.impact_loss = impact_loss_;
  e.chatter_loss = chatter_loss_;
  e.friction_loss = x(ifr());
  e.kinetic_change = kin - kinetic0_;
  e.potential_change = pot - (energy0_ - kinetic0_);
  e.residual = e.input_work - (e.kinetic_change + e.potential_change + e.damping_loss +
                               e.impact_loss + e.chatter_loss + e.friction_loss);
  e.scale = std::max({rec_.energy_scale(), std::abs(energy0_ - pot), std::abs(kin), kinetic0_,
                      impact_loss_ + chatter_loss_ + e.friction_loss});
  res_.rejected_steps =
      integ_.rejected_steps() + flight_integ_.rejected_steps() + slide_integ_.rejected_steps();
  res_.rhs_evaluations =
      integ_.rhs_evaluations() + flight_integ_.rhs_evaluations() + slide_integ_.rhs_evaluations();
  if (res_.status == Status::kCompleted) res_.message = "completed";
}

}  // namespace flexrock::detail
