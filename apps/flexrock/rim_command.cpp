// SPDX-License-Identifier: BSD-3-Clause
#include "rim_command.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "flexrock/io/outputs.hpp"
#include "flexrock/io/rim_outputs.hpp"
#include "flexrock/sim/axisymmetric.hpp"

namespace flexrock::cli {

int run_body_of_revolution(const io::Case& c, const std::string& output_dir, bool quiet) {
  const AxisymmetricBody& b = *c.body3d;
  const io::PairMotions m = io::pair_motions(c);
  const RimOptions o = rim_options(c.options);
  if (!quiet && c.azimuth) {
    fmt::print(
        "note: a body of revolution has no plane: azimuth_deg = {:g} is not used; the "
        "pair is run in 3D (H1 along x, H2 along y)\n",
        *c.azimuth);
  }
  const auto start = std::chrono::steady_clock::now();
  const RimResult r = simulate_axisymmetric(b, {&m.h1, &m.h2}, {}, o);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const io::OutputPaths paths = io::output_paths(c, output_dir);
  std::string write_error;
  try {
    io::write_rim_outputs(c, b, r, paths);
  } catch (const std::exception& e) {
    write_error = e.what();
  }
  constexpr double kDeg = 180.0 / std::numbers::pi;
  const double alpha = std::atan2(b.radius, b.height);
  if (!quiet) {
    fmt::print(
        "{}: body of revolution in 3D (R = {:g} m, h = {:g} m, alpha = {:.4g} rad), "
        "pair {} / {}\n",
        c.name, b.radius, b.height, alpha, c.horizontal.file, c.horizontal2.file);
    fmt::print("  status: {}{}{}\n", to_string(r.status), r.message.empty() ? "" : ": ", r.message);
    fmt::print(
        "  max tilt {:.6g} rad (tilt/alpha {:.4g}) toward {:.1f} deg; uplifts {}, "
        "landings {}\n",
        r.max_tilt, r.max_tilt / alpha, r.max_tilt_azimuth * kDeg, r.uplifts, r.landings);
    fmt::print("  max base offset {:.4g} m, max friction demand {:.4g}\n", r.max_offset,
               r.max_friction_demand);
    fmt::print("  energy: input {:.6g} J, impact loss {:.6g} J, residual {:.3g} J\n",
               r.energy.input_work, r.energy.impact_loss, r.energy.residual);
    if (std::isfinite(r.closest_pass)) {
      fmt::print(
          "  closest pass by upright without landing: {:.3g} rad (the response near "
          "upright is sensitive: docs/theory.md §27)\n",
          r.closest_pass);
    }
    fmt::print("  {} steps, {:.3f} s\n", r.steps, wall);
    for (const std::string* p : {&paths.time_history, &paths.events, &paths.summary})
      if (!p->empty() && write_error.empty()) fmt::print("  wrote {}\n", *p);
  }
  std::fflush(stdout);
  if (std::isfinite(r.closest_pass)) {
    // a roll through upright is resolved by the pivot zone: what follows is one sample, not a
    // converged answer (§27 measures how the peak tilt moves with the zone)
    fmt::print(stderr,
               "warning: the body rolled through upright within {:.3g} rad without landing; the "
               "response after that pass depends on how it is resolved and is not converged: take "
               "this run as one sample (docs/theory.md §27)\n",
               r.closest_pass);
  }
  if (!write_error.empty()) {
    fmt::print(stderr, "flexrock: error: could not write the outputs: {}\n", write_error);
    return 1;
  }
  if (r.status == RimStatus::kStopped) {
    fmt::print(stderr, "flexrock: error: the run could not complete: {}\n", r.message);
    return 1;
  }
  return 0;
}

}  // namespace flexrock::cli
