// SPDX-License-Identifier: BSD-3-Clause
// Results on disk: the time-history CSV, the event log CSV and the summary JSON of one run.
// Column names and JSON keys are stable and documented in docs/case-file.md. Every file is
// written atomically: to "PATH.tmp.<pid>", then renamed onto PATH, so a reader never sees half a
// file and a failed write leaves nothing behind.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <variant>
#include <vector>

#include "flexrock/io/case_file.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock::io {

/// Version of the summary JSON layout; raised only when keys are removed or change meaning.
inline constexpr int kSummarySchemaVersion = 2;

/// Writes a file atomically: `write` fills a stream opened on "PATH.tmp.<pid>" (a name too long
/// for NAME_MAX with the suffix is cut and ends in a hash of the whole name), which is flushed to
/// the disk (fsync) and renamed onto `path`; the directory is then synced too. Temporaries of
/// the same path left by processes that no longer run (killed by SIGKILL, a crash) are removed
/// first. Throws std::runtime_error naming the path and the operating system's reason (e.g.
/// "No space left on device") if the file cannot be written, or if `path` exists and is not a
/// regular file; the temporary file is removed. SIGINT, SIGTERM and SIGHUP left at their default
/// action get a handler (installed on the first call) that removes the temporaries being written
/// before the process dies of the signal: an interrupted program leaves complete files or none.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

/// Column names of the time history for a body with `modes` modes, each with its unit suffix:
/// time_s, phase, theta_rad, theta_dot_rad_per_s, uplift_m, q1, ..., q1_dot_per_s, ...,
/// base_acc_x_m_per_s2, base_acc_y_m_per_s2, reaction_x_N, reaction_y_N, resultant_m,
/// friction_demand, kinetic_J, potential_J, input_work_J, damping_loss_J, impact_loss_J.
std::vector<std::string> time_history_columns(int modes);

/// The time history's values, one vector per column of time_history_columns(modes), one
/// element per output time: what write_time_history prints (the Python module's arrays).
std::vector<std::vector<double>> time_history_values(const SimulationResult& result,
                                                     const Body& body);

/// The column reference of the time history, as the Markdown table of docs/case-file.md, written
/// from the table of columns with its begin and end marker lines (`flexrock keys --markdown`).
std::string time_history_column_reference();

/// The time history as CSV text (a header row, then one row per output time).
/// With `support` (a run on a [support]), the support's columns follow the body's.
void write_time_history(std::ostream& out, const SimulationResult& result, const Body& body,
                        const SupportRunResult* support = nullptr);

/// Column names of the event log, from its table of columns (src/io/outputs.cpp): time_s,
/// event, edge, theta_rad, theta_dot_before_rad_per_s, theta_dot_after_rad_per_s, energy_loss_J,
/// impulse_x_N_s, impulse_y_N_s, friction_demand.
std::vector<std::string> event_columns();

/// One column of the event log: numbers, or text (the event kind's name).
using EventColumnValues = std::variant<std::vector<double>, std::vector<std::string>>;

/// The event log as columns, in the order of event_columns(), one element per event: what
/// write_events prints (the Python module's arrays).
std::vector<EventColumnValues> event_values(const SimulationResult& result);

/// The column reference of the event log, as the Markdown table of docs/case-file.md, written
/// from the table of columns with its begin and end marker lines (`flexrock keys --markdown`).
std::string event_column_reference();

/// The event log as CSV text.
void write_events(std::ostream& out, const SimulationResult& result);

/// Where a run's outputs went (empty: not written), for the summary.
struct OutputPaths {
  std::string time_history;
  std::string summary;
  std::string events;
};

/// The summary JSON document (pretty-printed, keys as documented).
/// With `support` (a run on a [support]), a "support" object holds its parameters and peaks.
std::string summary_json(const Case& c, const Body& body, const SimulationResult& result,
                         const OutputPaths& paths, const SupportRunResult* support = nullptr);

/// The output paths of a case: `c.output` with relative paths taken relative to `output_dir`.
OutputPaths output_paths(const Case& c, const std::string& output_dir);

/// Throws InputError if an output is one of the case's input files (c.input_files) or two
/// outputs are the same file (io::check_distinct_files).
void check_output_paths(const Case& c, const OutputPaths& paths);

/// Writes the outputs `c.output` asks for, after check_output_paths(): first removes an old
/// summary at the summary path, then writes the time history, the event log and the summary
/// last. So a summary on disk vouches for the files it names under "outputs": they are complete
/// and from the same run. A failed or interrupted rerun can leave a new time history beside an
/// old event log, but never a summary beside files of another run. Relative paths are taken
/// relative to `output_dir` (created if missing). Returns the paths written.
OutputPaths write_outputs(const Case& c, const Body& body, const SimulationResult& result,
                          const std::string& output_dir, const SupportRunResult* support = nullptr);

}  // namespace flexrock::io
