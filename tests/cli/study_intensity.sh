#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# intensity measures in a sweep: the [intensity] table adds its columns after pgv_m_per_s, with
# the values the library's table computes for each scaled record; without it the CSV is the one
# of a sweep before the measures existed; fragility fits any of them; bad names are refused
source "$(dirname "$0")/common.sh"

cd "$WORK"
sed -e "s#\"../cases/#\"$SRC/examples/cases/#" -e "s#\"slender_block.toml\"#\"$SRC/examples/studies/slender_block.toml\"#" \
  -e "s#\"../../../shared/#\"$SRC/../shared/#" "$SRC/examples/studies/sweep.toml" >plain.toml
run "$FLEXROCK" sweep plain.toml -o plain.csv -q -j 2
expect_rc 0 "sweep without [intensity]"
head -1 plain.csv | grep -q "^index,body,record,requested_level,requested_units,scale,pga_m_per_s2,pga_g,pgv_m_per_s,duration_s,outcome," ||
  fail "plain sweep columns: $(head -1 plain.csv)"

cp plain.toml ims.toml
cat >>ims.toml <<'TOML'

[intensity]
measures = ["pgd", "arias", "cav", "d5_95", "pgv_over_pga"]
sa_periods = [0.3, 1.0]
TOML
run "$FLEXROCK" sweep ims.toml -o ims.csv -q -j 2
expect_rc 0 "sweep with [intensity]"
head -1 ims.csv | grep -q "^index,body,record,requested_level,requested_units,scale,pga_m_per_s2,pga_g,pgv_m_per_s,pgd_m,arias_m_per_s,cav_m_per_s,d5_95_s,pgv_over_pga_s,sa_T0.3_z0.05_m_per_s2,sa_T1_z0.05_m_per_s2,duration_s,outcome," ||
  fail "intensity columns: $(head -1 ims.csv)"
# the same runs: removing the seven columns gives the plain CSV byte for byte
cut -d, -f10-16 --complement ims.csv | cmp - plain.csv || fail "the outcomes changed with the measures"
# every measure, recomputed here from the record file scaled by the row's factor
python3 - "$SRC/../shared/data/elcentro_1940_ns.dat" ims.csv <<'PY'
import csv, math, sys
a = [float(x) * 9.80665 for line in open(sys.argv[1]) if not line.startswith("#") for x in line.split()]
t = [0.02 * i for i in range(len(a))]
rows = [r for r in csv.DictReader(open(sys.argv[2])) if r["record"] == "elcentro"]
assert rows
def ims(s):
    b = [s * x for x in a]
    sq = sum((t[i+1]-t[i]) * (b[i]**2 + b[i]*b[i+1] + b[i+1]**2) / 3 for i in range(len(b)-1))
    cav = 0.0
    for i in range(len(b) - 1):
        h, a0, a1 = t[i+1]-t[i], b[i], b[i+1]
        cav += 0.5*h*(a0*a0 + a1*a1)/(abs(a0)+abs(a1)) if a0*a1 < 0 else 0.5*h*(abs(a0)+abs(a1))
    # displacement by exact cubic steps, sampled finely (the extrema between samples are within
    # rounding of a fine sampling's)
    v = d = pgd = pgv = 0.0
    for i in range(len(b) - 1):
        h, a0 = t[i+1]-t[i], b[i]
        k = (b[i+1]-b[i]) / h
        for j in range(1, 21):
            x = h * j / 20
            pgd = max(pgd, abs(d + v*x + a0*x*x/2 + k*x**3/6))
        d += v*h + a0*h*h/2 + k*h**3/6
        v += (b[i] + b[i+1]) * h / 2
        pgv = max(pgv, abs(v))
    return {"arias_m_per_s": math.pi / (2 * 9.80665) * sq, "cav_m_per_s": cav, "pgd_m": pgd,
            "pgv_over_pga_s": pgv / max(abs(x) for x in b)}
for r in rows[::3]:
    want = ims(float(r["scale"]))
    for k, v in want.items():
        got = float(r[k])
        assert abs(got - v) <= 1e-6 * abs(v), (k, r["index"], got, v)
print("ok")
PY
[ $? -eq 0 ] || fail "measures differ from an independent computation"

# fragility on any of them
run "$FLEXROCK" fragility ims.csv --im cav --body block
expect_rc 0 "fragility against CAV"
expect_in "$WORK/out" "block: P(overturning | cav)"
expect_in "$WORK/out" " m/s  ["
run "$FLEXROCK" fragility ims.csv --im sa:1 --body statue
expect_rc 0 "fragility against Sa(1 s)"
expect_in "$WORK/out" " m/s^2  ["
run "$FLEXROCK" fragility ims.csv --im sa:0.3:0.05 --body statue
expect_rc 0 "fragility against Sa(0.3 s, 5 %)"
# the plot draws the fit against any of them (where the build has its Python package)
if [ "${FLEXROCK_TEST_PLOT:-0}" = 1 ]; then
  run "$FLEXROCK" plot ims.csv --im sa:1 -o sa.svg
  expect_rc 0 "plot against Sa(1 s)"
  grep -q "Sa(1 s, 5 %)" sa.svg || fail "no Sa axis label in the plot"
fi
# not written by the sweep, unknown, malformed: exit 2 with what to do
run "$FLEXROCK" fragility plain.csv --im pgd
expect_rc 2 "IM not in the CSV"
expect_in "$WORK/err" "needs the column 'pgd_m', which this sweep did not write"
run "$FLEXROCK" fragility ims.csv --im sa:2
expect_rc 2 "Sa period not in the CSV"
expect_in "$WORK/err" "sa_T2_z0.05_m_per_s2"
run "$FLEXROCK" fragility ims.csv --im pgx
expect_rc 2 "unknown IM"
expect_in "$WORK/err" "expected one of: pga, pga_g, pgv, scale, requested_level, pgd, arias"
run "$FLEXROCK" fragility ims.csv --im sa:x
expect_rc 2 "bad Sa period"
expect_in "$WORK/err" "\"x\" is not a number"

# stripes at levels of Sa(1 s): every record scaled so that its Sa(1 s) is the target, which
# its own Sa column shows; then the multiple-stripe fit over those stripes
sed -e 's/^target_pga = .*/target_im = "sa:1"\ntargets = { start = 0.1, stop = 0.8, step = 0.1 }/' plain.toml >stripes.toml
printf '\n[intensity]\nmeasures = ["arias"]\nsa_periods = [1]\n' >>stripes.toml
run "$FLEXROCK" sweep stripes.toml -o stripes.csv -q -j 2
expect_rc 0 "sweep at Sa targets"
python3 - stripes.csv <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 32
for r in rows:
    assert r["requested_units"] == "g", r["requested_units"]
    want = float(r["requested_level"]) * 9.80665
    got = float(r["sa_T1_z0.05_m_per_s2"])
    assert abs(got - want) <= 1e-12 * want, (r["index"], got, want)
print("ok")
PY
[ $? -eq 0 ] || fail "Sa of the scaled records differs from the targets"
run "$FLEXROCK" fragility stripes.csv --analysis msa --body statue --outcome theta --level 0.3
expect_rc 0 "multiple-stripe fit"
expect_in "$WORK/out" "stripe 0.1 g: "
expect_in "$WORK/out" "P(max theta/alpha > 0.3 | requested_level)"
# Arias targets scale by the square root of the ratio
sed -e 's/^target_pga = .*/target_im = "arias"\ntargets = [0.5, 1.0]/' -e '${/^units = "g"/d}' plain.toml >arias.toml
printf '\n[intensity]\nmeasures = ["arias"]\n' >>arias.toml
run "$FLEXROCK" sweep arias.toml -o arias.csv -q -j 2
expect_rc 0 "sweep at Arias targets"
python3 - arias.csv <<'PY'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    assert r["requested_units"] == "m/s", r["requested_units"]
    want, got = float(r["requested_level"]), float(r["arias_m_per_s"])
    assert abs(got - want) <= 1e-12 * want, (r["index"], got, want)
PY
[ $? -eq 0 ] || fail "Arias of the scaled records differs from the targets"
for bad in 'target_im = "d5_95"' 'target_im = "pga"' 'target_im = "sa:x"'; do
  sed -e "s/^target_pga = .*/$bad\ntargets = [1]/" -e '${/^units = "g"/d}' plain.toml >bad.toml
  run "$FLEXROCK" sweep bad.toml -o bad.csv -q
  expect_rc 2 "bad target: $bad"
  expect_in "$WORK/err" "scales.target_im"
done

# bad [intensity] tables: file, line, key
for bad in 'measures = ["pga"]' 'measures = ["sa"]' 'measures = ["pgd", "pgd"]' 'sa_periods = [0]' \
  'sa_periods = [1, 1]' 'sa_damping = 0.1' 'measure = ["pgd"]'; do
  printf '%s\n\n[intensity]\n%s\n' "$(cat plain.toml)" "$bad" >bad.toml
  run "$FLEXROCK" sweep bad.toml -o bad.csv -q
  expect_rc 2 "bad [intensity]: $bad"
  expect_in "$WORK/err" "bad.toml:"
  expect_in "$WORK/err" "intensity."
  [ ! -e bad.csv ] || fail "an output for a bad manifest"
done
echo "ok"
