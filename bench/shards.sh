#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Times a 10,000-run sweep (a slender rigid block, b = 0.2 m, h = 1.0 m, under El Centro at
# 10,000 scale factors) run whole on 2 threads, against the same sweep as 4 shards run one after
# another (2 threads each) and 2 at a time (1 thread each), plus `flexrock merge`; checks the
# merged file equals the whole run's byte for byte and prints a markdown table (wall seconds,
# bytes) for docs/studies.md. Builds nothing.
# Usage: bench/shards.sh [FLEXROCK] (default build/release/apps/flexrock); RUNS=1000 for a quick
# look.
set -euo pipefail
cd "$(dirname "$0")/.."
FLEXROCK="$(realpath "${1:-build/release/apps/flexrock}")"
RUNS="${RUNS:-10000}"
[ -x "$FLEXROCK" ] || { echo "shards.sh: no flexrock binary at $FLEXROCK" >&2; exit 2; }
SRC="$(pwd)"
DATA="$SRC/../shared/data"
[ -f "$DATA/elcentro_1940_ns.dat" ] || DATA="$SRC/tests/data"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/flexrock_shards.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"
cat >block.toml <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
TOML
cat >m.toml <<TOML
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
factors = { start = 0.001, stop = 10.0, count = $RUNS }
TOML

# wall, user and system seconds of a command (bash's time), as "wall cpu"
TIMEFORMAT='%R %U %S'
timed() {
  local t
  t=$({ time "$@" >/dev/null; } 2>&1 | tail -n 1)
  python3 -c "import sys; r,u,s=map(float,sys.argv[1:]); print(f'{r:.2f} {u+s:.2f}')" $t
}
add() { python3 -c "import sys; print(f'{float(sys.argv[1]) + float(sys.argv[2]):.2f}')" "$1" "$2"; }

load=$(cut -d' ' -f1-3 /proc/loadavg)
read -r whole whole_cpu < <(timed "$FLEXROCK" sweep m.toml -o whole.csv -j 2 -q)

# 4 shards one after another, each on both cores
seq_shards() { for k in 1 2 3 4; do "$FLEXROCK" sweep m.toml -o seq.csv --shard "$k/4" -j 2 -q; done; }
read -r seq_run seq_cpu < <(timed seq_shards)
shard_bytes=$(cat seq.csv.shard*of4 | wc -c)
read -r seq_merge seq_merge_cpu < <(timed "$FLEXROCK" merge -q seq.csv.shard1of4 seq.csv.shard2of4 \
  seq.csv.shard3of4 seq.csv.shard4of4)
cmp whole.csv seq.csv

# 4 shards, 2 at a time, each on one core
par_shards() {
  printf '%s\n' 1 2 3 4 | xargs -P 2 -I{} "$FLEXROCK" sweep m.toml -o par.csv --shard {}/4 -j 1 -q
}
read -r par_run par_cpu < <(timed par_shards)
read -r par_merge par_merge_cpu < <(timed "$FLEXROCK" merge -q par.csv.shard1of4 par.csv.shard2of4 \
  par.csv.shard3of4 par.csv.shard4of4)
cmp whole.csv par.csv

csv_bytes=$(wc -c <whole.csv)
echo "load average at the start: $load on $(nproc) cores (other work shares them: compare CPU)"
echo
echo "| ${RUNS}-run sweep | runs: wall [s] | runs: CPU [s] | merge: wall [s] | total wall [s] | bytes |"
echo "|---|---|---|---|---|---|"
echo "| one process, 2 threads | $whole | $whole_cpu | - | $whole | CSV $csv_bytes |"
echo "| 4 shards one after another, 2 threads each | $seq_run | $seq_cpu | $seq_merge | $(add "$seq_run" "$seq_merge") | 4 shard files $shard_bytes in all; merged CSV $(wc -c <seq.csv), identical |"
echo "| 4 shards 2 at a time, 1 thread each | $par_run | $par_cpu | $par_merge | $(add "$par_run" "$par_merge") | merged CSV $(wc -c <par.csv), identical |"
