#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# each new configuration runs on its own engine: a case that combines two (a support with
# restraints, a rocking frame on a support or with restraints, a body of revolution in 3D on a
# support or with restraints) is refused with the file, the line and the key, nothing written
source "$(dirname "$0")/common.sh"

DATA="$(cd "$SRC/../shared/data" && pwd)"
cd "$WORK"
block='[body]
type = "rigid_block"
width = 0.5
height = 2.0
mass = 1000.0'
frame='[body]
type = "rocking_frame"
column_width = 0.4
column_height = 3.0
column_mass = 500.0
beam_mass = 2000.0'
cylinder='[body]
type = "cylinder"
radius = 0.4
height = 2.0
mass = 1000.0'
pulse='[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
period = 1.0
duration = 3.0'
pair="[excitation.horizontal]
type = \"record\"
file = \"$DATA/RSN8884_14383980_13873090.AT2\"
[excitation.horizontal2]
type = \"record\"
file = \"$DATA/RSN8884_14383980_13873360.AT2\""
support='[support]
mass = 500.0
frequency_hz = 2.0'
tendon='[[restraint]]
kind = "tendon"
length = 10.0
stiffness = 1.0e7
prestress = 1.0e4'

refuse() {  # name body excitation extra1 extra2 expected-key expected-text
  printf '%s\n%s\n%s\n%s\n' "$2" "$3" "$4" "$5" >"$1.toml"
  run "$FLEXROCK" run "$1.toml" -o "out_$1" -q
  expect_rc 2 "$1"
  expect_in "$WORK/err" "$1.toml:"
  expect_in "$WORK/err" "key '$6'"
  expect_in "$WORK/err" "$7"
  [ ! -e "out_$1" ] || [ -z "$(ls -A "out_$1")" ] || fail "$1: output written for a refused case"
}
refuse support_restraint "$block" "$pulse" "$support" "$tendon" support "with [[restraint]] tables is not modelled yet"
refuse frame_support "$frame" "$pulse" "$support" "" support "a rocking_frame on a support is not modelled yet"
refuse frame_restraint "$frame" "$pulse" "$tendon" "" restraint "a rocking_frame with [[restraint]] tables"
refuse cylinder_support "$cylinder" "$pair" "$support" "" support "runs in 3D, where a [support] is not modelled yet"
refuse cylinder_restraint "$cylinder" "$pair" "$tendon" "" restraint "runs in 3D, where [[restraint]] tables are not modelled yet"
# each alone runs
printf '%s\n%s\n%s\n' "$block" "$pulse" "$support" >ok_support.toml
run "$FLEXROCK" run ok_support.toml -o out_ok -q
expect_rc 0 "a block on a support"
echo OK
