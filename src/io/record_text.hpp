// SPDX-License-Identifier: BSD-3-Clause
// The text of record files: lines with their numbers, tokens, numbers and the messages that name
// the file and line. Shared by the readers of records.cpp and agency_records.cpp. Internal to
// flexrock::io.
#pragma once

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "decimal_comma.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/io/files.hpp"
#include "flexrock/io/records.hpp"

namespace flexrock::io::detail {

// the largest point count we accept (guards against a garbled NPTS allocating gigabytes)
constexpr double kMaxPoints = 1e8;

// a line of a file with its 1-based number
struct Line {
  std::size_t number;
  std::string text;
};

// shortest round-trip text of a double
inline std::string show(double v) { return format_number(v); }

// the text in quotes, shortened to 80 characters
inline std::string quote(std::string_view s) {
  // appends rather than "\"" + std::string(...): GCC 12 warns falsely on the latter (PR 105651)
  constexpr std::size_t kMax = 80;
  std::string q;
  q.reserve(std::min(s.size(), kMax) + 5);
  q.push_back('"');
  q.append(s.substr(0, kMax));
  if (s.size() > kMax) q.append("...");
  q.push_back('"');
  return q;
}

// "path:line: message"
[[noreturn]] inline void fail(const std::string& path, std::size_t line,
                              const std::string& message) {
  throw InputError(path, line, "", message);
}

inline std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

inline bool is_blank(std::string_view s) { return trim(s).empty(); }

inline std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

// the whole file as lines, without line ends (LF or CRLF) and without a UTF-8 byte-order mark
inline std::vector<Line> read_lines(const std::string& path) {
  // a regular file only: a FIFO would block, a device (/dev/zero) would never end
  const std::string text = read_input_file(path, "record");
  std::vector<Line> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (lines.empty() && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
    lines.push_back({lines.size() + 1, std::move(line)});
    start = end + 1;
  }
  return lines;
}

// splits on whitespace, and on commas too when `commas` is set (empty fields are dropped), into
// `out`: a reader that reuses `out` line after line allocates nothing once it is large enough
inline void split_into(std::string_view s, bool commas, std::vector<std::string_view>& out) {
  out.clear();
  const auto sep = [commas](char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0 || (commas && c == ',');
  };
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && sep(s[i])) ++i;
    const std::size_t start = i;
    while (i < s.size() && !sep(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
}

inline std::vector<std::string_view> split(std::string_view s, bool commas) {
  std::vector<std::string_view> out;
  split_into(s, commas, out);
  return out;
}

// a number token: plain or E notation, optional sign, leading zero optional (".139E-02")
enum class Parsed { kOk, kNotANumber, kNotFinite };

inline Parsed parse_number(std::string_view token, double& value) {
  std::string_view t = token;
  if (t.size() > 1 && t.front() == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  if (t.empty()) return Parsed::kNotANumber;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range) return Parsed::kNotFinite;
  if (ec != std::errc() || ptr != t.data() + t.size()) return Parsed::kNotANumber;
  return std::isfinite(value) ? Parsed::kOk : Parsed::kNotFinite;
}

// parses a value token or fails with the file position and what it is
// (`what` is a view: the readers call this once a value, and build no string unless it fails)
inline double value_or_fail(const std::string& path, std::size_t line, std::string_view token,
                            std::string_view what) {
  double v = 0.0;
  switch (parse_number(token, v)) {
    case Parsed::kOk:
      return v;
    case Parsed::kNotFinite:
      fail(path, line,
           "expected a finite number for " + std::string(what) + ", got " + quote(token) +
               " (NaN or infinite values are not allowed)");
    case Parsed::kNotANumber:
      break;
  }
  fail(path, line, "expected a number for " + std::string(what) + ", got " + quote(token));
}

// "value 12" for messages
inline std::string nth_value(std::size_t k) { return "value " + std::to_string(k); }

// times i * dt
inline std::vector<double> uniform_times(std::size_t n, double dt) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<double>(i) * dt;
  return t;
}

// a comment line: '#' as the first non-blank character
inline bool is_comment(std::string_view s) {
  s = trim(s);
  return !s.empty() && s.front() == '#';
}

// the line up to an inline '#' comment
inline std::string_view strip_comment(std::string_view s) {
  const std::size_t hash = s.find('#');
  return hash == std::string_view::npos ? s : s.substr(0, hash);
}

// a number with a decimal comma would be split in two at the comma: refused, never split
inline void refuse_decimal_commas(const std::string& path, const Line& line,
                                  std::size_t min_tokens) {
  const std::string n = detail::decimal_comma_number(strip_comment(line.text), min_tokens);
  if (!n.empty()) fail(path, line.number, detail::decimal_comma_message(n));
}

inline bool all_blank(const std::vector<Line>& lines) {
  return std::all_of(lines.begin(), lines.end(), [](const Line& l) { return is_blank(l.text); });
}

// an acceleration unit written in a file, in any case: "g", "cm/s^2", "CM/SEC/SEC", "gal",
// "m/s2", with or without brackets ("[g]", "(cm/s/s)"); nullopt for anything else
inline std::optional<AccelUnit> accel_unit_from_text(std::string_view text) {
  std::string u = upper(trim(text));
  if (u.size() >= 2 &&
      ((u.front() == '[' && u.back() == ']') || (u.front() == '(' && u.back() == ')'))) {
    u = upper(trim(std::string_view(u).substr(1, u.size() - 2)));
  }
  while (!u.empty() && (u.back() == '.' || u.back() == ';')) u.pop_back();
  if (u == "G") return AccelUnit::kG;
  for (const char* a : {"CM/S/S", "CM/SEC/SEC", "CM/S^2", "CM/S**2", "CM/S2", "CM/SEC^2", "CM/SEC2",
                        "CM/SEC**2", "GAL", "GALS", "CM S^-2", "CM.S-2"}) {
    if (u == a) return AccelUnit::kCentimetersPerSecond2;
  }
  for (const char* a : {"M/S/S", "M/SEC/SEC", "M/S^2", "M/S**2", "M/S2", "M/SEC^2", "M/SEC2",
                        "M/SEC**2", "M S^-2", "M.S-2"}) {
    if (u == a) return AccelUnit::kMetersPerSecond2;
  }
  return std::nullopt;
}

// numbers of a line of values written by Fortran without blanks where a value is negative
// ("1.2E-02-3.4E-02"): split at blanks and before a sign that follows a digit or a point
inline std::vector<std::string_view> glued_tokens(std::string_view s) {
  std::vector<std::string_view> out;
  for (std::string_view w : split(s, false)) {
    std::size_t start = 0;
    for (std::size_t i = 1; i < w.size(); ++i) {
      const char p = w[i - 1];
      const bool after_mantissa = std::isdigit(static_cast<unsigned char>(p)) != 0 || p == '.';
      if ((w[i] == '-' || w[i] == '+') && after_mantissa) {
        out.push_back(w.substr(start, i - start));
        start = i;
      }
    }
    out.push_back(w.substr(start));
  }
  return out;
}

}  // namespace flexrock::io::detail
