// SPDX-License-Identifier: BSD-3-Clause
#include "event_location.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace flexrock::detail {

double locate_crossing(int slot, double tl, double tr, double gl, double gr, GuardProbe& probe) {
  auto g = [&](double tt) { return probe.guard_value(slot, tt); };
  auto tol = [](double a, double b) {
    return std::abs(b - a) <= 2e-15 * std::max(1.0, std::abs(a));
  };
  std::uintmax_t iters = 100;
  const auto r = boost::math::tools::toms748_solve(g, tl, tr, gl, gr, tol, iters);
  return r.second;  // the side where the function is <= 0
}

double first_crossing(int slot, const GuardSample* smp, int count, bool zero_start,
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
      return locate_crossing(slot, tl, smp[k].t, gl, cur, probe);
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
            return locate_crossing(slot, tl, tv, gl, gv, probe);
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
