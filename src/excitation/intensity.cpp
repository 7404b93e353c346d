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
  double omega, zeta;

  Step(double h, double w, double z) : omega(w), zeta(z) {
    const double wd = w * std::sqrt(1.0 - z * z);
    const double e = std::exp(-z * w * h), c = std::cos(wd * h), s = std::sin(wd * h);
    const double r = z / std::sqrt(1.0 - z * z);
    u11 = e * (c + r * s);
    u12 = e * s / wd;
    v21 = -e * w * w * s / wd;
    v22 = e * (c - r * s);
  }

  // u'' + 2 z w u' + w^2 u = f0 + f1 s on [0, h] with f = -a: particular solution
  // u_p = p0 + p1 s, p1 = f1/w^2, p0 = f0/w^2 - 2 z f1/w^3; the rest is free vibration
  void advance(double h, double a0, double a1, double& u, double& v) const {
    const double f0 = -a0, f1 = -(a1 - a0) / h;
    const double w2 = omega * omega;
    const double p1 = f1 / w2, p0 = f0 / w2 - 2.0 * zeta * f1 / (w2 * omega);
    const double du = u - p0, dv = v - p1;
    u = p0 + p1 * h + u11 * du + u12 * dv;
    v = p1 + v21 * du + v22 * dv;
  }
};

}  // namespace

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

double spectral_acceleration(const std::vector<double>& t, const std::vector<double>& a,
                             double period, double zeta) {
  FLEXROCK_THROW_UNLESS(std::isfinite(period) && period > 0.0,
                        "spectral acceleration: period must be > 0 [s]");
  const double omega = 2.0 * std::numbers::pi / period;
  double peak = 0.0;
  auto [x, v] =
      integrate_sdof(t, a, omega, zeta, [&](double u) { peak = std::max(peak, std::abs(u)); });
  // then one period of free vibration (the ground at rest) sampled at the last step
  const double h = t[t.size() - 1] - t[t.size() - 2];
  const Step step(h, omega, zeta);
  for (double s = 0.0; s < period; s += h) {
    step.advance(h, 0.0, 0.0, x, v);
    peak = std::max(peak, std::abs(x));
  }
  return omega * omega * peak;
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
