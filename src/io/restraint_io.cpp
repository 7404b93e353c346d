// SPDX-License-Identifier: BSD-3-Clause
// [[restraint]] tables: read from kRestraintKeys, their statics in words, and the outputs of a
// restrained run (docs/case-file.md, docs/theory.md §26).
#include "flexrock/io/restraint_io.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "restraint_reader.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;

namespace {

std::string kind_name(RestraintKind k) { return restraint_kind_info(k).name; }

}  // namespace

namespace detail {

std::vector<Restraint> read_restraints(TableReader& top, const BodyParameters& p,
                                       const SimulationOptions& opt) {
  std::vector<Restraint> out;
  if (!top.has("restraint")) return out;
  std::vector<std::string> kinds;
  for (const RestraintKindInfo& k : kRestraintKinds) kinds.emplace_back(k.name);
  const std::string inf_ok = " (inf: none)";
  for (TableReader& r : top.tables("restraint", "one table per tendon or anchor")) {
    Restraint t;
    const std::string kind = r.choice("kind", kinds);
    t.kind = kind == "anchor" ? RestraintKind::kAnchor : RestraintKind::kTendon;
    const bool anchor = t.kind == RestraintKind::kAnchor;
    // the body point
    if (r.has("corner")) {
      if (!anchor) r.fail("corner", "applies to kind = \"anchor\"; give a tendon body_x/body_y");
      if (r.has("body_x") || r.has("body_y"))
        r.fail("corner", "give either corner or body_x/body_y, not both");
      const long corner = r.integer_or("corner", 1, 1, "1 or 2 (the tipping point)");
      if (corner != 1 && corner != 2) r.expected("corner", "1 or 2 (the tipping point)");
      t.body_x = corner == 1 ? -p.b1 : p.b2;
      t.body_y = 0.0;
    } else {
      t.body_x = r.number_or("body_x", 0.0, "a length in m");
      const double y_default = anchor ? 0.0 : 2.0 * p.height;
      t.body_y = r.number_or("body_y", y_default, "a length in m");
      if (!(t.body_y >= 0.0)) r.expected("body_y", "a height >= 0 m (on or above the base)");
    }
    // the floor point
    const bool floor_given = r.has("floor_x") || r.has("floor_y");
    if (floor_given && r.has("length"))
      r.fail("length", "give either length or floor_x/floor_y, not both");
    if (floor_given) {
      t.floor_x = r.number_or("floor_x", t.body_x, "a length in m");
      t.floor_y = r.number("floor_y", "a height <= 0 m (the floor point, in the foundation)");
      if (!(t.floor_y <= 0.0)) r.expected("floor_y", "a height <= 0 m (in the foundation)");
    } else {
      const double length =
          anchor ? r.positive("length", "m (the bolt's free length, straight down from P)")
                 : r.positive_or("length", t.body_y > 0.0 ? t.body_y : 1.0, "m");
      if (!(t.body_y - length <= 0.0))
        r.expected("length", "a length >= body_y = " + format_number(t.body_y) +
                                 " m (the floor point must be on or below the floor)");
      t.floor_x = t.body_x;
      t.floor_y = t.body_y - length;
    }
    if (std::hypot(t.body_x - t.floor_x, t.body_y - t.floor_y) <= 1e-6 * p.height)
      r.fail(floor_given ? "floor_y" : "length",
             "the body point and the floor point coincide: give the tie a length > 0");
    // the law
    const std::string nn = "a number >= 0";
    const double k = r.number("stiffness", nn + " in N/m");
    if (!(k >= 0.0)) r.expected("stiffness", nn + " in N/m");
    t.stiffness = k;
    t.prestress = r.nonnegative_or("prestress", 0.0, "in N");
    t.slack = r.nonnegative_or("slack", 0.0, "in m");
    if (t.prestress > 0.0 && t.slack > 0.0)
      r.fail("slack", "a slack and a prestress exclude each other (a prestressed tie is taut)");
    if (auto fy = r.number_opt("yield_force", "a force in N > prestress" + inf_ok, true)) {
      if (!(*fy > t.prestress))
        r.expected("yield_force", "a force in N > prestress = " + format_number(t.prestress));
      if (std::isfinite(*fy) && !(k > 0.0))
        r.fail("yield_force", "a yield force needs a stiffness > 0");
      t.yield_force = *fy;
    }
    if (auto fe = r.number_opt("fracture_elongation", "a length in m > 0" + inf_ok, true)) {
      if (!(*fe > 0.0)) r.expected("fracture_elongation", "a length in m > 0" + inf_ok);
      t.fracture_elongation = *fe;
    }
    r.finish("in [[restraint]]");
    out.push_back(t);
  }
  // what the engine refuses (a flexible body, sliding, the compliant floor), at the first table
  try {
    validate_restraints(Body(p), out, opt);
  } catch (const InputError& e) {
    throw InputError(top.file(), top.tables("restraint", "").front().line(), "restraint", e.what());
  }
  return out;
}

}  // namespace detail

std::string restraint_key_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of restraint keys "
      "(include/flexrock/io/restraint_io.hpp); edit the table, not these lines -->\n"
      "| key | unit | default | meaning |\n|---|---|---|---|\n";
  for (const RestraintKey& k : kRestraintKeys)
    s += std::string("| `") + k.name + "` | " + k.unit + " | " + k.default_text + " | " + k.doc +
         " |\n";
  s += "<!-- end: written by `flexrock keys --markdown` -->\n";
  return s;
}

std::vector<std::string> restraint_statics_lines(const Body& body,
                                                 const std::vector<Restraint>& rs) {
  std::vector<std::string> v;
  if (rs.empty()) return v;
  const double g = body.g();
  const BodyParameters& p = body.params();
  for (int edge = 1; edge <= 2; ++edge) {
    const double a = uplift_acceleration(body, rs, edge);
    const double free = g * (edge == 1 ? body.alpha1() : body.alpha2());
    v.push_back("restraints: uplift onto edge " + std::to_string(edge) + " at " +
                format_number(a, 5) + " m/s^2 (" + format_number(a / g, 5) + " g; free body " +
                format_number(free / g, 5) + " g)");
    const double kr = self_centring_stiffness(body, rs, edge);
    v.push_back("restraints: post-uplift rotational stiffness on edge " + std::to_string(edge) +
                " " + format_number(kr, 5) + " N m/rad (" +
                (kr < 0.0 ? "softening" : "self-centring") + "; free body " +
                format_number(-p.mass * g * p.height, 5) + ")");
  }
  for (std::size_t i = 0; i < rs.size(); ++i) {
    if (rs[i].kind != RestraintKind::kTendon) continue;
    v.push_back("restraints: tendon " + std::to_string(i + 1) +
                ": critical stiffness (no softening after uplift) " +
                format_number(critical_stiffness(body, rs, static_cast<int>(i), 1), 5) +
                " N/m on edge 1, " +
                format_number(critical_stiffness(body, rs, static_cast<int>(i), 2), 5) +
                " N/m on edge 2; given " + format_number(rs[i].stiffness, 5) + " N/m");
  }
  // the rigid-plastic limit of the pushover's peak with stiff ties: each yielding tie's F_y on
  // its lever (anchors), each other tie's force at rest (a tendon's prestress)
  double m1 = p.mass * g * p.b1, m2 = p.mass * g * p.b2;
  bool capacity = false;
  for (const Restraint& r : rs) {
    const double f = std::isfinite(r.yield_force) ? r.yield_force : tie_force(r, 0.0);
    capacity = capacity || std::isfinite(r.yield_force);
    // a tie taut at rest pulls either way; a slack one only once it stretches
    const bool taut = tie_force(r, 0.0) > 0.0;
    const double l1 = tie_geometry(body, r, 1, 0.0).de, l2 = -tie_geometry(body, r, 2, 0.0).de;
    m1 += f * (taut ? l1 : std::max(0.0, l1));
    m2 += f * (taut ? l2 : std::max(0.0, l2));
  }
  if (capacity) {
    v.push_back("restraints: with stiff ties the body holds until they yield: about " +
                format_number(m1 / (p.mass * p.height) / g, 5) + " g onto edge 1, " +
                format_number(m2 / (p.mass * p.height) / g, 5) +
                " g onto edge 2 (the rigid-plastic limit of the pushover's peak)");
  }
  return v;
}

std::vector<std::string> restraint_history_columns(std::size_t n) {
  std::vector<std::string> v;
  for (std::size_t i = 1; i <= n; ++i) {
    v.push_back("restraint_force_N_" + std::to_string(i));
    v.push_back("restraint_elongation_m_" + std::to_string(i));
    v.push_back("restraint_energy_J_" + std::to_string(i));
  }
  return v;
}

std::string restraint_events_path(const std::string& events_path) {
  if (events_path.empty()) return {};
  const fs::path p(events_path);
  return (p.parent_path() / (p.stem().string() + ".restraints.csv")).string();
}

std::string restrained_summary_json(const Case& c, const Body& body, const RestrainedResult& r,
                                    const OutputPaths& paths) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(summary_json(c, body, r.result, paths));
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr; };
  auto when = [&](double t) { return t >= 0.0 ? num(t) : nullptr; };
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.restraints.size(); ++i) {
    const Restraint& in = c.restraints[i];
    const RestraintSummary& s = r.restraints[i];
    const RestraintKindInfo& k = restraint_kind_info(in.kind);
    std::string state = "intact";
    if (s.fractured)
      state = k.fractured;
    else if (s.yielded)
      state = k.yielded;
    list.push_back({{"kind", k.name},
                    {"state", state},
                    {"max_force_N", num(s.max_force)},
                    {"max_elongation_m", num(s.max_elongation)},
                    {"final_force_N", num(s.final_force)},
                    {"plastic_elongation_m", num(s.plastic_elongation)},
                    {"plastic_work_J", num(s.plastic_work)},
                    {"fracture_work_J", num(s.fracture_work)},
                    {"yield_time_s", when(s.yield_time)},
                    {"fracture_time_s", when(s.fracture_time)}});
  }
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  for (const RestraintEvent& e : r.events)
    events.push_back({{"time_s", e.time},
                      {"restraint", e.restraint + 1},
                      {"event", to_string(e.kind)},
                      {"force_N", num(e.force)},
                      {"elongation_m", num(e.elongation)},
                      {"plastic_elongation_m", num(e.plastic_elongation)},
                      {"energy_J", num(e.energy)}});
  j["restraints"] = {{"restraints", list},
                     {"stored_energy_change_J", num(r.stored_energy_change)},
                     {"plastic_work_J", num(r.plastic_work)},
                     {"fracture_work_J", num(r.fracture_work)},
                     {"events", events},
                     {"events_file", restraint_events_path(paths.events)}};
  return j.dump(2) + "\n";
}

OutputPaths write_restrained_outputs(const Case& c, const Body& body, const RestrainedResult& r,
                                     const std::string& output_dir) {
  // the event log as an unrestrained run writes it; the old summary goes first, the new one
  // comes last (write_outputs' promise: a summary vouches for the files it names)
  const OutputPaths paths = output_paths(c, output_dir);
  if (!paths.summary.empty() && ::unlink(paths.summary.c_str()) != 0 && errno != ENOENT)
    throw std::runtime_error("cannot remove the old summary " + paths.summary + ": " +
                             std::strerror(errno));
  Case plain = c;
  plain.output.summary.clear();
  plain.output.time_history.clear();
  (void)write_outputs(plain, body, r.result, output_dir);
  const std::size_t n = r.restraints.size();
  if (!paths.time_history.empty()) {
    // the time history again, the restraints' columns appended
    write_atomically(paths.time_history, [&](std::ostream& out) {
      std::vector<std::string> cols = time_history_columns(r.result.history.modes);
      const std::vector<std::string> more = restraint_history_columns(n);
      cols.insert(cols.end(), more.begin(), more.end());
      for (std::size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << cols[i];
      out << '\n';
      const std::vector<std::vector<double>> v = time_history_values(r.result, body);
      for (std::size_t k = 0; k < r.result.history.size(); ++k) {
        for (std::size_t j = 0; j < v.size(); ++j) out << (j ? "," : "") << format_number(v[j][k]);
        for (std::size_t i = 0; i < n; ++i) {
          const std::size_t at = k * n + i;
          out << ',' << format_number(r.force[at]) << ',' << format_number(r.elongation[at]) << ','
              << format_number(r.energy[at]);
        }
        out << '\n';
      }
    });
  }
  if (!paths.events.empty()) {
    write_atomically(restraint_events_path(paths.events), [&](std::ostream& out) {
      out << "time_s,restraint,kind,event,force_N,elongation_m,plastic_elongation_m,energy_J\n";
      for (const RestraintEvent& e : r.events) {
        out << format_number(e.time) << ',' << e.restraint + 1 << ','
            << kind_name(c.restraints[static_cast<std::size_t>(e.restraint)].kind) << ','
            << to_string(e.kind) << ',' << format_number(e.force) << ','
            << format_number(e.elongation) << ',' << format_number(e.plastic_elongation) << ','
            << format_number(e.energy) << '\n';
      }
    });
  }
  if (!paths.summary.empty()) {
    const std::string text = restrained_summary_json(c, body, r, paths);
    write_atomically(paths.summary, [&](std::ostream& out) { out << text; });
  }
  return paths;
}

}  // namespace flexrock::io
