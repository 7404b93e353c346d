// SPDX-License-Identifier: BSD-3-Clause
// Lognormal fragility by maximum likelihood: recovery of known parameters, the score at the
// estimate, a brute-force likelihood grid, the delta-method errors against a finite-difference
// Hessian, and clear errors for data without a finite estimate.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>

#include "flexrock/study/fragility.hpp"
#include "support/expect_error.hpp"

namespace flexrock::study {
namespace {

double phi_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// IMs log-uniform on [lo, hi], outcomes drawn from the lognormal model (seeded)
void synthetic(double theta, double beta, std::size_t n, unsigned seed, std::vector<double>& im,
               std::vector<int>& y) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  im.clear();
  y.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const double x = theta * std::exp(3.0 * beta * (2.0 * u(rng) - 1.0));
    im.push_back(x);
    y.push_back(u(rng) < phi_cdf(std::log(x / theta) / beta) ? 1 : 0);
  }
}

TEST(StudyFragility, RecoversKnownParametersFromALargeSample) {
  std::vector<double> im;
  std::vector<int> y;
  synthetic(0.45, 0.35, 20000, 12345u, im, y);
  const FragilityFit f = fit_lognormal(im, y);
  EXPECT_LT(f.se_ln_theta, 0.01);
  EXPECT_LT(f.se_beta, 0.01);
  EXPECT_LT(std::abs(std::log(f.theta / 0.45)), 4.0 * f.se_ln_theta);
  EXPECT_LT(std::abs(f.beta - 0.35), 4.0 * f.se_beta);
  EXPECT_LT(f.theta_lower, f.theta);
  EXPECT_GT(f.theta_upper, f.theta);
  EXPECT_EQ(f.samples, 20000u);
}

TEST(StudyFragility, ScoreVanishesAtTheEstimate) {
  std::vector<double> im;
  std::vector<int> y;
  synthetic(2.0, 0.5, 400, 7u, im, y);
  const FragilityFit f = fit_lognormal(im, y);
  // central differences of the log-likelihood in ln theta and beta
  const double h = 1e-5;
  const double lt = std::log(f.theta);
  const double d_lt = (lognormal_log_likelihood(im, y, std::exp(lt + h), f.beta) -
                       lognormal_log_likelihood(im, y, std::exp(lt - h), f.beta)) /
                      (2 * h);
  const double d_b = (lognormal_log_likelihood(im, y, f.theta, f.beta + h) -
                      lognormal_log_likelihood(im, y, f.theta, f.beta - h)) /
                     (2 * h);
  EXPECT_NEAR(d_lt, 0.0, 1e-5);
  EXPECT_NEAR(d_b, 0.0, 1e-5);
  EXPECT_NEAR(f.log_likelihood, lognormal_log_likelihood(im, y, f.theta, f.beta), 1e-9);
}

TEST(StudyFragility, NoPointOfABruteForceGridIsMoreLikely) {
  std::vector<double> im;
  std::vector<int> y;
  synthetic(0.8, 0.3, 120, 99u, im, y);
  const FragilityFit f = fit_lognormal(im, y);
  double best = -1e300, best_lt = 0, best_b = 0;
  for (int i = 0; i <= 400; ++i) {
    for (int j = 1; j <= 400; ++j) {
      const double lt = std::log(0.8) - 0.5 + i * 0.0025;
      const double b = j * 0.0025;
      const double ll = lognormal_log_likelihood(im, y, std::exp(lt), b);
      if (ll > best) {
        best = ll;
        best_lt = lt;
        best_b = b;
      }
    }
  }
  EXPECT_GE(f.log_likelihood, best - 1e-12);
  EXPECT_NEAR(std::log(f.theta), best_lt, 0.0025);
  EXPECT_NEAR(f.beta, best_b, 0.0025);
}

TEST(StudyFragility, DeltaMethodErrorsMatchTheNumericalInformation) {
  std::vector<double> im;
  std::vector<int> y;
  synthetic(1.3, 0.4, 300, 2024u, im, y);
  const FragilityFit f = fit_lognormal(im, y);
  // Hessian of the log-likelihood in (ln theta, beta) by finite differences; its negative inverse
  // is the covariance the delta method must give (the MLE is invariant to reparametrisation)
  auto ll = [&](double lt, double b) { return lognormal_log_likelihood(im, y, std::exp(lt), b); };
  const double lt = std::log(f.theta), b = f.beta, h = 1e-4;
  Eigen::Matrix2d H;
  H(0, 0) = (ll(lt + h, b) - 2 * ll(lt, b) + ll(lt - h, b)) / (h * h);
  H(1, 1) = (ll(lt, b + h) - 2 * ll(lt, b) + ll(lt, b - h)) / (h * h);
  H(0, 1) = H(1, 0) =
      (ll(lt + h, b + h) - ll(lt + h, b - h) - ll(lt - h, b + h) + ll(lt - h, b - h)) / (4 * h * h);
  const Eigen::Matrix2d cov = (-H).inverse();
  EXPECT_NEAR(f.se_ln_theta, std::sqrt(cov(0, 0)), 1e-3 * f.se_ln_theta);
  EXPECT_NEAR(f.se_beta, std::sqrt(cov(1, 1)), 1e-3 * f.se_beta);
  EXPECT_NEAR(f.cov_ln_theta_beta, cov(0, 1), 1e-3 * std::abs(cov(0, 1)) + 1e-9);
  // bounds from the standard errors
  const double z = normal_quantile(0.975);
  EXPECT_NEAR(z, 1.959963984540054, 1e-12);
  EXPECT_NEAR(f.theta_upper, f.theta * std::exp(z * f.se_ln_theta), 1e-12 * f.theta);
}

TEST(StudyFragility, CurveAndBandAreConsistent) {
  std::vector<double> im;
  std::vector<int> y;
  synthetic(1.0, 0.5, 500, 3u, im, y);
  const FragilityFit f = fit_lognormal(im, y);
  EXPECT_NEAR(fragility_probability(f, f.theta), 0.5, 1e-15);
  double prev = 0.0;
  for (double x = 0.2; x < 5.0; x *= 1.3) {
    const double p = fragility_probability(f, x);
    double lo = 0, hi = 0;
    fragility_band(f, x, lo, hi);
    EXPECT_GE(p, prev);
    EXPECT_LT(lo, p);
    EXPECT_GT(hi, p);
    prev = p;
  }
}

TEST(StudyFragility, DataWithoutAFiniteEstimateAreClearErrors) {
  test::expect_input_error(
      [] {
        fit_lognormal({1, 2, 3}, {0, 0, 0});
      },
      {"every one of the 3 outcomes is 0"});
  test::expect_input_error(
      [] {
        fit_lognormal({1, 2, 3}, {1, 1, 1});
      },
      {"every one of the 3 outcomes is 1"});
  test::expect_input_error(
      [] {
        fit_lognormal({1, 2, 3, 4}, {0, 0, 1, 1});
      },
      {"perfectly separated", "beta = 0"});
  test::expect_input_error(
      [] {
        fit_lognormal({1, 2, 3, 4}, {1, 1, 0, 0});
      },
      {"perfectly separated", "decreases"});
  test::expect_input_error([] { fit_lognormal({1, -2}, {0, 1}); }, {"observation 2", "> 0"});
  test::expect_input_error([] { fit_lognormal({1, 2}, {0}); }, {"as many outcomes"});
  test::expect_input_error([] { fit_lognormal({1, 2, 3}, {0, 2, 1}); }, {"0 or 1"});
}
}  // namespace
}  // namespace flexrock::study

namespace flexrock::study {
namespace {

TEST(FragilityFamily, CurvesCrossWhereTheirProbabilitiesAreEqual) {
  FragilityFit a, b;
  a.theta = 1.0;
  a.beta = 0.3;
  b.theta = 2.0;
  b.beta = 0.6;
  // ln x = (0.6 ln 1 - 0.3 ln 2) / (0.6 - 0.3) = -ln 2
  const double x = crossing_intensity(a, b);
  EXPECT_NEAR(x, 0.5, 1e-15);
  EXPECT_NEAR(fragility_probability(a, x), fragility_probability(b, x), 1e-15);
  EXPECT_NEAR(crossing_intensity(b, a), x, 1e-15);
  b.beta = 0.3;
  EXPECT_TRUE(std::isnan(crossing_intensity(a, b)));
}
}  // namespace
}  // namespace flexrock::study

namespace flexrock::study {
namespace {

TEST(CapacityFit, ExactCapacitiesGiveTheSampleMeanAndDeviationOfTheirLogs) {
  // every capacity known: the lognormal maximum likelihood is in closed form, mu = mean ln c,
  // beta^2 = mean (ln c - mu)^2
  std::mt19937_64 rng(7);
  std::normal_distribution<double> z(0.0, 1.0);
  std::vector<CapacityInterval> c;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < 300; ++i) {
    const double x = 0.4 * std::exp(0.5 * z(rng));
    c.push_back({x, x});
    sum += std::log(x);
  }
  const double mu = sum / 300.0;
  for (const CapacityInterval& x : c) sum2 += (std::log(x.upper) - mu) * (std::log(x.upper) - mu);
  const FragilityFit f = fit_capacity_intervals(c);
  EXPECT_NEAR(std::log(f.theta), mu, 1e-9);
  EXPECT_NEAR(f.beta, std::sqrt(sum2 / 300.0), 1e-9);
  // the standard errors of a normal sample: beta / sqrt(n) and beta / sqrt(2 n)
  EXPECT_NEAR(f.se_ln_theta, f.beta / std::sqrt(300.0), 1e-5 * f.se_ln_theta);
  EXPECT_NEAR(f.se_beta, f.beta / std::sqrt(600.0), 1e-5 * f.se_beta);
}

TEST(CapacityFit, IntervalsFromFirstFailuresAndRefusals) {
  // record a fails first at 0.3 (not at 0.2), survives 0.4 again: (0.2, 0.3]; b never: (0.4,
  // inf); c at its lowest: (0, 0.1]
  const std::vector<CapacityInterval> c =
      capacity_intervals({0.1, 0.2, 0.3, 0.4, 0.4, 0.1, 0.2, 0.3, 0.1}, {0, 0, 1, 0, 0, 0, 0, 0, 1},
                         {"a", "a", "a", "a", "b", "b", "b", "b", "c"});
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].lower, 0.2);
  EXPECT_EQ(c[0].upper, 0.3);
  EXPECT_EQ(c[1].lower, 0.4);
  EXPECT_TRUE(std::isinf(c[1].upper));
  EXPECT_EQ(c[2].lower, 0.0);
  EXPECT_EQ(c[2].upper, 0.1);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(fit_capacity_intervals({{0.4, inf}, {0.4, inf}}), InputError);
  EXPECT_THROW(fit_capacity_intervals({{0.2, 0.3}, {0.2, 0.3}}), InputError);
  // overlapping intervals: a capacity in (0.2, 0.3] fits both with beta -> 0
  EXPECT_THROW(fit_capacity_intervals({{0.1, 0.3}, {0.2, inf}}), InputError);
  EXPECT_THROW(fit_capacity_intervals({{0.4, 0.4}, {0.4, 0.4}}), InputError);
  EXPECT_NO_THROW(fit_capacity_intervals({{0.1, 0.2}, {0.2, 0.3}, {0.0, 0.1}, {0.3, inf}}));
  // stripes: equal IMs pooled, in increasing IM
  const std::vector<Stripe> s = stripes_of({0.3, 0.1, 0.3, 0.1}, {1, 0, 0, 0});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].im, 0.1);
  EXPECT_EQ(s[0].runs, 2u);
  EXPECT_EQ(s[1].failures, 1u);
  EXPECT_THROW(fit_stripes({{0.1, 2, 3}, {0.2, 2, 1}}), InputError);
}

TEST(CapacityFit, OneLevelLeavesBetaUnidentifiedAndIsRefused) {
  // one level L: records that fail at it have capacity in (0, L], the others in (L, inf); the
  // likelihood Phi(z)^k (1 - Phi(z))^m, z = (ln L - ln theta) / beta, depends on (theta, beta)
  // through z only, so at its maximum every beta is as likely
  const double inf = std::numeric_limits<double>::infinity(), L = 0.3;
  for (const std::size_t copies : {1u, 3u}) {
    std::vector<CapacityInterval> c;
    for (std::size_t k = 0; k < copies; ++k) {
      c.push_back({0.0, L});
      c.push_back({L, inf});
    }
    // the flatness, from the likelihood itself
    const double ll = capacity_log_likelihood(c, L, 0.5);
    for (const double beta : {0.01, 0.1, 2.0, 50.0}) {
      EXPECT_EQ(capacity_log_likelihood(c, L, beta), ll) << beta;
    }
    try {
      fit_capacity_intervals(c);
      ADD_FAILURE() << "one level was fitted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("beta is not identified"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("add levels"), std::string::npos) << e.what();
    }
  }
  // two levels with a record failing between them identify beta
  const FragilityFit f = fit_capacity_intervals({{0.0, 0.2}, {0.2, 0.3}, {0.3, inf}});
  EXPECT_GT(f.beta, 0.0);
  EXPECT_GT(f.se_beta, 0.0);
  EXPECT_LT(f.beta_lower, f.beta_upper);
}

}  // namespace
}  // namespace flexrock::study
