// SPDX-License-Identifier: BSD-3-Clause
// Qualification of an unanchored body (`flexrock qualify`, docs/qualify.md): a qualification
// file names the body, its parameter ranges, the input set scaled to the design level and the
// acceptance criteria; the session runs the bounding cases x records at the design level (a
// sweep session) and an incremental dynamic analysis per case and record (record spectrum
// sessions, bisected), both journaled and resumable, and returns the report's numbers as JSON
// and the demands as a loss-assessment (pelicun) CSV. The HTML and PDF are drawn from the JSON
// by the Python package (flexrock.report).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flexrock/io/study_files.hpp"
#include "flexrock/io/study_session.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/study/parallel.hpp"
#include "flexrock/study/sweep.hpp"

namespace flexrock::io {

/// One key of a qualification file: its table ("" for the top level), name, unit, default and
/// meaning. The one table the reader takes its expectations from, the key reference of
/// docs/qualify.md is written from and the errors quote.
struct QualifyKey {
  const char* table;
  const char* key;
  const char* unit;
  const char* default_value;
  const char* doc;
};
const std::vector<QualifyKey>& qualify_keys();
/// The row of a key; throws std::logic_error for a key not in the table.
const QualifyKey& qualify_key(std::string_view table, std::string_view key);
/// The key reference as the Markdown table of docs/qualify.md, with its begin and end markers.
std::string qualify_key_reference();

/// A bounding case: the nominal body at one corner of the parameter ranges.
struct QualifyCase {
  std::string name;               // as the CSVs and the report show it
  BodyParameters body;            // the body of this corner
  double friction = 0.0;          // static Coulomb coefficient [-] (inf: the floor holds)
  double kinetic_friction = 0.0;  // [-] (inf with an inf static one)
  double mass_factor = 1.0;       // [-] M x
  double cg_height_factor = 1.0;  // [-] h x (rigid bodies)
  double cg_offset = 0.0;         // [m] c.g. moved toward edge 2 (> 0) or edge 1 (< 0)
  std::optional<double> damping;  // [-] every mode's damping ratio (bodies with modes)
};

/// The acceptance criteria (absent: not checked).
struct QualifyCriteria {
  std::optional<double> tilt_fraction;      // [-] allowed max theta / overturning angle
  std::optional<double> sliding_clearance;  // [m] allowed peak sliding offset
  std::optional<double> impact_force;       // [N] allowed impact force estimate
  std::optional<double> uplift;             // [m] allowed uplift of a tipping point
};

/// A qualification file, read and checked.
struct QualifyFile {
  std::string source;  // path as given
  std::string name, description;
  std::string body_source;  // file the [body] table was read from
  std::string body_type;    // body.type
  BodyParameters body;      // nominal
  // parameter ranges, as given
  std::vector<double> friction;  // static coefficients (inf: the floor holds)
  double kinetic_ratio = 1.0;    // mu_k / mu_s
  double mass_tolerance = 0.0, cg_height_tolerance = 0.0, cg_offset_tolerance = 0.0;
  std::vector<double> damping_ratio;  // empty or {low, high}
  std::vector<QualifyCase> cases;
  // the design level: a target PGA (m/s^2 in spec.scales) or a factor on every record
  bool design_pga = true;
  double design_level = 0.0;  // as written, in design_units ("-" for a factor)
  std::string design_units;
  // bodies = the cases (each with its friction), records, scales = the design level, solver
  study::SweepSpec spec;
  QualifyCriteria criteria;
  bool ida = true;
  std::vector<double> ida_factors;       // multiples of the design level, strictly increasing
  double ida_tolerance = 0.01;           // relative width of the bisection's final bracket
  double history_dt = 0.01;              // [s] the governing time history's spacing
  bool fragility = false;                // fit a fragility of overturning to the IDA
  double contact_stiffness = 0.0;        // [N/m] > 0: the impact force on the compliant contact too
  std::vector<std::string> input_files;  // every file read
  std::vector<std::string> input_roles;  // what each is ("qualification", "body", "record")
  std::uint64_t hash = 0;                // FNV-1a of the files and of the cases
};

/// Reads a qualification file (TOML). Throws InputError naming file, line and key.
QualifyFile load_qualify_file(const std::string& path);

/// SHA-256 of bytes, as 64 lower-case hex digits (FIPS 180-4).
std::string sha256_hex(std::string_view bytes);

/// What a qualification writes: the report's numbers (JSON) and the demands (pelicun CSV).
struct QualifyReport {
  std::string json;
  std::string demands_csv;
  bool pass = false;                 // every criterion met, nothing overturned or stopped
  std::vector<std::string> summary;  // lines for the console: each criterion, the margin, warnings
};

/// A qualification from its file to its report: the design-level sweep and the IDA spectra as
/// study sessions journaled under `work_dir` (created), so that an interrupted qualification
/// goes on from where it stopped, with the same report.
class QualifySession {
 public:
  QualifySession(QualifyFile file, std::string work_dir);
  ~QualifySession();
  QualifySession(const QualifySession&) = delete;
  QualifySession& operator=(const QualifySession&) = delete;

  const QualifyFile& file() const { return file_; }
  /// Runs (design level) and IDA sessions (case x record).
  std::size_t design_runs() const;
  std::size_t ida_sessions() const { return ida_.size(); }
  /// Runs and spectrum cells finished before this start.
  std::size_t resumed() const;
  /// Every run left, on options.threads workers. A stop request (options.cancel) ends it between
  /// runs, each finished one journaled; run() again goes on.
  void run(const study::RunOptions& options);
  /// After run() completed: writes the work CSVs, deletes the journals, computes the report
  /// (the governing time history, the refined reruns and the impact sensitivity run here).
  QualifyReport finish();

 private:
  QualifyFile file_;
  std::string work_dir_;
  std::unique_ptr<SweepSession> design_;
  std::vector<std::unique_ptr<SpectrumSession>> ida_;  // case-major: case * records + record
};

}  // namespace flexrock::io
