// SPDX-License-Identifier: BSD-3-Clause
// Recording a run: extremes, time-history rows and events, from plain observations that the
// contact modes compute. Ordinary code, the same for every body size. Internal header.
#pragma once

#include <algorithm>
#include <cmath>

#include "flexrock/sim/simulate.hpp"

namespace flexrock::detail {

/// What the extremes and the history need of one instant.
struct Observation {
  double t = 0.0;  // [s]
  ContactMode mode = ContactMode::kFullContact;
  double theta = 0.0, theta_dot = 0.0;          // [rad], [rad/s]
  const double* q = nullptr;                    // [-] n values
  const double* q_dot = nullptr;                // [1/s] n values (history rows only)
  double fi = 0.0, fj = 0.0;                    // floor reaction over M g (0 in flight)
  double moment = 0.0;                          // about the c.g. projection, over M g h
  double offset = 0.0;                          // [m] horizontal offset of the base centre
  double lift = 0.0;                            // [m] height of the lower tipping point
  double high = 0.0;                            // [m] height of the higher tipping point
  double input_work = 0.0, damping_loss = 0.0;  // [J] cumulative
};

/// A floor pressing with less than this fraction of the weight holds no meaningful friction
/// demand: |F_I|/F_J grows without bound as F_J -> 0 before a lift-off (docs/theory.md, "Friction
/// demand").
inline constexpr double kPressingFraction = 0.05;

/// The friction demand |F_I|/F_J of an instant (the reaction over M g), 0 where the floor presses
/// with less than kPressingFraction of the weight.
inline double friction_demand(double fi, double fj) {
  return fj >= kPressingFraction ? std::abs(fi) / fj : 0.0;
}

class Recorder {
 public:
  Recorder(SimulationResult& res, double mass, double g, double height, int n);

  /// Folds one instant into the extremes (inline: the loop calls it at every sample).
  void observe(const Observation& o);
  /// Folds a value |q_j| that a search for its extreme found at some instant.
  void observe_deformation(int j, double abs_q) {
    res_.extremes.max_abs_q(j) = std::max(res_.extremes.max_abs_q(j), abs_q);
  }
  /// Folds the cumulative input work and damping loss [J] of an instant whose other quantities are
  /// known not to raise an extreme.
  void observe_energy(double input_work, double damping_loss) {
    energy_scale_ = std::max({energy_scale_, std::abs(input_work), std::abs(damping_loss)});
  }
  /// Appends one history row.
  void row(const Observation& o, BaseAcceleration base, double kinetic, double potential,
           double resultant, double impact_loss);
  /// Appends an event.
  void event(const Event& e) { res_.events.push_back(e); }
  /// Largest |input work| or |damping loss| seen [J].
  double energy_scale() const { return energy_scale_; }

 private:
  SimulationResult& res_;
  double mg_, height_;
  int n_;
  double energy_scale_ = 0.0;
};

inline void Recorder::observe(const Observation& o) {
  Extremes& ex = res_.extremes;
  if (o.theta > 0.0) ex.max_theta_edge1 = std::max(ex.max_theta_edge1, o.theta);
  if (o.theta < 0.0) ex.max_theta_edge2 = std::max(ex.max_theta_edge2, -o.theta);
  ex.max_uplift = std::max(ex.max_uplift, o.high);
  ex.max_offset = std::max(ex.max_offset, std::abs(o.offset));
  if (o.mode == ContactMode::kFlight) ex.max_flight_height = std::max(ex.max_flight_height, o.lift);
  for (int i = 0; i < n_; ++i) ex.max_abs_q(i) = std::max(ex.max_abs_q(i), std::abs(o.q[i]));
  ex.max_base_shear = std::max(ex.max_base_shear, mg_ * std::abs(o.fi));
  ex.max_overturning_moment =
      std::max(ex.max_overturning_moment, mg_ * height_ * std::abs(o.moment));
  ex.max_friction_demand = std::max(ex.max_friction_demand, friction_demand(o.fi, o.fj));
  energy_scale_ = std::max({energy_scale_, std::abs(o.input_work), std::abs(o.damping_loss)});
}

}  // namespace flexrock::detail
