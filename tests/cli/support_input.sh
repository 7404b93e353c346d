#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# a case on a [support]: what it does not model and bad keys are refused when the case is read,
# naming the file, the line and the key; `params` prints the support's figures; a study refuses a
# body file on a support rather than run it on the floor
source "$(dirname "$0")/common.sh"

base() {
  cat <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 1.8
mass = 800.0

[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
frequency_hz = 2.0
duration = 3.0
TOML
}

# $1: name, $2: extra TOML, $3: exit code, $4: expected text
case_of() {
  { base; printf '%s\n' "$2"; } >"$WORK/$1.toml"
  run "$FLEXROCK" check "$WORK/$1.toml"
  expect_rc "$3" "$1"
  [ -z "$4" ] || expect_in "$WORK/err" "$4"
}

case_of ok $'[support]\nmass = 1500.0\nfrequency_hz = 0.5\ndamping_ratio = 0.1' 0 ""
expect_in "$WORK/out" "support: m_s = 1500 kg, 0.5 Hz"
case_of both $'[support]\nmass = 1500.0\nfrequency_hz = 0.5\nstiffness = 1e5' 2 \
  "key 'support.stiffness': give either frequency_hz or stiffness, not both"
case_of neither $'[support]\nmass = 1500.0' 2 "key 'support.frequency_hz': missing; expected frequency_hz"
case_of nomass $'[support]\nfrequency_hz = 0.5' 2 "key 'support.mass': missing"
case_of negative $'[support]\nmass = -1.0\nfrequency_hz = 0.5' 2 "key 'support.mass': expected a number >= 0"
case_of typo $'[support]\nmass = 1.0\nfrequency_hz = 0.5\ndamping_ration = 0.1' 2 "support.damping_ration"
case_of sliding $'[support]\nmass = 1.0\nfrequency_hz = 0.5\n[solver]\nfriction_coefficient = 0.4' 2 \
  "sliding on a support is not modelled"
grep -q "$WORK/sliding.toml:[0-9]*: key 'support': sliding" "$WORK/err" || fail "no place: $(cat "$WORK/err")"
case_of compliant $'[support]\nmass = 1.0\nfrequency_hz = 0.5\n[solver]\ncontact_model = "compliant"\ncontact_stiffness = 1e8' 2 \
  "contact_model = compliant on a support is not modelled"

# params: the coupled frequency, the impact ratios and the transmissibility's thresholds
run "$FLEXROCK" params "$WORK/ok.toml"
expect_rc 0 "params"
expect_in "$WORK/out" "with the body as a rigid mass: f_s = 0.5 Hz, damping ratio 0.1"
expect_in "$WORK/out" "impact onto edge 1: theta_dot+/theta_dot- ="
expect_in "$WORK/out" "steady harmonic uplift"

# a study does not take a body on a support
cat >"$WORK/sweep.toml" <<TOML
[[body]]
name = "statue"
file = "$WORK/ok.toml"
TOML
run "$FLEXROCK" sweep "$WORK/sweep.toml" -o "$WORK/sweep.csv"
[ "$rc" -ne 0 ] || fail "a sweep ran a body on a support"
expect_in "$WORK/err" "a body on a support runs with \`flexrock run\` only"
echo "support input: ok"
