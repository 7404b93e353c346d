// SPDX-License-Identifier: BSD-3-Clause
// flexrock: the command line. Parses arguments, calls io/ and sim/, maps outcomes and errors to
// exit codes:
//   0  the run completed (the body may have overturned or lost contact: physical outcomes)
//   1  a run that could not complete (status "stopped"), or outputs that could not be written
//   2  bad input or usage (case file, record, body, options, command line)
#include <fmt/core.h>
#include <glob.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <future>
#include <new>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "flexrock/contact/support_impact.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/io/azimuth_outputs.hpp"
#include "flexrock/io/case_file.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/io/qualify.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/io/restraint_io.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/sim/restraints.hpp"
#include "flexrock/sim/rocking_frame.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/sim/step_cost.hpp"
#include "flexrock/sim/support.hpp"
#include "flexrock/study/azimuths.hpp"
#include "flexrock/version.hpp"
#include "plot_command.hpp"
#include "progress.hpp"
#include "qualify_command.hpp"
#include "rim_command.hpp"
#include "study_commands.hpp"
#include "verb_examples.hpp"

namespace {

using namespace flexrock;

constexpr int kExitOk = 0;
constexpr int kExitRunFailed = 1;
constexpr int kExitBadInput = 2;

// where the sticking contact of the impulsive floor breaks (docs/theory.md §15, §16), said by check
// and params
constexpr const char* kNoFrictionNote =
    "friction: no limit (friction_coefficient = inf): where the pivot force vanishes with a "
    "sideways force left the floor is let pull on the sticking pivot (pivot_tension), and a "
    "landing may need a pulling impulse (tensile_landing); runs report both with their "
    "magnitudes. A finite friction_coefficient removes them (the pivot slides instead), except "
    "briefly after a grazing landing shorter than the chatter interval (reported in the same "
    "figures)";

int error(const std::string& message, int code) {
  std::fflush(stdout);
  fmt::print(stderr, "flexrock: error: {}\n", message);
  return code;
}

// a case with [[restraint]] tables runs on the restrained engine (docs/theory.md §26), one on a
// [support] on the support's (§24); `tied` and `support` receive their results
SimulationResult run_with_progress(const Body& body, const io::Case& c, bool show_progress,
                                   std::optional<RestrainedResult>* tied = nullptr,
                                   SupportRunResult* support = nullptr) {
  const double end = c.options.t_end >= 0.0 ? c.options.t_end : c.motion.duration();
  cli::Progress progress(show_progress, end);
  std::atomic<double> reached{0.0};
  SimulationOptions options = c.options;
  options.progress = &reached;
  const auto start = std::chrono::steady_clock::now();
  auto future = std::async(std::launch::async, [&] {
    if (c.support && support) {
      *support = simulate(body, *c.support, c.motion, c.initial, options);
      return support->body;
    }
    if (c.frame) return simulate_frame(*c.frame, c.motion, c.initial, options);
    if (c.restraints.empty() || !tied) return simulate(body, c.motion, c.initial, options);
    *tied = simulate_restrained(body, c.restraints, c.motion, c.initial, options);
    return (*tied)->result;
  });
  while (future.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
    progress.draw_time(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        reached.load(std::memory_order_relaxed));
  }
  progress.clear();
  return future.get();  // rethrows InputError from the engine
}

// ---------------------------------------------------------------------------------------------
// the human summary of a run

std::string g_units(double a, double g) { return fmt::format("{:.4g} m/s^2 ({:.4g} g)", a, a / g); }

// each restraint's peak force and state, its yield and fracture, the plastic and fracture work
void print_restraints(const io::Case& c, const RestrainedResult& t) {
  for (std::size_t i = 0; i < t.restraints.size(); ++i) {
    const RestraintSummary& s = t.restraints[i];
    const RestraintKindInfo& k = restraint_kind_info(c.restraints[i].kind);
    std::string state = "intact";
    if (s.fractured) {
      state = fmt::format("{} at t = {:.4f} s", k.fractured, s.fracture_time);
    } else if (s.yielded) {
      state = fmt::format("{} at t = {:.4f} s, plastic elongation {:.4g} mm", k.yielded,
                          s.yield_time, 1e3 * s.plastic_elongation);
    }
    fmt::print("restraint {} ({}): peak force {:.6g} N, max elongation {:.4g} mm; {}\n", i + 1,
               k.name, s.max_force, 1e3 * s.max_elongation, state);
  }
  if (t.plastic_work > 0.0 || t.fracture_work > 0.0)
    fmt::print(
        "restraints: plastic work {:.6g} J, fracture work {:.6g} J (in the energy balance)\n",
        t.plastic_work, t.fracture_work);
}

void print_summary(const io::Case& c, const Body& body, const SimulationResult& r,
                   const io::OutputPaths& paths, bool quiet,
                   const RestrainedResult* tied = nullptr) {
  const BodyParameters& p = body.params();
  const Extremes& x = r.extremes;
  const EnergyBalance& e = r.energy;
  fmt::print("case: {}{}\n", c.name, c.description.empty() ? "" : " - " + c.description);
  fmt::print("body: {}{}, M = {:.6g} kg, h = {:.4g} m, b1 = {:.4g} m, b2 = {:.4g} m, {} mode{}\n",
             c.body_type, c.rigid ? " (taken rigid)" : "", p.mass, p.height, p.b1, p.b2,
             body.modes(), body.modes() == 1 ? "" : "s");
  fmt::print("excitation: {}{}, {:.4g} s\n", c.horizontal.type,
             c.vertical.type.empty() ? "" : " + vertical " + c.vertical.type, c.motion.duration());

  switch (r.status) {
    case Status::kCompleted:
      fmt::print("outcome: completed at t = {:.4f} s (final phase {})\n", r.t_end,
                 to_string(r.final_phase));
      break;
    case Status::kOverturned:
      fmt::print("outcome: OVERTURNED about edge {} at t = {:.4f} s\n", x.overturn_edge,
                 x.overturn_time);
      break;
    case Status::kStopped:
      fmt::print("outcome: STOPPED at t = {:.4f} s: {}\n", r.t_end, r.message);
      break;
  }
  fmt::print("peak tilt: {:.6g} rad on edge 1, {:.6g} rad on edge 2; max uplift {:.4g} mm\n",
             x.max_theta_edge1, x.max_theta_edge2, 1e3 * x.max_uplift);
  if (x.first_uplift_time >= 0.0) {
    fmt::print("uplift: first at t = {:.4f} s onto edge {}\n", x.first_uplift_time,
               x.first_uplift_edge);
  } else {
    // with restraints, their thresholds (docs/theory.md §26)
    const bool tied_down = !c.restraints.empty();
    fmt::print(
        "uplift: none (static uplift at {} onto edge 1, {} onto edge 2{})\n",
        g_units(tied_down ? uplift_acceleration(body, c.restraints, 1) : p.gravity * body.alpha1(),
                p.gravity),
        g_units(tied_down ? uplift_acceleration(body, c.restraints, 2) : p.gravity * body.alpha2(),
                p.gravity),
        tied_down ? ", restrained" : "");
  }
  if (x.overturn_time >= 0.0) {
    fmt::print("overturning: at t = {:.4f} s about edge {}\n", x.overturn_time, x.overturn_edge);
  } else {
    fmt::print("overturning: none\n");
  }
  fmt::print("impacts: {} (chatter cut-offs {})\n", x.impacts, x.chatter_cutoffs);
  if (c.options.contact_model == ContactModel::kCompliant) {
    fmt::print(
        "compliant contact: {} springs of {:.4g} N/m^{:g} at the tipping points; largest corner "
        "force {:.4g} N (resolved), largest impact impulse {:.4g} N s\n",
        to_string(c.options.contact_force_law), c.options.contact_stiffness,
        c.options.contact_exponent, x.max_contact_force, x.max_impulse);
  } else if (x.impacts > 0) {
    fmt::print(
        "impact law: {}; largest vertical impulse {:.4g} N s{}, largest force estimate {:.4g} N "
        "(a half-sine contact of an assumed {:.3g} ms: impact_duration)\n",
        to_string(c.options.impact_law), x.max_impulse,
        x.tensile_landings > 0
            ? fmt::format(" pressing, {:.4g} N s pulling (tensile_landing)", -x.max_tensile_impulse)
            : std::string(),
        x.max_impact_force, 1e3 * c.options.impact_duration);
  }
  if (x.lift_offs > 0) {
    fmt::print(
        "flight: {} lift-off(s), {:.4g} s in the air, up to {:.4g} mm; offset max {:.4g} mm, "
        "final {:.4g} mm\n",
        x.lift_offs, x.flight_time, 1e3 * x.max_flight_height, 1e3 * x.max_offset,
        1e3 * r.final_offset);
  }
  if (std::isfinite(c.options.friction_coefficient)) {
    fmt::print("sliding: {} slip(s), {:.4g} s sliding; offset max {:.4g} mm, final {:.4g} mm\n",
               x.slips, x.sliding_time, 1e3 * x.max_offset, 1e3 * r.final_offset);
    fmt::print(
        "energy lost: {:.6g} J (impacts {:.6g} J, chatter {:.6g} J, damping {:.6g} J, friction "
        "{:.6g} J)\n",
        e.impact_loss + e.chatter_loss + e.damping_loss + e.friction_loss, e.impact_loss,
        e.chatter_loss, e.damping_loss, e.friction_loss);
    fmt::print(
        "friction demand: max {:.4g} while sticking (coefficients: static {:.4g}, "
        "kinetic {:.4g})\n",
        x.max_friction_demand, c.options.friction_coefficient,
        std::min(c.options.friction_coefficient, c.options.kinetic_friction_coefficient));
  } else {
    fmt::print("energy lost: {:.6g} J (impacts {:.6g} J, chatter {:.6g} J, damping {:.6g} J)\n",
               e.impact_loss + e.chatter_loss + e.damping_loss, e.impact_loss, e.chatter_loss,
               e.damping_loss);
    fmt::print("friction demand: max {:.4g} (no friction limit given)\n", x.max_friction_demand);
  }
  fmt::print("energy balance residual: {:.3g} J ({:.3g} of {:.4g} J)\n", e.residual,
             e.scale > 0.0 ? std::abs(e.residual) / e.scale : 0.0, e.scale);
  if (r.chatter_cut_off) {
    fmt::print("note: the chatter criterion ended rocking {} time(s), removing {:.3g} J\n",
               x.chatter_cutoffs, e.chatter_loss);
  }
  // where the sticking contact broke (docs/theory.md §15, §16): how hard and how long
  const bool no_friction = !std::isfinite(c.options.friction_coefficient);
  const char* remedy =
      no_friction ? "; a finite friction_coefficient lets the contact slide instead" : "";
  if (r.pivot_tension || x.max_pivot_pull > 0.0) {
    const double w = p.mass * p.gravity;
    fmt::print(
        "warning: the floor pulled on a held pivot: largest pull {:.4g} N ({:.3g} M g), {:.4g} s "
        "under tension in all, over {} pivot_tension episode(s) (the pivot force vanished where "
        "the body could leave it only by sliding) and the holds after grazing landings. The "
        "model's sticking contact breaks there{}\n",
        x.max_pivot_pull, x.max_pivot_pull / w, x.tension_time, x.tension_episodes, remedy);
  }
  if (x.tensile_landings > 0) {
    fmt::print(
        "warning: {} landing(s) needed the floor to pull (events: tensile_landing); largest "
        "pulling impulse {:.4g} N s. The model's sticking contact breaks there{}\n",
        x.tensile_landings, -x.max_tensile_impulse, remedy);
  }
  if (r.impact_gained_energy) {
    fmt::print(
        "warning: an impact gained energy (check restitution_factor and the restitution "
        "ratios)\n");
  }
  if (x.impact_law_fallbacks > 0) {
    fmt::print(
        "warning: the {} impact law would have added energy at {} impact(s); {} took them "
        "(events: impact_law_fallback)\n",
        to_string(c.options.impact_law), x.impact_law_fallbacks,
        takes_measured_ratio(c.options.impact_law)
            ? "the elastic ratio sqrt(S_pre/S_post) of each"
            : "the paper's law (the modes moved fast against the tilt rate)");
  }
  if (tied) print_restraints(c, *tied);
  if (r.energy_unbalanced) {
    fmt::print(
        "warning: the energy balance does not close: |residual| {:.3g} J is above its bound "
        "{:.3g} J ({:g} of the scale + {:g} M g h, docs/reliability.md); the results are "
        "suspect: tighten rtol/atol or report the case (events: energy_unbalanced)\n",
        std::abs(e.residual), energy_residual_bound(body, e.scale), kEnergyResidualRelative,
        kEnergyResidualFloor);
  }
  if (!quiet) {
    for (const std::string* s : {&paths.time_history, &paths.events, &paths.summary}) {
      if (!s->empty()) fmt::print("wrote {}\n", *s);
    }
  }
}

// each record of a case: its file's PGA, PGV, duration and dt, and the factor it is run with
void print_records(const io::Case& c) {
  const double g = kStandardGravity;
  for (const auto* comp : {&c.horizontal, &c.horizontal2, &c.vertical}) {
    if (comp->type != "record") continue;
    const double factor = comp->scale * c.excitation_scale;
    fmt::print(
        "  record {}: {}: PGA {:.4g} g ({:.4g} m/s^2), PGV {:.4g} m/s, duration {:.4g} s, "
        "dt {}\n",
        comp == &c.horizontal    ? (c.pair ? "horizontal (H1)" : "horizontal")
        : comp == &c.horizontal2 ? "horizontal2 (H2)"
                                 : "vertical",
        comp->file, comp->pga / g, comp->pga, comp->pgv, comp->duration,
        comp->dt > 0.0 ? fmt::format("{:.4g} s", comp->dt) : std::string("not uniform"));
    if (factor != 1.0) {
      fmt::print("    run scaled by {:.6g}{}: PGA {:.4g} g, PGV {:.4g} m/s\n", factor,
                 c.scaled_to.empty() ? "" : " (to " + c.scaled_to + ")", factor * comp->pga / g,
                 factor * comp->pgv);
    }
  }
  if (c.pair) {
    fmt::print("  pair: a = H1 cos(beta) + H2 sin(beta), beta from H1 toward H2; {}\n",
               c.azimuth ? fmt::format("run at azimuth {:g} deg", *c.azimuth)
                         : fmt::format("every {:g} deg with 'flexrock azimuths'", c.azimuth_step));
  }
}

// the [body] keys as read, with the units of the table of body types, and the synthetic motions
void print_inputs(const io::Case& c) {
  std::string keys;
  for (const io::BodyKeyRead& k : c.body_keys) {
    keys += (keys.empty() ? "" : ", ") + k.name + " = " + k.value;
    if (!k.unit.empty() && k.unit != "-") keys += " " + k.unit;
    if (!k.given) keys += " (default)";
  }
  fmt::print("  body {}{}: {}\n", c.body_type, c.rigid ? " (taken as rigid)" : "", keys);
  for (const auto* comp : {&c.horizontal, &c.vertical}) {
    if (comp->type.empty() || comp->type == "record" || comp->type == "none") continue;
    const double a = comp->amplitude;
    fmt::print(
        "  {} {}: amplitude {:.4g} g ({:.4g} m/s^2){}\n",
        comp == &c.horizontal ? "horizontal" : "vertical", comp->type, a / kStandardGravity, a,
        c.excitation_scale == 1.0 ? std::string()
                                  : fmt::format(", run scaled by {:.6g}", c.excitation_scale));
  }
}

// a rocking frame's constants and its equivalent rigid body (docs/theory.md §25)
void print_frame(const RockingFrame& f, const char* indent) {
  const FrameConstants k = frame_constants(f);
  fmt::print(
      "{}rocking frame: {} columns {:.6g} m wide, {:.6g} m high, {:.6g} kg each; beam {:.6g} "
      "kg (gamma = m_b/(N m) = {:.6g})\n",
      indent, f.count, f.column_width, f.column_height, f.column_mass, f.beam_mass, k.gamma);
  fmt::print(
      "{}  alpha = {:.6g} rad ({:.4g} deg), the columns'; static uplift at g tan(alpha) = "
      "{:.6g} m/s^2\n",
      indent, k.alpha, k.alpha * 180.0 / std::numbers::pi, f.gravity * std::tan(k.alpha));
  fmt::print(
      "{}  p = {:.6g} rad/s (one column {:.6g}); impact ratio r = {:.6g} (one column {:.6g})\n",
      indent, k.p, k.column_p, k.r, k.column_r);
  fmt::print(
      "{}  equivalent rigid body: M = {:.6g} kg, h = {:.6g} m, b1 = b2 = {:.6g} m, zeta^2 = "
      "{:.6g}\n",
      indent, k.mass_eq, k.height_eq, k.height_eq * std::tan(k.alpha), k.zeta2_eq);
  fmt::print(
      "{}  reactions: the frame's = the equivalent body's + {:.6g} kg x (base acceleration + "
      "g); the frame's mass {:.6g} kg\n",
      indent, k.reaction_mass, k.mass_total);
  fmt::print(
      "{}  not modelled: sliding (friction_coefficient is refused) and flight (a run stops "
      "where the equivalent body's floor reaction reaches zero)\n",
      indent);
}

// what reading changed in the data, on stderr
void print_notes(const io::Case& c) {
  for (const std::string& n : c.notes) fmt::print(stderr, "flexrock: note: {}: {}\n", c.source, n);
}

// before a run: a body whose stiff rocking will take more than max_steps, or very long, on stderr
void print_step_cost_warning(const io::Case& c, const Body& body) {
  const double end = c.options.t_end >= 0.0 ? c.options.t_end : c.motion.duration();
  const std::string w =
      step_cost_warning(estimate_step_cost(body, c.options), end, c.options.max_steps);
  if (!w.empty()) fmt::print(stderr, "flexrock: warning: {}: {}\n", c.source, w);
}

// the support's lines of a run on a [support] (docs/theory.md §24)
void print_support_summary(const Body& body, const SupportParameters& s,
                           const SupportRunResult& r) {
  const SupportFrequencies f = support_frequencies(body, s);
  fmt::print(
      "support: m_s = {:.6g} kg, k = {:.6g} N/m, c = {:.6g} N s/m ({:.4g} Hz, damping "
      "ratio {:.4g} with the body as a rigid mass)\n",
      s.mass, s.stiffness, s.damping, f.frequency_hz, f.damping_ratio);
  fmt::print(
      "support peaks: |u| {:.6g} m, |u_dot| {:.6g} m/s, |k u + c u_dot| {:.6g} N; final u "
      "{:.6g} m\n",
      r.support.max_displacement, r.support.max_velocity, r.support.max_force,
      r.support.final_displacement);
}

// what `params` says of a case's [support]: the coupled frequencies, the impact ratios and the
// steady harmonic uplift thresholds from the transmissibility
void print_support_params(const Body& body, const SupportParameters& s) {
  const SupportFrequencies f = support_frequencies(body, s);
  const BodyParameters& p = body.params();
  fmt::print("support (docs/theory.md §24):\n");
  fmt::print("  m_s, k, c                 {:.6g} kg, {:.6g} N/m, {:.6g} N s/m\n", s.mass,
             s.stiffness, s.damping);
  fmt::print("  with the body as a rigid mass: f_s = {:.6g} Hz, damping ratio {:.6g}\n",
             f.frequency_hz, f.damping_ratio);
  for (const int edge : {1, 2}) {
    const double a_post = edge == 1 ? -body.alpha1() : body.alpha2();
    const double a_pre = edge == 1 ? body.alpha2() : -body.alpha1();
    const double on = support_impact(p.mass, s.mass, p.zeta2, a_pre, a_post).ratio;
    const double floor = (1.0 + p.zeta2 + a_pre * a_post) / (1.0 + p.zeta2 + a_post * a_post);
    fmt::print("  impact onto edge {}: theta_dot+/theta_dot- = {:.6g} (rigid floor {:.6g})\n", edge,
               on, floor);
  }
  fmt::print(
      "  steady harmonic uplift: amplitude of the ground acceleration = g min(b1, b2)/h / "
      "|T(f/f_s)|\n");
  fmt::print("  {:>10} {:>10} {:>12} {:>22}\n", "f/f_s", "f [Hz]", "|T|", "uplift amplitude");
  for (const double r : {0.25, 0.5, 0.8, 1.0, 1.25, 1.5, 2.0, 4.0}) {
    const double fin = r * f.frequency_hz;
    fmt::print("  {:>10.4g} {:>10.4g} {:>12.6g} {:>22}\n", r, fin,
               support_transmissibility(body, s, fin),
               g_units(support_uplift_amplitude(body, s, fin), p.gravity));
  }
}

// ---------------------------------------------------------------------------------------------
// commands

int cmd_run_one(const std::string& file, const std::string& output_dir, bool quiet,
                bool no_progress) {
  io::Case c;
  try {
    c = io::load_case(file);
    // before the run: an output may not overwrite an input or another output
    io::check_output_paths(c, io::output_paths(c, output_dir));
  } catch (const InputError& e) {
    return error(e.what(), kExitBadInput);
  } catch (const std::bad_alloc&) {
    return error(file + ": out of memory while reading the case and its records", kExitRunFailed);
  }
  // a body of revolution under a pair: the 3D engine (docs/theory.md §27)
  if (c.body3d && c.pair) {
    try {
      return cli::run_body_of_revolution(c, output_dir, quiet);
    } catch (const InputError& e) {
      return error(file + ": " + e.what(), kExitBadInput);
    }
  }
  if (c.pair && !c.azimuth) {
    return error(file +
                     ": [excitation] has a record pair ([excitation.horizontal2]) but no "
                     "azimuth_deg: give azimuth_deg to run one azimuth, or run every azimuth "
                     "with 'flexrock azimuths " +
                     file + "'",
                 kExitBadInput);
  }
  print_notes(c);
  const Body body(c.body);
  print_step_cost_warning(c, body);
  for (const std::string& line : io::restraint_statics_lines(body, c.restraints))
    if (!quiet) fmt::print("{}\n", line);
  SimulationResult r;
  std::optional<RestrainedResult> tied;
  SupportRunResult on_support;
  const SupportRunResult* support = c.support ? &on_support : nullptr;
  try {
    r = run_with_progress(body, c, !quiet && !no_progress && ::isatty(STDERR_FILENO), &tied,
                          &on_support);
  } catch (const InputError& e) {
    return error(file + ": " + e.what(), kExitBadInput);
  } catch (const std::bad_alloc&) {
    return error(file + ": out of memory during the run (the time history holds a row every " +
                     "output.dt = " + fmt::format("{:g}", c.options.output_dt) +
                     " s; the events one row each)",
                 kExitRunFailed);
  }
  // results that overflowed are no results: no file and no figures, only the reason
  if (!non_finite_output(r).empty()) {
    return error(file + ": the run could not complete: " + r.message + "; no output written",
                 kExitRunFailed);
  }
  io::OutputPaths paths;
  try {
    paths = tied ? io::write_restrained_outputs(c, body, *tied, output_dir)
                 : io::write_outputs(c, body, r, output_dir, support);
  } catch (const std::bad_alloc&) {
    print_summary(c, body, r, {}, quiet, tied ? &*tied : nullptr);
    return error("could not write the outputs: out of memory while formatting the summary",
                 kExitRunFailed);
  } catch (const std::exception& e) {
    print_summary(c, body, r, {}, quiet, tied ? &*tied : nullptr);
    return error(std::string("could not write the outputs: ") + e.what(), kExitRunFailed);
  }
  print_summary(c, body, r, paths, quiet, tied ? &*tied : nullptr);
  if (support) print_support_summary(body, *c.support, *support);
  if (r.status == Status::kStopped) {
    return error("the run could not complete: " + r.message, kExitRunFailed);
  }
  return kExitOk;
}

// a case with a record pair at every azimuth of its grid: the per-azimuth CSV, the envelope in a
// summary JSON and on the console
int cmd_azimuths(const std::string& file, const std::string& output_dir, bool quiet, int threads) {
  io::Case c;
  io::AzimuthPaths paths;
  try {
    c = io::load_case(file);
    if (!c.restraints.empty()) io::refuse_restraints(file, "'flexrock azimuths'");
    if (!c.pair) {
      throw InputError(file +
                       ": expected a record pair: [excitation.horizontal2] (a second "
                       "horizontal record) beside [excitation.horizontal]");
    }
    if (c.support) {
      throw InputError(file +
                       ": [support]: azimuths on a support are not built; run one azimuth "
                       "(azimuth_deg) with 'flexrock run'");
    }
    if (c.azimuth) {
      throw InputError(file +
                       ": [excitation] azimuth_deg fixes one azimuth ('flexrock run'); "
                       "remove it to run every azimuth of the grid (azimuth_step_deg)");
    }
    paths = io::azimuth_paths(c, output_dir);
    io::check_azimuth_paths(c, paths);
  } catch (const InputError& e) {
    return error(e.what(), kExitBadInput);
  }
  print_notes(c);
  const Body body(c.body);
  const std::vector<double> grid = study::azimuth_grid(c.azimuth_step);
  std::atomic<std::size_t> done{0};
  study::RunOptions run;
  run.threads = threads;
  run.completed = &done;
  std::vector<study::AzimuthRun> rows;
  try {
    rows = study::run_azimuths(
        body, grid, [&](double beta) { return io::azimuth_motion(c, beta); }, c.initial, c.options,
        run);
  } catch (const InputError& e) {
    return error(file + ": " + e.what(), kExitBadInput);
  }
  const study::AzimuthEnvelope e = study::envelope(rows);
  try {
    io::write_azimuth_outputs(c, body, rows, e, paths);
  } catch (const std::exception& ex) {
    return error(std::string("could not write the outputs: ") + ex.what(), kExitRunFailed);
  }
  fmt::print("case: {}\n", c.name);
  fmt::print("pair: H1 {}, H2 {}; beta from H1 toward H2, a = H1 cos(beta) + H2 sin(beta)\n",
             c.horizontal.file, c.horizontal2.file);
  const RotD pga = io::pair_peak_rotd(c);
  fmt::print("pair as run: RotD50 of the PGA {:.4g} g, RotD100 {:.4g} g\n",
             pga.rotd50 / kStandardGravity, pga.rotd100 / kStandardGravity);
  fmt::print("azimuths: {} (every {:g} deg over [0, 360))\n", grid.size(), c.azimuth_step);
  fmt::print("envelope: max tilt {:.6g} rad (theta/alpha {:.4g}) at {:g} deg\n", e.max_theta,
             e.max_theta_over_alpha, e.max_theta_azimuth);
  // what the planar model leaves out, with its size: the motion across the plane
  fmt::print(
      "planar model: the component across the plane is ignored; at {:g} deg it peaks at {:.4g} "
      "m/s^2, {:.3g} times the in-plane peak {:.4g} m/s^2\n",
      e.max_theta_azimuth, e.pga_across_at_max_theta,
      e.pga_along_at_max_theta > 0.0 ? e.pga_across_at_max_theta / e.pga_along_at_max_theta : 0.0,
      e.pga_along_at_max_theta);
  if (e.max_offset > 0.0) {
    fmt::print("envelope: max sliding offset {:.6g} m at {:g} deg\n", e.max_offset,
               e.max_offset_azimuth);
  } else {
    fmt::print("envelope: max sliding offset 0 (no sliding at any azimuth)\n");
  }
  if (e.max_impact_force > 0.0) {
    fmt::print("envelope: max impact force {:.6g} N at {:g} deg\n", e.max_impact_force,
               e.max_impact_force_azimuth);
  } else {
    fmt::print("envelope: max impact force 0 (no impact at any azimuth)\n");
  }
  if (e.overturned_azimuths.empty()) {
    fmt::print("overturning: at no azimuth\n");
  } else {
    std::string list;
    for (double a : e.overturned_azimuths)
      list += (list.empty() ? "" : ", ") + fmt::format("{:g}", a);
    fmt::print("overturning: at {} of {} azimuths ({} deg); first at t = {:.4f} s at {:g} deg\n",
               e.overturned_azimuths.size(), grid.size(), list, e.first_overturn_time,
               e.first_overturn_azimuth);
  }
  if (!quiet) fmt::print("wrote {}\nwrote {}\n", paths.table, paths.summary);
  if (!e.stopped_azimuths.empty()) {
    return error(fmt::format("{} of {} azimuths could not complete (outcome 'stopped' in {})",
                             e.stopped_azimuths.size(), grid.size(), paths.table),
                 kExitRunFailed);
  }
  return kExitOk;
}

// the case files named: each argument as given, or the files its wildcards match (for a
// pattern quoted past the shell, or a shell that does not expand them); sorted per argument
std::vector<std::string> expand_cases(const std::vector<std::string>& args) {
  std::vector<std::string> files;
  for (const std::string& a : args) {
    if (a.find_first_of("*?[") == std::string::npos) {
      files.push_back(a);
      continue;
    }
    glob_t g{};
    const int rc = ::glob(a.c_str(), 0, nullptr, &g);
    if (rc == GLOB_NOMATCH) {
      globfree(&g);
      throw InputError(a + ": no case file matches this pattern");
    }
    if (rc != 0) {
      globfree(&g);
      throw InputError(a + ": cannot expand this pattern");
    }
    for (std::size_t i = 0; i < g.gl_pathc; ++i) files.emplace_back(g.gl_pathv[i]);
    globfree(&g);
  }
  return files;
}

// every case in turn; the exit code is the worst (bad input 2 over a failed run 1)
int cmd_run(const std::vector<std::string>& args, const std::string& output_dir, bool quiet,
            bool no_progress) {
  const std::vector<std::string> files = expand_cases(args);
  int code = kExitOk;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (files.size() > 1 && i > 0) fmt::print("\n");
    code = std::max(code, cmd_run_one(files[i], output_dir, quiet, no_progress));
  }
  return code;
}

int cmd_check(const std::vector<std::string>& args, bool quiet) {
  const std::vector<std::string> files = expand_cases(args);
  int code = kExitOk;
  for (const std::string& file : files) {
    try {
      const io::Case c = io::load_case(file);
      io::check_output_paths(c, io::output_paths(c, ""));
      const Body body(c.body);
      print_step_cost_warning(c, body);
      if (!quiet) {
        fmt::print("{}: ok: body {} ({} mode{}), excitation {:.4g} s{}, outputs: {}{}{}\n", file,
                   c.body_type, body.modes(), body.modes() == 1 ? "" : "s", c.motion.duration(),
                   c.vertical.type.empty() ? "" : " (with vertical)",
                   c.output.time_history.empty() ? "" : c.output.time_history + " ",
                   c.output.events.empty() ? "" : c.output.events + " ", c.output.summary);
        print_inputs(c);
        if (c.frame) print_frame(*c.frame, "  ");
        print_records(c);
        if (c.support) {
          const SupportFrequencies f = support_frequencies(body, *c.support);
          fmt::print(
              "  support: m_s = {:.6g} kg, {:.4g} Hz, damping ratio {:.4g} (with the body "
              "as a rigid mass); rigid block: full contact, rocking, impacts, overturning\n",
              c.support->mass, f.frequency_hz, f.damping_ratio);
        }
        if (!std::isfinite(c.options.friction_coefficient) &&
            c.options.contact_model != ContactModel::kCompliant && c.restraints.empty())
          fmt::print("  {}\n", kNoFrictionNote);
        for (const std::string& line : io::restraint_statics_lines(body, c.restraints))
          fmt::print("  {}\n", line);
      }
      print_notes(c);
    } catch (const InputError& e) {
      code = error(e.what(), kExitBadInput);
    }
  }
  return code;
}

void print_matrix(const char* name, const MatrixX& m) {
  fmt::print("  {} =\n", name);
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    fmt::print("   ");
    for (Eigen::Index j = 0; j < m.cols(); ++j) fmt::print(" {:>13.6g}", m(i, j));
    fmt::print("\n");
  }
}

void print_vector(const char* name, const VectorX& v) {
  fmt::print("  {:<6} =", name);
  for (Eigen::Index i = 0; i < v.size(); ++i) fmt::print(" {:>13.6g}", v(i));
  fmt::print("\n");
}

int cmd_params(const std::string& file) {
  std::string type;
  BodyParameters p;
  std::optional<SupportParameters> support;
  std::optional<RockingFrame> frame;
  try {
    p = io::load_body(file, &type, nullptr, &frame, /*support_ok=*/true);
    support = io::load_support(file, p);
  } catch (const InputError& e) {
    return error(e.what(), kExitBadInput);
  }
  const Body body(p);
  const double g = p.gravity;
  fmt::print("body: {} from {}\n", type, file);
  if (frame) print_frame(*frame, "");
  if (frame) fmt::print("its equivalent rigid body:\n");
  fmt::print("  mass M                    {:.6g} kg\n", p.mass);
  fmt::print("  c.g. height h             {:.6g} m\n", p.height);
  fmt::print("  b1, b2                    {:.6g} m, {:.6g} m (c.g. to tipping points 1, 2)\n", p.b1,
             p.b2);
  fmt::print("  gravity g                 {:.6g} m/s^2\n", g);
  fmt::print("rigid-body parameters:\n");
  fmt::print("  alpha1 = b1/h             {:.6g} (slenderness angle atan(b1/h) = {:.4g} deg)\n",
             body.alpha1(), std::atan(body.alpha1()) * 180.0 / std::numbers::pi);
  fmt::print("  alpha2 = b2/h             {:.6g} (slenderness angle atan(b2/h) = {:.4g} deg)\n",
             body.alpha2(), std::atan(body.alpha2()) * 180.0 / std::numbers::pi);
  fmt::print("  zeta^2 = I/(M h^2)        {:.6g}\n", p.zeta2);
  fmt::print("  static uplift onto edge 1 (ground acceleration toward edge 2): g b1/h = {}\n",
             g_units(g * body.alpha1(), g));
  fmt::print("  static uplift onto edge 2 (ground acceleration toward edge 1): g b2/h = {}\n",
             g_units(g * body.alpha2(), g));
  fmt::print("  overturning angle         {:.6g} rad on edge 1, {:.6g} rad on edge 2\n",
             body.tipping_angle(1), body.tipping_angle(2));
  fmt::print("  rocking frequency p       {:.6g} rad/s\n", body.rocking_frequency());
  fmt::print(
      "contact (impulsive floor; friction_coefficient is a [solver] key of the case):\n  {}\n",
      kNoFrictionNote);
  if (support) print_support_params(body, *support);
  const int n = body.modes();
  fmt::print("deformation modes: {}\n", n);
  if (n > 0) {
    fmt::print("  {:>4} {:>13} {:>13} {:>13} {:>16}\n", "mode", "f [Hz]", "omega [rad/s]",
               "damping [-]", "q static [-]");
    const VectorX& w = body.natural_frequencies();
    const VectorX& z = body.damping_ratios();
    const VectorX& qs = body.static_deformation();
    for (int i = 0; i < n; ++i) {
      fmt::print("  {:>4} {:>13.6g} {:>13.6g} {:>13.6g} {:>16.6g}\n", i + 1,
                 w(i) / (2.0 * std::numbers::pi), w(i), i < z.size() ? z(i) : 0.0,
                 i < qs.size() ? qs(i) + 0.0 : 0.0);  // + 0.0: no "-0"
    }
    fmt::print(
        "  (frequencies of the pinned-base modes; q static: the deformation under gravity,"
        " standing on both edges)\n");
    fmt::print("dimensionless parameters (Moran & McLennan):\n");
    print_matrix("mu", p.mu);
    print_matrix("kappa", p.kappa);
    print_matrix("gamma", p.gamma);
    print_vector("psi_x", p.psi_x);
    print_vector("psi_y", p.psi_y);
    print_vector("delta", p.delta);
    print_vector("beta", p.beta);
  }
  // what the explicit integrator will cost (docs/theory.md, "Stiff rocking"), at the default
  // tolerances for a body file, at the case's for a case
  SimulationOptions opt;
  if (io::has_excitation(file)) {
    try {
      opt = io::load_case(file).options;
    } catch (const InputError& e) {
      return error(e.what(), kExitBadInput);
    }
  }
  const StepCost cost = estimate_step_cost(body, opt);
  fmt::print("explicit step cost while rocking ({} at rtol = {:g}):\n",
             cost.method == ExplicitMethod::kDop853 ? "DOP853" : "Dopri5", opt.rtol);
  fmt::print(
      "  stiffest motion {:.6g} rad/s ({:.6g} Hz), h omega ~ {:.3g}: about {:.4g} steps per "
      "simulated second, at least {:.4g} for stability ({:.4g} per 1/p = {:.4g} s)\n",
      cost.rocking_omega, cost.rocking_omega / (2.0 * std::numbers::pi), cost.h_omega,
      cost.rocking_steps_per_second, cost.rocking_min_steps_per_second,
      cost.rocking_steps_per_second * cost.rocking_time_scale, cost.rocking_time_scale);
  if (n > 0) {
    fmt::print(
        "  full contact: highest pinned-base mode {:.6g} Hz (exact propagation under a "
        "record)\n",
        cost.full_contact_omega / (2.0 * std::numbers::pi));
  }
  if (cost.contact_steps_per_second > 0.0) {
    fmt::print(
        "compliant contact's step cost (Dopri5 at rtol = {:g}; docs/theory.md, \"Compliant "
        "contact: step cost\"):\n  fastest motion on the corners' springs {:.6g} rad/s ({:.6g} "
        "Hz): at least {:.4g} steps per simulated second ({:.4g} for stability",
        opt.rtol, cost.contact_omega, cost.contact_omega / (2.0 * std::numbers::pi),
        cost.contact_steps_per_second, cost.contact_stable_steps_per_second);
    if (cost.contact_resonant_omega > 0.0)
      fmt::print(", {:.4g} for a resonant motion of {:.6g} rad/s at h omega ~ {:.3g}",
                 cost.contact_resonant_omega / cost.contact_h_omega, cost.contact_resonant_omega,
                 cost.contact_h_omega);
    fmt::print("); rocking takes more\n");
  }
  // the impact regime: the contact duration against the modal periods (theory §21)
  if (n > 0) {
    // the compliant contact's own duration: half the period of the body bouncing on both springs
    // (their secant stiffness under the weight for hunt_crossley)
    const bool compliant = opt.contact_model == ContactModel::kCompliant;
    double duration = opt.impact_duration;
    if (compliant) {
      const double mg = p.mass * p.gravity;
      const double k =
          0.5 * mg / static_penetration(opt.contact_stiffness, opt.contact_exponent, 0.5 * mg);
      duration = std::numbers::pi / std::sqrt(2.0 * k / p.mass);
    }
    const ImpactRegime reg = impact_regime(body.natural_frequencies(), duration);
    fmt::print(
        "impact regime (docs/theory.md §21): {} of {:.3g} ms ({}) "
        "lasts {:.3g} x the shortest modal period, {:.3g} x the longest\n",
        compliant ? "the compliant contact's half bounce period" : "an assumed contact",
        1e3 * duration, compliant ? "contact_stiffness" : "impact_duration",
        reg.duration_over_fastest, reg.duration_over_slowest);
    fmt::print(
        "  {}; closest impulsive law: {} (this run: {})\n",
        reg.between ? "some modes are neither much slower nor much faster than the contact: "
                      "neither impulsive law is exact for them"
        : reg.closest == ImpactLaw::kPaper
            ? "every mode is much slower than the contact: the modes cannot respond during it"
            : "every mode is much faster than the contact: the body is rigid during it",
        to_string(reg.closest), compliant ? "compliant" : to_string(opt.impact_law));
  }
  // a case file: its duration and max_steps too; a body file: the rate alone
  if (!io::has_excitation(file)) {
    const std::string w = step_cost_warning(cost, 0.0, 1);
    if (!w.empty()) fmt::print(stderr, "flexrock: warning: {}: {}\n", file, w);
  }
  // a case file: its records too
  if (io::has_excitation(file)) {
    try {
      const io::Case c = io::load_case(file);
      fmt::print("excitation: {}{}, {:.4g} s\n", c.horizontal.type,
                 c.vertical.type.empty() ? "" : " + vertical " + c.vertical.type,
                 c.motion.duration());
      print_records(c);
      print_notes(c);
      print_step_cost_warning(c, body);
      for (const std::string& line : io::restraint_statics_lines(body, c.restraints))
        fmt::print("{}\n", line);
    } catch (const InputError& e) {
      return error(e.what(), kExitBadInput);
    }
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"flexrock: rocking, impacts and overturning of free-standing deformable bodies",
               "flexrock"};
  app.set_version_flag("--version", std::string("flexrock ") + flexrock::version());
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  flexrock run examples/cases/museum_statue.toml        run a case, write CSV + JSON\n"
      "  flexrock run -o results -q examples/cases/slender_column.toml\n"
      "  flexrock check examples/cases/*.toml                    validate without running\n"
      "  flexrock params examples/cases/flexible_tank.toml       the body's derived parameters\n"
      "  flexrock plot museum_statue.csv -o statue.png           figure of a run (or a spectrum)\n"
      "\n"
      "Exit codes: 0 ok (overturning and loss of contact are results, not failures);\n"
      "1 a run that could not complete or outputs that could not be written;\n"
      "2 bad input or usage. Case-file keys: docs/case-file.md.");

  std::string output_dir, params_file;
  std::vector<std::string> run_files, check_files;
  bool quiet = false, no_progress = false;

  CLI::App* run = app.add_subcommand(
      "run", "Run cases: write each one's time-history CSV and summary JSON, print a summary");
  run->add_option("CASE", run_files, "case files (TOML); wildcards are expanded")->required();
  run->add_option("-o,--output-dir", output_dir,
                  "directory for outputs with relative paths (default: the working directory)");
  run->add_flag("-q,--quiet", quiet, "print only the results: no progress, no file list");
  run->add_flag("--no-progress", no_progress, "no progress bar, even on a terminal");

  std::string azimuth_file;
  int azimuth_threads = 0;
  CLI::App* azimuths = app.add_subcommand(
      "azimuths",
      "Run a case with a record pair at every azimuth of the body's plane: write the "
      "per-azimuth CSV and the envelope (summary JSON), print the envelope");
  azimuths->add_option("CASE", azimuth_file, "case file (TOML) with [excitation.horizontal2]")
      ->required();
  azimuths->add_option("-o,--output-dir", output_dir,
                       "directory for the outputs (default: the working directory)");
  azimuths->add_option("-j,--threads", azimuth_threads, "worker threads (0: every core)")
      ->check(CLI::NonNegativeNumber);
  azimuths->add_flag("-q,--quiet", quiet, "print only the results");

  CLI::App* check = app.add_subcommand("check", "Validate case files without running them");
  check->add_option("CASE", check_files, "case files (TOML)")->required();
  check->add_flag("-q,--quiet", quiet, "print nothing but errors");

  CLI::App* params = app.add_subcommand(
      "params", "Print a body's derived parameters (the [body] table of a case or body file)");
  params->add_option("BODY", params_file, "case or body file (TOML) with a [body] table")
      ->required();

  bool markdown = false;
  CLI::App* keys = app.add_subcommand(
      "keys",
      "Print the references of docs/case-file.md written from the library's tables: the "
      "synthetic motion types, the [solver] keys and the time-history columns; and of "
      "docs/studies.md: the "
      "spectrum and sweep CSV columns");
  keys->add_flag("--markdown", markdown,
                 "as the Markdown table of docs/case-file.md (the default)");

  flexrock::cli::PlotOptions plot_options;
  CLI::App* plot = flexrock::cli::add_plot_command(app, plot_options);

  flexrock::cli::StudyCommands studies(app);  // spectrum, sweep, fragility

  flexrock::cli::QualifyOptions qualify_options;
  CLI::App* qualify = flexrock::cli::add_qualify_command(app, qualify_options);
  flexrock::cli::add_verb_examples(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    error(e.what(), kExitBadInput);
    fmt::print(stderr, "Run 'flexrock --help' for usage.\n");
    return kExitBadInput;
  }

  try {
    if (*run) return cmd_run(run_files, output_dir, quiet, no_progress);
    if (*azimuths) return cmd_azimuths(azimuth_file, output_dir, quiet, azimuth_threads);
    if (*check) return cmd_check(check_files, quiet);
    if (*params) return cmd_params(params_file);
    if (*keys) {
      fmt::print("{}{}{}{}{}{}{}{}{}{}{}{}{}", io::body_key_reference(), io::pair_key_reference(),
                 io::record_format_reference(), io::pulse_key_reference(),
                 io::solver_key_reference(), io::support_key_reference(),
                 io::restraint_key_reference(), io::time_history_column_reference(),
                 io::event_column_reference(), io::azimuth_column_reference(),
                 io::study_column_reference(), cli::fragility_curve_column_reference(),
                 io::qualify_key_reference());
      return 0;
    }
    if (studies.selected()) return studies.run();
    if (*plot) return flexrock::cli::run_plot(plot_options);
    if (*qualify) return flexrock::cli::run_qualify(qualify_options);
  } catch (const InputError& e) {
    return error(e.what(), kExitBadInput);
  } catch (const std::bad_alloc&) {
    return error("out of memory", kExitRunFailed);
  } catch (const std::exception& e) {
    return error(e.what(), kExitRunFailed);
  }
  return kExitBadInput;
}
