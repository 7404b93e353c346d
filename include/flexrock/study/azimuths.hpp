// SPDX-License-Identifier: BSD-3-Clause
// A planar body under two horizontal components, at every azimuth of its plane: the runs and
// their envelope (docs/theory.md, "Two horizontal components"). The motion at each azimuth is
// the caller's (io builds it from a record pair); this layer runs them on threads and reduces.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/study/outcome.hpp"
#include "flexrock/study/parallel.hpp"

namespace flexrock::study {

/// One azimuth's run.
struct AzimuthRun {
  double azimuth_deg = 0.0;       // [deg] from H1 toward H2
  RunSummary summary;             // outcome, tilt, offsets, impacts (summarize())
  double max_theta_edge1 = 0.0;   // [rad] largest tilt on edge 1
  double max_theta_edge2 = 0.0;   // [rad] largest tilt on edge 2, as a positive number
  double max_impact_force = 0.0;  // [N] largest impact force: the estimate of an impulsive
                                  // impact (impact_duration) or the compliant corner force
  std::string message;            // why a stopped run stopped
  // the planar model's input and what it leaves out: the peaks of the component along the plane
  // (run) and of the one across it (ignored: no out-of-plane motion is modelled)
  double pga_along = 0.0;   // [m/s^2]
  double pga_across = 0.0;  // [m/s^2]
};

/// The envelope over azimuths: each largest value with its governing azimuth (the first azimuth
/// of the grid that reaches it), and the azimuths at which the body overturns. Where the body
/// overturns at some azimuth, the tilt is governed by the first overturned azimuth of the grid.
struct AzimuthEnvelope {
  std::size_t azimuths = 0;                 // runs
  double max_theta = 0.0;                   // [rad] largest |theta|
  double max_theta_azimuth = 0.0;           // [deg]
  double pga_along_at_max_theta = 0.0;      // [m/s^2] at the tilt's governing azimuth
  double pga_across_at_max_theta = 0.0;     // [m/s^2] the ignored component there
  double max_theta_over_alpha = 0.0;        // [-] largest |theta| / tipping angle
  double max_offset = 0.0;                  // [m] largest |offset| of the base (sliding)
  double max_offset_azimuth = 0.0;          // [deg]
  double max_impact_force = 0.0;            // [N]
  double max_impact_force_azimuth = 0.0;    // [deg]
  std::vector<double> overturned_azimuths;  // [deg] in grid order
  double first_overturn_time = -1.0;        // [s] earliest overturning over azimuths; -1: none
  double first_overturn_azimuth = 0.0;      // [deg] where it happens
  std::vector<double> stopped_azimuths;     // [deg] runs that could not complete
};

/// The azimuths 0, step, 2 step, ... below 360 [deg]; `step_deg` in (0, 360] must divide 360
/// (to 1e-9 relative), else InputError.
std::vector<double> azimuth_grid(double step_deg);

/// Runs `body` under `motion_at(beta)` for every beta of `azimuths_deg` (in parallel over
/// `run.threads`; the result does not depend on them), from `initial` with `options` (no time
/// history is kept: output_dt is set to 0). `motion_at` is called from several threads, at beta
/// and at beta + 90 (the component across the plane, whose peak is reported).
std::vector<AzimuthRun> run_azimuths(const Body& body, const std::vector<double>& azimuths_deg,
                                     const std::function<GroundMotion(double)>& motion_at,
                                     const InitialState& initial, const SimulationOptions& options,
                                     const RunOptions& run = {});

/// One azimuth's row from a finished simulation.
AzimuthRun azimuth_run(const Body& body, double azimuth_deg, const SimulationResult& result);

/// The envelope of the runs.
AzimuthEnvelope envelope(const std::vector<AzimuthRun>& runs);

}  // namespace flexrock::study
