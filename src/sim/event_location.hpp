// SPDX-License-Identifier: BSD-3-Clause
// Event location on a step: the guard functions sampled across it, brackets of their first
// crossing, and the crossing time refined by TOMS 748 on the stepper's dense output. Ordinary
// code, the same for every body size: the stepper is reached through GuardProbe. Internal header.
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include "automaton.hpp"

namespace flexrock::detail {

inline constexpr int kMaxSamples = 32;

/// The guard functions of the current mode at one time, in the mode's slot order, with the floor
/// reaction that the extremes need.
struct GuardSample {
  double t = 0.0;                      // [s]
  std::array<double, kMaxGuards> v{};  // guard values, slot order
  double fi = 0.0, fj = 0.0;           // floor reaction over M g, inertial I and J
  double moment = 0.0;                 // overturning moment about the c.g. projection, over M g h
};

class GuardProbe;

/// The crossing in [tl, tr] (gl > 0 >= gr) to 2e-15 relative in time: the side where g <= 0.
double locate_crossing(int slot, double tl, double tr, double gl, double gr, GuardProbe& probe);

/// The same for the polynomial g(t) = sign * sum_k c[k] (t - t0)^k, k = 0..degree, with
/// dc[k] = k c[k] (k = 1..degree; its derivative's, formed once by the caller), evaluated by
/// Horner's rule as the stepper's dense output evaluates it (so the sign at the returned time is
/// the sign guard_value gives; gl and gr are its values at tl and tr): Newton's method kept inside
/// the bracket, then the first time past the root, by ulps, where g <= 0.
double polynomial_crossing(const double* c, const double* dc, int degree, double sign, double t0,
                           double tl, double tr, double gl, double gr);

/// The guard values at any time within the last step (from its dense output), and the crossing of
/// one in a bracket: by default TOMS 748 on guard_value; a stepper whose guard is a polynomial on
/// the step (the rocking series) finds the root on the polynomial instead.
class GuardProbe {
 public:
  virtual double guard_value(int slot, double t) = 0;
  virtual double crossing(int slot, double tl, double tr, double gl, double gr) {
    return locate_crossing(slot, tl, tr, gl, gr, *this);
  }

 protected:
  ~GuardProbe() = default;
};

/// Time of the first crossing of `slot` from positive to non-positive among smp[0..count]
/// (+infinity if none). A guard that starts at exactly zero (`zero_start`: it is known to turn
/// positive, e.g. the impact function right after an uplift) is treated as positive at the start;
/// if no positive point is found by halving toward the start, it fires at the start when
/// `fires_if_unresolved`, else never in this step. Between three positive samples whose parabola
/// dips below a quarter of the smaller end value, the vertex is probed too.
// inline: the loop calls it for every guard after every step, and the scan is a few comparisons
inline double first_crossing(int slot, const GuardSample* smp, int count, bool zero_start,
                             bool fires_if_unresolved, GuardProbe& probe) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const auto j = static_cast<std::size_t>(slot);
  double prev = smp[0].v[j];
  double t_prev = smp[0].t;
  bool armed = prev > 0.0 || zero_start;
  for (int k = 1; k <= count; ++k) {
    const double cur = smp[k].v[j];
    if (armed && cur <= 0.0) {
      double tl = t_prev, gl = prev;
      if (!(gl > 0.0)) {
        // a guard that starts at zero: find a point inside where it is positive
        bool found = false;
        double span = smp[k].t - t_prev;
        for (int i = 1; i <= 60 && !found; ++i) {
          span *= 0.5;
          tl = t_prev + span;
          gl = probe.guard_value(slot, tl);
          found = gl > 0.0;
        }
        // the excursion is below resolution
        if (!found) return fires_if_unresolved ? t_prev : kInf;
      }
      return probe.crossing(slot, tl, smp[k].t, gl, cur);
    }
    // a dip between samples: parabola through three positive values with a vertex below zero
    if (armed && k + 1 <= count && cur > 0.0 && prev > 0.0 && smp[k + 1].v[j] > 0.0) {
      const double g0 = prev, g1 = cur, g2 = smp[k + 1].v[j];
      const double curv = g0 - 2.0 * g1 + g2;
      if (curv > 0.0) {
        const double u = 0.5 * (g0 - g2) / curv;  // vertex, in sample spacings from sample k
        const double gmin = g1 - 0.25 * (g0 - g2) * u;
        if (u > -1.0 && u < 1.0 && gmin < 0.25 * std::min(g0, g2)) {
          const double tv = smp[k].t + u * (smp[k + 1].t - smp[k].t);
          const double gv = probe.guard_value(slot, tv);
          if (gv <= 0.0) {
            const double tl = u > 0 ? smp[k].t : smp[k - 1].t;
            const double gl = u > 0 ? g1 : g0;
            return probe.crossing(slot, tl, tv, gl, gv);
          }
        }
      }
    }
    if (cur > 0.0) armed = true;
    prev = cur;
    t_prev = smp[k].t;
  }
  return kInf;
}

}  // namespace flexrock::detail
