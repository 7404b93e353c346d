#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# a body of revolution ("cylinder", "body_of_revolution") under a record pair: `flexrock run` runs
# it in 3D (docs/theory.md §27) and writes its time history, events and summary; alone (one
# component) it is its planar section; a body no rigid body can be is refused, nothing written
source "$(dirname "$0")/common.sh"

DATA="$(cd "$SRC/../shared/data" && pwd)"
mkdir -p "$WORK/cases" "$WORK/o"
body_case() {
  cat <<TOML
[body]
$1
[excitation]
scale = 3.0
[excitation.horizontal]
type = "record"
file = "$DATA/RSN8884_14383980_13873090.AT2"
$2
[output]
dt = 0.01
events = "events.csv"
TOML
}
pair='[excitation.horizontal2]
type = "record"
file = "'"$DATA"'/RSN8884_14383980_13873360.AT2"'
cask='type = "cylinder"
radius = 1.7
height = 5.9
mass = 120000.0'

body_case "$cask" "$pair" >"$WORK/cases/cask.toml"
run "$FLEXROCK" run -o "$WORK/o" "$WORK/cases/cask.toml"
expect_rc 0 "3D run of a cylinder under a pair"
expect_in "$WORK/out" "body of revolution in 3D"
head -1 "$WORK/o/cask.csv" | grep -qF "time_s,mode,tilt_rad,tilt_azimuth_deg,contact_angle_deg" ||
  fail "3D time-history columns"
python3 - "$WORK/o/cask.summary.json" "$WORK/o/cask.csv" "$WORK/o/events.csv" <<'PY' || fail "3D summary"
import csv, json, sys
s = json.load(open(sys.argv[1]))
assert s["engine"] == "3d_body_of_revolution", s
assert s["status"] == "completed", s
assert s["uplifts"] >= 1 and s["max_tilt_rad"] > 0, s
e = s["energy"]
assert abs(e["residual_J"]) <= 1e-5 * e["input_work_J"], e
rows = list(csv.DictReader(open(sys.argv[2])))
assert max(float(r["tilt_rad"]) for r in rows) <= s["max_tilt_rad"] * (1 + 1e-12)
ev = list(csv.DictReader(open(sys.argv[3])))
assert ev[0]["kind"] == "uplift", ev
PY

# one component: the planar section, by the planar engine
body_case "$cask" "" >"$WORK/cases/alone.toml"
run "$FLEXROCK" run -q -o "$WORK/o" "$WORK/cases/alone.toml"
expect_rc 0 "planar run of a cylinder"
python3 -c "import json,sys; s=json.load(open(sys.argv[1])); assert 'engine' not in s, s" \
  "$WORK/o/alone.summary.json" || fail "a single component runs the planar engine"

# C > 2 A: no rigid body; the file, the line and the rule named, nothing written
body_case 'type = "body_of_revolution"
mass = 1000.0
cg_height = 1.0
base_radius = 0.5
inertia_diameter = 100.0
inertia_axis = 300.0' "$pair" >"$WORK/cases/bad.toml"
run "$FLEXROCK" run -o "$WORK/o3" "$WORK/cases/bad.toml"
expect_rc 2 "impossible inertias"
expect_in "$WORK/err" "bad.toml:"
expect_in "$WORK/err" "C <= 2 A"
[ ! -e "$WORK/o3" ] || fail "output written for a refused body"
echo "body_of_revolution: ok"
