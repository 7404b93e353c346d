// SPDX-License-Identifier: BSD-3-Clause
// The event loop for bodies with 8 mode(s) (see simulator_instances.hpp).
#include "simulator.hpp"

namespace flexrock::detail {
// only the entry points: the members they reach are compiled with them, and no other (a
// rigid body's loop has no record walk, a flexible body's no series, arc or still path)
template Simulator<8, 8>::Simulator(const Body&, const GroundMotion&, const SimulationOptions&);
template SimulationResult Simulator<8, 8>::run(const InitialState&);
}  // namespace flexrock::detail
