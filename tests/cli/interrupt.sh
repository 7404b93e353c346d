#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Ctrl-C (SIGINT) or SIGTERM during `flexrock run`: during the simulation nothing is written; during
# the writing of the outputs the temporary is removed, and what is on disk is complete or absent
source "$(dirname "$0")/common.sh"
# job control: without it a non-interactive shell starts background commands with SIGINT ignored
set -m

# no file of the name pattern "*.tmp.*" under the directory
expect_no_temporaries() {
  local left
  left="$(find "$1" -name '*.tmp.*' 2>/dev/null || true)"
  [ -z "$left" ] || fail "temporary files left: $left"
}

# a body rocking forever (elastic impacts, no damping, no motion): killed mid-run. Its free
# rocking is in closed form, about a microsecond an impact, so the record is long enough for the
# impact limit (1e7) to be the end: about 10 s here, well after the signal
cat >"$WORK/endless.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
[excitation.horizontal]
type = "none"
duration = 1e12
[initial]
theta = 0.1
[solver]
impact_law = "restitution"
restitution_ratio = 1.0
[output]
dt = 0
TOML
for sig in INT TERM; do
  mkdir -p "$WORK/run_$sig"
  "$FLEXROCK" run -q -o "$WORK/run_$sig" "$WORK/endless.toml" >/dev/null 2>&1 &
  pid=$!
  sleep 1
  kill -0 "$pid" 2>/dev/null || fail "the endless run ended by itself"
  kill -s "$sig" "$pid"
  set +e
  wait "$pid"
  rc=$?
  set -e
  [ "$rc" -gt 128 ] || fail "SIG$sig mid-run: exit code $rc, expected death by the signal"
  [ -z "$(ls -A "$WORK/run_$sig")" ] || fail "SIG$sig mid-run left files: $(ls "$WORK/run_$sig")"
done

# a quick run with a long time history (400001 rows): killed while the CSV is being written
cat >"$WORK/long.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
[excitation.horizontal]
type = "none"
duration = 200.0
[output]
dt = 0.0005
events = "long.events.csv"
TOML
rows=400001
caught=0
for attempt in 1 2 3 4 5; do
  out="$WORK/write_$attempt"
  mkdir -p "$out"
  "$FLEXROCK" run -q -o "$out" "$WORK/long.toml" >/dev/null 2>&1 &
  pid=$!
  # wait for the temporary of the time history to appear, then interrupt
  for _ in $(seq 1 3000); do
    if [ -n "$(find "$out" -name 'long.csv.tmp.*' 2>/dev/null)" ]; then break; fi
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
  done
  kill -s INT "$pid" 2>/dev/null || true
  set +e
  wait "$pid"
  rc=$?
  set -e
  expect_no_temporaries "$out"
  if [ "$rc" -gt 128 ]; then
    caught=1
    # the summary is written last: it must not exist; a time history, if renamed, is complete
    [ ! -e "$out/long.summary.json" ] || fail "summary written by an interrupted run"
    if [ -e "$out/long.csv" ]; then
      [ "$(wc -l <"$out/long.csv")" -eq $((rows + 1)) ] || fail "partial time history on disk"
    fi
    break
  fi
  [ "$rc" -eq 0 ] || fail "exit code $rc"
done
[ "$caught" -eq 1 ] || fail "could not interrupt a run while it wrote its outputs (5 tries)"

# uninterrupted, the same case writes the whole set
run "$FLEXROCK" run -q -o "$WORK/whole" "$WORK/long.toml"
expect_rc 0 "uninterrupted run"
[ "$(wc -l <"$WORK/whole/long.csv")" -eq $((rows + 1)) ] || fail "time history rows"
[ -f "$WORK/whole/long.summary.json" ] || fail "no summary"
expect_no_temporaries "$WORK/whole"
echo "interrupt: ok"
