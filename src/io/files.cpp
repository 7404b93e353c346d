// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/io/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>
#include <string>
#include <system_error>

#include "flexrock/core/error.hpp"

namespace flexrock::io {

namespace fs = std::filesystem;

namespace {

// closes a descriptor on every path out
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// a byte count as a cap is stated: "256 MiB"
std::string size_in_words(std::uint64_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// what a non-regular file is, for messages
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

}  // namespace

std::string binary_data(const std::string& path, std::size_t offset) {
  return path + ": binary data (NUL byte at offset " + std::to_string(offset) + ")";
}

std::string read_input_file(const std::string& path, const std::string& what,
                            std::uint64_t max_bytes) {
  const std::string expected = "; expected a " + what + " file";
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below
  const Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (f.fd < 0) {
    const int e = errno;
    if (e == ENOENT) throw InputError(path + ": no such " + what + " file (cannot open it)");
    throw InputError(path + ": cannot open the " + what + " file: " + std::strerror(e));
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) {
    throw InputError(path + ": cannot read the " + what + " file: " + std::strerror(errno));
  }
  if (!S_ISREG(st.st_mode)) throw InputError(path + ": " + kind_of(st.st_mode) + expected);
  auto too_large = [&](std::uint64_t bytes, const char* qualifier) {
    return InputError(path + ": " + qualifier + std::to_string(bytes) + " bytes, over the " +
                      size_in_words(max_bytes) + " a " + what +
                      " file may have; expected a smaller " + what +
                      " file (docs/reliability.md, "
                      "\"Input sizes\")");
  };
  std::string text;
  char buf[1 << 16];
  bool reserved = false;
  for (;;) {
    const ssize_t n = ::read(f.fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      throw InputError(path + ": cannot read the " + what + " file: " + std::strerror(errno));
    }
    // every input is text: a NUL byte is binary data, found in the block that holds it (a large
    // binary file is refused at its first block, not after it was read whole)
    const auto* nul = static_cast<const char*>(std::memchr(buf, '\0', static_cast<std::size_t>(n)));
    if (nul) {
      throw InputError(binary_data(path, text.size() + static_cast<std::size_t>(nul - buf)) +
                       ", expected a text " + what + " file");
    }
    if (!reserved) {
      // the size once the first block said text or binary: a large binary file is named as such
      if (static_cast<std::uint64_t>(st.st_size) > max_bytes) {
        throw too_large(static_cast<std::uint64_t>(st.st_size), "");
      }
      reserved = true;
      try {
        text.reserve(static_cast<std::size_t>(st.st_size));
      } catch (const std::bad_alloc&) {
        throw InputError(path + ": out of memory for the " + std::to_string(st.st_size) +
                         " bytes of the " + what + " file");
      }
    }
    if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
      throw too_large(text.size() + static_cast<std::size_t>(n), "more than ");  // it grew
    }
    text.append(buf, static_cast<std::size_t>(n));
  }
  return text;
}

namespace {

// the path with its existing part resolved (symbolic links, "..") and the rest as written; the
// path itself when even that fails (a symbolic-link loop)
fs::path resolved(const std::string& p) {
  std::error_code ec;
  fs::path abs = fs::absolute(p, ec);
  if (ec) return fs::path(p).lexically_normal();
  const fs::path r = fs::weakly_canonical(abs, ec);
  return ec ? abs.lexically_normal() : r;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0) {
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  }
  return resolved(a) == resolved(b);
}

void check_distinct_files(const std::vector<NamedPath>& inputs,
                          const std::vector<NamedPath>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& out = outputs[i];
    if (out.path.empty()) continue;
    // a path that cannot name a file (a symbolic-link loop, a name over NAME_MAX), or names
    // something a regular file may not replace; a directory that cannot be written or created
    // is found by the writer (exit 1: outputs that could not be written)
    struct stat st {};
    if (::stat(out.path.c_str(), &st) == 0) {
      if (!S_ISREG(st.st_mode)) {
        throw InputError(out.role + " " + out.path + ": " + kind_of(st.st_mode) +
                         "; expected a path for a regular file");
      }
    } else if (errno == ELOOP || errno == ENAMETOOLONG) {
      throw InputError(out.role + " " + out.path + ": " + std::strerror(errno) +
                       "; expected a path for a regular file");
    }
    for (const NamedPath& in : inputs) {
      if (same_file(out.path, in.path)) {
        throw InputError(out.role + " " + out.path + " is the same file as the " + in.role + " " +
                         in.path + "; expected an output that does not overwrite an input");
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (same_file(out.path, outputs[j].path)) {
        throw InputError(out.role + " " + out.path + " is the same file as the " + outputs[j].role +
                         " " + outputs[j].path + "; expected a different file for each output");
      }
    }
  }
}

}  // namespace flexrock::io
