// SPDX-License-Identifier: BSD-3-Clause
// Files as the io layer opens them: every input is read whole through read_input_file(), which
// accepts only regular files (a FIFO would block forever, /dev/zero would read until memory runs
// out), and every path problem (missing, a symbolic-link loop, a name too long, no permission)
// is an InputError naming the path and the operating system's reason. same_file() and
// check_distinct_files() keep outputs off the inputs and off each other.
#pragma once

#include <string>
#include <vector>

namespace flexrock::io {

/// The whole content of the regular file at `path`. `what` names the file for messages ("record",
/// "case", ...). Throws InputError "<path>: <reason>; expected a <what> file" when the path is
/// missing, not a regular file (directory, FIFO, device, socket), unreadable or unresolvable
/// (ELOOP, ENAMETOOLONG). The file is opened without blocking, then checked, so a FIFO named
/// here never blocks.
std::string read_input_file(const std::string& path, const std::string& what);

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
