// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer entry point: see fuzz_inputs.hpp. Build with the "fuzz" preset (clang).
#include <cstddef>
#include <cstdint>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  flexrock::fuzz::agency(data, size);
  return 0;
}
