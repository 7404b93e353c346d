// SPDX-License-Identifier: BSD-3-Clause
// The [[uncertain]] and [sampling] tables of a sweep manifest (docs/studies.md, "Uncertain
// parameters"). Internal to flexrock::io.
#pragma once

#include "flexrock/study/sweep.hpp"
#include "table_reader.hpp"

namespace flexrock::io::detail {

/// Reads the manifest's [[uncertain]] tables and its [sampling] table into spec.uncertainty,
/// after the bodies and the solver: every distribution is checked, and so is that each parameter
/// applies to every body and to the solver's impact law. Errors name file, line and key.
void read_uncertainty(TableReader& top, study::SweepSpec& spec);

/// The reference of the uncertain parameters, as the Markdown table of docs/studies.md, written
/// from study::uncertain_kinds() with its begin and end marker lines (`flexrock keys --markdown`).
std::string uncertain_reference();

}  // namespace flexrock::io::detail
