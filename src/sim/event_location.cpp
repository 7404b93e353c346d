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

}  // namespace flexrock::detail
