// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/sim/rocking_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"

namespace flexrock {
namespace {

// the events where the equivalent body leaves the floor or lands pulling: its motion is no longer
// the frame's rocking (a pivot_tension episode is: the held pivot is the frame's, whose own
// reaction the samples below check)
bool leaves_floor(EventKind k) {
  return k == EventKind::kLiftOff || k == EventKind::kTensileLanding;
}

// the frame's contact forces at a time-history sample while rocking (docs/theory.md §25): the
// beam on the columns N_b = m_b (g + a_y + 2 y_c'') and the floor on the frame
// F_J = N m ((1 + gamma) (g + a_y) + (1 + 2 gamma) y_c''), y_c the columns' c.g. height
struct FrameForces {
  double beam = 0.0, floor = 0.0;  // [N]
};

FrameForces frame_forces(const RockingFrame& f, const FrameConstants& k, double theta,
                         double theta_dot, double ax, double ay) {
  const double g = f.gravity;
  const double R = std::hypot(0.5 * f.column_width, 0.5 * f.column_height);
  // phi = alpha - |theta|, measured toward the pivot; a_x acts toward edge 2 (theta > 0: edge 1)
  const double s = theta >= 0.0 ? 1.0 : -1.0;
  const double phi = k.alpha - s * theta;
  const double thdd = k.p * k.p / g * (s * ax * std::cos(phi) - (g + ay) * std::sin(phi));
  const double ycdd = R * (s * std::sin(phi) * thdd - std::cos(phi) * theta_dot * theta_dot);
  const double nm = f.count * f.column_mass;
  return {f.beam_mass * (g + ay + 2.0 * ycdd),
          nm * ((1.0 + k.gamma) * (g + ay) + (1.0 + 2.0 * k.gamma) * ycdd)};
}

}  // namespace

void validate_frame_options(const SimulationOptions& options) {
  FLEXROCK_THROW_UNLESS(
      !std::isfinite(options.friction_coefficient),
      "rocking_frame: friction_coefficient = " + format_number(options.friction_coefficient, 6) +
          ": sliding of a rocking frame (its columns on the floor, its beam on the columns) is not "
          "modelled; remove friction_coefficient (the floor and the beam hold whatever the "
          "demand)");
  FLEXROCK_THROW_UNLESS(options.contact_model == ContactModel::kImpulsive,
                        "rocking_frame: contact_model = \"compliant\": the compliant contact is "
                        "not modelled for a frame; use contact_model = \"impulsive\"");
}

SimulationResult simulate_frame(const RockingFrame& frame, const GroundMotion& motion,
                                const InitialState& initial, const SimulationOptions& options) {
  validate_frame_options(options);
  const FrameConstants fc = frame_constants(frame);
  const Body body(frame_equivalent_body(frame));
  // the frame's contact forces are checked on the time history: a run that asks for none gets
  // one at kFrameCheckDt for the check, dropped afterwards
  SimulationOptions run = options;
  if (!(run.output_dt > 0.0)) run.output_dt = kFrameCheckDt;
  SimulationResult r = simulate(body, motion, initial, run);
  double t_off = std::numeric_limits<double>::infinity();
  std::string why;
  for (const Event& e : r.events) {
    if (leaves_floor(e.kind)) {
      t_off = e.time;
      why = "the equivalent body's floor reaction reached zero (" + std::string(to_string(e.kind)) +
            "; the frame's own is larger by reaction_mass (g + a_v) = " +
            format_number(fc.reaction_mass * (frame.gravity + motion.at(e.time).y), 6) +
            " N there)";
      break;
    }
  }
  // the beam on the columns and the frame on the floor, at the time-history samples while rocking;
  // a negative one is then located between its sample and the one before by bisection on runs
  // that end there (their final state is the motion's at that instant)
  auto negative_at = [&](double t, FrameForces& ff) {
    SimulationOptions o = options;
    o.t_end = t;
    o.output_dt = 0.0;
    const SimulationResult e = simulate(body, motion, initial, o);
    if (e.final_phase != ContactMode::kRockingEdge1 && e.final_phase != ContactMode::kRockingEdge2)
      return false;
    const BaseAcceleration a = motion.at(t);
    ff = frame_forces(frame, fc, e.final_theta, e.final_theta_dot, a.x, a.y);
    return ff.beam < 0.0 || ff.floor < 0.0;
  };
  const History& h = r.history;
  for (std::size_t i = 0; i < h.size() && h.time[i] < t_off; ++i) {
    if (h.phase[i] != 1 && h.phase[i] != 2) continue;
    FrameForces ff =
        frame_forces(frame, fc, h.theta[i], h.theta_dot[i], h.base_acc_x[i], h.base_acc_y[i]);
    if (ff.beam < 0.0 || ff.floor < 0.0) {
      // [lo, hi]: holds at lo (the sample before), fails at hi; 40 halvings of a sample interval
      double lo = i > 0 ? h.time[i - 1] : 0.0, hi = h.time[i];
      for (int it = 0; it < 40 && hi - lo > 1e-12 * std::max(1.0, hi); ++it) {
        const double mid = 0.5 * (lo + hi);
        FrameForces fm;
        if (negative_at(mid, fm)) {
          hi = mid;
          ff = fm;
        } else {
          lo = mid;
        }
      }
      t_off = hi;
      why = ff.beam < 0.0 ? "the beam's contact force on the columns turns negative, " +
                                format_number(ff.beam, 6) + " N (the beam would lift off)"
                          : "the frame's floor reaction turns negative, " +
                                format_number(ff.floor, 6) + " N (the columns would lift off)";
      why += ", located between time-history samples " + format_number(run.output_dt, 6) +
             " s apart (a dip shorter than that between two samples that hold is not seen)";
      break;
    }
  }
  if (std::isfinite(t_off)) {
    // the run ends where the frame's model does: rerun to that instant
    SimulationOptions to_off = options;
    to_off.t_end = t_off;
    r = simulate(body, motion, initial, to_off);
    r.status = Status::kStopped;
    r.message = "rocking frame: at t = " + format_number(t_off, 8) + " s " + why +
                "; flight of a rocking frame is not modelled, the run stops";
  }
  if (!(options.output_dt > 0.0)) r.history = History{};
  return r;
}

}  // namespace flexrock
