// SPDX-License-Identifier: BSD-3-Clause
// Numbers as text, in one place: data files write the shortest text that reads back to the same
// double; messages write a fixed count of significant digits. In core so that every layer (the
// model's checks as well as io's files) formats alike; no file is touched here.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace flexrock {

/// The shortest text that reads back to the same double ("0.1", "1e-300", "6.283185307179586");
/// "nan", "inf" and "-inf" for the values that are not finite.
inline std::string format_number(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// `digits` significant digits, as printf's "%.<digits>g" ("0.3333333333" for 10 digits): for
/// messages, where a value the loader computed need not read back exactly.
inline std::string format_number(double v, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace flexrock
