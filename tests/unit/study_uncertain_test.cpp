// SPDX-License-Identifier: BSD-3-Clause
// Uncertain parameters: the sampler's moments against closed forms, truncation bounds, the Latin
// hypercube's strata, values that depend on the seed and the index only, bad distributions, and
// what a sampled value does to a body and to the solver options.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "flexrock/core/format.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/study/parallel.hpp"
#include "flexrock/study/sweep.hpp"
#include "flexrock/study/uncertain.hpp"
#include "support/expect_error.hpp"

namespace flexrock::study {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Moments {
  double mean = 0.0, variance = 0.0;
};

Moments moments(const std::vector<double>& x) {
  Moments m;
  for (double v : x) m.mean += v;
  m.mean /= static_cast<double>(x.size());
  for (double v : x) m.variance += (v - m.mean) * (v - m.mean);
  m.variance /= static_cast<double>(x.size() - 1);
  return m;
}

std::vector<double> draws(const UncertainParameter& p, std::size_t n, SamplingMethod method,
                          std::uint64_t seed = 12345) {
  Uncertainty u;
  u.parameters = {p};
  u.sampling.seed = seed;
  u.sampling.method = method;
  const SampleDesign d(u, n);
  std::vector<double> x;
  for (std::size_t i = 0; i < n; ++i) x.push_back(d.values(i)[0]);
  return x;
}

double pdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi); }
double cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

// n independent draws: the sample mean is within 5 standard errors sigma/sqrt(n) of the true
// mean (a chance of 6e-7 to miss with a good generator), and the sample variance within 5 of its
// standard error sigma^2 sqrt((kurtosis - 1)/n)
void expect_moments(const std::vector<double>& x, double mean, double variance, double kurtosis,
                    const char* what) {
  const Moments m = moments(x);
  const double n = static_cast<double>(x.size());
  EXPECT_NEAR(m.mean, mean, 5.0 * std::sqrt(variance / n)) << what;
  EXPECT_NEAR(m.variance, variance, 5.0 * variance * std::sqrt((kurtosis - 1.0) / n)) << what;
}

constexpr std::size_t kDraws = 200'000;

TEST(Uncertain, UniformMomentsAreClosedForm) {
  const UncertainParameter p{UncertainKind::kFriction, Distribution::kUniform, 0.3, 0.7};
  const auto x = draws(p, kDraws, SamplingMethod::kRandom);
  // mean (a+b)/2, variance (b-a)^2/12, kurtosis 9/5
  expect_moments(x, 0.5, 0.4 * 0.4 / 12.0, 1.8, "uniform");
  EXPECT_GE(*std::min_element(x.begin(), x.end()), 0.3);
  EXPECT_LE(*std::max_element(x.begin(), x.end()), 0.7);
}

TEST(Uncertain, NormalMomentsAreClosedForm) {
  const UncertainParameter p{UncertainKind::kSizeScale, Distribution::kNormal, 1.0, 0.05};
  expect_moments(draws(p, kDraws, SamplingMethod::kRandom), 1.0, 0.0025, 3.0, "normal");
}

TEST(Uncertain, LognormalMomentsAreClosedForm) {
  const double median = 0.6, beta = 0.2;
  const UncertainParameter p{UncertainKind::kFriction, Distribution::kLognormal, median, beta};
  const auto x = draws(p, kDraws, SamplingMethod::kRandom);
  // ln x is normal (ln median, beta^2)
  std::vector<double> lx;
  for (double v : x) lx.push_back(std::log(v));
  expect_moments(lx, std::log(median), beta * beta, 3.0, "ln of lognormal");
  // x itself: mean median e^(beta^2/2), variance mean^2 (e^(beta^2) - 1), kurtosis
  // e^(4 beta^2) + 2 e^(3 beta^2) + 3 e^(2 beta^2) - 3
  const double s2 = beta * beta;
  const double mean = median * std::exp(s2 / 2.0);
  const double kurt = std::exp(4 * s2) + 2 * std::exp(3 * s2) + 3 * std::exp(2 * s2) - 3;
  expect_moments(x, mean, mean * mean * (std::exp(s2) - 1.0), kurt, "lognormal");
}

// the truncated normal's mean and variance (Johnson, Kotz & Balakrishnan, ch. 13)
TEST(Uncertain, TruncatedNormalMomentsAreClosedFormAndBoundsHold) {
  const double mu = 0.5, sigma = 0.2, lo = 0.35, hi = 1.0;
  const UncertainParameter p{UncertainKind::kFriction, Distribution::kNormal, mu, sigma, lo, hi};
  const auto x = draws(p, kDraws, SamplingMethod::kRandom);
  const double a = (lo - mu) / sigma, b = (hi - mu) / sigma, z = cdf(b) - cdf(a);
  const double mean = mu + sigma * (pdf(a) - pdf(b)) / z;
  const double var =
      sigma * sigma * (1.0 + (a * pdf(a) - b * pdf(b)) / z - std::pow((pdf(a) - pdf(b)) / z, 2));
  // a kurtosis of 3 bounds the truncated one (a truncation thins the tails)
  expect_moments(x, mean, var, 3.0, "truncated normal");
  EXPECT_GE(*std::min_element(x.begin(), x.end()), lo);
  EXPECT_LE(*std::max_element(x.begin(), x.end()), hi);
}

TEST(Uncertain, TailTruncationsStayInsideTheirBounds) {
  // far in either tail, where F or 1 - F has few digits left
  for (const auto& [lo, hi] : {std::pair{5.0, 6.0}, std::pair{-6.0, -5.0}, std::pair{8.0, kInf}}) {
    const UncertainParameter p{UncertainKind::kSizeScale, Distribution::kNormal, 0.0, 1.0, lo, hi};
    // the size scale must be > 0: check the sampler alone, not the parameter's domain
    const auto x = draws(p, 20'000, SamplingMethod::kLatinHypercube);
    for (double v : x) {
      ASSERT_GE(v, lo);
      ASSERT_LE(v, hi);
    }
    // the mass piles up at the bound nearest the bulk: the mean lies within 1/|bound| of it
    const double near = std::abs(lo) < std::abs(hi) ? lo : hi;
    EXPECT_LT(std::abs(moments(x).mean - near), 1.0 / std::abs(near)) << lo << " " << hi;
  }
  // the extreme uniforms: with F(lower) = 1/2, pl + u (pu - pl) rounds to exactly 1 at
  // u = 1 - 2^-53 (a tie, to even): an infinite quantile unless kept inside (0, 1)
  const UncertainParameter cut{
      UncertainKind::kSizeScale, Distribution::kNormal, 0.0, 1.0, 0.0, kInf};
  for (const double u : {0x1p-53, 1.0 - 0x1p-53}) {
    const double x = quantile(cut, u);
    EXPECT_TRUE(std::isfinite(x) && x >= 0.0) << u << " " << x;
  }
  // the largest counter_uniform, hash bits all ones, is a double below 1
  EXPECT_LT((0x1p52 - 1.0 + 0.5) * 0x1p-52, 1.0);
  const UncertainParameter ln{
      UncertainKind::kFriction, Distribution::kLognormal, 0.5, 0.5, 0.4, 0.45};
  for (double v : draws(ln, 10'000, SamplingMethod::kRandom)) {
    ASSERT_GE(v, 0.4);
    ASSERT_LE(v, 0.45);
  }
}

TEST(Uncertain, LatinHypercubePutsExactlyOneSampleInEveryStratum) {
  Uncertainty u;
  u.parameters = {{UncertainKind::kFriction, Distribution::kUniform, 0.2, 0.8},
                  {UncertainKind::kMassScale, Distribution::kLognormal, 1.0, 0.1},
                  {UncertainKind::kRestitutionRatio, Distribution::kNormal, 0.8, 0.1, 0.0, 1.0}};
  u.sampling = {7, SamplingMethod::kLatinHypercube, SamplingScope::kRun};
  for (const std::size_t n : {1u, 2u, 17u, 1000u}) {
    const SampleDesign d(u, n);
    for (std::size_t k = 0; k < u.parameters.size(); ++k) {
      std::vector<int> hits(n, 0);
      for (std::size_t i = 0; i < n; ++i) {
        const double v = d.uniform(i, k);
        ASSERT_GT(v, 0.0);
        ASSERT_LT(v, 1.0);
        ++hits[static_cast<std::size_t>(v * static_cast<double>(n))];
      }
      EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }))
          << "n " << n << " parameter " << k;
    }
  }
  // the strata of two parameters are not the same permutation
  const SampleDesign d(u, 1000);
  int same = 0;
  for (std::size_t i = 0; i < 1000; ++i) {
    same += static_cast<int>(d.uniform(i, 0) * 1000) == static_cast<int>(d.uniform(i, 1) * 1000);
  }
  EXPECT_LT(same, 10);
}

TEST(Uncertain, LatinHypercubeMeanBeatsRandomDraws) {
  // the stratified mean of a uniform is off by at most (b - a)/(2n): far below random's
  // standard error (b - a)/sqrt(12 n)
  const UncertainParameter p{UncertainKind::kFriction, Distribution::kUniform, 0.0 + 0.2, 1.2};
  const std::size_t n = 400;
  const Moments m = moments(draws(p, n, SamplingMethod::kLatinHypercube));
  EXPECT_NEAR(m.mean, 0.7, 1.0 / (2.0 * n));
}

TEST(Uncertain, ValuesDependOnTheSeedAndTheIndexOnly) {
  Uncertainty u;
  u.parameters = {{UncertainKind::kFriction, Distribution::kLognormal, 0.5, 0.2},
                  {UncertainKind::kSizeScale, Distribution::kUniform, 0.9, 1.1}};
  for (const SamplingMethod method : {SamplingMethod::kRandom, SamplingMethod::kLatinHypercube}) {
    u.sampling = {99, method, SamplingScope::kRun};
    const std::size_t n = 5000;
    const SampleDesign a(u, n), b(u, n);
    std::vector<std::vector<double>> serial(n), threaded(n);
    for (std::size_t i = 0; i < n; ++i) serial[i] = a.values(i);
    // four threads, taking the indices in reverse
    parallel_for(n, 4, [&](std::size_t k) { threaded[n - 1 - k] = b.values(n - 1 - k); });
    EXPECT_EQ(serial, threaded);
    u.sampling.seed = 100;
    const SampleDesign c(u, n);
    EXPECT_NE(c.values(3), serial[3]);
  }
  // the plain random draw of index i does not depend on how many samples there are
  u.sampling = {99, SamplingMethod::kRandom, SamplingScope::kRun};
  EXPECT_EQ(SampleDesign(u, 10).values(7), SampleDesign(u, 10000).values(7));
  // nor on the other parameters after it
  Uncertainty one = u;
  one.parameters.pop_back();
  EXPECT_EQ(SampleDesign(one, 10).values(7)[0], SampleDesign(u, 10).values(7)[0]);
}

TEST(Uncertain, CounterUniformIsOpenAndSpread) {
  double lo = 1.0, hi = 0.0, sum = 0.0;
  const int n = 100'000;
  for (int i = 0; i < n; ++i) {
    const double v = counter_uniform(0, static_cast<std::uint64_t>(i), 0);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
  }
  EXPECT_GT(lo, 0.0);
  EXPECT_LT(hi, 1.0);
  EXPECT_NEAR(sum / n, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NE(counter_uniform(1, 0, 0), counter_uniform(0, 1, 0));
  EXPECT_NE(counter_uniform(0, 1, 0), counter_uniform(0, 0, 1));
}

TEST(Uncertain, BadDistributionsSayWhatIsRight) {
  using test::expect_input_error;
  auto check = [](UncertainParameter p) { validate(p); };
  // a normal friction can be negative: a lower bound is needed
  expect_input_error(
      [&] {
        check({UncertainKind::kFriction, Distribution::kNormal, 0.5, 0.1});
      },
      {"uncertain friction", "must be > 0", "give a lower bound"});
  check({UncertainKind::kFriction, Distribution::kNormal, 0.5, 0.1, 0.05, kInf});
  expect_input_error(
      [&] {
        check({UncertainKind::kFriction, Distribution::kNormal, 0.5, 0.1, 0.0, kInf});
      },
      {"must be > 0"});
  // a lognormal friction is > 0 as it is; a lognormal ratio needs an upper bound of 1
  check({UncertainKind::kFriction, Distribution::kLognormal, 0.5, 0.3});
  expect_input_error(
      [&] {
        check({UncertainKind::kRestitutionRatio, Distribution::kLognormal, 0.8, 0.1});
      },
      {"in [0, 1]", "give an upper bound"});
  expect_input_error(
      [&] {
        check({UncertainKind::kDampingRatio, Distribution::kUniform, 0.0, 1.0});
      },
      {"in [0, 1)", "minimum and maximum"});
  expect_input_error(
      [&] {
        check({UncertainKind::kFriction, Distribution::kUniform, 0.7, 0.3});
      },
      {"minimum < maximum"});
  expect_input_error(
      [&] {
        check({UncertainKind::kFriction, Distribution::kUniform, 0.3, 0.7, 0.4, 0.6});
      },
      {"lower and upper are for normal and lognormal"});
  expect_input_error(
      [&] {
        check({UncertainKind::kSizeScale, Distribution::kNormal, 1.0, 0.0});
      },
      {"standard deviation > 0"});
  expect_input_error(
      [&] {
        check({UncertainKind::kSizeScale, Distribution::kLognormal, -1.0, 0.1});
      },
      {"median > 0"});
  expect_input_error(
      [&] {
        check({UncertainKind::kSizeScale, Distribution::kNormal, 1.0, 0.1, 1.2, 1.1});
      },
      {"lower < upper"});
  // 40 standard deviations out: nothing left to sample
  expect_input_error(
      [&] {
        check({UncertainKind::kSizeScale, Distribution::kNormal, 1.0, 0.01, 1.4, 1.5});
      },
      {"keeps a probability of", "bounds around its bulk"});
  Uncertainty u;
  u.parameters = {{UncertainKind::kMassScale, Distribution::kUniform, 0.9, 1.1},
                  {UncertainKind::kMassScale, Distribution::kUniform, 0.8, 1.2}};
  expect_input_error([&] { validate(u); }, {"mass_scale", "given twice"});
}

TEST(Uncertain, SizeScaleKeepsModesAndSlowsRocking) {
  // Housner's block: p = sqrt(3 g / (4 R)), R the half-diagonal; s times every length: p/sqrt(s)
  Uncertainty u;
  u.parameters = {{UncertainKind::kSizeScale, Distribution::kUniform, 0.5, 3.0}};
  const Body rigid(apply(u, {2.0}, rigid_block(0.5, 2.0, 800.0)));
  const double r = std::hypot(0.5, 2.0);  // half-diagonal of the 1 m x 4 m block
  EXPECT_NEAR(rigid.rocking_frequency(), std::sqrt(3.0 * kStandardGravity / (4.0 * r)), 1e-12);
  EXPECT_NEAR(rigid.alpha1(), 0.25, 1e-15);  // b/h unchanged
  // a flexible body keeps its modal frequencies and its mass
  const BodyParameters tank = oscillator_on_slab(800.0, 3.0, 400.0, 2.0, 1.0, 0.02);
  const Body before(tank), after(apply(u, {1.7}, tank));
  EXPECT_NEAR(after.natural_frequencies()(0), before.natural_frequencies()(0),
              1e-12 * before.natural_frequencies()(0));
  EXPECT_NEAR(after.rocking_frequency(), before.rocking_frequency() / std::sqrt(1.7),
              1e-12 * before.rocking_frequency());
  EXPECT_EQ(after.params().mass, tank.mass);
}

// a rigid body about its pivot: p^2 = M g R / I_O, R the pivot to c.g. distance, I_O = I_cg + M R^2
double pivot_frequency(double mass, double inertia_cg, double b, double h) {
  const double r = std::hypot(b, h);
  return std::sqrt(mass * kStandardGravity * r / (inertia_cg + mass * r * r));
}

TEST(Uncertain, BaseWidthAndCgHeightMoveThePivotAndHoldTheInertia) {
  // a 1 m x 4 m block of 800 kg: I_cg = M (w^2 + H^2) / 12
  const double mass = 800.0, inertia = mass * (1.0 + 16.0) / 12.0;
  const BodyParameters block = rigid_block(1.0, 4.0, mass);
  Uncertainty u;
  u.parameters = {{UncertainKind::kBaseWidthScale, Distribution::kUniform, 0.5, 2.0}};
  const Body wide(apply(u, {1.3}, block));
  EXPECT_NEAR(wide.tipping_angle(1), std::atan(1.3 * 0.5 / 2.0), 1e-14);
  EXPECT_NEAR(wide.rocking_frequency(), pivot_frequency(mass, inertia, 1.3 * 0.5, 2.0), 1e-12);
  u.parameters = {{UncertainKind::kCgHeightScale, Distribution::kUniform, 0.5, 2.0}};
  const Body tall(apply(u, {0.8}, block));
  EXPECT_NEAR(tall.tipping_angle(2), std::atan(0.5 / (0.8 * 2.0)), 1e-14);
  EXPECT_NEAR(tall.rocking_frequency(), pivot_frequency(mass, inertia, 0.5, 0.8 * 2.0), 1e-12);
  // a body with modes: refused, its pinned-base modes are tied to the pivots and the c.g.
  test::expect_input_error(
      [&] { apply(u, {0.8}, oscillator_on_slab(800.0, 3.0, 400.0, 2.0, 1.0, 0.02)); },
      {"cg_height_scale", "has modes (1)", "expected a rigid body"});
}

TEST(Uncertain, MassFrequencyAndDampingActOnTheModes) {
  const BodyParameters tank = oscillator_on_slab(800.0, 3.0, 400.0, 2.0, 1.0, 0.02);
  const Body before(tank);
  const double w = before.natural_frequencies()(0);
  Uncertainty u;
  u.parameters = {{UncertainKind::kMassScale, Distribution::kUniform, 0.5, 2.0}};
  const Body heavier(apply(u, {1.44}, tank));
  EXPECT_NEAR(heavier.natural_frequencies()(0), w / 1.2, 1e-12 * w);
  EXPECT_NEAR(heavier.params().mass, 1.44 * tank.mass, 1e-9);
  EXPECT_NEAR(heavier.damping_ratios()(0), before.damping_ratios()(0), 1e-15);
  u.parameters = {{UncertainKind::kFrequencyScale, Distribution::kUniform, 0.5, 2.0}};
  EXPECT_NEAR(Body(apply(u, {1.3}, tank)).natural_frequencies()(0), 1.3 * w, 1e-12 * w);
  u.parameters = {{UncertainKind::kDampingRatio, Distribution::kUniform, 0.0, 0.1}};
  EXPECT_DOUBLE_EQ(Body(apply(u, {0.07}, tank)).damping_ratios()(0), 0.07);
  // nothing to scale on a rigid body
  test::expect_input_error([&] { apply(u, {0.07}, rigid_block(0.5, 2.0, 800.0)); },
                           {"damping_ratio", "rigid", "expected a body with modes"});
}

TEST(Uncertain, FrictionKeepsTheKineticRatioAndRestitutionSetsBothEdges) {
  Uncertainty u;
  u.parameters = {{UncertainKind::kFriction, Distribution::kUniform, 0.2, 0.8},
                  {UncertainKind::kRestitutionRatio, Distribution::kUniform, 0.5, 1.0}};
  SimulationOptions o;
  o.friction_coefficient = 0.5;
  o.kinetic_friction_coefficient = 0.4;
  apply(u, {0.6, 0.9}, o);
  EXPECT_DOUBLE_EQ(o.friction_coefficient, 0.6);
  EXPECT_DOUBLE_EQ(o.kinetic_friction_coefficient, 0.48);
  EXPECT_EQ(o.restitution_ratio_edge1, 0.9);
  EXPECT_EQ(o.restitution_ratio_edge2, 0.9);
  SimulationOptions none;  // no friction before: the kinetic coefficient equals the static one
  apply(u, {0.3, 0.9}, none);
  EXPECT_EQ(none.friction_coefficient, 0.3);
  EXPECT_TRUE(std::isinf(none.kinetic_friction_coefficient));
}

// a sweep of two bodies, two records, three levels, with sampled friction, size and damping
SweepSpec uncertain_sweep(SamplingScope scope) {
  SweepSpec s;
  s.bodies.push_back({"tank", oscillator_on_slab(800.0, 2.0, 400.0, 2.0, 1.0, 0.02)});
  s.bodies.push_back({"tank2", oscillator_on_slab(600.0, 3.0, 300.0, 1.5, 0.8, 0.0)});
  s.records.push_back({"one_sine", one_sine_pulse(1.0, 5.0, 3.0)});
  std::vector<double> a;
  for (int i = 0; i < 300; ++i) a.push_back(std::sin(0.1 * i) * std::exp(-0.005 * i));
  s.records.push_back({"sampled", GroundMotion::uniform(0.01, a)});
  s.scales = {1.0, 3.0, 5.0};
  s.free_periods = 1.0;
  s.uncertainty.parameters = {
      {UncertainKind::kFriction, Distribution::kLognormal, 0.5, 0.3},
      {UncertainKind::kSizeScale, Distribution::kNormal, 1.0, 0.1, 0.7, 1.3},
      {UncertainKind::kDampingRatio, Distribution::kUniform, 0.0, 0.05}};
  s.uncertainty.sampling = {3, SamplingMethod::kLatinHypercube, scope};
  return s;
}

TEST(UncertainSweep, RowsAreDirectRunsOfTheSampledBodyAndOptions) {
  const SweepSpec s = uncertain_sweep(SamplingScope::kRun);
  ASSERT_TRUE(has_friction(s));  // sampled friction: the rows carry the sliding columns
  const SampleDesign design = sample_design(s);
  EXPECT_EQ(design.samples(), 6u);
  const auto rows = run_sweep(s, {}, {.threads = 2});
  ASSERT_EQ(rows.size(), 12u);
  for (const SweepRow& row : rows) {
    const SweepRun run{row.index, row.body, row.record, row.scale_index};
    // every body meets the realisation of its (record, level)
    EXPECT_EQ(sample_index(s, run), row.record * 3 + row.scale_index);
    ASSERT_EQ(row.sampled, design.values(row.record * 3 + row.scale_index));
    // the same run made by hand: the body scaled and damped, friction in the options
    BodyParameters p = s.bodies[row.body].body;
    p.height *= row.sampled[1];
    p.b1 *= row.sampled[1];
    p.b2 *= row.sampled[1];
    p.kappa *= row.sampled[1];
    p.damping.kind = DampingKind::kModal;
    p.damping.modal_ratios = VectorX::Constant(1, row.sampled[2]);
    const Body body(p);
    SimulationOptions o = s.solver;
    o.friction_coefficient = row.sampled[0];
    o.t_end =
        s.records[row.record].motion.duration() + 2.0 * std::numbers::pi / body.rocking_frequency();
    EXPECT_DOUBLE_EQ(row.duration, o.t_end);
    const SimulationResult r =
        simulate(body, s.records[row.record].motion.scaled(row.scale), {}, o);
    const RunSummary direct = summarize(body, r);
    EXPECT_EQ(row.run.outcome, direct.outcome) << row.index;
    EXPECT_EQ(row.run.max_theta, direct.max_theta) << row.index;
    EXPECT_EQ(row.run.impacts, direct.impacts) << row.index;
  }
  // the rows differ between runs: the fit sees the scatter
  EXPECT_NE(rows[0].sampled, rows[1].sampled);
  EXPECT_EQ(rows[0].sampled, rows[6].sampled);  // body 2, the same (record, level)
}

TEST(UncertainSweep, ThreadsAndRanksChangeNoByte) {
  const SweepSpec s = uncertain_sweep(SamplingScope::kRun);
  std::vector<std::string> one;
  for (const SweepRow& r : run_sweep(s, {}, {.threads = 1})) one.push_back(io::sweep_row(s, r));
  // three threads; two ranks of two threads each, merged by index
  std::vector<std::string> three, ranks(one.size());
  for (const SweepRow& r : run_sweep(s, {}, {.threads = 3})) three.push_back(io::sweep_row(s, r));
  for (int rank = 0; rank < 2; ++rank) {
    for (const SweepRow& r : run_sweep(s, {}, {.threads = 2, .rank = rank, .ranks = 2})) {
      ranks[r.index] = io::sweep_row(s, r);
    }
  }
  EXPECT_EQ(one, three);
  EXPECT_EQ(one, ranks);
  // a single run alone gives its row too
  EXPECT_EQ(io::sweep_row(s, run_sweep_one(s, sweep_runs(s)[7])), one[7]);
}

TEST(UncertainSweep, RecordScopeSharesARealisationAcrossLevels) {
  const SweepSpec s = uncertain_sweep(SamplingScope::kRecord);
  const auto rows = run_sweep(s, {}, {.threads = 2});
  for (const SweepRow& r : rows) EXPECT_EQ(r.sampled, rows[r.record * 3].sampled);
  EXPECT_NE(rows[0].sampled, rows[3].sampled);
}

TEST(UncertainSweep, JournalRefusesAnotherSample) {
  const SweepSpec s = uncertain_sweep(SamplingScope::kRun);
  const auto rows = run_sweep(s, {2}, {.threads = 1});
  ASSERT_EQ(rows.size(), 1u);
  const std::string line = io::sweep_row(s, rows[0]);
  const io::JournalCheck check = io::sweep_journal_check(s);
  EXPECT_EQ(check(2, line), "");
  // the friction field of another draw: not this run's
  const std::string friction = format_number(rows[0].sampled[0]);
  std::string other = line;
  other.replace(other.find(friction), friction.size(), "0.5");
  EXPECT_NE(check(2, other).find("first fields are not those of run 2"), std::string::npos);
  // the columns: the sampled values after the intensity measures, before the duration
  const std::vector<std::string> cols = io::sweep_columns(s);
  const auto at = [&](const char* c) {
    return std::find(cols.begin(), cols.end(), c) - cols.begin();
  };
  EXPECT_EQ(at("friction_coefficient"), at("pgv_m_per_s") + 1);
  EXPECT_EQ(at("size_scale"), at("pgv_m_per_s") + 2);
  EXPECT_EQ(at("damping_ratio"), at("duration_s") - 1);
}

TEST(UncertainSweep, ARigidBodyRefusesModalParameters) {
  SweepSpec s = uncertain_sweep(SamplingScope::kRun);
  s.bodies.push_back({"block", rigid_block(0.4, 2.0, 1000.0)});
  test::expect_input_error([&] { validate(s); },
                           {"body 'block'", "sampled body", "damping_ratio", "rigid"});
  s.bodies.pop_back();
  s.uncertainty.parameters.push_back(
      {UncertainKind::kRestitutionRatio, Distribution::kUniform, 0.5, 0.9});
  test::expect_input_error([&] { validate(s); },
                           {"restitution_ratio", "impact_law = \"restitution\""});
}

}  // namespace
}  // namespace flexrock::study
