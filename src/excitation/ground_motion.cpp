// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/excitation/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"

namespace flexrock {

namespace {
void require_finite(const std::vector<double>& v, const char* what) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    FLEXROCK_THROW_UNLESS(std::isfinite(v[i]), std::string("ground motion: ") + what + " sample " +
                                                   std::to_string(i) + " is not finite");
  }
}

// breakpoints in increasing order, each once
void sort_unique(std::vector<double>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}
}  // namespace

GroundMotion GroundMotion::sampled(std::vector<double> time, std::vector<double> horizontal,
                                   std::vector<double> vertical) {
  FLEXROCK_THROW_UNLESS(time.size() >= 2, "ground motion: need at least 2 samples, got " +
                                              std::to_string(time.size()));
  FLEXROCK_THROW_UNLESS(horizontal.size() == time.size(),
                        "ground motion: " + std::to_string(time.size()) + " times but " +
                            std::to_string(horizontal.size()) + " horizontal values");
  FLEXROCK_THROW_UNLESS(vertical.empty() || vertical.size() == time.size(),
                        "ground motion: " + std::to_string(time.size()) + " times but " +
                            std::to_string(vertical.size()) + " vertical values");
  require_finite(time, "time");
  require_finite(horizontal, "horizontal acceleration");
  require_finite(vertical, "vertical acceleration");
  for (std::size_t i = 1; i < time.size(); ++i) {
    FLEXROCK_THROW_UNLESS(time[i] > time[i - 1],
                          "ground motion: times must increase strictly, but sample " +
                              std::to_string(i) + " (t = " + std::to_string(time[i]) +
                              " s) is not after sample " + std::to_string(i - 1));
  }
  GroundMotion m;
  m.has_vertical_ = !vertical.empty();
  if (vertical.empty()) vertical.assign(time.size(), 0.0);
  m.duration_ = time.back();
  m.time_ = std::move(time);
  m.ax_ = std::move(horizontal);
  m.ay_ = std::move(vertical);
  return m;
}

GroundMotion GroundMotion::uniform(double dt, std::vector<double> horizontal,
                                   std::vector<double> vertical, double start) {
  FLEXROCK_THROW_UNLESS(std::isfinite(dt) && dt > 0.0,
                        "ground motion: time step dt must be positive, got " + format_number(dt));
  std::vector<double> time(horizontal.size());
  for (std::size_t i = 0; i < time.size(); ++i) time[i] = start + static_cast<double>(i) * dt;
  GroundMotion m = sampled(std::move(time), std::move(horizontal), std::move(vertical));
  m.uniform_ = true;
  m.dt_ = dt;
  m.t0_ = start;
  return m;
}

GroundMotion GroundMotion::analytic(Function f, double duration, std::vector<double> breakpoints) {
  FLEXROCK_THROW_UNLESS(static_cast<bool>(f), "ground motion: analytic function is empty");
  FLEXROCK_THROW_UNLESS(std::isfinite(duration) && duration >= 0.0,
                        "ground motion: duration must be >= 0, got " + format_number(duration));
  GroundMotion m;
  m.f_ = std::move(f);
  m.duration_ = duration;
  breakpoints.push_back(0.0);
  breakpoints.push_back(duration);
  sort_unique(breakpoints);
  m.breaks_ = std::move(breakpoints);
  m.has_vertical_ = true;
  return m;
}

GroundMotion GroundMotion::none(double duration) {
  GroundMotion m = analytic([](double) { return BaseAcceleration{}; }, duration);
  m.none_ = true;
  return m;
}

GroundMotion GroundMotion::with_sinusoids(std::vector<SinusoidPiece> pieces) const {
  FLEXROCK_THROW_UNLESS(!is_sampled() && !none_,
                        "ground motion: only an analytic motion is described by sinusoids");
  GroundMotion m = *this;
  for (SinusoidPiece& p : pieces) {
    FLEXROCK_THROW_UNLESS(std::isfinite(p.begin) && std::isfinite(p.end) &&
                              std::isfinite(p.amplitude) && std::isfinite(p.omega) &&
                              std::isfinite(p.phase) && p.begin >= 0.0 && p.end > p.begin &&
                              p.end <= duration_,
                          "ground motion: a sinusoidal piece must be finite and lie within [0, " +
                              format_number(duration_) + "] s with end > begin");
    p.amplitude *= scale_;  // as the motion's function is scaled
    m.breaks_.push_back(p.begin);
    m.breaks_.push_back(p.end);
  }
  sort_unique(m.breaks_);
  m.sinusoids_.insert(m.sinusoids_.end(), pieces.begin(), pieces.end());
  return m;
}

double GroundMotion::quiet_from() const {
  if (none_) return 0.0;
  if (sinusoids_.empty()) return duration_;
  double end = 0.0;
  for (const SinusoidPiece& p : sinusoids_) end = std::max(end, p.end);
  return end;
}

BaseAcceleration GroundMotion::look_up(double t, Cursor& c) const {
  if (!time_.empty()) {
    if (t < time_.front() || t > time_.back()) return {};
    const std::size_t last = time_.size() - 2;  // the last interval
    std::size_t i;
    if (uniform_) {
      // direct index, clamped, then moved onto the interval time_[i] <= t < time_[i + 1] that
      // the samples' own times give (the quotient may round across a sample)
      const double s = (t - t0_) / dt_;
      i = std::min(static_cast<std::size_t>(s), last);
      if (i > 0 && t < time_[i]) --i;
      if (i < last && t >= time_[i + 1]) ++i;
    } else {
      // the cursor's interval or the next one (sequential use), else a binary search
      i = std::min(c.index, last);
      if (!(time_[i] <= t && t < time_[i + 1])) {
        if (i + 2 < time_.size() && time_[i + 1] <= t && t < time_[i + 2]) {
          ++i;
        } else {
          const auto it = std::upper_bound(time_.begin(), time_.end(), t);
          i = std::min(
              static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - time_.begin() - 1, 0)), last);
        }
      }
    }
    c.index = i;
    const double span = time_[i + 1] - time_[i];
    c.t0 = time_[i];
    c.t1 = time_[i + 1];
    c.x0 = ax_[i];
    c.y0 = ay_[i];
    c.x1 = ax_[i + 1];
    c.y1 = ay_[i + 1];
    c.sx = (ax_[i + 1] - ax_[i]) / span;
    c.sy = (ay_[i + 1] - ay_[i]) / span;
    return at(t, c);  // the cursor now covers t
  }
  if (t < 0.0 || t > duration_ || !f_) return {};
  const BaseAcceleration a = f_(t);
  return {scale_ * a.x, scale_ * a.y};
}

double GroundMotion::next_breakpoint(double t, Cursor& c) const {
  const std::vector<double>& b = time_.empty() ? breaks_ : time_;
  if (b.empty() || t >= b.back()) return std::numeric_limits<double>::infinity();
  if (uniform_) {
    // before the record: its first sample (and no negative double to size_t cast)
    if (t < time_.front()) return time_.front();
    // the sample after t, guarding against t sitting a rounding error below a sample
    auto k = static_cast<std::size_t>(std::floor((t - t0_) / dt_)) + 1;
    while (k > 0 && time_[k - 1] > t) --k;
    while (k < time_.size() && time_[k] <= t) ++k;
    return k < time_.size() ? time_[k] : std::numeric_limits<double>::infinity();
  }
  std::size_t i = std::min(c.index, b.size() - 1);
  while (i > 0 && b[i - 1] > t) --i;
  while (i < b.size() && b[i] <= t) ++i;
  c.index = i > 0 ? i - 1 : 0;
  return i < b.size() ? b[i] : std::numeric_limits<double>::infinity();
}

GroundMotion GroundMotion::scaled(double factor) const {
  FLEXROCK_THROW_UNLESS(std::isfinite(factor),
                        "ground motion: scale factor must be finite, got " + format_number(factor));
  GroundMotion m = *this;
  // samples are scaled in place, so horizontal() and vertical() give what the body feels
  if (m.time_.empty()) {
    m.scale_ *= factor;
    for (SinusoidPiece& p : m.sinusoids_) p.amplitude *= factor;
  } else {
    for (double& v : m.ax_) v *= factor;
    for (double& v : m.ay_) v *= factor;
  }
  return m;
}

}  // namespace flexrock
