// SPDX-License-Identifier: BSD-3-Clause
// Two horizontal components H1, H2 (H2 90 degrees from H1) seen along a direction: the plane of a
// planar body at azimuth beta, measured from H1 toward H2, receives a(t) = H1(t) cos(beta) +
// H2(t) sin(beta) (docs/theory.md, "Two horizontal components").
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "flexrock/core/error.hpp"

namespace flexrock {

/// c = cos(beta), s = sin(beta) for `beta_deg` in degrees, with the symmetries of the circle
/// exact: the angle is reduced to [0, 45] degrees before libm is called, so multiples of 90
/// degrees give 0 and +-1 exactly, cos(beta) is bitwise sin(90 - beta) and cos(beta + 180) is
/// bitwise -cos(beta). Swapping H1 and H2 (beta -> 90 - beta) or turning the body round (beta
/// -> beta + 180: the record's sign) then gives exactly the same projected record, or its
/// negative.
inline void direction_cosines(double beta_deg, double& c, double& s) {
  double d = std::fmod(beta_deg, 360.0);
  if (d < 0.0) d += 360.0;
  const int quadrant = static_cast<int>(d / 90.0) % 4;
  const double r = d - 90.0 * quadrant;  // [0, 90)
  constexpr double kDeg = std::numbers::pi / 180.0;
  // (c0, s0) = (cos r, sin r), from the angle nearer zero
  double c0 = 0.0, s0 = 0.0;
  if (r == 45.0) {
    // libm's cos and sin of 45 degrees may differ in the last bit: one value for both
    c0 = s0 = std::sqrt(0.5);
  } else if (r < 45.0) {
    c0 = r == 0.0 ? 1.0 : std::cos(r * kDeg);
    s0 = r == 0.0 ? 0.0 : std::sin(r * kDeg);
  } else {
    const double q = 90.0 - r;
    c0 = std::sin(q * kDeg);
    s0 = std::cos(q * kDeg);
  }
  switch (quadrant) {
    case 0:
      c = c0, s = s0;
      break;
    case 1:
      c = -s0, s = c0;
      break;
    case 2:
      c = -c0, s = -s0;
      break;
    default:
      c = s0, s = -c0;
      break;
  }
}

/// The component along azimuth `beta_deg` [deg] of the pair (h1, h2): h1 cos(beta) + h2
/// sin(beta), sample by sample [units of h1, h2]. Throws InputError when the lengths differ.
inline std::vector<double> project_horizontal(const std::vector<double>& h1,
                                              const std::vector<double>& h2, double beta_deg) {
  FLEXROCK_THROW_UNLESS(h1.size() == h2.size(),
                        "horizontal pair: the two components must have the same samples, got " +
                            std::to_string(h1.size()) + " and " + std::to_string(h2.size()));
  double c = 0.0, s = 0.0;
  direction_cosines(beta_deg, c, s);
  std::vector<double> a(h1.size());
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = c * h1[i] + s * h2[i];
  return a;
}

}  // namespace flexrock
