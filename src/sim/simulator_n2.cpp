// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 2 mode(s) (see simulator_instances.hpp).
#include "simulator.hpp"

namespace flexrock::detail {
template class Simulator<2, 2>;
}  // namespace flexrock::detail
