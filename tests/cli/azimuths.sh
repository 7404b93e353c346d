#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# a record pair: `flexrock azimuths` writes one row per azimuth and the envelope; the row at an
# azimuth is what `flexrock run` gives with azimuth_deg there (the same numbers as its summary);
# bad pairs are refused naming the file, the line and the key, with nothing written
source "$(dirname "$0")/common.sh"

DATA="$(cd "$SRC/../shared/data" && pwd)"
mkdir -p "$WORK/cases" "$WORK/o"
pair_case() {
  cat <<TOML
[body]
type = "rigid_block"
width = 0.5
height = 3.0
mass = 1000.0
[excitation]
scale = 3.0
$1
[excitation.horizontal]
type = "record"
file = "$DATA/RSN8884_14383980_13873090.AT2"
[excitation.horizontal2]
type = "record"
file = "$2"
[solver]
t_end = 40.0
[output]
dt = 0
TOML
}
H2="$DATA/RSN8884_14383980_13873360.AT2"
pair_case "azimuth_step_deg = 45" "$H2" >"$WORK/cases/pair.toml"
run "$FLEXROCK" azimuths -o "$WORK/o" "$WORK/cases/pair.toml"
expect_rc 0 "azimuths of a pair"
expect_in "$WORK/out" "azimuths: 8 (every 45 deg over [0, 360))"
expect_in "$WORK/out" "envelope: max tilt"
[ "$(wc -l <"$WORK/o/pair.azimuths.csv")" -eq 9 ] || fail "expected a header and 8 rows"
head -1 "$WORK/o/pair.azimuths.csv" | grep -q '^azimuth_deg,outcome,max_theta_rad,' ||
  fail "columns of the azimuth table"
json_get "$WORK/o/pair.azimuths.json" envelope.max_theta_rad >/dev/null
# RotD100 of the PGA is the largest peak over the 180 directions, computed here from the files
python3 - "$WORK/o/pair.azimuths.json" "$DATA" <<'PY' || fail "RotD of the PGA"
import json, math, sys
j = json.load(open(sys.argv[1]))["pair"]
def values(name):
    lines = open(sys.argv[2] + "/" + name).read().split("\n")[4:]
    return [float(x) for l in lines for x in l.split()]
a1 = values("RSN8884_14383980_13873090.AT2")
a2 = values("RSN8884_14383980_13873360.AT2")
peaks = sorted(3 * 9.80665 * max(abs(math.cos(math.radians(k)) * x + math.sin(math.radians(k)) * y)
                                 for x, y in zip(a1, a2)) for k in range(180))
assert math.isclose(j["rotd100_pga_m_per_s2"], peaks[-1], rel_tol=1e-6), (j, peaks[-1])
assert math.isclose(j["rotd50_pga_m_per_s2"], 0.5 * (peaks[89] + peaks[90]), rel_tol=1e-6), j
PY

# the row at 135 deg is `flexrock run` at azimuth_deg = 135, number for number
pair_case "azimuth_deg = 135" "$H2" >"$WORK/cases/one.toml"
run "$FLEXROCK" run -q -o "$WORK/o" "$WORK/cases/one.toml"
expect_rc 0 "run at one azimuth"
python3 - "$WORK/o/pair.azimuths.csv" "$WORK/o/one.summary.json" <<'PY' || fail "row 135 differs from the run"
import csv, json, sys
rows = {float(r["azimuth_deg"]): r for r in csv.DictReader(open(sys.argv[1]))}
s = json.load(open(sys.argv[2]))
r = rows[135.0]
x = s["peaks"]
assert float(r["max_theta_edge1_rad"]) == x["max_theta_edge1_rad"], (r, x)
assert float(r["max_theta_edge2_rad"]) == x["max_theta_edge2_rad"], (r, x)
assert int(r["impacts"]) == x["impacts"], (r, x)
assert float(r["max_theta_edge1_rad"]) > 0
PY

# a pair without azimuth_deg is not a `run`
run "$FLEXROCK" run -o "$WORK/o2" "$WORK/cases/pair.toml"
expect_rc 2 "run of a pair without azimuth_deg"
expect_in "$WORK/err" "flexrock azimuths"
[ ! -e "$WORK/o2" ] || [ -z "$(ls -A "$WORK/o2")" ] || fail "output written for a refused run"

# mismatched time steps: both files named, the key and its line; nothing written
pair_case "" "$DATA/A-CAT180.AT2.smc" >"$WORK/cases/bad_dt.toml"
run "$FLEXROCK" azimuths -o "$WORK/o3" "$WORK/cases/bad_dt.toml"
expect_rc 2 "pair of different time steps"
expect_in "$WORK/err" "bad_dt.toml:14: key 'excitation.horizontal2.file'"
expect_in "$WORK/err" "A-CAT180.AT2.smc"
expect_in "$WORK/err" "RSN8884_14383980_13873090.AT2"
[ ! -e "$WORK/o3" ] || fail "output written for a refused pair"

# an unknown key, with its line
pair_case "azimuth_stepdeg = 5" "$H2" >"$WORK/cases/typo.toml"
run "$FLEXROCK" azimuths -o "$WORK/o4" "$WORK/cases/typo.toml"
expect_rc 2 "unknown key"
expect_in "$WORK/err" "typo.toml:8: key 'excitation.azimuth_stepdeg'"
[ ! -e "$WORK/o4" ] || fail "output written for a refused case"
echo "ok"
