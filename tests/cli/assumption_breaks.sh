#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# where the sticking contact breaks without a friction limit the run says so, with the magnitude,
# on the console, in the summary's warnings and in the event log; check and params say that a
# finite friction coefficient removes it, and it does
source "$(dirname "$0")/common.sh"

# a rigid block of slenderness alpha = 0.25 rad (b/h = tan 0.25; 2 m tall, 1 t) under a one-sine
# pulse of A = 20 g tan(alpha) at omega_p = 2 p (p = sqrt(3 g / 4 R) = 2.66996 rad/s): a landing
# after its flight needs the floor to pull
cat >"$WORK/sine.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.510684
height = 2.0
mass = 1000.0
[excitation.horizontal]
type = "one_sine"
amplitude = 5.10684
units = "g"
period = 1.176638
duration = 8.0
[output]
events = "sine.events.csv"
TOML
run "$FLEXROCK" run -o "$WORK/res" "$WORK/sine.toml"
expect_rc 0 "one-sine run"
expect_in "$WORK/out" "landing(s) needed the floor to pull (events: tensile_landing); largest pulling impulse -"
expect_in "$WORK/out" "N s pulling (tensile_landing)"
s="$WORK/res/sine.summary.json"
[ "$(json_get "$s" warnings.tensile_landing)" = 'true' ] || fail "warnings.tensile_landing"
n=$(json_get "$s" warnings.tensile_landings)
[ "$n" -ge 1 ] || fail "warnings.tensile_landings = $n"
imp=$(json_get "$s" warnings.max_tensile_impulse_N_s)
# the event log's tensile_landing rows carry the impulse: the summary's is their largest pull
python3 - "$WORK/res/sine.events.csv" "$imp" "$n" <<'PY' || fail "event log against the summary"
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["event"] == "tensile_landing"]
assert len(rows) == int(sys.argv[3]), (len(rows), sys.argv[3])
worst = -min(float(r["impulse_y_N_s"]) for r in rows)
assert worst > 0 and abs(worst - float(sys.argv[2])) <= 1e-9 * worst, (worst, sys.argv[2])
PY
# the console's pulling impulse is the summary's
python3 - "$WORK/out" "$imp" <<'PY' || fail "console against the summary"
import re, sys
m = re.search(r"largest pulling impulse (-?[0-9.e+]+) N s", open(sys.argv[1]).read())
assert m and abs(-float(m.group(1)) - float(sys.argv[2])) <= 1e-3 * float(sys.argv[2]), m
PY

# check and params say what removes it; a finite coefficient does
run "$FLEXROCK" check "$WORK/sine.toml"
expect_rc 0 "check"
expect_in "$WORK/out" "A finite friction_coefficient removes them"
run "$FLEXROCK" params "$WORK/sine.toml"
expect_rc 0 "params"
expect_in "$WORK/out" "A finite friction_coefficient removes them"
printf '[solver]\nfriction_coefficient = 0.5\n' >>"$WORK/sine.toml"
run "$FLEXROCK" check "$WORK/sine.toml"
if grep -qF "removes them" "$WORK/out"; then fail "check with friction still warns"; fi
run "$FLEXROCK" run -o "$WORK/res2" "$WORK/sine.toml"
expect_rc 0 "one-sine run with friction"
[ "$(json_get "$WORK/res2/sine.summary.json" warnings.tensile_landings)" = '0' ] ||
  fail "tensile landings with friction"
if grep -qF "tensile_landing" "$WORK/out"; then fail "console warns with friction"; fi
echo "ok"
