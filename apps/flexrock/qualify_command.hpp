// SPDX-License-Identifier: BSD-3-Clause
// `flexrock qualify`: the qualification of an unanchored body (flexrock::io::QualifySession),
// its report's numbers (JSON) and demands (pelicun CSV), then the HTML and PDF drawn by the
// Python package (flexrock.report).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace flexrock::cli {

struct QualifyOptions {
  std::string file;        // the qualification file (TOML)
  std::string output_dir;  // where the report goes (default: the working directory)
  int threads = 0;         // 0: every core
  bool quiet = false;
  bool no_render = false;  // JSON and CSV only: no HTML or PDF (no Python needed)
};

CLI::App* add_qualify_command(CLI::App& app, QualifyOptions& options);

/// Runs the qualification; returns the exit code (0 done, whether it passes or not; 1 interrupted
/// or outputs not written; InputError for bad input propagates).
int run_qualify(const QualifyOptions& options);

}  // namespace flexrock::cli
