// SPDX-License-Identifier: BSD-3-Clause
// Checks that a call throws flexrock::InputError with every expected fragment in its message.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <string>

#include "flexrock/core/error.hpp"

namespace flexrock::test {

// expects fn() to throw InputError whose message holds every one of `parts`
inline void expect_input_error(const std::function<void()>& fn,
                               std::initializer_list<std::string> parts) {
  try {
    fn();
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const std::string& p : parts) {
      EXPECT_NE(what.find(p), std::string::npos) << "message lacks \"" << p << "\": " << what;
    }
    return;
  }
  ADD_FAILURE() << "no InputError thrown";
}

}  // namespace flexrock::test
