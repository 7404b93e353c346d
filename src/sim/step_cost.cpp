// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/sim/step_cost.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "compliant.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/integrate/dop853.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/model/dynamics.hpp"

namespace flexrock {

namespace {

// the eigenvalues of the rocking equations on `edge`, linearized by central differences at
// theta = 0, the static deformation, no velocity and no base motion: x = (theta, q, theta_dot,
// q_dot), x' = (theta_dot, q_dot, theta_ddot, q_ddot)
Eigen::VectorXcd rocking_eigenvalues(const Body& body,
                                     const Dynamics<Eigen::Dynamic, Eigen::Dynamic>& dyn,
                                     int edge) {
  const int n = body.modes();
  const int dim = 2 * n + 2;
  VectorX x0 = VectorX::Zero(dim);
  if (n > 0) x0.segment(1, n) = body.static_deformation();
  auto rhs = [&](const VectorX& x) {
    VectorX f(dim);
    const VectorX q = x.segment(1, n), qd = x.segment(n + 2, n);
    double thdd = 0.0;
    VectorX qdd(n);
    dyn.rocking_acceleration(edge, x(0), q, x(n + 1), qd, BaseAcceleration{}, thdd, qdd);
    f.head(n + 1) = x.tail(n + 1);
    f(n + 1) = thdd;
    f.tail(n) = qdd;
    return f;
  };
  MatrixX jac(dim, dim);
  for (int j = 0; j < dim; ++j) {
    const double eps = 1e-6 * std::max(1.0, std::abs(x0(j)));
    VectorX xp = x0, xm = x0;
    xp(j) += eps;
    xm(j) -= eps;
    jac.col(j) = (rhs(xp) - rhs(xm)) / (2.0 * eps);
  }
  const Eigen::EigenSolver<MatrixX> es(jac, false);
  return es.eigenvalues();
}

// the largest |eigenvalue| of the rocking equations on `edge`
double rocking_omega(const Body& body, const Dynamics<Eigen::Dynamic, Eigen::Dynamic>& dyn,
                     int edge) {
  return rocking_eigenvalues(body, dyn, edge).cwiseAbs().maxCoeff();
}

std::string hz(double omega) {
  const double f = omega / (2.0 * std::numbers::pi);
  return f >= 1e3 ? format_number(f / 1e3, 3) + " kHz" : format_number(f, 3) + " Hz";
}

// the compliant contact's DOPRI5 steps: its fast motions are the body's bounce and sway on the
// corners' springs, coupled to the structure's modes and heavily damped by the dashpots (real
// eigenvalues, often far above the springs' own omega_v). DOPRI5 must keep h lambda in its
// stability region for each, wherever it stands (the switch to the Rosenbrock method is keyed on
// the springs' own rate, not these coupled ones); it must also resolve, at rtol, a motion that
// a base motion drives to resonance (damping ratio below 1/sqrt(2)), as the rigid estimate does
void compliant_step_cost(const Body& body, const SimulationOptions& options, StepCost& c) {
  c.contact_h_omega =
      std::min(std::pow(options.rtol / kDopri5ErrorConstant, 0.2), kDopri5ImaginaryStability);
  double h_stable = std::numeric_limits<double>::infinity();
  for (int pivot = 0; pivot <= 2; ++pivot) {
    for (const std::complex<double>& mu :
         detail::compliant_rest_eigenvalues(body, options, pivot)) {
      const double r = std::abs(mu);
      c.contact_omega = std::max(c.contact_omega, r);
      h_stable = std::min(h_stable, dopri5_stable_step(mu));
      if (mu.imag() != 0.0 && -mu.real() < r / std::numbers::sqrt2)
        c.contact_resonant_omega = std::max(c.contact_resonant_omega, r);
    }
  }
  c.contact_stable_steps_per_second = std::isfinite(h_stable) ? 1.0 / h_stable : 0.0;
  c.contact_steps_per_second =
      std::max({c.contact_stable_steps_per_second, c.contact_resonant_omega / c.contact_h_omega,
                1.0 / options.max_step});
}

// the compliant contact's: its rate is a floor, at rest as while rocking
std::string compliant_step_cost_warning(const StepCost& c, double duration, long max_steps) {
  const double rate = c.contact_steps_per_second;
  const bool over = duration > 0.0 && rate * duration > static_cast<double>(max_steps);
  const bool slow = rate > kSlowStepsPerSecond;
  if (!over && !slow) return "";
  std::string w =
      "stiff compliant contact: the body on its corners' springs and dashpots has a "
      "motion of " +
      format_number(c.contact_omega, 3) + " rad/s (" + hz(c.contact_omega) +
      "), and Dopri5 needs at least " + format_number(rate, 3) + " steps per simulated second";
  if (over) {
    w += "; the " + format_number(duration, 4) + " s would take at least " +
         format_number(rate * duration, 3) +
         " steps, above max_steps = " + std::to_string(max_steps) +
         " (the run would stop within about " +
         format_number(static_cast<double>(max_steps) / rate, 3) +
         " s): raise [solver] max_steps, soften contact_stiffness, or use the impulsive contact";
  } else {
    w += ": a long run is slow (soften contact_stiffness, or use the impulsive contact)";
  }
  // the estimate is the stability bound's: rocking, accuracy at atol on the fast motions can hold
  // the steps several times shorter
  w += "; a rocking body takes more (docs/theory.md, \"Compliant contact: step cost\")";
  return w;
}

}  // namespace

StepCost estimate_step_cost(const Body& body, const SimulationOptions& options) {
  const Dynamics<Eigen::Dynamic, Eigen::Dynamic> dyn(body);
  StepCost c;
  c.rocking_time_scale = 1.0 / body.rocking_frequency();
  c.rocking_omega = std::max(rocking_omega(body, dyn, 1), rocking_omega(body, dyn, 2));
  c.full_contact_omega = body.modes() > 0 ? body.natural_frequencies().cwiseAbs().maxCoeff() : 0.0;
  c.method = options.methods.high_order_rocking ? ExplicitMethod::kDop853 : ExplicitMethod::kDopri5;
  const bool eighth = c.method == ExplicitMethod::kDop853;
  const double stable = eighth ? kDop853ImaginaryStability : kDopri5ImaginaryStability;
  c.h_omega = eighth ? std::min(std::pow(options.rtol / kDop853ErrorConstant, 0.125), stable)
                     : std::min(std::pow(options.rtol / kDopri5ErrorConstant, 0.2), stable);
  c.rocking_min_steps_per_second = c.rocking_omega / stable;
  c.rocking_steps_per_second = std::max(c.rocking_omega / c.h_omega, 1.0 / options.max_step);
  if (options.contact_model == ContactModel::kCompliant &&
      options.methods.contact_integrator != ContactIntegrator::kImplicit &&
      options.contact_stiffness > 0.0)
    compliant_step_cost(body, options, c);
  return c;
}

double rocking_stable_step(const Body& body, int edge, ExplicitMethod method) {
  const Dynamics<Eigen::Dynamic, Eigen::Dynamic> dyn(body);
  double h = std::numeric_limits<double>::infinity();
  // an undamped mode's eigenvalues come out of the differences with a real part of either sign
  // at rounding level: taken on the imaginary axis. The rocking motion's growing eigenvalue (real,
  // about +p) bounds no step.
  for (const std::complex<double>& mu : rocking_eigenvalues(body, dyn, edge)) {
    // a real matrix's complex eigenvalues come in exact conjugate pairs (Eigen's real Schur
    // form), and |R(conj z)| = |R(z)| for the methods' real coefficients: one of each pair
    if (mu.imag() < 0.0) continue;
    const std::complex<double> m{std::min(mu.real(), 0.0), mu.imag()};
    h = std::min(h,
                 method == ExplicitMethod::kDop853 ? dop853_stable_step(m) : dopri5_stable_step(m));
  }
  return h;
}

std::string step_cost_warning(const StepCost& c, double duration, long max_steps) {
  if (c.contact_steps_per_second > 0.0) return compliant_step_cost_warning(c, duration, max_steps);
  const double rate = c.rocking_steps_per_second;
  const bool over = duration > 0.0 && rate * duration > static_cast<double>(max_steps);
  const bool slow = rate > kSlowStepsPerSecond;
  if (!over && !slow) return "";
  std::string w =
      "stiff rocking: while rocking, the stiffest motion (" + format_number(c.rocking_omega, 3) +
      " rad/s, " + hz(c.rocking_omega) + ") sets the explicit integrator's step (" +
      (c.method == ExplicitMethod::kDop853 ? "DOP853" : "Dopri5") + ", h omega ~ " +
      format_number(c.h_omega, 2) + "): about " + format_number(rate, 3) +
      " steps per simulated second, at least " + format_number(c.rocking_min_steps_per_second, 3) +
      " for stability (" + format_number(rate * c.rocking_time_scale, 3) +
      " per rocking time scale 1/p = " + format_number(c.rocking_time_scale, 3) + " s)";
  if (over) {
    w += "; rocking through the " + format_number(duration, 4) + " s would take about " +
         format_number(rate * duration, 3) +
         " steps, above max_steps = " + std::to_string(max_steps) +
         " (the run would stop after about " +
         format_number(static_cast<double>(max_steps) / rate, 3) +
         " s of rocking): raise [solver] max_steps";
  } else {
    w += ": a long run is slow";
  }
  // the estimate is the explicit method's: a damped stiff motion decays, and the rocking
  // integrator then switches to the Rosenbrock method
  w += "; where that motion is damped, the rocking integrator switches to a Rosenbrock method "
       "and takes far fewer (docs/theory.md, \"Stiff rocking\")";
  return w;
}

}  // namespace flexrock
