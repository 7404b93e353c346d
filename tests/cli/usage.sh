#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# --help with examples, --version, usage errors: exit codes and "flexrock: error:" messages
source "$(dirname "$0")/common.sh"

run "$FLEXROCK" --help
expect_rc 0 "--help"
expect_in "$WORK/out" "Examples:"
expect_in "$WORK/out" "flexrock run examples/cases/museum_statue.toml"
expect_in "$WORK/out" "Exit codes"

run "$FLEXROCK" run --help
expect_rc 0 "run --help"
expect_in "$WORK/out" "--output-dir"

run "$FLEXROCK" --version
expect_rc 0 "--version"
grep -qE '^flexrock [0-9]+\.[0-9]+\.[0-9]+$' "$WORK/out" || fail "version line: $(cat "$WORK/out")"
# the one version source: project(flexrock VERSION x.y.z) in CMakeLists.txt
declared="$(sed -nE 's/^project\(flexrock VERSION ([0-9.]+).*/\1/p' "$SRC/CMakeLists.txt")"
[ -n "$declared" ] || fail "no project(flexrock VERSION ...) in $SRC/CMakeLists.txt"
[ "$(cat "$WORK/out")" = "flexrock $declared" ] || fail "--version says $(cat "$WORK/out"), CMake $declared"

run "$FLEXROCK"
expect_rc 2 "no subcommand"
expect_in "$WORK/err" "flexrock: error:"

run "$FLEXROCK" fly
expect_rc 2 "unknown subcommand"
expect_in "$WORK/err" "flexrock: error:"

run "$FLEXROCK" run
expect_rc 2 "run without a case"
expect_in "$WORK/err" "CASE"

run "$FLEXROCK" run --bogus x.toml
expect_rc 2 "unknown option"

run "$FLEXROCK" run "$WORK/none.toml"
expect_rc 2 "missing case file"
expect_in "$WORK/err" "flexrock: error: $WORK/none.toml: no such case file"
echo "usage: ok"
