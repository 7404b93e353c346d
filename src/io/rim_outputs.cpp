// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/io/rim_outputs.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <ostream>
#include <stdexcept>

#include "flexrock/core/format.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keys in the documented order

namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
}

const std::vector<RimColumn>& rim_columns() {
  static const std::vector<RimColumn> cols = {
      {"time_s", "s", "time", [](const RimHistory& h, std::size_t i) { return h.time[i]; }},
      {"mode", "-", "0 full contact, 1 rolling on the rim, 2 pivoting near upright",
       [](const RimHistory& h, std::size_t i) { return static_cast<double>(h.mode[i]); }},
      {"tilt_rad", "rad", "theta, the axis from the vertical",
       [](const RimHistory& h, std::size_t i) { return h.tilt[i]; }},
      {"tilt_azimuth_deg", "deg",
       "azimuth toward which the axis leans (and the contact lies), from H1 toward H2, unwrapped",
       [](const RimHistory& h, std::size_t i) { return h.azimuth[i] * kDeg; }},
      {"contact_angle_deg", "deg",
       "the contact's angle on the base circle in the body (the rolling angle), unwrapped",
       [](const RimHistory& h, std::size_t i) { return h.contact_angle[i] * kDeg; }},
      {"offset_x_m", "m", "base centre's offset on the floor along H1",
       [](const RimHistory& h, std::size_t i) { return h.x[i]; }},
      {"offset_y_m", "m", "along H2", [](const RimHistory& h, std::size_t i) { return h.y[i]; }},
      {"reaction_x_N", "N", "floor on body, along H1",
       [](const RimHistory& h, std::size_t i) { return h.reaction_x[i]; }},
      {"reaction_y_N", "N", "along H2",
       [](const RimHistory& h, std::size_t i) { return h.reaction_y[i]; }},
      {"reaction_z_N", "N", "vertical (normal force)",
       [](const RimHistory& h, std::size_t i) { return h.reaction_z[i]; }},
      {"friction_demand", "-", "|F_h| / F_z",
       [](const RimHistory& h, std::size_t i) { return h.friction_demand[i]; }},
      {"kinetic_J", "J", "kinetic energy relative to the floor",
       [](const RimHistory& h, std::size_t i) { return h.kinetic[i]; }},
      {"potential_J", "J", "M g z_G",
       [](const RimHistory& h, std::size_t i) { return h.potential[i]; }},
      {"input_work_J", "J", "work of the floor's motion (the pseudo-force), cumulative",
       [](const RimHistory& h, std::size_t i) { return h.input_work[i]; }},
      {"impact_loss_J", "J", "kinetic energy lost at landings, cumulative",
       [](const RimHistory& h, std::size_t i) { return h.impact_loss[i]; }},
  };
  return cols;
}

void write_rim_history(std::ostream& out, const RimHistory& h) {
  const auto& cols = rim_columns();
  for (std::size_t k = 0; k < cols.size(); ++k) out << (k ? "," : "") << cols[k].name;
  out << '\n';
  for (std::size_t i = 0; i < h.size(); ++i) {
    for (std::size_t k = 0; k < cols.size(); ++k)
      out << (k ? "," : "") << format_number(cols[k].value(h, i));
    out << '\n';
  }
}

void write_rim_events(std::ostream& out, const std::vector<RimEvent>& events) {
  out << "time_s,kind,tilt_rad,azimuth_deg,value,energy_loss_J\n";
  for (const RimEvent& e : events) {
    out << format_number(e.time) << ',' << to_string(e.kind) << ',' << format_number(e.tilt) << ','
        << format_number(e.azimuth * kDeg) << ',' << format_number(e.value) << ','
        << format_number(e.energy_loss) << '\n';
  }
}

std::string rim_summary_json(const Case& c, const AxisymmetricBody& b, const RimResult& r,
                             const OutputPaths& paths) {
  Json j;
  j["schema_version"] = 1;
  j["case"] = c.name;
  j["source"] = c.source;
  j["engine"] = "3d_body_of_revolution";
  j["body_type"] = c.body_type;
  Json body;
  body["mass_kg"] = b.mass;
  body["cg_height_m"] = b.height;
  body["base_radius_m"] = b.radius;
  body["inertia_diameter_kg_m2"] = b.inertia_diameter;
  body["inertia_axis_kg_m2"] = b.inertia_axis;
  body["alpha_rad"] = std::atan2(b.radius, b.height);
  body["p_rad_per_s"] = rocking_frequency(b);
  body["planar_landing_ratio"] = planar_landing_ratio(b);
  j["body"] = body;
  Json pair;
  pair["h1"] = c.horizontal.file;
  pair["h2"] = c.horizontal2.file;
  pair["vertical"] = c.vertical.file.empty() ? Json() : Json(c.vertical.file);
  pair["scale"] = c.excitation_scale;
  j["pair"] = pair;
  j["status"] = to_string(r.status);
  j["message"] = r.message;
  j["t_end_s"] = r.t_end;
  j["final_mode"] = to_string(r.final_mode);
  j["max_tilt_rad"] = r.max_tilt;
  j["max_tilt_over_alpha"] = r.max_tilt / std::atan2(b.radius, b.height);
  j["max_tilt_azimuth_deg"] = r.max_tilt_azimuth * kDeg;
  j["max_offset_m"] = r.max_offset;
  j["max_friction_demand"] = r.max_friction_demand;
  j["min_normal_force_N"] = std::isfinite(r.min_normal_force) ? Json(r.min_normal_force) : Json();
  j["uplifts"] = r.uplifts;
  j["landings"] = r.landings;
  // the closest the tilt came to upright without landing (rolled round it): where the 3D
  // response is sensitive (docs/theory.md §27); null: never
  j["closest_pass_rad"] = std::isfinite(r.closest_pass) ? Json(r.closest_pass) : Json();
  Json e;
  e["input_work_J"] = r.energy.input_work;
  e["kinetic_change_J"] = r.energy.kinetic_change;
  e["potential_change_J"] = r.energy.potential_change;
  e["impact_loss_J"] = r.energy.impact_loss;
  e["residual_J"] = r.energy.residual;
  j["energy"] = e;
  // the planar runs' bound on the residual (kEnergyResidualRelative, kEnergyResidualFloor)
  j["energy_unbalanced"] =
      !(std::abs(r.energy.residual) <= kEnergyResidualRelative * r.energy.scale +
                                           kEnergyResidualFloor * b.mass * b.gravity * b.height);
  j["steps"] = r.steps;
  j["rhs_evaluations"] = r.rhs_evaluations;
  Json files;
  files["time_history"] = paths.time_history;
  files["events"] = paths.events;
  j["files"] = files;
  return j.dump(2) + "\n";
}

PairMotions pair_motions(const Case& c) {
  if (!c.pair) throw std::logic_error("pair_motions: the case has no record pair");
  // the projections at 0 and 90 degrees are H1 and H2 exactly (direction_cosines)
  return {azimuth_motion(c, 0.0), azimuth_motion(c, 90.0)};
}

void write_rim_outputs(const Case& c, const AxisymmetricBody& body, const RimResult& r,
                       const OutputPaths& paths) {
  for (double v : {r.max_tilt, r.max_offset, r.max_friction_demand, r.energy.residual}) {
    if (!std::isfinite(v))
      throw std::runtime_error("the results are not finite; no output written");
  }
  for (const std::string& p : {paths.time_history, paths.summary, paths.events}) {
    if (p.empty()) continue;
    const fs::path parent = fs::path(p).parent_path();
    std::error_code ec;
    if (!parent.empty()) fs::create_directories(parent, ec);
    if (ec)
      throw std::runtime_error("cannot create directory " + parent.string() + ": " + ec.message());
  }
  if (!paths.summary.empty() && ::unlink(paths.summary.c_str()) != 0 && errno != ENOENT) {
    throw std::runtime_error("cannot remove the old summary " + paths.summary + ": " +
                             std::strerror(errno));
  }
  if (!paths.time_history.empty())
    write_atomically(paths.time_history,
                     [&](std::ostream& out) { write_rim_history(out, r.history); });
  if (!paths.events.empty())
    write_atomically(paths.events, [&](std::ostream& out) { write_rim_events(out, r.events); });
  if (!paths.summary.empty()) {
    const std::string json = rim_summary_json(c, body, r, paths);
    write_atomically(paths.summary, [&](std::ostream& out) { out << json; });
  }
}

}  // namespace flexrock::io
