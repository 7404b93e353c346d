// SPDX-License-Identifier: BSD-3-Clause
// Restraints in case files and outputs (docs/case-file.md, "[[restraint]]"; docs/theory.md §26).
// One table of keys drives the reader, its errors, `flexrock keys` and the docs.
#pragma once

#include <string>
#include <vector>

#include "flexrock/io/case_file.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/sim/restraints.hpp"

namespace flexrock::io {

/// One key of a [[restraint]] table.
struct RestraintKey {
  const char* name;
  const char* unit;
  const char* default_text;
  const char* doc;
};

/// The keys of [[restraint]], in the order of the docs.
inline constexpr RestraintKey kRestraintKeys[] = {
    {"kind", "-", "required",
     "`\"tendon\"` (a prestressed tie from the foundation to a point of the body) or `\"anchor\"` "
     "(a bolt at a point of the base: slack, capacity, fracture); one law, two sets of defaults"},
    {"corner", "-", "none",
     "anchors: 1 or 2, the tipping point it holds (body_x = -b1 or b2, body_y = 0); not with "
     "body_x/body_y"},
    {"body_x", "m", "0 (the point under the c.g.)",
     "the body point P along the base, from the point under the c.g. (x toward tipping point 2)"},
    {"body_y", "m", "tendon: 2 h; anchor: 0",
     "the body point P's height above the base (a tendon's default: the top of a uniform block)"},
    {"length", "m", "tendon: body_y; anchor: required",
     "the tie's free length at rest, straight down from P: F = (body_x, body_y - length); not "
     "with floor_x/floor_y"},
    {"floor_x", "m", "body_x",
     "the floor point F along the floor (with floor_y, instead of length)"},
    {"floor_y", "m", "none", "the floor point F's height, <= 0 (in the foundation)"},
    {"stiffness", "N/m", "required", "k, the tie's axial stiffness, >= 0"},
    {"prestress", "N", "0", "P_0, the tension at rest (tendons), >= 0; not with slack"},
    {"slack", "m", "0", "s, the elongation before it pulls (anchors), >= 0"},
    {"yield_force", "N", "inf (elastic)",
     "F_y > P_0: elastic-perfectly plastic past it, the plastic elongation kept"},
    {"fracture_elongation", "m", "inf (never)",
     "the elongation past the slack at which it breaks; the body is free there after"},
};

/// The key reference of [[restraint]], as the Markdown table of docs/case-file.md, with its begin
/// and end marker lines (`flexrock keys --markdown`).
std::string restraint_key_reference();

/// The restraints' statics of a case, for `flexrock check` and `params` (docs/theory.md §26):
/// lines of text, one per figure.
std::vector<std::string> restraint_statics_lines(const Body& body,
                                                 const std::vector<Restraint>& restraints);

/// The time-history CSV columns a restrained run adds: force_N_i, elongation_m_i, energy_J_i.
std::vector<std::string> restraint_history_columns(std::size_t restraints);

/// Writes the outputs of a restrained run as write_outputs() does, the time history with the
/// restraints' columns appended, the summary with a "restraints" object, and the restraints'
/// events (yield, unload, fracture) in "<events stem>.restraints.csv" beside the event log.
OutputPaths write_restrained_outputs(const Case& c, const Body& body, const RestrainedResult& r,
                                     const std::string& output_dir);

/// The summary JSON of a restrained run: summary_json() with its "restraints" object.
std::string restrained_summary_json(const Case& c, const Body& body, const RestrainedResult& r,
                                    const OutputPaths& paths);

/// The restraints' event log's path for the case's event log path (empty: none).
std::string restraint_events_path(const std::string& events_path);

}  // namespace flexrock::io
