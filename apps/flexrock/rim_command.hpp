// SPDX-License-Identifier: BSD-3-Clause
// `flexrock run` on a body of revolution with a record pair: the 3D engine (docs/theory.md §27).
#pragma once

#include <string>

#include "flexrock/io/case_file.hpp"

namespace flexrock::cli {

/// Runs the case's body of revolution (c.body3d) under its pair in 3D, writes its outputs and
/// prints its summary; returns the exit code (0 completed, overturned or ended by a mode the
/// engine does not model, which the status names; 1 stopped or outputs not written).
int run_body_of_revolution(const io::Case& c, const std::string& output_dir, bool quiet);

}  // namespace flexrock::cli
