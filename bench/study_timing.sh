#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Times `flexrock spectrum` on a GRID x GRID one-sine-pulse grid (default 256 x 256 = 65,536
# runs plus the bisection's) for (a) a slender rigid block, b = 0.2 m, h = 1.0 m (alpha = atan
# 0.2), and (b) an oscillator on a rocking base (examples/studies/oscillator_on_slab.toml), with
# 1 and 2 threads and, if the binary has MPI, 1 and 2 processes (rigid block). Prints a markdown
# section for docs/performance.md. Builds nothing.
# Usage: bench/study_timing.sh [FLEXROCK] (default build/release/apps/flexrock); GRID=64 for a
# quick look.
set -euo pipefail
cd "$(dirname "$0")/.."
FLEXROCK="$(realpath "${1:-build/release/apps/flexrock}")"
GRID="${GRID:-256}"
[ -x "$FLEXROCK" ] || { echo "study_timing.sh: no flexrock binary at $FLEXROCK" >&2; exit 2; }
SRC="$(pwd)"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/flexrock_study_timing.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

cat >"$WORK/block.toml" <<TOML
name = "slender rigid block, b = 0.2 m, h = 1.0 m"
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
[spectrum]
pulse = "one_sine"
amplitudes = { start = 0.5, stop = 8.0, count = $GRID }   # a_p / (g tan alpha)
frequencies = { start = 1.0, stop = 16.0, count = $GRID } # omega_p / p
TOML
cat >"$WORK/oscillator.toml" <<TOML
name = "oscillator on a rocking base"
body = "$SRC/examples/studies/oscillator_on_slab.toml"
[spectrum]
pulse = "one_sine"
amplitudes = { start = 0.5, stop = 8.0, count = $GRID }
frequencies = { start = 1.0, stop = 16.0, count = $GRID }
TOML

has_mpi=no
if command -v mpirun >/dev/null && ldd "$FLEXROCK" | grep -q libmpi; then has_mpi=yes; fi

rows=()
ref_block=""
# measure LABEL CORES SPEC THREADS [LAUNCHER...]: wall and CPU seconds (this shell's waited-for
# children), runs (cells + bisection)
measure() {
  local label="$1" cores="$2" spec="$3" threads="$4"
  shift 4
  local out="$WORK/out_$RANDOM.csv"
  local t0 t1 cpu0 cpu1
  t0=$(date +%s.%N)
  cpu0=$(awk '{print $14+$15+$16+$17}' /proc/$$/stat)
  "$@" "$FLEXROCK" spectrum "$spec" -o "$out" -q --no-progress -j "$threads" >/dev/null
  t1=$(date +%s.%N)
  cpu1=$(awk '{print $14+$15+$16+$17}' /proc/$$/stat)
  local ticks
  ticks=$(getconf CLK_TCK)
  local bis
  bis=$(awk -F, 'NR > 1 {s += $NF} END {print s + 0}' "${out%.csv}.boundary.csv")
  local runs=$((GRID * GRID + bis))
  local wall cpu
  wall=$(echo "$t1 - $t0" | bc -l)
  cpu=$(echo "($cpu1 - $cpu0) / $ticks" | bc -l)
  [ "$label" = "block, 1 thread" ] && ref_block="$out"
  if [ -n "$ref_block" ] && [ "$ref_block" != "$out" ] && [[ "$label" == block* ]]; then
    cmp -s "$ref_block" "$out" || echo "warning: $label wrote a different file" >&2
  fi
  rows+=("$(printf '| %s | %s | %d | %.1f | %.1f | %.0f | %.0f |' "$label" "$cores" "$runs" \
    "$wall" "$cpu" "$(echo "$runs / $wall / $cores" | bc -l)" "$(echo "$runs / $cpu" | bc -l)")")
  local key
  key=$(printf '%s' "$label" | tr -c 'A-Za-z0-9' '_')
  eval "wall_$key=$wall"
  eval "cpu_$key=$cpu"
}

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
measure "block, 1 thread" 1 "$WORK/block.toml" 1
measure "block, 2 threads" 2 "$WORK/block.toml" 2
measure "oscillator, 1 thread" 1 "$WORK/oscillator.toml" 1
measure "oscillator, 2 threads" 2 "$WORK/oscillator.toml" 2
if [ "$has_mpi" = yes ]; then
  MPI=(mpirun --allow-run-as-root --oversubscribe)
  measure "block, 1 MPI process" 1 "$WORK/block.toml" 1 "${MPI[@]}" -n 1
  measure "block, 2 MPI processes" 2 "$WORK/block.toml" 1 "${MPI[@]}" -n 2
fi
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

speedup() { printf '%.2f' "$(echo "$1 / $2" | bc -l)"; }
echo "## Studies at scale"
echo
echo "\`flexrock spectrum\`, one-sine pulses on a ${GRID} x ${GRID} grid (a_p/(g tan alpha) from 0.5"
echo "to 8, omega_p/p from 1 to 16), plus the bisection of the minimum overturning amplitude of"
echo "every column (tolerance 1e-3). Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(nproc) cores"
echo "($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')); load average before"
echo "$load_before, after $load_after (other work on the machine slows the wall times; CPU"
echo "seconds are less affected)."
echo
echo "| case | cores | runs | wall [s] | CPU [s] | runs/s per core (wall) | runs per CPU second |"
echo "|---|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
echo
echo "Speed-up, 1 -> 2 threads: block $(speedup "$wall_block__1_thread" "$wall_block__2_threads"),"\
" oscillator $(speedup "$wall_oscillator__1_thread" "$wall_oscillator__2_threads")."
if [ "$has_mpi" = yes ]; then
  echo "Speed-up, 1 -> 2 MPI processes (1 thread each): block"\
" $(speedup "$wall_block__1_MPI_process" "$wall_block__2_MPI_processes")."
fi
if [ "$GRID" = 256 ]; then
  met=$(echo "$cpu_block__1_thread < 5" | bc -l)
  printf '\nTarget: the 256 x 256 block spectrum on one core in under 5 s of CPU: %.1f s, %s.\n' \
    "$cpu_block__1_thread" "$([ "$met" = 1 ] && echo met || echo NOT met)"
fi
echo
echo "Commands (SPEC as in bench/study_timing.sh):"
echo
echo '```'
echo "flexrock spectrum SPEC -o out.csv -q --no-progress -j 1    # and -j 2"
[ "$has_mpi" = yes ] && echo "mpirun --allow-run-as-root --oversubscribe -n 2 flexrock spectrum SPEC -o out.csv -q -j 1"
# the binary as given from the source tree (an absolute path names one machine's checkout)
echo "GRID=$GRID bench/study_timing.sh $(realpath --relative-to="$SRC" "$FLEXROCK")"
echo '```'
