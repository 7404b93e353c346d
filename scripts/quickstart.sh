#!/usr/bin/env bash
# Builds flexrock (installing missing Debian packages) and runs a real example.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
./build/release/examples/engine_tour
