#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# inputs as engineers have them: check/params report each record's PGA, PGV, duration and dt and
# the factor to a target PGA, and check the body's keys with their units and each synthetic
# motion's amplitude; `run` takes several case files and wildcard patterns; a lumped
# body read from an ANSYS listing gets a note that its printed shapes were re-orthogonalised
source "$(dirname "$0")/common.sh"

DATA="$(cd "$SRC/../shared/data" && pwd)"
FE="$SRC/tests/data/fe"
mkdir -p "$WORK/cases"
block='[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
'
cat >"$WORK/cases/kobe.toml" <<TOML
$block
[excitation]
target_pga = 0.25
[excitation.horizontal]
type = "record"
file = "$DATA/kobe_1995_nishi_akashi_090.AT2"
[solver]
t_end = 1.0
TOML
cat >"$WORK/cases/pulse.toml" <<TOML
$block
[excitation.horizontal]
type = "one_sine"
amplitude = 0.1
units = "g"
period = 0.5
duration = 1.0
TOML
cat >"$WORK/cases/frame.toml" <<TOML
[body]
type = "lumped"
tip1_x = -0.6
tip2_x = 0.6
nodes_file = "$FE/frame_nodes.csv"
shapes_file = "$FE/frame_modes_ansys.lis"
frequencies_hz = [4.540, 9.663]
[excitation.horizontal]
type = "one_sine"
amplitude = 0.1
units = "g"
period = 0.5
duration = 1.0
TOML

run "$FLEXROCK" check "$WORK/cases/kobe.toml"
expect_rc 0 "check a scaled record"
expect_in "$WORK/out" "record horizontal: $DATA/kobe_1995_nishi_akashi_090.AT2: PGA "
expect_in "$WORK/out" "PGV "
expect_in "$WORK/out" "duration "
expect_in "$WORK/out" "dt 0.01 s"
expect_in "$WORK/out" "(to PGA 0.25 g): PGA 0.25 g"
# the body as read, key by key with the units of the table of body types
expect_in "$WORK/out" "  body rigid_block: width = 0.4 m, height = 2 m, mass = 100 kg"

run "$FLEXROCK" params "$WORK/cases/kobe.toml"
expect_rc 0 "params of a case with a record"
expect_in "$WORK/out" "record horizontal:"
expect_in "$WORK/out" "(to PGA 0.25 g)"

run "$FLEXROCK" check "$WORK/cases/frame.toml"
expect_rc 0 "check a body from an ANSYS listing"
expect_in "$WORK/err" "flexrock: note: $WORK/cases/frame.toml: lumped model: modes 1 and 2"
expect_in "$WORK/err" "re-orthogonalised"
expect_in "$WORK/out" "  body lumped: tip1_x = -0.6 m, tip2_x = 0.6 m, gravity = 9.80665 m/s^2 (default), "
expect_in "$WORK/out" "frequencies_hz = [2 values] Hz"
expect_in "$WORK/out" "  horizontal one_sine: amplitude 0.1 g (0.9807 m/s^2)"

# several cases, one of them through a pattern the shell did not expand
run "$FLEXROCK" run -q -o "$WORK/out1" "$WORK/cases/pulse.toml" "$WORK/cases/k*.toml"
expect_rc 0 "run two cases"
[ -f "$WORK/out1/pulse.summary.json" ] || fail "no pulse.summary.json"
[ -f "$WORK/out1/kobe.summary.json" ] || fail "no kobe.summary.json"
expect_in "$WORK/out" "case: pulse"
expect_in "$WORK/out" "case: kobe"

run "$FLEXROCK" run -q -o "$WORK/out2" "$WORK/cases/nothing*.toml"
expect_rc 2 "a pattern that matches nothing"
expect_in "$WORK/err" "no case file matches this pattern"
echo "real_inputs: ok"
