#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# a [[suite]] of record pairs in a sweep: one record per azimuth, a = H1 cos(beta) + H2 sin(beta);
# the rows at 0 and 90 deg are those of H1 and H2 swept alone, the row at 135 deg that of the
# projection computed here and written as a file, the row at 180 deg mirrors the one at 0 for a
# symmetric block; bad pairs are refused naming the file, the line and the key
source "$(dirname "$0")/common.sh"

DATA="$(cd "$SRC/../shared/data" && pwd)"
cd "$WORK"
cp "$DATA"/RSN8884_14383980_13873090.AT2 "$DATA"/RSN8884_14383980_13873360.AT2 .
cat >block.toml <<'TOML'
[body]
type = "rigid_block"
width = 0.5
height = 3.0
mass = 1000.0
TOML
cat >pairs.toml <<'TOML'
[[body]]
file = "block.toml"
[[suite]]
horizontal = "RSN*090.AT2"
horizontal2 = "RSN*360.AT2"
azimuths_deg = [0, 90, 135, 180]
[scales]
factors = [2.5]
TOML
# the same components alone, and the projection at 135 deg written here in m/s^2
python3 - <<'PY'
import math
def values(name):
    lines = open(name).read().split("\n")[4:]
    return [float(x) for l in lines for x in l.split()]
g = 9.80665
h1 = [g * v for v in values("RSN8884_14383980_13873090.AT2")]
h2 = [g * v for v in values("RSN8884_14383980_13873360.AT2")]
c, s = -math.sqrt(0.5), math.sqrt(0.5)  # 135 deg, as the library reduces it: exactly opposite
with open("p135.dat", "w") as f:
    f.write("".join(repr(c * a + s * b) + "\n" for a, b in zip(h1, h2)))
PY
cat >alone.toml <<'TOML'
[[body]]
file = "block.toml"
[[record]]
file = "RSN8884_14383980_13873090.AT2"
name = "h1"
[[record]]
file = "RSN8884_14383980_13873360.AT2"
name = "h2"
[[record]]
file = "p135.dat"
format = "single_column"
dt = 0.005
units = "m/s^2"
name = "p135"
[scales]
factors = [2.5]
TOML

run "$FLEXROCK" sweep pairs.toml -o pairs.csv -q
expect_rc 0 "a sweep over a suite of pairs"
expect_in "$WORK/out" "1 bodies x 4 records x 1 scales = 4 runs"
run "$FLEXROCK" sweep alone.toml -o alone.csv -q
expect_rc 0 "the components swept alone"
python3 - <<'PY' || fail "the rows of the pair at 0, 90, 135 and 180 deg"
import csv
pairs = {r["record"].split("@")[1]: r for r in csv.DictReader(open("pairs.csv"))}
alone = {r["record"]: r for r in csv.DictReader(open("alone.csv"))}
assert set(pairs) == {"0", "90", "135", "180"}, pairs.keys()
name = "RSN8884_14383980_13873090+RSN8884_14383980_13873360@"
assert all(r["record"] == name + k for k, r in pairs.items())
def same(a, b):
    keys = [k for k in a if k not in ("index", "record")]
    return [k for k in keys if a[k] != b[k]]
assert not same(pairs["0"], alone["h1"]), same(pairs["0"], alone["h1"])
assert not same(pairs["90"], alone["h2"]), same(pairs["90"], alone["h2"])
assert not same(pairs["135"], alone["p135"]), same(pairs["135"], alone["p135"])
# 180 deg: the record's negative; the symmetric block's response is the mirror of the one at 0
a, b = pairs["0"], pairs["180"]
for k in ("pga_m_per_s2", "pgv_m_per_s", "outcome", "max_theta_over_alpha", "impacts"):
    assert a[k] == b[k], (k, a[k], b[k])
assert a["outcome"] != "no_uplift", a["outcome"]
PY

# errors: key, line, file; no output
cat >bad.toml <<'TOML'
[[body]]
file = "block.toml"
[[suite]]
horizontal = ["RSN8884_14383980_13873090.AT2"]
horizontal2 = ["RSN8884_14383980_13873360.AT2", "p135.dat"]
[scales]
factors = [1]
TOML
run "$FLEXROCK" sweep bad.toml -o bad.csv -q
expect_rc 2 "lists of different lengths"
expect_in "$WORK/err" "bad.toml:5: key 'suite.horizontal2'"
expect_in "$WORK/err" "expected as many horizontal2 files as horizontal ones (1), got 2"
[ ! -e bad.csv ] || fail "output written for a refused sweep"
sed -e 's/^horizontal2 = .*/horizontal2 = ["RSN8884_14383980_13873360.AT2"]/' \
  -e 's/^\[scales\]/azimuths_deg = [0, 400]\n[scales]/' bad.toml >bad2.toml
run "$FLEXROCK" sweep bad2.toml -o bad.csv -q
expect_rc 2 "an azimuth out of range"
expect_in "$WORK/err" "key 'suite.azimuths_deg': expected distinct azimuths in [0, 360) deg, got 400"
sed -e '/^horizontal2/d' bad2.toml >bad3.toml
run "$FLEXROCK" sweep bad3.toml -o bad.csv -q
expect_rc 2 "azimuths without a pair"
expect_in "$WORK/err" "expected only with 'horizontal2' (a record pair)"
printf '0\n0.1\n-0.1\n' >short.dat
cat >bad4.toml <<'TOML'
[[body]]
file = "block.toml"
[[suite]]
horizontal = ["p135.dat"]
horizontal2 = ["short.dat"]
format = "single_column"
dt = 0.005
units = "m/s^2"
[scales]
factors = [1]
TOML
run "$FLEXROCK" sweep bad4.toml -o bad.csv -q
expect_rc 2 "a pair on two time grids"
expect_in "$WORK/err" "expected the horizontal2 record"
expect_in "$WORK/err" "short.dat on the time grid of its horizontal"
[ ! -e bad.csv ] || fail "output written for a refused sweep"
echo OK
