# SPDX-License-Identifier: BSD-3-Clause
# flexrock spectrum: columns, row counts, the same bytes for 1 and 3 threads, the record mode,
# errors with file:line and exit 2, no outputs after an error
source "$(dirname "$0")/common.sh"

cat >"$WORK/block.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
TOML
cat >"$WORK/spec.toml" <<'TOML'
body = "block.toml"
[spectrum]
pulse = "one_sine"
amplitudes = { start = 0.5, stop = 6.0, count = 8 }
frequencies = [1.5, 3.0, 6.0, 10.0]
free_periods = 3
TOML

run "$FLEXROCK" spectrum "$WORK/spec.toml" -o "$WORK/one.csv" -j 1
expect_rc 0 "spectrum with one thread"
expect_in "$WORK/out" "cells: 32"
[ -f "$WORK/one.boundary.csv" ] || fail "no boundary file next to the cells"
head -1 "$WORK/one.csv" | grep -q "^row,column,a_p_m_per_s2,a_p_over_g_tan_alpha,omega_p_rad_per_s,omega_p_over_p,scale,outcome,overturned,max_theta_over_alpha,impacts" ||
  fail "spectrum columns: $(head -1 "$WORK/one.csv")"
[ "$(wc -l <"$WORK/one.csv")" -eq 33 ] || fail "expected 32 cells + header"
[ "$(wc -l <"$WORK/one.boundary.csv")" -eq 5 ] || fail "expected 4 boundary rows + header"
# a_p/(g tan alpha) = 0.5 never uplifts a rigid block; the top row overturns somewhere
grep -q "^0,0,.*,no_uplift,0," "$WORK/one.csv" || fail "row 0 should not uplift"
grep -q ",overturned_" "$WORK/one.csv" || fail "no overturning in the grid"
grep -q ",found," "$WORK/one.boundary.csv" || fail "no bisected boundary"

run "$FLEXROCK" spectrum "$WORK/spec.toml" -o "$WORK/three.csv" -j 3 -q
expect_rc 0 "spectrum with three threads"
cmp "$WORK/one.csv" "$WORK/three.csv" || fail "the thread count changed the cells"
cmp "$WORK/one.boundary.csv" "$WORK/three.boundary.csv" || fail "the thread count changed the boundary"

# one record x scales, relative paths from the spec
printf '0\n0.1\n0.3\n-0.4\n0.2\n0\n-0.1\n0\n' >"$WORK/rec.dat"
cat >"$WORK/rec.toml" <<'TOML'
body = "block.toml"
[spectrum]
record = { file = "rec.dat", format = "single_column", dt = 0.1, units = "g" }
scales = [0.25, 0.5, 1.0, 2.0, 4.0]
TOML
run "$FLEXROCK" spectrum "$WORK/rec.toml" -o "$WORK/rec.csv" --no-bisect -q
expect_rc 0 "record spectrum"
[ "$(wc -l <"$WORK/rec.csv")" -eq 6 ] || fail "expected 5 scales + header"
[ ! -e "$WORK/rec.boundary.csv" ] || fail "--no-bisect wrote a boundary file"

# bad input: file:line: key, exit 2, nothing written
cat >"$WORK/bad.toml" <<'TOML'
body = "block.toml"
[spectrum]
pulse = "one_sine"
amplitudes = [1.0, 3.0, 2.0]
frequencies = [1.0]
TOML
run "$FLEXROCK" spectrum "$WORK/bad.toml" -o "$WORK/bad.csv"
expect_rc 2 "decreasing amplitudes"
expect_in "$WORK/err" "bad.toml:4: key 'spectrum.amplitudes': expected strictly increasing"
[ ! -e "$WORK/bad.csv" ] || fail "a failed spectrum left an output"
run "$FLEXROCK" spectrum "$WORK/spec.toml" -o "$WORK/x.csv" -j 0
expect_rc 2 "--threads 0"
expect_in "$WORK/err" "--threads: expected an integer >= 1"
run "$FLEXROCK" spectrum "$WORK/nope.toml"
expect_rc 2 "missing spec"
expect_in "$WORK/err" "nope.toml: no such spectrum file"
echo "ok"
