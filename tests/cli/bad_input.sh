#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# every kind of bad input: exit code 2, a message naming file, line and key, and no output files
source "$(dirname "$0")/common.sh"
DATA="$SRC/../shared/data"

BODY='[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
'
PULSE='[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
period = 1.0
duration = 2.0
'

# bad CASE_TEXT EXPECTED_MESSAGE...: `run` and `check` both fail with exit 2 and the messages
bad() {
  local text="$1"
  shift
  printf '%s' "$text" >"$WORK/case.toml"
  rm -rf "$WORK/res"
  run "$FLEXROCK" run -o "$WORK/res" "$WORK/case.toml"
  expect_rc 2 "run: $1"
  expect_in "$WORK/err" "flexrock: error: "
  for m in "$@"; do expect_in "$WORK/err" "$m"; done
  [ ! -e "$WORK/res" ] || [ -z "$(ls -A "$WORK/res")" ] || fail "outputs written for bad input: $1"
  [ ! -s "$WORK/out" ] || fail "stdout not empty for bad input: $(cat "$WORK/out")"
  run "$FLEXROCK" check "$WORK/case.toml"
  expect_rc 2 "check: $1"
  for m in "$@"; do expect_in "$WORK/err" "$m"; done
}

# TOML syntax
bad "${BODY}[excitation.horizontal" "case.toml:6:" "TOML syntax error"
# missing key
bad "[body]
type = \"rigid_block\"
width = 0.4
mass = 1.0
$PULSE" "case.toml:1:" "key 'body.height': missing"
# unknown key with a suggestion
bad "$BODY$PULSE[solver]
restitution_facter = 0.9
" "case.toml:13:" "key 'solver.restitution_facter': unknown key" "did you mean 'solver.restitution_factor'"
# impact laws: an unknown law, a ratio without the restitution law, the law without a ratio
bad "$BODY$PULSE[solver]
impact_law = \"elastic\"
" "case.toml:13:" "key 'solver.impact_law'" "one of: paper, rigid_body, restitution"
bad "$BODY$PULSE[solver]
restitution_ratio = 0.8
" "case.toml:13:" "key 'solver.restitution_ratio'" "applies to impact_law = \"restitution\""
bad "$BODY$PULSE[solver]
impact_law = \"restitution\"
restitution_ratio_edge1 = 0.8
" "key 'solver.restitution_ratio'" "restitution_ratio_edge1 and _edge2"
bad "$BODY$PULSE[solver]
impact_law = \"restitution\"
restitution_ratio = 1.2
" "case.toml:14:" "key 'solver.restitution_ratio'" "a number in [0, 1]"
# the compliant contact: a key without the model, the model without a stiffness, a bad force
# law, hunt_crossley without its restitution, both damping keys
bad "$BODY$PULSE[solver]
contact_stiffness = 1e8
" "case.toml:13:" "key 'solver.contact_stiffness'" "applies to contact_model = \"compliant\""
bad "$BODY$PULSE[solver]
contact_model = \"compliant\"
" "key 'solver.contact_stiffness'" "with contact_model = \"compliant\""
bad "$BODY$PULSE[solver]
contact_model = \"springs\"
" "case.toml:13:" "key 'solver.contact_model'" "one of: impulsive, compliant"
bad "$BODY$PULSE[solver]
contact_model = \"compliant\"
contact_stiffness = 1e8
contact_force_law = \"hunt_crossley\"
" "key 'solver.contact_restitution'" "with contact_force_law = \"hunt_crossley\""
bad "$BODY$PULSE[solver]
contact_model = \"compliant\"
contact_stiffness = 1e8
contact_damping_ratio = 2.0
contact_restitution = 0.5
" "case.toml:15:" "key 'solver.contact_damping_ratio'" "not both"
bad "$BODY$PULSE[solver]
contact_model = \"compliant\"
contact_stiffness = -1e8
" "case.toml:14:" "key 'solver.contact_stiffness'"
# negative and zero sizes
bad "[body]
type = \"rigid_block\"
width = -0.4
height = 2.0
mass = 1.0
$PULSE" "case.toml:3:" "key 'body.width'" "expected a number > 0 [m], got -0.4"
bad "[body]
type = \"rigid_block\"
width = 0.4
height = 0
mass = 1.0
$PULSE" "case.toml:4:" "key 'body.height'" "got 0"
# NaN and inf in the case file
bad "$BODY$PULSE[solver]
max_step = nan
" "case.toml:13:" "key 'solver.max_step'" "got nan"
bad "${BODY}[excitation.horizontal]
type = \"one_sine\"
amplitude = inf
units = \"g\"
period = 1.0
duration = 2.0
" "case.toml:8:" "excitation.horizontal.amplitude" "got inf"
# NaN in a record
printf '0.1\n0.2\nnan\n' >"$WORK/nan.dat"
bad "${BODY}[excitation.horizontal]
type = \"record\"
file = \"nan.dat\"
format = \"single_column\"
dt = 0.01
units = \"g\"
" "nan.dat:3:" "excitation.horizontal.file" "case.toml:8"
# non-increasing times
printf '0.0 0.1\n0.2 0.2\n0.1 0.3\n' >"$WORK/times.txt"
bad "${BODY}[excitation.horizontal]
type = \"record\"
file = \"times.txt\"
format = \"time_series\"
units = \"m/s^2\"
" "times.txt:3:"
# malformed AT2 (line 4 without numbers)
printf 'PEER NGA STRONG MOTION DATABASE RECORD\nX\nACCELERATION IN UNITS OF G\nNPTS, DT\n0.1\n' \
  >"$WORK/bad.AT2"
bad "${BODY}[excitation.horizontal]
type = \"record\"
file = \"bad.AT2\"
" "bad.AT2:4:" "NPTS"
# truncated AT2: the real record cut short
head -n 100 "$DATA/kobe_1995_nishi_akashi_090.AT2" >"$WORK/cut.AT2"
bad "${BODY}[excitation.horizontal]
type = \"record\"
file = \"cut.AT2\"
" "cut.AT2" "4096"
# modal mass matrix not positive definite
bad "[body]
type = \"paper\"
mass = 10.0
height = 1.0
b1 = 0.3
b2 = 0.3
zeta2 = 0.4
mu = [[1.0, 2.0], [2.0, 1.0]]
kappa = [[20.0, 0.0], [0.0, 30.0]]
$PULSE" "case.toml:1:" "positive definite"
# mode shapes that do not vanish at a tipping point
bad "[body]
type = \"lumped\"
tip1_x = -0.5
tip2_x = 0.5
nodes = [[-0.5, 0.0, 100.0], [0.5, 0.0, 100.0], [0.0, 2.0, 500.0]]
frequencies_hz = [2.0]
phi_x = [[0.3], [0.0], [1.0]]
phi_y = [[0.0], [0.0], [0.0]]
$PULSE" "case.toml:1:" "tipping point"

# params on a bad body
printf '[body]\ntype = "rigid_block"\nwidth = 0.4\n' >"$WORK/body.toml"
run "$FLEXROCK" params "$WORK/body.toml"
expect_rc 2 "params on a bad body"
expect_in "$WORK/err" "body.toml:1: key 'body.height': missing"
echo "bad input: ok"
