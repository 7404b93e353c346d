// SPDX-License-Identifier: BSD-3-Clause
// Case files: one TOML file describes a body, its excitation, the solver options and the outputs
// of one simulation. Every key is documented in docs/case-file.md with its unit and default.
//
// Errors are flexrock::InputError with messages of the form
//   "<file>:<line>: key '<table.key>': expected <what>, got <value>"
// and unknown keys are rejected with the closest known key ("did you mean ...").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"

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

/// A case, loaded and checked: everything a run needs.
struct Case {
  std::string source;       // path of the case file as given
  std::string stem;         // file name without extension, the default output base name
  std::string name;         // `name` (default: the stem)
  std::string description;  // `description` (default: empty)
  std::string body_type;    // body.type
  bool rigid = false;       // body.rigid: the modes were dropped
  BodyParameters body;      // the paper's parameters (already validated by Body)
  GroundMotion motion;      // [m/s^2] both components, scaled
  ExcitationComponent horizontal;
  ExcitationComponent vertical;   // type empty: no vertical component
  double excitation_scale = 1.0;  // [-] excitation.scale, or the factor to the target intensity
  InitialState initial;
  SimulationOptions options;  // options.output_dt is output.dt
  OutputSettings output;
  std::vector<std::string> notes;  // what reading changed in the data (re-orthogonalised shapes)
  std::string scaled_to;  // the target intensity excitation_scale was chosen for ("PGA 0.3 g")
  std::vector<std::string> input_files;  // the case file and its record files
  std::vector<BodyKeyRead> body_keys;    // the [body] keys read, in the table's order
};

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
/// file itself, nodes and shapes files). Throws InputError like load_case.
BodyParameters load_body(const std::string& path, std::string* type = nullptr,
                         std::vector<std::string>* files = nullptr);

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
