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

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/io/files.hpp"
#include "record_text.hpp"

namespace flexrock::io {

namespace {

using namespace detail;  // NOLINT(google-build-using-namespace): the text helpers

// what AT2 line 4 must hold, for messages
constexpr const char* kLine4Expected =
    "NPTS and DT, e.g. \"NPTS=   4096, DT=   .0100 SEC\" or \"4096    0.0100    NPTS, DT\"";
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
      if (const std::optional<AccelUnit> unit = accel_unit_from_text(words.front())) return *unit;
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

namespace {

// The fields of a two-column line, into `out`: split on semicolons (a comma then being a decimal
// mark), on commas (CSV, empty fields kept) or on whitespace. `out` is the reader's, reused line
// after line: its strings keep their storage, so a line costs no allocation (a fresh vector of
// fresh strings was most of the reader's time: about 1,500 of its 4,200 instructions a line).
class RowFields {
 public:
  std::size_t size() const { return n_; }
  const std::string& operator[](std::size_t k) const { return f_[k]; }
  const std::string& front() const { return f_[0]; }

  void split_row(std::string_view s) {
    n_ = 0;
    const char sep = s.find(';') != std::string_view::npos   ? ';'
                     : s.find(',') != std::string_view::npos ? ','
                                                             : ' ';
    if (sep == ' ') {
      // a bracketed unit after a name belongs to it: "time [s]   acc [g]" is two fields
      split_into(s, false, words_);
      for (const std::string_view w : words_) {
        if (n_ > 0 && (w.front() == '[' || w.front() == '(')) {
          f_[n_ - 1].append(" ").append(w);
        } else {
          next().assign(w);
        }
      }
      return;
    }
    std::size_t start = 0;
    while (true) {
      const std::size_t at = s.find(sep, start);
      std::string& f = next();
      f.assign(trim(s.substr(start, at == std::string_view::npos ? at : at - start)));
      if (sep == ';' && detail::decimal_comma_token(f)) std::replace(f.begin(), f.end(), ',', '.');
      if (at == std::string_view::npos) break;
      start = at + 1;
    }
    // a trailing separator at the end of a line is allowed
    if (n_ > 1 && f_[n_ - 1].empty()) --n_;
  }

 private:
  std::string& next() {
    if (n_ == f_.size()) f_.emplace_back();
    return f_[n_++];
  }
  std::vector<std::string> f_;
  std::vector<std::string_view> words_;  // a whitespace-separated line's words, reused
  std::size_t n_ = 0;
};

// the unit a header field states: the whole field ("g", "[s]") or its last bracketed part
// ("acc [cm/s^2]", "t(s)"); empty when it states none
std::string stated_unit(std::string_view field) {
  field = trim(field);
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    if (!field.empty() && field.back() == close) {
      const std::size_t at = field.rfind(open);
      if (at != std::string_view::npos)
        return std::string(trim(field.substr(at + 1, field.size() - at - 2)));
    }
  }
  return std::string(field);
}

bool is_seconds(std::string_view u) {
  const std::string x = upper(u);
  return x == "S" || x == "SEC" || x == "SECS" || x == "SECOND" || x == "SECONDS";
}

// text that names a unit ("ft/s^2", "mg"), not a word such as "horizontal"
bool looks_like_unit(std::string_view u) {
  const std::string x = upper(u);
  return x.find_first_of("/^*") != std::string::npos || x == "MG" || x == "UG" || x == "MGAL";
}

// a time unit other than seconds, which flexrock does not convert
bool is_other_time_unit(std::string_view u) {
  const std::string x = upper(u);
  return x == "MS" || x == "MSEC" || x == "MIN" || x == "H" || x == "HR" || x == "US";
}

}  // namespace

Record read_time_series(const std::string& path, std::optional<AccelUnit> units) {
  const std::vector<Line> lines = read_lines(path);
  if (all_blank(lines)) fail(path, 1, "empty file; expected time, acceleration pairs");

  Record r;
  r.source = path;
  std::optional<AccelUnit> stated;  // the acceleration unit the header rows state
  std::size_t stated_line = 0;
  std::size_t previous_line = 0;
  std::size_t header_rows = 0;  // rows of names or units before the first pair (at most 2)
  std::size_t columns = 0;      // fields of the first pair's row
  std::size_t columns_line = 0;
  RowFields f;
  for (const Line& line : lines) {
    if (is_comment(line.text)) {
      r.header.push_back(line.text);
      continue;
    }
    const std::string_view body = strip_comment(line.text);
    if (is_blank(body)) continue;
    if (body.find(';') == std::string_view::npos) refuse_decimal_commas(path, line, 2);
    f.split_row(body);
    // rows of names or units before the first pair: their first field is not a number
    double probe = 0.0;
    if (r.time.empty() && header_rows < 2 &&
        parse_number(f.front(), probe) == Parsed::kNotANumber) {
      ++header_rows;
      r.header.push_back(line.text);
      if (f.size() >= 2) {
        const std::string tu = stated_unit(f[0]);
        if (is_other_time_unit(tu)) {
          throw InputError(path, line.number, "column 1",
                           "expected the time in seconds, got \"" + tu + "\" in " +
                               quote(line.text) + "; convert the times to s");
        }
        const std::string au = stated_unit(f[1]);
        const std::optional<AccelUnit> u = accel_unit_from_text(au);
        if (u) {
          stated = u;
          stated_line = line.number;
        } else if ((f[1] != au || is_seconds(tu)) && looks_like_unit(au)) {
          // a unit (bracketed, or in a units row) that is no acceleration unit flexrock knows
          throw InputError(path, line.number, "column 2",
                           "expected an acceleration unit (g, m/s^2, cm/s^2, gal), got \"" + au +
                               "\" in " + quote(line.text));
        }
      }
      continue;
    }
    if (columns == 0) {
      if (f.size() < 2) {
        fail(path, line.number,
             "expected 2 columns (time [s], acceleration), got " + std::to_string(f.size()) +
                 " in " + quote(line.text));
      }
      columns = f.size();
      columns_line = line.number;
    }
    if (f.size() != columns) {
      fail(path, line.number,
           "expected " + std::to_string(columns) + " columns (time [s], acceleration" +
               (columns > 2 ? ", and the columns not read" : "") + ") as on line " +
               std::to_string(columns_line) + ", got " + std::to_string(f.size()) + " in " +
               quote(line.text));
    }
    const double t = value_or_fail(path, line.number, f[0], "the time");
    const double a = value_or_fail(path, line.number, f[1], "the acceleration");
    if (!r.time.empty() && !(t > r.time.back())) {
      fail(path, line.number,
           "expected strictly increasing times, got t = " + f[0] + " s, not after t = " +
               show(r.time.back()) + " s on line " + std::to_string(previous_line));
    }
    r.time.push_back(t);
    r.values.push_back(a);
    previous_line = line.number;
  }
  if (r.values.empty()) {
    fail(path, lines.size(), "expected time, acceleration pairs, got none");
  }
  if (stated && units && *stated != *units) {
    throw InputError(path, stated_line, "column 2",
                     "the file states the accelerations in " + std::string(unit_name(*stated)) +
                         ", but " + std::string(unit_name(*units)) +
                         " was given; expected the units the file states");
  }
  if (!stated && !units) {
    fail(path, 1,
         "the file does not state the units of its accelerations (no units row such as \"s, g\" "
         "or \"time [s], acc [cm/s^2]\"); expected the units to be given (g, m/s^2 or cm/s^2)");
  }
  r.units = stated ? *stated : *units;

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

// ---- the table of formats ------------------------------------------------------------------

const std::vector<RecordFormat>& record_formats() {
  using U = std::optional<AccelUnit>;
  static const std::vector<RecordFormat> formats = {
      {"at2", ".at2", false, RecordUnits::kFile, "PEER (NGA, NGA-West2)",
       "4 header lines (units on line 3, NPTS and DT in any of their forms on line 4), then NPTS "
       "values",
       [](const std::string& p, double, U) { return read_at2(p); }},
      {"smc", ".smc", false, RecordUnits::kFile, "USGS (strong-motion CD-ROMs; PEER's PEA2SMC)",
       "11 text lines, 48 integers (samples: the 17th), 50 reals (sampling rate: the 2nd), "
       "comment lines, then the values in cm/s^2",
       [](const std::string& p, double, U) { return read_smc(p); }},
      {"knet", ".ns .ew .ud .ns1 .ew1 .ud1 .ns2 .ew2 .ud2", false, RecordUnits::kFile,
       "NIED (K-NET, KiK-net)",
       "17 header lines (sampling frequency, scale factor), then counts; values = counts x scale "
       "factor [cm/s^2], offset kept",
       [](const std::string& p, double, U) { return read_knet(p); }},
      {"esm", ".acc.asc", false, RecordUnits::kFile,
       "ESM (Engineering Strong Motion database, ORFEUS)",
       "\"KEY: value\" header lines (NDATA, SAMPLING_INTERVAL_S, UNITS), then NDATA values",
       [](const std::string& p, double, U) { return read_esm(p); }},
      {"cosmos", ".v1 .v2 .v1c .v2c", false, RecordUnits::kFile, "COSMOS V1/V2 (CESMD, CGS, USGS)",
       "text, integer, real and comment headers, then the first acceleration block in its "
       "Fortran format (sample interval: real value 62, ms)",
       [](const std::string& p, double, U) { return read_cosmos(p); }},
      {"single_column", "", true, RecordUnits::kGiven, "any",
       "values every `dt`, any count a line, blanks or commas between them; '#' comments",
       [](const std::string& p, double dt, U u) {
         return read_single_column(p, dt, u.value_or(AccelUnit::kG));
       }},
      {"time_series", "", false, RecordUnits::kFileOrGiven, "any (spreadsheets, CSV exports)",
       "time [s], acceleration pairs; blanks, commas or semicolons (then a decimal comma); an "
       "optional names row and units row (`s, g`); columns after the second not read",
       [](const std::string& p, double, U u) { return read_time_series(p, u); }},
  };
  return formats;
}

const RecordFormat* find_record_format(std::string_view name) {
  for (const RecordFormat& f : record_formats()) {
    if (name == f.name) return &f;
  }
  return nullptr;
}

const RecordFormat* record_format_for(const std::string& path) {
  std::string name = path;
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const RecordFormat& f : record_formats()) {
    for (std::string_view suffix : split(f.suffixes, false)) {
      if (name.size() > suffix.size() && name.ends_with(suffix)) return &f;
    }
  }
  return nullptr;
}

std::string record_format_names() {
  std::string s;
  for (const RecordFormat& f : record_formats()) s += (s.empty() ? "" : ", ") + std::string(f.name);
  return s;
}

Record read_record(const std::string& path, const std::string& format, double dt,
                   std::optional<AccelUnit> units) {
  const RecordFormat* f = format.empty() ? record_format_for(path) : find_record_format(format);
  if (f == nullptr) {
    throw InputError(path + ": format: " +
                     (format.empty() ? std::string("the file name does not say the format")
                                     : "unknown format \"" + format + "\"") +
                     "; expected one of: " + record_format_names());
  }
  if (f->needs_dt && !(std::isfinite(dt) && dt > 0.0)) {
    throw InputError(path + ": dt: expected a positive sample spacing [s] for the " +
                     std::string(f->name) + " format, got " + show(dt));
  }
  if (f->units == RecordUnits::kGiven && !units) {
    throw InputError(path +
                     ": units: expected the units of the file's values (g, m/s^2 or "
                     "cm/s^2) for the " +
                     std::string(f->name) + " format");
  }
  Record r = f->read(path, dt, units);
  if (units && *units != r.units) {
    throw InputError(path + ": units: the file states its values in " +
                     std::string(unit_name(r.units)) + ", but " + std::string(unit_name(*units)) +
                     " was given; expected the units the file states (or none)");
  }
  return r;
}

std::string record_format_reference() {
  std::string s =
      "<!-- begin: written by `flexrock keys --markdown` from the table of record formats "
      "(src/io/records.cpp); edit the table, not these lines -->\n"
      "| `format` | chosen for names ending in | `dt` | `units` | published by | layout |\n"
      "|---|---|---|---|---|---|\n";
  for (const RecordFormat& f : record_formats()) {
    std::string suffixes;
    for (std::string_view x : split(f.suffixes, false)) {
      suffixes += (suffixes.empty() ? "`" : ", `") + std::string(x) + "`";
    }
    s += "| `" + std::string(f.name) + "` | " + (suffixes.empty() ? "(give `format`)" : suffixes) +
         " | " + (f.needs_dt ? "required" : "from the file") + " | " +
         (f.units == RecordUnits::kGiven         ? "required"
          : f.units == RecordUnits::kFileOrGiven ? "from a units row, else required"
                                                 : "from the file") +
         " | " + f.publisher + " | " + f.doc + " |\n";
  }
  return s + "<!-- end: written by `flexrock keys --markdown` -->\n";
}

}  // namespace flexrock::io
