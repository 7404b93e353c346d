#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates docs/validation.md and docs/validation/*.png: builds flexrock_validate (Release, in
# build/validation unless FLEXROCK_VALIDATION_BUILD names another build directory), then runs
# make_report.py with Debian's python3 (numpy, scipy, matplotlib). Extra arguments go to
# make_report.py (e.g. --quick for a coarse smoke run). About 3 minutes on 2 cores.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${FLEXROCK_VALIDATION_BUILD:-$root/build/validation}"
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLEXROCK_BUILD_TESTS=OFF \
    -DFLEXROCK_BUILD_EXAMPLES=OFF -DFLEXROCK_BUILD_VALIDATION=ON "${launcher[@]}"
fi
cmake --build "$build" --target flexrock_validate -j "${FLEXROCK_JOBS:-2}"
exec /usr/bin/python3 "$root/tools/validation/make_report.py" \
  --driver "$build/tools/validation/flexrock_validate" --work "$build/validation-work" "$@"
