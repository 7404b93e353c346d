// SPDX-License-Identifier: BSD-3-Clause
// Error reporting: InputError for what the user gave, FLEXROCK_DEMAND for our own invariants.
#pragma once

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>

namespace flexrock {

/// Thrown when user input (parameters, records, options) is invalid. The message says what is
/// wrong, where, and what would be right. An error of a file carries the place as fields (file,
/// line, key); its message is built from them: "<file>:<line>: key '<key>': <what>".
class InputError : public std::runtime_error {
 public:
  /// An error whose message already says all (no place, or one written into the text).
  explicit InputError(const std::string& message) : std::runtime_error(message), what_(message) {}
  /// An error at a place of a file: `line` 0 when unknown, `key` empty when none.
  InputError(std::string file, std::size_t line, std::string key, const std::string& what)
      : std::runtime_error(compose(file, line, key, what)),
        file_(std::move(file)),
        line_(line),
        key_(std::move(key)),
        what_(what) {}

  const std::string& file() const { return file_; }    // empty: no place
  std::size_t line() const { return line_; }           // 1-based; 0: unknown
  const std::string& key() const { return key_; }      // full key ("body.width"); empty: none
  const std::string& detail() const { return what_; }  // the message without the place
  bool has_place() const { return !file_.empty(); }

 private:
  static std::string compose(const std::string& file, std::size_t line, const std::string& key,
                             const std::string& what) {
    std::string s = file + ":";
    if (line > 0) s += std::to_string(line) + ":";
    if (!key.empty()) s += " key '" + key + "':";
    return s + " " + what;
  }
  std::string file_;
  std::size_t line_ = 0;
  std::string key_;
  std::string what_;
};

namespace detail {
[[noreturn]] inline void demand_failed(const char* cond, const char* file, int line) {
  std::fprintf(stderr, "flexrock: internal invariant failed: %s at %s:%d\n", cond, file, line);
  std::abort();
}
}  // namespace detail

}  // namespace flexrock

// user input check: throws flexrock::InputError with the message (a std::string expression)
#define FLEXROCK_THROW_UNLESS(cond, message)                         \
  do {                                                               \
    if (!(cond)) throw ::flexrock::InputError(std::string(message)); \
  } while (0)

// invariant check, always on: a failure is a bug in flexrock
#define FLEXROCK_DEMAND(cond)                                                  \
  do {                                                                         \
    if (!(cond)) ::flexrock::detail::demand_failed(#cond, __FILE__, __LINE__); \
  } while (0)
