// SPDX-License-Identifier: BSD-3-Clause
// The body sizes the event loop is compiled for: fixed sizes up to FLEXROCK_FIXED_MODES modes (8;
// the sanitizer builds keep 2) for the usual bodies (the products of the equations then unroll,
// where a dynamic size calls a general kernel for each), a stack-bounded size up to 16 modes,
// heap beyond. Each is instantiated once, in its own file (simulator_n*.cpp), so that they
// compile in parallel; a size not compiled is never named (simulate.cpp). Internal header.
#pragma once

#include "simulator.hpp"

namespace flexrock::detail {

extern template class Simulator<0, 0>;
extern template class Simulator<1, 1>;
extern template class Simulator<2, 2>;
extern template class Simulator<3, 3>;
extern template class Simulator<4, 4>;
extern template class Simulator<5, 5>;
extern template class Simulator<6, 6>;
extern template class Simulator<7, 7>;
extern template class Simulator<8, 8>;
extern template class Simulator<Eigen::Dynamic, 16>;
extern template class Simulator<Eigen::Dynamic, Eigen::Dynamic>;

}  // namespace flexrock::detail
