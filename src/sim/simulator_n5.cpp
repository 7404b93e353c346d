// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 5 mode(s) (see simulator_instances.hpp).
#include "simulator.hpp"

namespace flexrock::detail {
template class Simulator<5, 5>;
}  // namespace flexrock::detail
