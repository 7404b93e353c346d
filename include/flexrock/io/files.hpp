// SPDX-License-Identifier: BSD-3-Clause
// Files as the io layer opens them: every input is read whole through read_input_file(), which
// accepts only regular text files under a size cap of their kind (a FIFO would block forever,
// /dev/zero would read until memory runs out, a binary file is refused at its first NUL byte),
// and every path problem (missing, a symbolic-link loop, a name too long, no permission) is an
// InputError naming the path and the operating system's reason. same_file() and
// check_distinct_files() keep outputs off the inputs and off each other.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace flexrock::io {

/// The largest input file of each kind read (docs/reliability.md, "Input sizes"); a larger one is
/// refused before it is read. Data files (records, modal and uncertainty tables, sweep CSVs):
/// 256 MiB, about ten million samples of a record, 28 hours at 100 Hz.
inline constexpr std::uint64_t kMaxDataFileBytes = std::uint64_t{256} << 20;
/// TOML files (case files, sweep manifests, spectrum specs): 16 MiB, thousands of times the
/// largest case file an inline modal body makes.
inline constexpr std::uint64_t kMaxTomlFileBytes = std::uint64_t{16} << 20;

/// The whole content of the regular text file at `path`. `what` names the file for messages
/// ("record", "case", ...). Throws InputError "<path>: <reason>; expected a <what> file" when the
/// path is missing, not a regular file (directory, FIFO, device, socket), unreadable or
/// unresolvable (ELOOP, ENAMETOOLONG); "<path>: N bytes, over the <cap> a <what> file may have"
/// when it is larger than `max_bytes`; "<path>: binary data (NUL byte at offset N), expected a
/// text <what> file" at the first block that holds a NUL byte (no input format has one). The
/// file is opened without blocking, then checked, so a FIFO named here never blocks.
std::string read_input_file(const std::string& path, const std::string& what,
                            std::uint64_t max_bytes = kMaxDataFileBytes);

/// "<path>: binary data (NUL byte at offset N)": how every text input (records, tables, case
/// files, journals) names a file that holds a NUL byte; the caller says what was expected.
std::string binary_data(const std::string& path, std::size_t offset);

/// True when `a` and `b` are, or will be, the same file: the same inode when both exist (hard and
/// symbolic links too), else the same canonical path (the existing part of each path resolved,
/// the rest taken as written). Never throws.
bool same_file(const std::string& a, const std::string& b);

/// A path with the role it plays, for messages ("summary", "record file").
struct NamedPath {
  std::string role;
  std::string path;
};

/// Throws InputError when an output is the same file as an input, or two outputs are the same
/// file (empty paths are skipped): "<role> <path> is the same file as the <role> <path>; expected
/// ...". Also refuses an output path that cannot name a regular file: an existing directory,
/// device or FIFO, a path through a symbolic-link loop, a name too long. For a command's output
/// set, before anything is computed or written.
void check_distinct_files(const std::vector<NamedPath>& inputs,
                          const std::vector<NamedPath>& outputs);

}  // namespace flexrock::io
