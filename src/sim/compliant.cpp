// SPDX-License-Identifier: BSD-3-Clause
#include "compliant.hpp"

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

CornerContact corner_contact(const Body& body, const SimulationOptions& opt) {
  CornerContact cc;
  const double m = body.params().mass, g = body.g();
  cc.law = opt.contact_force_law;
  cc.k = opt.contact_stiffness;
  cc.p = cc.law == ContactForceLaw::kLinear ? 1.0 : opt.contact_exponent;
  // the static penetration with the weight shared by both tipping points, and the secant
  // stiffness there: the tangential spring's default, and the Hunt-Crossley law's slowest
  // meaningful approach speed (a contact that begins slower than sqrt(g delta_static) is
  // quasi-static: its damping is that of one beginning at that speed)
  const double delta_static = static_penetration(cc.k, cc.p, 0.5 * m * g);
  cc.k_secant = 0.5 * m * g / delta_static;
  const double zeta = opt.contact_restitution >= 0.0
                          ? damping_ratio_for_restitution(opt.contact_restitution)
                          : opt.contact_damping_ratio;
  if (cc.law == ContactForceLaw::kLinear) {
    // the body bouncing on both springs: omega_v = sqrt(2 k / M), each dashpot 2 zeta sqrt(k M/2)
    cc.c = 2.0 * zeta * std::sqrt(0.5 * cc.k * m);
  } else {
    const double e = opt.contact_restitution;
    cc.hc = 0.75 * (1.0 - e * e);
    cc.v_floor = std::sqrt(g * delta_static);
  }
  cc.k_t = opt.contact_tangential_stiffness == kTangentialStiffnessUnset
               ? cc.k_secant
               : opt.contact_tangential_stiffness;
  cc.c_t = 2.0 * (cc.law == ContactForceLaw::kLinear ? zeta : 1.0) * std::sqrt(0.5 * cc.k_t * m);
  return cc;
}

namespace {

// the contact's fastest rate [1/s]: the body bouncing on both springs (and swaying on the
// horizontal ones), omega (zeta + sqrt(zeta^2 - 1)) when overdamped, twice that because a
// corner's effective mass is below half the body's
double contact_rate(const Body& body, const CornerContact& cc) {
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

  bool stop(double t, const std::string& why) {
    res_.status = Status::kStopped;
    res_.message = why;
    Event ev;
    ev.time = t;
    ev.kind = EventKind::kStopped;
    rec_.event(ev);
    return false;
  }

  // closes the open touch: theta_dot after, the floor's impulse and the dissipation since
  void close_transfer(const State& x) {
    if (transfer_.event < 0) return;
    Event& ev = res_.events[static_cast<std::size_t>(transfer_.event)];
    ev.theta_dot_after = x(iv() + 2);
    ev.impulse_x = x(iw() + 4) - transfer_.ix;
    ev.impulse_y = x(iw() + 5) - transfer_.iy;
    ev.energy_loss = contact_loss(x) - transfer_.loss;
    Extremes& ex = res_.extremes;
    ex.max_impulse = std::max(ex.max_impulse, std::abs(ev.impulse_y));
    ex.max_impact_energy_loss = std::max(ex.max_impact_energy_loss, ev.energy_loss);
    transfer_.event = -1;
  }
  // the peak normal force of corner j's contact, written to its touch event
  void close_contact(std::size_t j) {
    Corner& k = corner_[j];
    if (k.touch >= 0) {
      double& estimate = res_.events[static_cast<std::size_t>(k.touch)].force_estimate;
      estimate = std::max(estimate, k.peak);  // a landing on both corners: the larger
      res_.extremes.max_impact_force = std::max(res_.extremes.max_impact_force, k.peak);
    }
    k.touch = -1;
    k.peak = 0.0;
  }

  // mode-time bookkeeping around a change of the corners' states
  void before_change() { mode_before_ = mode(); }
  void after_change(double t) {
    const ContactMode now = mode();
    const bool flew = mode_before_ == ContactMode::kFlight, flies = now == ContactMode::kFlight;
    const bool slid = mode_spec(mode_before_).slip != 0, slides = mode_spec(now).slip != 0;
    if (!flew && flies) flight_start_ = t;
    if (flew && !flies) res_.extremes.flight_time += t - flight_start_;
    if (!slid && slides) {
      slide_start_ = t;
      ++res_.extremes.slips;
      res_.friction_exceeded = true;
    }
    if (slid && !slides) res_.extremes.sliding_time += t - slide_start_;
  }

  Event event_at(double t, EventKind kind, int edge, const State& x) {
    Event ev;
    ev.time = t;
    ev.kind = kind;
    ev.edge = edge;
    ev.theta = x(2);
    ev.theta_dot_before = x(iv() + 2);
    ev.theta_dot_after = x(iv() + 2);
    GuardSample gs;
    evaluate(t, x, gs);
    ev.offset = observation(gs, x).offset;
    ev.friction_demand = gs.fj > 0.0 ? std::abs(gs.fi) / gs.fj : 0.0;
    return ev;
  }

  // a corner whose sticking force already needs more than mu_s F_n slips at once
  void resolve_stick(int e, State& x) {
    Corner& k = corner_[static_cast<std::size_t>(e - 1)];
    if (!std::isfinite(mu_s_) || k.state != CornerState::kStick) return;
    unpack(x);
    Eigen::Vector2d f, ve;
    corner_force(e, std::sin(x(2)), std::cos(x(2)), x, f, ve);
    if (std::abs(f(0)) <= mu_s_ * f(1)) return;
    start_slip(e, f, ve, x);
  }

  // a sticking corner starts to slip: its tangential spring lets go through the slider, so the
  // energy it held is the slip's work (the floor's springs give it to friction)
  void start_slip(int e, const Eigen::Vector2d& f, const Eigen::Vector2d& ve, State& x) {
    const std::size_t j = static_cast<std::size_t>(e - 1);
    Corner& k = corner_[j];
    const double s = std::sin(x(2)), c = std::cos(x(2));
    const double u = dyn_.corner_x(e, s, c, q_, x(0)) - k.anchor;
    const double delta = -dyn_.corner_height(e, s, c, q_, x(1));
    const double held = 0.5 * cc_.k_t * tangential_scale(cc_, f_ref_, delta) * u * u;
    x(iw() + 2) -= held;
    x(iw() + 3) += held;
    released_ += held;
    k.state = CornerState::kSlip;
    k.slip = ve(0) != 0.0 ? (ve(0) > 0.0 ? 1 : -1) : (f(0) > 0.0 ? -1 : 1);
    zero_start_[j + 2] = true;
  }

  // The guards that cross at one instant fire together (advance): an overturn ends the run;
  // corners that touch come down together (one touch event: a landing on both corners when both
  // were free), corners that leave the floor leave together (one lift_off when none is left),
  // then the friction switches of corners that neither touched nor left.
  bool fire(const std::array<bool, kMaxGuards>& fires, double t, State& x) {
    unpack(x);
    if (fires[4]) {
      const int edge = x(2) > 0.0 ? 1 : 2;
      res_.status = Status::kOverturned;
      res_.message = "overturned";
      res_.extremes.overturn_time = t;
      res_.extremes.overturn_edge = edge;
      rec_.event(event_at(t, EventKind::kOverturn, edge, x));
      return false;
    }
    before_change();
    const std::array<CornerState, 2> was = {corner_[0].state, corner_[1].state};
    const std::array<bool, 2> touch = {fires[0] && was[0] == CornerState::kFree,
                                       fires[1] && was[1] == CornerState::kFree};
    const std::array<bool, 2> release = {fires[0] && was[0] != CornerState::kFree,
                                         fires[1] && was[1] != CornerState::kFree};
    if ((touch[0] || touch[1]) && !touch_down(touch, t, x)) return false;
    if (release[0] || release[1]) release_corners(release, t, x);
    for (int e = 1; e <= 2; ++e) {
      const std::size_t j = static_cast<std::size_t>(e - 1);
      if (fires[j + 2] && corner_[j].state == was[j]) friction_switch(e, t, x);
    }
    after_change(t);
    return true;
  }

  // corners touching the floor: an impact when the other corner presses, a landing when it flies
  // (on both corners, edge 0, when both come down at once)
  bool touch_down(const std::array<bool, 2>& touch, double t, State& x) {
    close_transfer(x);
    if (++res_.extremes.impacts > opt_.max_impacts)
      return stop(t, "more than max_impacts = " + std::to_string(opt_.max_impacts) +
                         " touches of the floor");
    const bool both = touch[0] && touch[1];
    const int single = touch[0] ? 1 : 2;
    const bool impact =
        !both && corner_[static_cast<std::size_t>(2 - single)].state != CornerState::kFree;
    const double s = std::sin(x(2)), c = std::cos(x(2));
    const long index = static_cast<long>(res_.events.size());
    for (int e = 1; e <= 2; ++e) {
      const std::size_t j = static_cast<std::size_t>(e - 1);
      if (!touch[j]) continue;
      Corner& k = corner_[j];
      const Eigen::Vector2d vb = dyn_.corner_velocity_body(e, s, c, q_, x(iv() + 2), qd_,
                                                           Eigen::Vector2d(x(iv()), x(iv() + 1)));
      k.state = CornerState::kStick;
      k.anchor = dyn_.corner_x(e, s, c, q_, x(0));
      k.v_in = std::max(-(s * vb(0) + c * vb(1)), 0.0);
      k.peak = 0.0;
      k.touch = index;
      zero_start_[j] = true;
    }
    rec_.event(
        event_at(t, impact ? EventKind::kImpact : EventKind::kLanding, both ? 0 : single, x));
    transfer_.event = index;
    transfer_.ix = x(iw() + 4);
    transfer_.iy = x(iw() + 5);
    transfer_.loss = contact_loss(x);
    transfer_.theta_dot = x(iv() + 2);
    for (int e = 1; e <= 2; ++e)
      if (touch[static_cast<std::size_t>(e - 1)]) resolve_stick(e, x);
    return true;
  }

  // corners leaving the floor: the end of an impact's transfer, an uplift, or a lift-off (one,
  // edge 0, when no corner is left pressing)
  void release_corners(const std::array<bool, 2>& release, double t, const State& x) {
    // a transfer opened at this very instant (a corner touched as the other left) stays open
    const bool opened_now =
        transfer_.event >= 0 && res_.events[static_cast<std::size_t>(transfer_.event)].time == t;
    const bool closes = transfer_.event >= 0 && !opened_now;
    if (closes) close_transfer(x);
    for (std::size_t j = 0; j < 2; ++j) {
      if (!release[j]) continue;
      close_contact(j);
      corner_[j].state = CornerState::kFree;
      zero_start_[j] = true;
    }
    if (corner_[0].state == CornerState::kFree && corner_[1].state == CornerState::kFree) {
      rec_.event(event_at(t, EventKind::kLiftOff, 0, x));
      ++res_.extremes.lift_offs;
    } else if (!closes && !opened_now) {
      const int pivot = corner_[0].state != CornerState::kFree ? 1 : 2;
      rec_.event(event_at(t, EventKind::kUplift, pivot, x));
      if (res_.extremes.first_uplift_time < 0.0) {
        res_.extremes.first_uplift_time = t;
        res_.extremes.first_uplift_edge = pivot;
      }
    }
  }

  // corner e's friction guard: a sticking corner slips, a slipping one sticks where it is
  void friction_switch(int e, double t, State& x) {
    const std::size_t j = static_cast<std::size_t>(e - 1);
    Corner& k = corner_[j];
    unpack(x);
    const double s = std::sin(x(2)), c = std::cos(x(2));
    if (k.state == CornerState::kStick) {
      Eigen::Vector2d f, ve;
      corner_force(e, s, c, x, f, ve);
      start_slip(e, f, ve, x);
      rec_.event(event_at(t, EventKind::kSlipStart, e, x));
    } else if (k.state == CornerState::kSlip) {
      k.state = CornerState::kStick;
      k.anchor = dyn_.corner_x(e, s, c, q_, x(0));
      rec_.event(event_at(t, EventKind::kStick, e, x));
      resolve_stick(e, x);
    }
  }

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

// the body at rest on both springs: theta, y_c and (unless given) q from the statics, by Newton's
// method on the accelerations (a tilt appears when the c.g. is off the base's centre)
template <int MaxN>
void CompliantSim<MaxN>::place_at_rest(const InitialState& init, State& x) {
  const bool solve_q = init.q.size() == 0;
  const int m = 2 + (solve_q ? n_ : 0);
  auto residual = [&](const State& z, Eigen::VectorXd& r) {
    // the corners' anchors where they stand, so that no horizontal spring is stretched
    unpack(z);
    const double s = std::sin(z(2)), c = std::cos(z(2));
    for (int e = 1; e <= 2; ++e)
      corner_[static_cast<std::size_t>(e - 1)].anchor = dyn_.corner_x(e, s, c, q_, z(0));
    State dz(size());
    rhs(0.0, z, dz);
    r.resize(m);
    r(0) = dz(iv() + 1) / g_;
    r(1) = dz(iv() + 2) * h_ / g_;
    if (solve_q) r.tail(n_) = dz.segment(iv() + 3, n_) * h_ / g_;
  };
  auto unknown = [&](State& z, int i) -> double& {
    return i == 0 ? z(1) : i == 1 ? z(2) : z(i + 1);
  };
  Eigen::VectorXd r, r1;
  for (int it = 0; it < 30; ++it) {
    residual(x, r);
    if (r.cwiseAbs().maxCoeff() < 1e-14) break;
    Eigen::MatrixXd jac(m, m);
    for (int i = 0; i < m; ++i) {
      State z = x;
      const double step = i == 0 ? 1e-7 * h_ : 1e-7;
      unknown(z, i) += step;
      residual(z, r1);
      jac.col(i) = (r1 - r) / step;
    }
    const Eigen::VectorXd d = jac.fullPivLu().solve(r);
    for (int i = 0; i < m; ++i) unknown(x, i) -= d(i);
  }
  residual(x, r);  // leaves the anchors at the final place
}

// the initial state: on both corners' springs at rest (pivot 0) or on the pivot's, pressed by the
// whole weight; the corners' states and anchors set accordingly
template <int MaxN>
typename CompliantSim<MaxN>::State CompliantSim<MaxN>::initial_state(const InitialState& init,
                                                                     int pivot) {
  State x(size());
  x.setZero();
  const VectorX q0 = init.q.size() == n_ ? init.q : VectorX(body_.static_deformation());
  x.segment(3, n_) = q0;
  if (init.q_dot.size() == n_) x.segment(iv() + 3, n_) = init.q_dot;
  x(2) = init.theta;
  x(iv() + 2) = init.theta_dot;
  unpack(x);
  if (pivot == 0) {
    // both corners on their springs, at the static penetration
    const double delta = static_penetration(cc_.k, cc_.p, 0.5 * mg_);
    x(0) = h_ * dyn_.psi_x().dot(q_);
    x(1) = h_ * (1.0 + dyn_.psi_y().dot(q_)) - delta;
    x(iv()) = h_ * dyn_.psi_x().dot(qd_);
    x(iv() + 1) = h_ * dyn_.psi_y().dot(qd_);
    corner_[0].state = corner_[1].state = CornerState::kStick;
    place_at_rest(init, x);
  } else {
    // rocking on the pivot's spring, pressed by the whole weight
    const double delta = static_penetration(cc_.k, cc_.p, mg_);
    Eigen::Vector2d r, v;
    const double s = std::sin(x(2)), c = std::cos(x(2));
    dyn_.cg_from_pivot(pivot, s, c, q_, x(iv() + 2), qd_, r, v);
    x(0) = h_ * dyn_.alpha(pivot) + r(0);
    x(1) = -delta + r(1);
    x(iv()) = v(0);
    x(iv() + 1) = v(1);
    Corner& k = corner_[static_cast<std::size_t>(pivot - 1)];
    k.state = CornerState::kStick;
    unpack(x);
    k.anchor = dyn_.corner_x(pivot, s, c, q_, x(0));
  }
  return x;
}

// the eigenvalues of the equations of motion linearized by central differences at rest, on both
// corners (pivot 0) or on one, its corners sticking, without base motion: the coordinates and
// their rates, not the accumulators. The steps are a thousandth of the static penetration (and
// of the corresponding rates), where the linear law is exact and the clips are far
template <int MaxN>
Eigen::VectorXcd CompliantSim<MaxN>::rest_eigenvalues(int pivot, const InitialState& at) {
  const State x0 = initial_state(at, pivot);
  const int dim = 2 * (3 + n_);
  const double delta = static_penetration(cc_.k, cc_.p, 0.5 * mg_);
  const double omega_v = std::sqrt(2.0 * cc_.k_secant / m_);
  Eigen::MatrixXd jac(dim, dim);
  State xp(size()), xm(size()), fp(size()), fm(size());
  for (int j = 0; j < dim; ++j) {
    const int coord = j % (3 + n_);
    double eps = 1e-3 * delta * (coord < 2 ? 1.0 : 1.0 / h_);
    if (j >= 3 + n_) eps *= omega_v;
    xp = x0;
    xm = x0;
    xp(j) += eps;
    xm(j) -= eps;
    rhs(0.0, xp, fp);
    rhs(0.0, xm, fm);
    jac.col(j) = (fp.head(dim) - fm.head(dim)) / (2.0 * eps);
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> es(jac, false);
  return es.eigenvalues();
}

template <int MaxN>
SimulationResult CompliantSim<MaxN>::run(const InitialState& init) {
  int pivot = 0;
  if (init.theta > 0.0 || (init.theta == 0.0 && init.theta_dot > 0.0)) pivot = 1;
  if (init.theta < 0.0 || (init.theta == 0.0 && init.theta_dot < 0.0)) pivot = 2;
  State x = initial_state(init, pivot);
  t_end_ = opt_.t_end >= 0.0 ? opt_.t_end : motion_.duration();
  kinetic0_ = kinetic_energy(x);
  potential0_ = potential_energy(x);
  contact0_ = contact_energy(x);
  mode_before_ = mode();
  if (mode_before_ == ContactMode::kFlight) flight_start_ = 0.0;
  double t = 0.0;
  integ_.start([this](double tt, const State& z, State& dz) { rhs(tt, z, dz); }, ctl_, t, x);
  if (opt_.output_dt > 0.0) emit_row(t, x);
  next_output_ = 1;
  bool running = true;
  while (running && t < t_end_) running = advance(t, x);
  finish(t, x);
  return std::move(res_);
}

template <int MaxN>
bool CompliantSim<MaxN>::advance(double& t, State& x) {
  auto sys = [this](double tt, const State& z, State& dz) { rhs(tt, z, dz); };
  const double t_stop = std::min(motion_.next_breakpoint(t, break_cursor_), t_end_);
  if (integ_.step(sys, t_stop) != StiffSwitching<State>::Status::kAccepted)
    return stop(t, "the integrator's step collapsed at t = " + format_number(t, 9) +
                       " s (a contact stiffer than rtol/atol can follow)");
  if (++steps_ > opt_.max_steps)
    return stop(t, "more than max_steps = " + std::to_string(opt_.max_steps) + " steps");
  ++res_.steps;
  const double t0 = integ_.t0(), t1 = integ_.t1();
  // the guards at the samples of the step
  for (int k = 0; k <= samples_; ++k) {
    const double tk = k == samples_ ? t1 : t0 + (t1 - t0) * k / samples_;
    State& xk = states_[static_cast<std::size_t>(k)];
    if (k == 0) {
      xk = integ_.x0();
    } else if (k == samples_) {
      xk = integ_.x1();
    } else {
      integ_.dense(tk, xk);
    }
    evaluate(tk, xk, smp_[static_cast<std::size_t>(k)]);
    fn_at_[static_cast<std::size_t>(k)] = fn_;
    law_at_[static_cast<std::size_t>(k)] = law_;
  }
  double t_hit = std::numeric_limits<double>::infinity();
  int slot_hit = -1;
  std::array<double, kMaxGuards> crossing{};
  for (int slot = 0; slot < kMaxGuards; ++slot) {
    const double th = first_crossing(slot, smp_.data(), samples_,
                                     zero_start_[static_cast<std::size_t>(slot)], false, *this);
    crossing[static_cast<std::size_t>(slot)] = th;
    if (th < t_hit) {
      t_hit = th;
      slot_hit = slot;
    }
  }
  // the extremes at the samples before the crossing (the normal forces at them included) and at
  // the state just before it, then located between them
  int points = 0;
  for (int k = 0; k <= samples_; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    if (smp_[i].t >= t_hit) break;
    keep_point(points++, observe(smp_[i], states_[i], fn_at_[i]), fn_at_[i], law_at_[i]);
  }
  if (slot_hit >= 0 && points > 0 && t_hit > point_t_[static_cast<std::size_t>(points - 1)]) {
    integ_.dense(t_hit, buf_);
    GuardSample before;
    evaluate(t_hit, buf_, before);
    keep_point(points++, observe(before, buf_, fn_), fn_, law_);
  }
  observe_switches(points);
  locate_step_extremes(points);
  zero_start_.fill(false);
  if (slot_hit < 0) {
    emit_rows_until(t1);
    t = t1;
    x = integ_.x1();
    if (transfer_.event >= 0 && !(x(iv() + 2) * transfer_.theta_dot > 0.0)) close_transfer(x);
    if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
    return true;
  }
  integ_.restep_to(sys, t_hit);
  emit_rows_until(t_hit);
  t = t_hit;
  x = integ_.x1();
  GuardSample gs;
  evaluate(t, x, gs);
  observe(gs, x, fn_);
  // Zeno: more than 64 changes within 1e-9 s end the run
  if (burst_time_ >= 0.0 && t - burst_time_ <= 1e-9) {
    if (++burst_ > 64)
      return stop(t, "more than 64 contact changes within 1e-9 s at t = " + format_number(t, 9) +
                         " s (Zeno behaviour)");
  } else {
    burst_time_ = t;
    burst_ = 0;
  }
  // every guard whose crossing cannot be told from the first one's fires with it, at t_hit: a
  // crossing's bracket ends where it was returned and is crossing_resolution wide, and two
  // brackets that overlap are one instant (both corners of a level body lifting off or landing;
  // alone, the second corner's guard would start the next step already crossed, and be missed)
  std::array<bool, kMaxGuards> fires{};
  for (std::size_t i = 0; i < fires.size(); ++i)
    fires[i] =
        std::isfinite(crossing[i]) && crossing[i] - crossing_resolution(crossing[i]) <= t_hit;
  if (!fire(fires, t, x)) return false;
  integ_.start(sys, ctl_, t, x, integ_.suggested_step());
  if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
  return true;
}

template <int MaxN>
void CompliantSim<MaxN>::finish(double t, const State& x) {
  res_.t_end = t;
  if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
  if (opt_.output_dt > 0.0 && (res_.history.time.empty() || res_.history.time.back() < t - 1e-12))
    emit_row(t, x);
  close_transfer(x);
  for (std::size_t j = 0; j < 2; ++j) close_contact(j);
  const ContactMode now = mode();
  if (now == ContactMode::kFlight && res_.status != Status::kOverturned)
    res_.extremes.flight_time += t - flight_start_;
  if (mode_spec(now).slip != 0 && res_.status != Status::kOverturned)
    res_.extremes.sliding_time += t - slide_start_;
  res_.final_phase = now;
  res_.final_theta = x(2);
  res_.final_theta_dot = x(iv() + 2);
  res_.final_q = x.segment(3, n_);
  res_.final_q_dot = x.segment(iv() + 3, n_);
  GuardSample gs;
  State xf = x;
  evaluate(t, xf, gs);
  res_.final_offset = observation(gs, xf).offset;
  EnergyBalance& e = res_.energy;
  const double kin = kinetic_energy(xf), pot = potential_energy(xf);
  e.input_work = x(iw());
  e.damping_loss = x(iw() + 1);
  e.impact_loss = contact_loss(xf);
  e.friction_loss = x(iw() + 3);
  e.kinetic_change = kin - kinetic0_;
  e.potential_change = pot - potential0_;
  e.residual = e.input_work - (e.kinetic_change + e.potential_change + e.damping_loss +
                               e.impact_loss + e.friction_loss);
  e.scale = std::max({rec_.energy_scale(), std::abs(pot - potential0_), std::abs(kin), kinetic0_,
                      std::abs(e.impact_loss) + e.friction_loss, x(iw() + 2)});
  if (audit_) {
    audit_->dashpot_work = x(iw() + 6);
    audit_->released_at_slip = released_;
  }
  res_.rejected_steps = integ_.rejected_steps();
  res_.rhs_evaluations = integ_.rhs_evaluations();
  if (res_.status == Status::kCompleted) res_.message = "completed";
}

}  // namespace

SimulationResult simulate_compliant(const Body& body, const GroundMotion& motion,
                                    const InitialState& init, const SimulationOptions& opt,
                                    CompliantAudit* audit) {
  // a stack-bounded state up to 16 modes, heap beyond
  if (body.modes() <= 16) return CompliantSim<16>(body, motion, opt, audit).run(init);
  return CompliantSim<Eigen::Dynamic>(body, motion, opt, audit).run(init);
}

Eigen::VectorXcd compliant_rest_eigenvalues(const Body& body, const SimulationOptions& opt,
                                            int pivot, const InitialState& at) {
  const GroundMotion still = GroundMotion::none(1.0);
  if (body.modes() <= 16)
    return CompliantSim<16>(body, still, opt, nullptr).rest_eigenvalues(pivot, at);
  return CompliantSim<Eigen::Dynamic>(body, still, opt, nullptr).rest_eigenvalues(pivot, at);
}

}  // namespace flexrock::detail
