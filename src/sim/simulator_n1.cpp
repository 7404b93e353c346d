// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 1 mode(s) (see simulator_instances.hpp).
#include "simulator.hpp"

namespace flexrock::detail {
template SimulationResult run_event_loop<1, 1>(const Body&, const GroundMotion&,
                                               const SimulationOptions&, const InitialState&);
}  // namespace flexrock::detail
