// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/version.hpp"

namespace flexrock {

// compiled into the library, so that a program can tell which library it runs with
const char* version() noexcept { return FLEXROCK_VERSION_STRING; }

}  // namespace flexrock
