// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/fragility.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "flexrock/core/error.hpp"

namespace flexrock::study {

namespace {

constexpr double kSqrt2 = std::numbers::sqrt2;

double normal_cdf(double x) { return 0.5 * std::erfc(-x / kSqrt2); }

// log Phi(x), accurate far in the lower tail (asymptotic series below -35, where erfc underflows)
double log_cdf(double x) {
  if (x > -35.0) return std::log(normal_cdf(x));
  const double x2 = x * x;
  return -0.5 * x2 - 0.5 * std::log(2.0 * std::numbers::pi) - std::log(-x) +
         std::log1p(-1.0 / x2 + 3.0 / (x2 * x2));
}

// phi(x)/Phi(x), the inverse Mills ratio, stable in the lower tail
double mills(double x) {
  if (x > -35.0) {
    const double phi = std::exp(-0.5 * x * x) / std::sqrt(2.0 * std::numbers::pi);
    return phi / normal_cdf(x);
  }
  const double x2 = x * x;
  return -x / (1.0 - 1.0 / x2 + 3.0 / (x2 * x2));
}

struct Data {
  std::vector<double> z;  // ln IM - mean
  std::vector<int> y;
  double zbar = 0.0;
};

// log-likelihood, gradient and Hessian of eta = c + b z
double evaluate(const Data& d, double c, double b, Eigen::Vector2d* grad, Eigen::Matrix2d* hess) {
  double ll = 0.0;
  if (grad) grad->setZero();
  if (hess) hess->setZero();
  for (std::size_t i = 0; i < d.z.size(); ++i) {
    const double eta = c + b * d.z[i];
    // y = 1: log Phi(eta), lambda = phi/Phi(eta); y = 0: log Phi(-eta), lambda = -phi/Phi(-eta)
    const double s = d.y[i] ? 1.0 : -1.0;
    ll += log_cdf(s * eta);
    if (!grad) continue;
    const double lambda = s * mills(s * eta);
    const Eigen::Vector2d x(1.0, d.z[i]);
    *grad += lambda * x;
    // d lambda / d eta = -lambda (lambda + eta) for both outcomes
    if (hess) *hess -= lambda * (lambda + eta) * x * x.transpose();
  }
  return ll;
}

}  // namespace

double normal_quantile(double p) {
  FLEXROCK_THROW_UNLESS(p > 0.0 && p < 1.0, "normal_quantile: expected p in (0, 1)");
  return boost::math::quantile(boost::math::normal_distribution<double>(), p);
}

double lognormal_log_likelihood(const std::vector<double>& im, const std::vector<int>& failed,
                                double theta, double beta) {
  double ll = 0.0;
  for (std::size_t i = 0; i < im.size(); ++i) {
    const double eta = std::log(im[i] / theta) / beta;
    ll += log_cdf(failed[i] ? eta : -eta);
  }
  return ll;
}

FragilityFit fit_lognormal(const std::vector<double>& im, const std::vector<int>& failed,
                           double confidence) {
  FLEXROCK_THROW_UNLESS(im.size() == failed.size(),
                        "fragility: expected as many outcomes as intensity measures, got " +
                            std::to_string(failed.size()) + " and " + std::to_string(im.size()));
  FLEXROCK_THROW_UNLESS(im.size() >= 2, "fragility: expected at least 2 observations, got " +
                                            std::to_string(im.size()));
  FLEXROCK_THROW_UNLESS(confidence > 0.0 && confidence < 1.0,
                        "fragility: expected a confidence level in (0, 1)");
  Data d;
  std::size_t failures = 0;
  double zmax0 = -std::numeric_limits<double>::infinity(), zmin1 = -zmax0;
  double zmin0 = zmin1, zmax1 = zmax0;
  for (std::size_t i = 0; i < im.size(); ++i) {
    FLEXROCK_THROW_UNLESS(std::isfinite(im[i]) && im[i] > 0.0,
                          "fragility: observation " + std::to_string(i + 1) +
                              ": expected an intensity measure > 0 (finite), got " +
                              std::to_string(im[i]));
    FLEXROCK_THROW_UNLESS(failed[i] == 0 || failed[i] == 1,
                          "fragility: observation " + std::to_string(i + 1) +
                              ": expected an outcome 0 or 1, got " + std::to_string(failed[i]));
    const double z = std::log(im[i]);
    d.z.push_back(z);
    d.y.push_back(failed[i]);
    d.zbar += z;
    if (failed[i]) {
      ++failures;
      zmin1 = std::min(zmin1, z);
      zmax1 = std::max(zmax1, z);
    } else {
      zmin0 = std::min(zmin0, z);
      zmax0 = std::max(zmax0, z);
    }
  }
  const std::size_t n = im.size();
  FLEXROCK_THROW_UNLESS(failures > 0 && failures < n,
                        std::string("fragility: every one of the ") + std::to_string(n) +
                            " outcomes is " + (failures ? "1" : "0") +
                            ": the curve cannot be fitted (extend the range of the intensity "
                            "measure so that both outcomes occur)");
  FLEXROCK_THROW_UNLESS(
      zmax0 > zmin1,
      "fragility: the outcomes are perfectly separated by the intensity measure (every "
      "observation with outcome 0 has IM <= " +
          std::to_string(std::exp(zmax0)) +
          " <= every one with outcome 1): the maximum likelihood is at beta = 0, no finite "
          "estimate exists; add observations between the two groups");
  FLEXROCK_THROW_UNLESS(zmax1 > zmin0,
                        "fragility: the outcomes are perfectly separated with outcome 1 at the "
                        "lower intensity measures: the probability decreases with the IM, which "
                        "a lognormal fragility cannot describe");
  d.zbar /= static_cast<double>(n);
  for (double& z : d.z) z -= d.zbar;

  // Newton's method with step halving on (c, b); the log-likelihood is concave
  const double pbar = static_cast<double>(failures) / static_cast<double>(n);
  Eigen::Vector2d x(normal_quantile(pbar), 0.0);
  Eigen::Vector2d g;
  Eigen::Matrix2d h;
  double ll = evaluate(d, x(0), x(1), &g, &h);
  FragilityFit fit;
  int it = 0;
  for (; it < 200; ++it) {
    const Eigen::Vector2d step = h.ldlt().solve(-g);
    if (!step.allFinite()) break;
    double t = 1.0;
    Eigen::Vector2d xn;
    double lln = ll;
    for (int k = 0; k < 60; ++k, t *= 0.5) {
      xn = x + t * step;
      lln = evaluate(d, xn(0), xn(1), nullptr, nullptr);
      if (lln >= ll) break;
    }
    const bool small = (xn - x).norm() <= 1e-13 * (1.0 + x.norm());
    x = xn;
    ll = evaluate(d, x(0), x(1), &g, &h);
    if (small || g.norm() <= 1e-12 * static_cast<double>(n)) {
      ++it;
      break;
    }
  }
  const double c = x(0), b = x(1);
  FLEXROCK_THROW_UNLESS(b > 0.0,
                        "fragility: the fitted probability decreases with the intensity "
                        "measure (b = " +
                            std::to_string(b) +
                            "): a lognormal fragility cannot describe these data");
  // back to eta = a + b ln IM: a = c - b zbar; covariance from the observed information
  const double a = c - b * d.zbar;
  const Eigen::Matrix2d cov_cb = (-h).inverse();
  Eigen::Matrix2d tr;
  tr << 1.0, -d.zbar, 0.0, 1.0;
  const Eigen::Matrix2d cov_ab = tr * cov_cb * tr.transpose();
  // ln theta = -a/b, beta = 1/b; delta method
  Eigen::Matrix2d jac;
  jac << -1.0 / b, a / (b * b), 0.0, -1.0 / (b * b);
  const Eigen::Matrix2d cov_tb = jac * cov_ab * jac.transpose();
  fit.theta = std::exp(-a / b);
  fit.beta = 1.0 / b;
  fit.se_ln_theta = std::sqrt(std::max(0.0, cov_tb(0, 0)));
  fit.se_beta = std::sqrt(std::max(0.0, cov_tb(1, 1)));
  fit.cov_ln_theta_beta = cov_tb(0, 1);
  fit.confidence = confidence;
  const double zq = normal_quantile(0.5 + 0.5 * confidence);
  fit.theta_lower = fit.theta * std::exp(-zq * fit.se_ln_theta);
  fit.theta_upper = fit.theta * std::exp(zq * fit.se_ln_theta);
  fit.beta_lower = std::max(0.0, fit.beta - zq * fit.se_beta);
  fit.beta_upper = fit.beta + zq * fit.se_beta;
  fit.cov_ab[0] = cov_ab(0, 0);
  fit.cov_ab[1] = cov_ab(0, 1);
  fit.cov_ab[2] = cov_ab(1, 1);
  fit.log_likelihood = ll;
  fit.iterations = it;
  fit.samples = n;
  fit.failures = failures;
  return fit;
}

double fragility_probability(const FragilityFit& fit, double x) {
  if (!(x > 0.0)) return 0.0;
  return normal_cdf(std::log(x / fit.theta) / fit.beta);
}

double crossing_intensity(const FragilityFit& a, const FragilityFit& b) {
  if (a.beta == b.beta) return std::numeric_limits<double>::quiet_NaN();
  return std::exp((b.beta * std::log(a.theta) - a.beta * std::log(b.theta)) / (b.beta - a.beta));
}

void fragility_band(const FragilityFit& fit, double x, double& lower, double& upper) {
  if (!(x > 0.0)) {
    lower = upper = 0.0;
    return;
  }
  const double z = std::log(x);
  const double b = 1.0 / fit.beta;
  const double eta = b * (z - std::log(fit.theta));
  const double var = fit.cov_ab[0] + 2.0 * z * fit.cov_ab[1] + z * z * fit.cov_ab[2];
  const double k = normal_quantile(0.5 + 0.5 * fit.confidence) * std::sqrt(std::max(0.0, var));
  lower = normal_cdf(eta - k);
  upper = normal_cdf(eta + k);
}

}  // namespace flexrock::study
