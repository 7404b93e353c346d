// SPDX-License-Identifier: BSD-3-Clause
// `flexrock plot`: figures of a run, a spectrum or a fragility, drawn by the Python package
// (matplotlib).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace flexrock::cli {

struct PlotOptions {
  std::string file;           // a run's time-history, spectrum, sweep or fragility CSV
  std::string output;         // .png, .svg or .pdf; empty: next to `file`
  std::string kind = "auto";  // auto, response, loop, spectrum, fragility, ida
  std::string im;             // intensity measure of a sweep's fragility (empty: pga_g, or
                              // the one a fit or curve CSV records)
  std::string body;           // a fragility's body only (empty: each)
  std::string state;          // a fragility's damage state only (empty: each, or overturning)
  int dpi = 110;              // [1/inch] PNG resolution
  std::vector<double> tlim;   // [s] a time history's window: T0, T1 (empty: the whole run)
  std::string measure;        // the response of an IDA figure (empty: max_theta_over_alpha)
};

/// Adds the `plot` subcommand to `app`, filling `options`.
CLI::App* add_plot_command(CLI::App& app, PlotOptions& options);

/// The interpreter that draws (FLEXROCK_PYTHON overrides the one found at build time), with the
/// build's package (FLEXROCK_PYTHON_DIR overrides its directory) first on PYTHONPATH when it holds
/// `module_file` (e.g. "flexrock/plot.py";
/// without it an installed `flexrock` package is used). Empty, after an error on stderr saying
/// "`need`, but ... cannot be run (why); `then`", when it cannot be run.
std::string drawing_python(const char* module_file, const char* need, const char* then);

/// Replaces this process with `python3 -m flexrock.plot ...`; returns only on failure (exit code).
int run_plot(const PlotOptions& options);

}  // namespace flexrock::cli
