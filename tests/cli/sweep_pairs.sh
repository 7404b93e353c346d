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

# fragility over the pairs: --worst-azimuth makes one observation of each pair at each level,
# failed if any azimuth failed, with the median of the azimuths' measure; it equals the plain fit
# of those observations written here as a sweep CSV of their own
cp "$DATA"/RSN8883_14383980_13849090.AT2 "$DATA"/RSN8883_14383980_13849360.AT2 .
cat >slender.toml <<'TOML'
[body]
type = "rigid_block"
width = 0.3
height = 1.5
mass = 500.0
TOML
cat >wa.toml <<'TOML'
[[body]]
file = "slender.toml"
[[suite]]
horizontal = "RSN*090.AT2"
horizontal2 = "RSN*360.AT2"
azimuth_step_deg = 45
[scales]
factors = [0.5, 1, 1.5, 2, 3, 4, 6, 8]
TOML
run "$FLEXROCK" sweep wa.toml -o wa.csv -q
expect_rc 0 "a sweep of two pairs at 8 azimuths"
run "$FLEXROCK" fragility wa.csv --worst-azimuth -o worst.csv -q
expect_rc 0 "worst-azimuth fragility"
expect_in "$WORK/out" "P(overturning | rotd50:pga_g)"
python3 - <<'PY' || fail "the worst-azimuth observations"
import csv, statistics
rows = list(csv.DictReader(open("wa.csv")))
cols = list(rows[0])
groups = {}
for r in rows:
    groups.setdefault((r["record"].split("@")[0], r["requested_level"]), []).append(r)
assert len(groups) == 16 and all(len(g) == 8 for g in groups.values())
out = []
for i, g in enumerate(groups.values()):
    failed = [r for r in g if r["overturned"] == "1"]
    row = dict(failed[0] if failed else g[0])
    row["index"] = str(i)
    row["pga_g"] = repr(statistics.median(float(r["pga_g"]) for r in g))
    out.append(row)
n = sum(1 for r in out if r["overturned"] == "1")
assert 0 < n < 16, n
with open("grouped.csv", "w", newline="") as f:
    w = csv.DictWriter(f, cols, lineterminator="\n")
    w.writeheader()
    w.writerows(out)
open("failures", "w").write(str(n))
PY
expect_in "$WORK/out" "16 runs ($(cat failures) with the outcome)"
run "$FLEXROCK" fragility grouped.csv -o grouped_fit.csv -q
expect_rc 0 "the plain fit of the grouped observations"
python3 - <<'PY' || fail "worst-azimuth fit against the fit of its observations"
import csv
a = next(csv.DictReader(open("worst.csv")))
b = next(csv.DictReader(open("grouped_fit.csv")))
assert a["im_name"] == "rotd50:pga_g" and b["im_name"] == "pga_g", (a["im_name"], b["im_name"])
for k in ("samples", "failures", "theta", "beta", "theta_lower", "theta_upper"):
    assert a[k] == b[k], (k, a[k], b[k])
PY
# refused: a sweep of single records
run "$FLEXROCK" fragility alone.csv --worst-azimuth
expect_rc 2 "worst azimuth without pairs"
expect_in "$WORK/err" "is not one azimuth of a record pair"
# a target scales a pair, every azimuth alike, to the pair's RotD50 (computed here from the files)
sed -e 's/^factors = .*/target_pga = [0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1]\nunits = "g"/' wa.toml >wt.toml
run "$FLEXROCK" sweep wt.toml -o wt.csv -q
expect_rc 0 "a sweep of pairs to target PGAs"
python3 - <<'PY' || fail "a pair scaled to its RotD50 PGA"
import csv, math
g = 9.80665
def values(name):
    lines = open(name).read().split("\n")[4:]
    return [g * float(x) for l in lines for x in l.split()]
rows = list(csv.DictReader(open("wt.csv")))
for stem in ("RSN8883_14383980_1384", "RSN8884_14383980_1387"):
    a1, a2 = values(stem + "9090.AT2" if "8883" in stem else stem + "3090.AT2"), \
             values(stem + "9360.AT2" if "8883" in stem else stem + "3360.AT2")
    peaks = sorted(max(abs(math.cos(math.radians(k)) * x + math.sin(math.radians(k)) * y)
                       for x, y in zip(a1, a2)) for k in range(180))
    rotd50 = 0.5 * (peaks[89] + peaks[90])
    mine = [r for r in rows if r["record"].startswith(stem[:7])]
    assert len(mine) == 56, len(mine)
    for level in ("0.5", "0.6", "0.7", "0.8", "0.9", "1", "1.1"):
        at = [r for r in mine if r["requested_level"] == level]
        assert len({r["scale"] for r in at}) == 1, [r["scale"] for r in at]  # every azimuth alike
        s = float(at[0]["scale"])
        assert math.isclose(s * rotd50, float(level) * g, rel_tol=1e-12), (s * rotd50, level)
        # each azimuth's own PGA is its component's, not the target
        assert len({r["pga_m_per_s2"] for r in at}) > 1
PY
run "$FLEXROCK" fragility wt.csv --worst-azimuth --im requested_level -q
expect_rc 0 "worst azimuth over a pair sweep to targets"
sed -e 's/^factors = .*/target_im = "arias"\ntargets = [0.1]/' wa.toml >wv.toml
run "$FLEXROCK" sweep wv.toml -o wv.csv -q
expect_rc 2 "a pair to a target without a RotD"
expect_in "$WORK/err" "target_im takes sa for pairs, got 'arias'"
[ ! -e wv.csv ] || fail "output written for a refused sweep"
echo OK
