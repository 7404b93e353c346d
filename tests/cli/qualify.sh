#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# flexrock qualify on the shipped cabinet with a small suite: the verdict and the outputs, the
# inputs' SHA-256 against sha256sum, the same bytes for 1 and 2 threads and on regeneration (JSON,
# demand CSV, and with the Python package the HTML and PDF), and bad files refused with file,
# line and key before anything is written
source "$(dirname "$0")/common.sh"

DATA="$SRC/../shared/data"
cat >"$WORK/cab.toml" <<TOML
name = "cabinet (CI)"
body = "$SRC/examples/cases/asymmetric_cabinet.toml"
[ranges]
friction = [0.3, 0.6]
cg_offset_tolerance = 0.02
[[record]]
file = "$DATA/elcentro_1940_ns.dat"
format = "single_column"
dt = 0.02
units = "g"
name = "elcentro"
[[record]]
file = "$DATA/kobe_1995_nishi_akashi_090.AT2"
name = "kobe"
[design]
pga = 0.25
units = "g"
[criteria]
tilt_fraction = 0.5
sliding_clearance = 0.05
impact_force = 2.0e5
uplift = 0.05
[ida]
factors = [1, 2, 4, 8]
tolerance = 0.05
TOML

render=--no-render
[ "${FLEXROCK_TEST_PLOT:-0}" = 1 ] && render=

run "$FLEXROCK" qualify "$WORK/cab.toml" -o "$WORK/a" -j 2 $render
expect_rc 0 "qualify the cabinet"
expect_in "$WORK/out" "cabinet (CI): PASSES every criterion"
for f in cab.qualify.json cab.demands.csv cab.runs/design.csv; do
  [ -s "$WORK/a/$f" ] || fail "$f not written"
done
[ -e "$WORK/a/cab.runs/design.csv.partial" ] && fail "the journal was left behind"
[ "$(json_get "$WORK/a/cab.qualify.json" acceptance.pass)" = true ] || fail "acceptance.pass"
[ "$(json_get "$WORK/a/cab.qualify.json" schema)" = '"flexrock.qualification"' ] || fail "schema"
head -2 "$WORK/a/cab.demands.csv" >"$WORK/head"
printf ',1-ROT-0-1,1-SLD-0-1,1-IMF-0-1,1-UPL-0-1\nUnits,rad,m,N,m\n' | diff - "$WORK/head" ||
  fail "pelicun demand CSV header"
[ "$(wc -l <"$WORK/a/cab.demands.csv")" -eq $((2 + 4 * 2)) ] || fail "one demand row a run"

# every input's SHA-256 as sha256sum computes it
python3 - "$WORK/a/cab.qualify.json" <<'PY' || fail "SHA-256 of the inputs"
import hashlib, json, sys
j = json.load(open(sys.argv[1]))
assert len(j["inputs"]) == 4, j["inputs"]
for i in j["inputs"]:
    data = open(i["path"], "rb").read()
    assert i["sha256"] == hashlib.sha256(data).hexdigest(), i
    assert i["bytes"] == len(data), i
PY

# the same bytes with one thread, and again
run "$FLEXROCK" qualify "$WORK/cab.toml" -o "$WORK/b" -j 1 -q $render
expect_rc 0 "qualify again on one thread"
outs="cab.qualify.json cab.demands.csv"
[ -z "$render" ] && outs="$outs cab.html cab.pdf"
for f in $outs; do
  cmp "$WORK/a/$f" "$WORK/b/$f" || fail "$f differs between two qualifications of the same inputs"
done
if [ -z "$render" ]; then
  expect_in "$WORK/a/cab.html" "data:image/png;base64,"
  head -c 5 "$WORK/a/cab.pdf" | grep -q '%PDF-' || fail "cab.pdf is no PDF"
  grep -q CreationDate "$WORK/a/cab.pdf" && fail "the PDF carries a creation date"
fi

# interrupted by SIGINT once the journal holds a run, then the same command goes on from there
# to the same report
"$FLEXROCK" qualify "$WORK/cab.toml" -o "$WORK/i" -j 1 -q --no-render >"$WORK/i.out" 2>&1 &
pid=$!
for _ in $(seq 1 400); do
  # the journal's header and at least one finished run
  [ -f "$WORK/i/cab.runs/design.csv.partial" ] &&
    [ "$(wc -l <"$WORK/i/cab.runs/design.csv.partial")" -ge 2 ] && break
  sleep 0.01
done
kill -INT "$pid" 2>/dev/null || true
set +e
wait "$pid"
irc=$?
set -e
if [ "$irc" -eq 1 ]; then
  grep -q "interrupted: finished runs are kept in" "$WORK/i.out" || fail "interrupt message"
  [ -e "$WORK/i/cab.qualify.json" ] && fail "an interrupted qualification wrote its report"
  run "$FLEXROCK" qualify "$WORK/cab.toml" -o "$WORK/i" -j 2 --no-render
  expect_rc 0 "resume"
  expect_in "$WORK/out" "resuming:"
  cmp "$WORK/a/cab.qualify.json" "$WORK/i/cab.qualify.json" || fail "the resumed report differs"
else
  [ "$irc" -eq 0 ] || fail "exit code $irc after SIGINT"
  echo "note: the qualification finished before the interrupt; resume not exercised"
fi

# the shipped example (its 10-record suite from ../shared/data): it loads, runs and passes
run "$FLEXROCK" qualify "$SRC/examples/qualify/cabinet.toml" -o "$WORK/ex" -j 2 --no-render
expect_rc 0 "the shipped cabinet example"
expect_in "$WORK/out" "laboratory cabinet: PASSES every criterion"

# bad files: file, line and key, exit 2, nothing written
sed 's/^tilt_fraction = 0.5/tilt_fraction = 1.5/' "$WORK/cab.toml" >"$WORK/bad.toml"
run "$FLEXROCK" qualify "$WORK/bad.toml" -o "$WORK/c"
expect_rc 2 "a tilt fraction above 1"
expect_in "$WORK/err" "bad.toml:19: key 'criteria.tilt_fraction': expected allowed largest tilt"
[ -e "$WORK/c" ] && fail "a refused qualification wrote $WORK/c"
sed 's/^\[design\]/[desing]/' "$WORK/cab.toml" >"$WORK/bad.toml"
run "$FLEXROCK" qualify "$WORK/bad.toml" -o "$WORK/c"
expect_rc 2 "a misspelt table"
expect_in "$WORK/err" "key 'desing': unknown key at the top level"
echo "ok"
