// SPDX-License-Identifier: BSD-3-Clause
// The study subcommands of `flexrock`: spectrum, sweep, fragility (docs/studies.md).
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

namespace flexrock::cli {

/// Registers `spectrum`, `sweep` and `fragility` on the application; after parsing, selected()
/// says whether one of them was chosen and run() runs it and returns the exit code (0 ok, 1 a
/// run that could not complete, an interrupted study or outputs that could not be written,
/// 2 bad input). InputError and other exceptions propagate to the caller's handlers.
class StudyCommands {
 public:
  explicit StudyCommands(CLI::App& app);
  ~StudyCommands();
  bool selected() const;
  int run();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The column reference of the fragility curve CSV (`flexrock fragility --curve`), as the
/// Markdown table of docs/studies.md, written from its table of columns with its begin and end
/// marker lines (`flexrock keys --markdown`).
std::string fragility_curve_column_reference();

}  // namespace flexrock::cli
