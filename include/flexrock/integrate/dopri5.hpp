// SPDX-License-Identifier: BSD-3-Clause
// Dormand-Prince 5(4) with its 4th-order dense output (Hairer, Norsett & Wanner, "Solving ODEs I",
// code DOPRI5). Generic over the state type; knows nothing of bodies or contacts.
//
// Hand-written rather than Boost.Odeint's dense-output dopri5 because the event loop needs three
// things that stepper does not offer: a step that ends exactly on a prescribed time (a record
// sample, where the excitation has a kink) without restarting from the interpolant, a re-step
// from the last accepted point to an event time found on the dense output, and a per-step cap.
// The stages live in the object, so a step allocates nothing for fixed-size states.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace flexrock {

struct StepControl {
  double rtol = 1e-9;   // relative tolerance
  double atol = 1e-12;  // absolute tolerance (the state is in rad, -, rad/s, 1/s)
  int controlled = -1;  // components in the error norm (the first ones); -1: all
  double max_step = std::numeric_limits<double>::infinity();  // [s]
  double min_step = 1e-13;  // relative to max(1, |t|): below it the step has collapsed
};

namespace detail {

/// The first exit of |h mu| from an explicit method's stability region along mu's ray: `stable`
/// tells whether |h mu| = hr lies inside; scanned up to `most` (past the region's end) in `scan`
/// steps, then bisected. Returns the last |h mu| known inside.
template <class Stable>
double stability_exit(Stable&& stable, double most, int scan) {
  double lo = 0.0, hi = most;
  for (int i = 1; i <= scan; ++i) {
    const double hr = most * i / scan;
    if (!stable(hr)) {
      hi = hr;
      break;
    }
    lo = hr;
  }
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

/// Hairer's starting step for a method of order `order`: balances the first and second derivative
/// estimates at (t, x), f0 = f(t, x); evaluates f once more (into f1, with xs as scratch), counted
/// in `evaluations`.
template <class System, class State>
double hairer_initial_step(System&& sys, const StepControl& ctl, double t, const State& x,
                           const State& f0, State& xs, State& f1, double order, long& evaluations) {
  const int n = ctl.controlled < 0 ? static_cast<int>(x.size()) : ctl.controlled;
  if (n == 0) return std::min(ctl.max_step, 1.0);
  double d0 = 0.0, d1 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double sc = ctl.atol + ctl.rtol * std::abs(x(i));
    d0 += (x(i) / sc) * (x(i) / sc);
    d1 += (f0(i) / sc) * (f0(i) / sc);
  }
  d0 = std::sqrt(d0 / n);
  d1 = std::sqrt(d1 / n);
  double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  h0 = std::min(h0, ctl.max_step);
  xs = x + h0 * f0;
  sys(t + h0, xs, f1);
  ++evaluations;
  double d2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double sc = ctl.atol + ctl.rtol * std::abs(x(i));
    const double r = (f1(i) - f0(i)) / sc;
    d2 += r * r;
  }
  d2 = std::sqrt(d2 / n) / h0;
  const double dm = std::max(d1, d2);
  const double h1 = dm <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / dm, 1.0 / order);
  // a state tiny next to its derivative (a block released from 1e-15 rad: theta far below
  // atol, theta_ddot of order g/R) gives h0 ~ 1e-18 s, below the step that counts as
  // collapsed: start no lower than ten times that step; the error control shrinks a start
  // that is too long, and only then is a collapse real
  const double h_floor = std::min(10.0 * ctl.min_step * std::max(1.0, std::abs(t)), ctl.max_step);
  return std::max(std::min({100.0 * h0, h1, ctl.max_step}), h_floor);
}

}  // namespace detail

/// The longest step h [s] with h mu inside DOPRI5's stability region for every h' in (0, h]:
/// |R(z)| <= 1 for R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 + z^5/120 + z^6/600, its stability
/// polynomial (Hairer & Wanner II, IV.2). On the negative real axis it is 3.31 / |mu|; on the
/// imaginary axis 0.997 / |mu|, and a few percent of damping lifts it past 2 / |mu|. Infinite for
/// mu = 0 or a growing mode (Re mu > 0), which bounds no step.
inline double dopri5_stable_step(std::complex<double> mu) {
  const double r = std::abs(mu);
  if (!(r > 0.0) || mu.real() > 0.0) return std::numeric_limits<double>::infinity();
  const std::complex<double> d = mu / r;
  auto stable = [d](double hr) {
    const std::complex<double> z = hr * d;
    const std::complex<double> p =
        1.0 +
        z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z * (1.0 / 24.0 + z * (1.0 / 120.0 + z / 600.0)))));
    return std::abs(p) <= 1.0 + 1e-12;
  };
  // scan |h mu| up to 3.5 (the region ends before) for the first exit, then bisect it
  return detail::stability_exit(stable, 3.5, 350) / r;
}

template <class State>
class Dopri5 {
 public:
  enum class Status { kAccepted, kStepCollapsed };

  /// Starts at (t, x): evaluates f(t, x) and picks a first step unless `h` > 0 is given.
  template <class System>
  void start(System&& sys, const StepControl& ctl, double t, const State& x, double h = 0.0) {
    ctl_ = ctl;
    for (State* v : {&x0_, &xn_, &xs_, &err_, &k1_, &k2_, &k3_, &k4_, &k5_, &k6_, &k7_, &k1s_}) {
      v->setZero(x.size());
    }
    t0_ = t1_ = t;
    hd_ = 0.0;
    x0_ = x;
    x1_ = x;
    sys(t, x, k7_);
    ++rhs_evals_;
    h_ = h > 0.0 ? h : initial_step(sys, t, x);
    facold_ = 1e-4;
    dense_ready_ = false;
  }

  /// One accepted step from the current point, ending at or before t_stop (exactly at t_stop when
  /// it is reached). Afterwards the dense output covers [t0(), t1()].
  template <class System>
  Status step(System&& sys, double t_stop) {
    const double t = t1_;
    shift_start();
    for (;;) {
      double h = std::min(h_, ctl_.max_step);
      bool ends = false;
      if (t + h >= t_stop || t + 1.01 * h >= t_stop) {
        h = t_stop - t;
        ends = true;
      }
      // a NaN step (a state that overflowed) counts as collapsed too, never as a step to retry
      if (!(h >= ctl_.min_step * std::max(1.0, std::abs(t)))) {
        if (!ends || !(h > 0.0)) return Status::kStepCollapsed;
      }
      stages(sys, t, h);
      const double err = error_norm();
      if (!(err <= 1.0)) {
        ++rejected_;
        const double fac11 = std::isfinite(err) ? std::pow(err, kExpo1) : 1e10;
        h_ = h / std::min(kFacc1, fac11 / kSafe);
        continue;
      }
      // PI step-size control (Hairer's beta = 0.04)
      double fac = std::pow(err, kExpo1) / std::pow(facold_, kBeta);
      fac = std::clamp(fac / kSafe, kFacc2, kFacc1);
      facold_ = std::max(err, 1e-4);
      const double h_new = h / fac;
      h_ = ends ? std::max(h_new, h_) : h_new;  // a step cut short by t_stop keeps its stride
      accept(t, h, ends ? t_stop : t + h);
      return Status::kAccepted;
    }
  }

  /// Replaces the last accepted step by one from its start to `t_target` (within it), with no
  /// error control: used to land exactly on an event time found on the dense output.
  template <class System>
  void restep_to(System&& sys, double t_target) {
    const double t = t0_;
    const double h = t_target - t;
    k1_ = k1s_;
    x1_ = x0_;
    stages(sys, t, h);
    accept(t, h, t_target);
  }

  /// Re-evaluates f at the current point with time `t_eval`: after a step that ended on a jump
  /// of the forcing, the next step must start from the right-hand limit.
  template <class System>
  void refresh_derivative(System&& sys, double t_eval) {
    sys(t_eval, x1_, k7_);
    ++rhs_evals_;
  }

  /// State at t in [t0(), t1()] from the continuous extension of the last step.
  void dense(double t, State& out) const {
    if (!dense_ready_) prepare_dense();
    const double s = (t - t0_) / hd_, s1 = 1.0 - s;
    out = r1_ + s * (r2_ + s1 * (r3_ + s * (r4_ + s1 * r5_)));
  }

  double t0() const { return t0_; }
  double t1() const { return t1_; }
  const State& x0() const { return x0_; }
  const State& x1() const { return x1_; }
  const State& dxdt1() const { return k7_; }  // f(t1, x1)
  double suggested_step() const { return h_; }
  long rhs_evaluations() const { return rhs_evals_; }
  long rejected_steps() const { return rejected_; }

 private:
  static constexpr double kSafe = 0.9, kFacc1 = 5.0, kFacc2 = 0.1, kBeta = 0.04;
  static constexpr double kExpo1 = 0.2 - kBeta * 0.75;

  void shift_start() {
    // the new step starts where the last ended; FSAL: k1 = f(t1, x1)
    k1_ = k7_;
  }

  template <class System>
  void stages(System&& sys, double t, double h) {
    // Dormand-Prince coefficients
    constexpr double a21 = 1.0 / 5.0;
    constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
    constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
    constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                     a54 = -212.0 / 729.0;
    constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                     a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
    constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0,
                     a75 = -2187.0 / 6784.0, a76 = 11.0 / 84.0;
    constexpr double c2 = 0.2, c3 = 0.3, c4 = 0.8, c5 = 8.0 / 9.0;
    constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0,
                     e5 = -17253.0 / 339200.0, e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
    const State& x = x1_;
    xs_ = x + h * a21 * k1_;
    sys(t + c2 * h, xs_, k2_);
    xs_ = x + h * (a31 * k1_ + a32 * k2_);
    sys(t + c3 * h, xs_, k3_);
    xs_ = x + h * (a41 * k1_ + a42 * k2_ + a43 * k3_);
    sys(t + c4 * h, xs_, k4_);
    xs_ = x + h * (a51 * k1_ + a52 * k2_ + a53 * k3_ + a54 * k4_);
    sys(t + c5 * h, xs_, k5_);
    xs_ = x + h * (a61 * k1_ + a62 * k2_ + a63 * k3_ + a64 * k4_ + a65 * k5_);
    sys(t + h, xs_, k6_);
    xn_ = x + h * (a71 * k1_ + a73 * k3_ + a74 * k4_ + a75 * k5_ + a76 * k6_);
    sys(t + h, xn_, k7_);
    rhs_evals_ += 6;
    err_ = h * (e1 * k1_ + e3 * k3_ + e4 * k4_ + e5 * k5_ + e6 * k6_ + e7 * k7_);
  }

  double error_norm() const {
    const int n = ctl_.controlled < 0 ? static_cast<int>(x1_.size()) : ctl_.controlled;
    if (n == 0) return 0.0;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double sc = ctl_.atol + ctl_.rtol * std::max(std::abs(x1_(i)), std::abs(xn_(i)));
      const double r = err_(i) / sc;
      sum += r * r;
    }
    return std::sqrt(sum / n);
  }

  void accept(double t, double h, double t_end) {
    t0_ = t;
    t1_ = t_end;
    hd_ = h;
    x0_ = x1_;
    x1_ = xn_;
    k1s_ = k1_;
    dense_ready_ = false;
  }

  void prepare_dense() const {
    // Hairer's continuous extension of DOPRI5 (dense output coefficients d1..d7)
    constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                     d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                     d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
    r1_ = x0_;
    r2_ = x1_ - x0_;
    r3_ = hd_ * k1s_ - r2_;
    r4_ = r2_ - hd_ * k7_ - r3_;
    r5_ = hd_ * (d1 * k1s_ + d3 * k3_ + d4 * k4_ + d5 * k5_ + d6 * k6_ + d7 * k7_);
    dense_ready_ = true;
  }

  template <class System>
  double initial_step(System&& sys, double t, const State& x) {
    return detail::hairer_initial_step(sys, ctl_, t, x, k7_, xs_, k2_, 5.0, rhs_evals_);
  }

  StepControl ctl_;
  State x0_, x1_, xn_, xs_, err_;
  State k1_, k2_, k3_, k4_, k5_, k6_, k7_, k1s_;
  mutable State r1_, r2_, r3_, r4_, r5_;
  mutable bool dense_ready_ = false;
  double t0_ = 0.0, t1_ = 0.0, hd_ = 0.0, h_ = 0.0, facold_ = 1e-4;
  long rhs_evals_ = 0, rejected_ = 0;
};

}  // namespace flexrock
