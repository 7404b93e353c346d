// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/io/journal.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "flexrock/core/error.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/study_files.hpp"

namespace flexrock::io {

namespace {

std::string hex16(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string reason(int err) { return std::strerror(err); }

// a line as an error message can show it: control bytes as '?', at most 80 characters
std::string shown(std::string_view s) {
  std::string out;
  for (const char c : s.substr(0, 80)) {
    out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  }
  if (s.size() > 80) out += "...";
  return out;
}

std::string read_all(int fd, const std::string& path) {
  std::string text;
  char buf[1 << 16];
  if (::lseek(fd, 0, SEEK_SET) < 0) {
    throw std::runtime_error("cannot read the journal " + path + ": " + reason(errno));
  }
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot read the journal " + path + ": " + reason(errno));
    }
    if (n == 0) return text;
    // a NUL before the first line end: binary data, not a header (nor a header torn by a kill,
    // which writes text); found in the first block, before a large file is read whole
    if (text.find('\n') == std::string::npos) {
      const std::string_view block(buf, static_cast<std::size_t>(n));
      const std::size_t nul = block.substr(0, block.find('\n')).find('\0');
      if (nul != std::string_view::npos) {
        throw InputError(binary_data(path, text.size() + nul) +
                         ", expected a text flexrock journal: move it away; flexrock keeps a "
                         "study's finished runs in a file of this name");
      }
    }
    text.append(buf, static_cast<std::size_t>(n));
  }
}

void write_all(int fd, const std::string& text, const std::string& path) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("cannot write the journal " + path + ": " + reason(errno));
    }
    done += static_cast<std::size_t>(n);
  }
}

void truncate_to(int fd, std::size_t size, const std::string& path) {
  if (::ftruncate(fd, static_cast<off_t>(size)) != 0) {
    throw std::runtime_error("cannot truncate the journal " + path + ": " + reason(errno));
  }
}

std::uint64_t checksum(std::uint64_t seed, std::size_t index, const std::string& line) {
  return fnv1a(std::to_string(index) + " " + line, seed);
}

}  // namespace

std::string journal_header(const std::string& kind, std::uint64_t inputs, std::size_t runs) {
  return "# flexrock " + kind + " journal v3 inputs=" + hex16(inputs) +
         " runs=" + std::to_string(runs);
}

std::string journal_line(const std::string& header, std::size_t index, const std::string& line) {
  return std::to_string(index) + " " + hex16(checksum(fnv1a(header), index, line)) + " " + line;
}

Journal::Journal(std::string path, std::string kind, std::uint64_t inputs, std::size_t runs,
                 JournalCheck check)
    : path_(std::move(path)), kind_(std::move(kind)), runs_(runs) {
  const std::string header = journal_header(kind_, inputs, runs);
  seed_ = fnv1a(header);
  // open and lock; the lock must be on the file that is at `path` now: a writer that finishes
  // deletes its journal, and a process that opened it just before holds a dead file
  for (int attempt = 0;; ++attempt) {
    // O_NOFOLLOW: a symbolic link planted at the name (dangling or not) is never followed
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC | O_NONBLOCK | O_NOFOLLOW,
                 0644);
    if (fd_ < 0 && errno == ELOOP) {
      throw InputError(path_ + ": is a symbolic link; the " + kind_ +
                       " journal of this output must be a regular file that flexrock created "
                       "(move the link away; it was not followed)");
    }
    if (fd_ < 0) {
      throw std::runtime_error("cannot open the " + kind_ + " journal " + path_ + ": " +
                               reason(errno));
    }
    struct stat st {};
    // what is wrong with the file at the name, "" when it can be this journal: a regular file of
    // ours with no other name (a hard link to a file elsewhere would be written through)
    std::string foreign;
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
      foreign = "is not a regular file";
    } else if (st.st_uid != ::geteuid()) {
      foreign = "belongs to another user";
    } else if (st.st_nlink != 1) {
      foreign = "has other names (hard links)";
    }
    if (!foreign.empty()) {
      ::close(fd_);
      fd_ = -1;
      throw InputError(path_ + ": " + foreign + "; the " + kind_ +
                       " journal of this output must be a regular file that flexrock created "
                       "(move it away; it was not read or changed)");
    }
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd_);
      fd_ = -1;
      if (err == EWOULDBLOCK) {
        throw InputError(path_ + ": another flexrock process is running with this " + kind_ +
                         " journal (the same output): wait for it to end, or choose another "
                         "output (-o)");
      }
      throw std::runtime_error("cannot lock the journal " + path_ + ": " + reason(err));
    }
    struct stat now {};
    if (::lstat(path_.c_str(), &now) == 0 && now.st_dev == st.st_dev && now.st_ino == st.st_ino) {
      break;
    }
    ::close(fd_);
    fd_ = -1;
    if (attempt == 10) {
      throw std::runtime_error("cannot lock the journal " + path_ +
                               ": it keeps being replaced by another process");
    }
  }
  try {
    read_back(header, check);
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
}

void Journal::read_back(const std::string& header, const JournalCheck& check) {
  const std::string text = read_all(fd_, path_);
  // whole lines only: a line without its end was torn by a kill
  const std::size_t keep = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  const std::size_t first_end = text.find('\n');
  if (keep == 0) {
    // empty, or a header torn by a kill: nothing was journaled yet
    truncate_to(fd_, 0, path_);
    write_all(fd_, header + "\n", path_);
    return;
  }
  const std::string first = text.substr(0, first_end);
  const bool has_lines = keep > first_end + 1;
  if (first != header) {
    if (first.starts_with("# flexrock sweep journal v1 ") ||
        first.starts_with("# flexrock sweep journal v2 manifest=")) {
      throw InputError(path_ +
                       ": a sweep journal of an earlier flexrock (v1 or v2), whose lines have no "
                       "checksums and cannot be checked: delete it to compute its runs again "
                       "(or finish the sweep with the version that wrote it)");
    }
    if (!first.starts_with("# flexrock ") || first.find(" journal v") == std::string::npos) {
      // its content is not shown: the file may be anyone's
      throw InputError(path_ +
                       ":1: not a flexrock journal (its first line is not a journal "
                       "header): move it away; flexrock keeps a study's finished runs in a file "
                       "of this name");
    }
    if (!has_lines) {
      // a journal with no run in it loses nothing when started afresh
      truncate_to(fd_, 0, path_);
      write_all(fd_, header + "\n", path_);
      return;
    }
    throw InputError(path_ + ":1: a journal of other inputs or another run count (" + shown(first) +
                     ", expected " + header +
                     "): delete it to start afresh, or rerun the command and inputs that "
                     "wrote it");
  }
  std::map<std::size_t, std::size_t> where;  // index -> file line, for duplicates
  std::size_t n = 1;
  for (std::size_t pos = first_end + 1; pos < keep;) {
    const std::size_t end = text.find('\n', pos);
    const std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++n;
    auto corrupt = [&](const std::string& what) {
      throw InputError(path_ + ":" + std::to_string(n) + ": corrupt " + kind_ + " journal line (" +
                       what + "): \"" + shown(line) +
                       "\"; delete that line (its run is then computed again) or the whole "
                       "journal (every run is)");
    };
    if (line.find('\0') != std::string_view::npos) corrupt("a NUL byte");
    const std::size_t sp1 = line.find(' ');
    const std::size_t sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
    if (sp2 == std::string_view::npos || sp2 - sp1 != 17) {
      corrupt("expected \"<index> <16 hex digits> <line>\"");
    }
    std::size_t index = 0;
    const auto r = std::from_chars(line.data(), line.data() + sp1, index);
    if (r.ec != std::errc() || r.ptr != line.data() + sp1) corrupt("no run index");
    const std::string body(line.substr(sp2 + 1));
    if (line.substr(sp1 + 1, 16) != hex16(checksum(seed_, index, body))) {
      corrupt("its checksum does not match: the line was changed or damaged");
    }
    if (index >= runs_) {
      corrupt("run index " + std::to_string(index) + " out of range: " + std::to_string(runs_) +
              " runs");
    }
    if (check) {
      const std::string why = check(index, body);
      if (!why.empty()) corrupt("run " + std::to_string(index) + ": " + why);
    }
    const auto it = finished_.find(index);
    if (it != finished_.end()) {
      // the same line twice is harmless; two different results of one run are not
      if (it->second != body) {
        corrupt("run " + std::to_string(index) + " twice with different lines, first at line " +
                std::to_string(where[index]));
      }
      continue;
    }
    finished_[index] = body;
    where[index] = n;
  }
  resumed_ = finished_.size();
  if (keep < text.size()) truncate_to(fd_, keep, path_);
}

Journal::~Journal() {
  if (fd_ >= 0) ::close(fd_);
}

void Journal::append(std::size_t index, const std::string& line) {
  FLEXROCK_DEMAND(fd_ >= 0 && index < runs_ &&
                  line.find_first_of(std::string("\n\0", 2)) == std::string::npos);
  write_all(fd_,
            std::to_string(index) + " " + hex16(checksum(seed_, index, line)) + " " + line + "\n",
            path_);
  finished_[index] = line;
}

void Journal::remove() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // still locked: a process that opened it sees a deleted file
  ::close(fd_);
  fd_ = -1;
}

}  // namespace flexrock::io
