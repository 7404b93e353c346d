// SPDX-License-Identifier: BSD-3-Clause
// Shard files of a study and their merge (include/flexrock/io/study_shards.hpp).
#include "flexrock/io/study_shards.hpp"

#include <charconv>
#include <ostream>
#include <set>
#include <string_view>

#include "flexrock/core/error.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/journal.hpp"
#include "flexrock/io/outputs.hpp"

namespace flexrock::io {

namespace {

constexpr std::string_view kOutputPrefix = "# output ";
constexpr std::string_view kBoundaryPrefix = "# boundary ";
// more shards than this is a typo (a job array of a million tasks is not one study's split)
constexpr int kMaxShards = 1000000;

std::string hex16(std::uint64_t v) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = kDigits[v & 15];
  return s;
}

template <class T>
bool parse_number(std::string_view s, T& v, int base = 10) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v, base);
  return ec == std::errc() && p == s.data() + s.size() && !s.empty();
}

// the header lines, joined: what every line's checksum continues from
std::string header_text(const ShardFile& f) {
  std::string h = "# flexrock ";
  h.append(f.kind).append(" shard v1 shard=").append(std::to_string(f.shard.k)).append("/");
  h.append(std::to_string(f.shard.n)).append(" inputs=").append(hex16(f.inputs));
  h.append(" runs=").append(std::to_string(f.runs)).append(" cells=");
  h.append(std::to_string(f.cells)).append("\n").append(kOutputPrefix).append(f.output_header);
  if (f.cells < f.runs) h.append("\n").append(kBoundaryPrefix).append(f.boundary_header);
  return h;
}

// the study of a shard file, in words, for messages
std::string study_of(const ShardFile& f) {
  return f.kind + " of inputs " + hex16(f.inputs) + ", " + std::to_string(f.runs) + " runs";
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  Shard s;
  if (slash == std::string::npos || !parse_number(std::string_view(text).substr(0, slash), s.k) ||
      !parse_number(std::string_view(text).substr(slash + 1), s.n) || s.n < 1 || s.n > kMaxShards ||
      s.k < 1 || s.k > s.n) {
    throw InputError(
        "--shard: expected k/N with integers 1 <= k <= N <= " + std::to_string(kMaxShards) +
        " (shard k of N, e.g. 3/8), got \"" + text + "\"");
  }
  return s;
}

std::string shard_path(const std::string& output, const Shard& shard) {
  return output + ".shard" + std::to_string(shard.k) + "of" + std::to_string(shard.n);
}

std::string shard_output(const std::string& shard_file) {
  const std::size_t at = shard_file.rfind(".shard");
  if (at == std::string::npos || at == 0) return "";
  const std::string_view tail = std::string_view(shard_file).substr(at + 6);
  const std::size_t of = tail.find("of");
  int k = 0, n = 0;
  if (of == std::string_view::npos || !parse_number(tail.substr(0, of), k) ||
      !parse_number(tail.substr(of + 2), n)) {
    return "";
  }
  return shard_file.substr(0, at);
}

void write_shard_file(const ShardFile& f) {
  const std::string header = header_text(f);
  write_atomically(f.path, [&](std::ostream& out) {
    out << header << '\n';
    for (const auto& [i, line] : f.lines) out << journal_line(header, i, line) << '\n';
  });
}

ShardFile read_shard_file(const std::string& path) {
  const std::string text = read_input_file(path, "shard");
  ShardFile f;
  f.path = path;
  std::size_t pos = 0, n = 0;
  auto next_line = [&](std::string& line) {
    if (pos >= text.size()) return false;
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) {
      throw InputError(path + ":" + std::to_string(n + 1) +
                       ": the last line has no line end: a shard file is written whole, so this "
                       "one was cut or edited; run the shard again");
    }
    line = text.substr(pos, end - pos);
    pos = end + 1;
    ++n;
    return true;
  };
  auto bad = [&](const std::string& what) {
    return InputError(path + ":" + std::to_string(n) + ": " + what);
  };
  std::string first;
  if (!next_line(first) || !first.starts_with("# flexrock ")) {
    throw InputError(path +
                     ":1: not a flexrock shard file (expected \"# flexrock <kind> shard v1 "
                     "shard=k/N ...\", the file `flexrock sweep|spectrum --shard k/N` writes)");
  }
  // "# flexrock <kind> shard v1 shard=k/N inputs=H runs=R cells=C"
  std::vector<std::string_view> w;
  for (std::size_t a = 0; a < first.size();) {
    const std::size_t b = std::min(first.find(' ', a), first.size());
    w.push_back(std::string_view(first).substr(a, b - a));
    a = b + 1;
  }
  auto field = [&](std::size_t i, std::string_view key) -> std::string_view {
    if (i >= w.size() || !w[i].starts_with(key)) return {};
    return w[i].substr(key.size());
  };
  const std::string_view shard = field(5, "shard=");
  const std::size_t slash = shard.find('/');
  if (w.size() != 9 || w[3] != "shard" || w[4] != "v1" || (w[2] != "sweep" && w[2] != "spectrum") ||
      slash == std::string_view::npos || !parse_number(shard.substr(0, slash), f.shard.k) ||
      !parse_number(shard.substr(slash + 1), f.shard.n) || f.shard.k < 1 || f.shard.k > f.shard.n ||
      !parse_number(field(6, "inputs="), f.inputs, 16) ||
      !parse_number(field(7, "runs="), f.runs) || !parse_number(field(8, "cells="), f.cells) ||
      f.cells > f.runs) {
    if (w.size() > 3 && w[3] == "journal") {
      throw bad(
          "a journal, not a shard file: its shard is not finished; run the same shard "
          "command again to finish it");
    }
    throw bad(
        "expected \"# flexrock sweep|spectrum shard v1 shard=k/N inputs=<16 hex> runs=R "
        "cells=C\", got \"" +
        first.substr(0, 120) + "\"");
  }
  f.kind = std::string(w[2]);
  std::string line;
  if (!next_line(line) || !line.starts_with(kOutputPrefix)) {
    throw bad("expected \"" + std::string(kOutputPrefix) + "<the CSV's header>\"");
  }
  f.output_header = line.substr(kOutputPrefix.size());
  if (f.cells < f.runs) {
    if (!next_line(line) || !line.starts_with(kBoundaryPrefix)) {
      throw bad("expected \"" + std::string(kBoundaryPrefix) + "<the boundary CSV's header>\"");
    }
    f.boundary_header = line.substr(kBoundaryPrefix.size());
  }
  const std::string header = header_text(f);
  if (header != text.substr(0, pos - 1)) throw bad("a header line that flexrock did not write");
  while (next_line(line)) {
    const std::size_t sp = line.find(' ');
    std::size_t index = 0;
    if (sp == std::string::npos || !parse_number(std::string_view(line).substr(0, sp), index)) {
      throw bad("expected \"<run index> <checksum> <line>\", got \"" + line.substr(0, 80) + "\"");
    }
    if (index >= f.runs) {
      throw bad("run index " + std::to_string(index) + " out of range (" + std::to_string(f.runs) +
                " runs)");
    }
    const std::string body = line.size() > sp + 18 ? line.substr(sp + 18) : std::string();
    if (journal_line(header, index, body) != line) {
      throw bad(
          "checksum mismatch: the line was changed, or comes from another shard or study; "
          "run this shard again");
    }
    if (!f.lines.emplace(index, body).second) {
      throw bad("run " + std::to_string(index) + " twice");
    }
  }
  return f;
}

MergeResult merge_shards(const std::vector<std::string>& shard_files, const std::string& output,
                         const std::string& boundary_output) {
  FLEXROCK_THROW_UNLESS(!shard_files.empty(),
                        "merge: expected the shard files of one study (OUT.shard1ofN ...)");
  std::vector<ShardFile> shards;
  for (const std::string& p : shard_files) shards.push_back(read_shard_file(p));
  const ShardFile& a = shards.front();
  const bool boundary = a.cells < a.runs;
  std::vector<NamedPath> inputs;
  for (const std::string& p : shard_files) inputs.push_back({"shard", p});
  check_distinct_files(inputs,
                       {{"output", output}, {"boundary output", boundary ? boundary_output : ""}});
  // one study, one split
  std::map<int, const ShardFile*> by_k;
  for (const ShardFile& s : shards) {
    if (s.kind != a.kind || s.inputs != a.inputs || s.runs != a.runs || s.cells != a.cells ||
        s.output_header != a.output_header || s.boundary_header != a.boundary_header) {
      throw InputError(s.path + ": a shard of another study (" + study_of(s) + ") than " + a.path +
                       " (" + study_of(a) +
                       "); merge the shards of one study, run with the same inputs and options");
    }
    if (s.shard.n != a.shard.n) {
      throw InputError(s.path + ": shard " + std::to_string(s.shard.k) + "/" +
                       std::to_string(s.shard.n) + " of a split into " + std::to_string(s.shard.n) +
                       ", but " + a.path + " is of a split into " + std::to_string(a.shard.n) +
                       "; merge the shards of one split");
    }
    const auto [it, fresh] = by_k.emplace(s.shard.k, &s);
    if (!fresh) {
      throw InputError(s.path + ": shard " + std::to_string(s.shard.k) + "/" +
                       std::to_string(s.shard.n) + " given twice (also " + it->second->path +
                       "); give each shard once");
    }
  }
  std::string missing;
  for (int k = 1; k <= a.shard.n; ++k) {
    if (!by_k.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  }
  if (!missing.empty()) {
    throw InputError("merge: missing shard " + missing + " of " + std::to_string(a.shard.n) +
                     " (each of 1.." + std::to_string(a.shard.n) +
                     " once); run it with --shard k/" + std::to_string(a.shard.n) +
                     " or give its file, then merge again");
  }
  // every run once
  std::map<std::size_t, const std::string*> lines;
  std::map<std::size_t, const ShardFile*> from;
  for (const ShardFile& s : shards) {
    for (const auto& [i, line] : s.lines) {
      if (!lines.emplace(i, &line).second) {
        throw InputError(s.path + ": run " + std::to_string(i) + " is also in " + from[i]->path +
                         "; shards of one split share no run");
      }
      from[i] = &s;
    }
  }
  if (lines.size() != a.runs) {
    std::size_t first = 0;
    while (lines.count(first)) ++first;
    throw InputError("merge: " + std::to_string(lines.size()) + " of " + std::to_string(a.runs) +
                     " runs in the shards (run " + std::to_string(first) +
                     " is in none); every shard file must be complete");
  }
  write_atomically(output, [&](std::ostream& out) {
    out << a.output_header << '\n';
    for (const auto& [i, line] : lines) {
      if (i < a.cells) out << *line << '\n';
    }
  });
  if (boundary) {
    write_atomically(boundary_output, [&](std::ostream& out) {
      out << a.boundary_header << '\n';
      for (const auto& [i, line] : lines) {
        if (i >= a.cells) out << *line << '\n';
      }
    });
  }
  return {a.kind, shards.size(), a.runs, boundary};
}

}  // namespace flexrock::io
