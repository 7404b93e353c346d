#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# a sweep with uncertain parameters writes the same file, byte for byte, with 1 and 2 threads,
# with 2 MPI processes (when an mpiexec is given as $3) and after a SIGKILL and a resume; its
# sampled columns follow the manifest's seed, method and scope; bad [[uncertain]] and [sampling]
# tables are refused with file, line and key, exit 2, and no output
source "$(dirname "$0")/common.sh"
MPIEXEC="${3:-}"

DATA="$SRC/../shared/data"
[ -f "$DATA/elcentro_1940_ns.dat" ] || DATA="$SRC/tests/data"
[ -f "$DATA/elcentro_1940_ns.dat" ] || fail "no El Centro record in $DATA"
cat >"$WORK/tank.toml" <<'TOML'
[body]
type = "oscillator_on_slab"
top_mass = 800.0
frequency_hz = 2.0
base_mass = 400.0
height = 2.0
base_width = 1.0
damping_ratio = 0.02
TOML
# 40 slow runs (a small max_step, or $2), so that a kill arrives mid-way; every kind of body
# parameter and friction, a Latin hypercube
manifest() {
  cat <<TOML
free_periods = 1
[[body]]
file = "tank.toml"
[[record]]
name = "elcentro"
file = "$DATA/elcentro_1940_ns.dat"
format = "single_column"
dt = 0.02
units = "g"
[scales]
factors = { start = 0.5, stop = 4.4, step = 0.1 }
[solver]
max_step = ${2:-0.001}
[[uncertain]]
parameter = "friction"
distribution = "lognormal"
median = 0.7
beta = 0.2
[[uncertain]]
parameter = "frequency_scale"
distribution = "normal"
mean = 1.0
standard_deviation = 0.1
lower = 0.7
upper = 1.3
[[uncertain]]
parameter = "damping_ratio"
distribution = "uniform"
minimum = 0.01
maximum = 0.05
[[uncertain]]
parameter = "mass_scale"
distribution = "normal"
mean = 1.0
standard_deviation = 0.05
lower = 0.8
[[uncertain]]
parameter = "size_scale"
distribution = "lognormal"
median = 1.0
beta = 0.03
$1
TOML
}
manifest '[sampling]
seed = 7
method = "lhs"' >"$WORK/m.toml"

run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/j1.csv" -j 1 -q
expect_rc 0 "1-thread sweep"
[ "$(wc -l <"$WORK/j1.csv")" -eq 41 ] || fail "expected 40 rows + header"
expect_in "$WORK/j1.csv" "pgv_m_per_s,friction_coefficient,frequency_scale,damping_ratio,mass_scale,size_scale,duration_s"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/j2.csv" -j 2 -q
expect_rc 0 "2-thread sweep"
cmp "$WORK/j1.csv" "$WORK/j2.csv" || fail "1 and 2 threads differ"

# the Latin hypercube: 40 runs, 40 strata of the damping ratio's uniform [0.01, 0.05], one each
python3 - "$WORK/j1.csv" <<'PY' || fail "the damping ratios are not one per stratum"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
strata = sorted(int((float(r["damping_ratio"]) - 0.01) / 0.04 * 40) for r in rows)
assert strata == list(range(40)), strata
# every run its own draw: 40 different frictions, all > 0; truncations held
assert len({r["friction_coefficient"] for r in rows}) == 40
assert all(0.7 <= float(r["frequency_scale"]) <= 1.3 for r in rows)
assert all(float(r["mass_scale"]) >= 0.8 for r in rows)
PY

if [ -n "$MPIEXEC" ]; then
  run "$MPIEXEC" --allow-run-as-root --oversubscribe -n 2 "$FLEXROCK" sweep "$WORK/m.toml" \
    -o "$WORK/mpi.csv" -j 1 -q
  expect_rc 0 "2-process sweep"
  cmp "$WORK/j1.csv" "$WORK/mpi.csv" || fail "2 MPI processes differ from threads"
fi

# killed mid-way, resumed: the same file
"$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv" -j 1 -q >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 600); do
  if [ -f "$WORK/out.csv.partial" ] && [ "$(($(wc -l <"$WORK/out.csv.partial") - 1))" -ge 5 ]; then
    break
  fi
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.05
done
kill -KILL "$pid" 2>/dev/null || fail "the sweep ended before SIGKILL (too fast to test)"
wait "$pid" 2>/dev/null || true
[ ! -e "$WORK/out.csv" ] || fail "a killed sweep wrote the final file"
done_rows=$(($(wc -l <"$WORK/out.csv.partial") - 1))
[ "$done_rows" -ge 5 ] && [ "$done_rows" -lt 40 ] || fail "$done_rows rows in the journal"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/out.csv" -j 2
expect_rc 0 "resumed sweep"
expect_in "$WORK/out" "resuming: $done_rows of 40 runs already in"
cmp "$WORK/j1.csv" "$WORK/out.csv" || fail "the resumed sweep differs"

# another seed, other values; plain random draws; one realisation per record at every level (these
# check the sampled columns only, so they run at the default max_step)
# the five sampled columns (friction .. size_scale) of a sweep's rows, one line a run
sampled() { cut -d, -f10-14 "$1" | tail -n +2; }
manifest '[sampling]
seed = 8
method = "lhs"' 0.01 >"$WORK/seed8.toml"
run "$FLEXROCK" sweep "$WORK/seed8.toml" -o "$WORK/seed8.csv" -j 2 -q
expect_rc 0 "seed 8"
[ "$(sampled "$WORK/seed8.csv" | sort -u | wc -l)" -eq 40 ] ||
  fail "seed 8: expected 40 different realisations"
cmp -s <(sampled "$WORK/j1.csv") <(sampled "$WORK/seed8.csv") &&
  fail "seeds 7 and 8 drew the same values"
manifest '[sampling]
seed = 7
per = "record"' 0.01 >"$WORK/per.toml"
run "$FLEXROCK" sweep "$WORK/per.toml" -o "$WORK/per.csv" -j 2 -q
expect_rc 0 "per record"
[ "$(sampled "$WORK/per.csv" | sort -u | wc -l)" -eq 1 ] ||
  fail "per = \"record\": expected one realisation for the one record"
# no [sampling]: seed 0, random
manifest '' 0.01 >"$WORK/plain.toml"
run "$FLEXROCK" sweep "$WORK/plain.toml" -o "$WORK/plain.csv" -j 2 -q
expect_rc 0 "default sampling"

# a rigid block: its base width and c.g. height
cat >"$WORK/rigid.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
TOML
cat >"$WORK/geometry.toml" <<TOML
[[body]]
file = "rigid.toml"
[[record]]
file = "$DATA/elcentro_1940_ns.dat"
format = "single_column"
dt = 0.02
units = "g"
[scales]
target_pga = [0.1, 0.2, 0.3, 0.4]
[[uncertain]]
parameter = "base_width_scale"
distribution = "uniform"
minimum = 0.8
maximum = 1.2
[[uncertain]]
parameter = "cg_height_scale"
distribution = "normal"
mean = 1.0
standard_deviation = 0.1
lower = 0.7
upper = 1.3
TOML
run "$FLEXROCK" sweep "$WORK/geometry.toml" -o "$WORK/g1.csv" -j 1 -q
expect_rc 0 "geometry, 1 thread"
expect_in "$WORK/g1.csv" "pgv_m_per_s,base_width_scale,cg_height_scale,duration_s"
run "$FLEXROCK" sweep "$WORK/geometry.toml" -o "$WORK/g2.csv" -j 2 -q
cmp "$WORK/g1.csv" "$WORK/g2.csv" || fail "geometry: 1 and 2 threads differ"

# bad input: exit 2, file:line: key, what is right, no output
bad() {  # $1 file name, $2.. fragments expected in the message
  local f="$1"
  shift
  run "$FLEXROCK" sweep "$WORK/$f" -o "$WORK/bad.csv" -q
  expect_rc 2 "$f"
  for part in "$@"; do expect_in "$WORK/err" "$part"; done
  [ ! -e "$WORK/bad.csv" ] && [ ! -e "$WORK/bad.csv.partial" ] || fail "$f: a refused sweep wrote output"
}
base() {
  cat <<TOML
[[body]]
file = "tank.toml"
[[record]]
file = "$DATA/elcentro_1940_ns.dat"
format = "single_column"
dt = 0.02
units = "g"
[scales]
factors = [1.0]
$1
TOML
}
base '[[uncertain]]
parameter = "friction"
distribution = "normal"
mean = 0.5
standard_deviation = 0.1' >"$WORK/b1.toml"
bad b1.toml "b1.toml:12: key 'uncertain.distribution'" "must be > 0" "give a lower bound"
base '[[uncertain]]
parameter = "fricton"
distribution = "uniform"
minimum = 0.3
maximum = 0.6' >"$WORK/b2.toml"
bad b2.toml "b2.toml:11: key 'uncertain.parameter'" 'did you mean "friction"'
base '[[uncertain]]
parameter = "friction"
distribution = "uniform"
minimum = 0.3
maximum = 0.6
lower = 0.4' >"$WORK/b3.toml"
bad b3.toml "b3.toml:15: key 'uncertain.lower'" "unknown key for a uniform distribution"
base '[[uncertain]]
parameter = "size_scale"
distribution = "uniform"
minimum = 1.2
maximum = 0.8' >"$WORK/b4.toml"
bad b4.toml "b4.toml:14: key 'uncertain.maximum'" "expected a number > minimum"
base '[sampling]
seed = 3' >"$WORK/b5.toml"
bad b5.toml "key 'sampling'" "only with [[uncertain]]"
base '[[uncertain]]
parameter = "restitution_ratio"
distribution = "uniform"
minimum = 0.5
maximum = 0.9' >"$WORK/b6.toml"
bad b6.toml "b6.toml:11: key 'uncertain.parameter'" 'impact_law = "restitution"'
base '[[uncertain]]
parameter = "mass_scale"
distribution = "lognormal"
median = 1.0
beta = 0.1
[sampling]
method = "lhc"' >"$WORK/b7.toml"
bad b7.toml "key 'sampling.method'" 'did you mean "lhs"'
base '[[uncertain]]
parameter = "mass_scale"
distribution = "lognormal"
median = 1.0
beta = 0.1
[sampling]
seed = -1' >"$WORK/b8.toml"
bad b8.toml "b8.toml:16: key 'sampling.seed'" "an integer >= 0"
cat >"$WORK/block.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
TOML
sed 's/tank.toml/block.toml/' "$WORK/m.toml" >"$WORK/b9.toml"
bad b9.toml "b9.toml:" "key 'uncertain.parameter'" "body 'block'" "the body is rigid"
base '[[uncertain]]
parameter = "size_scale"
distribution = "normal"
mean = 1.0
standard_deviation = 0.01
lower = 1.5' >"$WORK/b10.toml"
bad b10.toml "b10.toml:15: key 'uncertain.lower'" "keeps a probability of"
base '[[uncertain]]
parameter = "size_scale"
distribution = "uniform"
minimum = 0.9
maximum = 1.1
[[uncertain]]
parameter = "size_scale"
distribution = "uniform"
minimum = 0.8
maximum = 1.2' >"$WORK/b11.toml"
bad b11.toml "b11.toml:16: key 'uncertain.parameter'" "given twice"
echo "ok"
