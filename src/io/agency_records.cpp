// SPDX-License-Identifier: BSD-3-Clause
// Record files as agencies publish them: USGS SMC, NIED K-NET/KiK-net ASCII, ESM ASCII and
// COSMOS V1/V2. Like the AT2 reader, every error names the file, the line and the header field,
// and says what was expected; header lines are matched by their labels, not their positions,
// where the formats' writers differ.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/io/records.hpp"
#include "record_text.hpp"

namespace flexrock::io {

namespace {

using namespace detail;  // NOLINT(google-build-using-namespace): the text helpers

// a failure at a header field: "path:line: key 'FIELD': message"
[[noreturn]] void fail_field(const std::string& path, std::size_t line, const std::string& field,
                             const std::string& message) {
  throw InputError(path, line, field, message);
}

// the values of lines [first, end), any count a line (blanks or a sign between them), exactly
// `npts` of them; `what` names the format in messages
std::vector<double> read_values(const std::string& path, const std::vector<Line>& lines,
                                std::size_t first, std::size_t npts, const std::string& npts_from) {
  std::vector<double> values;
  std::size_t bytes = 0;
  for (std::size_t i = first; i < lines.size(); ++i) bytes += lines[i].text.size() + 1;
  values.reserve(std::min(npts, bytes / 2 + 1));
  for (std::size_t i = first; i < lines.size(); ++i) {
    refuse_decimal_commas(path, lines[i], 1);
    for (std::string_view token : glued_tokens(lines[i].text)) {
      if (values.size() == npts) {
        fail(path, lines[i].number,
             "more values than the " + std::to_string(npts) + " samples " + npts_from +
                 " states: found " + nth_value(npts + 1) + " " + quote(token));
      }
      values.push_back(value_or_fail(path, lines[i].number, token,
                                     nth_value(values.size() + 1) + " of " + std::to_string(npts)));
    }
  }
  if (values.size() < npts) {
    fail(path, lines.empty() ? 1 : lines.back().number,
         "expected " + std::to_string(npts) + " values (" + npts_from + "), got only " +
             std::to_string(values.size()) + " by the end of the file");
  }
  return values;
}

// a sample count read from a header: a whole number in [1, 1e8]
std::size_t sample_count(const std::string& path, std::size_t line, const std::string& field,
                         double n, const std::string& text) {
  if (!(n >= 1.0 && n <= kMaxPoints && n == std::floor(n))) {
    fail_field(
        path, line, field,
        "expected the number of samples, a positive integer (at most 1e8), got " + quote(text));
  }
  return static_cast<std::size_t>(n);
}

// the times i dt of `r`, refused when they overflow
void set_uniform_times(Record& r, const std::string& path, std::size_t line,
                       const std::string& field) {
  r.time = uniform_times(r.values.size(), r.dt);
  if (!std::isfinite(r.time.back())) {
    fail_field(path, line, field,
               "a sample spacing of " + show(r.dt) + " s over " + std::to_string(r.values.size()) +
                   " samples overflows the time axis; expected a spacing in seconds");
  }
}

// ---- Fortran fixed-width fields (COSMOS) ---------------------------------------------------

// "(8F10.5)", "(10I8)", "(1P5E14.7)": values a line and field width
struct FortranFormat {
  std::size_t per_line = 0;
  std::size_t width = 0;
};

std::optional<FortranFormat> fortran_format(std::string_view text) {
  std::string f;
  for (char c : text) {
    if (!std::isspace(static_cast<unsigned char>(c)) && c != '(' && c != ')') {
      f.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    }
  }
  // a scale factor "1P" or "1P," before the descriptor changes nothing for values with a point
  const std::size_t p = f.find('P');
  if (p != std::string::npos) {
    f.erase(0, p + 1);
    if (!f.empty() && f.front() == ',') f.erase(0, 1);
  }
  std::size_t i = 0;
  const auto number = [&](std::size_t& out) {
    const std::size_t start = i;
    while (i < f.size() && std::isdigit(static_cast<unsigned char>(f[i])) != 0) ++i;
    if (i == start || i - start > 4) return false;
    out = std::stoul(f.substr(start, i - start));
    return true;
  };
  FortranFormat ff;
  if (!number(ff.per_line)) ff.per_line = 1;
  if (i >= f.size() || std::string_view("IFEG").find(f[i]) == std::string_view::npos) {
    return std::nullopt;
  }
  ++i;
  if (!number(ff.width)) return std::nullopt;
  if (i < f.size() && f[i] == '.') {
    ++i;
    std::size_t decimals = 0;
    if (!number(decimals)) return std::nullopt;
  }
  if (i != f.size() || ff.per_line == 0 || ff.width == 0) return std::nullopt;
  return ff;
}

// `count` values in fixed-width fields from lines[at]; `at` moves past them
std::vector<double> fixed_width_values(const std::string& path, const std::vector<Line>& lines,
                                       std::size_t& at, std::size_t count, const FortranFormat& ff,
                                       const std::string& what) {
  std::vector<double> out;
  out.reserve(std::min<std::size_t>(count, 1u << 20));
  while (out.size() < count) {
    if (at >= lines.size()) {
      fail(path, lines.empty() ? 1 : lines.back().number,
           "expected " + std::to_string(count) + " " + what + ", got only " +
               std::to_string(out.size()) + " by the end of the file");
    }
    const Line& line = lines[at++];
    std::string_view text = line.text;
    // fields of `width` characters, up to per_line of them; a short line ends early
    bool ended = false;
    for (std::size_t k = 0; k < ff.per_line && out.size() < count; ++k) {
      const std::size_t start = k * ff.width;
      const std::string_view field =
          start < text.size() ? trim(text.substr(start, ff.width)) : std::string_view{};
      if (field.empty()) {
        ended = true;
        continue;
      }
      if (ended) {
        fail(path, line.number,
             "a blank field before " + quote(field) + " in " + quote(line.text) + "; expected " +
                 what + " in fields of " + std::to_string(ff.width) + " characters with no gaps");
      }
      out.push_back(value_or_fail(path, line.number, field,
                                  what + " " + std::to_string(out.size() + 1) + " of " +
                                      std::to_string(count) + " (fields of " +
                                      std::to_string(ff.width) + " characters)"));
    }
    if (!ended && text.size() > ff.per_line * ff.width &&
        !is_blank(text.substr(ff.per_line * ff.width))) {
      fail(path, line.number,
           "more than " + std::to_string(ff.per_line) + " fields of " + std::to_string(ff.width) +
               " characters in " + quote(line.text) + "; expected the format the header states");
    }
  }
  return out;
}

// the leading integer of a COSMOS count line ("  100 Integer-header values follow on 10 lines,
// Format= (10I8)"): the count, the lines and the format
struct CountLine {
  std::size_t count = 0;
  std::size_t lines = 0;
  FortranFormat format;
};

CountLine cosmos_count_line(const std::string& path, const Line& line, const std::string& kind,
                            bool has_format) {
  const std::string expected =
      has_format ? "\"<n> " + kind + " values follow on <k> lines, Format= (<format>)\""
                 : "\"<n> Comment line(s) follow, each starting with a |\"";
  const std::vector<std::string_view> words = split(line.text, false);
  CountLine c;
  double n = 0.0;
  if (words.empty() || parse_number(words[0], n) != Parsed::kOk || n < 0.0 || n > kMaxPoints ||
      n != std::floor(n)) {
    fail(path, line.number, "expected " + expected + ", got " + quote(line.text));
  }
  c.count = static_cast<std::size_t>(n);
  const std::string u = upper(line.text);
  if (u.find(upper(kind)) == std::string::npos) {
    fail(path, line.number, "expected " + expected + ", got " + quote(line.text));
  }
  if (!has_format) return c;
  const std::size_t on = u.find(" ON ");
  double k = 0.0;
  if (on != std::string::npos) {
    const std::vector<std::string_view> after = split(std::string_view(u).substr(on + 4), false);
    if (!after.empty()) (void)parse_number(after[0], k);
  }
  const std::size_t fmt = u.find("FORMAT");
  std::optional<FortranFormat> ff;
  if (fmt != std::string::npos) {
    std::string_view rest = std::string_view(u).substr(fmt + 6);
    const std::size_t eq = rest.find('=');
    if (eq != std::string_view::npos) ff = fortran_format(rest.substr(eq + 1));
  }
  if (!ff || !(k >= 0.0 && k == std::floor(k))) {
    fail(path, line.number,
         "expected " + expected + " with the line count and a Fortran format such as (10I8), got " +
             quote(line.text));
  }
  c.lines = static_cast<std::size_t>(k);
  c.format = *ff;
  return c;
}

}  // namespace

// ---- USGS SMC --------------------------------------------------------------------------------

Record read_smc(const std::string& path) {
  constexpr std::size_t kText = 11, kIntLines = 6, kInts = 48, kRealLines = 10, kReals = 50;
  constexpr long kIntUnknown = -32768;
  const std::vector<Line> lines = read_lines(path);
  if (all_blank(lines)) fail(path, 1, "empty file; expected a USGS SMC record");
  if (lines.size() < kText + kIntLines + kRealLines) {
    fail(path, lines.size(),
         "expected 11 text lines, 6 lines of integer and 10 of real header values (SMC), got "
         "the end of the file after " +
             std::to_string(lines.size()) + " lines");
  }
  Record r;
  r.source = path;
  r.units = AccelUnit::kCentimetersPerSecond2;  // the format's unit for accelerograms

  // line 1: the data type code
  const std::string_view type = trim(lines[0].text);
  const char code = type.empty() ? ' ' : type.front();
  if (code == '3' || code == '4' || code == '5') {
    fail_field(path, 1, "data type",
               "expected an accelerogram (data type 0, 1 or 2), got " + quote(type) +
                   " (velocity, displacement or spectra: read the accelerogram file instead)");
  }
  if (code != '0' && code != '1' && code != '2') {
    fail_field(path, 1, "data type",
               "expected an SMC text header such as \"2 CORRECTED ACCELEROGRAM\" (data type 0, 1 "
               "or 2), got " +
                   quote(type));
  }
  for (std::size_t i = 0; i < kText; ++i) r.header.push_back(lines[i].text);

  // 48 integers, 8 a line
  std::vector<long> ints;
  for (std::size_t i = kText; i < kText + kIntLines; ++i) {
    for (std::string_view token : split(lines[i].text, false)) {
      double v = 0.0;
      const std::string field = "integer header value " + std::to_string(ints.size() + 1);
      if (parse_number(token, v) != Parsed::kOk || v != std::floor(v) || std::abs(v) > 1e9) {
        fail_field(path, lines[i].number, field, "expected an integer, got " + quote(token));
      }
      ints.push_back(static_cast<long>(v));
    }
  }
  if (ints.size() != kInts) {
    fail(path, lines[kText + kIntLines - 1].number,
         "expected 48 integer header values on lines 12-17 (8 a line), got " +
             std::to_string(ints.size()));
  }
  // 50 reals, 5 a line (E15.7: a sign may follow the previous value without a blank)
  std::vector<double> reals;
  for (std::size_t i = kText + kIntLines; i < kText + kIntLines + kRealLines; ++i) {
    for (std::string_view token : glued_tokens(lines[i].text)) {
      reals.push_back(value_or_fail(path, lines[i].number, token,
                                    "real header value " + std::to_string(reals.size() + 1)));
    }
  }
  if (reals.size() != kReals) {
    fail(path, lines[kText + kIntLines + kRealLines - 1].number,
         "expected 50 real header values on lines 18-27 (5 a line), got " +
             std::to_string(reals.size()));
  }
  const std::size_t int_line3 = lines[kText + 2].number;  // holds the 17th integer
  const std::size_t real_line1 = lines[kText + kIntLines].number;
  const long n_comments = ints[15];
  const long n_samples = ints[16];
  const double real_unknown = reals[0];
  const double rate = reals[1];
  const std::size_t npts = sample_count(
      path, int_line3, "integer header value 17 (samples)",
      n_samples == kIntUnknown ? -1.0 : static_cast<double>(n_samples), std::to_string(n_samples));
  if (!(rate > 0.0 && rate < 1e6 && rate != real_unknown)) {
    fail_field(path, real_line1, "real header value 2 (sampling rate)",
               "expected the sampling rate [samples/s], got " + show(rate) +
                   (rate == real_unknown ? " (the unknown-value marker)" : ""));
  }
  r.dt = 1.0 / rate;

  // the comment lines
  std::size_t at = kText + kIntLines + kRealLines;
  if (n_comments < 0 || static_cast<std::size_t>(n_comments) > lines.size() - at) {
    fail_field(path, lines[kText + 1].number, "integer header value 16 (comment lines)",
               "expected the number of comment lines (0 to " + std::to_string(lines.size() - at) +
                   "), got " + std::to_string(n_comments));
  }
  for (long k = 0; k < n_comments; ++k, ++at) {
    const std::string_view t = lines[at].text;
    if (t.empty() || t.front() != '|') {
      fail(path, lines[at].number,
           "expected comment line " + std::to_string(k + 1) + " of " + std::to_string(n_comments) +
               " (integer header value 16) starting with '|', got " + quote(t));
    }
    r.header.push_back(lines[at].text);
  }
  r.values = read_values(path, lines, at, npts, "integer header value 17");
  set_uniform_times(r, path, real_line1, "real header value 2 (sampling rate)");
  return r;
}

// ---- NIED K-NET / KiK-net ------------------------------------------------------------------

Record read_knet(const std::string& path) {
  const std::vector<Line> lines = read_lines(path);
  if (all_blank(lines)) fail(path, 1, "empty file; expected a K-NET or KiK-net ASCII record");
  Record r;
  r.source = path;
  r.units = AccelUnit::kCentimetersPerSecond2;

  // header: the leading lines that start with a letter ("Origin Time ...", "Memo.")
  std::size_t at = 0;
  std::optional<double> rate, factor;
  std::size_t rate_line = 0;
  const auto label_is = [](std::string_view text, std::string_view label) {
    std::string squeezed;
    for (char c : text) {
      if (!std::isspace(static_cast<unsigned char>(c))) squeezed.push_back(c);
    }
    return upper(squeezed).starts_with(label);
  };
  while (at < lines.size()) {
    const std::string_view t = trim(lines[at].text);
    if (!t.empty() && std::isalpha(static_cast<unsigned char>(t.front())) == 0) break;
    if (t.empty()) {
      ++at;
      continue;
    }
    const Line& line = lines[at++];
    r.header.push_back(line.text);
    const std::vector<std::string_view> words = split(line.text, false);
    const std::string_view value = words.back();
    if (label_is(t, "SAMPLINGFREQ")) {
      // "100Hz"
      std::string_view num = value;
      if (upper(num).ends_with("HZ")) num.remove_suffix(2);
      double f = 0.0;
      if (words.size() < 3 || parse_number(num, f) != Parsed::kOk || !(f > 0.0 && f < 1e6)) {
        fail_field(path, line.number, "Sampling Freq(Hz)",
                   "expected a sampling frequency such as \"100Hz\", got " + quote(line.text));
      }
      rate = f;
      rate_line = line.number;
    } else if (label_is(t, "SCALEFACTOR")) {
      // "3920(gal)/6182761": cm/s^2 per count
      const std::string v(value);
      const std::size_t open = v.find('('), close = v.find(')'), slash = v.find('/');
      double num = 0.0, den = 0.0;
      const bool shaped = open != std::string::npos && close > open && slash > close;
      const bool ok = shaped && upper(v.substr(open + 1, close - open - 1)) == "GAL" &&
                      parse_number(std::string_view(v).substr(0, open), num) == Parsed::kOk &&
                      parse_number(std::string_view(v).substr(slash + 1), den) == Parsed::kOk &&
                      num > 0.0 && den > 0.0;
      if (!ok) {
        fail_field(path, line.number, "Scale Factor",
                   "expected \"<gal>(gal)/<counts>\" such as \"3920(gal)/6182761\", got " +
                       quote(line.text));
      }
      factor = num / den;
    }
  }
  const std::size_t last_header = at == 0 ? 1 : lines[at - 1].number;
  if (!rate) {
    fail_field(path, last_header, "Sampling Freq(Hz)",
               "missing from the header; expected a line such as \"Sampling Freq(Hz) 100Hz\"");
  }
  if (!factor) {
    fail_field(path, last_header, "Scale Factor",
               "missing from the header; expected a line such as \"Scale Factor "
               "3920(gal)/6182761\"");
  }
  for (std::size_t i = at; i < lines.size(); ++i) {
    refuse_decimal_commas(path, lines[i], 1);
    for (std::string_view token : glued_tokens(lines[i].text)) {
      r.values.push_back(*factor * value_or_fail(path, lines[i].number, token,
                                                 "count " + std::to_string(r.values.size() + 1)));
    }
  }
  if (r.values.empty()) fail(path, last_header, "expected counts after the header, got none");
  r.dt = 1.0 / *rate;
  set_uniform_times(r, path, rate_line, "Sampling Freq(Hz)");
  return r;
}

// ---- ESM -----------------------------------------------------------------------------------

Record read_esm(const std::string& path) {
  const std::vector<Line> lines = read_lines(path);
  if (all_blank(lines)) fail(path, 1, "empty file; expected an ESM ASCII record");
  Record r;
  r.source = path;

  // "KEY: value" lines: a key without blanks before the first ':'
  struct Entry {
    std::string value;
    std::size_t line = 0;
  };
  std::optional<Entry> ndata, interval, units, type;
  std::size_t at = 0;
  for (; at < lines.size(); ++at) {
    const std::string_view t = trim(lines[at].text);
    if (t.empty()) continue;
    const std::size_t colon = t.find(':');
    double probe = 0.0;
    if (colon == std::string_view::npos || colon == 0 ||
        t.substr(0, colon).find_first_of(" \t") != std::string_view::npos ||
        parse_number(t, probe) == Parsed::kOk) {
      break;
    }
    r.header.push_back(lines[at].text);
    const std::string key = upper(t.substr(0, colon));
    const Entry e{std::string(trim(t.substr(colon + 1))), lines[at].number};
    if (key == "NDATA") ndata = e;
    if (key == "SAMPLING_INTERVAL_S") interval = e;
    if (key == "UNITS") units = e;
    if (key == "DATA_TYPE") type = e;
  }
  if (r.header.empty()) {
    fail(path, 1,
         "expected ESM header lines \"KEY: value\" (EVENT_NAME:, NDATA:, SAMPLING_INTERVAL_S:, "
         "UNITS:, ...), got " +
             quote(lines[0].text));
  }
  const std::size_t last_header = lines[at == 0 ? 0 : at - 1].number;
  const auto require = [&](const std::optional<Entry>& e, const char* key, const char* example) {
    if (!e) {
      fail_field(path, last_header, key,
                 std::string("missing from the header; expected a line such as \"") + key + ": " +
                     example + "\"");
    }
  };
  require(ndata, "NDATA", "16000");
  require(interval, "SAMPLING_INTERVAL_S", "0.005000");
  require(units, "UNITS", "cm/s^2");
  if (type && upper(type->value).find("ACCELERATION") == std::string::npos) {
    fail_field(path, type->line, "DATA_TYPE",
               "expected an acceleration record, got " + quote(type->value) +
                   " (read the file of the acceleration, *.ACC.ASC, instead)");
  }
  double n = 0.0;
  if (parse_number(ndata->value, n) != Parsed::kOk) n = -1.0;
  const std::size_t npts = sample_count(path, ndata->line, "NDATA", n, ndata->value);
  double dt = 0.0;
  if (parse_number(interval->value, dt) != Parsed::kOk || !(dt > 0.0)) {
    fail_field(path, interval->line, "SAMPLING_INTERVAL_S",
               "expected a positive sample spacing [s], got " + quote(interval->value));
  }
  r.dt = dt;
  const std::optional<AccelUnit> u = accel_unit_from_text(units->value);
  if (!u) {
    fail_field(path, units->line, "UNITS",
               "expected an acceleration unit (cm/s^2, m/s^2 or g), got " + quote(units->value));
  }
  r.units = *u;
  r.values = read_values(path, lines, at, npts, "NDATA");
  set_uniform_times(r, path, interval->line, "SAMPLING_INTERVAL_S");
  return r;
}

// ---- COSMOS V1/V2 ----------------------------------------------------------------------------

Record read_cosmos(const std::string& path) {
  const std::vector<Line> lines = read_lines(path);
  if (all_blank(lines)) fail(path, 1, "empty file; expected a COSMOS V1 or V2 record");
  Record r;
  r.source = path;

  // line 1: "Corrected acceleration  (Format v01.20 with 13 text lines) ..."
  const std::string first = upper(lines[0].text);
  const std::size_t fmt = first.find("(FORMAT V");
  const std::size_t with = first.find("WITH", fmt == std::string::npos ? 0 : fmt);
  double text_lines = 0.0;
  if (with != std::string::npos) {
    const std::vector<std::string_view> w = split(std::string_view(first).substr(with + 4), false);
    if (!w.empty()) (void)parse_number(w[0], text_lines);
  }
  if (fmt == std::string::npos || !(text_lines >= 1.0 && text_lines <= 1000.0) ||
      text_lines != std::floor(text_lines)) {
    fail_field(path, 1, "text header",
               "expected a COSMOS first line such as \"Corrected acceleration  (Format v01.20 "
               "with 13 text lines)\", got " +
                   quote(lines[0].text));
  }
  const std::string kind = first.substr(0, fmt);
  if (kind.find("COUNTS") != std::string::npos || kind.find("ACCELERATION") == std::string::npos) {
    fail_field(path, 1, "data type",
               "expected an acceleration record in physical units (V1 \"Uncorrected "
               "acceleration\" or V2 \"Corrected acceleration\"), got " +
                   quote(trim(lines[0].text.substr(0, fmt))) +
                   " (raw counts, velocity, displacement or spectra are not read)");
  }
  const std::size_t n_text = static_cast<std::size_t>(text_lines);
  std::size_t at = n_text;
  if (lines.size() <= at) {
    fail(path, lines.size(),
         "expected " + std::to_string(n_text) +
             " text lines (line 1) and the integer header, got the end of the file");
  }
  for (std::size_t i = 0; i < n_text; ++i) r.header.push_back(lines[i].text);
  // the unknown-value markers on the last text line ("... unknown/unspecified:   -999, -999.0")
  std::optional<double> real_unknown;
  {
    const std::string& t = lines[n_text - 1].text;
    const std::size_t colon = t.rfind(':');
    if (colon != std::string::npos && upper(t).find("UNKNOWN") != std::string::npos) {
      const std::vector<std::string_view> w = split(std::string_view(t).substr(colon + 1), true);
      double v = 0.0;
      if (w.size() >= 2 && parse_number(w[1], v) == Parsed::kOk) real_unknown = v;
    }
  }

  // the integer header, then the real header, each after its count line
  const CountLine ic = cosmos_count_line(path, lines[at], "Integer-header", true);
  ++at;
  (void)fixed_width_values(path, lines, at, ic.count, ic.format, "integer header values");
  if (at >= lines.size())
    fail(path, lines.size(), "expected the real-header count line, got the end of the file");
  const CountLine rc = cosmos_count_line(path, lines[at], "Real-header", true);
  const std::size_t real_start = lines[at].number + 1;
  ++at;
  const std::vector<double> reals =
      fixed_width_values(path, lines, at, rc.count, rc.format, "real header values");
  // the line of real value k (1-based), for messages
  const auto real_line = [&](std::size_t k) { return real_start + (k - 1) / rc.format.per_line; };
  if (at >= lines.size())
    fail(path, lines.size(), "expected the comment count line, got the end of the file");
  const CountLine cc = cosmos_count_line(path, lines[at], "Comment", false);
  ++at;
  for (std::size_t k = 0; k < cc.count; ++k, ++at) {
    if (at >= lines.size()) {
      fail(path, lines.size(),
           "expected " + std::to_string(cc.count) + " comment lines, got the end of the file");
    }
    r.header.push_back(lines[at].text);
  }

  // the data line: "16596 acceleration pts, approx 82 secs, units=cm/sec2 (04), Format=(8F10.5)"
  if (at >= lines.size())
    fail(path, lines.size(), "expected the data line, got the end of the file");
  const Line& data = lines[at++];
  const std::string du = upper(data.text);
  const std::string expected_data =
      "a data line such as \"16596 acceleration pts, approx 82 secs, units=cm/sec2 (04), "
      "Format=(8F10.5)\"";
  const std::vector<std::string_view> dw = split(data.text, false);
  double n = -1.0;
  if (dw.empty() || parse_number(dw[0], n) != Parsed::kOk ||
      du.find("ACCELERATION") == std::string::npos) {
    fail_field(path, data.number, "data line",
               "expected " + expected_data + ", got " + quote(data.text));
  }
  const std::size_t npts = sample_count(path, data.number, "data line", n, std::string(dw[0]));
  // units: the text after "units=", else the code in parentheses (COSMOS table 2)
  std::optional<AccelUnit> unit;
  const std::size_t ueq = du.find("UNITS=");
  if (ueq != std::string::npos) {
    const std::string_view rest = std::string_view(du).substr(ueq + 6);
    const std::size_t end = rest.find_first_of("(,");
    unit = accel_unit_from_text(rest.substr(0, end));
    const std::size_t open = rest.find('(');
    if (!unit && open != std::string_view::npos && open == end) {
      const std::string_view code = trim(rest.substr(open + 1, rest.find(')') - open - 1));
      if (code == "04" || code == "4" || code == "10") unit = AccelUnit::kCentimetersPerSecond2;
      if (code == "02" || code == "2") unit = AccelUnit::kG;
    }
  }
  if (!unit) {
    fail_field(
        path, data.number, "units",
        "expected units=cm/sec2 (04), units=g (02) or units=gal (10) in " + quote(data.text));
  }
  r.units = *unit;
  const std::size_t feq = du.find("FORMAT=");
  const std::optional<FortranFormat> ff =
      feq == std::string::npos ? std::nullopt
                               : fortran_format(std::string_view(du).substr(feq + 7));
  if (!ff) {
    fail_field(path, data.number, "Format",
               "expected a Fortran format such as Format=(8F10.5) in " + quote(data.text));
  }

  // the sample interval: real value 62 [ms]
  constexpr std::size_t kDtIndex = 62;
  if (reals.size() < kDtIndex || !(reals[kDtIndex - 1] > 0.0) ||
      (real_unknown && reals[kDtIndex - 1] == *real_unknown)) {
    fail_field(path, reals.size() < kDtIndex ? real_start : real_line(kDtIndex),
               "real header value 62 (sample interval, ms)",
               "expected the sample interval [ms], got " +
                   (reals.size() < kDtIndex ? std::string("only ") + std::to_string(reals.size()) +
                                                  " real header values"
                                            : show(reals[kDtIndex - 1])));
  }
  r.dt = reals[kDtIndex - 1] / 1000.0;
  r.values = fixed_width_values(path, lines, at, npts, *ff, "acceleration values");
  set_uniform_times(r, path, real_line(kDtIndex), "real header value 62 (sample interval, ms)");
  return r;
}

}  // namespace flexrock::io
