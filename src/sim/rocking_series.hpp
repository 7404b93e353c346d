// SPDX-License-Identifier: BSD-3-Clause
// A rigid body's rocking (no modes, no slip) stepped by the Taylor series of its motion
// (docs/theory.md, "Rocking of a rigid body by its Taylor series"). Under a sampled record the base
// acceleration is linear between two samples, and a pulse made of sinusoids has its own series in
// closed form, so the series' coefficients follow from the equation of motion by a recurrence with
// one sine and cosine per step (and one per active sinusoid); the polynomial is the step's dense
// output. Same interface as Dopri5 (the event loop's stepper); the `sys` arguments
// are unused: the equation is built in. Internal header.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/integrate/dopri5.hpp"

namespace flexrock::detail {

/// [lo, hi] and its arithmetic, for reaction_range's enclosures. By hand: Boost.Interval, with
/// exact rounding and its checks off, measured 770 instructions per enclosure against 520 here
/// (callgrind, case (c) of bench/: 6 % of the run), its generic sign dispatch not being inlined.
/// Rounding is not directed: the enclosures are compared with margins far above it.
struct Span {
  double lo, hi;
  friend Span operator+(Span a, Span b) { return {a.lo + b.lo, a.hi + b.hi}; }
  friend Span operator-(Span a, Span b) { return {a.lo - b.hi, a.hi - b.lo}; }
  friend Span operator*(double s, Span a) {
    return s >= 0.0 ? Span{s * a.lo, s * a.hi} : Span{s * a.hi, s * a.lo};
  }
  friend Span square(Span a) {
    const double least = a.lo > 0.0 ? a.lo : a.hi < 0.0 ? -a.hi : 0.0;
    const double most = std::max(-a.lo, a.hi);
    return {least * least, most * most};
  }
  friend Span operator-(double s, Span a) { return {s - a.hi, s - a.lo}; }
  friend Span operator*(Span a, Span b) {
    const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    return {std::min(std::min(p1, p2), std::min(p3, p4)),
            std::max(std::max(p1, p2), std::max(p3, p4))};
  }
};

/// Enclosures over a series step of the floor reaction over M g (F_I, F_J) and of |M| over M g h
/// (RockingSeries::reaction_range).
struct ReactionRange {
  double fi_lo, fi_hi, fj_lo, fj_hi, moment_abs;
};

/// The rocking equation of a rigid body about a pivot at alpha (over h), the floor accelerating by
/// (g u, g (v - 1)):  theta'' = k ((alpha v + u) cos theta + (v - alpha u) sin theta), k = (g/h)/m,
/// m = 1 + zeta^2 + alpha^2, and the input power M h g theta' ((u + alpha (v - 1)) cos theta +
/// ((v - 1) - alpha u) sin theta). `State` holds theta, theta_dot, input work, damping loss.
template <class State>
class RockingSeries {
 public:
  enum class Status { kAccepted, kStepCollapsed };
  static constexpr int kMaxOrder = 30;  // highest power of theta's series

  explicit RockingSeries(const GroundMotion& motion) : motion_(motion) {}

  /// The pivot: alpha, k = (g/h)/m [1/s^2], M h g [J] and g [m/s^2].
  void set_pivot(double alpha, double k, double mhg, double g) {
    alpha_ = alpha;
    k_ = k;
    mhg_ = mhg;
    g_ = g;
  }

  template <class System>
  void start(System&&, const StepControl& ctl, double t, const State& x, double = 0.0) {
    ctl_ = ctl;
    // the order: Jorba & Zou's -ln(eps)/2 + 1 as the most the step may need; fewer terms are used
    // where they reach the tolerance already (a record's short intervals)
    const double eps = std::clamp(ctl.rtol, 1e-16, 1e-3);
    max_order_ = std::clamp(static_cast<int>(std::ceil(-0.5 * std::log(eps))) + 2, 8, kMaxOrder);
    higher_ = 0;
    t0_ = t1_ = t;
    x0_ = x;
    x1_ = x;
    order_ = 0;
    th_.fill(0.0);
    dth_.fill(0.0);
    w_.fill(0.0);
    th_[0] = x(0);
    th_[1] = x(1);
    dth_[1] = x(1);
    w_[0] = x(2);
    h_ = ctl.max_step;
  }

  /// One step from t1() toward t_stop, ending on it when reached; t_stop must not lie past the
  /// record sample or the motion's breakpoint after t1() (the base acceleration must be linear, or
  /// one sinusoid, on the step).
  template <class System>
  Status step(System&&, double t_stop) {
    const double t = t1_;
    double h = std::min(t_stop - t, ctl_.max_step);
    bool ends = false;
    if (t + 1.01 * h >= t_stop) {
      // as Dopri5: a step within 1 % of t_stop ends on it (no sliver of a step left after it)
      h = t_stop - t;
      ends = true;
    }
    if (!(h > 0.0)) return Status::kStepCollapsed;
    forcing(t);
    x0_ = x1_;
    const double tol_th = ctl_.atol + ctl_.rtol * std::abs(x1_(0));
    const double tol_om = ctl_.atol + ctl_.rtol * std::abs(x1_(1));
    // terms up to the first order whose last two terms at h are within the tolerance
    series_start(x1_(0), x1_(1));
    int p = 0;      // theta's series is known to power p + 1
    double hp = h;  // h^(p-1) for the tolerance test, one product per order
    int hp_power = 1;
    for (;;) {
      add_term(p);
      ++p;
      if (p >= kMinOrder) {
        for (; hp_power < p - 1; ++hp_power) hp *= h;
        if (within(p, h, hp, tol_th, tol_om)) break;
      }
      if (p >= max_order_) {
        // the step is too long for this order: the radius from the last two terms
        const double hr = radius(p, tol_th, tol_om);
        if (!(hr >= ctl_.min_step * std::max(1.0, std::abs(t)))) return Status::kStepCollapsed;
        if (hr < h) {
          h = hr;
          ends = false;
        }
        break;
      }
    }
    order_ = p;
    work_series(p);
    t0_ = t;
    t1_ = ends ? t_stop : t + h;
    hd_ = h;
    h_ = h;
    eval(t1_ - t0_, x1_);
    return Status::kAccepted;
  }

  /// Ends the last step at t_target (within it): the polynomial holds there too.
  template <class System>
  void restep_to(System&&, double t_target) {
    t1_ = t_target;
    eval(t_target - t0_, x1_);
  }

  /// The longest step: the event loop's cap while it samples the guards, +infinity while it bounds
  /// them over the whole step (the series' tolerance alone then sets the step).
  void set_max_step(double h) { ctl_.max_step = h; }

  /// The floor reaction over M g along I and J and the overturning moment about the c.g.'s
  /// projection over M g h on the last step, as series in tau: fi[k], fj[k], mo[k] for
  /// k = 0..order() (docs/theory.md, "Guards of the series step by bounds"); gh = g/h [1/s^2].
  /// With A = alpha theta_dot^2 - theta'' and B = alpha theta'' + theta_dot^2 over g/h:
  /// F_I = u + A cos + B sin, F_J = v + A sin - B cos, M = alpha (v cos - u sin - B). theta''
  /// and sin, cos are known to power order() - 2 by the step: the recurrence goes two terms
  /// further, so that the reaction is known to the power theta is (the step's polynomial itself
  /// is not changed).
  void reaction_series(double gh, double* fi, double* fj, double* mo) {
    add_term(order_);
    add_term(order_ + 1);
    const int p = order_ + 2;
    const double ig = 1.0 / gh;
    std::array<double, kMaxOrder + 4> a, b;
    for (int k = 0; k < p; ++k) {
      double w2 = 0.0;  // theta_dot^2's term k; theta_dot's term i is dth_[i + 1]
      for (int i = 0; i <= k; ++i) w2 += dth_[i + 1] * dth_[k - i + 1];
      const double dd = (k + 1.0) * (k + 2.0) * th_[k + 2];  // theta''
      a[k] = (alpha_ * w2 - dd) * ig;
      b[k] = (alpha_ * dd + w2) * ig;
    }
    const int nf = std::max(2, std::min(p, higher_));  // the forcing's terms
    for (int k = 0; k < p; ++k) {
      double x = 0.0, y = 0.0, vc = 0.0, us = 0.0;
      for (int i = 0; i <= k; ++i) {
        x += a[i] * c_[k - i] + b[i] * s_[k - i];
        y += a[i] * s_[k - i] - b[i] * c_[k - i];
      }
      for (int i = 0; i <= k && i < nf; ++i) {
        vc += v_term(i) * c_[k - i];
        us += u_term(i) * s_[k - i];
      }
      fi[k] = u_term(k) + x;
      fj[k] = v_term(k) + y;
      mo[k] = alpha_ * (vc - us - b[k]);
    }
  }
  /// Enclosures over [t0(), t0() + tau] of the last step of what reaction_series gives, by
  /// interval arithmetic (docs/theory.md, "Guards of the series step by bounds"), O(order) instead
  /// of the series' O(order^2): the step's polynomial bounds theta and theta_dot, and with theta''
  /// = k (a1 u + b1 v) put in, a1 = cos - alpha sin, b1 = alpha cos + sin, 1/m = k/(g/h):
  /// F_I = u (1 - a1^2/m) - v a1 b1/m + theta_dot^2 b1/(g/h),
  /// F_J = v (1 - b1^2/m) - u a1 b1/m - theta_dot^2 a1/(g/h),
  /// M = alpha (u (-sin - alpha a1/m) + v (cos - alpha b1/m) - theta_dot^2/(g/h)).
  ReactionRange reaction_range(double gh, double tau) const {
    // a polynomial's range on [0, tau]: c0 + linear tau' + sum_{from..to} c_k tau'^k, the sum
    // within +-sum |c_k| tau^k
    auto range = [tau](double c0, double linear, const double* c, int from, int to) {
      double e = 0.0;
      for (int k = to; k >= from; --k) e = e * tau + std::abs(c[k]);
      for (int k = 0; k < from; ++k) e *= tau;
      const double lt = linear * tau;
      return Span{c0 + std::min(0.0, lt) - e, c0 + std::max(0.0, lt) + e};
    };
    const int p = order_;  // theta to p + 1, theta_dot to p
    // sin and cos move no more than theta does
    const double move = range(0.0, 0.0, th_.data(), 1, p + 1).hi;
    const Span sn{std::max(-1.0, s_[0] - move), std::min(1.0, s_[0] + move)};
    const Span cs{std::max(-1.0, c_[0] - move), std::min(1.0, c_[0] + move)};
    const Span om2 = square(range(th_[1], 0.0, dth_.data() + 1, 1, p));  // theta_dot^2
    // the forcing: linear, or a sinusoid's series (terms 2 to higher_ - 1)
    const Span u = range(u0_, u1_, uk_.data(), 2, higher_ - 1);
    const Span v = range(v0_, v1_, vk_.data(), 2, higher_ - 1);
    // theta'' = k (a1 u + b1 v), with k/(g/h) = 1/m: each of u, v and theta_dot^2 once per form,
    // so that the forcing's swing over the step is not counted twice
    const Span a1 = cs - alpha_ * sn, b1 = alpha_ * cs + sn;
    const double im = k_ / gh, ig = 1.0 / gh;
    const Span fi = u * (1.0 - im * square(a1)) - im * v * (a1 * b1) + ig * om2 * b1;
    const Span fj = v * (1.0 - im * square(b1)) - im * u * (a1 * b1) - ig * om2 * a1;
    const Span mo =
        alpha_ * (u * (-1.0 * sn - alpha_ * im * a1) + v * (cs - alpha_ * im * b1) - ig * om2);
    return {fi.lo, fi.hi, fj.lo, fj.hi, std::max(-mo.lo, mo.hi)};
  }
  /// The input work's series on the last step: W(t0 + tau) = sum_k w[k] tau^k, k = 0..order() - 1.
  const double* work_coefficients() const { return w_.data(); }

  /// The forcing is re-read at every step: nothing to refresh.
  template <class System>
  void refresh_derivative(System&&, double) {}

  /// State at t in [t0(), t1()] from the step's polynomial.
  void dense(double t, State& out) const {
    out.resize(x0_.size());
    eval(t - t0_, out);
  }

  double t0() const { return t0_; }
  double t1() const { return t1_; }
  const State& x0() const { return x0_; }
  const State& x1() const { return x1_; }
  double suggested_step() const { return h_; }
  long rhs_evaluations() const { return 0; }
  long rejected_steps() const { return 0; }
  /// theta's series on the last step: theta(t0 + tau) = sum_k c[k] tau^k, k = 0..order()
  const double* theta_coefficients() const { return th_.data(); }
  /// k c[k], k = 0..order(): theta_dot(t0 + tau) = sum_k (k + 1) c[k + 1] tau^k
  const double* theta_rate_coefficients() const { return dth_.data(); }
  int order() const { return order_ + 1; }

 private:
  static constexpr int kMinOrder = 5;

  // the forcing's term k: u = Xdd/g and v = 1 + Ydd/g
  double u_term(int k) const {
    if (k == 0) return u0_;
    if (k == 1) return u1_;
    return k < higher_ ? uk_[static_cast<std::size_t>(k)] : 0.0;
  }
  double v_term(int k) const {
    if (k == 0) return v0_;
    if (k == 1) return v1_;
    return k < higher_ ? vk_[static_cast<std::size_t>(k)] : 0.0;
  }

  // u = Xdd/g and v = 1 + Ydd/g on [t, t_stop] as u0 + u1 tau, v0 + v1 tau (zero outside the
  // record); the interval is found by index, walking from the last one. A motion of sinusoids
  // adds the terms of order 2 and up (higher_ of them).
  void forcing(double t) {
    u0_ = u1_ = v1_ = 0.0;
    v0_ = 1.0;
    higher_ = 0;
    if (motion_.is_sinusoidal()) {
      sinusoid_forcing(t);
      return;
    }
    const std::vector<double>& ts = motion_.times();
    if (ts.size() < 2 || t < ts.front() || t >= ts.back()) return;
    std::size_t i = std::min(index_, ts.size() - 2);
    while (i > 0 && ts[i] > t) --i;
    while (i + 2 < ts.size() && ts[i + 1] <= t) ++i;
    index_ = i;
    const double dt = ts[i + 1] - ts[i], w = (t - ts[i]) / dt;
    const std::vector<double>& hx = motion_.horizontal();
    const double gi = 1.0 / g_;
    u0_ = gi * (hx[i] + w * (hx[i + 1] - hx[i]));
    u1_ = gi * (hx[i + 1] - hx[i]) / dt;
    if (motion_.has_vertical()) {
      const std::vector<double>& vy = motion_.vertical();
      v0_ = 1.0 + gi * (vy[i] + w * (vy[i + 1] - vy[i]));
      v1_ = gi * (vy[i + 1] - vy[i]) / dt;
    }
  }

  // the Taylor series at t of the sinusoids active on [t, next breakpoint): a sin(w (t + tau) +
  // phi) = sum_k a w^k / k! sin(w t + phi + k pi/2) tau^k, to the highest order a step may use
  void sinusoid_forcing(double t) {
    const int terms = max_order_ + 1;  // add_term(j < max_order_) and work_series reach j
    std::fill_n(uk_.begin(), terms, 0.0);
    std::fill_n(vk_.begin(), terms, 0.0);
    bool any = false;
    for (const SinusoidPiece& p : motion_.sinusoids()) {
      if (!(p.begin <= t && t < p.end)) continue;
      any = true;
      const double sn = std::sin(p.omega * t + p.phase), cs = std::cos(p.omega * t + p.phase);
      const double cycle[4] = {sn, cs, -sn, -cs};
      std::array<double, kMaxOrder + 2>& out = p.vertical ? vk_ : uk_;
      double f = p.amplitude / g_;  // a w^k / k! over g
      for (int k = 0; k < terms; ++k) {
        out[static_cast<std::size_t>(k)] += f * cycle[k & 3];
        f *= p.omega / (k + 1);
      }
    }
    if (!any) return;
    u0_ = uk_[0];
    u1_ = uk_[1];
    v0_ = 1.0 + vk_[0];
    v1_ = vk_[1];
    higher_ = terms;
  }

  void series_start(double theta, double theta_dot) {
    th_[0] = theta;
    th_[1] = theta_dot;
    dth_[1] = theta_dot;
    s_[0] = std::sin(theta);
    c_[0] = std::cos(theta);
    // theta'' = k (P cos + Q sin), P = alpha v + u, Q = v - alpha u: linear in tau
    p0_ = k_ * (alpha_ * v0_ + u0_);
    p1_ = k_ * (alpha_ * v1_ + u1_);
    q0_ = k_ * (v0_ - alpha_ * u0_);
    q1_ = k_ * (v1_ - alpha_ * u1_);
    for (int i = 2; i < higher_; ++i) {
      const auto k = static_cast<std::size_t>(i);
      pk_[k] = k_ * (alpha_ * vk_[k] + uk_[k]);
      qk_[k] = k_ * (vk_[k] - alpha_ * uk_[k]);
    }
  }

  // the sine and cosine terms of order j > 0
  void sincos_term(int j) {
    double s = 0.0, c = 0.0;
    for (int i = 1; i <= j; ++i) {
      const double it = dth_[i];
      s += it * c_[j - i];
      c -= it * s_[j - i];
    }
    const double inv = 1.0 / j;
    s_[j] = s * inv;
    c_[j] = c * inv;
  }

  // the sine and cosine terms of order j, then theta's term of order j + 2
  void add_term(int j) {
    if (j > 0) sincos_term(j);
    double a = p0_ * c_[j] + q0_ * s_[j];
    if (j > 0) a += p1_ * c_[j - 1] + q1_ * s_[j - 1];
    for (int i = 2; i <= j && i < higher_; ++i) {
      const auto k = static_cast<std::size_t>(i), l = static_cast<std::size_t>(j - i);
      a += pk_[k] * c_[l] + qk_[k] * s_[l];
    }
    th_[j + 2] = a / ((j + 1.0) * (j + 2.0));
    dth_[j + 2] = (j + 2) * th_[j + 2];
  }

  // the last two terms of theta (powers p, p + 1) and theta_dot (p - 1, p) at h are within
  // their tolerances
  bool within(int p, double h, double hp, double tol_th, double tol_om) const {
    const double a = std::abs(th_[p]), b = std::abs(th_[p + 1]);
    const double e_th = hp * h * (a + b * h);
    const double e_om = hp * (p * a + (p + 1) * b * h);
    return e_th <= tol_th && e_om <= tol_om;
  }

  // the longest step at which each of those terms alone is within its tolerance, with a margin
  double radius(int p, double tol_th, double tol_om) const {
    // the least of the four (tol / c)^(1/k), compared by their logarithms: one exp, not four
    double e = std::numeric_limits<double>::infinity();
    auto cap = [&e](double tol, double c, int k) {
      if (c > 0.0) e = std::min(e, std::log(tol / c) / k);
    };
    const double a = std::abs(th_[p]), b = std::abs(th_[p + 1]);
    cap(tol_th, a, p);
    cap(tol_th, b, p + 1);
    cap(tol_om, p * a, p - 1);
    cap(tol_om, (p + 1) * b, p);
    return kSafe * std::exp(e);
  }

  // the input work's series: W' = M h g theta' (a cos + b sin), a = u + alpha (v - 1) and
  // b = (v - 1) - alpha u (times M h g). With theta' cos = sin' and theta' sin = -cos', W' =
  // a sin' - b cos', whose term k - 1 gives W_k = sum_{i<k} (k - i) (a_i s_{k-i} - b_i c_{k-i}) /
  // k: O(p) under a record (a and b linear), where the product of theta' with the bracket's series
  // was O(p^2). It needs sin and cos to power p, one term past the step's.
  void work_series(int p) {
    w_[0] = x0_(2);
    if (u0_ == 0.0 && u1_ == 0.0 && v0_ == 1.0 && v1_ == 0.0 && higher_ == 0) {
      // the floor at rest (free rocking after a record or a pulse): no power, no work
      std::fill_n(w_.begin() + 1, p, 0.0);
      return;
    }
    sincos_term(p);
    const double a0 = mhg_ * (u0_ + alpha_ * (v0_ - 1.0)), a1 = mhg_ * (u1_ + alpha_ * v1_);
    const double b0 = mhg_ * ((v0_ - 1.0) - alpha_ * u0_), b1 = mhg_ * (v1_ - alpha_ * u1_);
    // a sinusoid's terms of order 2 and up, once per step: M h g (u_i + alpha v_i) and
    // M h g (v_i - alpha u_i)
    const int top = std::min(p, higher_);
    std::array<double, kMaxOrder + 2> ak, bk;
    for (int i = 2; i < top; ++i) {
      const auto m = static_cast<std::size_t>(i);
      ak[m] = mhg_ * (uk_[m] + alpha_ * vk_[m]);
      bk[m] = mhg_ * (vk_[m] - alpha_ * uk_[m]);
    }
    double kd = 0.0;  // k - 1, then k
    for (int k = 1; k <= p; ++k) {
      double sum = kd * (a1 * s_[k - 1] - b1 * c_[k - 1]);
      kd += 1.0;
      for (int i = 2; i < k && i < top; ++i) {
        const auto m = static_cast<std::size_t>(i), l = static_cast<std::size_t>(k - i);
        sum += (k - i) * (ak[m] * s_[l] - bk[m] * c_[l]);
      }
      w_[k] = (a0 * s_[k] - b0 * c_[k]) + sum / kd;
    }
  }

  void eval(double tau, State& out) const {
    const int p = order_;  // theta to p + 1, theta_dot to p, work to p
    double th = th_[p + 1], om = dth_[p + 1], w = w_[p];
    for (int k = p; k >= 1; --k) {
      th = th * tau + th_[k];
      om = om * tau + dth_[k];
      w = w * tau + w_[k - 1];
    }
    th = th * tau + th_[0];
    out(0) = th;
    out(1) = om;
    out(2) = w;
    out(3) = x0_(3);  // no damping without modes
  }

  static constexpr double kSafe = 0.9;
  const GroundMotion& motion_;
  StepControl ctl_;
  double alpha_ = 0.0, k_ = 0.0, mhg_ = 0.0, g_ = 9.81;
  double u0_ = 0.0, u1_ = 0.0, v0_ = 1.0, v1_ = 0.0;
  double p0_ = 0.0, p1_ = 0.0, q0_ = 0.0, q1_ = 0.0;
  // two terms beyond the step's order for the reaction's series (reaction_series)
  std::array<double, kMaxOrder + 4> th_{}, s_{}, c_{}, w_{};
  std::array<double, kMaxOrder + 4> dth_{};  // k th_[k], formed once per term (theta_dot's)
  // a sinusoidal motion's series of u and v - 1, and k P, k Q from them; used from order 2 up to
  // higher_ - 1 (0: a linear forcing)
  std::array<double, kMaxOrder + 2> uk_{}, vk_{}, pk_{}, qk_{};
  int higher_ = 0;
  State x0_, x1_;
  double t0_ = 0.0, t1_ = 0.0, hd_ = 0.0, h_ = 0.0;
  int order_ = 0, max_order_ = 12;
  std::size_t index_ = 0;
};

}  // namespace flexrock::detail
