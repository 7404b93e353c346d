#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# flexrock spectrum is resumable: interrupted by SIGINT and killed by SIGKILL among its cells, and
# stopped by SIGTERM in the middle of its bisection, the same command continues from the journal
# with another thread count, and the final files equal an uninterrupted run byte for byte. A
# tolerance below the minimum is refused before anything runs; a second spectrum on the same
# output is refused while the first runs.
source "$(dirname "$0")/common.sh"

DATA="$SRC/../shared/data"
[ -f "$DATA/elcentro_1940_ns.dat" ] || DATA="$SRC/tests/data"
[ -f "$DATA/elcentro_1940_ns.dat" ] || fail "no El Centro record in $DATA"
cat >"$WORK/block.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
TOML
# 30 slow cells (a small max_step: a friction limit far above any demand keeps the rocking
# series on sampled steps, which max_step caps), then a long bisection (the narrowest tolerance
# allowed: about 40 runs), so that signals arrive mid-way
cat >"$WORK/s.toml" <<TOML
body = "block.toml"
[spectrum]
record = { file = "$DATA/elcentro_1940_ns.dat", format = "single_column", dt = 0.02, units = "g", name = "elcentro" }
scales = { start = 0.2, stop = 6.0, step = 0.2 }
free_periods = 1
bisection_tolerance = 1e-12
[solver]
max_step = 0.0005
friction_coefficient = 100.0
TOML
cells=30

run "$FLEXROCK" spectrum "$WORK/s.toml" -o "$WORK/ref.csv" -j 2 -q
expect_rc 0 "uninterrupted spectrum"
[ "$(wc -l <"$WORK/ref.csv")" -eq $((cells + 1)) ] || fail "expected $cells cells + header"
[ "$(wc -l <"$WORK/ref.boundary.csv")" -eq 2 ] || fail "expected one boundary row + header"
grep -q ",found," "$WORK/ref.boundary.csv" || fail "no bisected boundary: $(cat "$WORK/ref.boundary.csv")"
[ ! -e "$WORK/ref.csv.partial" ] || fail "the journal of a finished spectrum was not removed"

# waits until the journal holds at least $1 lines after its header (or the spectrum ended)
wait_lines() {
  for _ in $(seq 1 1200); do
    if [ -f "$WORK/out.csv.partial" ] && [ "$(($(wc -l <"$WORK/out.csv.partial") - 1))" -ge "$1" ]; then
      return 0
    fi
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.05
  done
}

# INT and KILL among the cells; TERM once every cell is journaled, while the bisection runs
for sig in INT KILL TERM; do
  rm -f "$WORK/out.csv" "$WORK/out.boundary.csv" "$WORK/out.csv.partial"
  "$FLEXROCK" spectrum "$WORK/s.toml" -o "$WORK/out.csv" -j 1 -q >"$WORK/out" 2>"$WORK/err" &
  pid=$!
  if [ "$sig" = TERM ]; then wait_lines "$cells"; else wait_lines 5; fi
  sent=$(date +%s)
  kill -"$sig" "$pid" 2>/dev/null || fail "the spectrum ended before SIG$sig (too fast to test)"
  set +e
  wait "$pid"
  rc=$?
  set -e
  # a stop request is seen between runs: the one under way finishes, no more
  [ $(($(date +%s) - sent)) -le 30 ] || fail "SIG$sig took $(($(date +%s) - sent)) s to stop the spectrum"
  [ ! -e "$WORK/out.csv" ] || fail "SIG$sig: an interrupted spectrum wrote the cells"
  [ ! -e "$WORK/out.boundary.csv" ] || fail "SIG$sig: an interrupted spectrum wrote the boundary"
  [ -f "$WORK/out.csv.partial" ] || fail "SIG$sig: no journal"
  done_lines=$(($(wc -l <"$WORK/out.csv.partial") - 1))
  if [ "$sig" = TERM ]; then
    [ "$done_lines" -eq "$cells" ] || fail "SIGTERM: $done_lines lines in the journal, expected the $cells cells"
  else
    [ "$done_lines" -ge 5 ] && [ "$done_lines" -lt "$cells" ] || fail "SIG$sig: $done_lines lines in the journal"
  fi
  if [ "$sig" != KILL ]; then
    [ "$rc" -eq 1 ] || fail "SIG$sig: exit code $rc, expected 1"
    expect_in "$WORK/err" "interrupted: finished cells are kept in $WORK/out.csv.partial"
    [ "$(tail -c 1 "$WORK/out.csv.partial" | od -An -c | tr -d ' ')" = '\n' ] || fail "torn journal"
  else
    # a torn last line, as a kill in the middle of a write leaves it
    printf '29 0123456789abcdef 29,0,half a li' >>"$WORK/out.csv.partial"
  fi
  run "$FLEXROCK" spectrum "$WORK/s.toml" -o "$WORK/out.csv" -j 3
  expect_rc 0 "resumed spectrum after SIG$sig"
  expect_in "$WORK/out" "resuming: $done_lines of $((cells + 1)) cells and boundaries already in"
  cmp "$WORK/ref.csv" "$WORK/out.csv" || fail "SIG$sig: the resumed cells differ from the uninterrupted ones"
  cmp "$WORK/ref.boundary.csv" "$WORK/out.boundary.csv" || fail "SIG$sig: the resumed boundary differs"
  [ ! -e "$WORK/out.csv.partial" ] || fail "the journal was not removed"
done

# a second spectrum on the same output while the first runs: refused, the first unharmed
rm -f "$WORK/out.csv" "$WORK/out.boundary.csv" "$WORK/out.csv.partial"
"$FLEXROCK" spectrum "$WORK/s.toml" -o "$WORK/out.csv" -j 1 -q >/dev/null 2>&1 &
pid=$!
wait_lines 1
run "$FLEXROCK" spectrum "$WORK/s.toml" -o "$WORK/out.csv" -j 1 -q
expect_rc 2 "a second spectrum on the same output"
expect_in "$WORK/err" "another flexrock process is running with this spectrum journal"
wait "$pid" || fail "the first spectrum failed beside a refused second one"
cmp "$WORK/ref.csv" "$WORK/out.csv" || fail "the first spectrum's cells were changed"

# a changed value in the middle of the journal is refused, with its line
rm -f "$WORK/out.csv" "$WORK/out.boundary.csv"
"$FLEXROCK" spectrum "$WORK/s.toml" -o "$WORK/out.csv" -j 1 -q >/dev/null 2>&1 &
pid=$!
wait_lines 4
kill -INT "$pid"
wait "$pid" || true
sed -i '3s/$/0/' "$WORK/out.csv.partial"
run "$FLEXROCK" spectrum "$WORK/s.toml" -o "$WORK/out.csv"
expect_rc 2 "a corrupt journal"
expect_in "$WORK/err" "$WORK/out.csv.partial:3: corrupt spectrum journal line"
[ ! -e "$WORK/out.csv" ] || fail "a refused spectrum wrote an output"
# deleting the line recomputes that cell only: the same bytes again
sed -i '3d' "$WORK/out.csv.partial"
run "$FLEXROCK" spectrum "$WORK/s.toml" -o "$WORK/out.csv" -j 2 -q
expect_rc 0 "the journal without its corrupt line"
cmp "$WORK/ref.csv" "$WORK/out.csv" || fail "the cells differ after a corrupt line was deleted"

# a bisection tolerance below the minimum once looped forever: refused, with the key, no journal
sed 's/bisection_tolerance = 1e-12/bisection_tolerance = 1e-16/' "$WORK/s.toml" >"$WORK/tiny.toml"
run "$FLEXROCK" spectrum "$WORK/tiny.toml" -o "$WORK/tiny.csv"
expect_rc 2 "bisection_tolerance = 1e-16"
expect_in "$WORK/err" "key 'spectrum.bisection_tolerance': expected a number in [1e-12, 1)"
[ ! -e "$WORK/tiny.csv.partial" ] || fail "a refused spectrum left a journal"
echo "ok"
