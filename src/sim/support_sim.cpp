// SPDX-License-Identifier: BSD-3-Clause
// A rigid block on a support that moves with it (docs/theory.md §24): its own event loop, beside
// the single body's Simulator. The state is (u, theta, u_dot, theta_dot, input work, dashpot work)
// with u the support's displacement relative to the ground; DOP853 steps it, the guards of the
// current mode are sampled on its dense output and located by TOMS 748 (event_location.hpp).
//
// | mode             | guards (fire going down to 0)                  | reset                  |
// |------------------|------------------------------------------------|------------------------|
// | full contact     | uplift edge 1: alpha_1 g_y - A                 | rock on edge 1         |
// |                  | uplift edge 2: alpha_2 g_y + A                 | rock on edge 2         |
// |                  | lift-off: g_y / g                              | stop (flight not built)|
// |                  | support peak: u u_dot                          | record                 |
// | rocking on e     | impact: s theta                                | impact map (§24)       |
// |                  | overturn: limit - s theta                      | stop (overturned)      |
// |                  | lift-off: F_y / M g                            | stop (flight not built)|
// |                  | peak: s theta_dot                              | record                 |
// |                  | support peak: u u_dot                          | record                 |
// (A: the support's absolute acceleration; g_y = g + Y''; s = +1 on edge 1, -1 on edge 2.)
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "event_location.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/contact/support_impact.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/integrate/dop853.hpp"
#include "flexrock/sim/support.hpp"

namespace flexrock {

namespace {

using State = Eigen::Matrix<double, 6, 1>;
constexpr int kU = 0, kTheta = 1, kUDot = 2, kThetaDot = 3, kWorkIn = 4, kWorkDamp = 5;
constexpr double kInf = std::numeric_limits<double>::infinity();
// DOP853: an 8th-order step with 7th-order dense output, about half of DOPRI5's steps on these
// smooth motions at the engine's tolerances
using Stepper = Dop853<State>;

// the guard slots of each mode
constexpr int kFullUplift1 = 0, kFullUplift2 = 1, kFullLiftOff = 2, kFullSupportPeak = 3;
constexpr int kRockImpact = 0, kRockOverturn = 1, kRockLiftOff = 2, kRockPeak = 3,
              kRockSupportPeak = 4;

// 64 contact changes within this span end the run (a cascade the loop cannot resolve)
constexpr int kZenoChanges = 64;
constexpr double kZenoSpan = 1e-9;

// the constants of the block and the support
struct Plant {
  double m = 0.0, ms = 0.0, h = 0.0, zeta2 = 0.0, g = 0.0, k = 0.0, c = 0.0;
  double alpha1 = 0.0, alpha2 = 0.0;
  double mt() const { return m + ms; }
  // alpha of the pivot on `edge` (§1): -alpha_1 on edge 1, alpha_2 on edge 2
  double alpha(int edge) const { return edge == 1 ? -alpha1 : alpha2; }
};

// the derivative and what the outputs and guards read, in mode `edge` (0: full contact)
struct Eval {
  double udd = 0.0, thdd = 0.0;
  double fx = 0.0, fy = 0.0;  // [N] the support's force on the block, inertial I and J
  double acc = 0.0;           // [m/s^2] the support's absolute acceleration
  double p_in = 0.0;          // [W] the base acceleration's power on the relative momenta
  double p_damp = 0.0;        // [W] the dashpot's dissipation c u_dot^2
};

Eval evaluate(const Plant& p, int edge, const State& x, BaseAcceleration a) {
  Eval e;
  const double u = x(kU), ud = x(kUDot), gy = p.g + a.y;
  if (edge == 0) {
    // full contact: one rigid mass m + m_s on the spring and dashpot
    e.acc = -(p.k * u + p.c * ud) / p.mt() + 0.0;  // + 0.0: no "-0" in the outputs
    e.udd = e.acc - a.x;
    e.fx = p.m * e.acc;
    e.fy = p.m * gy;
    e.p_in = -a.x * p.mt() * ud;
  } else {
    const double al = p.alpha(edge), th = x(kTheta), thd = x(kThetaDot);
    const double s = std::sin(th), c = std::cos(th);
    const double cx = al * s - c, cy = -s - al * c, cxp = al * c + s;
    // the 2 x 2 mass matrix of (u, theta) and its right-hand side (§24)
    const double m11 = p.mt(), m12 = p.m * p.h * cx;
    const double m22 = p.m * p.h * p.h * (1.0 + p.zeta2 + al * al);
    const double r1 = -p.mt() * a.x - p.c * ud - p.k * u - p.m * p.h * cxp * thd * thd;
    const double r2 = -p.m * p.h * cx * a.x - p.m * p.h * cy * gy;
    const double det = m11 * m22 - m12 * m12;
    e.udd = (r1 * m22 - m12 * r2) / det;
    e.thdd = (m11 * r2 - m12 * r1) / det;
    e.acc = a.x + e.udd;
    e.fx = p.m * (e.acc + p.h * (cx * e.thdd + cxp * thd * thd));
    e.fy = p.m * gy + p.m * p.h * (cy * e.thdd - (c - al * s) * thd * thd);
    const double vx = ud + p.h * cx * thd, vy = p.h * cy * thd;
    e.p_in = -a.x * (p.ms * ud + p.m * vx) - a.y * p.m * vy;
  }
  e.p_damp = p.c * ud * ud;
  return e;
}

// kinetic energy relative to the ground and potential energy (gravity above the support, spring)
double kinetic(const Plant& p, int edge, const State& x) {
  const double ud = x(kUDot);
  if (edge == 0) return 0.5 * p.mt() * ud * ud;
  const double al = p.alpha(edge), th = x(kTheta), thd = x(kThetaDot);
  const double cx = al * std::sin(th) - std::cos(th), cy = -std::sin(th) - al * std::cos(th);
  const double vx = ud + p.h * cx * thd, vy = p.h * cy * thd;
  return 0.5 * p.ms * ud * ud + 0.5 * p.m * (vx * vx + vy * vy) +
         0.5 * p.m * p.zeta2 * p.h * p.h * thd * thd;
}

double potential(const Plant& p, int edge, const State& x) {
  const double u = x(kU);
  double y = p.h;
  if (edge != 0) y = p.h * (std::cos(x(kTheta)) - p.alpha(edge) * std::sin(x(kTheta)));
  return 0.5 * p.k * u * u + p.m * p.g * y;
}

// the exact full-contact update (docs/theory.md §24): block and support one mass m + m_s on the
// spring and dashpot, u'' + 2 zeta w u' + w^2 u = -a(t), under a base acceleration linear in time
// on the step, a(t0 + tau) = a0 + s tau (a sampled record between its samples). The particular
// solution A + B tau plus the free motion exp(F tau) w0; the base's work from
// -m_t [a u] + m_t s int u, the dashpot's as the work less the change of energy
class ExactWalk {
 public:
  explicit ExactWalk(const Plant& p)
      : mt_(p.mt()), k_(p.k), c_(p.c), w2_(p.k / p.mt()), zw2_(p.c / p.mt()) {}

  double omega() const { return std::sqrt(w2_); }

  void begin(double t0, const State& x0, double a0, double slope) {
    t0_ = t1_ = t0;
    x0_ = x1_ = x0;
    a0_ = a0;
    s_ = slope;
  }
  void end_at(double t1) {
    t1_ = t1;
    dense(t1, x1_);
  }
  double t0() const { return t0_; }
  double t1() const { return t1_; }
  const State& x0() const { return x0_; }
  const State& x1() const { return x1_; }

  void dense(double t, State& out) const {
    const double tau = t - t0_;
    const double mu = -0.5 * zw2_, d2 = mu * mu - w2_;
    double cc = 1.0, ss = tau;  // cos or cosh of d tau, and sin(d tau)/d or sinh(d tau)/d
    if (d2 < 0.0) {
      const double d = std::sqrt(-d2);
      cc = std::cos(d * tau);
      ss = std::sin(d * tau) / d;
    } else if (d2 > 0.0) {
      const double d = std::sqrt(d2);
      cc = std::cosh(d * tau);
      ss = std::sinh(d * tau) / d;
    }
    const double e = std::exp(mu * tau);
    const double p11 = e * (cc - mu * ss), p12 = e * ss, p21 = -e * w2_ * ss,
                 p22 = e * (cc + mu * ss);
    const double b = -s_ / w2_, a = (-a0_ - zw2_ * b) / w2_;
    const double u0 = x0_(kU), v0 = x0_(kUDot);
    const double wu0 = u0 - a, wv0 = v0 - b;
    const double wu = p11 * wu0 + p12 * wv0, wv = p21 * wu0 + p22 * wv0;
    const double u = a + b * tau + wu, v = b + wv;
    // int_0^tau w = F^-1 (exp(F tau) - I) w0, F^-1 = [[-2 zeta w, -1], [w^2, 0]] / w^2
    const double int_u = a * tau + 0.5 * b * tau * tau + (-zw2_ * (wu - wu0) - (wv - wv0)) / w2_;
    const double work = -mt_ * ((a0_ + s_ * tau) * u - a0_ * u0) + mt_ * s_ * int_u;
    const double de = 0.5 * mt_ * (v * v - v0 * v0) + 0.5 * k_ * (u * u - u0 * u0);
    out = x0_;
    out(kU) = u;
    out(kUDot) = v;
    out(kWorkIn) = x0_(kWorkIn) + work;
    out(kWorkDamp) = x0_(kWorkDamp) + (c_ > 0.0 ? work - de : 0.0);
  }

 private:
  double mt_, k_, c_, w2_, zw2_;  // w2 = w^2, zw2 = 2 zeta w
  double t0_ = 0.0, t1_ = 0.0, a0_ = 0.0, s_ = 0.0;
  State x0_ = State::Zero(), x1_ = State::Zero();
};

class SupportLoop final : public detail::GuardProbe {
 public:
  SupportLoop(const Body& body, const SupportParameters& sp, const GroundMotion& motion,
              const InitialState& init, const SimulationOptions& opt)
      : body_(body), motion_(motion), opt_(opt) {
    const BodyParameters& bp = body.params();
    p_.m = bp.mass;
    p_.ms = sp.mass;
    p_.h = bp.height;
    p_.zeta2 = bp.zeta2;
    p_.g = bp.gravity;
    p_.k = sp.stiffness;
    p_.c = sp.damping;
    p_.alpha1 = body.alpha1();
    p_.alpha2 = body.alpha2();
    walk_ = ExactWalk(p_);
    x_.setZero();
    x_(kU) = sp.displacement;
    x_(kUDot) = sp.velocity;
    x_(kTheta) = init.theta;
    x_(kThetaDot) = init.theta_dot;
    if (init.theta != 0.0) {
      edge_ = init.theta > 0.0 ? 1 : 2;
    } else if (init.theta_dot != 0.0) {
      edge_ = init.theta_dot > 0.0 ? 1 : 2;
    }
    // the chatter interval (§10): Housner's frequency parameter of the stiffer edge
    double p2 = 0.0;
    for (const double a : {p_.alpha1, p_.alpha2})
      p2 = std::max(p2, body.g_over_h() * std::sqrt(1.0 + a * a) / (1.0 + p_.zeta2 + a * a));
    chatter_dt_ = opt.chatter_ratio * 2.0 * std::numbers::pi / std::sqrt(p2);
    t_end_ = opt.t_end >= 0.0 ? opt.t_end : motion.duration();
    walk_ok_ = opt.methods.full_contact_walk && (motion.is_sampled() || motion.is_none());
    ctl_.rtol = opt.rtol;
    ctl_.atol = opt.atol;
    ctl_.controlled = 4;
    ctl_.max_step = opt.max_step;
    samples_ = std::clamp(opt.event_samples, 1, detail::kMaxSamples);
  }

  SupportRunResult run() {
    SimulationResult& r = out_.body;
    k0_ = kinetic(p_, edge_, x_);
    e0_ = k0_ + potential(p_, edge_, x_);
    r.history.modes = 0;
    r.extremes.max_abs_q = VectorX(0);
    next_output_ = 0.0;
    last_change_ = -kInf;
    // a block at rest that the support's start already uplifts
    if (edge_ == 0) enter_full_contact(0.0, /*at_start=*/true);
    if (!stopped_) record_until(0.0, x_);
    observe(0.0, x_);
    if (edge_ != 0 && !stopped_) {
      first_uplift(0.0);
      check_entry_reaction();
    }
    bool restart = true;
    Stepper st;
    stepper_ = &st;
    auto rhs = [this](double t, const State& x, State& dx) { derivative(t, x, dx); };
    while (!stopped_ && t_ < t_end_) {
      const double t_stop = std::min(motion_.next_breakpoint(t_, cursor_), t_end_);
      walking_ = edge_ == 0 && walk_ok_;
      nsamp_ = samples_;
      if (walking_) {
        // full contact under a record: one exact update per sample interval (capped by
        // max_step), its guards sampled at most 0.5 rad of the support's motion apart
        const double tb = motion_.next_breakpoint(t_, cursor_);
        const double a0 = motion_.at(t_, cursor_).x;
        const double slope = std::isfinite(tb) ? (motion_.at(tb, cursor_).x - a0) / (tb - t_) : 0.0;
        double h = std::min(t_stop - t_, opt_.max_step);
        const double w = walk_.omega();
        if (w * h > 0.5 * detail::kMaxSamples) h = 0.5 * detail::kMaxSamples / w;
        nsamp_ =
            std::clamp(static_cast<int>(std::ceil(w * h / 0.5)), samples_, detail::kMaxSamples);
        walk_.begin(t_, x_, a0, slope);
        walk_.end_at(t_ + h >= t_stop ? t_stop : t_ + h);
        restart = true;  // the integrator starts afresh where the walk ends
      } else {
        if (restart) {
          st.start(rhs, ctl_, t_, x_);
          restart = false;
        }
        if (st.step(rhs, t_stop) != Stepper::Status::kAccepted) {
          stop("the integrator's step collapsed at t = " + format_number(t_, 6) +
               " s (a stiff support: lower its frequency or loosen rtol)");
          break;
        }
      }
      ++r.steps;
      if (r.steps > opt_.max_steps) {
        stop("max_steps = " + std::to_string(opt_.max_steps) + " reached");
        break;
      }
      // the guards on the step's samples
      const double t0 = step_t0(), t1 = walking_ ? walk_.t1() : st.t1();
      xs_[0] = walking_ ? walk_.x0() : st.x0();
      smp_[0] = sample(t0, xs_[0]);
      for (int i = 1; i <= nsamp_; ++i) {
        const double ti = i == nsamp_ ? t1 : t0 + (t1 - t0) * i / nsamp_;
        State& xi = xs_[static_cast<std::size_t>(i)];
        if (i == nsamp_) {
          xi = walking_ ? walk_.x1() : st.x1();
        } else {
          dense_at(ti, xi);
        }
        smp_[static_cast<std::size_t>(i)] = sample(ti, xi);
      }
      have_step_ = true;
      double t_ev = kInf;
      int slot = -1;
      for (int j = 0; j < guard_count(); ++j) {
        const bool zero_start = j == kRockImpact && edge_ != 0 && zero_start_impact_;
        const double tc = detail::first_crossing(j, smp_.data(), nsamp_, zero_start,
                                                 /*fires_if_unresolved=*/false, *this);
        if (tc < t_ev) {
          t_ev = tc;
          slot = j;
        }
      }
      zero_start_impact_ = false;
      if (slot >= 0) {
        if (walking_) {
          walk_.end_at(t_ev);
          x_ = walk_.x1();
        } else {
          st.restep_to(rhs, t_ev);
          x_ = st.x1();
        }
        t_ = t_ev;
        fold_samples(t_ev);
        record_until(t_, x_);
        observe(t_, x_);
        const bool again = fire(slot);
        restart = restart || again;
      } else {
        fold_samples(t1);
        t_ = t1;
        x_ = walking_ ? walk_.x1() : st.x1();
        record_until(t_, x_);
        observe(t_, x_);
        // a breakpoint of the motion: the next step starts from the right-hand limit
        if (!walking_ && t_ == t_stop && t_stop < t_end_) st.refresh_derivative(rhs, t_);
      }
      if (opt_.progress) opt_.progress->store(t_, std::memory_order_relaxed);
    }
    r.rejected_steps = st.rejected_steps();
    r.rhs_evaluations = st.rhs_evaluations();
    finish();
    return out_;
  }

  // GuardProbe: the guard at a time within the last step
  double guard_value(int slot, double t) override {
    State x;
    dense_at(t, x);
    return guard(slot, t, x);
  }

 private:
  int guard_count() const { return edge_ == 0 ? 4 : 5; }

  // the last step's dense output and start, from the exact walk or the integrator
  void dense_at(double t, State& x) const {
    if (walking_) {
      walk_.dense(t, x);
    } else {
      stepper_->dense(t, x);
    }
  }
  double step_t0() const { return walking_ ? walk_.t0() : stepper_->t0(); }
  double side() const { return edge_ == 1 ? 1.0 : -1.0; }

  double limit(int edge) const {
    return opt_.overturn == OverturnCriterion::kHalfPi ? 0.5 * std::numbers::pi
                                                       : body_.tipping_angle(edge);
  }

  void derivative(double t, const State& x, State& dx) {
    const BaseAcceleration a = motion_.at(t, cursor_);
    const Eval e = evaluate(p_, edge_, x, a);
    dx(kU) = x(kUDot);
    dx(kTheta) = edge_ == 0 ? 0.0 : x(kThetaDot);
    dx(kUDot) = e.udd;
    dx(kThetaDot) = edge_ == 0 ? 0.0 : e.thdd;
    dx(kWorkIn) = e.p_in;
    dx(kWorkDamp) = e.p_damp;
  }

  double guard(int slot, double t, const State& x) {
    const BaseAcceleration a = motion_.at(t, cursor_);
    const double gy = p_.g + a.y;
    if (edge_ == 0) {
      const double acc = -(p_.k * x(kU) + p_.c * x(kUDot)) / p_.mt();
      switch (slot) {
        case kFullUplift1:
          return (p_.alpha1 * gy - acc) / p_.g;
        case kFullUplift2:
          return (p_.alpha2 * gy + acc) / p_.g;
        case kFullLiftOff:
          return gy / p_.g;
        default:
          return x(kU) * x(kUDot);
      }
    }
    switch (slot) {
      case kRockImpact:
        return side() * x(kTheta);
      case kRockOverturn:
        return limit(edge_) - side() * x(kTheta);
      case kRockLiftOff: {
        const double fy = evaluate(p_, edge_, x, a).fy / (p_.m * p_.g);
        if (!tension_) return fy;
        // held in tension: until the support presses again, or a lift-off becomes consistent
        return std::min(-fy, -flight_corner_acceleration(x, a) / p_.g);
      }
      case kRockPeak:
        return side() * x(kThetaDot);
      default:
        return x(kU) * x(kUDot);
    }
  }

  detail::GuardSample sample(double t, const State& x) {
    detail::GuardSample s;
    s.t = t;
    for (int j = 0; j < guard_count(); ++j) s.v[static_cast<std::size_t>(j)] = guard(j, t, x);
    return s;
  }

  // the extremes at the step's samples before `t_upto` (the states the guards were sampled at)
  void fold_samples(double t_upto) {
    for (int i = 0; i <= nsamp_; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (smp_[k].t >= t_upto) break;
      observe(smp_[k].t, xs_[k]);
    }
  }

  // the extremes at one state
  void observe(double t, const State& x) {
    Extremes& ex = out_.body.extremes;
    SupportExtremes& se = out_.support;
    const Eval e = evaluate(p_, edge_, x, motion_.at(t, cursor_));
    se.max_displacement = std::max(se.max_displacement, std::abs(x(kU)));
    se.max_velocity = std::max(se.max_velocity, std::abs(x(kUDot)));
    se.max_force = std::max(se.max_force, std::abs(p_.k * x(kU) + p_.c * x(kUDot)));
    const double th = x(kTheta);
    if (th > 0.0) ex.max_theta_edge1 = std::max(ex.max_theta_edge1, th);
    if (th < 0.0) ex.max_theta_edge2 = std::max(ex.max_theta_edge2, -th);
    const BodyParameters& bp = body_.params();
    ex.max_uplift = std::max(ex.max_uplift, (bp.b1 + bp.b2) * std::sin(std::abs(th)));
    ex.max_base_shear = std::max(ex.max_base_shear, std::abs(e.fx));
    ex.max_overturning_moment =
        std::max(ex.max_overturning_moment, std::abs(moment_about_projection(x, e)));
    if (e.fy < 0.0) ex.max_pivot_pull = std::max(ex.max_pivot_pull, -e.fy);
    if (e.fy >= 0.05 * p_.m * p_.g) {
      ex.max_friction_demand = std::max(ex.max_friction_demand, std::abs(e.fx) / e.fy);
    }
  }

  // the moment of the support's force on the block about the c.g.'s projection on the base
  double moment_about_projection(const State& x, const Eval& e) const {
    if (edge_ == 0) return p_.h * e.fx;  // the resultant's moment balances M h A
    // the force acts at the pivot, h alpha from the projection along the base
    const double al = p_.alpha(edge_), th = x(kTheta);
    const double px = p_.h * al * std::cos(th), py = p_.h * al * std::sin(th);
    // from the c.g.'s projection (the base's centre line) to the pivot
    return px * e.fy - py * e.fx;
  }

  // the time-history rows up to t (inclusive) from the state at t or the last step's dense output
  void record_until(double t, const State& x_at_t) {
    if (opt_.output_dt <= 0.0) return;
    while (next_output_ <= t * (1.0 + 1e-15) + 1e-300 && next_output_ <= t_end_) {
      const double tr = next_output_;
      State x = x_at_t;
      if (tr < t && have_step_ && step_t0() <= tr) dense_at(tr, x);
      row(tr, x);
      ++rows_;
      next_output_ = static_cast<double>(rows_) * opt_.output_dt;
    }
  }

  void row(double t, const State& x) {
    History& h = out_.body.history;
    SupportHistory& sh = out_.history;
    const BaseAcceleration a = motion_.at(t, cursor_);
    const Eval e = evaluate(p_, edge_, x, a);
    h.time.push_back(t);
    h.phase.push_back(edge_);
    h.theta.push_back(x(kTheta));
    h.theta_dot.push_back(x(kThetaDot));
    h.base_acc_x.push_back(a.x);
    h.base_acc_y.push_back(a.y);
    h.reaction_x.push_back(e.fx);
    h.reaction_y.push_back(e.fy);
    h.resultant.push_back(edge_ == 0 ? -p_.h * e.fx / e.fy : p_.h * p_.alpha(edge_));
    h.friction_demand.push_back(e.fy > 0.0 ? std::abs(e.fx) / e.fy : kInf);
    h.kinetic.push_back(kinetic(p_, edge_, x));
    h.potential.push_back(potential(p_, edge_, x));
    h.input_work.push_back(x(kWorkIn));
    h.damping_loss.push_back(x(kWorkDamp));
    h.impact_loss.push_back(impact_loss_ + chatter_loss_);
    h.offset.push_back(0.0);
    h.lift.push_back(0.0);
    sh.displacement.push_back(x(kU));
    sh.velocity.push_back(x(kUDot));
    sh.acceleration.push_back(e.acc);
    sh.force.push_back(p_.k * x(kU) + p_.c * x(kUDot) + 0.0);
  }

  Event event_at(double t, EventKind kind) const {
    Event ev;
    ev.time = t;
    ev.kind = kind;
    ev.edge = edge_;
    ev.theta = x_(kTheta);
    return ev;
  }

  bool zeno(double t) {
    if (t - zeno_t0_ > kZenoSpan) {
      zeno_t0_ = t;
      zeno_count_ = 0;
    }
    if (++zeno_count_ < kZenoChanges) return false;
    stop(std::to_string(kZenoChanges) + " contact changes within " + format_number(kZenoSpan) +
         " s at t = " + format_number(t, 9) + " s");
    return true;
  }

  void stop(const std::string& why) {
    out_.body.status = Status::kStopped;
    out_.body.message = why;
    stopped_ = true;
    out_.body.events.push_back(event_at(t_, EventKind::kStopped));
  }

  // a lift-off: flight on a support is not modelled, so the run ends here, with the magnitude
  void lift_off() {
    const BaseAcceleration a = motion_.at(t_, cursor_);
    const Eval e = evaluate(p_, edge_, x_, a);
    stop("the block's vertical reaction on the support reached zero (F_J = " +
         format_number(e.fy, 4) + " N at t = " + format_number(t_, 6) +
         " s): the block would leave the support, and flight on a support is not modelled");
  }

  // the lower corner's vertical acceleration relative to the support if the block flew from
  // this state (theta_ddot = 0, the c.g. falling at g + Y''): -g_y + h (cos - alpha sin)
  // theta_dot^2
  double flight_corner_acceleration(const State& x, BaseAcceleration a) const {
    const double th = x(kTheta), al = p_.alpha(edge_);
    return -(p_.g + a.y) + p_.h * (std::cos(th) - al * std::sin(th)) * x(kThetaDot) * x(kThetaDot);
  }

  // the support's vertical force on the rocking block reached zero (or, held in tension, the
  // support presses again or a lift-off became consistent): as on the rigid floor (§15), a
  // lift-off whose corner would accelerate into the support keeps its pivot, the support pulling
  // (pivot_tension); a consistent lift-off is flight, not modelled on a support: the run stops
  void rocking_lift_off() {
    SimulationResult& r = out_.body;
    const BaseAcceleration a = motion_.at(t_, cursor_);
    const double fy = evaluate(p_, edge_, x_, a).fy;
    if (tension_ && fy >= 0.0) {
      end_tension(t_);  // presses again
      return;
    }
    if (flight_corner_acceleration(x_, a) > 0.0) {
      lift_off();
      return;
    }
    tension_ = true;
    tension_since_ = t_;
    r.pivot_tension = true;
    ++r.extremes.tension_episodes;
    r.events.push_back(event_at(t_, EventKind::kPivotTension));
  }

  // a rocking state entered (the start, an impact) whose support would already have to pull: its
  // lift-off guard starts below zero, where no crossing is seen, so it is decided here
  void check_entry_reaction() {
    const BaseAcceleration a = motion_.at(t_, cursor_);
    if (evaluate(p_, edge_, x_, a).fy < 0.0) rocking_lift_off();
  }

  void end_tension(double t) {
    if (!tension_) return;
    out_.body.extremes.tension_time += t - tension_since_;
    tension_ = false;
  }

  void first_uplift(double t) {
    Extremes& ex = out_.body.extremes;
    if (ex.first_uplift_time < 0.0) {
      ex.first_uplift_time = t;
      ex.first_uplift_edge = edge_;
    }
  }

  // full contact from now: uplifts at once where the entry state already calls for it
  void enter_full_contact(double t, bool at_start) {
    edge_ = 0;
    x_(kTheta) = 0.0;
    x_(kThetaDot) = 0.0;
    const double g1 = guard(kFullUplift1, t, x_), g2 = guard(kFullUplift2, t, x_);
    if (guard(kFullLiftOff, t, x_) <= 0.0) {
      lift_off();
      return;
    }
    if (g1 < 0.0 || g2 < 0.0) {
      if (!at_start && zeno(t)) return;
      uplift(t, g1 < 0.0 ? 1 : 2);
    }
  }

  void uplift(double t, int edge) {
    edge_ = edge;
    x_(kTheta) = 0.0;
    x_(kThetaDot) = 0.0;
    zero_start_impact_ = true;
    last_change_ = t;
    out_.body.events.push_back(event_at(t, EventKind::kUplift));
    first_uplift(t);
  }

  // the impact at theta = 0 (docs/theory.md §24): the landing corner sticks; the block's moment
  // of momentum about it and the linear momentum of block and support are conserved
  void impact(double t) {
    end_tension(t);
    SimulationResult& r = out_.body;
    const int pre = edge_, post = pre == 1 ? 2 : 1;
    const double a_pre = p_.alpha(pre), a_post = p_.alpha(post);
    const SupportImpact map = support_impact(p_.m, p_.ms, p_.zeta2, a_pre, a_post);
    const double thm = x_(kThetaDot), udm = x_(kUDot);
    const double t_before = kinetic(p_, pre, x_);
    const ImpactLawInfo& law = impact_law_info(opt_.impact_law);
    // n = 0: paper and rigid_body are the same map (times restitution_factor); restitution takes
    // the measured ratio. The linear momentum gives u_dot+ in each
    double thp =
        law.rebound == Rebound::kMeasuredRatio
            ? (post == 1 ? opt_.restitution_ratio_edge1 : opt_.restitution_ratio_edge2) * thm
            : map.ratio * opt_.restitution_factor * thm;
    const bool chatter = t - last_change_ < chatter_dt_;
    const double s_post = post == 1 ? 1.0 : -1.0;
    const bool both = chatter || !(s_post * thp > 0.0);
    if (both) thp = 0.0;
    const double udp = support_velocity_after(map, p_.h, thm, thp, udm);
    Event ev = event_at(t, chatter ? EventKind::kChatterCutoff : EventKind::kImpact);
    ev.edge = post;
    ev.theta_dot_before = thm;
    ev.theta_dot_after = thp;
    // the support's impulse on the block: the change of the block's momentum (theta = 0)
    ev.impulse_x = p_.m * ((udp - p_.h * thp) - (udm - p_.h * thm));
    ev.impulse_y = p_.m * p_.h * (-a_post * thp + a_pre * thm);
    x_(kUDot) = udp;
    x_(kThetaDot) = thp;
    x_(kTheta) = 0.0;
    edge_ = post;
    const double t_after = both ? 0.5 * p_.mt() * udp * udp : kinetic(p_, post, x_);
    const double loss = t_before - t_after;
    ev.energy_loss = loss;
    ev.friction_demand = ev.impulse_y > 0.0 ? std::abs(ev.impulse_x) / ev.impulse_y : kInf;
    const double impulse = std::hypot(ev.impulse_x, ev.impulse_y);
    ev.force_estimate = std::numbers::pi * impulse / (2.0 * opt_.impact_duration);
    Extremes& ex = r.extremes;
    ++ex.impacts;
    if (chatter) {
      ++ex.chatter_cutoffs;
      r.chatter_cut_off = true;
      chatter_loss_ += loss;
    } else {
      impact_loss_ += loss;
      ex.max_impulse = std::max(ex.max_impulse, std::abs(ev.impulse_y));
      ex.max_impact_energy_loss = std::max(ex.max_impact_energy_loss, loss);
      ex.max_impact_force = std::max(ex.max_impact_force, ev.force_estimate);
    }
    r.events.push_back(ev);
    if (loss < -kImpactEnergyRounding * t_before) {
      r.impact_gained_energy = true;
      Event g = ev;
      g.kind = EventKind::kImpactGainedEnergy;
      r.events.push_back(g);
    }
    last_change_ = t;
    if (ex.impacts >= opt_.max_impacts) {
      stop("max_impacts = " + std::to_string(opt_.max_impacts) + " reached");
      return;
    }
    if (zeno(t)) return;
    if (both) {
      if (!chatter) r.events.push_back(event_at(t, EventKind::kRockingEnded));
      enter_full_contact(t, false);
    } else {
      zero_start_impact_ = true;
      check_entry_reaction();
    }
  }

  // the event of guard `slot` at t_: returns whether the stepper restarts
  bool fire(int slot) {
    SimulationResult& r = out_.body;
    if (edge_ == 0) {
      switch (slot) {
        case kFullUplift1:
        case kFullUplift2:
          if (zeno(t_)) return true;
          uplift(t_, slot == kFullUplift1 ? 1 : 2);
          return true;
        case kFullLiftOff:
          lift_off();
          return true;
        default:
          return false;  // a support peak: observed
      }
    }
    switch (slot) {
      case kRockImpact:
        impact(t_);
        return true;
      case kRockOverturn: {
        r.status = Status::kOverturned;
        r.extremes.overturn_time = t_;
        r.extremes.overturn_edge = edge_;
        r.events.push_back(event_at(t_, EventKind::kOverturn));
        stopped_ = true;
        return true;
      }
      case kRockLiftOff:
        rocking_lift_off();
        return true;
      case kRockPeak:
        r.events.push_back(event_at(t_, EventKind::kPeak));
        return false;
      default:
        return false;
    }
  }

  void finish() {
    SimulationResult& r = out_.body;
    end_tension(t_);
    r.t_end = t_;
    r.final_phase = edge_ == 0   ? ContactMode::kFullContact
                    : edge_ == 1 ? ContactMode::kRockingEdge1
                                 : ContactMode::kRockingEdge2;
    r.final_theta = x_(kTheta);
    r.final_theta_dot = x_(kThetaDot);
    r.final_q = VectorX(0);
    r.final_q_dot = VectorX(0);
    out_.support.final_displacement = x_(kU);
    out_.support.final_velocity = x_(kUDot);
    EnergyBalance& e = r.energy;
    const double e1 = kinetic(p_, edge_, x_) + potential(p_, edge_, x_);
    e.input_work = x_(kWorkIn);
    e.damping_loss = x_(kWorkDamp);
    e.impact_loss = impact_loss_;
    e.chatter_loss = chatter_loss_;
    e.kinetic_change = kinetic(p_, edge_, x_) - k0_;
    e.potential_change = e1 - e0_ - e.kinetic_change;
    e.residual = e.input_work - (e.kinetic_change + e.potential_change + e.damping_loss +
                                 e.impact_loss + e.chatter_loss);
    e.scale = std::max({std::abs(e.input_work), std::abs(e.damping_loss), std::abs(e.impact_loss),
                        std::abs(e0_), std::abs(e1), p_.m * p_.g * p_.h});
    if (!(std::abs(e.residual) <= energy_residual_bound(body_, e.scale))) {
      r.energy_unbalanced = true;
      Event ev = event_at(t_, EventKind::kEnergyUnbalanced);
      ev.energy_loss = e.residual;
      r.events.push_back(ev);
    }
  }

  const Body& body_;
  const GroundMotion& motion_;
  const SimulationOptions& opt_;
  Plant p_;
  StepControl ctl_;
  GroundMotion::Cursor cursor_;
  State x_;
  int edge_ = 0;  // 0: full contact, 1 or 2: rocking on that edge
  double t_ = 0.0, t_end_ = 0.0;
  double chatter_dt_ = 0.0, last_change_ = 0.0;
  double impact_loss_ = 0.0, chatter_loss_ = 0.0, e0_ = 0.0, k0_ = 0.0;
  double next_output_ = 0.0;
  long rows_ = 0;
  int samples_ = 4;
  bool stopped_ = false, zero_start_impact_ = false;
  bool tension_ = false;  // rocking with the support pulling on the pivot (pivot_tension)
  double tension_since_ = 0.0;
  double zeno_t0_ = -kInf;
  int zeno_count_ = 0;
  std::array<detail::GuardSample, detail::kMaxSamples + 1> smp_{};
  std::array<State, detail::kMaxSamples + 1> xs_{};  // the states of the samples
  Stepper* stepper_ = nullptr;
  ExactWalk walk_{p_};
  bool walk_ok_ = false;    // full contact may be walked exactly (a sampled record, or none)
  bool walking_ = false;    // the last step was the exact walk's
  bool have_step_ = false;  // a step has been taken (its dense output exists)
  int nsamp_ = 4;           // samples of the last step
  SupportRunResult out_;
};

}  // namespace

SupportParameters SupportParameters::from_frequency(double mass, double body_mass,
                                                    double frequency_hz, double damping_ratio) {
  SupportParameters s;
  s.mass = mass;
  const double mt = mass + body_mass, w = 2.0 * std::numbers::pi * frequency_hz;
  s.stiffness = mt * w * w;
  s.damping = 2.0 * damping_ratio * std::sqrt(s.stiffness * mt);
  return s;
}

SupportFrequencies support_frequencies(const Body& body, const SupportParameters& s) {
  const double mt = s.mass + body.params().mass;
  SupportFrequencies f;
  f.frequency_hz = std::sqrt(s.stiffness / mt) / (2.0 * std::numbers::pi);
  f.damping_ratio = s.damping / (2.0 * std::sqrt(s.stiffness * mt));
  return f;
}

double support_transmissibility(const Body& body, const SupportParameters& s, double frequency_hz) {
  const SupportFrequencies f = support_frequencies(body, s);
  const double r = frequency_hz / f.frequency_hz, z = f.damping_ratio;
  const double num = 1.0 + (2.0 * z * r) * (2.0 * z * r);
  const double den = (1.0 - r * r) * (1.0 - r * r) + (2.0 * z * r) * (2.0 * z * r);
  return std::sqrt(num / den);
}

double support_uplift_amplitude(const Body& body, const SupportParameters& s, double frequency_hz) {
  return body.g() * std::min(body.alpha1(), body.alpha2()) /
         support_transmissibility(body, s, frequency_hz);
}

void validate_support(const Body& body, const SupportParameters& s, const InitialState& init,
                      const SimulationOptions& o) {
  validate_options(body, init, o);
  FLEXROCK_THROW_UNLESS(std::isfinite(s.mass) && s.mass >= 0.0,
                        "support: mass must be >= 0 and finite [kg], got " + format_number(s.mass));
  FLEXROCK_THROW_UNLESS(
      std::isfinite(s.stiffness) && s.stiffness > 0.0,
      "support: stiffness must be > 0 and finite [N/m], got " + format_number(s.stiffness));
  FLEXROCK_THROW_UNLESS(
      std::isfinite(s.damping) && s.damping >= 0.0,
      "support: damping must be >= 0 and finite [N s/m], got " + format_number(s.damping));
  FLEXROCK_THROW_UNLESS(std::isfinite(s.displacement) && std::isfinite(s.velocity),
                        "support: the initial displacement and velocity must be finite");
  FLEXROCK_THROW_UNLESS(body.modes() == 0,
                        "support: a flexible body on a support is not modelled (the body has " +
                            std::to_string(body.modes()) +
                            " modes); take it rigid (body.rigid = true)");
  FLEXROCK_THROW_UNLESS(o.contact_model == ContactModel::kImpulsive,
                        "support: contact_model = compliant on a support is not modelled; the "
                        "block's corners meet the support by the impulsive law");
  FLEXROCK_THROW_UNLESS(!std::isfinite(o.friction_coefficient),
                        "support: sliding on a support is not modelled (friction_coefficient = " +
                            format_number(o.friction_coefficient) +
                            "); leave friction_coefficient out (the base holds)");
}

SupportRunResult simulate(const Body& body, const SupportParameters& support,
                          const GroundMotion& motion, const InitialState& initial,
                          const SimulationOptions& options) {
  validate_support(body, support, initial, options);
  SupportLoop loop(body, support, motion, initial, options);
  SupportRunResult r = loop.run();
  if (const std::string bad = non_finite_output(r.body); !bad.empty()) {
    r.body.status = Status::kStopped;
    r.body.message = "the results are not finite (" + bad + ")";
  }
  return r;
}

}  // namespace flexrock
