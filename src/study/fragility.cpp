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
#include "flexrock/core/format.hpp"

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

// the observed information -hess must be positive definite, and not merely by rounding: where it
// is singular the likelihood is flat along an eigenvector and the data do not identify (theta,
// beta); the covariance would be its inverse, infinite there
void require_identified(const Eigen::Matrix2d& hess, const std::string& what,
                        const std::string& hint) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(-0.5 * (hess + hess.transpose()));
  const Eigen::Vector2d l = eig.eigenvalues();  // ascending
  FLEXROCK_THROW_UNLESS(l.allFinite() && l(1) > 0.0 && l(0) > 1e-8 * l(1),
                        what +
                            ": beta is not identified: the likelihood is flat (its information "
                            "matrix is singular, eigenvalues " +
                            format_number(l(0), 6) + " and " + format_number(l(1), 6) +
                            "), so every beta fits these data equally; " + hint);
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
                              format_number(im[i]));
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
          format_number(std::exp(zmax0), 6) +
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
                            format_number(b, 6) +
                            "): a lognormal fragility cannot describe these data");
  require_identified(h, "fragility",
                     "add runs at intensity measures between and around the present ones");
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

FragilityFit fit_stripes(const std::vector<Stripe>& stripes, double confidence) {
  std::vector<double> im;
  std::vector<int> failed;
  double log_binomial = 0.0;
  for (std::size_t j = 0; j < stripes.size(); ++j) {
    const Stripe& s = stripes[j];
    const std::string where = "multiple-stripe fit: stripe " + std::to_string(j + 1) + " (IM " +
                              format_number(s.im) + "): ";
    FLEXROCK_THROW_UNLESS(std::isfinite(s.im) && s.im > 0.0,
                          where + "expected an intensity measure > 0");
    FLEXROCK_THROW_UNLESS(s.failures <= s.runs, where + "expected at most " +
                                                    std::to_string(s.runs) + " failures, got " +
                                                    std::to_string(s.failures));
    for (std::size_t k = 0; k < j; ++k) {
      FLEXROCK_THROW_UNLESS(stripes[k].im != s.im, where + "the same IM as stripe " +
                                                       std::to_string(k + 1) + ": merge them");
    }
    // the run-by-run outcomes of the stripe: the same likelihood up to ln C(n, z)
    for (std::size_t i = 0; i < s.runs; ++i) {
      im.push_back(s.im);
      failed.push_back(i < s.failures ? 1 : 0);
    }
    const auto n = static_cast<double>(s.runs), z = static_cast<double>(s.failures);
    log_binomial += std::lgamma(n + 1.0) - std::lgamma(z + 1.0) - std::lgamma(n - z + 1.0);
  }
  FragilityFit fit = fit_lognormal(im, failed, confidence);
  fit.log_likelihood += log_binomial;
  return fit;
}

namespace {

// log(Phi(b) - Phi(a)) for a < b, accurate in either tail (by symmetry to the lower one)
double log_interval(double a, double b) {
  if (a > 0.0) return log_interval(-b, -a);
  if (!std::isfinite(a)) return log_cdf(b);
  const double pb = normal_cdf(b), pa = normal_cdf(a);
  if (pb - pa > 1e-300) return std::log(pb - pa);
  // both far in the lower tail
  return log_cdf(b) + std::log1p(-std::exp(log_cdf(a) - log_cdf(b)));
}

double phi(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * std::numbers::pi); }

// log-likelihood and its gradient in (mu, beta), mu = ln theta
double interval_ll(const std::vector<CapacityInterval>& c, double mu, double beta,
                   Eigen::Vector2d* grad) {
  double ll = 0.0;
  if (grad) grad->setZero();
  for (const CapacityInterval& x : c) {
    if (x.lower == x.upper) {
      // an exact capacity: the lognormal density
      const double z = (std::log(x.upper) - mu) / beta;
      ll += -0.5 * z * z - std::log(beta * x.upper) - 0.5 * std::log(2.0 * std::numbers::pi);
      if (grad) *grad += Eigen::Vector2d(z / beta, (z * z - 1.0) / beta);
      continue;
    }
    const double a =
        x.lower > 0.0 ? (std::log(x.lower) - mu) / beta : -std::numeric_limits<double>::infinity();
    const double b = std::isfinite(x.upper) ? (std::log(x.upper) - mu) / beta
                                            : std::numeric_limits<double>::infinity();
    const double l = log_interval(a, b);
    ll += l;
    if (!grad) continue;
    // d/dmu (Phi(b) - Phi(a)) = -(phi(b) - phi(a)) / beta, d/dbeta = -(b phi(b) - a phi(a)) / beta
    const double pb = std::isfinite(b) ? phi(b) : 0.0, pa = std::isfinite(a) ? phi(a) : 0.0;
    const double bpb = std::isfinite(b) ? b * pb : 0.0, apa = std::isfinite(a) ? a * pa : 0.0;
    const double p = std::exp(l);
    *grad += Eigen::Vector2d(-(pb - pa) / (beta * p), -(bpb - apa) / (beta * p));
  }
  return ll;
}

}  // namespace

double capacity_log_likelihood(const std::vector<CapacityInterval>& capacities, double theta,
                               double beta) {
  return interval_ll(capacities, std::log(theta), beta, nullptr);
}

FragilityFit fit_capacity_intervals(const std::vector<CapacityInterval>& c, double confidence) {
  FLEXROCK_THROW_UNLESS(
      c.size() >= 2, "capacity fit: expected at least 2 records, got " + std::to_string(c.size()));
  FLEXROCK_THROW_UNLESS(confidence > 0.0 && confidence < 1.0,
                        "capacity fit: expected a confidence level in (0, 1)");
  std::size_t reached = 0;
  double sum = 0.0;  // of ln of a point in each finite interval, for the start
  double max_lower = 0.0, min_upper = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < c.size(); ++i) {
    const CapacityInterval& x = c[i];
    FLEXROCK_THROW_UNLESS(x.lower >= 0.0 && x.upper >= x.lower && std::isfinite(x.lower) &&
                              !std::isnan(x.upper) && (x.upper > 0.0),
                          "capacity fit: record " + std::to_string(i + 1) +
                              ": expected 0 <= lower <= upper, upper > 0, got (" +
                              format_number(x.lower) + ", " + format_number(x.upper) + "]");
    if (std::isfinite(x.upper)) {
      ++reached;
      sum += std::log(x.lower > 0.0 ? std::sqrt(x.lower * x.upper) : x.upper);
    }
    max_lower = std::max(max_lower, x.lower);
    min_upper = std::min(min_upper, x.upper);
  }
  FLEXROCK_THROW_UNLESS(reached > 0,
                        "capacity fit: no record failed at any level (every one is truncated): "
                        "the median lies above the highest level; extend the levels");
  // one capacity inside every interval (or one exact capacity for all) fits them all with
  // beta -> 0, as a threshold that separates the outcomes perfectly does
  const bool same = std::all_of(c.begin(), c.end(), [&](const CapacityInterval& x) {
    return x.lower == c[0].lower && x.upper == c[0].upper;
  });
  FLEXROCK_THROW_UNLESS(!same && !(max_lower < min_upper),
                        "capacity fit: every record's capacity lies in (" +
                            format_number(max_lower) + ", " + format_number(min_upper) +
                            "]: the maximum likelihood is at beta = 0, no finite estimate "
                            "exists; add levels in that range or more records");
  // Newton on y = (mu, s), s = ln beta (beta stays > 0); the Hessian by central differences of
  // the analytic gradient
  auto value = [&](const Eigen::Vector2d& y, Eigen::Vector2d* g) {
    const double beta = std::exp(y(1));
    Eigen::Vector2d gb;
    const double ll = interval_ll(c, y(0), beta, g ? &gb : nullptr);
    if (g) *g = Eigen::Vector2d(gb(0), gb(1) * beta);  // d/ds = beta d/dbeta
    return ll;
  };
  auto hessian = [&](const Eigen::Vector2d& y) {
    Eigen::Matrix2d h;
    for (int k = 0; k < 2; ++k) {
      const double e = 1e-5 * (1.0 + std::abs(y(k)));
      Eigen::Vector2d yp = y, ym = y, gp, gm;
      yp(k) += e;
      ym(k) -= e;
      value(yp, &gp);
      value(ym, &gm);
      h.col(k) = (gp - gm) / (2.0 * e);
    }
    return Eigen::Matrix2d(0.5 * (h + h.transpose()));
  };
  Eigen::Vector2d y(sum / static_cast<double>(reached), std::log(0.5)), g;
  double ll = value(y, &g);
  int it = 0;
  for (; it < 200; ++it) {
    const Eigen::Matrix2d h = hessian(y);
    Eigen::Vector2d step = h.ldlt().solve(-g);
    // away from the maximum the Hessian may not be negative definite: then ascend the gradient
    if (!step.allFinite() || step.dot(g) <= 0.0) step = g / (1.0 + g.norm());
    double t = 1.0;
    Eigen::Vector2d yn = y;
    double lln = ll;
    for (int k = 0; k < 60; ++k, t *= 0.5) {
      yn = y + t * step;
      lln = value(yn, nullptr);
      if (std::isfinite(lln) && lln >= ll) break;
    }
    const bool small = (yn - y).norm() <= 1e-12 * (1.0 + y.norm());
    y = yn;
    ll = value(y, &g);
    FLEXROCK_THROW_UNLESS(y(1) > std::log(1e-8),
                          "capacity fit: beta goes to 0: the capacities cannot be told apart "
                          "from one value; add levels between them");
    if (small || g.norm() <= 1e-10 * static_cast<double>(c.size())) {
      ++it;
      break;
    }
  }
  const double mu = y(0), beta = std::exp(y(1));
  // covariance of (mu, beta) from the observed information in (mu, beta)
  const Eigen::Matrix2d hs = hessian(y);
  require_identified(hs, "capacity fit",
                     "with every capacity bracketed by the same level (one level with records "
                     "failing at it and records surviving it) only the median is known: add "
                     "levels so that records fail between two of them");
  Eigen::Matrix2d to_beta;  // y = (mu, ln beta): d(mu, beta)/dy
  to_beta << 1.0, 0.0, 0.0, beta;
  // at the maximum the gradient is zero, so the information transforms with the Jacobian
  const Eigen::Matrix2d cov_y = (-hs).inverse();
  const Eigen::Matrix2d cov_mb = to_beta * cov_y * to_beta.transpose();
  FragilityFit fit;
  fit.theta = std::exp(mu);
  fit.beta = beta;
  fit.se_ln_theta = std::sqrt(std::max(0.0, cov_mb(0, 0)));
  fit.se_beta = std::sqrt(std::max(0.0, cov_mb(1, 1)));
  fit.cov_ln_theta_beta = cov_mb(0, 1);
  fit.confidence = confidence;
  const double zq = normal_quantile(0.5 + 0.5 * confidence);
  fit.theta_lower = fit.theta * std::exp(-zq * fit.se_ln_theta);
  fit.theta_upper = fit.theta * std::exp(zq * fit.se_ln_theta);
  fit.beta_lower = std::max(0.0, beta - zq * fit.se_beta);
  fit.beta_upper = beta + zq * fit.se_beta;
  // (a, b) = (-mu/beta, 1/beta) for the band
  Eigen::Matrix2d jac;
  jac << -1.0 / beta, mu / (beta * beta), 0.0, -1.0 / (beta * beta);
  const Eigen::Matrix2d cov_ab = jac * cov_mb * jac.transpose();
  fit.cov_ab[0] = cov_ab(0, 0);
  fit.cov_ab[1] = cov_ab(0, 1);
  fit.cov_ab[2] = cov_ab(1, 1);
  fit.log_likelihood = ll;
  fit.iterations = it;
  fit.samples = c.size();
  fit.failures = reached;
  return fit;
}

std::vector<Stripe> stripes_of(const std::vector<double>& im, const std::vector<int>& failed) {
  FLEXROCK_THROW_UNLESS(im.size() == failed.size(),
                        "stripes: expected as many outcomes as intensity measures");
  std::vector<Stripe> out;
  for (std::size_t i = 0; i < im.size(); ++i) {
    auto it = std::find_if(out.begin(), out.end(), [&](const Stripe& s) { return s.im == im[i]; });
    if (it == out.end()) {
      out.push_back({im[i], 0, 0});
      it = out.end() - 1;
    }
    ++it->runs;
    if (failed[i]) ++it->failures;
  }
  std::sort(out.begin(), out.end(), [](const Stripe& a, const Stripe& b) { return a.im < b.im; });
  return out;
}

std::vector<CapacityInterval> capacity_intervals(const std::vector<double>& im,
                                                 const std::vector<int>& failed,
                                                 const std::vector<std::string>& record) {
  FLEXROCK_THROW_UNLESS(im.size() == failed.size() && im.size() == record.size(),
                        "capacity intervals: expected one IM, outcome and record per run");
  std::vector<std::string> names;
  std::vector<std::vector<std::pair<double, int>>> runs;
  for (std::size_t i = 0; i < im.size(); ++i) {
    const auto at = std::find(names.begin(), names.end(), record[i]);
    if (at == names.end()) {
      names.push_back(record[i]);
      runs.emplace_back();
    }
    runs[static_cast<std::size_t>(std::find(names.begin(), names.end(), record[i]) - names.begin())]
        .push_back({im[i], failed[i]});
  }
  std::vector<CapacityInterval> out;
  for (auto& r : runs) {
    std::sort(r.begin(), r.end());
    CapacityInterval c{r.back().first, std::numeric_limits<double>::infinity()};
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (r[k].second) {
        c = {k == 0 ? 0.0 : r[k - 1].first, r[k].first};
        break;
      }
    }
    out.push_back(c);
  }
  return out;
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
