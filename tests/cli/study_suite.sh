#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# record suites in a sweep manifest: [[suite]] pairs horizontal and vertical files by a glob's '*'
# (or lists by position); the vertical reaches the engine scaled by its horizontal's factor (a
# downward floor acceleration beyond g lifts the block off, half of it does not); -j 1 and -j 2
# write the same bytes; globs that match nothing, unpaired files and verticals on another time
# grid are refused naming the file, line and key, with no output file
source "$(dirname "$0")/common.sh"
cd "$WORK"

# three synthetic PEER pairs: a small 2 Hz horizontal sine (below the block's uplift threshold
# g tan(alpha) = 0.2 g) and a vertical that is zero but for a 0.2 s step at 0.5 s
python3 - suite <<'PY'
import math, os, sys
d = sys.argv[1]
os.makedirs(d, exist_ok=True)
def at2(path, vals, dt):
    with open(path, "w") as f:
        f.write("PEER NGA STRONG MOTION DATABASE RECORD\nSYNTHETIC TEST RECORD\n")
        f.write("ACCELERATION TIME SERIES IN UNITS OF G\n")
        f.write("NPTS= %d, DT= %.4f SEC\n" % (len(vals), dt))
        for i in range(0, len(vals), 5):
            f.write("".join("%15.7E" % v for v in vals[i:i + 5]) + "\n")
dt, n = 0.01, 300
# downward steps of 1.5 g and 1.3 g; the third is upward (0.5 g): never a lift-off
for k, (ah, av) in enumerate([(0.05, -1.5), (0.04, -1.3), (0.03, 0.5)], 1):
    at2(f"{d}/RSN{k}_H1.AT2", [ah * math.sin(4 * math.pi * i * dt) for i in range(n)], dt)
    at2(f"{d}/RSN{k}_UP.AT2", [av if 50 <= i < 70 else 0.0 for i in range(n)], dt)
PY

cat >suite.toml <<TOML
free_periods = 1

[[body]]
name = "block"
file = "$SRC/examples/studies/slender_block.toml"

[[suite]]
horizontal = "suite/*_H1.AT2"
vertical = "suite/*_UP.AT2"

[[suite]]   # the same horizontals without their verticals
horizontal = ["suite/RSN1_H1.AT2", "suite/RSN2_H1.AT2", "suite/RSN3_H1.AT2"]

[scales]
factors = [0.5, 1.0]
TOML
run "$FLEXROCK" sweep suite.toml -o j1.csv -q -j 1
expect_rc 0 "suite sweep -j 1"
run "$FLEXROCK" sweep suite.toml -o j2.csv -q -j 2
expect_rc 0 "suite sweep -j 2"
cmp j1.csv j2.csv || fail "-j 1 and -j 2 differ"

python3 - j1.csv <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
names = [r["record"] for r in rows[::2]]
assert names == ["RSN1_H1+RSN1_UP", "RSN2_H1+RSN2_UP", "RSN3_H1+RSN3_UP",
                 "RSN1_H1", "RSN2_H1", "RSN3_H1"], names
by = {(r["record"], float(r["scale"])): r for r in rows}
for k, down in ((1, True), (2, True), (3, False)):
    pair, h = f"RSN{k}_H1+RSN{k}_UP", f"RSN{k}_H1"
    for s in (0.5, 1.0):
        # the intensity is the horizontal's, scaled by the factor
        assert by[(pair, s)]["pga_m_per_s2"] == by[(h, s)]["pga_m_per_s2"]
        assert abs(float(by[(pair, s)]["pga_m_per_s2"]) - s * float(by[(pair, 1.0)]["pga_m_per_s2"])) \
            <= 1e-15 * float(by[(pair, 1.0)]["pga_m_per_s2"])
        # the horizontal alone never lifts the block
        assert by[(h, s)]["outcome"] == "no_uplift" and by[(h, s)]["first_uplift_time_s"] == "-1"
    # the vertical is scaled with its horizontal: at half the factor the step is 0.75 g or
    # 0.65 g down and the block stays on the floor; at the full factor (1.5 g, 1.3 g) the floor
    # falls away faster than g during the step (0.5 s to 0.7 s; the record's linear
    # interpolation crosses -g within the sample before it)
    assert by[(pair, 0.5)]["outcome"] == "no_uplift", by[(pair, 0.5)]
    r = by[(pair, 1.0)]
    if down:
        t = float(r["first_uplift_time_s"])
        assert r["outcome"] != "no_uplift" and 0.49 < t < 0.5, r
        assert float(r["max_uplift_m"]) > 0.01 and float(r["max_impulse_N_s"]) > 0, r
    else:
        assert r["outcome"] == "no_uplift" and r["first_uplift_time_s"] == "-1", r
print("ok")
PY
[ $? -eq 0 ] || fail "suite rows"

# a manifest without [[suite]] is unchanged: the [[record]] tables of the same files give the
# same rows for the horizontals alone
cat >records.toml <<TOML
free_periods = 1

[[body]]
name = "block"
file = "$SRC/examples/studies/slender_block.toml"

[[record]]
file = "suite/RSN1_H1.AT2"

[[record]]
file = "suite/RSN2_H1.AT2"

[[record]]
file = "suite/RSN3_H1.AT2"

[scales]
factors = [0.5, 1.0]
TOML
run "$FLEXROCK" sweep records.toml -o rec.csv -q -j 2
expect_rc 0 "[[record]] sweep"
{ head -1 j1.csv; tail -n 6 j1.csv | awk -F, 'BEGIN{OFS=","} {$1 = $1 - 6; print}'; } | cmp - rec.csv ||
  fail "the horizontal-only suite rows differ from [[record]] rows"

# resume: a suite sweep killed mid-way continues from its journal to the same bytes (factors
# that rock and overturn the block, for runs slow enough to kill); after a
# suite file changed, its journal is refused (the files' bytes are inputs of the journal)
sed -e 's/^factors = .*/factors = { start = 4.0, stop = 8.0, count = 40 }/' suite.toml >slow.toml
printf '[solver]\nmax_step = 0.0005\n' >>slow.toml
run "$FLEXROCK" sweep slow.toml -o ref.csv -q -j 2
expect_rc 0 "uninterrupted suite sweep"
[ "$(wc -l <ref.csv)" -eq 241 ] || fail "expected 240 rows + header"
rm -f out.csv out.csv.partial
"$FLEXROCK" sweep slow.toml -o out.csv -j 1 -q >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 600); do
  if [ -f out.csv.partial ] && [ "$(($(wc -l <out.csv.partial) - 1))" -ge 5 ]; then break; fi
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.05
done
kill -KILL "$pid" 2>/dev/null || fail "the suite sweep ended before SIGKILL (too fast to test)"
wait "$pid" || true
done_rows=$(($(wc -l <out.csv.partial) - 1))
[ "$done_rows" -ge 5 ] && [ "$done_rows" -lt 240 ] || fail "$done_rows rows in the journal"
cp out.csv.partial kept.partial
cp suite/RSN3_UP.AT2 RSN3_UP.keep
echo >>suite/RSN3_UP.AT2  # the same values, other bytes
run "$FLEXROCK" sweep slow.toml -o out.csv -q
expect_rc 2 "a journal of other suite files"
expect_in "$WORK/err" "a journal of other inputs or another run count"
[ ! -e out.csv ] || fail "a refused resume wrote an output"
cp RSN3_UP.keep suite/RSN3_UP.AT2
cp kept.partial out.csv.partial
run "$FLEXROCK" sweep slow.toml -o out.csv -j 2
expect_rc 0 "resumed suite sweep"
expect_in "$WORK/out" "resuming: $done_rows of 240 runs already in"
cmp ref.csv out.csv || fail "the resumed suite sweep differs from the uninterrupted one"

# two MPI processes write the bytes threads do (where the build has MPI)
if [ -n "${3:-}" ]; then
  run "$3" --allow-run-as-root --oversubscribe -n 2 "$FLEXROCK" sweep suite.toml -o mpi.csv -j 1 -q
  expect_rc 0 "2-process suite sweep"
  cmp j1.csv mpi.csv || fail "the 2-process suite sweep differs from the threaded one"
fi

# bad suites: exit 2, the file, line and key, what was expected, no output
bad() {  # $1: what, $2: expected text; the manifest is bad.toml
  rm -f bad.csv
  run "$FLEXROCK" sweep bad.toml -o bad.csv -q
  expect_rc 2 "$1"
  expect_in "$WORK/err" "$2"
  [ ! -e bad.csv ] || fail "$1: an output file was written"
}
head -6 suite.toml >head.toml
suite() { cat head.toml - >bad.toml <<<"$1
[scales]
factors = [1.0]"; }

suite '[[suite]]
horizontal = "suite/*_H9.AT2"'
bad "glob without a match" "bad.toml:8: key 'suite.horizontal': the pattern \"suite/*_H9.AT2\" matches no file"
suite '[[suite]]
horizontal = "nodir/*_H1.AT2"'
bad "missing directory" "bad.toml:8: key 'suite.horizontal': expected an existing directory"
suite '[[suite]]
horizontal = "su*/*_H1.AT2"'
bad "wildcard in a directory" "key 'suite.horizontal': expected wildcards ('*', '?') in the file name only"

mkdir -p unpaired mistimed
cp suite/* unpaired/
rm unpaired/RSN3_UP.AT2
suite '[[suite]]
horizontal = "unpaired/*_H1.AT2"
vertical = "unpaired/*_UP.AT2"'
bad "horizontal without a vertical" "bad.toml:9: key 'suite.vertical': the horizontal record unpaired/RSN3_H1.AT2 has no vertical one"
cp suite/RSN2_UP.AT2 unpaired/RSN4_UP.AT2
rm unpaired/RSN3_H1.AT2
bad "vertical without a horizontal" "key 'suite.horizontal': the vertical record unpaired/RSN4_UP.AT2 has no horizontal one"
suite '[[suite]]
horizontal = "suite/*_H?.AT2"
vertical = "suite/*_UP.AT2"'
bad "a glob that cannot pair" "key 'suite.horizontal': expected exactly one '*' (and no '?')"
suite '[[suite]]
horizontal = "suite/*.AT2"
vertical = "suite/*_UP.AT2"'
bad "a file in both components" "bad.toml:9: key 'suite.vertical': the file suite/RSN1_UP.AT2 is both a horizontal and a vertical component"
suite '[[suite]]
horizontal = ["suite/RSN1_H1.AT2", "suite/RSN2_H1.AT2"]
vertical = ["suite/RSN1_UP.AT2"]'
bad "lists of different lengths" "bad.toml:9: key 'suite.vertical': expected as many vertical files as horizontal ones (2), got 1"
suite '[[suite]]
horizontal = ["suite/RSN1_H1.AT2"]
vertical = "suite/*_UP.AT2"'
bad "a list with a glob" "key 'suite.vertical': expected 'horizontal' and 'vertical' both globs or both arrays"
suite '[[suite]]
horizontal = ["suite/RSN1_H1.AT2", "suite/RSN9_H1.AT2"]'
bad "a listed file that does not exist" "(record matched by key 'suite.horizontal' at bad.toml:8)"
suite '[[suite]]
horizontal = ["suite/RSN1_H1.AT2", "suite/RSN1_H1.AT2"]'
bad "a file twice" "key 'suite.horizontal': expected unique record names, got \"RSN1_H1\" twice"
suite '[[suite]]
horizontal = "suite/*_H1.AT2"
verticle = "suite/*_UP.AT2"'
bad "a misspelt key" "verticle"

# a vertical on another time grid is refused, not resampled: dt 0.02 s for the same samples
cp suite/*_H1.AT2 suite/RSN1_UP.AT2 suite/RSN2_UP.AT2 mistimed/
sed '4s/.*/NPTS= 300, DT= 0.0200 SEC/' suite/RSN3_UP.AT2 >mistimed/RSN3_UP.AT2
suite '[[suite]]
horizontal = "mistimed/*_H1.AT2"
vertical = "mistimed/*_UP.AT2"'
bad "a vertical with another dt" "bad.toml:9: key 'suite.vertical': expected the vertical record mistimed/RSN3_UP.AT2 on the time grid of its horizontal mistimed/RSN3_H1.AT2 (300 samples, dt 0.01 s), got 300 samples, dt 0.02 s"
# and one with fewer samples
head -50 suite/RSN3_UP.AT2 | sed '4s/.*/NPTS= 230, DT= 0.0100 SEC/' >mistimed/RSN3_UP.AT2
bad "a shorter vertical" "got 230 samples, dt 0.01 s"

# neither [[record]] nor [[suite]]
printf '[[body]]\nfile = "%s/examples/studies/slender_block.toml"\n[scales]\nfactors = [1.0]\n' "$SRC" >bad.toml
bad "no records" "[[record]]: missing; expected a record"
echo "ok"
