// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 9 to 16 modes (stack-bounded) and with more (heap), see
// simulator_instances.hpp.
#include "simulator.hpp"

namespace flexrock::detail {
template class Simulator<Eigen::Dynamic, 16>;
template class Simulator<Eigen::Dynamic, Eigen::Dynamic>;
}  // namespace flexrock::detail
