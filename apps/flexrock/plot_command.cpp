// SPDX-License-Identifier: BSD-3-Clause
#include "plot_command.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

// set by CMake: where the build lays out the Python package, and the interpreter with numpy and
// matplotlib
#ifndef FLEXROCK_PYTHON_DIR
#define FLEXROCK_PYTHON_DIR ""
#endif
#ifndef FLEXROCK_PYTHON_EXECUTABLE
#define FLEXROCK_PYTHON_EXECUTABLE "/usr/bin/python3"
#endif

namespace flexrock::cli {

CLI::App* add_plot_command(CLI::App& app, PlotOptions& options) {
  CLI::App* plot = app.add_subcommand(
      "plot",
      "Plot a run's time-history CSV (response figure or moment-rotation loop), a spectrum CSV, "
      "or a fragility (a sweep CSV, or the fit or curve CSV of flexrock fragility) as PNG, SVG "
      "or PDF (needs Python 3 with matplotlib)");
  plot->add_option("CSV", options.file,
                   "time-history CSV of `flexrock run` (its summary JSON and event log are read "
                   "from next to it), spectrum CSV, sweep CSV or fragility CSV")
      ->required();
  plot->add_option("-o,--output", options.output,
                   "figure file, .png, .svg or .pdf (default: the CSV's name with .png)");
  plot->add_option("--kind", options.kind,
                   "auto (by the CSV header), response, loop, rim (a body of revolution run in "
                   "3D: the tilt's orbit and the contact's path), spectrum, fragility, ida (a "
                   "sweep's response against its intensity measure, a curve per record)")
      ->check(CLI::IsMember({"auto", "response", "loop", "rim", "spectrum", "fragility", "ida"}));
  plot->add_option("--tlim,--xlim", options.tlim, "T0 T1: a time history's window [s]")
      ->expected(2);
  plot->add_option("--measure", options.measure,
                   "the response of an ida figure: max_theta_over_alpha (default), "
                   "max_theta_rad, max_uplift_m, max_impulse_N_s, max_friction_demand, "
                   "energy_lost_J");
  plot->add_option("--im", options.im,
                   "intensity measure of a sweep's fragility: pga (m/s^2), pga_g (default), pgv "
                   "(m/s), scale, requested_level, or one the sweep wrote (pgd, arias, cav, "
                   "d5_95, pgv_over_pga, sa:T[:zeta]), as flexrock fragility --im; a fit or "
                   "curve CSV records its own, which labels the axis");
  plot->add_option("--body", options.body, "a fragility's body only (default: each)");
  plot->add_option("--state", options.state,
                   "a fragility's damage state only (overturned, theta:0.5, ...): of a fit or "
                   "curve CSV of flexrock fragility --state, or the state a sweep is fitted for");
  plot->add_option("--dpi", options.dpi, "PNG resolution")->check(CLI::Range(10, 1200));
  return plot;
}

std::string drawing_python(const char* module_file, const char* need, const char* then) {
  const char* env_python = std::getenv("FLEXROCK_PYTHON");
  const std::string python = env_python && *env_python ? env_python : FLEXROCK_PYTHON_EXECUTABLE;
  if (::access(python.c_str(), X_OK) != 0) {
    fmt::print(stderr, "flexrock: error: {}, but {} cannot be run ({}); {}\n", need, python,
               std::strerror(errno), then);
    return {};
  }
  // FLEXROCK_PYTHON_DIR in the environment: another copy of the package (a relocated build)
  const char* env_dir = std::getenv("FLEXROCK_PYTHON_DIR");
  const std::string dir = env_dir && *env_dir ? env_dir : FLEXROCK_PYTHON_DIR;
  std::error_code ec;
  if (!dir.empty() && std::filesystem::exists(dir + "/" + module_file, ec)) {
    const char* old = std::getenv("PYTHONPATH");
    const std::string path = old && *old ? dir + ":" + old : dir;
    ::setenv("PYTHONPATH", path.c_str(), 1);
  }
  return python;
}

int run_plot(const PlotOptions& options) {
  const std::string python =
      drawing_python("flexrock/plot.py", "flexrock plot needs Python 3 with numpy and matplotlib",
                     "install them with scripts/install-deps.sh --python");
  if (python.empty()) return 1;
  // `python3 -m flexrock.plot` would import the whole package, which needs the compiled module;
  // a time history's figures need only numpy and matplotlib, so where the package cannot be
  // imported (the quickstart builds the command alone) its drawing modules are loaded under an
  // empty package of the same directory
  const std::string bootstrap =
      "import os, sys, types\n"
      "try:\n"
      "    import flexrock\n"
      "except ImportError:\n"
      "    here = next((os.path.join(d, 'flexrock') for d in sys.path\n"
      "                 if os.path.isfile(os.path.join(d or '.', 'flexrock', 'plot.py'))), None)\n"
      "    if here is None:\n"
      "        raise\n"
      "    pkg = types.ModuleType('flexrock')\n"
      "    pkg.__path__ = [here]\n"
      "    sys.modules['flexrock'] = pkg\n"
      "from flexrock.plot import main\n"
      "sys.exit(main(sys.argv[1:]))\n";
  std::vector<std::string> args = {python,   "-c",         bootstrap, options.file,
                                   "--kind", options.kind, "--dpi",   std::to_string(options.dpi)};
  for (const auto& [flag, value] :
       {std::pair{"--im", &options.im}, std::pair{"--body", &options.body},
        std::pair{"--state", &options.state}}) {
    if (value->empty()) continue;
    args.push_back(flag);
    args.push_back(*value);
  }
  if (!options.measure.empty()) {
    args.push_back("--measure");
    args.push_back(options.measure);
  }
  if (options.tlim.size() == 2) {
    // the shortest text that reads back as the same double
    args.push_back("--tlim");
    args.push_back(fmt::format("{}", options.tlim[0]));
    args.push_back(fmt::format("{}", options.tlim[1]));
  }
  if (!options.output.empty()) {
    args.push_back("--output");
    args.push_back(options.output);
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  ::execv(python.c_str(), argv.data());
  fmt::print(stderr, "flexrock: error: cannot run {}: {}\n", python, std::strerror(errno));
  return 1;
}

}  // namespace flexrock::cli
