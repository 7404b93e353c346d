// SPDX-License-Identifier: BSD-3-Clause
// A study as a session: its plan (the runs left), its journal (io/journal.hpp) over one or several
// processes, the runs of this process, and the final file. The command line and Python run,
// resume and finish a sweep through the same code, so that either can finish a sweep the other
// started, with the same bytes. The processes talk through StudyTransport: one process by
// default; the command line implements it with MPI.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flexrock/io/journal.hpp"
#include "flexrock/io/study_files.hpp"
#include "flexrock/io/study_shards.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/study/parallel.hpp"
#include "flexrock/study/spectrum.hpp"
#include "flexrock/study/sweep.hpp"

namespace flexrock::io {

/// How the processes of a study share it: this process's rank among `size` and three collective
/// calls (every process makes each, in the same order). The default is one process.
class StudyTransport {
 public:
  virtual ~StudyTransport() = default;
  virtual int rank() const { return 0; }
  virtual int size() const { return 1; }
  /// Every process's bytes, concatenated in rank order, on rank 0 (the others get "").
  virtual std::string gather(const std::string& mine) const { return mine; }
  /// Rank 0's bytes on every process.
  virtual std::string broadcast(const std::string& bytes) const { return bytes; }
  /// True on every process if it is true on any.
  virtual bool any(bool v) const { return v; }
  bool root() const { return rank() == 0; }
};

/// The journal of a study over one or several processes: rank 0 holds PATH and merges into it
/// what other processes left in PATH.rank<r> when an interrupted study was run by several;
/// every process learns the lines finished before this start; the others journal their runs to
/// PATH.rank<r> (created with their first line). Lines are the rows as the CSV writes them.
class StudyJournal {
 public:
  /// Opens the journal (io::Journal: `kind`, `inputs`, `runs`, `check`) on rank 0 and tells
  /// every process what it holds; every process throws alike when rank 0 cannot use it.
  StudyJournal(const StudyTransport& transport, std::string path, std::string kind,
               std::uint64_t inputs, std::size_t runs, JournalCheck check);
  ~StudyJournal();
  StudyJournal(const StudyJournal&) = delete;
  StudyJournal& operator=(const StudyJournal&) = delete;

  const std::string& path() const { return path_; }
  /// Lines finished before this start, by run index (on every process).
  const std::map<std::size_t, std::string>& known() const { return known_; }
  /// A run finished here: into this process's journal. Callers serialize.
  void append(std::size_t index, const std::string& line);
  /// After the work (every process calls it): every line of every process, on rank 0; the
  /// others get an empty map.
  const std::map<std::size_t, std::string>& gather();
  /// A line found on rank 0 after gather() (a bisection done there).
  void append_on_root(std::size_t index, const std::string& line);
  /// Every process calls it last: with rank 0's `outputs_written`, every journal is deleted;
  /// without, they stay for the next start.
  void finish(bool outputs_written);

 private:
  void open_root();

  const StudyTransport& transport_;
  std::string path_, kind_;
  std::uint64_t inputs_;
  std::size_t runs_;
  JournalCheck check_;
  std::unique_ptr<Journal> main_;             // rank 0
  std::unique_ptr<Journal> own_;              // other ranks
  std::map<std::size_t, std::string> known_;  // finished before this start
  std::map<std::size_t, std::string> added_;  // other ranks: finished here
};

/// One process's transport of a study alone (the default of a session).
const StudyTransport& single_process();

/// A sweep from its manifest to its CSV: `output` is written once every run is finished, the
/// runs finished so far are kept in the journal `output`.partial (and .rank<r>), and a session
/// opened on the same manifest and output goes on from there. The CSV has the same bytes
/// whether the sweep ran at once or was interrupted and resumed, by the command line or by
/// Python, on any number of threads and processes.
class SweepSession {
 public:
  /// Checks every run of the manifest (study::validate) and that no input is the output or its
  /// journal, then opens the journal: before it exists, a sweep that could not run leaves none
  /// behind. Throws InputError for bad input or a journal of other inputs or a damaged one. The
  /// session keeps its own copy of the manifest. With `shard` (one process only), the session is
  /// shard k of N (io/study_shards.hpp): its share is the runs of index i mod N == k - 1, its
  /// journal shard_path(output).partial, and finish() writes the shard file
  /// shard_path(output, shard) in place of the CSV (merge_shards() makes the CSV).
  SweepSession(SweepManifest manifest, std::string output,
               const StudyTransport& transport = single_process(),
               std::optional<Shard> shard = std::nullopt);
  ~SweepSession();
  SweepSession(const SweepSession&) = delete;
  SweepSession& operator=(const SweepSession&) = delete;

  std::size_t runs() const { return runs_; }
  /// Runs finished before this start (in the journal).
  std::size_t resumed() const { return journal_.known().size(); }
  /// Runs left to every process.
  std::size_t remaining() const { return runs_ - resumed(); }
  /// The runs left to this process: every size-th of those left.
  const std::vector<std::size_t>& share() const { return share_; }
  const std::string& output() const { return output_; }
  const std::string& journal_path() const { return journal_.path(); }

  /// Runs this process's share on options.threads workers (options.rank and ranks are the
  /// transport's), journaling each row as it finishes. A stop request (options.cancel) ends it
  /// between runs, every finished one journaled; run() again goes on with the runs left. Throws
  /// std::runtime_error after finish().
  void run(const study::RunOptions& options);
  /// After run() on every process, when none was stopped: gathers the rows on rank 0, writes
  /// the CSV there (atomically) and deletes the journals. Returns every row in index order on
  /// rank 0 (empty on the others). Throws std::runtime_error when the CSV cannot be written
  /// or when a run is not finished (run() stopped or not called; the journals are kept). A shard
  /// writes its shard file and returns its own rows.
  std::vector<study::SweepRow> finish();
  /// The file finish() writes: the CSV, or a shard's shard file.
  std::string written() const { return shard_ ? shard_path(output_, *shard_) : output_; }
  const SweepManifest& manifest() const { return manifest_; }

 private:
  // throws std::runtime_error naming `call` once finish() has written the CSV
  void require_open(const char* call) const;
  // finish() of a shard: its lines into its shard file
  std::vector<study::SweepRow> finish_shard(const std::map<std::size_t, std::string>& lines);

  SweepManifest manifest_;
  std::string output_;
  const StudyTransport& transport_;
  std::optional<Shard> shard_;
  // rows computed here or read back from the journal (by the journal's check: before journal_)
  std::map<std::size_t, study::SweepRow> rows_;
  std::size_t runs_ = 0;
  StudyJournal journal_;
  std::vector<std::size_t> share_;
  bool finished_ = false;  // finish() wrote the CSV: run() and finish() refuse
};

/// A spectrum from its spec file to its CSVs: the cells CSV `output` and, when it bisects, the
/// boundary CSV `boundary_output`, written once every cell and boundary is finished; the finished
/// ones are kept in the journal `output`.partial (cells by index, then one boundary per column)
/// and a session opened on the same spec, bisection and output goes on from there, with the same
/// bytes on any number of threads and processes.
class SpectrumSession {
 public:
  /// Builds the grid, checking every run it makes (study::spectrum_grid), and that no input is
  /// an output, then opens the journal. `file.pulse.bisect` / `file.record.bisect` say whether it
  /// bisects (`boundary_output` is unused when not). Throws InputError as SweepSession does.
  /// With `shard`, shard k of N as SweepSession's: its share is the columns (a record: the rows)
  /// j mod N == k - 1 with their boundaries; a record spectrum that bisects cannot be split so
  /// (its bisection needs every row's outcome) and throws InputError.
  SpectrumSession(SpectrumFile file, std::string output, std::string boundary_output,
                  const StudyTransport& transport = single_process(),
                  std::optional<Shard> shard = std::nullopt);
  ~SpectrumSession();
  SpectrumSession(const SpectrumSession&) = delete;
  SpectrumSession& operator=(const SpectrumSession&) = delete;

  const SpectrumFile& file() const { return file_; }
  const Body& body() const { return body_; }
  bool bisect() const { return bisect_; }
  /// The grid with nothing run: alpha, p, every cell's amplitudes, the boundary slots.
  const study::SpectrumResult& grid() const { return grid_; }
  std::size_t cells() const { return grid_.cells.size(); }
  /// Cells and boundaries (the journal's runs).
  std::size_t runs() const { return grid_.cells.size() + grid_.boundary.size(); }
  std::size_t resumed() const { return journal_.known().size(); }
  /// Cells left to this process (its share of the columns, or of a record's rows).
  std::size_t share_cells() const { return share_cells_; }
  const std::string& journal_path() const { return journal_.path(); }

  /// Runs this process's share (study::compute_spectrum or compute_record_spectrum with the
  /// journal as its resume), journaling each cell and boundary as it finishes. A stop request
  /// (options.cancel) ends it between runs; run() again goes on with those left. Throws
  /// std::runtime_error after finish().
  void run(const study::RunOptions& options);
  /// After run() on every process, when none was stopped: gathers the lines on rank 0, bisects
  /// a record spectrum run by several processes there (`cancel` stops it: then nothing is
  /// written, the journals stay and the result has no cells), writes the CSVs (the boundary
  /// last, an old one removed first) and deletes the journals. Returns the whole result on rank
  /// 0, every cell and boundary read back as data (empty on the others). Throws
  /// std::runtime_error when an output cannot be written or when a cell or boundary is not
  /// finished (run() stopped or not called; the journals are kept). A shard writes its shard
  /// file and returns the grid with its own cells and boundaries marked computed.
  study::SpectrumResult finish(const std::atomic<bool>* cancel = nullptr);
  /// The file finish() writes first: the cells CSV, or a shard's shard file.
  std::string written() const { return shard_ ? shard_path(output_, *shard_) : output_; }

 private:
  std::string unfinished(std::size_t done, std::size_t of, const char* what) const;
  void require_open(const char* call) const;
  study::SpectrumResult finish_shard(const std::map<std::size_t, std::string>& lines);

  SpectrumFile file_;
  Body body_;
  std::string output_, boundary_output_;
  const StudyTransport& transport_;
  std::optional<Shard> shard_;
  bool bisect_ = true;
  study::SpectrumResult grid_;
  StudyJournal journal_;
  study::SpectrumResume resume_;
  std::size_t share_cells_ = 0;
  bool finished_ = false;  // finish() wrote the CSVs: run() and finish() refuse
};

/// A sweep CSV read back as rows through the sweep's columns (read_sweep_row for every line):
/// every run of the manifest once, in index order. Throws InputError naming the file and line.
std::vector<study::SweepRow> read_sweep_csv(const study::SweepSpec& spec, const std::string& path);

}  // namespace flexrock::io
