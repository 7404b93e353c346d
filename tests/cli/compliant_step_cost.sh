#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# the compliant contact's step cost is known before the run: a slab of b/h = 0.01 carrying a 57 Hz
# oscillator on a critically damped contact of omega_v = 1000 p needs at least 2.7e5 Dopri5 steps
# per simulated second (its bounce coupled to the oscillator: 8.9e5 rad/s); params shows it, and
# check and run warn that 2 s will pass max_steps = 300000, which the run then does
source "$(dirname "$0")/common.sh"

cat >"$WORK/slab.toml" <<'TOML'
[body]
type = "oscillator_on_slab"
top_mass = 1000.0
frequency_hz = 57.0
base_mass = 500.0
height = 2.0
base_width = 0.04
damping_ratio = 0.02
[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
frequency_hz = 1.0
duration = 2.0
[solver]
contact_model = "compliant"
contact_stiffness = 3.677e9
contact_damping_ratio = 1.0
max_steps = 300000
TOML
run "$FLEXROCK" params "$WORK/slab.toml"
expect_rc 0 "params of a stiff compliant case"
expect_in "$WORK/out" "compliant contact's step cost"
expect_in "$WORK/out" "at least 2.694e+05 steps per simulated second"
expect_in "$WORK/err" "stiff compliant contact"
run "$FLEXROCK" check "$WORK/slab.toml"
expect_rc 0 "check of a stiff compliant case"
expect_in "$WORK/err" "warning: $WORK/slab.toml: stiff compliant contact"
expect_in "$WORK/err" "the 2 s would take at least 5.39e+05 steps, above max_steps = 300000"
expect_in "$WORK/err" "raise [solver] max_steps, soften contact_stiffness"
# warned before the run, which then stops at the step limit
run "$FLEXROCK" run -o "$WORK/res" "$WORK/slab.toml"
expect_rc 1 "a run past max_steps"
expect_in "$WORK/err" "above max_steps = 300000"
expect_in "$WORK/err" "more than max_steps = 300000 steps"
# the step limit raised: no warning (2.7e5 steps a second is not slow)
sed 's/^max_steps = 300000$/max_steps = 2000000/' "$WORK/slab.toml" >"$WORK/raised.toml"
run "$FLEXROCK" check "$WORK/raised.toml"
expect_rc 0 "check with a raised step limit"
if grep -q "stiff compliant contact" "$WORK/err"; then fail "warned though raised: $(cat "$WORK/err")"; fi
# the impulsive contact keeps its own estimate and says nothing of the compliant one
grep -v '^contact_' "$WORK/raised.toml" >"$WORK/impulsive.toml"
run "$FLEXROCK" params "$WORK/impulsive.toml"
expect_rc 0 "params of the impulsive case"
if grep -q "compliant contact's step cost" "$WORK/out"; then fail "compliant cost on impulsive"; fi

echo "compliant step cost: ok"
