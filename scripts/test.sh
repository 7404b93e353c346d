#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds flexrock with every test and runs them all; installs missing Debian packages first.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --mpi --docs  # MPI: the 2-process study test runs too; docs: the API reference builds
cmake --preset release
cmake --build --preset release -j"$(nproc)"
ctest --preset release -j"$(nproc)"
