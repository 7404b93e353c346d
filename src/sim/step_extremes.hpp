// SPDX-License-Identifier: BSD-3-Clause
// The extremes of a stepped motion between the points a step observed (its samples and the state
// just before an event): located, not sampled (docs/theory.md, "Extremes between samples"). One
// routine for every stepper that samples its guards: the impulsive model's loop and the compliant
// contact's. Internal header.
#pragma once

#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace flexrock::detail {

/// Quantities whose largest values a run reports (|u_j|, |F_I|, a contact force, a height) peak
/// between a step's observed points t[0] < ... < t[points - 1] (vals[p] their values at t[p], an
/// Eigen array each; extreme the largest of each before this step's searches, in the same units):
/// the parabola through three neighbours (the divided differences f01, f012) has its vertex in the
/// part of the step nearest the middle one (the first and last triples reach the step's ends), and
/// where that vertex lies above the extreme, Brent's search over the triple's span (20 bits of it)
/// on `quantity(k, t)` finds the peak of quantity k, and `visit(t)` observes it (every quantity
/// folded there). Sampled alone, a quantity misses about (h w / S)^2 / 8 of its peak for a motion
/// of w on a step h with S samples. Over equally spaced points every quantity is tested at once
/// and with no division; only a triple where one could peak goes to the parabolas. Against the
/// extreme before the step's searches: a point another quantity's search observed does not locate
/// this one's peak.
template <class Values, class Quantity, class Visit>
void locate_peaks_between(const double* t, const Values* vals, int points, const Values& extreme,
                          Quantity&& quantity, Visit&& visit) {
  if (points < 3) return;
  const auto last = static_cast<std::size_t>(points - 1);
  const auto count = static_cast<int>(extreme.size());
  // the samples are equally spaced (d); the last point may be the event's, closer
  const double d = t[1] - t[0];
  const bool even = std::abs((t[last] - t[last - 1]) - d) <= 1e-9 * d;
  for (std::size_t c = 1; c < last; ++c) {
    const double from = c == 1 ? -1.0 : -0.5, to = c + 1 == last ? 1.0 : 0.5;
    if (even) {
      // every quantity at once, with no division: with d2 = y0 - 2 y1 + y2 < 0 the vertex is at
      // s = (y0 - y2) / (2 d2) spacings from the middle point, within [from, to], and lies
      // y1 - (y2 - y0)^2 / (8 d2) high, above the extreme E: each condition a negative number
      const Values &y0 = vals[c - 1], &y1 = vals[c], &y2 = vals[c + 1];
      const auto d2 = y0 - 2.0 * y1 + y2;
      const auto slope = y0 - y2;
      const auto concave_peak = d2.max(slope - 2.0 * from * d2).max(2.0 * to * d2 - slope);
      if (!(concave_peak.max(8.0 * d2 * (y1 - extreme) - slope.square()).minCoeff() < 0.0))
        continue;
    }
    // the parabola of each quantity by divided differences, for one that peaks above its extreme
    const double x0 = t[c - 1], x1 = t[c], x2 = t[c + 1];
    if (!(x0 < x1 && x1 < x2)) continue;
    for (int k = 0; k < count; ++k) {
      const double y0 = vals[c - 1](k), y1 = vals[c](k), y2 = vals[c + 1](k);
      const double f01 = (y1 - y0) / (x1 - x0);
      const double f012 = ((y2 - y1) / (x2 - x1) - f01) / (x2 - x0);
      if (!(f012 < 0.0)) continue;  // no peak inside
      const double xv = 0.5 * (x0 + x1) - 0.5 * f01 / f012;
      const double lo = c == 1 ? x0 : 0.5 * (x0 + x1), hi = c + 1 == last ? x2 : 0.5 * (x1 + x2);
      if (!(xv >= lo && xv <= hi)) continue;
      if (!(y0 + (f01 + f012 * (xv - x1)) * (xv - x0) > extreme(k))) continue;
      // over u in [0, 1] on the triple's span: Brent's tolerance is relative to u
      std::uintmax_t iterations = 40;
      const double w = x2 - x0;
      const double u =
          boost::math::tools::brent_find_minima(
              [&](double uu) { return -quantity(k, x0 + w * uu); }, 0.0, 1.0, 20, iterations)
              .first;
      visit(x0 + w * u);
    }
  }
}

/// A switch inside a step puts a quantity's peak at it, where no parabola finds it (a friction
/// demand that counts only while the floor presses enough, a force clipped at zero): between a and
/// b, where `pressing(t)` holds at a if `pressing_at_a` and at b if not, the switch by 40
/// halvings, returned on the pressing side.
template <class Pressing>
double bisect_switch(double a, double b, bool pressing_at_a, Pressing&& pressing) {
  double press = pressing_at_a ? a : b, other = pressing_at_a ? b : a;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (press + other);
    (pressing(mid) ? press : other) = mid;
  }
  return press;
}

/// The time within [t[0], t[points - 1]] where f < 0, from f's values fv at the points: between
/// two points of opposite signs the sign change by bisect_switch on `f(t)`. A dip below zero
/// between two points where f >= 0 is not seen: the points must resolve f, as the guards' do (the
/// floor's pull on a held pivot, whose end the lift-off guard's samples bracket).
template <class F>
double time_negative(const double* t, const double* fv, int points, F&& f) {
  double sum = 0.0;
  for (int p = 1; p < points; ++p) {
    const double a = t[p - 1], b = t[p];
    const bool na = fv[p - 1] < 0.0, nb = fv[p] < 0.0;
    if (na && nb) {
      sum += b - a;
    } else if (na != nb) {
      const double c = bisect_switch(a, b, na, [&](double tt) { return f(tt) < 0.0; });
      sum += na ? c - a : b - c;
    }
  }
  return sum;
}

}  // namespace flexrock::detail
