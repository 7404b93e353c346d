#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# a run that cannot complete exits 1; piped output and --quiet carry no progress bar; params
source "$(dirname "$0")/common.sh"

cat >"$WORK/stop.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
[excitation.horizontal]
type = "harmonic"
amplitude = 0.05
units = "g"
frequency_hz = 2.0
duration = 5.0
[solver]
max_steps = 20
TOML
run "$FLEXROCK" run -o "$WORK/res" "$WORK/stop.toml"
expect_rc 1 "stopped run"
expect_in "$WORK/out" "outcome: STOPPED"
expect_in "$WORK/err" "flexrock: error: the run could not complete"
[ "$(json_get "$WORK/res/stop.summary.json" outcome.status)" = '"stopped"' ] || fail "status"

# piped: nothing but results (no carriage returns, nothing on stderr); --quiet: no file list
sed 's/^max_steps = 20$//' "$WORK/stop.toml" >"$WORK/ok.toml"
run "$FLEXROCK" run -o "$WORK/res" "$WORK/ok.toml"
expect_rc 0 "piped run"
[ ! -s "$WORK/err" ] || fail "stderr not empty: $(cat "$WORK/err")"
if grep -q $'\r' "$WORK/out"; then fail "progress characters in piped output"; fi
expect_in "$WORK/out" "wrote $WORK/res/ok.csv"
run "$FLEXROCK" run -q -o "$WORK/res" "$WORK/ok.toml"
expect_rc 0 "quiet run"
if grep -q "^wrote" "$WORK/out"; then fail "--quiet lists files"; fi
expect_in "$WORK/out" "peak tilt:"

# outputs can be switched off; an unwritable output directory is a run failure (exit 1)
printf '\n[output]\ntime_history = ""\n' >>"$WORK/ok.toml"
run "$FLEXROCK" run -o "$WORK/res2" "$WORK/ok.toml"
expect_rc 0 "no time history"
[ ! -e "$WORK/res2/ok.csv" ] || fail "time history written though switched off"
[ -f "$WORK/res2/ok.summary.json" ] || fail "no summary"
touch "$WORK/file"
run "$FLEXROCK" run -o "$WORK/file/sub" "$WORK/ok.toml"
expect_rc 1 "unwritable output directory"
expect_in "$WORK/err" "could not write the outputs"

# a run whose energy balance does not close says so on the console and in the summary: the
# flexible tank at rtol = atol = 1e-3 (its default run closes the balance, checked as well)
cp "$SRC/examples/cases/flexible_tank.toml" "$WORK/tank.toml"
run "$FLEXROCK" run -o "$WORK/res3" "$WORK/tank.toml"
expect_rc 0 "tank at the default tolerances"
if grep -q "energy balance does not close" "$WORK/out"; then fail "default run flagged"; fi
[ "$(json_get "$WORK/res3/tank.summary.json" warnings.energy_unbalanced)" = 'false' ] ||
  fail "default run: warnings.energy_unbalanced"
printf '\n[solver]\nrtol = 1e-3\natol = 1e-3\n[output]\nevents = "tank.events.csv"\n' >>"$WORK/tank.toml"
run "$FLEXROCK" run -o "$WORK/res3" "$WORK/tank.toml"
expect_rc 0 "tank at rtol 1e-3"
expect_in "$WORK/out" "warning: the energy balance does not close"
[ "$(json_get "$WORK/res3/tank.summary.json" warnings.energy_unbalanced)" = 'true' ] ||
  fail "loose run: warnings.energy_unbalanced"
expect_in "$WORK/res3/tank.events.csv" "energy_unbalanced"

# a run whose results overflow (a finite body of 1e307 kg under a 2 g pulse: the base shear
# M a is inf) fails with the reason, exit 1, and writes nothing, not even an old set's summary
cat >"$WORK/overflow.toml" <<'TOML'
[body]
type = "rigid_block"
width = 4.0
height = 1.8
mass = 1e307
[excitation.horizontal]
type = "one_sine"
amplitude = 2.0
units = "g"
period = 1.0
duration = 2.0
[output]
dt = 0.01
events = "overflow.events.csv"
TOML
run "$FLEXROCK" run -o "$WORK/res4" "$WORK/overflow.toml"
expect_rc 1 "non-finite results"
expect_in "$WORK/err" "the results are not finite (max base shear = inf)"
expect_in "$WORK/err" "no output written"
for f in overflow.csv overflow.events.csv overflow.summary.json; do
  [ ! -e "$WORK/res4/$f" ] || fail "non-finite run wrote $f"
done
if grep -qi "nan\|inf" "$WORK/out"; then fail "non-finite figures printed: $(cat "$WORK/out")"; fi

# params: the derived parameters of a flexible body
run "$FLEXROCK" params "$SRC/examples/cases/flexible_tank.toml"
expect_rc 0 "params"
for what in "alpha1 = b1/h" "alpha2 = b2/h" "g b1/h" "g b2/h" "deformation modes: 2" "f [Hz]" \
            "damping" "q static" "kappa =" "psi_x"; do
  expect_in "$WORK/out" "$what"
done
# stiff rocking is known before the run: a slab of b/h = 0.01 carrying a 980 Hz oscillator rocks
# with a coupled motion near 128 kHz; check and params give the figures and, for a 40 s record,
# the step limit it would reach (DOP853 at the default rtol: about 1.7e6 steps per simulated
# second); the examples get no such warning
cat >"$WORK/stiff.toml" <<'TOML'
[body]
type = "oscillator_on_slab"
top_mass = 1000.0
frequency_hz = 980.0
base_mass = 1000.0
height = 4.0
base_width = 0.04
[excitation.horizontal]
type = "harmonic"
amplitude = 0.05
units = "g"
frequency_hz = 2.0
duration = 40.0
TOML
run "$FLEXROCK" check "$WORK/stiff.toml"
expect_rc 0 "check of a stiff body"
expect_in "$WORK/err" "warning: $WORK/stiff.toml: stiff rocking"
expect_in "$WORK/err" "steps per simulated second"
expect_in "$WORK/err" "above max_steps = 50000000"
run "$FLEXROCK" params "$WORK/stiff.toml"
expect_rc 0 "params of a stiff body"
expect_in "$WORK/out" "explicit step cost while rocking"
expect_in "$WORK/err" "stiff rocking"
printf '[solver]\nmax_steps = 1000000000\n' >>"$WORK/stiff.toml"
run "$FLEXROCK" check "$WORK/stiff.toml"
expect_rc 0 "check of a stiff body with a raised step limit"
expect_in "$WORK/err" "a long run is slow"
if grep -q "max_steps" "$WORK/err"; then fail "step limit named though raised"; fi
run "$FLEXROCK" check "$SRC"/examples/cases/*.toml
expect_rc 0 "check of the examples"
if grep -q "stiff rocking" "$WORK/err"; then fail "an example warned: $(cat "$WORK/err")"; fi

echo "run outcomes: ok"
