// SPDX-License-Identifier: BSD-3-Clause
// The outputs of a body of revolution run in 3D (`flexrock run` on a "cylinder" or
// "body_of_revolution" with a record pair, docs/theory.md §27): the time history from one table
// of columns (rim_columns()), the events and the summary JSON, written atomically, the summary
// last, as the outputs of a planar run (outputs.hpp).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "flexrock/io/case_file.hpp"
#include "flexrock/io/outputs.hpp"
#include "flexrock/sim/axisymmetric.hpp"

namespace flexrock::io {

/// One column of the 3D time history.
struct RimColumn {
  const char* name;  // with its unit suffix
  const char* unit;
  const char* doc;
  double (*value)(const RimHistory& h, std::size_t row);
};

/// Every column, in the CSV's order.
const std::vector<RimColumn>& rim_columns();

/// The time history CSV: a header row, then one row per output time.
void write_rim_history(std::ostream& out, const RimHistory& h);

/// The events CSV: time, kind, tilt, azimuth, magnitude, energy loss.
void write_rim_events(std::ostream& out, const std::vector<RimEvent>& events);

/// The summary JSON of a 3D run.
std::string rim_summary_json(const Case& c, const AxisymmetricBody& body, const RimResult& r,
                             const OutputPaths& paths);

/// The floor motion of a case with a record pair, for the 3D engine: H1 along x with the vertical
/// (`h1`), H2 along y (`h2`), each scaled as for a planar run.
struct PairMotions {
  GroundMotion h1, h2;
};
PairMotions pair_motions(const Case& c);

/// Writes the outputs the case asks for (the summary last, after removing an old one); nothing is
/// written when a reported value is not finite. Throws std::runtime_error when a file cannot be
/// written.
void write_rim_outputs(const Case& c, const AxisymmetricBody& body, const RimResult& r,
                       const OutputPaths& paths);

}  // namespace flexrock::io
