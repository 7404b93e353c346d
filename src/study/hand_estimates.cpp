// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/hand_estimates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "flexrock/core/error.hpp"

namespace flexrock::study {

RockingConstants rocking_constants(const BodyParameters& body, int edge) {
  FLEXROCK_THROW_UNLESS(edge == 1 || edge == 2, "rocking_constants: edge must be 1 or 2");
  const double b = edge == 1 ? body.b1 : body.b2;
  const double h = body.height, M = body.mass;
  RockingConstants c;
  c.R = std::hypot(b, h);
  c.alpha = std::atan2(b, h);
  c.I_O = body.zeta2 * M * h * h + M * c.R * c.R;
  c.p = std::sqrt(M * body.gravity * c.R / c.I_O);
  return c;
}

double uplift_threshold(const BodyParameters& body, int edge) {
  return body.gravity * (edge == 1 ? body.b1 : body.b2) / body.height;
}

double sliding_threshold(double mu_s, double g) { return mu_s * g; }

double housner_rectangular_min_amplitude(const RockingConstants& c, double g, double t1) {
  // phi = theta - alpha + a/g grows as (a/g - alpha) cosh(p t) during the pulse; the free motion
  // after it crosses theta = alpha iff (a/g - alpha) e^(p t1) > a/g
  return g * c.alpha / (-std::expm1(-c.p * t1));
}

double housner_rectangular_min_duration(const RockingConstants& c, double g, double a) {
  if (!(a > g * c.alpha)) return std::numeric_limits<double>::infinity();
  return -std::log1p(-g * c.alpha / a) / c.p;
}

double housner_critical_velocity(const RockingConstants& c, double mass, double height, double g) {
  // (M h V)^2 / (2 I_O) = M g R (1 - cos alpha)
  const double barrier = mass * g * c.R * (1.0 - std::cos(c.alpha));
  return std::sqrt(2.0 * barrier * c.I_O) / (mass * height);
}

double newmark_rectangular_displacement(double A, double t1, double mu, double g) {
  if (!(A > mu * g)) return 0.0;
  // slides t1 A/(mu g): (A - mu g) t1^2/2 during the pulse, (A - mu g)^2 t1^2/(2 mu g) after
  return A * (A - mu * g) * t1 * t1 / (2.0 * mu * g);
}

namespace {

double sgn(double x) { return x < 0.0 ? -1.0 : 1.0; }

// smallest root x in (0, xmax] of v - B x - s x^2 / 2, or +inf
double first_stop(double v, double B, double s, double xmax) {
  double best = std::numeric_limits<double>::infinity();
  auto take = [&](double x) {
    if (x > 0.0 && x <= xmax && x < best) best = x;
  };
  if (v == 0.0) {
    // q = -x (B + s x / 2): the root at 0 is where sliding starts
    if (s != 0.0) take(-2.0 * B / s);
    return best;
  }
  if (s == 0.0) {
    if (B != 0.0) take(v / B);
    return best;
  }
  // a x^2 + b x + c with a = -s/2, b = -B, c = v (the cancellation-free pair of roots)
  const double a = -0.5 * s, b = -B, c = v;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return best;
  const double q = -0.5 * (b + sgn(b) * std::sqrt(disc));
  if (q != 0.0) {
    take(q / a);
    take(c / q);
  }
  return best;
}

}  // namespace

NewmarkResult newmark_sliding(std::span<const double> t, std::span<const double> a, double mu_s,
                              double mu_k, double g) {
  FLEXROCK_THROW_UNLESS(t.size() == a.size() && t.size() >= 2,
                        "newmark_sliding: expected as many times as accelerations, at least 2");
  FLEXROCK_THROW_UNLESS(mu_s > 0.0 && mu_k > 0.0 && mu_k <= mu_s,
                        "newmark_sliding: expected 0 < mu_k <= mu_s");
  NewmarkResult r;
  const double hold = mu_s * g, kin = mu_k * g;
  bool stuck = true;
  double sigma = 0.0, v = 0.0, d = 0.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i];
    FLEXROCK_THROW_UNLESS(h >= 0.0, "newmark_sliding: times must not decrease");
    if (h == 0.0) continue;  // a jump: the next segment starts from the new value
    const double a0 = a[i], s = (a[i + 1] - a[i]) / h;
    double tau = 0.0;
    while (tau < h) {
      const double a_tau = a0 + s * tau;
      if (stuck) {
        // the first time in [tau, h] where |a| reaches the static limit
        double start = std::numeric_limits<double>::infinity(), target = 0.0;
        if (std::abs(a_tau) > hold) {
          start = tau;
          target = a_tau;
        } else if (s != 0.0) {
          for (double T : {hold, -hold}) {
            const double u = (T - a0) / s;
            if (u >= tau && u < h && s * T > 0.0 && u < start) {
              start = u;
              target = T;
            }
          }
        }
        if (!std::isfinite(start)) break;
        tau = start;
        stuck = false;
        sigma = -sgn(target);
        v = 0.0;
        ++r.slips;
        continue;
      }
      // sliding along sigma: v' = -a - sigma mu_k g until v returns to zero
      const double B = a_tau + sigma * kin;
      const double stop = first_stop(v, B, s, h - tau);
      const bool stops = std::isfinite(stop);
      const double x = stops ? stop : h - tau;
      d += v * x - 0.5 * B * x * x - s * x * x * x / 6.0;
      r.sliding_time += x;
      r.max_offset = std::max(r.max_offset, std::abs(d));
      v = stops ? 0.0 : v - B * x - 0.5 * s * x * x;
      tau += x;
      if (stops) {
        const double a_stop = a0 + s * tau;
        if (std::abs(a_stop) <= hold) {
          stuck = true;
        } else {
          sigma = -sgn(a_stop);  // friction cannot hold: it slides the other way
          ++r.slips;
        }
      }
    }
  }
  r.final_offset = d;
  return r;
}

}  // namespace flexrock::study
