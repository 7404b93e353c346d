// SPDX-License-Identifier: BSD-3-Clause
// Ground-motion record files as agencies publish them: PEER NGA .AT2, USGS SMC, NIED K-NET and
// KiK-net ASCII, ESM ASCII, COSMOS V1/V2; single-column (or several values a line) with a given
// dt, and time/acceleration text or CSV. The only layer that reads files. record_formats() (below)
// is the one table of formats: case files, study files, Python and docs/case-file.md read it.
//
// A reader returns a Record that keeps the values in the file's units; Record::to_motion() (or
// combine() for a horizontal plus a vertical component) converts them to m/s^2, applies a scale
// factor and builds the in-memory GroundMotion. Every parse error is a flexrock::InputError whose
// message starts with "<path>:<line>: " (1-based line) and says what was expected and what was
// found.
#pragma once

#include <cstddef>
#include <optional>
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

/// Reads time [s] / acceleration pairs, one pair a line, separated by whitespace, a comma (CSV)
/// or a semicolon. '#' lines are comments. Before the first pair there may be a row of column
/// names and a row of units ("s, g" or "[s];[cm/s^2]"), or names that carry their units
/// ("time [s], acc (cm/s/s)"): the acceleration unit they state is the record's, and must agree
/// with `units` when both are given; a time unit other than seconds is refused. In a line
/// separated by semicolons a comma is a decimal mark ("0,01;-0,05"). Columns after the second
/// (velocity, displacement, flags) are not read, but every row must have as many columns as the
/// first one. Times must increase strictly. Record::dt is set only when the times are uniform to
/// 1e-9 relative; time and values are kept as given either way.
Record read_time_series(const std::string& path, std::optional<AccelUnit> units);

/// Reads a USGS SMC file (the format of the USGS strong-motion CD-ROMs, also written by PEER's
/// PEA2SMC): a text line whose first character gives the data type (0 unknown, 1 uncorrected, 2
/// corrected accelerogram; 3 velocity, 4 displacement and 5 spectra are refused), ten more text
/// lines, 48 integers 8 a line (-32768 unknown; the 16th counts the comment lines, the 17th the
/// samples), 50 reals 5 a line (1.7e38 unknown; the 2nd is the sampling rate [1/s]), the comment
/// lines ('|'), then the values in cm/s^2, any count a line, blanks or a sign between them.
Record read_smc(const std::string& path);

/// Reads a NIED K-NET or KiK-net ASCII file (.NS, .EW, .UD; KiK-net .NS1 ... .UD2): 17 header
/// lines "Label  value" in any order ("Sampling Freq(Hz)  100Hz", "Scale Factor  3920(gal)/6182761"
/// required; the rest kept), then integer counts, any count a line. Values are counts times the
/// scale factor [cm/s^2], the recorder's offset kept as published (subtract the mean before
/// integrating: the record is not baseline-corrected).
Record read_knet(const std::string& path);

/// Reads an ESM (Engineering Strong Motion database) ASCII file: "KEY: value" header lines in any
/// order and count (NDATA, SAMPLING_INTERVAL_S, UNITS required; DATA_TYPE, if given, must be an
/// acceleration), then NDATA values, any count a line.
Record read_esm(const std::string& path);

/// Reads the first acceleration channel of a COSMOS V1 or V2 file (COSMOS Strong-Motion Data
/// Format v01.20): a text header whose first line states "(Format v01.20 with N text lines)", the
/// integer and real headers as their count lines state (the sample interval is real value 62, in
/// ms), the comment lines, then the data line ("16596 acceleration pts, approx 82 secs,
/// units=cm/sec2 (04), Format=(8F10.5)") and its values in that Fortran format. Later blocks
/// (velocity, displacement, other channels) are not read.
Record read_cosmos(const std::string& path);

/// One record format: its name in case and study files, how its files are recognised, what the
/// caller must supply and its reader. record_formats() is the one table of them.
/// Where a format's units come from.
enum class RecordUnits {
  kFile,         // the file states them
  kFileOrGiven,  // a row of the file may state them; else the caller gives them
  kGiven,        // the file never states them: the caller gives them
};

struct RecordFormat {
  const char* name;       // `format = "..."`
  const char* suffixes;   // file-name endings that select it, lower case, blank-separated
  bool needs_dt;          // the file does not state its sample spacing: `dt` required
  RecordUnits units;      // where the units of the values come from
  const char* publisher;  // who publishes files in this format
  const char* doc;        // one line for docs and messages
  Record (*read)(const std::string& path, double dt, std::optional<AccelUnit> units);
};

/// Every record format, in the order of the docs.
const std::vector<RecordFormat>& record_formats();

/// The format named `name`, or null.
const RecordFormat* find_record_format(std::string_view name);

/// The format a file name selects by its ending (case-insensitive), or null.
const RecordFormat* record_format_for(const std::string& path);

/// The names of every format, "at2, smc, ..." for messages.
std::string record_format_names();

/// Reads `path` in the format named `format` (empty: chosen by the file name's ending), with the
/// sample spacing `dt` [s] where the format needs it and the units of the values where the file
/// does not state them; units given for a file that states its own must agree with them.
Record read_record(const std::string& path, const std::string& format, double dt,
                   std::optional<AccelUnit> units);

/// The Markdown table of record formats of docs/case-file.md (`flexrock keys --markdown`).
std::string record_format_reference();

/// A horizontal record with an optional vertical one (`vertical` may be null), both converted to
/// m/s^2 and multiplied by `scale`. The vertical is linearly interpolated onto the horizontal's
/// times when the two time grids differ, and is zero where it does not cover them. Throws if the
/// records' time spans do not overlap.
GroundMotion combine(const Record& horizontal, const Record* vertical, double scale = 1.0);

}  // namespace flexrock::io
