# SPDX-License-Identifier: BSD-3-Clause
# flexrock sweep is resumable: interrupted by SIGINT and killed by SIGKILL mid-way, the same
# command continues from the journal, and the final file equals an uninterrupted run byte for
# byte. A journal of another manifest is refused.
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
# 60 slow runs (a small max_step), so that a signal arrives mid-way
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
printf '# flexrock sweep journal v2 manifest=0000000000000001 runs=60\n0%s\n' "$(printf ',%.0s' $(seq 23))" \
  >"$WORK/mix.csv.partial"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/mix.csv"
expect_rc 2 "foreign journal"
expect_in "$WORK/err" "a sweep journal of another manifest or run count"
[ ! -e "$WORK/mix.csv" ] || fail "a refused sweep wrote an output"
echo "ok"
