// SPDX-License-Identifier: BSD-3-Clause
// Error reporting: InputError for what the user gave, FLEXROCK_DEMAND for our own invariants.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace flexrock {

/// Thrown when user input (parameters, records, options) is invalid. The message says what is
/// wrong, where, and what would be right.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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
