// SPDX-License-Identifier: BSD-3-Clause
// sin and cos of one angle at once, fast where a rocking body's angle lives.
#pragma once

#include <cmath>
#include <numbers>

namespace flexrock {

namespace detail {
// outside sin_cos's range: libm, out of line so that the polynomial path stays small enough to be
// inlined at its callers (called once per right-hand side)
[[gnu::cold, gnu::noinline]] inline void sin_cos_libm(double x, double& s, double& c) {
  s = std::sin(x);
  c = std::cos(x);
}
}  // namespace detail

/// s = sin(x), c = cos(x). For |x| <= pi/4 (rocking angles are well inside) by their Taylor
/// polynomials in z = x^2, to within about an ulp of the libm values; elsewhere by libm. The
/// rocking right-hand side and the guard samples need both at every call, and libm's sincos
/// (about 95 instructions with its range reduction and dispatch) was 7 % of a flexible run.
/// Truncation: sin stops after x^15, whose remainder x^17/17! < 6e-17 |x| on the range; cos
/// after x^16, remainder x^18/18! < 3e-18.
inline void sin_cos(double x, double& s, double& c) {
  constexpr double kQuarterPi = std::numbers::pi / 4.0;
  if (!(std::abs(x) <= kQuarterPi)) [[unlikely]] {
    detail::sin_cos_libm(x, s, c);
    return;
  }
  const double z = x * x, z2 = z * z, z4 = z2 * z2;
  // 1/k! for the odd (sin) and even (cos) powers in z, grouped in pairs (Estrin's scheme: the
  // pairs are independent, so the chain of dependent products is four long, not seven); the
  // leading terms are added last, exactly as x and 1 - z/2, so the rounding of the small rest
  // stays below an ulp
  const double ps =
      (-1.0 / 6.0 + z * (1.0 / 120.0)) + z2 * (-1.0 / 5040.0 + z * (1.0 / 362880.0)) +
      z4 * ((-1.0 / 39916800.0 + z * (1.0 / 6227020800.0)) + z2 * (-1.0 / 1307674368000.0));
  const double pc =
      (1.0 / 24.0 + z * (-1.0 / 720.0)) + z2 * (1.0 / 40320.0 + z * (-1.0 / 3628800.0)) +
      z4 * ((1.0 / 479001600.0 + z * (-1.0 / 87178291200.0)) + z2 * (1.0 / 20922789888000.0));
  s = x + x * (z * ps);
  const double half = 0.5 * z;
  c = (1.0 - half) + ((1.0 - (1.0 - half)) - half) + z * (z * pc);
}

}  // namespace flexrock
