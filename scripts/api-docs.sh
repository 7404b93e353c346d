#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the API reference: C++ (Doxygen, from the public headers' comments) and Python (Sphinx
# autodoc over the built package, from its numpydoc docstrings), installing doxygen and
# python3-sphinx when missing. Needs the release build (the Python module), which it brings up to
# date. Warnings that name an undocumented or broken item fail the build.
# Usage: scripts/api-docs.sh [OUT]     (default build/api: OUT/cpp/html, OUT/python/index.html)
#   FLEXROCK_API_BUILD=DIR: use that build's Python module as it is (no install, no build: the
#   test api_docs does so)
set -euo pipefail
cd "$(dirname "$0")/.."
out="$(realpath -m "${1:-build/api}")"
build="${FLEXROCK_API_BUILD:-}"
if [ -z "$build" ]; then
  scripts/install-deps.sh --docs
  [ -f build/release/CMakeCache.txt ] || cmake --preset release >/dev/null
  cmake --build --preset release -j"$(nproc)" --target _flexrock >/dev/null
  build=build/release
fi
build="$(realpath "$build")"
mkdir -p "$out"

FLEXROCK_API_OUT="$out" doxygen docs/api/Doxyfile
if [ -s "$out/doxygen-warnings.txt" ]; then
  echo "api-docs.sh: Doxygen warnings ($out/doxygen-warnings.txt):" >&2
  head -n 20 "$out/doxygen-warnings.txt" >&2
  exit 1
fi

# -W: a warning (an unresolved reference, a malformed docstring) is an error; -E: no stale cache
PYTHONPATH="$build/python" /usr/bin/python3 -m sphinx -q -W -E -b html \
  -d "$out/python-doctrees" docs/api/python "$out/python"
echo "api-docs.sh: C++ $out/cpp/html/index.html, Python $out/python/index.html"
