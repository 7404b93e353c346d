// SPDX-License-Identifier: BSD-3-Clause
// Fragility curves: the lognormal model P(failure | IM = x) = Phi(ln(x / theta) / beta) fitted by
// maximum likelihood to binary outcomes (Baker 2015). In z = ln x it is a probit regression
// P = Phi(a + b z) with a = -ln(theta) / beta, b = 1 / beta, whose log-likelihood is concave:
// Newton's method with a step-halving line search finds the maximum. Confidence bounds come from
// the observed Fisher information (the inverse Hessian at the maximum) by the delta method.
#pragma once

#include <cstddef>
#include <vector>

namespace flexrock::study {

struct FragilityFit {
  double theta = 0.0;                           // median capacity, in the units of the IM
  double beta = 0.0;                            // [-] lognormal standard deviation
  double se_ln_theta = 0.0;                     // [-] standard error of ln(theta) (delta method)
  double se_beta = 0.0;                         // [-] standard error of beta (delta method)
  double cov_ln_theta_beta = 0.0;               // [-] their covariance
  double confidence = 0.95;                     // [-] level of the bounds below (two-sided)
  double theta_lower = 0.0, theta_upper = 0.0;  // bounds on theta: exp(ln theta -+ z se)
  double beta_lower = 0.0, beta_upper = 0.0;    // bounds on beta: beta -+ z se (lower >= 0)
  double cov_ab[3] = {0.0, 0.0, 0.0};           // covariance of (a, b): var a, cov ab, var b
  double log_likelihood = 0.0;                  // at the maximum
  int iterations = 0;                           // Newton iterations
  std::size_t samples = 0;                      // observations used
  std::size_t failures = 0;                     // of which outcome = 1
};

/// Fits the lognormal fragility to intensity measures `im` (> 0, finite) and outcomes `failed`
/// (0 or 1) by maximum likelihood. `confidence` in (0, 1). Throws InputError for sizes that
/// differ, fewer than 2 samples, an IM <= 0, all outcomes equal, or data that a threshold on
/// the IM separates perfectly (the maximum is at beta = 0: no finite estimate), each with a
/// message saying so.
FragilityFit fit_lognormal(const std::vector<double>& im, const std::vector<int>& failed,
                           double confidence = 0.95);

/// P(failure | IM = x) = Phi(ln(x / theta) / beta); x <= 0 gives 0.
double fragility_probability(const FragilityFit& fit, double x);

/// Pointwise confidence band of the curve at x: Phi(eta -+ z sd(eta)), eta = a + b ln x, with
/// var(eta) from the covariance of (a, b). Writes lower and upper.
void fragility_band(const FragilityFit& fit, double x, double& lower, double& upper);

/// Where two fitted curves cross: the x > 0 at which ln(x/theta)/beta is the same for both,
/// ln x = (beta_b ln theta_a - beta_a ln theta_b) / (beta_b - beta_a); NaN for equal betas
/// (parallel curves: they never cross, whatever their medians).
double crossing_intensity(const FragilityFit& a, const FragilityFit& b);

/// Log-likelihood of (theta, beta) for the data (for tests and profile checks).
double lognormal_log_likelihood(const std::vector<double>& im, const std::vector<int>& failed,
                                double theta, double beta);

/// The standard normal quantile Phi^-1(p), p in (0, 1).
double normal_quantile(double p);

}  // namespace flexrock::study
