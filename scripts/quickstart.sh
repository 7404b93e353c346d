#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds flexrock (installing missing Debian packages) and runs a real case end to end: a statue
# under El Centro 1940, and draws its response. Outputs go to build/example/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
# only what the first result needs: the command line and the engine under it (`flexrock plot`
# draws a time history with numpy and matplotlib alone; scripts/test.sh builds the rest: the
# Python module, the tests and the benches)
cmake --build --preset release -j"$(nproc)" --target flexrock
build/release/apps/flexrock run -o build/example examples/cases/museum_statue.toml
build/release/apps/flexrock plot build/example/museum_statue.csv -o build/example/museum_statue.png
