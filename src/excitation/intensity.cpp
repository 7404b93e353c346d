// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/excitation/intensity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "flexrock/core/error.hpp"

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

}  // namespace flexrock
