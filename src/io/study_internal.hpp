// SPDX-License-Identifier: BSD-3-Clause
// What the readers and writers of study files share (src/io/study_*.cpp): the texts of numbers
// and names, the checked reads of grids, [solver] tables, records and record suites, the sliding
// columns that end the spectrum and sweep rows, the fields of a journaled line, and the column
// reference of docs/studies.md. Internal to flexrock_io.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/io/study_files.hpp"
#include "table_reader.hpp"

namespace flexrock::io::study_detail {

using detail::describe;
using detail::line_of;
// the checked reads of a table, shared with the case-file loader
using Keys = detail::TableReader;
// a field's value by its column's type (the variant's alternative)
using Value = FieldValue;

// shortest text that reads back to the same double (messages: "inf" and "nan" as such)
std::string num(double v);
// a number field of a study CSV or journal: the shortest text that reads back to the same
// double, empty where there is no finite value, never "inf" or "nan"
std::string field(double v);
std::string join(const std::vector<std::string>& v, const char* sep = ", ");
// a regular file's bytes (read_input_file refuses FIFOs and devices)
std::string file_bytes(const std::string& path);

// a body file of a study: refuses a rocking_frame, whose runs the studies do not yet make within
// the frame's model (docs/theory.md §25: its contact checks and stops); `type` from load_body
inline void refuse_frame(const std::string& type, const std::string& path) {
  FLEXROCK_THROW_UNLESS(type != "rocking_frame",
                        path +
                            ": [body] type 'rocking_frame': studies (spectra, sweeps, "
                            "fragility, qualify) do not run rocking frames yet; run it as a "
                            "case (flexrock run), which checks the frame's contacts");
}

long long integer(const Value& v);
double real(const Value& v);
const std::string& text(const Value& v);

std::optional<study::Outcome> outcome_named(std::string_view name);
std::optional<Status> status_named(std::string_view name);
std::optional<study::Regime> regime_named(std::string_view name);
// the name's value, or InputError "unknown outcome/status ..."
study::Outcome outcome_value(const Value& v);
Status status_value(const Value& v);

// a list of numbers: an array, or a table {start, stop, count[, spacing]} or {start, stop,
// step}; nullopt when the key is absent
std::optional<std::vector<double>> grid_opt(Keys& r, std::string_view key, const std::string& unit);
// [solver]: the keys of a case file's [solver] table that make sense for a study (no t_end)
void read_solver(Keys& r, SimulationOptions& o, const BodyParameters& body);
// a record table {file, format, units, dt, name}; the record's bytes go into `hash`
Record read_record(Keys& r, std::string& name, std::uint64_t* hash,
                   std::vector<std::string>& files);
// a name usable as a CSV field (no commas, quotes or line ends), or InputError at `key`
void check_name(Keys& r, const std::string& key, const std::string& name);

// the records of a [[suite]] (study_suites.cpp); file bytes go into `hash`, paths into `files`
std::vector<study::SweepRecord> read_suite(Keys& r, std::uint64_t& hash,
                                           std::vector<std::string>& files);

// one column of what a study adds for a run with finite friction: name, unit, meaning and its
// field of a run. The same table ends the spectrum and the sweep rows (after their last column),
// only when friction is finite, so that a study without friction writes what it always did
struct SlidingColumn {
  const char* name;
  const char* unit;
  const char* doc;
  ColumnType type;
  Value (*get)(const study::RunSummary& r);
  void (*set)(study::RunSummary& r, const Value& v);
};
std::span<const SlidingColumn> sliding_columns();
void add_sliding_columns(std::vector<std::string>& v);
void add_sliding_fields(std::string& s, const study::RunSummary& r);

// the fields of a journaled line (study_journal.cpp)
std::vector<std::string_view> fields_of(std::string_view line);
// a finite number as field() writes it ("inf" and "nan" are never written)
bool is_number(std::string_view f);
// a field's text read back as a value of its column's type (a real left empty is NaN)
Value parse_field(std::string_view f, ColumnType type);
// the first field where a line and the line written back from what was read of it differ
std::string first_difference(const std::vector<std::string>& names, std::string_view line,
                             std::string_view again);

// the column reference of one table, as a Markdown table between begin and end markers;
// `source` is the file that holds the table
template <class Column>
std::string column_block(const char* what, const char* source, std::span<const Column> columns) {
  std::string s = std::string(
                      "<!-- begin: written by `flexrock keys --markdown` from the table "
                      "of ") +
                  what + " columns (" + source +
                  "); edit the table, not these lines -->\n"
                  "| column | unit | meaning |\n"
                  "|---|---|---|\n";
  for (const Column& c : columns) {
    s.append("| `").append(c.name).append("` | ").append(c.unit).append(" | ").append(c.doc);
    s.append(" |\n");
  }
  return s + "<!-- end: written by `flexrock keys --markdown` -->\n";
}
// each table's block, from the file that holds it
std::string spectrum_column_block();
std::string boundary_column_block();
std::string sweep_column_block();
std::string sliding_column_block();
std::string fragility_column_block();

}  // namespace flexrock::io::study_detail
