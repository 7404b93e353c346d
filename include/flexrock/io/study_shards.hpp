// SPDX-License-Identifier: BSD-3-Clause
// Shards: a study split into N independent processes without MPI (array jobs, task launchers).
// Shard k of N runs a deterministic share of the runs (those of index, or for a spectrum those
// of column or row, i with i mod N == k - 1), keeps its own journal, and ends with a shard file
// of its lines; merge_shards() joins the N shard files into the files a single run writes, byte
// for byte. Format of a shard file (docs/studies.md, "Shards"):
//
//   # flexrock <kind> shard v1 shard=<k>/<N> inputs=<16 hex digits> runs=<R> cells=<C>
//   # output <the header line of the output CSV>
//   # boundary <the header line of the boundary CSV>      (a spectrum that bisects: C < R)
//   <index> <16 hex digits: checksum> <the run's output line>
//   ...
//
// The checksum is that of a journal line (io/journal.hpp), continued from the header lines':
// a changed byte, a line of another study or a moved line is caught.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace flexrock::io {

/// Shard k of n (1 <= k <= n); {1, 1} is the whole study.
struct Shard {
  int k = 1;
  int n = 1;
  bool whole() const { return n == 1; }
  /// Whether the unit (a sweep's run, a spectrum's column or record row) `i` is this shard's.
  bool owns(std::size_t i) const {
    return i % static_cast<std::size_t>(n) == static_cast<std::size_t>(k - 1);
  }
};

/// "k/N" as `--shard` takes it. Throws InputError "--shard: expected k/N ..., got ...".
Shard parse_shard(const std::string& text);

/// The shard file of `output`: "<output>.shard<k>of<N>".
std::string shard_path(const std::string& output, const Shard& shard);

/// The output a shard file belongs to ("out.csv.shard2of4" -> "out.csv"); "" when the name has
/// no such suffix.
std::string shard_output(const std::string& shard_file);

/// What a shard file holds: its study (kind, inputs, runs, cells, the CSV headers) and lines.
struct ShardFile {
  std::string path;
  std::string kind;  // "sweep" or "spectrum"
  Shard shard;
  std::uint64_t inputs = 0;
  std::size_t runs = 0;
  std::size_t cells = 0;  // lines of index < cells go to the output, the others to the boundary
  std::string output_header, boundary_header;
  std::map<std::size_t, std::string> lines;
};

/// Writes a shard file atomically (no partial file on failure).
void write_shard_file(const ShardFile& f);

/// Reads and checks a shard file: its header, every line's checksum and index. Throws InputError
/// naming the file and line.
ShardFile read_shard_file(const std::string& path);

/// What merge_shards() wrote.
struct MergeResult {
  std::string kind;
  std::size_t shards = 0, runs = 0;
  bool boundary = false;  // a boundary CSV was written
};

/// Joins the shard files of one study into `output` (and `boundary_output` for a spectrum that
/// bisects), with the bytes a single run writes. Refuses, with InputError and nothing written,
/// shards of different studies or shard counts, a shard missing or given twice, a run missing
/// or in two shards, and an output that is one of the shard files.
MergeResult merge_shards(const std::vector<std::string>& shard_files, const std::string& output,
                         const std::string& boundary_output);

}  // namespace flexrock::io
