// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/io/study_session.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "flexrock/core/error.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/outputs.hpp"

namespace flexrock::io {

namespace {

namespace fs = std::filesystem;

// "index<TAB>line<NEWLINE>" records: the lines of finished runs between processes
std::string pack(const std::map<std::size_t, std::string>& lines) {
  std::string s;
  for (const auto& [k, v] : lines) s += std::to_string(k) + "\t" + v + "\n";
  return s;
}

std::map<std::size_t, std::string> unpack(const std::string& s) {
  std::map<std::size_t, std::string> out;
  std::istringstream in(s);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t tab = line.find('\t');
    out[std::stoul(line.substr(0, tab))] = line.substr(tab + 1);
  }
  return out;
}

std::string join_columns(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + v[i];
  return s;
}

}  // namespace

namespace {

// the journal of an output, or of a shard of it
std::string journal_of(const std::string& output, const std::optional<Shard>& shard) {
  return (shard ? shard_path(output, *shard) : output) + ".partial";
}

// a shard is one process: its split is by --shard, not by MPI ranks
void check_shard_transport(const std::optional<Shard>& shard, const StudyTransport& transport) {
  if (shard && transport.size() > 1) {
    throw InputError("--shard: a shard runs in one process; started as " +
                     std::to_string(transport.size()) +
                     " MPI processes, drop --shard (MPI splits the study) or mpirun");
  }
}

}  // namespace

const StudyTransport& single_process() {
  static const StudyTransport one;
  return one;
}

// ---------------------------------------------------------------------------------------------
// the journal over processes

StudyJournal::StudyJournal(const StudyTransport& transport, std::string path, std::string kind,
                           std::uint64_t inputs, std::size_t runs, JournalCheck check)
    : transport_(transport),
      path_(std::move(path)),
      kind_(std::move(kind)),
      inputs_(inputs),
      runs_(runs),
      check_(std::move(check)) {
  std::string known, failure;
  if (transport_.root()) {
    try {
      open_root();
      known = pack(main_->finished());
    } catch (const InputError& e) {
      failure = std::string("I") + e.what();
    } catch (const std::exception& e) {
      failure = std::string("R") + e.what();
    }
  }
  // every process stops alike when rank 0 cannot use the journal
  failure = transport_.broadcast(failure);
  if (!failure.empty()) {
    if (failure[0] == 'I') throw InputError(failure.substr(1));
    throw std::runtime_error(failure.substr(1));
  }
  known_ = unpack(transport_.broadcast(known));
}

StudyJournal::~StudyJournal() = default;

void StudyJournal::append(std::size_t index, const std::string& line) {
  if (transport_.root()) {
    main_->append(index, line);
    return;
  }
  if (!own_) {
    own_ = std::make_unique<Journal>(path_ + ".rank" + std::to_string(transport_.rank()), kind_,
                                     inputs_, runs_, check_);
  }
  own_->append(index, line);
  added_[index] = line;
}

const std::map<std::size_t, std::string>& StudyJournal::gather() {
  const std::map<std::size_t, std::string> all = unpack(transport_.gather(pack(added_)));
  if (!transport_.root()) return added_ = {};
  for (const auto& [i, line] : all) {
    if (!main_->finished().count(i)) main_->remember(i, line);
  }
  return main_->finished();
}

void StudyJournal::append_on_root(std::size_t index, const std::string& line) {
  main_->append(index, line);
}

void StudyJournal::finish(bool outputs_written) {
  if (!transport_.any(transport_.root() && outputs_written)) return;
  if (own_) own_->remove();
  if (main_) main_->remove();
}

void StudyJournal::open_root() {
  main_ = std::make_unique<Journal>(path_, kind_, inputs_, runs_, check_);
  // journals other processes left: merged, then deleted
  const fs::path p(path_);
  const std::string prefix = p.filename().string() + ".rank";
  std::vector<fs::path> others;
  std::error_code ec;
  for (const auto& e :
       fs::directory_iterator(p.parent_path().empty() ? fs::path(".") : p.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() > prefix.size() && name.starts_with(prefix) &&
        name.find_first_not_of("0123456789", prefix.size()) == std::string::npos) {
      others.push_back(e.path());
    }
  }
  for (const fs::path& o : others) {
    Journal other(o.string(), kind_, inputs_, runs_, check_);
    for (const auto& [i, line] : other.finished()) {
      const auto it = main_->finished().find(i);
      if (it == main_->finished().end()) {
        main_->append(i, line);
      } else if (it->second != line) {
        throw InputError(o.string() + ": run " + std::to_string(i) + " differs from its line in " +
                         path_ + ": delete one of the two journals");
      }
    }
    other.remove();
  }
}

// ---------------------------------------------------------------------------------------------
// the sweep

namespace {

// every run checked and the files kept apart before the journal exists: a sweep that could not
// run must not leave a journal behind
std::size_t checked_runs(const SweepManifest& m, const std::string& output,
                         const std::optional<Shard>& shard, const StudyTransport& transport) {
  study::validate(m.spec);
  std::vector<NamedPath> inputs;
  for (const std::string& f : m.input_files) inputs.push_back({"input", f});
  const std::string written = shard ? shard_path(output, *shard) : output;
  check_distinct_files(
      inputs, {{shard ? "shard file" : "output", written}, {"journal", journal_of(output, shard)}});
  check_shard_transport(shard, transport);
  return study::sweep_runs(m.spec).size();
}

// a journal line must be its run's CSV line (sweep_journal_check, which says what is wrong in
// the journal's words) and read back as that run's row, kept in `rows` (read once)
JournalCheck sweep_rows_check(const study::SweepSpec& spec,
                              std::map<std::size_t, study::SweepRow>& rows) {
  JournalCheck lines = sweep_journal_check(spec);
  return [&spec, &rows, lines](std::size_t index, const std::string& line) -> std::string {
    if (std::string why = lines(index, line); !why.empty()) return why;
    try {
      rows[index] = read_sweep_row(spec, index, line);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
}

}  // namespace

SweepSession::SweepSession(SweepManifest manifest, std::string output,
                           const StudyTransport& transport, std::optional<Shard> shard)
    : manifest_(std::move(manifest)),
      output_(std::move(output)),
      transport_(transport),
      shard_(shard),
      runs_(checked_runs(manifest_, output_, shard_, transport_)),
      journal_(transport, journal_of(output_, shard_), "sweep", manifest_.hash, runs_,
               sweep_rows_check(manifest_.spec, rows_)) {
  // a shard's share is by index (the same whatever its journal holds), MPI's by the runs left
  std::vector<std::size_t> left;
  for (std::size_t i = 0; i < runs_; ++i) {
    if (!journal_.known().count(i) && (!shard_ || shard_->owns(i))) left.push_back(i);
  }
  // this process's share: every size-th of the runs left
  const auto size = static_cast<std::size_t>(transport_.size());
  for (auto k = static_cast<std::size_t>(transport_.rank()); k < left.size(); k += size) {
    share_.push_back(left[k]);
  }
}

SweepSession::~SweepSession() = default;

void SweepSession::require_open(const char* call) const {
  if (finished_) {
    throw std::runtime_error(output_ + ": " + call +
                             " after finish(): the session is over (its CSV written, its journal "
                             "deleted); open a new session to run the sweep again");
  }
}

void SweepSession::run(const study::RunOptions& options) {
  require_open("run()");
  // a second run() (after a stopped one) takes only the runs not finished yet: a run journaled
  // twice would make the journal one the next start refuses
  std::vector<std::size_t> todo;
  for (const std::size_t i : share_) {
    if (!rows_.count(i)) todo.push_back(i);
  }
  if (todo.empty()) return;
  study::RunOptions o = options;
  o.rank = 0;
  o.ranks = 1;  // the share is already this process's
  study::run_sweep(manifest_.spec, todo, o, [&](const study::SweepRow& r) {
    journal_.append(r.index, sweep_row(manifest_.spec, r));
    rows_[r.index] = r;
  });
}

std::vector<study::SweepRow> SweepSession::finish() {
  require_open("finish()");
  const std::map<std::size_t, std::string>& lines = journal_.gather();
  if (!transport_.root()) {
    journal_.finish(false);
    finished_ = true;
    return {};
  }
  if (shard_) return finish_shard(lines);
  // finish() before run() has done every run (or after a stopped one): a usage error the caller
  // mends by running on, never an abort
  if (lines.size() != runs_) {
    journal_.finish(false);
    throw std::runtime_error(
        output_ + ": finish() before every run is done: " + std::to_string(lines.size()) + " of " +
        std::to_string(runs_) + " runs are finished (journal " + journal_.path() +
        "); call run() first: it goes on from the journal, then finish() writes the CSV");
  }
  // every row as data: those computed here or read when the journal was checked as they are,
  // the others (from other processes) read back from their lines
  std::vector<study::SweepRow> rows;
  rows.reserve(runs_);
  try {
    for (const auto& [i, line] : lines) {
      const auto it = rows_.find(i);
      rows.push_back(it != rows_.end() ? it->second : read_sweep_row(manifest_.spec, i, line));
    }
    write_atomically(output_, [&](std::ostream& out) {
      out << join_columns(sweep_columns(manifest_.spec)) << '\n';
      for (const study::SweepRow& r : rows) out << sweep_row(manifest_.spec, r) << '\n';
    });
  } catch (...) {
    journal_.finish(false);
    throw;
  }
  journal_.finish(true);
  finished_ = true;
  return rows;
}

std::vector<study::SweepRow> SweepSession::finish_shard(
    const std::map<std::size_t, std::string>& lines) {
  ShardFile f;
  f.path = shard_path(output_, *shard_);
  f.kind = "sweep";
  f.shard = *shard_;
  f.inputs = manifest_.hash;
  f.runs = f.cells = runs_;
  f.output_header = join_columns(sweep_columns(manifest_.spec));
  std::vector<study::SweepRow> rows;
  try {
    for (std::size_t i = 0; i < runs_; ++i) {
      if (!shard_->owns(i)) continue;
      const auto it = lines.find(i);
      if (it == lines.end()) {
        throw std::runtime_error(output_ + ": finish() before every run of shard " +
                                 std::to_string(shard_->k) + "/" + std::to_string(shard_->n) +
                                 " is done (journal " + journal_.path() +
                                 "); call run() first: it goes on from the journal");
      }
      f.lines[i] = it->second;
      const auto r = rows_.find(i);
      rows.push_back(r != rows_.end() ? r->second : read_sweep_row(manifest_.spec, i, it->second));
    }
    write_shard_file(f);
  } catch (...) {
    journal_.finish(false);
    throw;
  }
  journal_.finish(true);
  finished_ = true;
  return rows;
}

// ---------------------------------------------------------------------------------------------
// the spectrum

namespace {

bool bisects(const SpectrumFile& f) { return f.is_record ? f.record.bisect : f.pulse.bisect; }

// the grid, with every run it makes checked, and the files kept apart, before the journal
// exists: a run that could not start must not leave a journal behind
study::SpectrumResult checked_grid(const SpectrumFile& f, const Body& body,
                                   const std::string& output, const std::string& boundary,
                                   const std::optional<Shard>& shard,
                                   const StudyTransport& transport) {
  std::vector<NamedPath> inputs;
  for (const std::string& i : f.input_files) inputs.push_back({"input", i});
  if (shard) {
    check_distinct_files(inputs, {{"shard file", shard_path(output, *shard)},
                                  {"journal", journal_of(output, shard)}});
  } else {
    check_distinct_files(inputs,
                         {{"output", output}, {"boundary output", bisects(f) ? boundary : ""}});
  }
  check_shard_transport(shard, transport);
  if (shard && f.is_record && bisects(f)) {
    throw InputError(
        "--shard: a record spectrum's bisection needs the outcome of every scale, which no "
        "shard has; split it with --no-bisect (the cells only), or run it whole or under MPI");
  }
  return f.is_record ? study::record_spectrum_grid(body, f.record)
                     : study::spectrum_grid(body, f.pulse);
}

// a journal line must be its cell's or boundary's line (spectrum_journal_check) and read back
// as that cell or boundary
JournalCheck spectrum_rows_check(const study::SpectrumResult& grid, bool normalized, double g) {
  JournalCheck lines = spectrum_journal_check(grid, normalized, g);
  return [&grid, lines, normalized, g](std::size_t index, const std::string& line) -> std::string {
    if (std::string why = lines(index, line); !why.empty()) return why;
    try {
      if (index < grid.cells.size()) {
        read_spectrum_cell(grid, index, line, g);
      } else {
        read_boundary(grid, index - grid.cells.size(), line, normalized, g);
      }
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
}

}  // namespace

SpectrumSession::SpectrumSession(SpectrumFile file, std::string output, std::string boundary_output,
                                 const StudyTransport& transport, std::optional<Shard> shard)
    : file_(std::move(file)),
      body_(file_.body),
      output_(std::move(output)),
      boundary_output_(std::move(boundary_output)),
      transport_(transport),
      shard_(shard),
      bisect_(bisects(file_)),
      grid_(checked_grid(file_, body_, output_, boundary_output_, shard_, transport_)),
      // its inputs are the files and whether the boundary is bisected
      journal_(transport, journal_of(output_, shard_), "spectrum",
               fnv1a(bisect_ ? "bisect" : "no-bisect", file_.hash), runs(),
               spectrum_rows_check(grid_, file_.pulse.normalized || file_.is_record, body_.g())) {
  const std::size_t n = cells();
  for (const auto& [i, line] : journal_.known()) {
    if (i < n) {
      resume_.cells[i] = read_spectrum_cell(grid_, i, line, body_.g()).run.outcome;
    } else {
      resume_.boundaries.insert(i - n);
    }
  }
  // each cell and boundary journaled is also resumed by a later run() of this session (after a
  // stopped one): journaled twice, the journal would be one the next start refuses. The
  // callbacks are serialized and nothing reads resume_ while the runs go.
  resume_.on_cell = [this](const study::SpectrumCell& c) {
    const std::size_t columns = file_.is_record ? 1 : file_.pulse.frequencies.size();
    const std::size_t index = c.row * columns + c.column;
    journal_.append(index, spectrum_row(grid_, c, body_.g()));
    resume_.cells[index] = c.run.outcome;
  };
  const bool normalized = file_.pulse.normalized || file_.is_record;
  resume_.on_boundary = [this, normalized](const study::OverturnBoundary& b) {
    journal_.append(cells() + b.column, boundary_row(grid_, b, normalized, body_.g()));
    resume_.boundaries.insert(b.column);
  };
  // the cells left in this process's share (the bisection's runs come on top)
  const std::size_t columns = file_.is_record ? 1 : file_.pulse.frequencies.size();
  const auto size = static_cast<std::size_t>(shard_ ? shard_->n : transport_.size());
  const auto rank = static_cast<std::size_t>(shard_ ? shard_->k - 1 : transport_.rank());
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t unit = file_.is_record ? i : i % columns;
    if (unit % size == rank && !resume_.cells.count(i)) ++share_cells_;
  }
}

SpectrumSession::~SpectrumSession() = default;

void SpectrumSession::require_open(const char* call) const {
  if (finished_) {
    throw std::runtime_error(output_ + ": " + call +
                             " after finish(): the session is over (its CSVs written, its journal "
                             "deleted); open a new session to run the spectrum again");
  }
}

void SpectrumSession::run(const study::RunOptions& options) {
  require_open("run()");
  study::RunOptions o = options;
  o.rank = shard_ ? shard_->k - 1 : transport_.rank();
  o.ranks = shard_ ? shard_->n : transport_.size();
  if (file_.is_record) {
    study::compute_record_spectrum(body_, file_.record, o, &resume_);
  } else {
    study::compute_spectrum(body_, file_.pulse, o, &resume_);
  }
}

std::string SpectrumSession::unfinished(std::size_t done, std::size_t of, const char* what) const {
  return output_ + ": finish() before every cell and boundary is done: " + std::to_string(done) +
         " of " + std::to_string(of) + " " + what + " are finished (journal " + journal_.path() +
         "); call run() first: it goes on from the journal, then finish() writes the CSVs";
}

study::SpectrumResult SpectrumSession::finish(const std::atomic<bool>* cancel) {
  require_open("finish()");
  const std::map<std::size_t, std::string>& lines = journal_.gather();
  if (!transport_.root()) {
    journal_.finish(false);
    finished_ = true;
    return {};
  }
  if (shard_) return finish_shard(lines);
  const double g = body_.g();
  const bool normalized = file_.pulse.normalized || file_.is_record;
  const std::size_t n = cells();
  study::SpectrumResult res = grid_;
  bool stopped = false;
  // whatever fails here, every process still makes the journal's last collective call
  try {
    // finish() before run() has done every cell (or after a stopped one): a usage error the
    // caller mends by running on
    std::size_t done = 0;
    for (std::size_t i = 0; i < n; ++i) done += lines.count(i);
    if (done != n) throw std::runtime_error(unfinished(done, n, "cells"));
    // every cell as data, read back from its line
    for (std::size_t i = 0; i < n; ++i) {
      res.cells[i] = read_spectrum_cell(grid_, i, lines.at(i), g);
      res.cells[i].computed = true;
    }
    // a record spectrum spread over processes: the bisection here, from every cell's outcome
    if (file_.is_record && bisect_ && !lines.count(n)) {
      const study::OverturnBoundary b =
          study::record_boundary(body_, file_.record, res.cells, cancel);
      stopped = !b.computed;
      if (!stopped) journal_.append_on_root(n, boundary_row(grid_, b, true, g));
    }
    if (!stopped) {
      if (lines.size() != runs()) {
        throw std::runtime_error(unfinished(lines.size() - n, runs() - n, "boundaries"));
      }
      for (std::size_t j = 0; j < res.boundary.size(); ++j) {
        res.boundary[j] = read_boundary(grid_, j, lines.at(n + j), normalized, g);
      }
      // the boundary is written last and an old one removed first: a boundary file on disk is
      // from the same run as the cells beside it
      if (bisect_ && ::unlink(boundary_output_.c_str()) != 0 && errno != ENOENT) {
        throw std::runtime_error("cannot remove the old " + boundary_output_ + ": " +
                                 std::strerror(errno));
      }
      write_atomically(output_, [&](std::ostream& out) {
        out << join_columns(spectrum_columns(res.sliding, res.units)) << '\n';
        for (const study::SpectrumCell& c : res.cells) out << spectrum_row(res, c, g) << '\n';
      });
      if (bisect_) {
        write_atomically(boundary_output_, [&](std::ostream& out) {
          out << join_columns(boundary_columns(res.units)) << '\n';
          for (const study::OverturnBoundary& b : res.boundary) {
            out << boundary_row(res, b, normalized, g) << '\n';
          }
        });
      }
    }
  } catch (...) {
    journal_.finish(false);
    throw;
  }
  journal_.finish(!stopped);
  finished_ = !stopped;
  // a stopped bisection: nothing written, the journal stays for the next start
  return stopped ? study::SpectrumResult{} : res;
}

study::SpectrumResult SpectrumSession::finish_shard(
    const std::map<std::size_t, std::string>& lines) {
  const double g = body_.g();
  const bool normalized = file_.pulse.normalized || file_.is_record;
  const std::size_t n = cells();
  const std::size_t columns = file_.is_record ? 1 : file_.pulse.frequencies.size();
  ShardFile f;
  f.path = shard_path(output_, *shard_);
  f.kind = "spectrum";
  f.shard = *shard_;
  f.inputs = fnv1a(bisect_ ? "bisect" : "no-bisect", file_.hash);
  f.runs = runs();
  f.cells = n;
  f.output_header = join_columns(spectrum_columns(grid_.sliding, grid_.units));
  if (bisect_) f.boundary_header = join_columns(boundary_columns(grid_.units));
  study::SpectrumResult res = grid_;
  try {
    std::size_t missing = 0;
    for (std::size_t i = 0; i < runs(); ++i) {
      // a cell's unit is its column (a record: its row); a boundary's is its column
      const std::size_t unit = i < n ? (file_.is_record ? i : i % columns) : i - n;
      if (!shard_->owns(unit)) continue;
      const auto it = lines.find(i);
      if (it == lines.end()) {
        ++missing;
        continue;
      }
      f.lines[i] = it->second;
      if (i < n) {
        res.cells[i] = read_spectrum_cell(grid_, i, it->second, g);
        res.cells[i].computed = true;
      } else {
        res.boundary[i - n] = read_boundary(grid_, i - n, it->second, normalized, g);
      }
    }
    if (missing > 0) {
      throw std::runtime_error(output_ + ": finish() before every cell and boundary of shard " +
                               std::to_string(shard_->k) + "/" + std::to_string(shard_->n) +
                               " is done (" + std::to_string(missing) + " left; journal " +
                               journal_.path() +
                               "); call run() first: it goes on from the journal");
    }
    write_shard_file(f);
  } catch (...) {
    journal_.finish(false);
    throw;
  }
  journal_.finish(true);
  finished_ = true;
  return res;
}

std::vector<study::SweepRow> read_sweep_csv(const study::SweepSpec& spec, const std::string& path) {
  const std::string text = read_input_file(path, "sweep CSV");
  const std::string header = join_columns(sweep_columns(spec));
  const std::size_t runs = study::sweep_runs(spec).size();
  std::vector<study::SweepRow> rows;
  std::size_t n = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    ++n;
    if (n == 1) {
      FLEXROCK_THROW_UNLESS(line == header, path + ":1: not the header of this sweep's CSV (" +
                                                line.substr(0, 80) + "), expected " +
                                                header.substr(0, 80) + "...");
      continue;
    }
    FLEXROCK_THROW_UNLESS(rows.size() < runs, path + ":" + std::to_string(n) +
                                                  ": more rows than the " + std::to_string(runs) +
                                                  " runs of the sweep");
    try {
      rows.push_back(read_sweep_row(spec, rows.size(), line));
    } catch (const InputError& e) {
      throw InputError(path + ":" + std::to_string(n) + ": " + e.what());
    }
  }
  FLEXROCK_THROW_UNLESS(rows.size() == runs, path + ": " + std::to_string(rows.size()) +
                                                 " rows, expected one per run (" +
                                                 std::to_string(runs) + ")");
  return rows;
}

}  // namespace flexrock::io
