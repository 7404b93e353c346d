#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# the references of docs/case-file.md (synthetic motion types, time-history columns) are the ones
# `flexrock keys --markdown` writes from the library's tables: the docs cannot drift from them
source "$(dirname "$0")/common.sh"

run "$FLEXROCK" keys --markdown
expect_rc 0 "keys --markdown"
expect_in "$WORK/out" "| \`one_sine\` |"
expect_in "$WORK/out" "| \`none\` |"
expect_in "$WORK/out" "| \`lift_m\` | m |"

# the lines from each begin marker to its end marker, in the docs
sed -n '/^<!-- begin: written by `flexrock keys --markdown`/,/^<!-- end: written by `flexrock keys --markdown`/p' \
  "$SRC/docs/case-file.md" >"$WORK/docs"
[ -s "$WORK/docs" ] || fail "no generated key reference in docs/case-file.md (begin/end markers)"
if ! diff -u "$WORK/docs" "$WORK/out" >"$WORK/diff"; then
  cat "$WORK/diff" >&2
  fail "docs/case-file.md differs from 'flexrock keys --markdown': replace its generated block with the command's output"
fi
echo "ok"
