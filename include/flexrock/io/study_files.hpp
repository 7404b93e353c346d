// SPDX-License-Identifier: BSD-3-Clause
// Files of studies: spectrum specs and sweep manifests (TOML), the spectrum and sweep CSVs, what
// their journals (io/journal.hpp) may hold, and a sweep CSV read back for fragility fits.
// Every key, column and rule is documented in docs/studies.md. Errors are InputError with
// "<file>:<line>: key '<key>': expected ..., got ..." messages, as for case files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iosfwd>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "flexrock/io/journal.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/study/fragility.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/sweep.hpp"

namespace flexrock::io {

/// The most values a grid ({start, stop, count}, {start, stop, step} or an array) may hold, and
/// the most runs (grid cells, bodies x records x scales) a study may have: typos such as
/// count = 1e12 or step = 1e-9 are refused naming the key instead of exhausting the memory.
inline constexpr std::size_t kMaxGridPoints = 1'000'000;
inline constexpr std::size_t kMaxStudyRuns = 2'000'000;

// ---------------------------------------------------------------------------------------------
// spectrum

/// A spectrum spec file: a body and either a pulse grid or a record with scale factors.
struct SpectrumFile {
  std::string source;       // path as given
  std::string name;         // `name` (default: the file stem)
  std::string body_source;  // file the [body] table was read from
  BodyParameters body;      // validated
  bool is_record = false;   // true: `record` (one record x scales); false: `pulse` grid
  study::SpectrumSpec pulse;
  study::RecordSpectrumSpec record;
  std::string record_name;               // record.name (default: the record file's stem)
  std::vector<std::string> input_files;  // every file read: the spec, body and record files
  std::uint64_t hash = 0;  // FNV-1a of the spec and of the body and record files it names
};

/// Reads a spectrum spec (TOML). `body` is a path to a case or body file (relative to the spec)
/// or the spec has its own [body] table. Throws InputError naming file, line and key.
SpectrumFile load_spectrum_file(const std::string& path);

/// Columns of the spectrum CSV (one row per grid cell, row-major); with `sliding` (a spec with a
/// finite friction coefficient: SpectrumResult::sliding) the sliding columns follow; a grid given
/// in other units than SI (SpectrumResult::units) has columns in them (a_p_g, f_p_hz) after
/// the SI ones.
std::vector<std::string> spectrum_columns(bool sliding = false, const study::GridUnits& units = {});
/// One CSV line (no line end) of a cell (with the sliding fields when result.sliding).
std::string spectrum_row(const study::SpectrumResult& result, const study::SpectrumCell& cell,
                         double g);
/// Columns of the boundary CSV (one row per frequency column), with those in the grid's units
/// as for spectrum_columns.
std::vector<std::string> boundary_columns(const study::GridUnits& units = {});
/// One CSV line (no line end) of a column's minimum overturning amplitude.
std::string boundary_row(const study::SpectrumResult& result, const study::OverturnBoundary& b,
                         bool normalized, double g);
/// The whole spectrum CSV (header + cells) and boundary CSV (header + rows).
void write_spectrum_csv(std::ostream& out, const study::SpectrumResult& result, double g);
void write_boundary_csv(std::ostream& out, const study::SpectrumResult& result, bool normalized,
                        double g);

// ---------------------------------------------------------------------------------------------
// sweep

/// A sweep manifest: bodies x records x scales, with the solver options.
struct SweepManifest {
  std::string source;  // path as given
  study::SweepSpec spec;
  std::uint64_t hash = 0;  // FNV-1a of the manifest, the body and record files it names
  std::vector<std::string> input_files;  // every file read: the manifest, bodies, records
};

/// Reads a sweep manifest (TOML): [[body]] tables naming case/body files, [[record]] tables
/// naming record files (format, units, dt), a [scales] table, optional [solver]. Relative paths
/// are relative to the manifest. Throws InputError naming file, line and key.
SweepManifest load_sweep_manifest(const std::string& path);

/// Columns of the sweep CSV; with `sliding` (study::has_friction of the spec) the sliding columns
/// follow.
std::vector<std::string> sweep_columns(bool sliding = false);
/// Columns of a spec's sweep CSV: those above with the requested intensity measures
/// (SweepSpec::measures) after pgv_m_per_s, and the sliding columns if it has friction.
std::vector<std::string> sweep_columns(const study::SweepSpec& spec);

/// The column references of the spectrum, boundary, sweep, sliding and fragility fit CSVs, as the
/// Markdown tables of docs/studies.md, written from the tables of columns with their begin and end
/// marker lines (`flexrock keys --markdown`).
std::string study_column_reference();
/// One CSV line (no line end) of a row; its first field is the run index. With friction
/// (study::has_friction) it ends with the sliding fields.
std::string sweep_row(const study::SweepSpec& spec, const study::SweepRow& row);

/// What the line of run `index` in a sweep journal (io::Journal) must be: the run's CSV line,
/// whose index, body, record, scale, PGA, PGV and duration are those the manifest gives that
/// run, with a field per column, a known outcome and status, and numbers where numbers belong.
/// `spec` must outlive the check.
JournalCheck sweep_journal_check(const study::SweepSpec& spec);

/// The same for a spectrum journal: runs 0 .. cells-1 are the cells' CSV lines (row-major), then
/// one boundary line per column (when bisecting). `grid` is study::spectrum_grid (or
/// record_spectrum_grid) of the spec; `normalized` and `g` as for boundary_row.
JournalCheck spectrum_journal_check(const study::SpectrumResult& grid, bool normalized, double g);

// ---------------------------------------------------------------------------------------------
// rows as data: the tables of columns (name, unit, type) drive the header, the writer, the reader
// and the Python arrays; text exists only in the files

/// How a study CSV field is written and read back, and the dtype of its Python array.
enum class ColumnType {
  kInteger,  // indices, counts, flags: decimal digits
  kReal,     // [SI] the shortest text that reads back to the same double; empty: no finite value
  kText,     // names and classes (outcome, status, regime): no comma, quote or line end
};

/// One field of a row, of its column's type.
using FieldValue = std::variant<long long, double, std::string>;

/// A column of a study CSV as its table declares it.
struct ColumnInfo {
  std::string name;
  std::string unit;
  ColumnType type = ColumnType::kReal;
};

/// The columns of a spec's sweep CSV (the names of sweep_columns(spec)) with units and types.
std::vector<ColumnInfo> sweep_column_info(const study::SweepSpec& spec);
/// The fields of a row, one per column of sweep_column_info(spec); a real the run did not have
/// (not finite) is written empty.
std::vector<FieldValue> sweep_values(const study::SweepSpec& spec, const study::SweepRow& row);
/// The columns of the spectrum CSV (spectrum_columns(sliding, units)) with units and types.
std::vector<ColumnInfo> spectrum_column_info(bool sliding = false,
                                             const study::GridUnits& units = {});
/// Columns of the boundary CSV, and the fields of a column's boundary, one per column (as
/// boundary_row writes them).
std::vector<ColumnInfo> boundary_column_info(const study::GridUnits& units = {});
std::vector<FieldValue> boundary_values(const study::SpectrumResult& result,
                                        const study::OverturnBoundary& b, bool normalized,
                                        double g);
/// The fields of a cell, one per column of spectrum_column_info(result.sliding).
std::vector<FieldValue> spectrum_values(const study::SpectrumResult& result,
                                        const study::SpectrumCell& cell, double g);
/// A field's text in a study CSV or journal.
std::string format_field(const FieldValue& v);

/// The row of run `index` read back from its CSV line (sweep_row): the run's indices from the
/// index, what the run found from the fields. The line must be exactly what sweep_row writes for
/// that row (so a file written from rows read back has the bytes the runs wrote); throws
/// InputError saying which field is wrong. Reals written empty read back as NaN.
study::SweepRow read_sweep_row(const study::SweepSpec& spec, std::size_t index,
                               const std::string& line);
/// The same for cell `index` of a spectrum (`grid` as for spectrum_journal_check): the grid's
/// cell with its run read back from the line (spectrum_row).
study::SpectrumCell read_spectrum_cell(const study::SpectrumResult& grid, std::size_t index,
                                       const std::string& line, double g);
/// The boundary of a column read back from its line (boundary_row; `normalized` and `g` as
/// there): what the bisection found, with computed = true. Reals written empty read back as NaN.
study::OverturnBoundary read_boundary(const study::SpectrumResult& grid, std::size_t column,
                                      const std::string& line, bool normalized, double g);

// ---------------------------------------------------------------------------------------------
// fragility input

/// A CSV file read as text: the header's column names and the rows' fields.
struct CsvTable {
  std::string source;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::size_t> lines;  // 1-based file line of each row
  /// Index of the named column; throws InputError naming the file and the columns there are.
  std::size_t column(const std::string& name) const;
};

/// Reads a comma-separated file with a header row (no quoting). Every row must have as many
/// fields as the header. Throws InputError with file:line.
CsvTable read_csv_table(const std::string& path);

/// What a fragility fit counts as failure (a damage state's outcome).
enum class FragilityOutcome {
  kOverturned,      // the run overturned
  kUplift,          // it left full contact: any outcome class but no_uplift
  kTheta,           // max theta/alpha > level [-]
  kEnergy,          // energy lost > level [J]
  kOffset,          // peak sliding offset > level [m]
  kResidualOffset,  // |residual sliding offset| > level [m]
};

/// One row per outcome: its name (--outcome, --state), the sweep column it reads, whether it
/// takes a level, whether the column is one of the sliding ones (a sweep with finite friction),
/// and its --state form for messages.
struct FragilityOutcomeInfo {
  FragilityOutcome outcome;
  const char* name;
  const char* column;
  bool levelled;          // failure: the column's value above the level (or overturned)
  bool sliding;           // the column exists only with a finite friction coefficient
  const char* state_doc;  // "theta:X (max theta/alpha > X)"
  const char* what;       // what fails, as the fit is titled: "overturning", "energy lost > "
  const char* unit;       // after the level of a levelled outcome: "", " J", " m"
};
inline constexpr FragilityOutcomeInfo kFragilityOutcomes[] = {
    {FragilityOutcome::kOverturned, "overturned", "overturned", false, false, "overturned",
     "overturning", ""},
    {FragilityOutcome::kUplift, "uplift", "outcome", false, false, "uplift", "uplift", ""},
    {FragilityOutcome::kTheta, "theta", "max_theta_over_alpha", true, false,
     "theta:X (max theta/alpha > X)", "max theta/alpha > ", ""},
    {FragilityOutcome::kEnergy, "energy", "energy_lost_J", true, false,
     "energy:X (energy lost > X J)", "energy lost > ", " J"},
    {FragilityOutcome::kOffset, "offset", "max_offset_m", true, true,
     "offset:X (peak sliding offset > X m)", "peak sliding offset > ", " m"},
    {FragilityOutcome::kResidualOffset, "residual_offset", "final_offset_m", true, true,
     "residual_offset:X (|residual offset| > X m)", "residual offset > ", " m"},
};
/// The row of an outcome, and of a name (nullptr if none).
const FragilityOutcomeInfo& fragility_outcome(FragilityOutcome outcome);
const FragilityOutcomeInfo* find_fragility_outcome(std::string_view name);

/// The kind of a fit's intensity measure: a column every sweep writes, or one of the sweep's
/// [intensity] table.
enum class FragilityMeasureKind { kPga, kPgaG, kPgv, kScale, kRequestedLevel, kIntensity };

/// An intensity measure of a fit, typed: what it is, the sweep column it reads and its unit.
struct FragilityMeasure {
  FragilityMeasureKind kind = FragilityMeasureKind::kPga;
  std::string name = "pga";             // as given: "pga", "pga_g", "sa:0.5", ...
  std::string column = "pga_m_per_s2";  // the sweep CSV column
  std::string unit = "m/s^2";           // requested_level: "-" (the file's requested_units)
  study::MeasureRequest request;        // kIntensity: the measure, its period and damping
};
/// The measure so named (fragility_measures()); throws InputError listing the names.
FragilityMeasure fragility_measure(const std::string& name);

/// What a fragility fit of a sweep CSV counts as failure, by names (see FragilityOutcome).
struct FragilityQuery {
  std::string im = "pga";              // fragility_measures(): "pga" [m/s^2], "pga_g" [g], "pgv"
                                       // [m/s], "scale" [-], "pgd" [m], "sa:0.5" [m/s^2], ...
  std::string outcome = "overturned";  // "overturned", "uplift" (left full contact: any class
                                       // but no_uplift), "theta" (max theta/alpha > level),
                                       // "energy" (energy lost > level [J]), "offset" (peak
                                       // sliding offset > level [m]), "residual_offset"
                                       // (|residual offset| > level [m]); the last two need a
                                       // sweep CSV with the sliding columns
  double level = 0.0;                  // threshold of all but "overturned"
  std::string body;                    // only rows of this body (empty: every body)
  // the rows of one record pair's azimuths (`<H1>+<H2>@<beta>`) at one level are one
  // observation: failed at any azimuth, its measure the median over them ("rotd50:<im>")
  bool worst_azimuth = false;
};

/// The intensity measures a fit may use (FragilityQuery::im), as help and errors list them:
/// pga, pga_g, pgv, scale, requested_level, then every measure of
/// flexrock::intensity_measures() ("sa:T[:zeta]" for Sa at period T [s], damping ratio zeta,
/// 0.05 by default).
std::vector<std::string> fragility_measures();
/// The sweep CSV column of an intensity measure so named; throws InputError listing the names.
std::string fragility_im_column(const std::string& im);

/// The observations of one body for a fit.
struct FragilityData {
  std::string body;
  std::vector<double> im;
  std::vector<int> failed;
  std::size_t excluded = 0;  // rows left out: status stopped or contact_lost
  // the record of each observation (its `record` column; empty names if the file has none)
  std::vector<std::string> record;
  std::string im_name;  // the intensity measure, as --im names it ("pga_g", "sa:1", ...)
  std::string im_unit;  // its unit ("g", "m/s^2"; requested_level: the sweep's requested_units)
};

/// Checks a sweep CSV read without its manifest as a resume checks a journal line, so far as
/// no manifest is needed: each run index once, an outcome known and its `overturned` flag the
/// one that goes with it, `overturn_edge` 0, 1 or 2, counts, known status and regime words,
/// the run's figures finite or empty (each check where the file has the column). Throws
/// InputError naming file:line and the column.
void check_sweep_table(const CsvTable& table);

/// Groups a sweep CSV's rows by body (in first-appearance order) and turns each row into an
/// (IM, outcome) pair. Checks the table first (check_sweep_table). Throws InputError for
/// unknown columns, bodies or outcome names, and for fields that are not numbers (file:line).
std::vector<FragilityData> fragility_data(const CsvTable& table, const FragilityQuery& query);

/// Columns of the fragility fit CSV, and one line of it.
std::vector<std::string> fragility_columns();
std::string fragility_row(const FragilityData& data, const study::FragilityFit& fit);

/// A damage state of a fit of several at once (`flexrock fragility --state`): "overturned",
/// "uplift" (any class but no_uplift), or "theta:X", "energy:X", "offset:X",
/// "residual_offset:X" (the FragilityQuery outcome of that name with level X > 0).
struct DamageState {
  std::string label;                                         // as given, e.g. "theta:0.5"
  FragilityOutcome outcome = FragilityOutcome::kOverturned;  // what fails
  double level = 0.0;  // threshold of a levelled outcome (0 for overturned and uplift)
};
/// Parses a damage state; throws InputError saying what is expected.
DamageState damage_state(const std::string& text);
/// The observations of fragility_data for a typed measure and damage state (`body` empty: every
/// body).
std::vector<FragilityData> fragility_data(const CsvTable& table, const FragilityMeasure& measure,
                                          const DamageState& state, const std::string& body = {},
                                          bool worst_azimuth = false);
/// The fit CSV of several damage states: the columns above with `state` after `body`, and a
/// line of it.
std::vector<std::string> fragility_state_columns();
std::string fragility_state_row(const FragilityData& data, const study::FragilityFit& fit,
                                const std::string& state);

// ---------------------------------------------------------------------------------------------

/// 64-bit FNV-1a of bytes, continued from `h` (for journal headers and lines).
std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h = 1469598103934665603ULL);

}  // namespace flexrock::io
