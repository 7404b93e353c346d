// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/io/azimuth_outputs.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/outputs.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keys in the documented order

namespace {

std::string n(double v) { return format_number(v); }
std::string i(long v) { return std::to_string(v); }

}  // namespace

const std::vector<AzimuthColumn>& azimuth_columns() {
  using R = study::AzimuthRun;
  static const std::vector<AzimuthColumn> kColumns = {
      {"azimuth_deg", "deg", "azimuth beta of the body's plane, from H1 toward H2",
       [](const R& r) { return n(r.azimuth_deg); }},
      {"outcome", "-",
       "`no_uplift`, `rocking`, `overturned_after_impacts`, `overturned_without_impact` or "
       "`stopped`",
       [](const R& r) { return std::string(study::to_string(r.summary.outcome)); }},
      {"max_theta_rad", "rad", "largest \\|theta\\| on either edge",
       [](const R& r) { return n(r.summary.max_theta); }},
      {"max_theta_edge1_rad", "rad", "largest tilt on edge 1 (theta > 0)",
       [](const R& r) { return n(r.max_theta_edge1); }},
      {"max_theta_edge2_rad", "rad", "largest tilt on edge 2 (theta < 0), as a positive number",
       [](const R& r) { return n(r.max_theta_edge2); }},
      {"max_theta_over_alpha", "-", "largest \\|theta\\| / the edge's tipping angle",
       [](const R& r) { return n(r.summary.max_theta_over_alpha); }},
      {"overturn_time_s", "s", "time of overturning; -1: none",
       [](const R& r) { return n(r.summary.overturn_time); }},
      {"overturn_edge", "-", "edge overturned about; 0: none",
       [](const R& r) { return i(r.summary.overturn_edge); }},
      {"impacts", "-", "impacts, chatter cut-offs and landings",
       [](const R& r) { return i(r.summary.impacts); }},
      {"max_impact_force_N", "N",
       "largest impact force: the estimate of an impulsive impact (`impact_duration`) or the "
       "compliant corner force",
       [](const R& r) { return n(r.max_impact_force); }},
      {"max_offset_m", "m", "largest \\|offset\\| of the base from where it stood (sliding)",
       [](const R& r) { return n(r.summary.max_offset); }},
      {"final_offset_m", "m", "offset of the base at the end, along +I of this azimuth",
       [](const R& r) { return n(r.summary.final_offset); }},
      {"max_friction_demand", "-", "largest \\|F_I\\|/F_J, impulses included",
       [](const R& r) { return n(r.summary.max_friction_demand); }},
      {"t_end_s", "s", "time reached", [](const R& r) { return n(r.summary.t_end); }},
      {"pga_along_m_per_s2", "m/s^2", "peak of the component along the plane (the run's input)",
       [](const R& r) { return n(r.pga_along); }},
      {"pga_across_m_per_s2", "m/s^2",
       "peak of the component across the plane, which the planar model ignores (no "
       "out-of-plane motion)",
       [](const R& r) { return n(r.pga_across); }},
  };
  return kColumns;
}

std::string azimuth_column_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of azimuth columns "
      "(src/io/azimuth_outputs.cpp); edit the table, not these lines -->\n"
      "| column | unit | meaning |\n"
      "|---|---|---|\n";
  for (const AzimuthColumn& c : azimuth_columns()) {
    s.append("| `").append(c.name).append("` | ").append(c.unit).append(" | ");
    s.append(c.doc).append(" |\n");
  }
  s += "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

void write_azimuth_table(std::ostream& out, const std::vector<study::AzimuthRun>& runs) {
  const auto& cols = azimuth_columns();
  for (std::size_t k = 0; k < cols.size(); ++k) out << (k ? "," : "") << cols[k].name;
  out << '\n';
  for (const study::AzimuthRun& r : runs) {
    for (std::size_t k = 0; k < cols.size(); ++k) out << (k ? "," : "") << cols[k].value(r);
    out << '\n';
  }
}

std::string azimuth_summary_json(const Case& c, const Body& body,
                                 const std::vector<study::AzimuthRun>& runs,
                                 const study::AzimuthEnvelope& e, const std::string& table_path) {
  (void)body;
  Json j;
  j["schema_version"] = 1;
  j["case"] = c.name;
  j["source"] = c.source;
  j["body_type"] = c.body_type;
  Json pair;
  pair["h1"] = c.horizontal.file;
  pair["h2"] = c.horizontal2.file;
  pair["vertical"] = c.vertical.file.empty() ? Json() : Json(c.vertical.file);
  pair["samples"] = c.pair ? c.pair->h1.npts() : 0;
  pair["scale"] = c.excitation_scale;
  pair["convention"] = "a(t) = H1(t) cos(beta) + H2(t) sin(beta), beta from H1 toward H2";
  if (c.pair) {
    const RotD r = pair_peak_rotd(c);
    pair["rotd50_pga_m_per_s2"] = r.rotd50;
    pair["rotd100_pga_m_per_s2"] = r.rotd100;
  }
  j["pair"] = pair;
  j["azimuth_step_deg"] = c.azimuth_step;
  j["azimuths"] = runs.size();
  Json env;
  env["max_theta_rad"] = e.max_theta;
  env["max_theta_azimuth_deg"] = e.max_theta_azimuth;
  env["max_theta_over_alpha"] = e.max_theta_over_alpha;
  env["pga_along_at_max_theta_m_per_s2"] = e.pga_along_at_max_theta;
  env["pga_across_at_max_theta_m_per_s2"] = e.pga_across_at_max_theta;
  env["max_offset_m"] = e.max_offset;
  // an azimuth governs only a value that happened: none without sliding or impacts
  env["max_offset_azimuth_deg"] = e.max_offset > 0.0 ? Json(e.max_offset_azimuth) : Json();
  env["max_impact_force_N"] = e.max_impact_force;
  env["max_impact_force_azimuth_deg"] =
      e.max_impact_force > 0.0 ? Json(e.max_impact_force_azimuth) : Json();
  env["overturned_azimuths_deg"] = e.overturned_azimuths;
  env["first_overturn_time_s"] =
      e.first_overturn_time >= 0.0 ? Json(e.first_overturn_time) : Json();
  env["first_overturn_azimuth_deg"] =
      e.first_overturn_time >= 0.0 ? Json(e.first_overturn_azimuth) : Json();
  env["stopped_azimuths_deg"] = e.stopped_azimuths;
  j["envelope"] = env;
  j["outputs"] = {{"table", table_path}};
  return j.dump(2) + "\n";
}

RotD pair_peak_rotd(const Case& c) {
  // the pair as run (scaled), at beta = 0 and 90: H1 and H2 themselves
  const GroundMotion h1 = azimuth_motion(c, 0.0), h2 = azimuth_motion(c, 90.0);
  return rotd_spectral_acceleration(h1.times(), h1.horizontal(), h2.horizontal(),
                                    kMinSpectralPeriod);
}

AzimuthPaths azimuth_paths(const Case& c, const std::string& output_dir) {
  auto at = [&](const std::string& name) {
    return output_dir.empty() ? name : (fs::path(output_dir) / name).string();
  };
  return {at(c.stem + ".azimuths.csv"), at(c.stem + ".azimuths.json")};
}

void check_azimuth_paths(const Case& c, const AzimuthPaths& paths) {
  std::vector<NamedPath> inputs;
  for (const std::string& f : c.input_files) inputs.push_back({"input", f});
  check_distinct_files(inputs,
                       {{"azimuth table", paths.table}, {"azimuth summary", paths.summary}});
}

void write_azimuth_outputs(const Case& c, const Body& body,
                           const std::vector<study::AzimuthRun>& runs,
                           const study::AzimuthEnvelope& envelope, const AzimuthPaths& paths) {
  check_azimuth_paths(c, paths);
  for (const study::AzimuthRun& r : runs) {
    const study::RunSummary& s = r.summary;
    for (double v : {s.max_theta, s.max_offset, s.final_offset, r.max_impact_force}) {
      if (!std::isfinite(v)) {
        throw std::runtime_error("the results at azimuth " + format_number(r.azimuth_deg) +
                                 " deg are not finite; no output written");
      }
    }
  }
  for (const std::string& p : {paths.table, paths.summary}) {
    const fs::path parent = fs::path(p).parent_path();
    std::error_code ec;
    if (!parent.empty()) fs::create_directories(parent, ec);
    if (ec)
      throw std::runtime_error("cannot create directory " + parent.string() + ": " + ec.message());
  }
  if (::unlink(paths.summary.c_str()) != 0 && errno != ENOENT) {
    throw std::runtime_error("cannot remove the old summary " + paths.summary + ": " +
                             std::strerror(errno));
  }
  write_atomically(paths.table, [&](std::ostream& out) { write_azimuth_table(out, runs); });
  const std::string json = azimuth_summary_json(c, body, runs, envelope, paths.table);
  write_atomically(paths.summary, [&](std::ostream& out) { out << json; });
}

}  // namespace flexrock::io
