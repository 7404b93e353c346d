// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/azimuths.hpp"

#include <algorithm>
#include <cmath>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/excitation/intensity.hpp"

namespace flexrock::study {

std::vector<double> azimuth_grid(double step_deg) {
  const double count = 360.0 / step_deg;
  FLEXROCK_THROW_UNLESS(
      step_deg > 0.0 && step_deg <= 360.0 && std::abs(count - std::round(count)) <= 1e-9 * count,
      "azimuth step: expected a step in (0, 360] deg that divides 360, got " +
          format_number(step_deg));
  const auto n = static_cast<std::size_t>(std::round(count));
  std::vector<double> grid(n);
  // each azimuth as i * step, not a running sum: no drift over the circle
  for (std::size_t i = 0; i < n; ++i) grid[i] = static_cast<double>(i) * step_deg;
  return grid;
}

AzimuthRun azimuth_run(const Body& body, double azimuth_deg, const SimulationResult& result) {
  AzimuthRun a;
  a.azimuth_deg = azimuth_deg;
  a.summary = summarize(body, result);
  a.max_theta_edge1 = result.extremes.max_theta_edge1;
  a.max_theta_edge2 = result.extremes.max_theta_edge2;
  a.max_impact_force =
      std::max(result.extremes.max_impact_force, result.extremes.max_contact_force);
  if (result.status == Status::kStopped) a.message = result.message;
  return a;
}

std::vector<AzimuthRun> run_azimuths(const Body& body, const std::vector<double>& azimuths_deg,
                                     const std::function<GroundMotion(double)>& motion_at,
                                     const InitialState& initial, const SimulationOptions& options,
                                     const RunOptions& run) {
  SimulationOptions o = options;
  o.output_dt = 0.0;
  o.progress = nullptr;
  std::vector<AzimuthRun> rows(azimuths_deg.size());
  parallel_for(
      azimuths_deg.size(), run.threads,
      [&](std::size_t i) {
        const GroundMotion m = motion_at(azimuths_deg[i]);
        rows[i] = azimuth_run(body, azimuths_deg[i], simulate(body, m, initial, o));
        rows[i].pga_along = peak_acceleration(m).x;
        rows[i].pga_across = peak_acceleration(motion_at(azimuths_deg[i] + 90.0)).x;
        if (run.completed) run.completed->fetch_add(1, std::memory_order_relaxed);
      },
      run.cancel);
  return rows;
}

AzimuthEnvelope envelope(const std::vector<AzimuthRun>& runs) {
  AzimuthEnvelope e;
  e.azimuths = runs.size();
  // the first azimuth of the grid that reaches each largest value governs
  auto raise = [](double v, double az, double& best, double& where) {
    if (v > best) {
      best = v;
      where = az;
    }
  };
  bool overturn_governs = false;
  for (const AzimuthRun& r : runs) {
    const RunSummary& s = r.summary;
    // an overturning governs the tilt: the first overturned azimuth of the grid (the tilts at
    // which runs stop differ only by where the criterion was located)
    if (overturned(s.outcome) && !overturn_governs) {
      overturn_governs = true;
      e.max_theta = s.max_theta;
      e.max_theta_azimuth = r.azimuth_deg;
    } else if (!overturn_governs) {
      raise(s.max_theta, r.azimuth_deg, e.max_theta, e.max_theta_azimuth);
    }
    e.max_theta_over_alpha = std::max(e.max_theta_over_alpha, s.max_theta_over_alpha);
    raise(s.max_offset, r.azimuth_deg, e.max_offset, e.max_offset_azimuth);
    raise(r.max_impact_force, r.azimuth_deg, e.max_impact_force, e.max_impact_force_azimuth);
    if (overturned(s.outcome)) {
      e.overturned_azimuths.push_back(r.azimuth_deg);
      if (e.first_overturn_time < 0.0 || s.overturn_time < e.first_overturn_time) {
        e.first_overturn_time = s.overturn_time;
        e.first_overturn_azimuth = r.azimuth_deg;
      }
    }
    if (s.status == Status::kStopped) e.stopped_azimuths.push_back(r.azimuth_deg);
  }
  for (const AzimuthRun& r : runs) {
    if (r.azimuth_deg == e.max_theta_azimuth) {
      e.pga_along_at_max_theta = r.pga_along;
      e.pga_across_at_max_theta = r.pga_across;
      break;
    }
  }
  return e;
}

}  // namespace flexrock::study
