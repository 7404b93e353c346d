// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/core/sin_cos.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace flexrock {
namespace {

// distance in units in the last place of the larger
double ulps(double got, double want) {
  const double unit = std::numeric_limits<double>::epsilon() *
                      std::max(std::abs(want), std::numeric_limits<double>::min());
  return std::abs(got - want) / unit;
}

// The polynomials against libm over their range, densely near zero and near pi/4, and libm's
// own values beyond it
TEST(SinCos, WithinAnUlpOfLibm) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst_s = 0.0, worst_c = 0.0;
  for (int k = 0; k < 200000; ++k) {
    const double scale =
        k % 4 == 0 ? 0.78539816339744830962 : std::pow(10.0, -8.0 * std::abs(u(rng)));
    const double x = scale * u(rng);
    double s = 0.0, c = 0.0;
    sin_cos(x, s, c);
    worst_s = std::max(worst_s, ulps(s, std::sin(x)));
    worst_c = std::max(worst_c, ulps(c, std::cos(x)));
  }
  EXPECT_LE(worst_s, 1.0);
  EXPECT_LE(worst_c, 1.0);
  for (double x : {0.0, -0.0, 0.78539816339744830962, -0.78539816339744830962, 0.8, -2.5, 40.0}) {
    double s = 1.0, c = 1.0;
    sin_cos(x, s, c);
    EXPECT_LE(ulps(s, std::sin(x)), 1.0) << x;
    EXPECT_LE(ulps(c, std::cos(x)), 1.0) << x;
  }
  double s = 0.0, c = 0.0;
  sin_cos(std::numeric_limits<double>::quiet_NaN(), s, c);
  EXPECT_TRUE(std::isnan(s) && std::isnan(c));
}

}  // namespace
}  // namespace flexrock
