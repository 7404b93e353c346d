// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 9 to 16 modes (stack-bounded) and with more (heap), see
// simulator_instances.hpp.
#include "simulator.hpp"

namespace flexrock::detail {
template SimulationResult run_event_loop<Eigen::Dynamic, 16>(const Body&, const GroundMotion&,
                                                             const SimulationOptions&,
                                                             const InitialState&);
template SimulationResult run_event_loop<Eigen::Dynamic, Eigen::Dynamic>(const Body&,
                                                                         const GroundMotion&,
                                                                         const SimulationOptions&,
                                                                         const InitialState&);
}  // namespace flexrock::detail
