// SPDX-License-Identifier: BSD-3-Clause
// Case files: one TOML file describes a body, its excitation, the solver options and the outputs
// of one simulation. Every key is documented in docs/case-file.md with its unit and default.
//
// Errors are flexrock::InputError with messages of the form
//   "<file>:<line>: key '<table.key>': expected <what>, got <value>"
// and unknown keys are rejected with the closest known key ("did you mean ...").
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/model/assemblies.hpp"
#include "flexrock/model/axisymmetric_body.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/restraints.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/sim/support.hpp"

namespace flexrock::io {

/// Where the results of a run go. Relative paths are relative to the output directory the
/// caller chooses (the `flexrock run --output-dir`, default the working directory); an empty
/// path writes nothing.
struct OutputSettings {
  double dt = 0.01;          // [s] time-history spacing; 0: no time history
  std::string time_history;  // CSV time history (default "<case stem>.csv")
  std::string summary;       // summary JSON (default "<case stem>.summary.json")
  std::string events;        // event log CSV (default: none)
};

/// One component (horizontal or vertical) of the excitation, as the case file describes it.
struct ExcitationComponent {
  std::string type;        // "record", "harmonic", "one_sine", ..., "none"
  std::string file;        // record file, resolved against the case file's directory
  std::string format;      // "at2", "single_column" or "time_series" (records)
  std::string units;       // units of the file's values or of `amplitude`
  double amplitude = 0.0;  // [m/s^2] peak of a synthetic motion, converted to SI
  double scale = 1.0;      // [-] factor on a record component
  // a record's file as read, before any scale factor
  double pga = 0.0;       // [m/s^2] peak ground acceleration
  double pgv = 0.0;       // [m/s] peak ground velocity (no baseline correction)
  double duration = 0.0;  // [s] last sample time less the first
  double dt = 0.0;        // [s] sample spacing; 0: not uniform
};

/// One key of a [body] as it was read, for `flexrock check`.
struct BodyKeyRead {
  std::string name;   // the key
  std::string value;  // the number as given (or its default), "[2 x 2]" for a matrix, a path
  std::string unit;   // of the key, from the table of body types
  bool given = true;  // false: the default
};

/// Two horizontal components of one station, H1 and H2 (H2 90 degrees from H1), with the
/// vertical component when one is given: the input of a planar body at every azimuth. The body's
/// plane at azimuth beta, measured from H1 toward H2, receives a(t) = H1(t) cos(beta) + H2(t)
/// sin(beta) (docs/theory.md, "Two horizontal components").
struct RecordPair {
  Record h1, h2;  // each with its component's scale applied, cut to their common samples
  std::optional<Record> vertical_record;        // a vertical record
  std::optional<GroundMotion> vertical_motion;  // a synthetic vertical motion
};

/// One key of [excitation] for a record pair, from the table that the reader, `flexrock keys`
/// and docs/case-file.md share.
struct PairKey {
  const char* name;
  const char* unit;
  const char* default_text;
  const char* doc;
};

/// The keys of a record pair in [excitation], in the order of the docs.
inline constexpr PairKey kPairKeys[] = {
    {"[excitation.horizontal2]", "table", "none",
     "the second horizontal component H2, 90 degrees from `[excitation.horizontal]` (H1) toward "
     "which azimuths are measured: `type = \"record\"` with the record keys below; the two must "
     "have the same time step, and are cut to the shorter"},
    {"azimuth_deg", "deg", "none",
     "with a pair: the azimuth beta of the body's plane, from H1 toward H2; `flexrock run` runs "
     "a(t) = H1 cos(beta) + H2 sin(beta). Without it a pair is run by `flexrock azimuths` only"},
    {"azimuth_step_deg", "deg", "5",
     "with a pair: the step of the azimuth grid of `flexrock azimuths` over [0, 360), > 0, "
     "dividing 360"},
};

/// The key reference of a record pair, as the Markdown table of docs/case-file.md, written from
/// kPairKeys with its begin and end marker lines (`flexrock keys --markdown`).
std::string pair_key_reference();

/// One key of [support] (docs/theory.md §24), from the table that the reader, `flexrock keys`
/// and docs/case-file.md share.
struct SupportKey {
  const char* name;
  const char* unit;
  const char* default_text;
  const char* doc;
};

/// The keys of [support], in the order of the docs.
inline constexpr SupportKey kSupportKeys[] = {
    {"mass", "kg", "required",
     "m_s: the support's mass, >= 0 (0: a massless spring and dashpot under the body)"},
    {"frequency_hz", "Hz", "required (or `stiffness`)",
     "the frequency of the support with the body as a rigid mass on it, sqrt(k / (m_s + M)) / 2 "
     "pi, > 0"},
    {"stiffness", "N/m", "required (or `frequency_hz`)",
     "k: the horizontal spring from the ground to the support, > 0"},
    {"damping_ratio", "-", "0",
     "the damping ratio of the support with the body as a rigid mass on it, c / (2 sqrt(k (m_s + "
     "M))), >= 0 (or `damping`)"},
    {"damping", "N s/m", "0", "c: the horizontal dashpot from the ground to the support, >= 0"},
    {"displacement", "m", "0", "u(0): the support's displacement from the ground at the start"},
    {"velocity", "m/s", "0",
     "u_dot(0): the support's velocity relative to the ground at the start"},
};

/// The key reference of [support], as the Markdown table of docs/case-file.md, written from
/// kSupportKeys with its begin and end marker lines (`flexrock keys --markdown`).
std::string support_key_reference();

/// A case, loaded and checked: everything a run needs.
struct Case {
  std::string source;       // path of the case file as given
  std::string stem;         // file name without extension, the default output base name
  std::string name;         // `name` (default: the stem)
  std::string description;  // `description` (default: empty)
  std::string body_type;    // body.type
  bool rigid = false;       // body.rigid: the modes were dropped
  BodyParameters body;      // the paper's parameters (already validated by Body)
  // a body of revolution ("cylinder", "body_of_revolution") as itself: with a record pair
  // `flexrock run` runs it in 3D (docs/theory.md §27); body is then its planar section
  std::optional<AxisymmetricBody> body3d;
  GroundMotion motion;  // [m/s^2] both components, scaled
  ExcitationComponent horizontal;
  ExcitationComponent vertical;            // type empty: no vertical component
  ExcitationComponent horizontal2;         // type empty: one horizontal component, not a pair
  std::shared_ptr<const RecordPair> pair;  // a record pair (horizontal2 given), else null
  std::optional<double> azimuth;           // [deg] excitation.azimuth_deg (pairs only)
  double azimuth_step = 0.0;               // [deg] excitation.azimuth_step_deg (pairs only)
  double excitation_scale = 1.0;  // [-] excitation.scale, or the factor to the target intensity
  InitialState initial;
  SimulationOptions options;  // options.output_dt is output.dt
  OutputSettings output;
  std::vector<std::string> notes;  // what reading changed in the data (re-orthogonalised shapes)
  std::string scaled_to;  // the target intensity excitation_scale was chosen for ("PGA 0.3 g")
  std::vector<std::string> input_files;  // the case file and its record files
  std::vector<BodyKeyRead> body_keys;    // the [body] keys read, in the table's order
  std::vector<Restraint> restraints;     // [[restraint]] tables (docs/theory.md §26); empty: none
  // [support]: the body stands on a support that moves with it (docs/theory.md §24); none: the
  // rigid floor
  std::optional<SupportParameters> support;
  std::optional<RockingFrame> frame;  // body.type = "rocking_frame": the frame (`body` is its
                                      // equivalent rigid body; run it with simulate_frame)
};

/// The ground motion of a case with a record pair at azimuth `beta_deg` [deg] (from H1 toward H2):
/// the projection H1 cos(beta) + H2 sin(beta) as a record in m/s^2, with the vertical component
/// and excitation.scale applied as for a single record. Throws std::logic_error without a pair.
GroundMotion azimuth_motion(const Case& c, double beta_deg);

/// The projected horizontal record of a pair at azimuth `beta_deg` [deg], in m/s^2 on H1's
/// samples, before excitation.scale: what azimuth_motion() runs (project_horizontal()).
std::vector<double> projected_record(const RecordPair& pair, double beta_deg);

/// Whether a case (or body) file has an [excitation] table. Throws InputError for a file that
/// cannot be read or parsed.
bool has_excitation(const std::string& path);

/// The most time-history rows a case may ask for (its duration / output.dt): a typo such as
/// output.dt = 1e-300 is refused naming the key instead of exhausting the memory.
inline constexpr std::size_t kMaxHistoryRows = 10'000'000;

/// Reads and checks a case file: the syntax, every key, the body (through the builders and
/// Body), the records it names (relative to the case file), the options and the initial state.
/// Throws InputError naming the file, the line and the key.
Case load_case(const std::string& path);

/// Reads only the [body] table of a case (or body) file: for `flexrock params`. Other tables are
/// ignored. `type` receives body.type; `files`, when given, gets every file read appended (the
/// file itself, nodes and shapes files); `frame`, when given, the frame of a rocking_frame
/// (else empty). Throws InputError like load_case.
/// A file with a [support] table is refused unless `support_ok` (the studies run bodies on the
/// rigid floor only; `flexrock params` reads the support with load_support).
BodyParameters load_body(const std::string& path, std::string* type = nullptr,
                         std::vector<std::string>* files = nullptr,
                         std::optional<RockingFrame>* frame = nullptr, bool support_ok = false);

/// The [support] of a case file with `body` standing on it, or none (for `flexrock params`).
/// Throws InputError like load_case.
std::optional<SupportParameters> load_support(const std::string& path, const BodyParameters& body);

/// Throws InputError when the case (or body) file at `path` has [[restraint]] tables: `what`
/// (a study, a qualification) would run the body without them. Restraints run with `flexrock run`.
void refuse_restraints(const std::string& path, const std::string& what);

/// The key reference of the body types (body.type), as the Markdown tables of docs/case-file.md,
/// written from the table of body types (model/builders.hpp) with its begin and end marker lines
/// (`flexrock keys --markdown`).
std::string body_key_reference();

/// The key reference of the synthetic motion types (excitation.*.type), as the Markdown table of
/// docs/case-file.md, written from the table of pulse types (excitation/pulses.hpp) with its
/// begin and end marker lines. `flexrock keys --markdown` prints it; a test checks that the docs
/// hold it unchanged.
std::string pulse_key_reference();

/// The key reference of [solver], as the Markdown table of docs/case-file.md, written from the
/// table of solver keys (sim/solver_keys.hpp) with its begin and end marker lines
/// (`flexrock keys --markdown`).
std::string solver_key_reference();

/// Levenshtein edit distance (insertions, deletions, substitutions), for "did you mean".
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `key` if it is close enough to be a likely typo, else empty.
std::string closest_key(std::string_view key, const std::vector<std::string>& candidates);

}  // namespace flexrock::io
