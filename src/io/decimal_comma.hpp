// SPDX-License-Identifier: BSD-3-Clause
// Numbers written with a decimal comma ("-0,050"), which the readers of text files would split
// at the comma into two numbers. flexrock reads '.' as the decimal mark only; a line whose commas
// can only be decimal commas is refused, never split. Internal to flexrock::io.
#pragma once

#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace flexrock::io::detail {

// "-0,050", "1,25E-03": an optional sign, digits, one comma, digits, an optional exponent
inline bool decimal_comma_token(std::string_view t) {
  const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  const std::size_t int_start = i;
  while (i < t.size() && digit(t[i])) ++i;
  if (i == int_start || i >= t.size() || t[i] != ',') return false;
  const std::size_t frac_start = ++i;
  while (i < t.size() && digit(t[i])) ++i;
  if (i == frac_start) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    const std::size_t exp_start = i;
    while (i < t.size() && digit(t[i])) ++i;
    if (i == exp_start) return false;
  }
  return i == t.size();
}

// The first number of `line` written with a decimal comma when the line's commas can be nothing
// else, or "" when the line is fine. They can be nothing else when ';' separates the values
// ("0,01;-0,05"), or when every comma of the line lies inside such a number and the line has at
// least `min_tokens` of them, separated by blanks ("0,01 -0,05"). A single "1,5" is two values
// for a reader of comma-separated pairs (min_tokens 2) and a decimal comma for a reader of
// values (min_tokens 1), where it is refused as ambiguous.
inline std::string decimal_comma_number(std::string_view line, std::size_t min_tokens) {
  // no comma, no decimal comma: the common line returns before any work (a record's reader
  // calls this once a line)
  if (line.find(',') == std::string_view::npos) return {};
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  const auto sep = [](char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ';'; };
  while (i < line.size()) {
    while (i < line.size() && sep(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !sep(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  std::string_view first;
  std::size_t commas_inside = 0;
  for (std::string_view t : tokens) {
    if (!decimal_comma_token(t)) continue;
    if (first.empty()) first = t;
    ++commas_inside;
  }
  if (first.empty()) return {};
  const bool semicolons = line.find(';') != std::string_view::npos;
  std::size_t commas = 0;
  for (char c : line) commas += c == ',' ? 1 : 0;
  if (semicolons || (commas == commas_inside && tokens.size() >= min_tokens)) {
    return std::string(first);
  }
  return {};
}

// the message for a decimal comma found in `token`
inline std::string decimal_comma_message(const std::string& token) {
  std::string dot = token;
  for (char& c : dot) {
    if (c == ',') c = '.';
  }
  return "found \"" + token +
         "\", a number with a decimal comma? flexrock reads only '.' as the decimal mark and a "
         "comma as a separator, so it would split this number in two; write " +
         dot + " (or, if these are two values, put a blank after the comma)";
}

}  // namespace flexrock::io::detail
