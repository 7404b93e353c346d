#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Instructions a line to read a two-column text record: callgrind's count of `flexrock check` on
# a case whose record has 200,000 lines, minus the same on 100,000 lines, over 100,000 (the
# difference leaves out the start-up and the case file). `check` also computes the record's
# PGA, PGV and duration, a few tens of instructions a sample. Instructions, not time: the count
# does not depend on the machine's load.
# Usage: bench/reader_cost.sh [FLEXROCK]     (default build/release/apps/flexrock; needs valgrind)
set -euo pipefail
flexrock="$(realpath "${1:-build/release/apps/flexrock}")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
count() {
  valgrind --tool=callgrind --callgrind-out-file="$work/cg" "$flexrock" check "$1" 2>&1 >/dev/null |
    sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
for n in 100000 200000; do
  # a deterministic record: time with 4 decimals, acceleration in E notation, as agencies write
  awk -v n="$n" 'BEGIN { s = 12345; for (i = 0; i < n; i++) { s = (s * 1103515245 + 12345) % 2147483648;
    printf "%.4f %.7e\n", i * 0.005, (s / 2147483648 - 0.5) * 0.2 } }' >"$work/r$n.txt"
  printf '[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 1.8\nmass = 800.0\n[excitation.horizontal]\ntype = "record"\nfile = "r%s.txt"\nformat = "time_series"\nunits = "g"\n' \
    "$n" >"$work/c$n.toml"
done
a=$(count "$work/c100000.toml")
b=$(count "$work/c200000.toml")
echo "two-column record: $(((b - a) / 100000)) instructions a line (callgrind, flexrock check)"
