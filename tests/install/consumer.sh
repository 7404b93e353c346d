#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `cmake --install` of a build into a scratch prefix, then tests/consumer, a project outside the
# tree, configured against that prefix with find_package(flexrock), built and run.
# Usage: consumer.sh BUILD_DIR SOURCE_DIR [FLAGS]
#   FLAGS: compile and link flags the library was built with that its users need too (the
#   sanitizer runtime of an instrumented build); empty for a plain build.
set -euo pipefail
build="$1"
src="$2"
flags="${3:-}"
work="$(mktemp -d "${TMPDIR:-/tmp}/flexrock_consumer.XXXXXX")"
trap 'rm -rf "$work"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
for f in include/flexrock/version.hpp include/flexrock/sim/simulate.hpp \
  include/flexrock/io/records.hpp bin/flexrock; do
  [ -e "$work/prefix/$f" ] || fail "cmake --install did not install $f"
done
config="$(find "$work/prefix" -name flexrockConfig.cmake)"
[ -n "$config" ] || fail "no flexrockConfig.cmake installed"
[ -e "$(dirname "$config")/flexrockConfigVersion.cmake" ] || fail "no flexrockConfigVersion.cmake"
# the installed command runs and reports the version
"$work/prefix/bin/flexrock" --version | grep -qE '^flexrock [0-9]+\.[0-9]+\.[0-9]+$' ||
  fail "installed flexrock --version"

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$src/tests/consumer" -B "$work/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="$flags" >"$work/configure.log" ||
  { cat "$work/configure.log" >&2; fail "configuring the consumer against the installed tree"; }
cmake --build "$work/build" >"$work/build.log" 2>&1 ||
  { cat "$work/build.log" >&2; fail "building the consumer"; }
"$work/build/uplift_and_impact"
"$work/build/read_record" "$work/record.txt"
echo "consumer: ok"
