// SPDX-License-Identifier: BSD-3-Clause
#include "recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flexrock::detail {

Recorder::Recorder(SimulationResult& res, double mass, double g, double height, int n)
    : res_(res), mg_(mass * g), height_(height), n_(n) {
  res_.extremes.max_abs_q = VectorX::Zero(n);
  res_.history.modes = n;
}

void Recorder::observe(const Observation& o) {
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
  if (o.fj >= kPressingFraction)
    ex.max_friction_demand = std::max(ex.max_friction_demand, std::abs(o.fi) / o.fj);
  energy_scale_ = std::max({energy_scale_, std::abs(o.input_work), std::abs(o.damping_loss)});
}

void Recorder::row(const Observation& o, BaseAcceleration base, double kinetic, double potential,
                   double resultant, double impact_loss) {
  History& h = res_.history;
  h.time.push_back(o.t);
  h.phase.push_back(static_cast<int>(o.mode));
  h.theta.push_back(o.theta);
  h.theta_dot.push_back(o.theta_dot);
  for (int i = 0; i < n_; ++i) {
    h.q.push_back(o.q[i]);
    h.q_dot.push_back(o.q_dot[i]);
  }
  h.base_acc_x.push_back(base.x);
  h.base_acc_y.push_back(base.y);
  h.reaction_x.push_back(mg_ * o.fi);
  h.reaction_y.push_back(mg_ * o.fj);
  h.resultant.push_back(resultant);
  const bool flying = o.mode == ContactMode::kFlight;
  h.friction_demand.push_back(flying       ? 0.0
                              : o.fj > 0.0 ? std::abs(o.fi) / o.fj
                                           : std::numeric_limits<double>::infinity());
  h.kinetic.push_back(kinetic);
  h.potential.push_back(potential);
  h.input_work.push_back(o.input_work);
  h.damping_loss.push_back(o.damping_loss);
  h.impact_loss.push_back(impact_loss);
  h.offset.push_back(o.offset);
  h.lift.push_back(o.lift);
}

}  // namespace flexrock::detail
