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

# params: the derived parameters of a flexible body
run "$FLEXROCK" params "$SRC/examples/cases/flexible_tank.toml"
expect_rc 0 "params"
for what in "alpha1 = b1/h" "alpha2 = b2/h" "g b1/h" "g b2/h" "deformation modes: 2" "f [Hz]" \
            "damping" "q static" "kappa =" "psi_x"; do
  expect_in "$WORK/out" "$what"
done
echo "run outcomes: ok"
