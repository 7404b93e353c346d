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
