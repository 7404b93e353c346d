// SPDX-License-Identifier: BSD-3-Clause
// Files of studies: spectrum specs and sweep manifests (TOML), the spectrum and sweep CSVs, the
// sweep journal that makes a sweep resumable, and a sweep CSV read back for fragility fits.
// Every key, column and rule is documented in docs/studies.md. Errors are InputError with
// "<file>:<line>: key '<key>': expected ..., got ..." messages, as for case files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

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
};

/// Reads a spectrum spec (TOML). `body` is a path to a case or body file (relative to the spec)
/// or the spec has its own [body] table. Throws InputError naming file, line and key.
SpectrumFile load_spectrum_file(const std::string& path);

/// Columns of the spectrum CSV (one row per grid cell, row-major).
std::vector<std::string> spectrum_columns();
/// One CSV line (no line end) of a cell.
std::string spectrum_row(const study::SpectrumResult& result, const study::SpectrumCell& cell,
                         double g);
/// Columns of the boundary CSV (one row per frequency column).
std::vector<std::string> boundary_columns();
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

/// Columns of the sweep CSV.
std::vector<std::string> sweep_columns();
/// One CSV line (no line end) of a row; its first field is the run index.
std::string sweep_row(const study::SweepSpec& spec, const study::SweepRow& row);

/// The journal of a sweep: "OUT.partial", a header line with the manifest's hash and the run
/// count, then one CSV line per finished run, appended and flushed as runs finish (in any
/// order). Opening an existing journal reads its finished lines, drops a torn last line (no
/// line end: the writer was killed mid-line) and truncates the file to the complete lines.
class SweepJournal {
 public:
  /// Opens (or creates) the journal at `path`. A journal whose header differs (another manifest
  /// or another run count) is an InputError saying so; a journal with the same header resumes.
  SweepJournal(std::string path, std::uint64_t hash, std::size_t runs);
  ~SweepJournal();
  SweepJournal(const SweepJournal&) = delete;
  SweepJournal& operator=(const SweepJournal&) = delete;

  /// Finished lines by run index (read at opening, plus those appended since).
  const std::map<std::size_t, std::string>& finished() const { return finished_; }
  /// Appends one finished run's line and flushes it to the operating system.
  void append(std::size_t index, const std::string& line);
  /// Adds lines (e.g. gathered from other processes) without writing them.
  void remember(std::size_t index, const std::string& line) { finished_[index] = line; }
  /// Closes and deletes the journal file.
  void remove();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::map<std::size_t, std::string> finished_;
};

/// The header line of a journal (no line end).
std::string journal_header(std::uint64_t hash, std::size_t runs);
/// The run index of a sweep CSV line (its first field); throws InputError if it has none.
std::size_t row_index(const std::string& line);

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

/// What a fragility fit of a sweep CSV counts as failure.
struct FragilityQuery {
  std::string im = "pga";              // "pga" [m/s^2], "pga_g" [g], "pgv" [m/s] or "scale" [-]
  std::string outcome = "overturned";  // "overturned", "theta" (max theta/alpha > level),
                                       // "energy" (energy lost > level [J])
  double level = 0.0;                  // threshold of "theta" and "energy"
  std::string body;                    // only rows of this body (empty: every body)
};

/// The observations of one body for a fit.
struct FragilityData {
  std::string body;
  std::vector<double> im;
  std::vector<int> failed;
  std::size_t excluded = 0;  // rows left out: status stopped or contact_lost
};

/// Groups a sweep CSV's rows by body (in first-appearance order) and turns each row into an
/// (IM, outcome) pair. Throws InputError for unknown columns, bodies or outcome names, and for
/// fields that are not numbers (file:line).
std::vector<FragilityData> fragility_data(const CsvTable& table, const FragilityQuery& query);

/// Columns of the fragility fit CSV, and one line of it.
std::vector<std::string> fragility_columns();
std::string fragility_row(const FragilityData& data, const study::FragilityFit& fit);

// ---------------------------------------------------------------------------------------------

/// 64-bit FNV-1a of bytes, continued from `h` (for journal headers).
std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h = 1469598103934665603ULL);

}  // namespace flexrock::io
