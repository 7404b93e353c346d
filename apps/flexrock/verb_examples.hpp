// SPDX-License-Identifier: BSD-3-Clause
// Examples of every verb, shown at the end of `flexrock VERB --help`: one table, which
// tests/cli/verb_help.sh checks covers every verb (each example names its verb first).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

namespace flexrock::cli {

struct VerbExamples {
  std::string_view verb;
  std::string_view lines;  // "command  # what it does" lines, each starting with the verb
};

inline constexpr VerbExamples kVerbExamples[] = {
    {"run",
     "flexrock run examples/cases/museum_statue.toml            # CSV + summary JSON beside it\n"
     "flexrock run cases/*.toml -o out/ -q                      # many cases, results only"},
    {"check", "flexrock check examples/cases/*.toml                      # validate, run nothing"},
    {"params",
     "flexrock params examples/cases/museum_statue.toml         # alpha, p, R of the body"},
    {"keys", "flexrock keys --markdown > keys.md                        # the references of docs/"},
    {"plot",
     "flexrock plot museum_statue.csv -o statue.png             # a time history\n"
     "flexrock plot sweep.csv --body statue -o fragility.pdf    # a sweep's fragility, PGA [g]\n"
     "flexrock plot one_sine_block.spectrum.csv                 # a spectrum and its boundary\n"
     "flexrock plot ida.csv --kind ida --body statue            # IDA curves, one per record\n"
     "flexrock plot museum_statue.csv --tlim 5 15               # a window of a time history"},
    {"azimuths",
     "flexrock azimuths pair.toml -o out/                       # a record pair at every 5 deg\n"
     "flexrock azimuths pair.toml -j 2 -q                       # 2 threads, the envelope only"},
    {"spectrum",
     "flexrock spectrum examples/studies/one_sine_block.toml    # cells + boundary CSVs\n"
     "flexrock spectrum spec.toml --no-bisect -j 4              # the grid only, 4 threads\n"
     "flexrock spectrum spec.toml -o s.csv --shard 2/8          # shard 2 of 8 (then merge)"},
    {"sweep",
     "flexrock sweep examples/studies/sweep.toml -o ida.csv     # resumable: rerun to go on\n"
     "flexrock sweep m.toml -o ida.csv --shard 3/16             # one task of an array job\n"
     "mpirun -n 4 flexrock sweep m.toml -o ida.csv              # 4 MPI processes, same bytes"},
    {"merge",
     "flexrock merge ida.csv.shard*of16                         # the shards -> ida.csv\n"
     "flexrock merge s.csv.shard*of8 -o spectrum.csv            # a spectrum and its boundary"},
    {"fragility",
     "flexrock fragility ida.csv -o fit.csv --curve curve.csv   # per body, PGA in g\n"
     "flexrock fragility ida.csv --im sa:1 --state uplift --state theta:0.5\n"
     "flexrock fragility ida.csv --analysis msa                 # stripes at the levels\n"
     "flexrock fragility pairs.csv --worst-azimuth              # record pairs: worst azimuth"},
    {"qualify",
     "flexrock qualify examples/qualify/cabinet.toml -o report/ # bounding cases, IDA, report"},
};

/// Sets every subcommand's footer to its examples; a verb without any is a programming error.
inline void add_verb_examples(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands({})) {
    for (const VerbExamples& e : kVerbExamples) {
      if (e.verb == sub->get_name()) sub->footer("\nExamples:\n" + std::string(e.lines));
    }
  }
}

}  // namespace flexrock::cli
