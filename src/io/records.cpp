// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/io/records.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "decimal_comma.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/io/files.hpp"

namespace flexrock::io {

namespace {

// what AT2 line 4 must hold, for messages
constexpr const char* kLine4Expected =
    "NPTS and DT, e.g. \"NPTS=   4096, DT=   .0100 SEC\" or \"4096    0.0100    NPTS, DT\"";
// the largest point count we accept (guards against a garbled NPTS allocating gigabytes)
constexpr double kMaxPoints = 1e8;

// a line of a file with its 1-based number
struct Line {
  std::size_t number;
  std::string text;
};

// shortest round-trip text of a double
std::string show(double v) { return format_number(v); }

// the text in quotes, shortened to 80 characters
std::string quote(std::string_view s) {
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
[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& message) {
  throw InputError(path, line, "", message);
}

std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

bool is_blank(std::string_view s) { return trim(s).empty(); }

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

// the whole file as lines, without line ends (LF or CRLF) and without a UTF-8 byte-order mark
std::vector<Line> read_lines(const std::string& path) {
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

// splits on whitespace, and on commas too when `commas` is set (empty fields are dropped)
std::vector<std::string_view> split(std::string_view s, bool commas) {
  std::vector<std::string_view> out;
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
  return out;
}

// a number token: plain or E notation, optional sign, leading zero optional (".139E-02")
enum class Parsed { kOk, kNotANumber, kNotFinite };

Parsed parse_number(std::string_view token, double& value) {
  std::string_view t = token;
  if (t.size() > 1 && t.front() == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  if (t.empty()) return Parsed::kNotANumber;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range) return Parsed::kNotFinite;
  if (ec != std::errc() || ptr != t.data() + t.size()) return Parsed::kNotANumber;
  return std::isfinite(value) ? Parsed::kOk : Parsed::kNotFinite;
}

// parses a value token or fails with the file position and what it is
double value_or_fail(const std::string& path, std::size_t line, std::string_view token,
                     const std::string& what) {
  double v = 0.0;
  switch (parse_number(token, v)) {
    case Parsed::kOk:
      return v;
    case Parsed::kNotFinite:
      fail(path, line,
           "expected a finite number for " + what + ", got " + quote(token) +
               " (NaN or infinite values are not allowed)");
    case Parsed::kNotANumber:
      break;
  }
  fail(path, line, "expected a number for " + what + ", got " + quote(token));
}

// "value 12" for messages
std::string nth_value(std::size_t k) { return "value " + std::to_string(k); }

// units named in AT2 line 3 ("... IN UNITS OF G")
AccelUnit at2_units(const std::string& path, const Line& line) {
  const std::string u = upper(line.text);
  const std::string expected =
      "the units line, e.g. \"ACCELERATION TIME HISTORY IN UNITS OF G\" (units G, CM/S/S or "
      "M/S/S)";
  if (u.find("VELOCITY") != std::string::npos || u.find("DISPLACEMENT") != std::string::npos) {
    fail(path, line.number,
         "expected an acceleration record (" + expected + "), got " + quote(line.text) +
             " (a velocity or displacement file: read the .AT2 file instead)");
  }
  const std::size_t at = u.find("UNITS OF");
  if (at != std::string::npos) {
    const std::vector<std::string_view> words = split(std::string_view(u).substr(at + 8), true);
    if (!words.empty()) {
      std::string_view w = words.front();
      while (!w.empty() && (w.back() == '.' || w.back() == ';')) w.remove_suffix(1);
      if (w == "G") return AccelUnit::kG;
      for (const char* s :
           {"CM/S/S", "CM/SEC/SEC", "CM/S^2", "CM/S2", "CM/SEC^2", "CM/SEC2", "GAL", "GALS"}) {
        if (w == s) return AccelUnit::kCentimetersPerSecond2;
      }
      for (const char* s : {"M/S/S", "M/SEC/SEC", "M/S^2", "M/S2", "M/SEC^2", "M/SEC2"}) {
        if (w == s) return AccelUnit::kMetersPerSecond2;
      }
    }
  }
  fail(path, line.number, "expected " + expected + ", got " + quote(line.text));
}

// NPTS and DT from AT2 line 4, in any of the forms listed in records.hpp
std::pair<std::size_t, double> at2_npts_dt(const std::string& path, const Line& line) {
  enum class Kind { kNpts, kDt, kNumber };
  struct Token {
    Kind kind;
    std::string text;
    double value = 0.0;
  };
  const std::string got = ", got " + quote(line.text);

  // tokens: labels, numbers ("SEC" units dropped, also when glued to a number)
  std::string u = upper(line.text);
  std::replace_if(
      u.begin(), u.end(), [](char c) { return c == ',' || c == '=' || c == ':'; }, ' ');
  std::vector<Token> tokens;
  for (std::string_view w : split(u, false)) {
    if (w == "NPTS") {
      tokens.push_back({Kind::kNpts, std::string(w)});
      continue;
    }
    if (w == "DT") {
      tokens.push_back({Kind::kDt, std::string(w)});
      continue;
    }
    if (w == "SEC" || w == "SECS" || w == "S" || w == "SECONDS") continue;
    std::string_view num = w;
    for (std::string_view suffix : {"SECS", "SEC", "S"}) {
      if (num.size() > suffix.size() && num.ends_with(suffix)) {
        num.remove_suffix(suffix.size());
        break;
      }
    }
    double v = 0.0;
    const Parsed p = parse_number(num, v);
    if (p == Parsed::kNotFinite) {
      fail(path, line.number, std::string("expected finite ") + kLine4Expected + got);
    }
    if (p != Parsed::kOk) {
      fail(path, line.number,
           std::string("expected ") + kLine4Expected + got + " (unexpected " + quote(w) + ")");
    }
    tokens.push_back({Kind::kNumber, std::string(num), v});
  }

  std::vector<const Token*> labels, numbers;
  for (const Token& t : tokens) (t.kind == Kind::kNumber ? numbers : labels).push_back(&t);
  if (tokens.empty()) fail(path, line.number, std::string("expected ") + kLine4Expected + got);
  if (!labels.empty() && numbers.empty()) {
    fail(path, line.number,
         std::string("expected ") + kLine4Expected + got + " (labels but no numbers)");
  }

  const Token* npts = nullptr;
  const Token* dt = nullptr;
  const auto assign = [&](const Token* label, const Token* number) {
    const Token*& slot = label->kind == Kind::kNpts ? npts : dt;
    if (slot != nullptr) {
      fail(path, line.number,
           std::string("expected ") + kLine4Expected + got + " (" + label->text + " given twice)");
    }
    slot = number;
  };
  if (labels.empty()) {
    // unlabelled "4096 0.0100": the integer literal is NPTS
    const auto integral = [](const Token* t) {
      return std::all_of(t->text.begin(), t->text.end(),
                         [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
    };
    if (numbers.size() != 2 || integral(numbers[0]) == integral(numbers[1])) {
      fail(path, line.number,
           std::string("expected ") + kLine4Expected + got +
               " (without labels, expected exactly two numbers: an integer NPTS and a decimal DT)");
    }
    npts = integral(numbers[0]) ? numbers[0] : numbers[1];
    dt = integral(numbers[0]) ? numbers[1] : numbers[0];
  } else if (tokens.front().kind == Kind::kNumber) {
    // "4096 0.0100 NPTS, DT": numbers first, then the labels in the same order
    const bool ordered = numbers.size() == labels.size() && numbers.size() == 2 &&
                         tokens[2].kind != Kind::kNumber && tokens[1].kind == Kind::kNumber;
    if (!ordered) {
      fail(path, line.number,
           std::string("expected ") + kLine4Expected + got +
               " (expected two numbers followed by their two labels)");
    }
    assign(labels[0], numbers[0]);
    assign(labels[1], numbers[1]);
  } else {
    // "NPTS= 4096, DT= .0100 SEC": each label followed by its number
    for (std::size_t i = 0; i < tokens.size(); i += 2) {
      const Token& t = tokens[i];
      if (t.kind == Kind::kNumber) {
        fail(path, line.number,
             std::string("expected ") + kLine4Expected + got + " (number " + quote(t.text) +
                 " has no label)");
      }
      if (i + 1 >= tokens.size() || tokens[i + 1].kind != Kind::kNumber) {
        fail(path, line.number,
             std::string("expected ") + kLine4Expected + got + " (no number after " + t.text + ")");
      }
      assign(&t, &tokens[i + 1]);
    }
  }
  if (npts == nullptr || dt == nullptr) {
    fail(path, line.number,
         std::string("expected ") + kLine4Expected + got + " (" +
             (npts == nullptr ? "NPTS" : "DT") + " is missing)");
  }
  const double n = npts->value;
  if (!(n >= 1.0 && n <= kMaxPoints && n == std::floor(n))) {
    fail(path, line.number,
         "expected NPTS to be a positive integer (at most 1e8), got " + quote(npts->text) + " in " +
             quote(line.text));
  }
  if (!(dt->value > 0.0)) {
    fail(path, line.number,
         "expected DT to be a positive time step [s], got " + quote(dt->text) + " in " +
             quote(line.text));
  }
  return {static_cast<std::size_t>(n), dt->value};
}

// times i * dt
std::vector<double> uniform_times(std::size_t n, double dt) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<double>(i) * dt;
  return t;
}

// a comment line: '#' as the first non-blank character
bool is_comment(std::string_view s) {
  s = trim(s);
  return !s.empty() && s.front() == '#';
}

// the line up to an inline '#' comment
std::string_view strip_comment(std::string_view s) {
  const std::size_t hash = s.find('#');
  return hash == std::string_view::npos ? s : s.substr(0, hash);
}

// fields of a two-column line: split on commas (CSV, empty fields kept) or whitespace
std::vector<std::string_view> fields(std::string_view s) {
  if (s.find(',') == std::string_view::npos) return split(s, false);
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    out.push_back(trim(s.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  // a trailing comma at the end of a line is allowed
  if (out.size() > 1 && out.back().empty()) out.pop_back();
  return out;
}

// a number with a decimal comma would be split in two at the comma: refused, never split
void refuse_decimal_commas(const std::string& path, const Line& line, std::size_t min_tokens) {
  const std::string n = detail::decimal_comma_number(strip_comment(line.text), min_tokens);
  if (!n.empty()) fail(path, line.number, detail::decimal_comma_message(n));
}

bool all_blank(const std::vector<Line>& lines) {
  return std::all_of(lines.begin(), lines.end(), [](const Line& l) { return is_blank(l.text); });
}

}  // namespace

// the row of a unit in kAccelUnits
const AccelUnitInfo& accel_unit_info(AccelUnit unit) {
  for (const AccelUnitInfo& u : kAccelUnits) {
    if (u.unit == unit) return u;
  }
  FLEXROCK_DEMAND(false);
  return kAccelUnits[0];
}

double to_si_factor(AccelUnit unit) { return accel_unit_info(unit).to_si; }

std::string_view unit_name(AccelUnit unit) { return accel_unit_info(unit).name; }

std::size_t Record::peak_index() const {
  std::size_t k = 0;
  for (std::size_t i = 1; i < values.size(); ++i) {
    if (std::abs(values[i]) > std::abs(values[k])) k = i;
  }
  return k;
}

std::vector<double> Record::to_si(double scale) const {
  FLEXROCK_THROW_UNLESS(std::isfinite(scale),
                        source + ": scale factor must be finite, got " + show(scale));
  const double f = to_si_factor(units) * scale;
  std::vector<double> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = f * values[i];
  return out;
}

GroundMotion Record::to_motion(double scale) const {
  FLEXROCK_THROW_UNLESS(npts() >= 2, source + ": a ground motion needs at least 2 samples, got " +
                                         std::to_string(npts()));
  if (dt > 0.0) return GroundMotion::uniform(dt, to_si(scale), {}, time.front());
  return GroundMotion::sampled(time, to_si(scale));
}

Record read_at2(const std::string& path) {
  const std::vector<Line> lines = read_lines(path);
  if (all_blank(lines)) {
    fail(path, 1, "empty file; expected a PEER NGA .AT2 record (4 header lines, then NPTS values)");
  }
  static constexpr const char* kHeader[] = {
      "header line 1 (\"PEER NGA STRONG MOTION DATABASE RECORD\")",
      "header line 2 (event, date, station, component)",
      "header line 3 (\"ACCELERATION TIME HISTORY IN UNITS OF G\")",
      "header line 4 (NPTS and DT)",
  };
  if (lines.size() < 4) {
    fail(path, lines.size() + 1,
         std::string("expected ") + kHeader[lines.size()] + ", got the end of the file");
  }

  Record r;
  r.source = path;
  for (std::size_t i = 0; i < 4; ++i) r.header.push_back(lines[i].text);
  r.units = at2_units(path, lines[2]);
  const auto [npts, dt] = at2_npts_dt(path, lines[3]);
  r.dt = dt;
  // a short file claiming a huge NPTS must fail on its count, not on a giant allocation: each
  // value needs at least one character and a separator
  std::size_t value_bytes = 0;
  for (std::size_t i = 4; i < lines.size(); ++i) value_bytes += lines[i].text.size() + 1;
  r.values.reserve(std::min(npts, value_bytes / 2 + 1));

  // values: exactly npts finite numbers, any count a line
  for (std::size_t i = 4; i < lines.size(); ++i) {
    refuse_decimal_commas(path, lines[i], 1);
    for (std::string_view token : split(lines[i].text, false)) {
      if (r.values.size() == npts) {
        fail(path, lines[i].number,
             "more values than NPTS = " + std::to_string(npts) + " (line 4): found " +
                 nth_value(npts + 1) + " " + quote(token) + "; expected exactly " +
                 std::to_string(npts) + " values");
      }
      r.values.push_back(
          value_or_fail(path, lines[i].number, token,
                        nth_value(r.values.size() + 1) + " of " + std::to_string(npts)));
    }
  }
  if (r.values.size() < npts) {
    fail(path, lines.size(),
         "expected NPTS = " + std::to_string(npts) + " values (line 4), got only " +
             std::to_string(r.values.size()) + " by the end of the file");
  }
  r.time = uniform_times(npts, dt);
  if (!std::isfinite(r.time.back())) {
    fail(path, 4,
         "DT = " + show(dt) + " s times NPTS = " + std::to_string(npts) +
             " overflows the time axis; expected a DT in seconds (e.g. 0.005)");
  }
  return r;
}

Record read_single_column(const std::string& path, double dt, AccelUnit units) {
  FLEXROCK_THROW_UNLESS(
      std::isfinite(dt) && dt > 0.0,
      path + ": argument 'dt' = " + show(dt) + ", expected a positive finite time step [s]");
  const std::vector<Line> lines = read_lines(path);
  if (all_blank(lines)) fail(path, 1, "empty file; expected acceleration values");

  Record r;
  r.source = path;
  r.units = units;
  r.dt = dt;
  for (const Line& line : lines) {
    if (is_comment(line.text)) {
      r.header.push_back(line.text);
      continue;
    }
    refuse_decimal_commas(path, line, 1);
    for (std::string_view token : split(strip_comment(line.text), true)) {
      r.values.push_back(value_or_fail(path, line.number, token, nth_value(r.values.size() + 1)));
    }
  }
  if (r.values.empty()) {
    fail(path, lines.size(), "expected acceleration values, got only comments and blank lines");
  }
  r.time = uniform_times(r.values.size(), dt);
  FLEXROCK_THROW_UNLESS(std::isfinite(r.time.back()),
                        path + ": argument 'dt' = " + show(dt) + " s times " +
                            std::to_string(r.values.size()) +
                            " values overflows the time axis; expected a time step in seconds");
  return r;
}

Record read_time_series(const std::string& path, AccelUnit units) {
  const std::vector<Line> lines = read_lines(path);
  if (all_blank(lines)) fail(path, 1, "empty file; expected time, acceleration pairs");

  Record r;
  r.source = path;
  r.units = units;
  std::size_t previous_line = 0;
  bool first_row = true;
  for (const Line& line : lines) {
    if (is_comment(line.text)) {
      r.header.push_back(line.text);
      continue;
    }
    const std::string_view body = strip_comment(line.text);
    if (is_blank(body)) continue;
    refuse_decimal_commas(path, line, 2);
    const std::vector<std::string_view> f = fields(body);
    // an optional header row: the first row, if its first field is not a number
    double probe = 0.0;
    if (first_row && parse_number(f.front(), probe) == Parsed::kNotANumber) {
      first_row = false;
      r.header.push_back(line.text);
      continue;
    }
    first_row = false;
    if (f.size() != 2) {
      fail(path, line.number,
           "expected 2 columns (time [s], acceleration), got " + std::to_string(f.size()) + " in " +
               quote(line.text));
    }
    const double t = value_or_fail(path, line.number, f[0], "the time");
    const double a = value_or_fail(path, line.number, f[1], "the acceleration");
    if (!r.time.empty() && !(t > r.time.back())) {
      fail(path, line.number,
           "expected strictly increasing times, got t = " + std::string(f[0]) +
               " s, not after t = " + show(r.time.back()) + " s on line " +
               std::to_string(previous_line));
    }
    r.time.push_back(t);
    r.values.push_back(a);
    previous_line = line.number;
  }
  if (r.values.empty()) {
    fail(path, lines.size(), "expected time, acceleration pairs, got none");
  }

  // uniform sampling: every time within 1e-9 dt of t0 + i dt
  const std::size_t n = r.time.size();
  if (n >= 2) {
    const double dt = (r.time.back() - r.time.front()) / static_cast<double>(n - 1);
    bool uniform = true;
    for (std::size_t i = 0; i < n && uniform; ++i) {
      uniform = std::abs(r.time[i] - (r.time.front() + static_cast<double>(i) * dt)) <= 1e-9 * dt;
    }
    if (uniform) r.dt = dt;
  }
  return r;
}

GroundMotion combine(const Record& horizontal, const Record* vertical, double scale) {
  if (vertical == nullptr) return horizontal.to_motion(scale);
  const Record& h = horizontal;
  const Record& v = *vertical;
  FLEXROCK_THROW_UNLESS(h.npts() >= 2, h.source +
                                           ": a ground motion needs at least 2 samples, "
                                           "got " +
                                           std::to_string(h.npts()));
  FLEXROCK_THROW_UNLESS(v.npts() >= 2, v.source +
                                           ": a vertical component needs at least 2 "
                                           "samples, got " +
                                           std::to_string(v.npts()));
  const auto span = [](const Record& rec) {
    return "(" + show(rec.time.front()) + " s to " + show(rec.time.back()) + " s)";
  };
  FLEXROCK_THROW_UNLESS(v.time.front() < h.time.back() && h.time.front() < v.time.back(),
                        "combine: the vertical record " + v.source + " " + span(v) +
                            " does not overlap the horizontal record " + h.source + " " + span(h) +
                            "; expected time spans that overlap");

  std::vector<double> ax = h.to_si(scale);
  const std::vector<double> vy = v.to_si(scale);
  std::vector<double> ay(h.npts(), 0.0);

  // same grid (to 1e-9 of the step): take the values as they are
  bool same = h.npts() == v.npts();
  const double tol = 1e-9 * (h.time.back() - h.time.front()) / static_cast<double>(h.npts() - 1);
  for (std::size_t i = 0; same && i < h.npts(); ++i) same = std::abs(h.time[i] - v.time[i]) <= tol;
  if (same) {
    ay = vy;
  } else {
    // linear interpolation of the vertical at each horizontal time, zero outside its span
    std::size_t j = 0;
    for (std::size_t i = 0; i < h.npts(); ++i) {
      const double t = h.time[i];
      if (t < v.time.front() || t > v.time.back()) continue;
      while (j + 2 < v.npts() && v.time[j + 1] <= t) ++j;
      const double w = (t - v.time[j]) / (v.time[j + 1] - v.time[j]);
      ay[i] = vy[j] + w * (vy[j + 1] - vy[j]);
    }
  }
  if (h.dt > 0.0) return GroundMotion::uniform(h.dt, std::move(ax), std::move(ay), h.time.front());
  return GroundMotion::sampled(h.time, std::move(ax), std::move(ay));
}

}  // namespace flexrock::io
