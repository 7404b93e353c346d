// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's loop (compliant.hpp): its state, the corners' forces, the equations of
// motion, the guards and what a run observes. The touches, releases and slips are in
// compliant_events.hpp, the loop's steps in compliant_loop.hpp; each body size is compiled in its
// own file (compliant.cpp, compliant_dynamic.cpp). Internal header.
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <string>

#include "automaton.hpp"
#include "compliant.hpp"
#include "crossing_resolution.hpp"
#include "event_location.hpp"
#include "flexrock/contact/corner_potential.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/integrate/stiff_switching.hpp"
#include "flexrock/model/dynamics.hpp"
#include "flexrock/sim/contact_rules.hpp"
#include "recorder.hpp"
#include "step_extremes.hpp"

namespace flexrock::detail {

// the contact's fastest rate [1/s]: the body bouncing on both springs (and swaying on the
// horizontal ones), omega (zeta + sqrt(zeta^2 - 1)) when overdamped, twice that because a
// corner's effective mass is below half the body's
inline double contact_rate(const Body& body, const CornerContact& cc) {
  const double m = body.params().mass;
  const double k_n = cc.law == ContactForceLaw::kLinear ? cc.k : cc.k_secant;
  auto rate = [m](double k, double c) {
    const double w = std::sqrt(2.0 * k / m), zeta = c / (2.0 * std::sqrt(0.5 * k * m));
    return w * (zeta + std::sqrt(std::max(zeta * zeta - 1.0, 0.0)));
  };
  const double c_n = cc.law == ContactForceLaw::kLinear ? cc.c : 2.0 * std::sqrt(0.5 * k_n * m);
  return 2.0 * std::max({rate(k_n, c_n), rate(cc.k_t, cc.c_t), std::sqrt(2.0 * k_n / m)});
}

enum class CornerState { kFree, kStick, kSlip };

struct Corner {
  CornerState state = CornerState::kFree;
  int slip = 0;       // slip sign s while slipping (+1: along +I)
  double anchor = 0;  // [m] xi_e: where a sticking corner's horizontal spring is unstretched
  double v_in = 0;    // [m/s] approach speed at the touch (Hunt-Crossley damping)
  long touch = -1;    // index of this contact's touch event
  double peak = 0;    // [N] largest normal force since the touch
};

// a touch's impulse, loss and theta_dot after, measured until the next touch or release, or
// until theta_dot has reached zero (the end of the step where it did: a body that stays on both
// corners would otherwise count its weight into the impulse)
struct Transfer {
  long event = -1;
  double ix = 0, iy = 0, loss = 0;  // the accumulators at the touch
  double theta_dot = 0;             // [rad/s] at the touch
};

template <int MaxN>
class CompliantSim final : private GuardProbe {
  static constexpr int MaxS = MaxN == Eigen::Dynamic ? Eigen::Dynamic : 2 * (3 + MaxN) + 7;

 public:
  using Dyn = Dynamics<Eigen::Dynamic, MaxN>;
  using Vec = typename Dyn::Vec;
  using Mat = typename Dyn::Mat;
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, MaxS, 1>;
  // the n deformations and the kReported other quantities whose extremes a run reports
  static constexpr int kReported = 10;
  static constexpr int MaxQ = MaxN == Eigen::Dynamic ? Eigen::Dynamic : MaxN + kReported;
  using Quantities = Eigen::Array<double, Eigen::Dynamic, 1, Eigen::ColMajor, MaxQ, 1>;

  CompliantSim(const Body& body, const GroundMotion& motion, const SimulationOptions& opt,
               CompliantAudit* audit)
      : audit_(audit),
        body_(body),
        dyn_(body),
        motion_(motion),
        opt_(opt),
        n_(body.modes()),
        cc_(corner_contact(body, opt)),
        integ_(3.3 / contact_rate(body, cc_),
               static_cast<StiffMethod>(opt.methods.contact_integrator)),
        rec_(res_, body.params().mass, body.g(), body.params().height, body.modes()) {
    m_ = body.params().mass;
    g_ = body.g();
    h_ = body.params().height;
    mg_ = m_ * g_;
    f_ref_ = 0.5 * mg_;
    mu_s_ = opt.friction_coefficient;
    mu_k_ = std::min(opt.kinetic_friction_coefficient, opt.friction_coefficient);
    mu_cg_inv_ = body.flight_mu_inverse();
    const bool half_pi = opt.overturn == OverturnCriterion::kHalfPi;
    limit_[0] = half_pi ? 0.5 * std::numbers::pi : body.tipping_angle(1);
    limit_[1] = half_pi ? 0.5 * std::numbers::pi : body.tipping_angle(2);
    samples_ = std::clamp(opt.event_samples, 1, kMaxSamples);
    ctl_.rtol = opt.rtol;
    ctl_.atol = opt.atol;
    ctl_.max_step = opt.max_step;
    ctl_.controlled = 2 * (3 + n_);
    q_.setZero(n_);
    qd_.setZero(n_);
    qdd_.setZero(n_);
    gq_.setZero(n_);
    z_.setZero(n_);
    buf_.setZero(size());
    for (State& s : states_) s.setZero(size());
    for (Quantities& v : point_vals_) v.setZero(n_ + kReported);
    point_extreme_.setZero(n_ + kReported);
    point_scratch_.setZero(n_ + kReported);
  }

  SimulationResult run(const InitialState& init);
  Eigen::VectorXcd rest_eigenvalues(int pivot, const InitialState& at);

 private:
  // ---- the state: (x_c, y_c, theta, q), their rates, then the accumulated input work, damping
  // loss, work taken by the floor's springs and dashpots, friction work, the floor's impulse, and
  // the dashpots' work (the floor's work less the springs': for the audit)
  int size() const { return 2 * (3 + n_) + 7; }
  int iv() const { return 3 + n_; }
  int iw() const { return 2 * (3 + n_); }

  template <class X>
  void unpack(const X& x) {
    q_ = x.segment(3, n_);
    qd_ = x.segment(iv() + 3, n_);
  }

  // the force of the floor on corner e (inertial components) and the corner's velocity; with
  // `dashpot`, the power its dashpots take (the force less the contact potential's gradient,
  // against the corner's velocity); with `law`, the normal law's part of the normal force (zero
  // where it clips a pull: the kink the extremes must find)
  template <class X>
  double corner_force(int e, double s, double c, const X& x, Eigen::Vector2d& f,
                      Eigen::Vector2d& ve, double* dashpot = nullptr, double* law = nullptr) const {
    const Corner& k = corner_[static_cast<std::size_t>(e - 1)];
    const Eigen::Vector2d vc(x(iv()), x(iv() + 1));
    const Eigen::Vector2d vb = dyn_.corner_velocity_body(e, s, c, q_, x(iv() + 2), qd_, vc);
    ve = {c * vb(0) - s * vb(1), s * vb(0) + c * vb(1)};
    const double delta = -dyn_.corner_height(e, s, c, q_, x(1));
    if (k.state == CornerState::kStick) {
      const double u = dyn_.corner_x(e, s, c, q_, x(0)) - k.anchor;
      const CornerForce cf = sticking_corner_force(cc_, f_ref_, delta, -ve(1), u, ve(0), k.v_in);
      f = {cf.t, cf.n};
      if (law) *law = normal_force(cc_, delta, -ve(1), k.v_in);
      if (dashpot) {
        const double phi = tangential_scale(cc_, f_ref_, delta);
        const double fn_el =
            phi * f_ref_ + 0.5 * cc_.k_t * tangential_scale_slope(cc_, f_ref_, delta) * u * u;
        *dashpot = -(cf.n - fn_el) * ve(1) - (cf.t + phi * cc_.k_t * u) * ve(0);
      }
      return cf.n;
    }
    const double fn = normal_force(cc_, delta, -ve(1), k.v_in);
    if (law) *law = fn;
    f = {k.state == CornerState::kSlip ? -k.slip * mu_k_ * fn : 0.0, fn};
    if (dashpot) *dashpot = -(fn - tangential_scale(cc_, f_ref_, delta) * f_ref_) * ve(1);
    return fn;
  }

  void rhs(double t, const State& x, State& dx) {
    unpack(x);
    const double s = std::sin(x(2)), c = std::cos(x(2)), thd = x(iv() + 2);
    const Eigen::Vector2d vc(x(iv()), x(iv() + 1));
    const BaseAcceleration a = motion_.at(t, rhs_cursor_);
    double thdd = 0.0;
    dyn_.flight_acceleration(q_, thd, qd_, thdd, qdd_);
    // the corner forces' generalised forces on (theta, q) over M h^2: -B_e^T R^T F / (M h)
    // (docs/theory.md, "Compliant contact")
    double g_theta = 0.0, fx = 0.0, fy = 0.0, p_floor = 0.0, p_friction = 0.0, p_dashpot = 0.0;
    gq_.setZero();
    for (int e = 1; e <= 2; ++e) {
      const Corner& k = corner_[static_cast<std::size_t>(e - 1)];
      if (k.state == CornerState::kFree) continue;
      Eigen::Vector2d f, ve;
      double dashpot = 0.0;
      corner_force(e, s, c, x, f, ve, &dashpot);
      p_dashpot += dashpot;
      const double fbx = c * f(0) + s * f(1), fby = -s * f(0) + c * f(1);
      const double wx = -dyn_.alpha(e) + dyn_.psi_x().dot(q_), wy = 1.0 + dyn_.psi_y().dot(q_);
      g_theta -= (-wy * fbx + wx * fby) / (m_ * h_);
      if (n_ > 0) gq_.noalias() -= (dyn_.psi_x() * fbx + dyn_.psi_y() * fby) / (m_ * h_);
      fx += f(0);
      fy += f(1);
      if (k.state == CornerState::kSlip) {
        p_friction += f(0) * ve(0);
        p_floor += f(1) * ve(1);
      } else {
        p_floor += f.dot(ve);
      }
    }
    // A_cg [dthdd; dqdd] = [g_theta; g_q], by block elimination with the constant mu_cg^-1
    double dthdd = 0.0;
    if (n_ == 0) {
      dthdd = g_theta / dyn_.flight_inertia(q_);
    } else {
      const Vec b = dyn_.flight_coupling(q_);
      z_.noalias() = mu_cg_inv_ * b;
      const Vec y = mu_cg_inv_ * gq_;
      dthdd = (g_theta - b.dot(y)) / (dyn_.flight_inertia(q_) - b.dot(z_));
      qdd_ += y - z_ * dthdd;
    }
    dx.head(iv()) = x.segment(iv(), iv());
    dx(iv()) = -a.x + fx / m_;
    dx(iv() + 1) = -g_ - a.y + fy / m_;
    dx(iv() + 2) = thdd + dthdd;
    dx.segment(iv() + 3, n_) = qdd_;
    dx(iw()) = dyn_.flight_input_power(vc, a);
    dx(iw() + 1) = dyn_.damping_power(qd_);
    dx(iw() + 2) = -p_floor;
    dx(iw() + 3) = -p_friction;
    dx(iw() + 4) = fx;
    dx(iw() + 5) = fy;
    dx(iw() + 6) = p_dashpot;
  }

  // guards in slot order: corner 1 and 2 contact, corner 1 and 2 friction, overturning
  template <class X>
  void evaluate(double t, const X& x, GuardSample& gs) {
    unpack(x);
    const double s = std::sin(x(2)), c = std::cos(x(2));
    gs.t = t;
    double fx = 0.0, fy = 0.0, moment = 0.0;
    for (int e = 1; e <= 2; ++e) {
      const std::size_t j = static_cast<std::size_t>(e - 1);
      const Corner& k = corner_[j];
      const double y = dyn_.corner_height(e, s, c, q_, x(1));
      fn_[j] = law_[j] = 0.0;
      if (k.state == CornerState::kFree) {
        gs.v[j] = y / h_;
        gs.v[j + 2] = 1.0;
        continue;
      }
      Eigen::Vector2d f, ve;
      fn_[j] = corner_force(e, s, c, x, f, ve, nullptr, &law_[j]);
      gs.v[j] = -y / h_;
      if (k.state == CornerState::kSlip) {
        gs.v[j + 2] = k.slip * ve(0) / std::sqrt(g_ * h_);
      } else {
        gs.v[j + 2] = std::isfinite(mu_s_) ? (mu_s_ * f(1) - std::abs(f(0))) / mg_ : 1.0;
      }
      fx += f(0);
      fy += f(1);
      moment += (dyn_.corner_x(e, s, c, q_, x(0)) - x(0)) * f(1);
    }
    gs.v[4] = std::min(limit_[0] - x(2), limit_[1] + x(2));
    gs.fi = fx / mg_;
    gs.fj = fy / mg_;
    gs.moment = moment / (mg_ * h_);
  }

  double guard_value(int slot, double t) override {
    integ_.dense(t, buf_);
    GuardSample gs;
    evaluate(t, buf_, gs);
    return gs.v[static_cast<std::size_t>(slot)];
  }

  // the body's contact mode, read from the corners
  ContactMode mode() const {
    const bool c1 = corner_[0].state != CornerState::kFree;
    const bool c2 = corner_[1].state != CornerState::kFree;
    const int pivot = c1 && c2 ? 0 : c1 ? 1 : c2 ? 2 : -1;
    int slip = 0;
    for (const Corner& k : corner_)
      if (k.state == CornerState::kSlip && slip == 0) slip = k.slip;
    return pivot < 0 ? ContactMode::kFlight : contact_mode(pivot, slip);
  }

  double contact_energy(const State& x) {
    unpack(x);
    const double s = std::sin(x(2)), c = std::cos(x(2));
    double e = 0.0;
    for (int i = 1; i <= 2; ++i) {
      const Corner& k = corner_[static_cast<std::size_t>(i - 1)];
      if (k.state == CornerState::kFree) continue;
      const double delta = -dyn_.corner_height(i, s, c, q_, x(1));
      e += k.state == CornerState::kStick
               ? corner_potential(cc_, f_ref_, delta, dyn_.corner_x(i, s, c, q_, x(0)) - k.anchor)
               : normal_spring_energy(cc_, delta);
    }
    return e;
  }
  double kinetic_energy(const State& x) {
    unpack(x);
    return dyn_.flight_kinetic_energy(q_, x(iv() + 2), qd_, Eigen::Vector2d(x(iv()), x(iv() + 1)));
  }
  double potential_energy(const State& x) {
    unpack(x);
    return dyn_.flight_potential_energy(x(1), q_) + contact_energy(x);
  }
  // the dissipation of the springs and dashpots so far: the floor's work less what they store
  double contact_loss(const State& x) { return x(iw() + 2) - (contact_energy(x) - contact0_); }

  Observation observation(const GuardSample& gs, const State& x) {
    Observation o;
    o.t = gs.t;
    o.mode = mode();
    o.theta = x(2);
    o.theta_dot = x(iv() + 2);
    o.q = x.data() + 3;
    o.q_dot = x.data() + iv() + 3;
    o.fi = gs.fi;
    o.fj = gs.fj;
    o.moment = gs.moment;
    o.input_work = x(iw());
    o.damping_loss = x(iw() + 1);
    unpack(x);
    const double s = std::sin(x(2)), c = std::cos(x(2));
    const double y1 = dyn_.corner_height(1, s, c, q_, x(1));
    const double y2 = dyn_.corner_height(2, s, c, q_, x(1));
    o.lift = std::min(y1, y2);
    o.high = std::max(y1, y2);
    o.offset = x(0) + h_ * (-c * dyn_.psi_x().dot(q_) + s * (1.0 + dyn_.psi_y().dot(q_)));
    return o;
  }

  // gs and fn (the corners' normal forces) as evaluate() left them for the instant x
  // (returns the observation, for keep_point)
  Observation observe(const GuardSample& gs, const State& x, const std::array<double, 2>& fn) {
    const Observation o = observation(gs, x);
    rec_.observe(o);
    for (std::size_t j = 0; j < 2; ++j) {
      if (corner_[j].state == CornerState::kFree) continue;
      corner_[j].peak = std::max(corner_[j].peak, fn[j]);
      res_.extremes.max_contact_force = std::max(res_.extremes.max_contact_force, fn[j]);
    }
    return o;
  }

  // the quantities whose largest values the run reports, at the instant o (fn its corners' forces
  // as evaluate() left them): |q_j|, then |F_I| and |moment| (over M g, M g h), the friction
  // demand, theta on edge 1 and on edge 2, the higher corner's height, |offset|, the height in
  // flight, and each corner's normal force while it touches [N] (its contact's peak, the touch
  // event's force)
  void reported_values(const Observation& o, const std::array<double, 2>& fn, Quantities& v) const {
    for (int i = 0; i < n_; ++i) v(i) = std::abs(o.q[i]);
    v(n_) = std::abs(o.fi);
    v(n_ + 1) = std::abs(o.moment);
    v(n_ + 2) = friction_demand(o.fi, o.fj);
    v(n_ + 3) = std::max(o.theta, 0.0);
    v(n_ + 4) = std::max(-o.theta, 0.0);
    v(n_ + 5) = o.high;
    v(n_ + 6) = std::abs(o.offset);
    v(n_ + 7) = o.mode == ContactMode::kFlight ? o.lift : 0.0;
    for (std::size_t j = 0; j < 2; ++j)
      v(n_ + 8 + static_cast<int>(j)) = corner_[j].state == CornerState::kFree ? 0.0 : fn[j];
  }
  // the same quantities' extremes so far
  void reported_extremes(Quantities& e) const {
    const Extremes& ex = res_.extremes;
    e.head(n_) = ex.max_abs_q.array();
    e(n_) = ex.max_base_shear / mg_;
    e(n_ + 1) = ex.max_overturning_moment / (mg_ * h_);
    e(n_ + 2) = ex.max_friction_demand;
    e(n_ + 3) = ex.max_theta_edge1;
    e(n_ + 4) = ex.max_theta_edge2;
    e(n_ + 5) = ex.max_uplift;
    e(n_ + 6) = ex.max_offset;
    e(n_ + 7) = ex.max_flight_height;
    e(n_ + 8) = corner_[0].peak;
    e(n_ + 9) = corner_[1].peak;
  }
  // (law: the normal laws' parts of fn, whose clipping at zero is the corners' pressing switch)
  void keep_point(int p, const Observation& o, const std::array<double, 2>& fn,
                  const std::array<double, 2>& law) {
    const auto pp = static_cast<std::size_t>(p);
    point_t_[pp] = o.t;
    reported_values(o, fn, point_vals_[pp]);
    point_press_[pp] = {law[0] > 0.0, law[1] > 0.0, o.fj >= kPressingFraction};
  }
  // the peaks between the step's kept points 0..points-1 (step_extremes.hpp), on the dense output
  void locate_step_extremes(int points) {
    if (points < 3) return;
    reported_extremes(point_extreme_);
    locate_peaks_between(
        point_t_.data(), point_vals_.data(), points, point_extreme_,
        [this](int k, double t) {
          integ_.dense(t, buf_);
          GuardSample gs;
          evaluate(t, buf_, gs);
          reported_values(observation(gs, buf_), fn_, point_scratch_);
          return point_scratch_(k);
        },
        [this](double t) { observe_at(t); });
  }
  // the state at t within the last step, evaluated and observed (an extreme located there)
  void observe_at(double t) {
    integ_.dense(t, buf_);
    GuardSample gs;
    evaluate(t, buf_, gs);
    observe(gs, buf_, fn_);
  }

  // Two switches inside a step make a reported quantity jump or kink, so that its peak lies at
  // the switch, where no parabola finds it: a touching corner's force is clipped at zero where its
  // dashpot would pull (max(0, ...)), and the moment rises as the corner that leaves unloads until
  // its force reaches zero; the friction demand |F_I|/F_J counts only while the floor presses with
  // at least kPressingFraction of the weight, and rises toward that limit before a lift-off.
  // Between two kept points where one of them switches, the switch is bisected on the dense output
  // (bisect_switch) and observed on the side where the force still presses.
  void observe_switches(int points) {
    for (int p = 1; p < points; ++p) {
      const auto pp = static_cast<std::size_t>(p);
      for (int j = 0; j < 3; ++j) {
        const auto jj = static_cast<std::size_t>(j);
        // j = 0, 1: corner j + 1's force (never pressing while free); j = 2: the floor's
        // pressing for the friction demand
        const bool pressed_before = point_press_[pp - 1][jj];
        if (pressed_before == point_press_[pp][jj]) continue;
        observe_at(bisect_switch(point_t_[pp - 1], point_t_[pp], pressed_before, [&](double t) {
          integ_.dense(t, buf_);
          GuardSample gs;
          evaluate(t, buf_, gs);
          return j < 2 ? law_[jj] > 0.0 : gs.fj >= kPressingFraction;
        }));
      }
    }
  }

  void emit_rows_until(double t_cut) {
    if (opt_.output_dt <= 0.0) return;
    for (;;) {
      const double to = static_cast<double>(next_output_) * opt_.output_dt;
      if (to > t_cut || to > t_end_ * (1.0 + 1e-14)) break;
      integ_.dense(std::min(to, integ_.t1()), buf_);
      emit_row(to, buf_);
      ++next_output_;
    }
  }
  void emit_row(double t, const State& x) {
    GuardSample gs;
    evaluate(t, x, gs);
    const Observation o = observation(gs, x);
    const double resultant = gs.fj > 0.0 ? h_ * gs.moment / gs.fj : 0.0;
    rec_.row(o, motion_.at(t, row_cursor_), kinetic_energy(x), potential_energy(x), resultant,
             contact_loss(x));
  }

  // the touches, releases and slips (compliant_events.hpp)
  bool stop(double t, const std::string& why);
  void close_transfer(const State& x);
  void close_contact(std::size_t j);
  void before_change();
  void after_change(double t);
  Event event_at(double t, EventKind kind, int edge, const State& x);
  void resolve_stick(int e, State& x);
  void start_slip(int e, const Eigen::Vector2d& f, const Eigen::Vector2d& ve, State& x);
  bool fire(const std::array<bool, kMaxGuards>& fires, double t, State& x);
  bool touch_down(const std::array<bool, 2>& touch, double t, State& x);
  void release_corners(const std::array<bool, 2>& release, double t, const State& x);
  void friction_switch(int e, double t, State& x);

  bool advance(double& t, State& x);
  void place_at_rest(const InitialState& init, State& x);
  State initial_state(const InitialState& init, int pivot);
  void finish(double t, const State& x);

  CompliantAudit* audit_;
  const Body& body_;
  Dyn dyn_;
  const GroundMotion& motion_;
  SimulationOptions opt_;
  int n_;
  CornerContact cc_;
  // DOPRI5 while accuracy sets the step, the Rosenbrock method while the springs' stability
  // would: an explicit step is held below about 3.3 / lambda by the contact's fastest rate lambda
  // however slowly the body moves (a body resting on its springs)
  StiffSwitching<State> integ_;
  SimulationResult res_;
  Recorder rec_;
  double m_ = 0, g_ = 0, h_ = 0, mg_ = 0, mu_s_ = 0, mu_k_ = 0;
  double f_ref_ = 0;     // [N] the normal spring's force at rest on both corners (M g / 2)
  double released_ = 0;  // [J] tangential springs' energy let go at slip starts
  Mat mu_cg_inv_;
  std::array<double, 2> limit_{};
  int samples_ = 4;
  StepControl ctl_;
  std::array<Corner, 2> corner_{};
  Transfer transfer_;
  std::array<double, 2> fn_{};  // the corners' normal forces at the last evaluation [N]
  std::array<std::array<double, 2>, kMaxSamples + 1> fn_at_{};  // fn_ at this step's samples
  // the normal laws' parts of fn_ (clipped at zero where a dashpot would pull), and at the samples
  std::array<double, 2> law_{};
  std::array<std::array<double, 2>, kMaxSamples + 1> law_at_{};
  std::array<bool, kMaxGuards> zero_start_{};
  std::array<GuardSample, kMaxSamples + 1> smp_;
  std::array<State, kMaxSamples + 1> states_;
  // the reported quantities (reported_values) at the step's observed points, for their extremes
  std::array<double, kMaxSamples + 2> point_t_{};
  std::array<Quantities, kMaxSamples + 2> point_vals_;
  Quantities point_extreme_, point_scratch_;
  // at the same points: corner 1's and 2's force pressing, the floor pressing the friction demand's
  // kPressingFraction (observe_switches)
  std::array<std::array<bool, 3>, kMaxSamples + 2> point_press_{};
  GroundMotion::Cursor rhs_cursor_, row_cursor_, break_cursor_;
  Vec q_, qd_, qdd_, gq_, z_;
  State buf_;
  double t_end_ = 0, kinetic0_ = 0, potential0_ = 0, contact0_ = 0;
  double flight_start_ = 0, slide_start_ = 0;
  ContactMode mode_before_ = ContactMode::kFullContact;
  long next_output_ = 0, steps_ = 0;
  double burst_time_ = -1.0;
  int burst_ = 0;
};

}  // namespace flexrock::detail
