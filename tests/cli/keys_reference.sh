#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# the references of docs/case-file.md (body types, synthetic motion types, time-history and
# event-log columns) and of docs/studies.md (spectrum, boundary, sweep, fragility fit and curve CSV
# columns) are the ones `flexrock keys --markdown` writes from the library's tables: the docs
# cannot drift from them
source "$(dirname "$0")/common.sh"

run "$FLEXROCK" keys --markdown
expect_rc 0 "keys --markdown"
expect_in "$WORK/out" "| \`one_sine\` |"
expect_in "$WORK/out" "| \`none\` |"
expect_in "$WORK/out" "| \`lift_m\` | m |"
expect_in "$WORK/out" "| \`max_friction_demand\` | - |"
expect_in "$WORK/out" "| \`impulse_y_N_s\` | N s |"
expect_in "$WORK/out" "| \`bisection_runs\` | - |"
expect_in "$WORK/out" "| \`log_likelihood\` | - |"

# the lines from each begin marker to its end marker, in the docs
sed -n '/^<!-- begin: written by `flexrock keys --markdown`/,/^<!-- end: written by `flexrock keys --markdown`/p' \
  "$SRC/docs/case-file.md" "$SRC/docs/studies.md" "$SRC/docs/qualify.md" >"$WORK/docs"
[ -s "$WORK/docs" ] || fail "no generated reference in docs/case-file.md, docs/studies.md (begin/end markers)"
if ! diff -u "$WORK/docs" "$WORK/out" >"$WORK/diff"; then
  cat "$WORK/diff" >&2
  fail "docs/case-file.md or docs/studies.md differs from 'flexrock keys --markdown': replace their generated blocks with the command's output"
fi
echo "ok"
