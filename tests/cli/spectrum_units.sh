# SPDX-License-Identifier: BSD-3-Clause
# flexrock spectrum on physical axes asked in g and Hz: the CSVs keep those units, in columns
# named by them beside the SI ones, holding the grid's own numbers; the SI columns are those of
# the same spectrum spelled in m/s^2 and rad/s; shards and their merge carry the columns; a grid in
# SI has no such columns
source "$(dirname "$0")/common.sh"
cd "$WORK"

cat >block.toml <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
TOML
cat >g_hz.toml <<'TOML'
body = "block.toml"
[spectrum]
pulse = "one_sine"
axes = "physical"
amplitude_units = "g"
frequency_units = "Hz"
amplitudes = [0.1, 0.2, 0.3, 0.7]
frequencies = [0.5, 1.1, 2.3]
bisection_tolerance = 0.01
free_periods = 2
TOML
# the same grid in SI: a_p = a [g] * 9.80665, omega_p = 2 pi f (the products the reader forms)
python3 - <<'PY'
import math
a = ", ".join(repr(v * 9.80665) for v in [0.1, 0.2, 0.3, 0.7])
f = ", ".join(repr(2.0 * math.pi * v) for v in [0.5, 1.1, 2.3])
open("si.toml", "w").write(f'''body = "block.toml"
[spectrum]
pulse = "one_sine"
axes = "physical"
amplitudes = [{a}]
frequencies = [{f}]
bisection_tolerance = 0.01
free_periods = 2
''')
PY

run "$FLEXROCK" spectrum g_hz.toml -o g.csv -q
expect_rc 0 "a spectrum in g and Hz"
run "$FLEXROCK" spectrum si.toml -o si.csv -q
expect_rc 0 "the same spectrum in SI"

python3 - <<'PY' || fail "the columns in g and Hz"
import csv, math
def table(p):
    with open(p) as f:
        r = list(csv.reader(f))
    return r[0], r[1:]
h, rows = table("g.csv")
hs, rows_si = table("si.csv")
# the unit columns right after the SI ones they restate, and only in the g/Hz file
assert h[h.index("a_p_m_per_s2") + 1] == "a_p_g", h
assert h[h.index("omega_p_rad_per_s") + 1] == "f_p_hz", h
assert "a_p_g" not in hs and "f_p_hz" not in hs, hs
# their values are the grid's numbers as written, not the SI ones divided back
col = {n: [r[h.index(n)] for r in rows] for n in h}
assert sorted(set(col["a_p_g"]), key=float) == ["0.1", "0.2", "0.3", "0.7"], set(col["a_p_g"])
assert sorted(set(col["f_p_hz"]), key=float) == ["0.5", "1.1", "2.3"], set(col["f_p_hz"])
# without them, the file is the SI spectrum's, byte for byte
drop = [h.index("a_p_g"), h.index("f_p_hz")]
strip = lambda r: [v for i, v in enumerate(r) if i not in drop]
assert strip(h) == hs and [strip(r) for r in rows] == rows_si
# the boundary: f_p_hz after omega_p_rad_per_s, min_overturning_g after min_overturning_m_per_s2
bh, b = table("g.boundary.csv")
assert bh[bh.index("omega_p_rad_per_s") + 1] == "f_p_hz", bh
assert bh[bh.index("min_overturning_m_per_s2") + 1] == "min_overturning_g", bh
bc = {n: [r[bh.index(n)] for r in b] for n in bh}
assert bc["f_p_hz"] == ["0.5", "1.1", "2.3"], bc["f_p_hz"]
assert bc["frequency"] == bc["f_p_hz"]  # the grid's own column is in Hz too
found = [i for i, k in enumerate(bc["kind"]) if k == "found"]
assert found, bc["kind"]
for i in found:
    g_val, si_val = float(bc["min_overturning_g"][i]), float(bc["min_overturning_m_per_s2"][i])
    assert bc["min_overturning_g"][i] == bc["min_overturning"][i]
    assert abs(g_val * 9.80665 - si_val) <= 1e-12 * si_val, (g_val, si_val)
    # bisected in g: inside the bracket the grid gives, to the tolerance asked
    lo = float(bc["safe_below"][i])
    assert lo < g_val and g_val - lo <= 0.01 * g_val * (1 + 1e-12), (lo, g_val)
PY

# shards of the g/Hz spectrum merge into the single run's files
for k in 1 2; do
  run "$FLEXROCK" spectrum g_hz.toml -o s.csv --shard "$k/2" -j 1 -q
  expect_rc 0 "shard $k/2 of the g/Hz spectrum"
done
run "$FLEXROCK" merge s.csv.shard*of2
expect_rc 0 "merge of the g/Hz shards"
cmp g.csv s.csv || fail "the merged g/Hz cells differ from the single run"
cmp g.boundary.csv s.boundary.csv || fail "the merged g/Hz boundary differs from the single run"
echo OK
