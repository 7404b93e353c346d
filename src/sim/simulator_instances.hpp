// SPDX-License-Identifier: BSD-3-Clause
// The body sizes the event loop is compiled for: fixed sizes up to FLEXROCK_FIXED_MODES modes (8;
// the sanitizer builds keep 2) for the usual bodies (the products of the equations then unroll,
// where a dynamic size calls a general kernel for each), a stack-bounded size up to 16 modes,
// heap beyond. Each size's entry points (the constructor and run) are instantiated once, in its own
// file (simulator_n*.cpp), so that they compile in parallel, and with them only the members they
// reach; a size not compiled is never named (simulate.cpp). Internal header.
#pragma once

#include "simulator.hpp"

namespace flexrock::detail {

extern template Simulator<0, 0>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<0, 0>::run(const InitialState&);
extern template Simulator<1, 1>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<1, 1>::run(const InitialState&);
extern template Simulator<2, 2>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<2, 2>::run(const InitialState&);
extern template Simulator<3, 3>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<3, 3>::run(const InitialState&);
extern template Simulator<4, 4>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<4, 4>::run(const InitialState&);
extern template Simulator<5, 5>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<5, 5>::run(const InitialState&);
extern template Simulator<6, 6>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<6, 6>::run(const InitialState&);
extern template Simulator<7, 7>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<7, 7>::run(const InitialState&);
extern template Simulator<8, 8>::Simulator(const Body&, const GroundMotion&,
                                           const SimulationOptions&);
extern template SimulationResult Simulator<8, 8>::run(const InitialState&);
extern template Simulator<Eigen::Dynamic, 16>::Simulator(const Body&, const GroundMotion&,
                                                         const SimulationOptions&);
extern template SimulationResult Simulator<Eigen::Dynamic, 16>::run(const InitialState&);
extern template Simulator<Eigen::Dynamic, Eigen::Dynamic>::Simulator(const Body&,
                                                                     const GroundMotion&,
                                                                     const SimulationOptions&);
extern template SimulationResult Simulator<Eigen::Dynamic, Eigen::Dynamic>::run(
    const InitialState&);

}  // namespace flexrock::detail
