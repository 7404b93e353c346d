// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 9 to 16 modes (stack-bounded) and with more (heap), see
// simulator_instances.hpp.
#include "simulator.hpp"

namespace flexrock::detail {
// only the entry points: the members they reach are compiled with them, and no other (a
// rigid body's loop has no record walk, a flexible body's no series, arc or still path)
template Simulator<Eigen::Dynamic, 16>::Simulator(const Body&, const GroundMotion&,
                                                  const SimulationOptions&);
template SimulationResult Simulator<Eigen::Dynamic, 16>::run(const InitialState&);
template Simulator<Eigen::Dynamic, Eigen::Dynamic>::Simulator(const Body&, const GroundMotion&,
                                                              const SimulationOptions&);
template SimulationResult Simulator<Eigen::Dynamic, Eigen::Dynamic>::run(const InitialState&);
}  // namespace flexrock::detail
