// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/outcome.hpp"

#include <algorithm>
#include <cmath>

namespace flexrock::study {

RunSummary summarize(const Body& body, const SimulationResult& r) {
  RunSummary s;
  const Extremes& x = r.extremes;
  s.status = r.status;
  s.max_theta = std::max(x.max_theta_edge1, x.max_theta_edge2);
  s.max_theta_over_alpha = std::max(x.max_theta_edge1 / body.tipping_angle(1),
                                    x.max_theta_edge2 / body.tipping_angle(2));
  s.impacts = x.impacts;
  s.first_uplift_time = x.first_uplift_time;
  s.overturn_time = x.overturn_time;
  s.overturn_edge = x.overturn_edge;
  s.max_impulse = x.max_impulse;
  s.energy_lost = r.energy.impact_loss + r.energy.chatter_loss + r.energy.damping_loss;
  s.max_friction_demand = x.max_friction_demand;
  s.max_uplift = x.max_uplift;
  s.t_end = r.t_end;
  s.max_offset = x.max_offset;
  s.final_offset = r.final_offset;
  s.sliding_time = x.sliding_time;
  s.slips = x.slips;
  s.tension_episodes = x.tension_episodes;
  s.max_pivot_pull = x.max_pivot_pull;
  s.tension_time = x.tension_time;
  s.tensile_landings = x.tensile_landings;
  s.max_tensile_impulse = x.max_tensile_impulse;
  if (flexrock::overturned(r)) {
    // the engine's one overturning rule, whether the body was rocking or in flight
    s.outcome =
        x.impacts == 0 ? Outcome::kOverturnedWithoutImpact : Outcome::kOverturnedAfterImpacts;
  } else if (r.status == Status::kStopped) {
    s.outcome = Outcome::kStopped;
  } else {
    // an uplift without any tilt (the base acceleration touching the threshold) is no rocking;
    // a body that left the floor (flight) did move
    const bool moved = (x.first_uplift_time >= 0.0 && s.max_theta > 0.0) || x.lift_offs > 0;
    s.outcome = moved ? Outcome::kRocking : Outcome::kNoUplift;
  }
  // the same test of uplift as the outcome's; an overturned or stopped body that tilted did too
  const bool uplifted =
      (x.first_uplift_time >= 0.0 && s.max_theta > 0.0) || x.lift_offs > 0 || overturned(s.outcome);
  const bool slid = x.slips > 0 || x.sliding_time > 0.0;
  s.regime = slid ? (uplifted ? Regime::kSlidingRocking : Regime::kSliding)
                  : (uplifted ? Regime::kRocking : Regime::kNone);
  return s;
}

}  // namespace flexrock::study
