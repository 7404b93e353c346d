// SPDX-License-Identifier: BSD-3-Clause
// The body sizes the event loop is compiled for: fixed sizes up to FLEXROCK_FIXED_MODES modes (8;
// the sanitizer builds keep 2) for the usual bodies (the products of the equations then unroll,
// where a dynamic size calls a general kernel for each), a stack-bounded size up to 16 modes,
// heap beyond. Each size's loop is compiled once, in its own file (simulator_n*.cpp), so that the
// sizes compile in parallel; this header declares only the entry point, so that the file that
// picks a size (simulate.cpp) does not see the loop's class at all (naming the class there
// instantiated its destructor and virtual members for every size: two CPU-minutes of the build).
// Internal header.
#pragma once

#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock::detail {

/// One run of the event loop for a body of N modes (at most MaxN): the loop's constructor and run.
template <int N, int MaxN>
SimulationResult run_event_loop(const Body& body, const GroundMotion& motion,
                                const SimulationOptions& opt, const InitialState& init);

}  // namespace flexrock::detail
