// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/outcome.hpp"

#include <algorithm>
#include <cmath>

namespace flexrock::study {

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::kNoUplift:
      return "no_uplift";
    case Outcome::kRocking:
      return "rocking";
    case Outcome::kOverturnedAfterImpacts:
      return "overturned_after_impacts";
    case Outcome::kOverturnedWithoutImpact:
      return "overturned_without_impact";
    case Outcome::kContactLost:
      return "contact_lost";
    case Outcome::kStopped:
      return "stopped";
  }
  return "unknown";
}

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
  switch (r.status) {
    case Status::kOverturned:
      s.outcome =
          x.impacts == 0 ? Outcome::kOverturnedWithoutImpact : Outcome::kOverturnedAfterImpacts;
      break;
    case Status::kContactLost: {
      // a body that leaves the floor already past its static overturning angle is falling: the
      // static criterion (paper eq. 5) would have called it overturned before this point
      const int edge = r.final_theta >= 0.0 ? 1 : 2;
      if (std::abs(r.final_theta) >= body.tipping_angle(edge)) {
        s.outcome =
            x.impacts == 0 ? Outcome::kOverturnedWithoutImpact : Outcome::kOverturnedAfterImpacts;
        s.overturn_time = r.t_end;
        s.overturn_edge = edge;
      } else {
        s.outcome = Outcome::kContactLost;
      }
      break;
    }
    case Status::kStopped:
      s.outcome = Outcome::kStopped;
      break;
    case Status::kCompleted:
      // an uplift without any tilt (the base acceleration touching the threshold) is no rocking
      s.outcome =
          x.first_uplift_time >= 0.0 && s.max_theta > 0.0 ? Outcome::kRocking : Outcome::kNoUplift;
      break;
  }
  return s;
}

}  // namespace flexrock::study
