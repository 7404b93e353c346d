// SPDX-License-Identifier: BSD-3-Clause
// Fragility curves: the lognormal model P(failure | IM = x) = Phi(ln(x / theta) / beta) fitted by
// maximum likelihood to binary outcomes (Baker 2015). In z = ln x it is a probit regression
// P = Phi(a + b z) with a = -ln(theta) / beta, b = 1 / beta, whose log-likelihood is concave:
// Newton's method with a step-halving line search finds the maximum. Confidence bounds come from
// the observed Fisher information (the inverse Hessian at the maximum) by the delta method.
#pragma once

#include <cstddef>
#include <string>
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

/// One stripe of a multiple-stripe analysis: every run at the same intensity measure.
struct Stripe {
  double im = 0.0;           // the stripe's IM (> 0, finite)
  std::size_t runs = 0;      // runs at the stripe (those classified)
  std::size_t failures = 0;  // of which failed
};

/// Multiple-stripe analysis (Baker 2015, eq. 11): maximizes the binomial log-likelihood
/// sum_j ln C(n_j, z_j) + z_j ln p_j + (n_j - z_j) ln(1 - p_j), p_j = Phi(ln(x_j/theta)/beta),
/// over the stripes. Its maximum is that of the run-by-run likelihood of fit_lognormal (the
/// binomial coefficients do not depend on theta, beta), so the same Newton iteration finds it;
/// log_likelihood includes the coefficients. A stripe may hold fewer runs than another (records
/// that could not be scaled to it, runs left out). Throws InputError as fit_lognormal does, and
/// for a stripe with more failures than runs or two stripes at one IM.
FragilityFit fit_stripes(const std::vector<Stripe>& stripes, double confidence = 0.95);

/// Where a record's capacity (the IM at which it first fails) lies: in (lower, upper]. From an
/// incremental dynamic analysis at discrete levels: upper the first level at which it failed,
/// lower the level before (0 if it failed at the first); a record that never failed up to the
/// highest level x_max has (x_max, inf): it is truncated there (Baker 2015, "truncated IDA").
/// lower == upper is a capacity known exactly.
struct CapacityInterval {
  double lower = 0.0;  // [IM] >= 0
  double upper = 0.0;  // [IM] >= lower; inf: never failed
};

/// Fits the lognormal distribution of capacities to intervals (exact capacities contribute the
/// density phi(ln(c/theta)/beta) / (beta c), intervals Phi(b) - Phi(a), truncated records
/// 1 - Phi(ln(x_max/theta)/beta): Baker 2015 eq. 8 for truncated IDA, with the interval of
/// discrete levels in place of an exact capacity) by maximum likelihood: Newton's method on
/// (ln theta, ln beta) with an analytic gradient and a central-difference Hessian, step halving.
/// Throws InputError when no finite estimate exists: fewer than 2 records, every record
/// truncated, or one IM inside every interval (the capacities cannot be told apart: the maximum
/// is at beta = 0, as for outcomes a threshold separates perfectly).
FragilityFit fit_capacity_intervals(const std::vector<CapacityInterval>& capacities,
                                    double confidence = 0.95);

/// The stripes of run-by-run observations: runs with equal IMs form one stripe; in increasing
/// IM.
std::vector<Stripe> stripes_of(const std::vector<double>& im, const std::vector<int>& failed);

/// The capacity interval of each record of an incremental dynamic analysis, from run-by-run
/// observations and the record of each (`record[i]` names observation i's): a record's runs in
/// increasing IM; upper the IM of its first failure, lower that of the run before (0: it failed
/// at its lowest); never failed: (its highest IM, inf). Later runs of a record that failed are
/// not used (a rocking body may survive a higher level; its capacity is the first failure). In
/// the order records first appear.
std::vector<CapacityInterval> capacity_intervals(const std::vector<double>& im,
                                                 const std::vector<int>& failed,
                                                 const std::vector<std::string>& record);

/// Log-likelihood of (theta, beta) for capacity intervals (for tests and profile checks).
double capacity_log_likelihood(const std::vector<CapacityInterval>& capacities, double theta,
                               double beta);

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
