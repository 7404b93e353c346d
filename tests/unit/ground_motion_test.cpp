// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/excitation/ground_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace flexrock {
namespace {

TEST(GroundMotion, ScaledRecordScalesItsSamples) {
  const auto m = GroundMotion::uniform(0.01, {0.0, 1.0, -2.0}, {0.5, 0.0, 0.25}).scaled(3.0);
  EXPECT_EQ(m.horizontal(), (std::vector<double>{0.0, 3.0, -6.0}));
  EXPECT_EQ(m.vertical(), (std::vector<double>{1.5, 0.0, 0.75}));
  EXPECT_DOUBLE_EQ(m.at(0.015).x, -1.5);
  const auto f = GroundMotion::analytic([](double t) { return BaseAcceleration{t, -t}; }, 1.0);
  EXPECT_DOUBLE_EQ(f.scaled(2.0).at(0.5).y, -1.0);
}

TEST(GroundMotion, UnevenRecordAnswersInAnyOrder) {
  // linear between samples whether the cursor walks forward, jumps, or is new
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> t{0.0}, a{0.0};
  for (int i = 0; i < 500; ++i) {
    t.push_back(t.back() + 0.001 + 0.01 * u(rng));
    a.push_back(2 * u(rng) - 1);
  }
  const auto m = GroundMotion::sampled(t, a);
  GroundMotion::Cursor walking;
  for (int k = 0; k < 2000; ++k) {
    const double tq = t.back() * u(rng);
    const std::size_t i =
        static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), tq) - t.begin() - 1);
    const double want = a[i] + (tq - t[i]) / (t[i + 1] - t[i]) * (a[i + 1] - a[i]);
    EXPECT_NEAR(m.at(tq, walking).x, want, 1e-14);
    EXPECT_NEAR(m.at(tq).x, want, 1e-14);
  }
}

// A cursor keeps the interval it last found; what at() answers must still depend on the time
// alone: the sample itself at a sample time, from whichever side the cursor comes, and the same
// bits from a walking cursor as from a fresh one
TEST(GroundMotion, CursorAnswersDependOnTheTimeAlone) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> a, b, t{0.0};
  for (int i = 0; i < 200; ++i) {
    a.push_back(2 * u(rng) - 1);
    b.push_back(2 * u(rng) - 1);
    if (i > 0) t.push_back(t.back() + 0.002 + 0.01 * u(rng));
  }
  for (const GroundMotion& m :
       {GroundMotion::uniform(0.01, a, b, 0.5), GroundMotion::sampled(t, a, b)}) {
    const std::vector<double>& ts = m.times();
    GroundMotion::Cursor walking;
    auto same = [&](double tq) {
      const BaseAcceleration w = m.at(tq, walking), f = m.at(tq);
      EXPECT_EQ(w.x, f.x) << tq;
      EXPECT_EQ(w.y, f.y) << tq;
      return w;
    };
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      // the interval's interior, its end (from inside), its start again (from the next one)
      const double mid = ts[k] + 0.37 * (ts[k + 1] - ts[k]);
      const BaseAcceleration v = same(mid);
      const double w = (mid - ts[k]) / (ts[k + 1] - ts[k]);
      EXPECT_NEAR(v.x, a[k] + w * (a[k + 1] - a[k]), 1e-14);
      EXPECT_NEAR(v.y, b[k] + w * (b[k + 1] - b[k]), 1e-14);
      EXPECT_EQ(same(ts[k + 1]).x, a[k + 1]);
      same(ts[k + 1] + 0.5 * (ts[std::min(k + 2, ts.size() - 1)] - ts[k + 1]));
      EXPECT_EQ(same(ts[k]).x, a[k]);
      EXPECT_EQ(same(ts[k]).y, b[k]);
    }
    // jumps in any order, and the record's outside (zero)
    for (int j = 0; j < 500; ++j) same(ts.front() - 0.1 + (ts.back() - ts.front() + 0.2) * u(rng));
    EXPECT_EQ(same(ts.back()).x, a.back());
    EXPECT_EQ(same(std::nextafter(ts.back(), 1e9)).x, 0.0);
    EXPECT_EQ(same(std::nextafter(ts.front(), -1e9)).y, 0.0);
  }
}

// A uniform record's lookup takes the interval from the quotient (t - t0)/dt, which may round
// across a sample: one ulp below a sample it can give the next interval, at a sample the one
// before. The fix-ups move it onto the interval the samples' own times give, t0 <= t < t1. The
// first one's loss would not go unseen (the cursor would not cover t, and the lookup would repeat
// itself); the second one's would: [t_(k-1), t_k] covers t_k at its end. This test fails without
// it.
TEST(GroundMotion, UniformLookupKeepsTheIntervalTheSampleTimesGive) {
  std::vector<double> a;
  for (int i = 0; i < 2001; ++i) a.push_back(std::sin(0.37 * i));
  int below = 0, at = 0;  // quotients that rounded across the sample, either way
  for (double t0 : {0.0, 0.5, 3.7}) {
    for (double dt : {0.01, 0.005, 0.02, 1.0 / 3.0}) {
      const GroundMotion m = GroundMotion::uniform(dt, a, {}, t0);
      const std::vector<double>& ts = m.times();
      for (std::size_t k = 1; k + 1 < ts.size(); ++k) {
        for (const double tq : {std::nextafter(ts[k], -1e9), ts[k]}) {
          GroundMotion::Cursor c;
          m.at(tq, c);
          const std::size_t i = tq < ts[k] ? k - 1 : k;  // the interval holding tq
          ASSERT_EQ(c.t0, ts[i]) << "t0 " << t0 << " dt " << dt << " k " << k;
          ASSERT_EQ(c.t1, ts[i + 1]) << "t0 " << t0 << " dt " << dt << " k " << k;
          const auto s = static_cast<std::size_t>((tq - ts.front()) / dt);
          if (tq < ts[k] && s == k) ++below;
          if (tq == ts[k] && s == k - 1) ++at;
        }
      }
    }
  }
  // the cases the fix-ups are for do occur here
  EXPECT_GT(below, 0);
  EXPECT_GT(at, 0);
}

}  // namespace
}  // namespace flexrock
