// SPDX-License-Identifier: BSD-3-Clause
// Ground-motion record files: PEER NGA .AT2, single-column (or several values a line) with a given
// dt, and two-column time/acceleration text or CSV. The only layer that reads files.
//
// A reader returns a Record that keeps the values in the file's units; Record::to_motion() (or
// combine() for a horizontal plus a vertical component) converts them to m/s^2, applies a scale
// factor and builds the in-memory GroundMotion. Every parse error is a flexrock::InputError whose
// message starts with "<path>:<line>: " (1-based line) and says what was expected and what was
// found.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "flexrock/core/types.hpp"
#include "flexrock/excitation/ground_motion.hpp"

namespace flexrock::io {

/// Units of acceleration values in a record.
enum class AccelUnit {
  kG,                      // standard gravity, 9.80665 m/s^2
  kMetersPerSecond2,       // m/s^2
  kCentimetersPerSecond2,  // cm/s^2 (gal)
};

/// Every unit with its name in files and its size: the one statement of both.
struct AccelUnitInfo {
  AccelUnit unit;
  const char* name;  // in files and messages
  double to_si;      // [m/s^2] one unit
};
inline constexpr AccelUnitInfo kAccelUnits[] = {
    {AccelUnit::kG, "g", kStandardGravity},
    {AccelUnit::kMetersPerSecond2, "m/s^2", 1.0},
    {AccelUnit::kCentimetersPerSecond2, "cm/s^2", 0.01},
};

/// Metres per second squared in one `unit` (g: kStandardGravity).
double to_si_factor(AccelUnit unit);

/// Short name of a unit: "g", "m/s^2", "cm/s^2".
std::string_view unit_name(AccelUnit unit);

/// An acceleration record as read from a file, values still in the file's units.
struct Record {
  std::string source;               // path the record was read from
  std::vector<std::string> header;  // header or comment lines, verbatim (no line ends)
  AccelUnit units = AccelUnit::kG;  // units of `values`
  double dt = 0.0;             // [s] sample spacing for uniformly sampled records; 0 if not uniform
  std::vector<double> time;    // [s] sample times, strictly increasing (first at 0 for AT2 and dt)
  std::vector<double> values;  // accelerations in `units`, one per time

  /// Number of samples.
  std::size_t npts() const { return values.size(); }
  /// Time of the last sample [s] (0 if empty).
  double duration() const { return time.empty() ? 0.0 : time.back(); }
  /// Index of the value with the largest magnitude (the PGA sample); 0 when empty.
  std::size_t peak_index() const;

  /// Values converted to m/s^2 and multiplied by `scale`.
  std::vector<double> to_si(double scale = 1.0) const;
  /// The record as a horizontal ground motion in m/s^2, multiplied by `scale` (e.g. to scale a
  /// record to a target PGA). Uniformly sampled records give GroundMotion::uniform.
  GroundMotion to_motion(double scale = 1.0) const;
};

/// Reads a PEER NGA strong-motion .AT2 file (both header generations). Line 3 must state the
/// units ("... IN UNITS OF G"; CM/S/S, CM/SEC/SEC, GAL and M/S/S are also understood). Line 4
/// gives NPTS and DT in any of the forms
///   "4096 0.0100 NPTS, DT"   "0.0100 4096 DT, NPTS"   "NPTS= 4096, DT= .0100 SEC,"
///   "DT= .0100 SEC, NPTS= 4096,"   "NPTS= 4096 DT= .0100 SEC"   "NPTS 4096 DT .0100"
///   "4096 0.0100" (unlabelled: the integer is NPTS)
/// and the values follow, any count a line, in fixed or E notation (".1394908E-02" too), with LF
/// or CRLF line ends and blank lines anywhere after line 4. Exactly NPTS finite values are
/// required: fewer or more is an error. Sample i is at time i * DT.
Record read_at2(const std::string& path);

/// Reads accelerations sampled every `dt` [s] from t = 0, any count of values a line, separated by
/// whitespace or commas; lines whose first non-blank character is '#' are comments (kept in
/// Record::header). All values are kept, including trailing zero pads. `units` are those of the
/// file's values (the file does not say; the caller must).
Record read_single_column(const std::string& path, double dt, AccelUnit units);

/// Reads time [s] / acceleration pairs, one pair a line, separated by whitespace or a comma (CSV).
/// '#' lines are comments; the first non-comment line may be a header row (it is kept if it holds
/// no number). Times must increase strictly. Record::dt is set only when the times are uniform
/// to 1e-9 relative; time and values are kept as given either way.
Record read_time_series(const std::string& path, AccelUnit units);

/// A horizontal record with an optional vertical one (`vertical` may be null), both converted to
/// m/s^2 and multiplied by `scale`. The vertical is linearly interpolated onto the horizontal's
/// times when the two time grids differ, and is zero where it does not cover them. Throws if the
/// records' time spans do not overlap.
GroundMotion combine(const Record& horizontal, const Record* vertical, double scale = 1.0);

}  // namespace flexrock::io
