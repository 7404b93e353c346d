#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# the same input gives byte-identical outputs: every example run twice, and a spectrum of a
# flexible body with 1 and 3 threads
source "$(dirname "$0")/common.sh"

for name in museum_statue flexible_tank asymmetric_cabinet slender_column; do
  for pass in a b; do
    mkdir -p "$WORK/$pass"
    # the same relative output directory, so that the paths in the summaries agree
    (cd "$WORK/$pass" && "$FLEXROCK" run -q -o out "$SRC/examples/cases/$name.toml" >/dev/null) ||
      fail "run $name ($pass)"
  done
done
count=0
for f in "$WORK"/a/out/*; do
  cmp "$f" "$WORK/b/out/$(basename "$f")" || fail "$(basename "$f") differs between two runs"
  count=$((count + 1))
done
[ "$count" -ge 8 ] || fail "expected a time history and a summary per example, got $count files"

# threads: the cells of a spectrum of a two-mode body do not depend on the thread count
cp "$SRC/examples/cases/flexible_tank.toml" "$WORK/tank.toml"
cat >"$WORK/spec.toml" <<'TOML'
body = "tank.toml"
[spectrum]
pulse = "one_sine"
amplitudes = { start = 0.5, stop = 4.0, count = 4 }
frequencies = [1.0, 3.0, 6.0]
free_periods = 2
TOML
run "$FLEXROCK" spectrum "$WORK/spec.toml" -o "$WORK/one.csv" -j 1 -q
expect_rc 0 "spectrum, 1 thread"
run "$FLEXROCK" spectrum "$WORK/spec.toml" -o "$WORK/three.csv" -j 3 -q
expect_rc 0 "spectrum, 3 threads"
cmp "$WORK/one.csv" "$WORK/three.csv" || fail "the thread count changed the spectrum cells"
cmp "$WORK/one.boundary.csv" "$WORK/three.boundary.csv" || fail "the thread count changed the boundary"
echo "reproducible: ok"
