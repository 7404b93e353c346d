// SPDX-License-Identifier: BSD-3-Clause
// The journal of a study (a sweep or a spectrum): "OUT.partial", where the output line of every
// finished run is appended and handed to the operating system as the run finishes, so that a
// study killed at any point resumes where it stopped and ends with the same bytes as an
// uninterrupted one. Format (docs/studies.md, "Journals"):
//
//   # flexrock <kind> journal v3 inputs=<16 hex digits> runs=<N>
//   <index> <16 hex digits: checksum> <the run's output line>
//   ...
//
// The checksum is a 64-bit FNV-1a of "<index> <line>", continued from the header's, so that a
// changed byte, a line of another journal or a moved line is caught. Every line read back is
// checked (checksum, index, duplicates, and the caller's JournalCheck of its contents). The file
// is held under an exclusive advisory lock (flock) while it is open: a second process that opens
// the same journal is refused instead of interleaving its lines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>

namespace flexrock::io {

/// What a run's line must be: returns "" if `line` is a valid output line of run `index`, else
/// what is wrong with it (in words, for the error message).
using JournalCheck = std::function<std::string(std::size_t index, const std::string& line)>;

class Journal {
 public:
  /// Opens and locks the journal at `path`, creating it (with its header) if absent. An
  /// existing one resumes: its lines are read and checked, a torn last line (no line end: the
  /// writer was killed mid-line) is dropped and the file truncated to its complete lines.
  /// `kind` ("sweep", "spectrum") and `inputs` (a hash of every input file and option that
  /// changes a result) and `runs` (indices are 0 .. runs-1) make the header. Throws InputError,
  /// naming the file and line and saying what to do, when another process holds the journal,
  /// when its header differs (other inputs; a journal that holds no line yet is started afresh
  /// instead), when it is a journal of an earlier version without checksums, or when a line is
  /// corrupt (checksum, index out of range, a run twice with different lines, `check` fails).
  /// Throws std::runtime_error when the file cannot be created or read.
  Journal(std::string path, std::string kind, std::uint64_t inputs, std::size_t runs,
          JournalCheck check = {});
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  /// Finished lines by run index: those read at opening, plus those added since.
  const std::map<std::size_t, std::string>& finished() const { return finished_; }
  /// Lines that were in the file when it was opened.
  std::size_t resumed() const { return resumed_; }
  /// Appends one finished run's line (without line end; no '\n' or NUL in it) in one write(2):
  /// a kill leaves whole lines or a torn last one. Throws std::runtime_error with the reason
  /// (errno) when the write fails. Not thread-safe: callers serialize.
  void append(std::size_t index, const std::string& line);
  /// Adds a line (e.g. gathered from another process) without writing it.
  void remember(std::size_t index, const std::string& line) { finished_[index] = line; }
  /// Deletes the journal file and releases the lock.
  void remove();
  const std::string& path() const { return path_; }

 private:
  void read_back(const std::string& header, const JournalCheck& check);

  std::string path_;
  std::string kind_;
  std::size_t runs_ = 0;
  std::uint64_t seed_ = 0;  // checksum of the header: where every line's checksum starts
  int fd_ = -1;
  std::size_t resumed_ = 0;
  std::map<std::size_t, std::string> finished_;
};

/// The header line of a journal (no line end).
std::string journal_header(const std::string& kind, std::uint64_t inputs, std::size_t runs);
/// One journal line of a run (no line end), as Journal::append writes it.
std::string journal_line(const std::string& header, std::size_t index, const std::string& line);

}  // namespace flexrock::io
