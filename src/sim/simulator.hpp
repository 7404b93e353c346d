// SPDX-License-Identifier: BSD-3-Clause
// The event loop: phases, event location on the dense output, impacts, outputs. Internal header.
#pragma once

#include <algorithm>
#include <array>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "contact_propagator.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/model/dynamics.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock::detail {

// event functions, positive while nothing happens; the slot meaning depends on the phase:
//   full contact: uplift about edge 1, uplift about edge 2, vertical reaction, friction margin
//   rocking:      impact (s theta), overturn margin, vertical reaction, friction margin, peak (s
//   theta_dot)
inline constexpr int kEventSlots = 5;
inline constexpr int kSlotFriction = 3;
inline constexpr int kSlotPeak = 4;
inline constexpr int kMaxSamples = 32;

// a number for a message: 6 significant digits, no trailing zeros (std::to_string prints 1e-13 as
// "0.000000")
inline std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

template <int N, int MaxN>
class Simulator {
 public:
  static constexpr int S = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N + 4;
  static constexpr int MaxS = MaxN == Eigen::Dynamic ? Eigen::Dynamic : 2 * MaxN + 4;
  using Dyn = Dynamics<N, MaxN>;
  using Vec = typename Dyn::Vec;
  using State = Eigen::Matrix<double, S, 1, Eigen::ColMajor, MaxS, 1>;

  Simulator(const Body& body, const GroundMotion& motion, const SimulationOptions& opt)
      : body_(body),
        dyn_(body),
        motion_(motion),
        opt_(opt),
        n_(body.modes()),
        samples_(std::clamp(opt.event_samples, 1, kMaxSamples)),
        prop_(dyn_, motion, samples_, opt.max_step, opt.exact_full_contact) {
    q_.resize(n_);
    qd_.resize(n_);
    qdd_.resize(n_);
    // shortest period among the pinned-base modes and the rigid rocking motion
    double shortest = 2.0 * std::numbers::pi / body.rocking_frequency();
    if (n_ > 0)
      shortest = std::min(shortest, 2.0 * std::numbers::pi / body.natural_frequencies().maxCoeff());
    chatter_interval_ = opt.chatter_ratio * shortest;
    overturn_limit_[0] =
        opt.overturn == OverturnCriterion::kHalfPi ? 0.5 * std::numbers::pi : body.tipping_angle(1);
    overturn_limit_[1] =
        opt.overturn == OverturnCriterion::kHalfPi ? 0.5 * std::numbers::pi : body.tipping_angle(2);
    ctl_.rtol = opt.rtol;
    ctl_.atol = opt.atol;
    ctl_.max_step = opt.max_step;
    ctl_.controlled = 2 * n_ + 2;  // the energy quadratures do not steer the step
    for (State& xk : sample_states_) xk.setZero(2 * n_ + 4);
  }

  SimulationResult run(const InitialState& init) {
    State x(2 * n_ + 4);
    x.setZero();
    x(0) = init.theta;
    x(n_ + 1) = init.theta_dot;
    x.segment(1, n_) = init.q.size() == n_ ? init.q : VectorX(body_.static_deformation());
    if (init.q_dot.size() == n_) x.segment(n_ + 2, n_) = init.q_dot;
    if (init.theta > 0.0 || (init.theta == 0.0 && init.theta_dot > 0.0)) {
      phase_ = Phase::kRockingEdge1;
    } else if (init.theta < 0.0 || init.theta_dot < 0.0) {
      phase_ = Phase::kRockingEdge2;
    }
    t_end_ = opt_.t_end >= 0.0 ? opt_.t_end : motion_.duration();
    res_.extremes.max_abs_q = VectorX::Zero(n_);
    res_.history.modes = n_;
    energy0_ = mechanical_energy(x);
    kinetic0_ = energy0_ - dyn_.potential_energy(rocking() ? dyn_.alpha(edge()) : 0.0, x(0), q_);
    last_contact_change_ = -std::numeric_limits<double>::infinity();

    double t = 0.0;
    bool running = start_phase(t, x);
    if (opt_.output_dt > 0.0) emit_row(t, x);
    next_output_ = 1;
    while (running && t < t_end_) {
      running = advance(t, x);
    }
    finish(t, x);
    return std::move(res_);
  }

 private:
  // ---- state layout: theta, q[n], theta_dot, q_dot[n], input work, damping loss
  int iq() const { return 1; }
  int ithd() const { return n_ + 1; }
  int iqd() const { return n_ + 2; }
  int iw() const { return 2 * n_ + 2; }
  int id() const { return 2 * n_ + 3; }
  int edge() const { return static_cast<int>(phase_); }
  bool rocking() const { return phase_ != Phase::kFullContact; }

  void unpack(const State& x) {
    q_ = x.segment(iq(), n_);
    qd_ = x.segment(iqd(), n_);
  }

  // the right-hand side of the current phase
  void rhs(double t, const State& x, State& dx) {
    const BaseAcceleration a = motion_.at(t, rhs_cursor_);
    unpack(x);
    dx.resize(x.size());
    double thdd = 0.0;
    if (rocking()) {
      const double sn = std::sin(x(0)), cs = std::cos(x(0));
      dyn_.rocking_acceleration_sc(edge(), sn, cs, q_, x(ithd()), qd_, a, thdd, qdd_);
      dx(0) = x(ithd());
      dx(iw()) = dyn_.input_power_sc(dyn_.alpha(edge()), sn, cs, q_, x(ithd()), qd_, a);
    } else {
      dyn_.full_contact_acceleration(q_, qd_, a, qdd_);
      dx(0) = 0.0;
      dx(iw()) = dyn_.input_power(0.0, 0.0, q_, 0.0, qd_, a);
    }
    dx.segment(iq(), n_) = qd_;
    dx(ithd()) = thdd;
    dx.segment(iqd(), n_) = qdd_;
    dx(id()) = dyn_.damping_power(qd_);
  }

  struct Sample {
    double t = 0.0;
    std::array<double, kEventSlots> v{};
    Eigen::Vector2d reaction{0.0, 0.0};  // over M g
    double moment = 0.0;                 // overturning moment over M g h
  };

  // event functions (and the reaction, for the extremes) at (t, x)
  void evaluate(double t, const State& x, Sample& s) {
    const BaseAcceleration a = motion_.at(t, event_cursor_);
    unpack(x);
    s.t = t;
    if (rocking()) {
      const double sg = edge_sign(edge());
      double thdd = 0.0;
      const double sn = std::sin(x(0)), cs = std::cos(x(0));
      dyn_.rocking_acceleration_sc(edge(), sn, cs, q_, x(ithd()), qd_, a, thdd, qdd_);
      s.reaction = dyn_.rocking_reaction_sc(edge(), sn, cs, q_, x(ithd()), qd_, thdd, qdd_, a);
      s.v[0] = sg * x(0);
      s.v[1] = overturn_limit_[edge() - 1] - sg * x(0);
      s.v[kSlotPeak] = sg * x(ithd());
      // reaction at the pivot, moment about the c.g. projection: alpha h F_j(body)
      const double fy_body = -s.reaction(0) * sn + s.reaction(1) * cs;
      s.moment = dyn_.alpha(edge()) * fy_body;
    } else {
      dyn_.full_contact_acceleration(q_, qd_, a, qdd_);
      s.reaction = dyn_.full_contact_reaction(qdd_, a);
      const Eigen::Vector2d u = dyn_.uplift_functions(q_, qdd_, a);
      s.v[0] = u(0);
      s.v[1] = u(1);
      s.v[kSlotPeak] = 1.0;
      s.moment = dyn_.contact_moment(0.0, q_, qdd_, a);
    }
    s.v[2] = s.reaction(1);
    s.v[kSlotFriction] = std::isfinite(opt_.friction_coefficient)
                             ? opt_.friction_coefficient * s.reaction(1) - std::abs(s.reaction(0))
                             : 1.0;
  }

  static bool terminal(int slot) { return slot < kSlotFriction; }

  // starts the integrator in the current phase at (t, x); false when the run ends here
  bool start_phase(double t, State& x) {
    if (!rocking()) {
      x(0) = 0.0;
      x(ithd()) = 0.0;
    }
    still_ = n_ == 0 && !rocking();
    exact_ = !still_ && !rocking() && prop_.available();
    if (still_) {
      // a rigid body in full contact does not move: no integration until it uplifts
      x_still_ = x;
      still_t1_ = t;
    } else if (exact_) {
      // a flexible body in full contact under a record: exact steps between its samples
      prop_.start(t, x);
    } else {
      integ_.start([this](double tt, const State& xx, State& dd) { rhs(tt, xx, dd); }, ctl_, t, x);
    }
    evaluate(t, x, s0_);
    observe(s0_, x);
    // after an uplift or impact theta = 0 and it must grow: the impact (and, after an uplift,
    // the peak) function starts at zero and is known to turn positive
    zero_start_.fill(false);
    if (rocking() && entered_by_contact_change_) {
      zero_start_[0] = s0_.v[0] == 0.0;
      zero_start_[kSlotPeak] = s0_.v[kSlotPeak] == 0.0;
    }
    entered_by_contact_change_ = false;
    if (s0_.v[2] <= 0.0) return contact_lost(t, x);
    if (rocking() && s0_.v[1] <= 0.0) return overturned(t, x);
    if (s0_.v[kSlotFriction] <= 0.0 && !friction_over_) friction_exceeded(t, s0_);
    if (s0_.v[kSlotFriction] > 0.0) friction_over_ = false;
    if (!rocking() && !suppress_uplift_at_start_) {
      if (s0_.v[0] <= 0.0 || s0_.v[1] <= 0.0) {
        const int e = s0_.v[0] <= s0_.v[1] ? 1 : 2;
        return uplift(t, x, e);
      }
    }
    suppress_uplift_at_start_ = false;
    return true;
  }

  // one accepted step plus whatever happens in it; false when the run ends
  bool advance(double& t, State& x) {
    if (still_) return advance_still(t, x);
    if (exact_) return advance_with(prop_, t, x);
    return advance_with(integ_, t, x);
  }

  // the step of `integ` (the integrator, or the exact propagator in full contact)
  template <class Stepper>
  bool advance_with(Stepper& integ, double& t, State& x) {
    auto sys = [this](double tt, const State& xx, State& dd) { rhs(tt, xx, dd); };
    const double t_stop = std::min(t_end_, motion_.next_breakpoint(t, break_cursor_));
    if (++res_.steps > opt_.max_steps)
      return stop(
          t, x,
          "step limit reached (" + std::to_string(opt_.max_steps) + " steps; raise max_steps)");
    if (integ.step(sys, t_stop) != Dopri5<State>::Status::kAccepted) {
      // the step limit is relative (min_step x max(1 s, t)); while rocking the usual cause is
      // impacts accumulating with the chatter cut-off disabled, so the message says so
      const double h_min = ctl_.min_step * std::max(1.0, std::abs(t));
      const std::string cause =
          rocking() && opt_.chatter_ratio <= 0.0
              ? "impacts accumulating while rocking with the chatter cut-off disabled "
                "(chatter_ratio = 0); set chatter_ratio > 0"
              : "the equations became too stiff or singular; loosen rtol/atol or check the body";
      return stop(t, x,
                  "integration step collapsed below " + short_number(h_min) +
                      " s near t = " + short_number(t) + " s (" + cause + ")");
    }
    const double t0 = integ.t0(), t1 = integ.t1();
    if (opt_.progress) opt_.progress->store(t1, std::memory_order_relaxed);
    // sample the event functions across the step, keeping the states for the extremes
    auto& smp = samples_buf_;
    smp[0] = s0_;
    for (int k = 1; k <= samples_; ++k) {
      const double tk = k == samples_ ? t1 : t0 + (t1 - t0) * k / samples_;
      State& xk = sample_states_[static_cast<std::size_t>(k)];
      if (k == samples_) {
        xk = integ.x1();
      } else {
        integ.dense(tk, xk);
      }
      evaluate(tk, xk, smp[k]);
    }
    // earliest crossing per slot
    double t_hit = std::numeric_limits<double>::infinity();
    int slot_hit = -1;
    std::array<double, kEventSlots> when;
    when.fill(std::numeric_limits<double>::infinity());
    for (int j = 0; j < kEventSlots; ++j) {
      when[j] = find_crossing(j, smp, samples_);
      if (terminal(j) && when[j] < t_hit) {
        t_hit = when[j];
        slot_hit = j;
      }
    }
    // non-terminal events before the terminal one (or the step end)
    for (int j : {kSlotPeak, kSlotFriction}) {
      if (when[j] <= std::min(t_hit, t1)) record_nonterminal(j, when[j]);
    }
    // extremes from the samples that precede any state change
    for (int k = 1; k <= samples_; ++k) {
      if (smp[k].t >= t_hit) break;
      observe(smp[k], sample_states_[static_cast<std::size_t>(k)]);
    }
    if (slot_hit < 0) {
      // an analytic motion may jump at a breakpoint: start the next step from its right limit
      if (t1 == t_stop && t1 < t_end_ && !motion_.is_sampled()) {
        integ.refresh_derivative(sys, std::nextafter(t1, t_end_));
      }
      emit_rows_until(t1);
      t = t1;
      x = integ.x1();
      s0_ = smp[samples_];
      zero_start_.fill(false);
      if (s0_.v[kSlotFriction] > 0.0) friction_over_ = false;
      return true;
    }
    // land exactly on the event and act on it
    if (t_hit > t0) integ.restep_to(sys, t_hit);
    emit_rows_until(t_hit);
    t = t_hit;
    x = t_hit > t0 ? integ.x1() : integ.x0();
    return act(slot_hit, t, x);
  }

  // a rigid body in full contact does not move, and its event functions (uplift about either edge,
  // vertical reaction, friction margin) depend on the base acceleration alone, linearly
  // (docs/theory.md, "A rigid body in full contact"). Under a sampled record they are linear
  // between samples, so a sign check at each sample finds every crossing and the state jumps from
  // sample to sample; an analytic motion is checked at event_samples points per max_step.
  bool advance_still(double& t, State& x) {
    // each span checked counts as a step toward max_steps
    if (++res_.steps > opt_.max_steps)
      return stop(
          t, x,
          "step limit reached (" + std::to_string(opt_.max_steps) + " steps; raise max_steps)");
    double ta = t, tb = t;
    int samples = 1;
    if (motion_.is_sampled()) {
      tb = scan_record(t);
    } else if (t >= motion_.duration()) {
      tb = t_end_;  // the motion is over (zero): nothing can change any more
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
      evaluate(tk, x_still_, smp[k]);
    }
    still_t1_ = tb;
    if (opt_.progress) opt_.progress->store(tb, std::memory_order_relaxed);
    double t_hit = std::numeric_limits<double>::infinity();
    int slot_hit = -1;
    std::array<double, kEventSlots> when;
    when.fill(std::numeric_limits<double>::infinity());
    for (int j = 0; j < kEventSlots; ++j) {
      when[j] = find_crossing(j, smp, samples);
      if (terminal(j) && when[j] < t_hit) {
        t_hit = when[j];
        slot_hit = j;
      }
    }
    if (when[kSlotFriction] <= std::min(t_hit, tb))
      record_nonterminal(kSlotFriction, when[kSlotFriction]);
    for (int k = 1; k <= samples; ++k) {
      if (smp[k].t >= t_hit) break;
      observe(smp[k], x_still_);
    }
    if (slot_hit < 0) {
      emit_rows_until(tb);
      t = tb;
      s0_ = smp[samples];
      if (s0_.v[kSlotFriction] > 0.0) friction_over_ = false;
      return true;
    }
    emit_rows_until(t_hit);
    t = t_hit;
    x = x_still_;
    return act(slot_hit, t, x);
  }

  // walks the record's samples after t while every event function stays positive there, folding
  // their reactions into the extremes; returns the end of the first span that may hold a crossing
  // (a sample where some function is <= 0), or the end time. scan_from_ is the span's start.
  double scan_record(double t) {
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
    // uplift about edge 1 / edge 2, vertical reaction, friction margin, over M g (rigid body)
    for (; i < ts.size() && ts[i] < t_end_; ++i) {
      const double ax = hx[i] / g, ay = 1.0 + (vertical ? vy[i] / g : 0.0);
      const double u1 = a1 * ay - ax, u2 = a2 * ay + ax;
      if (!(u1 > 0.0 && u2 > 0.0 && ay > 0.0)) break;
      if (friction) {
        // an exceedance is reported once, and again only after the margin has turned positive
        if (fc * ay - std::abs(ax) > 0.0) {
          friction_over_ = false;
        } else if (!friction_over_) {
          break;
        }
      }
      shear = std::max(shear, std::abs(ax));
      demand = std::max(demand, std::abs(ax) / ay);
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

  // time of the first crossing of slot j in the step, or +inf
  double find_crossing(int j, const std::array<Sample, kMaxSamples + 1>& smp, int samples) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (!rocking() && j == kSlotPeak) return kInf;
    if (j == kSlotFriction && friction_over_) return kInf;
    double prev = smp[0].v[j];
    double t_prev = smp[0].t;
    bool armed = prev > 0.0 || zero_start_[j];
    for (int k = 1; k <= samples; ++k) {
      const double cur = smp[k].v[j];
      if (armed && cur <= 0.0) {
        double tl = t_prev, gl = prev;
        if (!(gl > 0.0)) {
          // a phase that starts at zero: find a point inside where the function is positive
          bool found = false;
          double span = smp[k].t - t_prev;
          for (int i = 1; i <= 60 && !found; ++i) {
            span *= 0.5;
            tl = t_prev + span;
            gl = value_at(j, tl);
            found = gl > 0.0;
          }
          // the excursion is below resolution: an impact at the start, no peak
          if (!found) return j == 0 ? t_prev : kInf;
        }
        return locate(j, tl, smp[k].t, gl, cur);
      }
      // a dip between samples: parabola through three positive values with a vertex below zero
      if (armed && k + 1 <= samples && cur > 0.0 && prev > 0.0 && smp[k + 1].v[j] > 0.0) {
        const double g0 = prev, g1 = cur, g2 = smp[k + 1].v[j];
        const double curv = g0 - 2.0 * g1 + g2;
        if (curv > 0.0) {
          const double u = 0.5 * (g0 - g2) / curv;  // vertex, in sample spacings from sample k
          const double gmin = g1 - 0.25 * (g0 - g2) * u;
          if (u > -1.0 && u < 1.0 && gmin < 0.25 * std::min(g0, g2)) {
            const double tv = smp[k].t + u * (smp[k + 1].t - smp[k].t);
            const double gv = value_at(j, tv);
            if (gv <= 0.0) {
              const double tl = u > 0 ? smp[k].t : smp[k - 1].t;
              const double gl = u > 0 ? g1 : g0;
              return locate(j, tl, tv, gl, gv);
            }
          }
        }
      }
      if (cur > 0.0) armed = true;
      prev = cur;
      t_prev = smp[k].t;
    }
    return kInf;
  }

  // the state at t within the last step (or the still state)
  void state_at(double t, State& out) const {
    if (still_) {
      out = x_still_;
    } else if (exact_) {
      prop_.dense(t, out);
    } else {
      integ_.dense(t, out);
    }
  }

  double value_at(int j, double t) {
    Sample s;
    state_at(t, xr_);
    evaluate(t, xr_, s);
    return s.v[j];
  }

  double locate(int j, double tl, double tr, double gl, double gr) {
    auto g = [&](double tt) { return value_at(j, tt); };
    auto tol = [](double a, double b) {
      return std::abs(b - a) <= 2e-15 * std::max(1.0, std::abs(a));
    };
    std::uintmax_t iters = 100;
    const auto r = boost::math::tools::toms748_solve(g, tl, tr, gl, gr, tol, iters);
    return r.second;  // the side where the function is <= 0
  }

  void record_nonterminal(int slot, double t) {
    state_at(t, xr_);
    Sample s;
    evaluate(t, xr_, s);
    if (slot == kSlotPeak) {
      Event e;
      e.time = t;
      e.kind = EventKind::kPeak;
      e.edge = edge();
      e.theta = xr_(0);
      res_.events.push_back(e);
      observe_theta(xr_(0));
    } else {
      friction_exceeded(t, s);
    }
  }

  void friction_exceeded(double t, const Sample& s) {
    friction_over_ = true;
    res_.friction_exceeded = true;
    Event e;
    e.time = t;
    e.kind = EventKind::kFrictionExceeded;
    e.edge = rocking() ? edge() : 0;
    e.friction_demand = s.reaction(1) > 0.0 ? std::abs(s.reaction(0)) / s.reaction(1)
                                            : std::numeric_limits<double>::infinity();
    res_.events.push_back(e);
  }

  // a state-changing event at (t, x) in slot j; false when the run ends
  bool act(int slot, double t, State& x) {
    // events piling up at one instant would loop forever: stop instead
    if (t - zeno_time_ < 1e-9 * std::max(1.0, t)) {
      if (++same_time_events_ > 64) {
        return stop(t, x,
                    "events accumulate at t = " + std::to_string(t) +
                        " s without time advancing (Zeno behaviour)");
      }
    } else {
      zeno_time_ = t;
      same_time_events_ = 0;
    }
    if (slot == 2) return contact_lost(t, x);
    if (!rocking()) return uplift(t, x, slot == 0 ? 1 : 2);
    if (slot == 1) return overturned(t, x);
    return impact(t, x);
  }

  bool uplift(double t, State& x, int e) {
    Event ev;
    ev.time = t;
    ev.kind = EventKind::kUplift;
    ev.edge = e;
    res_.events.push_back(ev);
    if (res_.extremes.first_uplift_time < 0.0) {
      res_.extremes.first_uplift_time = t;
      res_.extremes.first_uplift_edge = e;
    }
    phase_ = e == 1 ? Phase::kRockingEdge1 : Phase::kRockingEdge2;
    entered_by_contact_change_ = true;
    x(0) = 0.0;
    x(ithd()) = 0.0;
    last_contact_change_ = t;
    return start_phase(t, x);
  }

  bool impact(double t, State& x) {
    const int pre = edge();
    const int landing = pre == 1 ? 2 : 1;
    unpack(x);
    const double thd_minus = x(ithd());
    const bool chatter = t - last_contact_change_ < chatter_interval_;
    const auto out =
        resolve_impact(dyn_, landing, q_, thd_minus, qd_, opt_.restitution_factor, chatter);
    Event ev;
    ev.time = t;
    ev.kind = chatter ? EventKind::kChatterCutoff
                      : (out.both_edges ? EventKind::kRockingEnded : EventKind::kImpact);
    ev.edge = landing;
    ev.theta_dot_before = thd_minus;
    ev.theta_dot_after = out.theta_dot;
    ev.energy_loss = out.energy_loss;
    ev.impulse_x = out.impulse(0);
    ev.impulse_y = out.impulse(1);
    ev.friction_demand = out.impulse(1) > 0.0 ? std::abs(out.impulse(0)) / out.impulse(1)
                                              : std::numeric_limits<double>::infinity();
    res_.events.push_back(ev);
    Extremes& ex = res_.extremes;
    ++ex.impacts;
    if (chatter) {
      res_.chatter_cut_off = true;
      chatter_loss_ += out.energy_loss;
    } else {
      impact_loss_ += out.energy_loss;
    }
    ex.max_impulse = std::max(ex.max_impulse, out.impulse(1));
    ex.max_impact_energy_loss = std::max(ex.max_impact_energy_loss, out.energy_loss);
    // the cut-off is a numerical device on a vanishing impulse (its ratio is 1/alpha for a rigid
    // block whatever the speed): it sets no friction demand
    if (!chatter) ex.max_friction_demand = std::max(ex.max_friction_demand, ev.friction_demand);
    if (!chatter && std::isfinite(opt_.friction_coefficient) &&
        ev.friction_demand > opt_.friction_coefficient) {
      res_.friction_exceeded = true;
      Event fe = ev;
      fe.kind = EventKind::kFrictionExceeded;
      res_.events.push_back(fe);
    }
    if (out.energy_loss < -1e-12 * std::max(1.0, energy_scale_)) {
      res_.impact_gained_energy = true;
      Event ge = ev;
      ge.kind = EventKind::kImpactGainedEnergy;
      res_.events.push_back(ge);
    }
    x(0) = 0.0;
    x(ithd()) = out.theta_dot;
    x.segment(iqd(), n_) = out.q_dot;
    phase_ = out.both_edges ? Phase::kFullContact
                            : (landing == 1 ? Phase::kRockingEdge1 : Phase::kRockingEdge2);
    entered_by_contact_change_ = true;
    // a degenerate excursion (no time since uplift) must not uplift again at once
    if (out.both_edges && t == last_contact_change_) suppress_uplift_at_start_ = true;
    last_contact_change_ = t;
    if (ex.impacts > opt_.max_impacts) {
      return stop(t, x, "impact limit reached (" + std::to_string(opt_.max_impacts) + ")");
    }
    return start_phase(t, x);
  }

  bool overturned(double t, State& x) {
    res_.status = Status::kOverturned;
    res_.extremes.overturn_time = t;
    res_.extremes.overturn_edge = edge();
    observe_theta(x(0));
    Event ev;
    ev.time = t;
    ev.kind = EventKind::kOverturn;
    ev.edge = edge();
    ev.theta = x(0);
    res_.events.push_back(ev);
    res_.message = std::string("overturned about edge ") + std::to_string(edge()) +
                   " at t = " + std::to_string(t) + " s";
    return false;
  }

  bool contact_lost(double t, State& /*x*/) {
    res_.status = Status::kContactLost;
    Event ev;
    ev.time = t;
    ev.kind = EventKind::kContactLost;
    ev.edge = rocking() ? edge() : 0;
    res_.events.push_back(ev);
    res_.message = "contact lost at t = " + std::to_string(t) +
                   " s: the floor would have to pull the body down (vertical reaction <= 0; "
                   "e.g. the base accelerates downward faster than g); the model does not "
                   "follow a body in flight";
    return false;
  }

  bool stop(double t, State& /*x*/, std::string why) {
    res_.status = Status::kStopped;
    Event ev;
    ev.time = t;
    ev.kind = EventKind::kStopped;
    res_.events.push_back(ev);
    res_.message = std::move(why);
    return false;
  }

  // ---- outputs
  double mechanical_energy(const State& x) {
    unpack(x);
    const double a = rocking() ? dyn_.alpha(edge()) : 0.0;
    return dyn_.kinetic_energy(a, q_, x(ithd()), qd_) + dyn_.potential_energy(a, x(0), q_);
  }

  void observe_theta(double theta) {
    Extremes& ex = res_.extremes;
    if (theta > 0.0) ex.max_theta_edge1 = std::max(ex.max_theta_edge1, theta);
    if (theta < 0.0) ex.max_theta_edge2 = std::max(ex.max_theta_edge2, -theta);
    const double b = body_.params().b1 + body_.params().b2;
    ex.max_uplift = std::max(ex.max_uplift, b * std::sin(std::abs(theta)));
  }

  void observe(const Sample& s, const State& x) {
    Extremes& ex = res_.extremes;
    observe_theta(x(0));
    for (int i = 0; i < n_; ++i) ex.max_abs_q(i) = std::max(ex.max_abs_q(i), std::abs(x(iq() + i)));
    const double mg = dyn_.mass() * dyn_.g();
    ex.max_base_shear = std::max(ex.max_base_shear, mg * std::abs(s.reaction(0)));
    ex.max_overturning_moment =
        std::max(ex.max_overturning_moment, mg * dyn_.height() * std::abs(s.moment));
    if (s.reaction(1) > 0.0)
      ex.max_friction_demand =
          std::max(ex.max_friction_demand, std::abs(s.reaction(0)) / s.reaction(1));
    energy_scale_ = std::max({energy_scale_, std::abs(x(iw())), std::abs(x(id()))});
  }

  void emit_rows_until(double t_cut) {
    if (opt_.output_dt <= 0.0) return;
    for (;;) {
      const double to = static_cast<double>(next_output_) * opt_.output_dt;
      if (to > t_cut || to > t_end_ * (1.0 + 1e-14)) break;
      state_at(std::min(to, still_ ? still_t1_ : (exact_ ? prop_.t1() : integ_.t1())), xr_);
      emit_row(to, xr_);
      ++next_output_;
    }
  }

  void emit_row(double t, const State& x) {
    History& h = res_.history;
    Sample s;
    evaluate(t, x, s);
    const BaseAcceleration a = motion_.at(t, event_cursor_);
    unpack(x);
    const double mg = dyn_.mass() * dyn_.g();
    const double alpha = rocking() ? dyn_.alpha(edge()) : 0.0;
    h.time.push_back(t);
    h.phase.push_back(static_cast<int>(phase_));
    h.theta.push_back(x(0));
    h.theta_dot.push_back(x(ithd()));
    for (int i = 0; i < n_; ++i) {
      h.q.push_back(x(iq() + i));
      h.q_dot.push_back(x(iqd() + i));
    }
    h.base_acc_x.push_back(a.x);
    h.base_acc_y.push_back(a.y);
    h.reaction_x.push_back(mg * s.reaction(0));
    h.reaction_y.push_back(mg * s.reaction(1));
    h.resultant.push_back(dyn_.height() * (rocking() ? alpha : s.moment / s.reaction(1)));
    h.friction_demand.push_back(s.reaction(1) > 0.0 ? std::abs(s.reaction(0)) / s.reaction(1)
                                                    : std::numeric_limits<double>::infinity());
    h.kinetic.push_back(dyn_.kinetic_energy(alpha, q_, x(ithd()), qd_));
    h.potential.push_back(dyn_.potential_energy(alpha, x(0), q_));
    h.input_work.push_back(x(iw()));
    h.damping_loss.push_back(x(id()));
    h.impact_loss.push_back(impact_loss_ + chatter_loss_);
  }

  void finish(double t, const State& x) {
    res_.t_end = t;
    if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
    if (opt_.output_dt > 0.0 &&
        (res_.history.time.empty() || res_.history.time.back() < t - 1e-12)) {
      emit_row(t, x);
    }
    res_.final_phase = phase_;
    res_.final_theta = x(0);
    res_.final_theta_dot = x(ithd());
    res_.final_q = x.segment(iq(), n_);
    res_.final_q_dot = x.segment(iqd(), n_);
    unpack(x);
    const double a = rocking() ? dyn_.alpha(edge()) : 0.0;
    EnergyBalance& e = res_.energy;
    const double kin = dyn_.kinetic_energy(a, q_, x(ithd()), qd_);
    const double pot = dyn_.potential_energy(a, x(0), q_);
    e.input_work = x(iw());
    e.damping_loss = x(id());
    e.impact_loss = impact_loss_;
    e.chatter_loss = chatter_loss_;
    e.kinetic_change = kin - kinetic0_;
    e.potential_change = pot - (energy0_ - kinetic0_);
    e.residual = e.input_work - (e.kinetic_change + e.potential_change + e.damping_loss +
                                 e.impact_loss + e.chatter_loss);
    e.scale = std::max({energy_scale_, std::abs(energy0_ - pot), std::abs(kin), kinetic0_,
                        impact_loss_ + chatter_loss_});
    res_.rejected_steps = integ_.rejected_steps();
    res_.rhs_evaluations = integ_.rhs_evaluations();
    if (res_.status == Status::kCompleted) res_.message = "completed";
  }

  const Body& body_;
  Dyn dyn_;
  const GroundMotion& motion_;
  SimulationOptions opt_;
  int n_;
  StepControl ctl_;
  int samples_ = 4;
  Dopri5<State> integ_;
  ContactPropagator<N, MaxN, State> prop_;
  bool exact_ = false;  // a flexible body in full contact, stepped by prop_
  Phase phase_ = Phase::kFullContact;
  GroundMotion::Cursor rhs_cursor_, event_cursor_, break_cursor_;
  Vec q_, qd_, qdd_;
  State xr_;
  std::array<Sample, kMaxSamples + 1> samples_buf_;   // event functions at this step's samples
  std::array<State, kMaxSamples + 1> sample_states_;  // the states there (sized once)
  Sample s0_;
  std::size_t scan_index_ = 0;  // the record sample the last scan stopped at
  double scan_from_ = 0.0;      // [s] the last sample the scan passed with no event
  bool still_ = false;  // a rigid body in full contact: the state is x_still_, nothing integrates
  State x_still_;
  double still_t1_ = 0.0;  // [s] end of the span checked last while still
  std::array<bool, kEventSlots> zero_start_{};
  std::array<double, 2> overturn_limit_{};
  bool friction_over_ = false;
  bool entered_by_contact_change_ = false;
  bool suppress_uplift_at_start_ = false;
  double chatter_interval_ = 0.0;
  double last_contact_change_ = 0.0;
  double t_end_ = 0.0;
  long next_output_ = 0;
  double energy0_ = 0.0, kinetic0_ = 0.0;
  double impact_loss_ = 0.0, chatter_loss_ = 0.0, energy_scale_ = 0.0;
  double zeno_time_ = -1.0;
  int same_time_events_ = 0;
  SimulationResult res_;
};

}  // namespace flexrock::detail
