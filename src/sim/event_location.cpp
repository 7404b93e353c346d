// SPDX-License-Identifier: BSD-3-Clause
#include "event_location.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "crossing_resolution.hpp"

namespace flexrock::detail {

double locate_crossing(int slot, double tl, double tr, double gl, double gr, GuardProbe& probe) {
  auto g = [&](double tt) { return probe.guard_value(slot, tt); };
  auto tol = [](double a, double b) { return std::abs(b - a) <= crossing_resolution(a); };
  std::uintmax_t iters = 100;
  const auto r = boost::math::tools::toms748_solve(g, tl, tr, gl, gr, tol, iters);
  return r.second;  // the side where the function is <= 0
}

// Newton rather than TOMS 748 on the dense output: the polynomial and its derivative cost one
// Horner pass each, where every TOMS 748 probe rebuilt the state and all guards of the mode
double polynomial_crossing(const double* c, const double* dc, int degree, double sign, double t0,
                           double tl, double tr, double gl, double gr) {
  auto g = [&](double t) {
    const double tau = t - t0;
    double v = c[degree];
    for (int k = degree - 1; k >= 0; --k) v = v * tau + c[k];
    return sign * v;
  };
  auto dg = [&](double t) {
    const double tau = t - t0;
    double v = dc[degree];
    for (int k = degree - 1; k >= 1; --k) v = v * tau + dc[k];
    return sign * v;
  };
  double a = tl, b = tr;                    // g(a) > 0 >= g(b) throughout
  double t = a + (b - a) * gl / (gl - gr);  // a secant start
  for (int it = 0; it < 100; ++it) {
    const double v = g(t);
    (v > 0.0 ? a : b) = t;
    const double tn = t - v / dg(t);
    const double tol = 1e-15 * std::max(1.0, std::abs(t));
    // converged: the step is below rounding (it may then fall on the bracket's end)
    if (std::abs(tn - t) <= tol) {
      t = tn;
      break;
    }
    if (b - a <= 2.0 * tol) break;
    t = tn > a && tn < b ? tn : 0.5 * (a + b);  // Newton while it stays inside, else halve
  }
  // the first representable time at or past the root where g <= 0
  t = std::clamp(t, a, b);
  if (g(t) <= 0.0) {
    for (int k = 0; k < 16; ++k) {
      const double before = std::nextafter(t, a);
      if (before <= a || g(before) > 0.0) break;
      t = before;
    }
    return t;
  }
  for (int k = 0; k < 16 && t < b; ++k, t = std::nextafter(t, b)) {
    if (g(t) <= 0.0) return t;
    a = t;
  }
  // not within 16 ulps (a root Newton did not close in on): halve the rest of the bracket
  for (int it = 0; it < 200 && b - a > 2e-15 * std::max(1.0, std::abs(a)); ++it) {
    const double m = 0.5 * (a + b);
    (g(m) > 0.0 ? a : b) = m;
  }
  return b;
}

}  // namespace flexrock::detail
