// SPDX-License-Identifier: BSD-3-Clause
// The reader of [[restraint]] tables (restraint_io.cpp), for load_case. Internal header.
#pragma once

#include <vector>

#include "flexrock/sim/restraints.hpp"
#include "table_reader.hpp"

namespace flexrock::io::detail {

/// Every [[restraint]] table of the case's top level, read by kRestraintKeys and checked (the
/// engine's own checks too, placed at the first table); empty without one.
std::vector<Restraint> read_restraints(TableReader& top, const BodyParameters& body,
                                       const SimulationOptions& options);

}  // namespace flexrock::io::detail
