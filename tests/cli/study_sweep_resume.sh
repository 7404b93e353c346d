# SPDX-License-Identifier: BSD-3-Clause
# flexrock sweep is resumable: interrupted by SIGINT and killed by SIGKILL mid-way, the same
# command continues from the journal, and the final file equals an uninterrupted run byte for
# byte. A journal of another manifest, of the previous format or with a damaged line is refused;
# a second sweep on the same output is refused while the first runs; options no run could use
# are refused before any journal exists.
source "$(dirname "$0")/common.sh"

DATA="$SRC/../shared/data"
[ -f "$DATA/elcentro_1940_ns.dat" ] || DATA="$SRC/tests/data"
cat >"$WORK/block.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
TOML
# 60 slow runs (a small max_step: a friction limit far above any demand keeps the rocking series
# on sampled steps, which max_step caps), so that a signal arrives mid-way
cat >"$WORK/m.toml" <<TOML
free_periods = 1
[[body]]
file = "block.toml"
[[record]]
name = "elcentro"
file = "$DATA/elcentro_1940_ns.dat"
format = "single_column"
dt = 0.02
units = "g"
[scales]
factors = { start = 0.1, stop = 6.0, step = 0.1 }
[solver]
max_step = 0.0005
friction_coefficient = 100.0
TOML
[ -f "$DATA/elcentro_1940_ns.dat" ] || fail "no El Centro record in $DATA"

run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/ref.csv" -j 2 -q
expect_rc 0 "uninterrupted sweep"
[ "$(wc -l <"$WORK/ref.csv")" -eq 61 ] || fail "expected 60 rows + header"

# waits until the journal holds at least $1 finished rows (or the sweep ended)
wait_rows() {
  for _ in $(seq 1 600); do
    if [ -f "$WORK/out.csv.partial" ] && [ "$(($(wc -l <"$WORK/out.csv.partial") - 1))" -ge "$1" ]; then
      return 0
    fi
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.05
  done
}

for sig in INT KILL; do
  rm -f "$WORK/out.csv" "$WORK/out.csv.partial"
  "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv" -j 1 -q >"$WORK/out" 2>"$WORK/err" &
  pid=$!
  wait_rows 5
  kill -"$sig" "$pid" 2>/dev/null || fail "the sweep ended before SIG$sig (too fast to test)"
  set +e
  wait "$pid"
  rc=$?
  set -e
  [ ! -e "$WORK/out.csv" ] || fail "SIG$sig: an interrupted sweep wrote the final file"
  [ -f "$WORK/out.csv.partial" ] || fail "SIG$sig: no journal"
  done_rows=$(($(wc -l <"$WORK/out.csv.partial") - 1))
  [ "$done_rows" -ge 5 ] && [ "$done_rows" -lt 60 ] || fail "SIG$sig: $done_rows rows in the journal"
  if [ "$sig" = INT ]; then
    [ "$rc" -eq 1 ] || fail "SIGINT: exit code $rc, expected 1"
    expect_in "$WORK/err" "interrupted: finished runs are kept in $WORK/out.csv.partial"
    # every line is whole after a SIGINT
    [ "$(tail -c 1 "$WORK/out.csv.partial" | od -An -c | tr -d ' ')" = '\n' ] || fail "torn journal"
  fi
  # a torn last line, as a kill in the middle of a write leaves it
  [ "$sig" = KILL ] && printf '59,half a li' >>"$WORK/out.csv.partial"
  run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv" -j 2
  expect_rc 0 "resumed sweep after SIG$sig"
  expect_in "$WORK/out" "resuming: $done_rows of 60 runs already in"
  cmp "$WORK/ref.csv" "$WORK/out.csv" || fail "SIG$sig: the resumed sweep differs from the uninterrupted one"
  [ ! -e "$WORK/out.csv.partial" ] || fail "the journal was not removed"
done

# a journal of another manifest (or another run count) is an error, not a mix
printf '# flexrock sweep journal v3 inputs=0000000000000001 runs=60\n0 0123456789abcdef 0,x\n' \
  >"$WORK/mix.csv.partial"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/mix.csv"
expect_rc 2 "foreign journal"
expect_in "$WORK/err" "a journal of other inputs or another run count"
[ ! -e "$WORK/mix.csv" ] || fail "a refused sweep wrote an output"
# a journal of the previous format, without checksums: refused, saying what to do
printf '# flexrock sweep journal v2 manifest=0000000000000001 runs=60\n0%s\n' "$(printf ',%.0s' $(seq 23))" \
  >"$WORK/mix.csv.partial"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/mix.csv"
expect_rc 2 "v1 journal"
expect_in "$WORK/err" "no checksums and cannot be checked: delete it to compute its runs again"

# a changed value in a middle line (here the outcome), a NUL, a duplicated run with another
# result: each refused with its line, nothing written; without the line the run is computed again
rm -f "$WORK/out.csv" "$WORK/out.csv.partial"
"$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv" -j 1 -q >/dev/null 2>&1 &
pid=$!
wait_rows 6
kill -INT "$pid"
wait "$pid" || true
cp "$WORK/out.csv.partial" "$WORK/good.partial"
for damage in 's/,no_uplift,0,/,rocking,0,/;t;s/,rocking,0,/,no_uplift,0,/' 's/,elcentro,/,elcentr\x00,/' 's/,0,\([0-9]\)/,1,\1/'; do
  cp "$WORK/good.partial" "$WORK/out.csv.partial"
  sed -i "3{$damage}" "$WORK/out.csv.partial"
  ! cmp -s "$WORK/good.partial" "$WORK/out.csv.partial" || fail "sed '$damage' changed nothing"
  run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv"
  expect_rc 2 "a corrupt journal line ($damage)"
  expect_in "$WORK/err" "$WORK/out.csv.partial:3: corrupt sweep journal line"
  [ ! -e "$WORK/out.csv" ] || fail "a refused sweep wrote an output"
done
# run 2's line again, with another result (a valid checksum would need the tool: a copy of
# another line under run 2's index is caught by the checksum as well)
cp "$WORK/good.partial" "$WORK/out.csv.partial"
sed -n '5p' "$WORK/good.partial" | sed 's/^[0-9]* /2 /' >>"$WORK/out.csv.partial"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv"
expect_rc 2 "a run twice"
expect_in "$WORK/err" "corrupt sweep journal line"
# the damaged line deleted: that run is computed again, and the result is the same
cp "$WORK/good.partial" "$WORK/out.csv.partial"
sed -i '3d' "$WORK/out.csv.partial"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv" -j 2 -q
expect_rc 0 "the journal without a line"
cmp "$WORK/ref.csv" "$WORK/out.csv" || fail "the sweep differs after a journal line was deleted"

# two sweeps on the same output: the second is refused while the first runs; the first's
# result is whole
rm -f "$WORK/out.csv" "$WORK/out.csv.partial"
"$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv" -j 1 -q >/dev/null 2>&1 &
pid=$!
wait_rows 1
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv" -j 1 -q
expect_rc 2 "a second sweep on the same output"
expect_in "$WORK/err" "another flexrock process is running with this sweep journal"
wait "$pid" || fail "the first sweep failed beside a refused second one"
cmp "$WORK/ref.csv" "$WORK/out.csv" || fail "the first sweep's result was changed"

# options that no run could use are refused before the journal exists, naming the key, so the
# corrected manifest runs at once
sed 's/^max_step = 0.0005$/max_step = 0.0005\nevent_samples = 100/' "$WORK/m.toml" >"$WORK/bad.toml"
run "$FLEXROCK" sweep "$WORK/bad.toml" -o "$WORK/bad.csv"
expect_rc 2 "event_samples = 100"
expect_in "$WORK/err" "event_samples"
[ ! -e "$WORK/bad.csv.partial" ] || fail "a refused sweep left a journal"
sed 's/^free_periods = 1$/free_periods = 1e308/' "$WORK/m.toml" >"$WORK/bad.toml"
run "$FLEXROCK" sweep "$WORK/bad.toml" -o "$WORK/bad.csv"
expect_rc 2 "free_periods = 1e308"
expect_in "$WORK/err" "free_periods"
[ ! -e "$WORK/bad.csv.partial" ] || fail "a refused sweep left a journal"
sed 's/^factors = .*$/factors = [1.0, 1e308]/' "$WORK/m.toml" >"$WORK/bad.toml"
run "$FLEXROCK" sweep "$WORK/bad.toml" -o "$WORK/bad.csv"
expect_rc 2 "a scale that overflows"
expect_in "$WORK/err" "overflows"
[ ! -e "$WORK/bad.csv.partial" ] || fail "a refused sweep left a journal"
echo "ok"
