#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# records as agencies publish them, from a case file: the SMC file is read by its name's ending
# (no format key) with its own units and rate; units that disagree with the file, or a name that
# says no format, are refused naming the key and the line
source "$(dirname "$0")/common.sh"

DATA="$(cd "$SRC/../shared/data" && pwd)"
mkdir -p "$WORK/cases"
case_with() {
  cat <<TOML
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
[excitation.horizontal]
type = "record"
$1
[solver]
t_end = 1.0
TOML
}
case_with "file = \"$DATA/A-CAT090.AT2.smc\"" >"$WORK/cases/smc.toml"
run "$FLEXROCK" check "$WORK/cases/smc.toml"
expect_rc 0 "check an SMC record chosen by its name"
# 41.355427 cm/s^2 = 0.04217 g = 0.4136 m/s^2; 50 samples/s
expect_in "$WORK/out" "record horizontal: $DATA/A-CAT090.AT2.smc: PGA 0.04217 g (0.4136 m/s^2)"
expect_in "$WORK/out" "dt 0.02 s"

case_with "file = \"$DATA/A-CAT090.AT2.smc\"
units = \"g\"" >"$WORK/cases/bad_units.toml"
run "$FLEXROCK" check "$WORK/cases/bad_units.toml"
expect_rc 2 "units that disagree with the SMC file"
expect_in "$WORK/err" "bad_units.toml:9: key 'excitation.horizontal.units'"
expect_in "$WORK/err" "expected the units the smc file states (cm/s^2)"

printf '0.1\n0.2\n' >"$WORK/cases/rec.txt"
case_with "file = \"rec.txt\"
units = \"g\"" >"$WORK/cases/no_format.toml"
run "$FLEXROCK" check "$WORK/cases/no_format.toml"
expect_rc 2 "a record file whose name says no format"
expect_in "$WORK/err" "key 'excitation.horizontal.format'"
expect_in "$WORK/err" "at2, smc, knet, esm, cosmos, single_column, time_series"
# a spreadsheet's CSV whose units row states the units: no units key needed
printf 'time;acceleration\ns;cm/s^2\n0;0\n0,01;98,0665\n0,02;0\n' >"$WORK/cases/sheet.csv"
case_with "file = \"sheet.csv\"
format = \"time_series\"" >"$WORK/cases/sheet.toml"
run "$FLEXROCK" check "$WORK/cases/sheet.toml"
expect_rc 0 "a time series with a units row and decimal commas"
expect_in "$WORK/out" "sheet.csv: PGA 0.1 g (0.9807 m/s^2)"
echo "ok"
