// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's loop for bodies of more than 16 modes (heap), compiled apart from the
// stack-bounded size (compliant.cpp) so that the two compile in parallel.
#include "compliant_loop.hpp"

namespace flexrock::detail {
template SimulationResult run_compliant<Eigen::Dynamic>(const Body&, const GroundMotion&,
                                                        const InitialState&,
                                                        const SimulationOptions&, CompliantAudit*);
template Eigen::VectorXcd run_compliant_rest_eigenvalues<Eigen::Dynamic>(const Body&,
                                                                         const GroundMotion&,
                                                                         const SimulationOptions&,
                                                                         int, const InitialState&);
}  // namespace flexrock::detail
