// SPDX-License-Identifier: BSD-3-Clause
// The modes' equations as one unit: each contact mode's right-hand side (full contact and rocking,
// flight, sliding), its guard functions with the floor reaction, and what a run observes of a
// state (energies, reactions, the base's offset). Every stepper reads the guards through
// evaluate(), and nothing else evaluates them. The unit owns what the equations read: the
// dynamics, the motion and its cursors, the evaluation scratch, the limits derived once from the
// body and the options, and the current contact mode. Internal header.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "automaton.hpp"
#include "event_location.hpp"
#include "flexrock/core/sin_cos.hpp"
#include "flexrock/model/dynamics.hpp"
#include "flexrock/sim/simulate.hpp"
#include "recorder.hpp"

namespace flexrock::detail {

template <int N, int MaxN>
class ModeEquations {
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

  // `modal`: the body in its pinned-base modal coordinates, which the state carries; `body`: the
  // given body, whose deformation u = to_user q a run reports (docs/theory.md, "Modal coordinates")
  ModeEquations(const Body& modal, const Body& body, const GroundMotion& ground,
                const SimulationOptions& opt)
      : dyn(modal), motion(ground), to_user(body.pinned_base_modes()), n(body.modes()) {
    scratch.qu.resize(n);
    scratch.qdu.resize(n);
    scratch.q.resize(n);
    scratch.qd.resize(n);
    scratch.qdd.resize(n);
    scratch.qdd1.resize(n);
    mu_s = opt.friction_coefficient;
    mu_k = std::min(opt.kinetic_friction_coefficient, opt.friction_coefficient);
    base_width = body.params().b1 + body.params().b2;
    const bool half_pi = opt.overturn == OverturnCriterion::kHalfPi;
    overturn_limit[0] = half_pi ? 0.5 * std::numbers::pi : body.tipping_angle(1);
    overturn_limit[1] = half_pi ? 0.5 * std::numbers::pi : body.tipping_angle(2);
    quiet_from = motion.quiet_from();
  }

  // ---- state layout
  int iq() const { return 1; }
  int ithd() const { return n + 1; }
  int iqd() const { return n + 2; }
  int iw() const { return 2 * n + 2; }
  int id() const { return 2 * n + 3; }
  int ixc() const { return 2 * n + 4; }   // x_c, y_c, then their rates
  int isd() const { return 2 * n + 8; }   // d [m]: the base's slip along I
  int isv() const { return 2 * n + 9; }   // d_dot [m/s]
  int ifr() const { return 2 * n + 10; }  // friction work while sliding [J]
  // the same three in a SlideState, after its first 2n + 4 entries
  int jsd() const { return 2 * n + 4; }
  // the current mode's pivot and slip (the automaton table)
  int edge() const { return mode_spec(mode).pivot == 2 ? 2 : 1; }
  bool rocking() const { return mode_spec(mode).pivot > 0; }
  bool full_contact() const { return mode_spec(mode).pivot == 0; }
  bool flying() const { return mode == ContactMode::kFlight; }
  int slip() const { return mode_spec(mode).slip; }
  bool sliding() const { return mode_spec(mode).slip != 0; }
  template <class X>
  Eigen::Vector2d cg_velocity(const X& x) const {
    return {x(ixc() + 2), x(ixc() + 3)};
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
    } else if (from.size() == 2 * n + 7) {
      to.head(2 * n + 4) = from.head(2 * n + 4);
      to.segment(isd(), 3) = from.tail(3);
    } else {
      to.head(from.size()) = from;
    }
  }
  // q and q_dot of a state into the scratch
  template <class X>
  void unpack(const X& x) {
    scratch.q = x.segment(iq(), n);
    scratch.qd = x.segment(iqd(), n);
  }

  // ---- equations of motion: full contact and rocking, flight, sliding (the current mode's)
  void contact_rhs(double t, const ContactState& x, ContactState& dx);
  void flight_rhs(double t, const FlightState& x, FlightState& dx);
  void slide_rhs(double t, const SlideState& x, SlideState& dx);
  // d_ddot [m/s^2] of the current sliding mode at (scratch.q, scratch.qd), with theta_ddot,
  // q_ddot (in scratch.qdd) and the reaction over M g; a' = a + d_ddot I is the sliding frame's
  // acceleration (theory §18). A slide with no consistent d_ddot sets slide_inconsistent.
  double slide_acceleration(double sn, double cs, double theta_dot, BaseAcceleration a,
                            double& theta_ddot, Eigen::Vector2d& reaction);
  // ---- guard functions of the current mode, in its slot order, with the floor reaction
  void evaluate(double t, const State& x, GuardSample& s);
  // the rocking modes' guard values from the state and the sample's F_J
  void rocking_guards(int e, const State& x, GuardSample& s) const;
  // evaluate() on a rigid body's closed-form arc where sin(phi), cos(phi) are known (the peak,
  // the floor): the reaction as the arc's function of phi, with no sincos of theta
  template <class Arc>
  void arc_sample(const Arc& arc, double t, const State& x, double sp, double cp,
                  GuardSample& s) const;

  // ---- what a run observes; `offset` [m]: the base centre's offset while in contact without slip
  Observation observation(double t, const State& x, const GuardSample& s, double offset);
  void flight_heights(const State& x, double offset, Observation& o);  // the tipping points'
  double kinetic_energy(const State& x);
  double potential_energy(const State& x);
  double offset_of(const State& x, double offset);  // the base centre's offset [m]

  Dyn dyn;
  const GroundMotion& motion;
  Mat to_user;  // Phi: u = Phi q
  int n;        // modes
  ContactMode mode = ContactMode::kFullContact;
  // the motion's cursors: each reader of the base acceleration keeps its own place in the record
  struct Cursors {
    GroundMotion::Cursor rhs, event, brk;  // right-hand sides, guards, breakpoints
  } cursor;
  // scratch of the equations and the observation (sized once)
  struct Scratch {
    Vec q, qd, qdd;       // q, q_dot, q_ddot of the state being evaluated
    Vec qdd1;             // q_ddot at a unit slip acceleration
    mutable Vec qu, qdu;  // u of the last observation, u_dot of the last history row
  } scratch;
  double mu_s = 0.0, mu_k = 0.0;  // static and kinetic friction coefficients (inf: no limit)
  std::array<double, 2> overturn_limit{};  // [rad] on edge 1 (theta > 0) and edge 2
  double base_width = 0.0;                 // [m] b1 + b2
  double quiet_from = 0.0;                 // the base acceleration is zero after this [s]
  bool slide_inconsistent = false;         // a sliding mode had no consistent slip acceleration
};

template <int N, int MaxN>
void ModeEquations<N, MaxN>::contact_rhs(double t, const ContactState& x, ContactState& dx) {
  const BaseAcceleration a = motion.at(t, cursor.rhs);
  dx.resize(x.size());
  if (rocking()) {
    // from the state to its derivative in place, every shared sum formed once
    double sn = 0.0, cs = 0.0;
    sin_cos(x(0), sn, cs);
    typename Dyn::RockingRates r;
    dyn.rocking_rates_sc(edge(), sn, cs, x.data() + iq(), x(ithd()), x.data() + iqd(), a,
                         dx.data() + iqd(), r);
    dx(0) = x(ithd());
    dx.segment(iq(), n) = x.segment(iqd(), n);
    dx(ithd()) = r.theta_ddot;
    dx(iw()) = r.input_power;
    dx(id()) = r.damping_power;
    return;
  }
  unpack(x);
  dyn.full_contact_acceleration(scratch.q, scratch.qd, a, scratch.qdd);
  dx(0) = 0.0;
  dx.segment(iq(), n) = scratch.qd;
  dx(ithd()) = 0.0;
  dx.segment(iqd(), n) = scratch.qdd;
  dx(iw()) = dyn.input_power(0.0, 0.0, scratch.q, 0.0, scratch.qd, a);
  dx(id()) = dyn.damping_power(scratch.qd);
}

// theory "Flight": the c.g. is ballistic relative to the base, the rest feels no gravity
template <int N, int MaxN>
void ModeEquations<N, MaxN>::flight_rhs(double t, const FlightState& x, FlightState& dx) {
  const BaseAcceleration a = motion.at(t, cursor.rhs);
  unpack(x);
  dx.resize(x.size());
  double thdd = 0.0;
  dyn.flight_acceleration(scratch.q, x(ithd()), scratch.qd, thdd, scratch.qdd);
  dx(0) = x(ithd());
  dx.segment(iq(), n) = scratch.qd;
  dx(ithd()) = thdd;
  dx.segment(iqd(), n) = scratch.qdd;
  dx(iw()) = dyn.flight_input_power(cg_velocity(x), a);
  dx(id()) = dyn.damping_power(scratch.qd);
  dx(ixc()) = x(ixc() + 2);
  dx(ixc() + 1) = x(ixc() + 3);
  dx(ixc() + 2) = -a.x;
  dx(ixc() + 3) = -dyn.g() - a.y;
}

// theory §18: with the base sliding, the body moves as in the mode without slip on a base that
// accelerates at a + d_ddot I, so the accelerations and the floor reaction are affine in d_ddot,
// and Coulomb's F_I = -s mu_k F_J is one linear equation for it
template <int N, int MaxN>
double ModeEquations<N, MaxN>::slide_acceleration(double sn, double cs, double theta_dot,
                                                  BaseAcceleration a, double& theta_ddot,
                                                  Eigen::Vector2d& reaction) {
  const BaseAcceleration a1{a.x + 1.0, a.y};  // a unit slip acceleration [m/s^2]
  Eigen::Vector2d r0, r1;
  double thdd0 = 0.0, thdd1 = 0.0;
  if (rocking()) {
    const int e = edge();
    dyn.rocking_acceleration_sc(e, sn, cs, scratch.q, theta_dot, scratch.qd, a, thdd0, scratch.qdd);
    r0 =
        dyn.rocking_reaction_sc(e, sn, cs, scratch.q, theta_dot, scratch.qd, thdd0, scratch.qdd, a);
    dyn.rocking_acceleration_sc(e, sn, cs, scratch.q, theta_dot, scratch.qd, a1, thdd1,
                                scratch.qdd1);
    r1 = dyn.rocking_reaction_sc(e, sn, cs, scratch.q, theta_dot, scratch.qd, thdd1, scratch.qdd1,
                                 a1);
  } else {
    dyn.full_contact_acceleration(scratch.q, scratch.qd, a, scratch.qdd);
    r0 = dyn.full_contact_reaction(scratch.qdd, a);
    dyn.full_contact_acceleration(scratch.q, scratch.qd, a1, scratch.qdd1);
    r1 = dyn.full_contact_reaction(scratch.qdd1, a1);
  }
  const double s = slip();
  const Eigen::Vector2d dr = r1 - r0;  // the reaction's change per m/s^2 of d_ddot
  // k > 0: friction opposing the slip decelerates it; k <= 0 has no consistent slide (Painleve)
  const double k = dr(0) + s * mu_k * dr(1);
  if (!(k > 0.0)) slide_inconsistent = true;
  const double dd = -(r0(0) + s * mu_k * r0(1)) / k;
  theta_ddot = thdd0 + dd * (thdd1 - thdd0);
  scratch.qdd += dd * (scratch.qdd1 - scratch.qdd);
  reaction = r0 + dd * dr;
  return dd;
}

// the sliding modes (theory §18): the contact mode's equations in the sliding frame, the slip, and
// the powers relative to the base: input -M a.(v_cm + d_dot I), friction dissipation -F_I d_dot
template <int N, int MaxN>
void ModeEquations<N, MaxN>::slide_rhs(double t, const SlideState& x, SlideState& dx) {
  const BaseAcceleration a = motion.at(t, cursor.rhs);
  unpack(x);
  dx.resize(x.size());
  double sn = 0.0, cs = 0.0;
  sin_cos(x(0), sn, cs);
  const double v = x(jsd() + 1);
  double thdd = 0.0;
  Eigen::Vector2d r;
  const double dd = slide_acceleration(sn, cs, x(ithd()), a, thdd, r);
  const double al = rocking() ? dyn.alpha(edge()) : 0.0;
  dx(0) = rocking() ? x(ithd()) : 0.0;
  dx.segment(iq(), n) = scratch.qd;
  dx(ithd()) = thdd;
  dx.segment(iqd(), n) = scratch.qdd;
  dx(iw()) =
      dyn.input_power_sc(al, sn, cs, scratch.q, x(ithd()), scratch.qd, a) - dyn.mass() * a.x * v;
  dx(id()) = dyn.damping_power(scratch.qd);
  dx(jsd()) = v;
  dx(jsd() + 1) = dd;
  dx(jsd() + 2) = -dyn.mass() * dyn.g() * r(0) * v;
}

template <int N, int MaxN>
void ModeEquations<N, MaxN>::evaluate(double t, const State& x, GuardSample& s) {
  // after the motion's end (GroundMotion::quiet_from) the floor is at rest
  const BaseAcceleration a = t > quiet_from ? BaseAcceleration{} : motion.at(t, cursor.event);
  unpack(x);
  s.t = t;
  // each value goes to its guard's slot in the mode's list, which the table fixes at compile time
  auto& v = s.v;
  const double mu = mu_s;
  switch (mode) {
    case ContactMode::kFullContact: {
      constexpr ContactMode m = ContactMode::kFullContact;
      dyn.full_contact_acceleration(scratch.q, scratch.qd, a, scratch.qdd);
      const Eigen::Vector2d r = dyn.full_contact_reaction(scratch.qdd, a);
      Eigen::Vector2d u;
      s.fi = r(0);
      s.fj = r(1);
      s.moment = dyn.contact_moments(scratch.q, scratch.qdd, a, u);
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
      dyn.rocking_acceleration_sc(e, sn, cs, scratch.q, x(ithd()), scratch.qd, a, thdd,
                                  scratch.qdd);
      const Eigen::Vector2d r = dyn.rocking_reaction_sc(e, sn, cs, scratch.q, x(ithd()), scratch.qd,
                                                        thdd, scratch.qdd, a);
      s.fi = r(0);
      s.fj = r(1);
      // reaction at the pivot, moment about the c.g. projection: alpha h F_j(body)
      s.moment = dyn.alpha(e) * (-r(0) * sn + r(1) * cs);
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
      s.moment = dyn.contact_moments(scratch.q, scratch.qdd, as, u);
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
      s.moment = dyn.alpha(e) * (-r(0) * sn + r(1) * cs);
      v[kSlot<m, Guard::kImpact>] = sg * x(0);
      v[kSlot<m, Guard::kOverturn>] = overturn_limit[static_cast<std::size_t>(e - 1)] - sg * x(0);
      v[kSlot<m, Guard::kLiftOff>] = s.fj;
      v[kSlot<m, Guard::kSlipStop>] = slip() * x(isv());
      v[kSlot<m, Guard::kPeak>] = sg * x(ithd());
      break;
    }
    case ContactMode::kFlight: {
      constexpr ContactMode m = ContactMode::kFlight;
      double sn = 0.0, cs = 0.0;
      sin_cos(x(0), sn, cs);
      const double h = dyn.height();
      s.fi = s.fj = s.moment = 0.0;
      v[kSlot<m, Guard::kLandingEdge1>] = dyn.corner_height(1, sn, cs, scratch.q, x(ixc() + 1)) / h;
      v[kSlot<m, Guard::kLandingEdge2>] = dyn.corner_height(2, sn, cs, scratch.q, x(ixc() + 1)) / h;
      v[kSlot<m, Guard::kOverturn>] = std::min(overturn_limit[0] - x(0), overturn_limit[1] + x(0));
      break;
    }
  }
}

template <int N, int MaxN>
void ModeEquations<N, MaxN>::rocking_guards(int e, const State& x, GuardSample& s) const {
  constexpr ContactMode m = ContactMode::kRockingEdge1;  // both edges list the same guards
  static_assert(mode_spec(ContactMode::kRockingEdge1).guards ==
                mode_spec(ContactMode::kRockingEdge2).guards);
  const double sg = edge_sign(e), mu = mu_s;
  auto& v = s.v;
  v[kSlot<m, Guard::kImpact>] = sg * x(0);
  v[kSlot<m, Guard::kOverturn>] = overturn_limit[static_cast<std::size_t>(e - 1)] - sg * x(0);
  v[kSlot<m, Guard::kLiftOff>] = s.fj;
  v[kSlot<m, Guard::kFrictionLimit>] = std::isfinite(mu) ? mu * s.fj - std::abs(s.fi) : 1.0;
  v[kSlot<m, Guard::kPeak>] = sg * x(ithd());
}

template <int N, int MaxN>
template <class Arc>
void ModeEquations<N, MaxN>::arc_sample(const Arc& arc, double t, const State& x, double sp,
                                        double cp, GuardSample& s) const {
  s.t = t;
  s.fi = arc.fi(sp, cp);
  s.fj = arc.press(cp);
  s.moment = arc.signed_moment(sp, cp);
  rocking_guards(edge(), x, s);
}

template <int N, int MaxN>
double ModeEquations<N, MaxN>::kinetic_energy(const State& x) {
  unpack(x);
  if (flying()) return dyn.flight_kinetic_energy(scratch.q, x(ithd()), scratch.qd, cg_velocity(x));
  const double a = rocking() ? dyn.alpha(edge()) : 0.0;
  const double t_pivot = dyn.kinetic_energy(a, scratch.q, x(ithd()), scratch.qd);
  if (!sliding()) return t_pivot;
  // theory §18: T = T_pivot + M d_dot v_cm,x + 1/2 M d_dot^2
  Eigen::Vector2d r, v;
  dyn.cg_from_pivot(edge(), std::sin(x(0)), std::cos(x(0)), scratch.q, x(ithd()), scratch.qd, r, v);
  const double vd = x(isv());
  return t_pivot + dyn.mass() * vd * (v(0) + 0.5 * vd);
}

template <int N, int MaxN>
double ModeEquations<N, MaxN>::potential_energy(const State& x) {
  unpack(x);
  if (flying()) return dyn.flight_potential_energy(x(ixc() + 1), scratch.q);
  const double a = rocking() ? dyn.alpha(edge()) : 0.0;
  return dyn.potential_energy(a, x(0), scratch.q);
}

// the horizontal offset of the base centre from where the body stood [m]
template <int N, int MaxN>
double ModeEquations<N, MaxN>::offset_of(const State& x, double offset) {
  if (sliding()) return x(isd());
  if (!flying()) return offset;
  unpack(x);
  // the base centre is the tipping-point line's point at alpha = 0
  const double sn = std::sin(x(0)), cs = std::cos(x(0)), h = dyn.height();
  return x(ixc()) +
         h * (-cs * dyn.psi_x().dot(scratch.q) + sn * (1.0 + dyn.psi_y().dot(scratch.q)));
}

template <int N, int MaxN>
inline Observation ModeEquations<N, MaxN>::observation(double t, const State& x,
                                                       const GuardSample& s, double offset) {
  Observation o;
  o.t = t;
  o.mode = mode;
  o.theta = x(0);
  o.theta_dot = x(ithd());
  // u only: the extremes need no u_dot, which emit_row adds for a history row
  if (n > 0) scratch.qu.noalias() = Dyn::mv(to_user, x.segment(iq(), n));
  o.q = scratch.qu.data();
  o.fi = s.fi;
  o.fj = s.fj;
  o.moment = s.moment;
  o.input_work = x(iw());
  o.damping_loss = x(id());
  if (flying()) {
    flight_heights(x, offset, o);
  } else {
    o.high = base_width * std::sin(std::abs(x(0)));
    o.offset = sliding() ? x(isd()) : offset;
  }
  return o;
}

template <int N, int MaxN>
void ModeEquations<N, MaxN>::flight_heights(const State& x, double offset, Observation& o) {
  unpack(x);
  const double sn = std::sin(x(0)), cs = std::cos(x(0));
  const double y1 = dyn.corner_height(1, sn, cs, scratch.q, x(ixc() + 1));
  const double y2 = dyn.corner_height(2, sn, cs, scratch.q, x(ixc() + 1));
  o.lift = std::min(y1, y2);
  o.high = std::max(y1, y2);
  o.offset = offset_of(x, offset);
}

}  // namespace flexrock::detail
