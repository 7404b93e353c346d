// SPDX-License-Identifier: BSD-3-Clause
// A Rosenbrock method of order 4 (L-stable, an embedded order-3 error estimate, a continuous
// extension) for stiff phases: generic over an Eigen vector state; knows nothing of bodies.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "flexrock/integrate/dopri5.hpp"

namespace flexrock {

// For a stiff phase (a body resting on stiff springs with strong dashpots) it takes the steps the
// motion allows, where an explicit method is held to the springs' period by stability.
//
// Hand-written on Eigen: Boost.Odeint's rosenbrock4 needs Boost.uBLAS, whose storage does not
// compile as C++20 with Debian 12's Boost (1.74). The coefficients and the step-size control are
// those of Odeint's rosenbrock4 and rosenbrock4_controller (Hairer and Wanner's RODAS-type
// Kaps-Rentrop form) but for d4, the time-derivative weight of the fourth stage: Odeint has
// +0.0362, which makes the method first order on problems that depend on time
// (tests/unit/rosenbrock4_test.cpp); Hairer's RODAS has -0.0362, which gives order 4. The
// Jacobian is taken by forward differences of the right-hand side (the systems it serves are only
// piecewise smooth: no closed form is kept in step with them); the components past
// StepControl::controlled (accumulated integrals) are taken to feed no right-hand side.
template <class State>
class Rosenbrock4 {
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                               State::MaxRowsAtCompileTime, State::MaxRowsAtCompileTime>;
  // Odeint's default_rosenbrock_coefficients
  static constexpr double kGamma = 0.25, kD1 = 0.25, kD2 = -0.1043, kD3 = 0.1035,
                          kD4 = -0.3620000000000023e-01, kC2 = 0.386, kC3 = 0.21, kC4 = 0.63;
  static constexpr double kC21 = -0.5668800000000000e+01, kA21 = 0.1544000000000000e+01;
  static constexpr double kC31 = -0.2430093356833875e+01, kC32 = -0.2063599157091915e+00,
                          kA31 = 0.9466785280815826e+00, kA32 = 0.2557011698983284e+00;
  static constexpr double kC41 = -0.1073529058151375e+00, kC42 = -0.9594562251023355e+01,
                          kC43 = -0.2047028614809616e+02, kA41 = 0.3314825187068521e+01,
                          kA42 = 0.2896124015972201e+01, kA43 = 0.9986419139977817e+00;
  static constexpr double kC51 = 0.7496443313967647e+01, kC52 = -0.1024680431464352e+02,
                          kC53 = -0.3399990352819905e+02, kC54 = 0.1170890893206160e+02,
                          kA51 = 0.1221224509226641e+01, kA52 = 0.6019134481288629e+01,
                          kA53 = 0.1253708332932087e+02, kA54 = -0.6878860361058950e+00;
  static constexpr double kC61 = 0.8083246795921522e+01, kC62 = -0.7981132988064893e+01,
                          kC63 = -0.3152159432874371e+02, kC64 = 0.1631930543123136e+02,
                          kC65 = -0.6058818238834054e+01;
  static constexpr double kD21 = 0.1012623508344586e+02, kD22 = -0.7487995877610167e+01,
                          kD23 = -0.3480091861555747e+02, kD24 = -0.7992771707568823e+01,
                          kD25 = 0.1025137723295662e+01, kD31 = -0.6762803392801253e+00,
                          kD32 = 0.6087714651680015e+01, kD33 = 0.1643084320892478e+02,
                          kD34 = 0.2476722511418386e+02, kD35 = -0.6594389125716872e+01;

 public:
  /// Starts at (t, x) with the first step `h` (> 0), or a thousandth of the largest.
  template <class System>
  void start(System&& sys, const StepControl& ctl, double t, const State& x, double h = 0.0) {
    (void)sys;
    ctl_ = ctl;
    const Eigen::Index m = x.size();
    for (State* v : {&x0_, &x1_, &xn_, &xs_, &f_, &dfdt_, &g1_, &g2_, &g3_, &g4_, &g5_, &tmp_,
                     &err_, &c3_, &c4_, &f1_})
      v->setZero(m);
    jac_.setZero(m, m);
    x1_ = x;
    x0_ = x;
    t0_ = t1_ = t;
    h_ = h > 0.0 ? h : std::min(1e-3 * ctl.max_step, 1e-5);
    first_ = true;
    last_rejected_ = false;
    t_right_ = -std::numeric_limits<double>::infinity();
  }

  enum class Status { kAccepted, kStepCollapsed };

  /// One accepted step from the current point, ending at or before t_stop (exactly at t_stop when
  /// it is reached). Afterwards the dense output covers [t0(), t1()].
  template <class System>
  Status step(System&& sys, double t_stop) {
    for (int tries = 0; tries < 500; ++tries) {
      double dt = std::min({h_, t_stop - t1_, ctl_.max_step});
      const bool ends = dt >= t_stop - t1_;
      if (!(dt >= ctl_.min_step * std::max(1.0, std::abs(t1_))) && !ends)
        return Status::kStepCollapsed;
      stages(sys, x1_, t1_, dt);
      const double err = error_norm();
      // Odeint's rosenbrock4_controller
      constexpr double kSafe = 0.9, kFac1 = 5.0, kFac2 = 1.0 / 6.0;
      double fac = std::clamp(std::pow(err, 0.25) / kSafe, kFac2, kFac1);
      double dt_new = dt / fac;
      if (!(err <= 1.0)) {
        ++rejected_;
        last_rejected_ = true;
        h_ = std::isfinite(dt_new) ? dt_new : 0.1 * dt;
        continue;
      }
      if (!first_) {
        double pred = (dt_old_ / dt) * std::pow(err * err / err_old_, 0.25) / kSafe;
        pred = std::clamp(pred, kFac2, kFac1);
        fac = std::max(fac, pred);
        dt_new = dt / fac;
      }
      first_ = false;
      dt_old_ = dt;
      err_old_ = std::max(0.01, err);
      if (last_rejected_) dt_new = std::min(dt_new, dt);
      last_rejected_ = false;
      accept(t_stop, dt, ends);
      h_ = ends ? std::max(std::min(dt_new, ctl_.max_step), h_) : std::min(dt_new, ctl_.max_step);
      return Status::kAccepted;
    }
    return Status::kStepCollapsed;
  }

  // the last step again from its start, ending at t (within it), without error control
  template <class System>
  void restep_to(System&& sys, double t) {
    xs_ = x0_;
    stages(sys, xs_, t0_, t - t0_);
    x1_ = xn_;
    t1_ = t;
    extension();
  }

  /// After a step that ended on a jump of the forcing, the next step (and a re-step from there)
  /// evaluates f at its start at `t_eval`, the jump's right-hand side.
  template <class System>
  void refresh_derivative(System&& /*sys*/, double t_eval) {
    t_right_ = t_eval;
  }

  void dense(double t, State& out) const {
    const double s = (t - t0_) / (t1_ - t0_), s1 = 1.0 - s;
    out = x0_ * s1 + s * (x1_ + s1 * (c3_ + s * c4_));
  }
  double t0() const { return t0_; }
  double t1() const { return t1_; }
  const State& x0() const { return x0_; }
  const State& x1() const { return x1_; }
  double suggested_step() const { return h_; }
  long rhs_evaluations() const { return rhs_; }
  long rejected_steps() const { return rejected_; }

 private:
  void accept(double t_stop, double dt, bool ends) {
    x0_.swap(x1_);
    x1_ = xn_;
    t0_ = t1_;
    t1_ = ends ? t_stop : t1_ + dt;
    extension();
  }
  // the continuous extension's coefficients
  void extension() {
    c3_ = kD21 * g1_ + kD22 * g2_ + kD23 * g3_ + kD24 * g4_ + kD25 * g5_;
    c4_ = kD31 * g1_ + kD32 * g2_ + kD33 * g3_ + kD34 * g4_ + kD35 * g5_;
  }

  double error_norm() const {
    const Eigen::Index m = ctl_.controlled < 0 ? x1_.size() : ctl_.controlled;
    double sum = 0.0;
    for (Eigen::Index i = 0; i < m; ++i) {
      const double sk = ctl_.atol + ctl_.rtol * std::max(std::abs(x1_(i)), std::abs(xn_(i)));
      sum += (err_(i) / sk) * (err_(i) / sk);
    }
    return std::sqrt(sum / static_cast<double>(std::max<Eigen::Index>(m, 1)));
  }

  // one step of length dt from (t, x) into xn_, its error into err_
  template <class System>
  void stages(System& sys, const State& x, double t, double dt) {
    const Eigen::Index m = x.size();
    const Eigen::Index controlled = ctl_.controlled < 0 ? m : ctl_.controlled;
    // at a jump of the forcing the step starts from its right-hand limit (refresh_derivative)
    const double ts = t < t_right_ && t_right_ <= std::nextafter(t, t_right_) ? t_right_ : t;
    sys(ts, x, f_);
    // the Jacobian by forward differences; the accumulated integrals feed no right-hand side
    tmp_ = x;
    for (Eigen::Index j = 0; j < m; ++j) {
      if (j >= controlled) {
        jac_.col(j).setZero();
        continue;
      }
      const double d = 1.5e-8 * std::max(std::abs(x(j)), 1e-4);
      tmp_(j) = x(j) + d;
      sys(ts, tmp_, f1_);
      tmp_(j) = x(j);
      jac_.col(j) = (f1_ - f_) / d;
    }
    const double dtt = 1.5e-8 * std::max(std::abs(t), 1.0);
    sys(ts + dtt, x, f1_);
    dfdt_ = (f1_ - f_) / dtt;
    rhs_ += controlled + 2;
    jac_ *= -1.0;
    jac_.diagonal().array() += 1.0 / (kGamma * dt);
    lu_.compute(jac_);
    g1_ = lu_.solve(f_ + dt * kD1 * dfdt_);
    tmp_ = x + kA21 * g1_;
    sys(t + kC2 * dt, tmp_, f1_);
    g2_ = lu_.solve(f1_ + dt * kD2 * dfdt_ + kC21 * g1_ / dt);
    tmp_ = x + kA31 * g1_ + kA32 * g2_;
    sys(t + kC3 * dt, tmp_, f1_);
    g3_ = lu_.solve(f1_ + dt * kD3 * dfdt_ + (kC31 * g1_ + kC32 * g2_) / dt);
    tmp_ = x + kA41 * g1_ + kA42 * g2_ + kA43 * g3_;
    sys(t + kC4 * dt, tmp_, f1_);
    g4_ = lu_.solve(f1_ + dt * kD4 * dfdt_ + (kC41 * g1_ + kC42 * g2_ + kC43 * g3_) / dt);
    tmp_ = x + kA51 * g1_ + kA52 * g2_ + kA53 * g3_ + kA54 * g4_;
    sys(t + dt, tmp_, f1_);
    g5_ = lu_.solve(f1_ + (kC51 * g1_ + kC52 * g2_ + kC53 * g3_ + kC54 * g4_) / dt);
    tmp_ += g5_;
    sys(t + dt, tmp_, f1_);
    err_ = lu_.solve(f1_ + (kC61 * g1_ + kC62 * g2_ + kC63 * g3_ + kC64 * g4_ + kC65 * g5_) / dt);
    xn_ = tmp_ + err_;
    rhs_ += 5;
  }

  StepControl ctl_;
  State x0_, x1_, xn_, xs_, f_, f1_, dfdt_, g1_, g2_, g3_, g4_, g5_, tmp_, err_, c3_, c4_;
  Matrix jac_;
  Eigen::PartialPivLU<Matrix> lu_;
  double t0_ = 0.0, t1_ = 0.0, h_ = 0.0, dt_old_ = 0.0, err_old_ = 0.0;
  double t_right_ = -std::numeric_limits<double>::infinity();  // [s] see refresh_derivative
  bool first_ = true, last_rejected_ = false;
  long rhs_ = 0, rejected_ = 0;
};

}  // namespace flexrock
