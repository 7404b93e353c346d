// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/excitation/ground_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

}  // namespace
}  // namespace flexrock
