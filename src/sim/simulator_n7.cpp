// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 7 mode(s) (see simulator_instances.hpp).
#include "simulator.hpp"

namespace flexrock::detail {
template class Simulator<7, 7>;
}  // namespace flexrock::detail
