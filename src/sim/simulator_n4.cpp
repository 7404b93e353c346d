// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 4 mode(s) (see simulator_instances.hpp).
#include "simulator.hpp"

namespace flexrock::detail {
template SimulationResult run_event_loop<4, 4>(const Body&, const GroundMotion&,
                                               const SimulationOptions&, const InitialState&);
}  // namespace flexrock::detail
