// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/excitation/intensity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/excitation/azimuth.hpp"

namespace flexrock {

namespace {

void require_record(const std::vector<double>& t, const std::vector<double>& a) {
  FLEXROCK_THROW_UNLESS(t.size() == a.size() && t.size() >= 2,
                        "record intensity: expected as many times as values, at least 2, got " +
                            std::to_string(t.size()) + " times and " + std::to_string(a.size()) +
                            " values");
}

// one exact step of the oscillator over h with a going linearly from a0 to a1
struct Step {
  double u11, u12, v21, v22;  // free vibration: [u; v](h) = [[u11 u12]; [v21 v22]] [u; v](0)
  double g0u, g1u, g0v, g1v;  // forced, from rest: [u; v](h) += [g0u g1u; g0v g1v] [f0; f1]
  double omega, zeta;
  bool series;  // w h <= 1: the coefficients from their power series in w h

  Step(double h, double w, double z) : omega(w), zeta(z), series(w * h <= 1.0) {
    if (series) {
      // g(s) = e^(-z w s) sin(w_d s) / w_d, the response to a unit impulse, is G(w s) / w with
      // G'' + 2 z G' + G = 0, G(0) = 0, G'(0) = 1: G = sum c_k x^k, c_(k+2) = -(2 z (k+1)
      // c_(k+1) + c_k) / ((k+1)(k+2)). With X = w h: g(h) = h S1, g'(h) = S2, its integral
      // G1(h) = h^2 S3 and double integral G2(h) = h^3 S4, S1..S4 = sum over k >= 1 of c_k
      // X^(k-1) times 1, k, 1/(k+1), 1/((k+1)(k+2)). The terms fall as X^k / k!: no
      // cancellation, and no division by w, which the closed form below needs (1 - u11)/w^2
      // of: it loses (w h)^-2 of the digits, all of them as the period grows without bound.
      const double X = w * h;
      double c0 = 0.0, c1 = 1.0, xk = 1.0;  // c_(k-1), c_k, X^(k-1)
      double s1 = 0.0, s2 = 0.0, s3 = 0.0, s4 = 0.0;
      // c_k = (l1^k - l2^k) / ((l1 - l2) k!), l1,2 the roots of l^2 + 2 z l + 1, of modulus 1:
      // a sum of k products of modulus 1 over k!, so |c_k| <= 1 / (k - 1)!, and at X <= 1 the
      // terms after the 30th add less than 1e-30
      for (int k = 1; k <= 30 && xk != 0.0; ++k) {
        const double t = c1 * xk;
        const double kd = k;
        s1 += t;
        s2 += kd * t;
        s3 += t / (kd + 1.0);
        s4 += t / ((kd + 1.0) * (kd + 2.0));
        const double c2 = -(2.0 * z * kd * c1 + c0) / (kd * (kd + 1.0));
        c0 = c1;
        c1 = c2;
        xk *= X;
      }
      u11 = s2 + 2.0 * z * X * s1;  // g' + 2 z w g: the free vibration from (1, 0)
      u12 = h * s1;
      v21 = -(w * X) * s1;  // -w^2 g
      v22 = s2;
      g0u = h * h * s3;
      g1u = h * h * h * s4;
      g0v = h * s1;
      g1v = h * h * s3;
      return;
    }
    const double wd = w * std::sqrt(1.0 - z * z);
    const double e = std::exp(-z * w * h), c = std::cos(wd * h), s = std::sin(wd * h);
    const double r = z / std::sqrt(1.0 - z * z);
    u11 = e * (c + r * s);
    u12 = e * s / wd;
    v21 = -e * w * w * s / wd;
    v22 = e * (c - r * s);
    g0u = g1u = g0v = g1v = 0.0;
  }

  // u'' + 2 z w u' + w^2 u = f0 + f1 s on [0, h] with f = -a
  void advance(double h, double a0, double a1, double& u, double& v) const {
    const double f0 = -a0, f1 = -(a1 - a0) / h;
    if (series) {
      const double un = u11 * u + u12 * v + g0u * f0 + g1u * f1;
      v = v21 * u + v22 * v + g0v * f0 + g1v * f1;
      u = un;
      return;
    }
    // particular solution u_p = p0 + p1 s, p1 = f1/w^2, p0 = f0/w^2 - 2 z f1/w^3; the rest is
    // free vibration
    const double w2 = omega * omega;
    const double p1 = f1 / w2, p0 = f0 / w2 - 2.0 * zeta * f1 / (w2 * omega);
    const double du = u - p0, dv = v - p1;
    u = p0 + p1 * h + u11 * du + u12 * dv;
    v = p1 + v21 * du + v22 * dv;
  }
};

// sin(x) / x, 1 at 0
double sinc(double x) { return std::abs(x) < 1e-8 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

}  // namespace

BaseAcceleration peak_acceleration(const GroundMotion& m) {
  BaseAcceleration peak;
  auto take = [&](double t) {
    const BaseAcceleration a = m.at(t);
    peak.x = std::max(peak.x, std::abs(a.x));
    peak.y = std::max(peak.y, std::abs(a.y));
  };
  if (m.is_sampled()) {
    for (double t : m.times()) take(t);
    return peak;
  }
  const int n = 20000;
  for (int i = 0; i <= n; ++i) take(m.duration() * i / n);
  GroundMotion::Cursor c;
  for (double t = m.next_breakpoint(-1.0, c); std::isfinite(t); t = m.next_breakpoint(t, c))
    take(t);
  return peak;
}

double peak_ground_acceleration(const std::vector<double>& a) {
  double peak = 0.0;
  for (double x : a) peak = std::max(peak, std::abs(x));
  return peak;
}

double peak_ground_velocity(const std::vector<double>& t, const std::vector<double>& a) {
  require_record(t, a);
  double v = 0.0, peak = 0.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i], a0 = a[i], a1 = a[i + 1];
    // an extremum of v inside the step where a crosses zero
    if (a0 * a1 < 0.0) {
      const double s = a0 * h / (a0 - a1);
      peak = std::max(peak, std::abs(v + a0 * s + 0.5 * (a1 - a0) * s * s / h));
    }
    v += 0.5 * (a0 + a1) * h;
    peak = std::max(peak, std::abs(v));
  }
  return peak;
}

double peak_sampled_velocity(const std::vector<double>& t, const std::vector<double>& a) {
  require_record(t, a);
  double v = 0.0, peak = 0.0;
  for (std::size_t i = 1; i < a.size(); ++i) {
    v += 0.5 * (a[i] + a[i - 1]) * (t[i] - t[i - 1]);
    peak = std::max(peak, std::abs(v));
  }
  return peak;
}

double peak_ground_displacement(const std::vector<double>& t, const std::vector<double>& a) {
  require_record(t, a);
  double v = 0.0, d = 0.0, peak = 0.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i], a0 = a[i], k = (a[i + 1] - a[i]) / h;
    // in the step: v(s) = v + a0 s + k s^2/2, d(s) = d + v s + a0 s^2/2 + k s^3/6
    auto disp = [&](double s) { return d + s * (v + s * (0.5 * a0 + s * k / 6.0)); };
    // extrema of d where v(s) = 0 inside the step: the roots of k s^2/2 + a0 s + v
    if (k == 0.0) {
      if (a0 != 0.0) {
        const double s = -v / a0;
        if (s > 0.0 && s < h) peak = std::max(peak, std::abs(disp(s)));
      }
    } else {
      const double disc = a0 * a0 - 2.0 * k * v;
      if (disc >= 0.0) {
        // the stable pair of roots: q = -(a0 + sign(a0) sqrt(disc)), s = q/k and 2v/q
        const double q = -(a0 + std::copysign(std::sqrt(disc), a0));
        for (const double s : {q / k, q != 0.0 ? 2.0 * v / q : -1.0}) {
          if (s > 0.0 && s < h) peak = std::max(peak, std::abs(disp(s)));
        }
      }
    }
    d = disp(h);
    v += 0.5 * (a0 + a[i + 1]) * h;
    peak = std::max(peak, std::abs(d));
  }
  return peak;
}

namespace {

// integral of a^2 over a step where a goes linearly from a0 to a1 in h
double step_square(double h, double a0, double a1) {
  return h * (a0 * a0 + a0 * a1 + a1 * a1) / 3.0;
}

}  // namespace

double arias_intensity(const std::vector<double>& t, const std::vector<double>& a) {
  require_record(t, a);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    sum += step_square(t[i + 1] - t[i], a[i], a[i + 1]);
  return std::numbers::pi / (2.0 * kStandardGravity) * sum;
}

double cumulative_absolute_velocity(const std::vector<double>& t, const std::vector<double>& a) {
  require_record(t, a);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i], a0 = a[i], a1 = a[i + 1];
    // a sign change splits the step into two triangles at the zero s = h a0 / (a0 - a1)
    sum += a0 * a1 < 0.0 ? 0.5 * h * (a0 * a0 + a1 * a1) / (std::abs(a0) + std::abs(a1))
                         : 0.5 * h * (std::abs(a0) + std::abs(a1));
  }
  return sum;
}

double significant_duration(const std::vector<double>& t, const std::vector<double>& a, double from,
                            double to) {
  require_record(t, a);
  FLEXROCK_THROW_UNLESS(from >= 0.0 && from < to && to <= 1.0,
                        "significant duration: expected 0 <= from < to <= 1");
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    total += step_square(t[i + 1] - t[i], a[i], a[i + 1]);
  if (!(total > 0.0)) return 0.0;
  // the first instant where the cumulative integral reaches `level`: the step holding it, then
  // bisection on its cubic, increasing in s
  auto instant = [&](double level) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      const double h = t[i + 1] - t[i], a0 = a[i], k = (a[i + 1] - a[i]) / h;
      const double step = step_square(h, a0, a[i + 1]);
      if (sum + step < level && i + 2 < t.size()) {
        sum += step;
        continue;
      }
      // integral over [0, s] of (a0 + k x)^2 = a0^2 s + a0 k s^2 + k^2 s^3 / 3
      double lo = 0.0, hi = h;
      for (int it = 0; it < 200 && hi - lo > 1e-15 * (1.0 + std::abs(t[i])); ++it) {
        const double s = 0.5 * (lo + hi);
        const double part = s * (a0 * a0 + s * (a0 * k + s * k * k / 3.0));
        (sum + part < level ? lo : hi) = s;
      }
      return t[i] + 0.5 * (lo + hi);
    }
    return t.back();
  };
  return instant(to * total) - instant(from * total);
}

// the oscillator over the record from rest; `sample(u)` at every sample after the first;
// returns the state at the end
template <class F>
std::pair<double, double> integrate_sdof(const std::vector<double>& t, const std::vector<double>& a,
                                         double omega, double zeta, F sample) {
  require_record(t, a);
  FLEXROCK_THROW_UNLESS(std::isfinite(omega) && omega > 0.0,
                        "oscillator: natural frequency must be > 0 and finite");
  FLEXROCK_THROW_UNLESS(zeta >= 0.0 && zeta < 1.0, "oscillator: damping ratio must be in [0, 1)");
  double x = 0.0, v = 0.0, h_last = t[1] - t[0];
  Step step(h_last, omega, zeta);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i];
    FLEXROCK_THROW_UNLESS(h > 0.0, "oscillator: record times must increase");
    // uniform records form the step once
    if (h != h_last) step = Step(h, omega, zeta);
    h_last = h;
    step.advance(h, a[i], a[i + 1], x, v);
    sample(x);
  }
  return {x, v};
}

std::vector<double> sdof_displacement(const std::vector<double>& t, const std::vector<double>& a,
                                      double omega, double zeta) {
  std::vector<double> u{0.0};
  u.reserve(t.size());
  integrate_sdof(t, a, omega, zeta, [&](double x) { u.push_back(x); });
  return u;
}

void require_spectral_period(double period, const std::string& key) {
  FLEXROCK_THROW_UNLESS(std::isfinite(period) && period >= kMinSpectralPeriod,
                        key + ": expected a period >= " + format_number(kMinSpectralPeriod) +
                            " s (finite), got " + format_number(period) +
                            " s; below it the oscillator follows the ground and Sa is the PGA "
                            "(use pga)");
}

double free_vibration_peak(double u0, double v0, double omega, double zeta, double h,
                           double period) {
  const double q = std::sqrt(1.0 - zeta * zeta), wd = omega * q;
  // u(s) = e^(-z w s) (u0 cos(wd s) + (v0 + z w u0) sin(wd s) / wd), sin(wd s) / wd as
  // s sinc(wd s): exact where wd s is too small for sin(wd s) / wd
  auto u = [&](double s) {
    return std::exp(-zeta * omega * s) *
           (u0 * std::cos(wd * s) + (v0 + zeta * omega * u0) * s * sinc(wd * s));
  };
  // u'(s) = e^(-z w s) (v0 cos(wd s) - w (w u0 + z v0) sin(wd s) / wd): zero at wd s = theta
  // mod pi, tan(theta) = v0 q / (w u0 + z v0); the first zero after 0 is theta1 in (0, pi],
  // the next one pi later, and |u| at the extrema falls by e^(-z pi / q) from one to the next:
  // between two extrema u is monotone, so |u| falls to zero and rises again
  double theta1 = std::atan2(v0 * q, omega * u0 + zeta * v0);
  if (!(theta1 > 0.0)) theta1 += std::numbers::pi;
  const double extrema[2] = {theta1 / wd, (theta1 + std::numbers::pi) / wd};
  // the samples k h, k = 1 .. n with n h >= period: the largest |u| is at k = 1, k = n, or a
  // sample beside an extremum inside [h, n h]; beyond 2^53 samples (a period that long against
  // the step) they are not representable, and the sampled peak is the continuous one to within
  // (wd h)^2 / 8 < 1e-31 relative: the extrema themselves
  const double n = std::ceil(period / h);
  double peak = 0.0;
  if (n < 9.0e15) {
    auto at = [&](double k) {
      if (k >= 1.0 && k <= n) peak = std::max(peak, std::abs(u(k * h)));
    };
    at(1.0);
    at(n);
    for (const double s : extrema) {
      at(std::floor(s / h));
      at(std::ceil(s / h));
    }
  } else {
    peak = std::abs(u(h));
    for (const double s : extrema) {
      if (s >= h && s <= period) peak = std::max(peak, std::abs(u(s)));
    }
  }
  return peak;
}

double spectral_acceleration(const std::vector<double>& t, const std::vector<double>& a,
                             double period, double zeta) {
  require_spectral_period(period, "spectral acceleration: period");
  const double omega = 2.0 * std::numbers::pi / period;
  double peak = 0.0;
  auto [x, v] =
      integrate_sdof(t, a, omega, zeta, [&](double u) { peak = std::max(peak, std::abs(u)); });
  // then one period of free vibration (the ground at rest) sampled at the last step, in closed
  // form: the cost no longer grows with the period over the step
  const double h = t[t.size() - 1] - t[t.size() - 2];
  peak = std::max(peak, free_vibration_peak(x, v, omega, zeta, h, period));
  // w (w peak): w^2 underflows long before w peak does
  return omega * (omega * peak);
}

RotD rotd_peak_acceleration(const std::vector<double>& a1, const std::vector<double>& a2) {
  FLEXROCK_THROW_UNLESS(a1.size() == a2.size() && !a1.empty(),
                        "RotD: the two components must have the same samples, got " +
                            std::to_string(a1.size()) + " and " + std::to_string(a2.size()));
  RotD r;
  r.by_angle.resize(180);
  for (int k = 0; k < 180; ++k) {
    double c = 0.0, s = 0.0;
    direction_cosines(k, c, s);
    double peak = 0.0;
    for (std::size_t i = 0; i < a1.size(); ++i)
      peak = std::max(peak, std::abs(c * a1[i] + s * a2[i]));
    r.by_angle[static_cast<std::size_t>(k)] = peak;
  }
  std::vector<double> sorted = r.by_angle;
  std::sort(sorted.begin(), sorted.end());
  r.rotd50 = 0.5 * (sorted[89] + sorted[90]);
  r.rotd100 = sorted.back();
  return r;
}

RotD rotd_spectral_acceleration(const std::vector<double>& t, const std::vector<double>& a1,
                                const std::vector<double>& a2, double period, double zeta) {
  require_spectral_period(period, "RotD: period");
  FLEXROCK_THROW_UNLESS(a1.size() == a2.size(),
                        "RotD: the two components must have the same samples, got " +
                            std::to_string(a1.size()) + " and " + std::to_string(a2.size()));
  const double omega = 2.0 * std::numbers::pi / period;
  std::vector<double> u1, u2;
  u1.reserve(t.size());
  u2.reserve(t.size());
  const auto [x1, v1] = integrate_sdof(t, a1, omega, zeta, [&](double u) { u1.push_back(u); });
  const auto [x2, v2] = integrate_sdof(t, a2, omega, zeta, [&](double u) { u2.push_back(u); });
  const double h = t[t.size() - 1] - t[t.size() - 2];
  RotD r;
  r.by_angle.resize(180);
  for (int k = 0; k < 180; ++k) {
    // the rotated component's response, by superposition (theta exact at 0: u1 itself)
    double c = 0.0, s = 0.0;
    direction_cosines(k, c, s);
    double peak = 0.0;
    for (std::size_t i = 0; i < u1.size(); ++i)
      peak = std::max(peak, std::abs(c * u1[i] + s * u2[i]));
    peak = std::max(peak,
                    free_vibration_peak(c * x1 + s * x2, c * v1 + s * v2, omega, zeta, h, period));
    r.by_angle[static_cast<std::size_t>(k)] = omega * (omega * peak);
  }
  std::vector<double> sorted = r.by_angle;
  std::sort(sorted.begin(), sorted.end());
  r.rotd50 = 0.5 * (sorted[89] + sorted[90]);
  r.rotd100 = sorted.back();
  return r;
}

namespace {

using Record = std::vector<double>;

const IntensityMeasure kIntensityMeasures[] = {
    {"pga", "pga_m_per_s2", "m/s^2", "peak \\|a\\| over the samples", 1, false, true,
     [](const Record&, const Record& a, double, double) { return peak_ground_acceleration(a); }},
    {"pgv", "pgv_m_per_s", "m/s",
     "peak \\|v\\| over the samples, v the trapezoidal integral of a from 0 at the first sample "
     "(no baseline correction)",
     1, false, true,
     [](const Record& t, const Record& a, double, double) { return peak_sampled_velocity(t, a); }},
    {"pgd", "pgd_m", "m",
     "peak \\|d\\|, d the double integral of the piecewise-linear a from rest, extrema between "
     "samples included (no baseline correction: long-period drift counts)",
     1, false, false,
     [](const Record& t, const Record& a, double, double) {
       return peak_ground_displacement(t, a);
     }},
    {"arias", "arias_m_per_s", "m/s", "Arias intensity pi/(2g) integral of a^2 dt", 2, false, false,
     [](const Record& t, const Record& a, double, double) { return arias_intensity(t, a); }},
    {"cav", "cav_m_per_s", "m/s", "cumulative absolute velocity: integral of \\|a\\| dt", 1, false,
     false,
     [](const Record& t, const Record& a, double, double) {
       return cumulative_absolute_velocity(t, a);
     }},
    {"d5_95", "d5_95_s", "s",
     "significant duration: time from 5 % to 95 % of the Arias intensity (the same for every "
     "scale)",
     0, false, false,
     [](const Record& t, const Record& a, double, double) { return significant_duration(t, a); }},
    {"pgv_over_pga", "pgv_over_pga_s", "s", "PGV/PGA as defined above (the same for every scale)",
     0, false, false,
     [](const Record& t, const Record& a, double, double) {
       const double pga = peak_ground_acceleration(a);
       return pga > 0.0 ? peak_sampled_velocity(t, a) / pga : 0.0;
     }},
    {"sa", "", "m/s^2",
     "pseudo-spectral acceleration omega^2 max \\|u\\| of the linear oscillator of period T "
     "and damping ratio zeta, exact for the piecewise-linear record, over the record and one "
     "period after it; column `sa_T<T>_z<zeta>_m_per_s2`",
     1, true, false,
     [](const Record& t, const Record& a, double period, double zeta) {
       return spectral_acceleration(t, a, period, zeta);
     }},
};

}  // namespace

std::span<const IntensityMeasure> intensity_measures() { return kIntensityMeasures; }

const IntensityMeasure* find_intensity_measure(std::string_view name) {
  for (const IntensityMeasure& m : kIntensityMeasures) {
    if (name == m.name) return &m;
  }
  return nullptr;
}

std::string spectral_column(double period, double zeta) {
  return "sa_T" + format_number(period) + "_z" + format_number(zeta) + "_m_per_s2";
}

}  // namespace flexrock
