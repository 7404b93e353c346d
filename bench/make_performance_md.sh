#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates docs/performance.md: builds the benchmarks, runs Google Benchmark (JSON) and the
# peer comparison (with the rigid rocking's former DOPRI5 step beside its Taylor series), the
# flexible body's rocking step (DOP853 beside the former DOPRI5), the study timings (a 256 x 256 spectrum unless GRID is set), and writes the tables, the commands, the
# machine and the date.
# Usage: bench/make_performance_md.sh [--quick]
#   BUILD_DIR (default build/bench, the bench preset) is configured if needed.
#   --quick: fewer tolerances and repetitions in the peer comparison (minutes instead of ~15).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build/bench}
quick=()
[ "${1:-}" = "--quick" ] && quick=(--quick)
py=/usr/bin/python3
# the peers' rows need scipy and Siconos: without them the document would be written with those
# rows missing (compare.py runs on without a peer), so stop before measuring anything
if ! $py -c "import scipy, siconos" 2>/dev/null; then
  echo "make_performance_md.sh: $py cannot import scipy and siconos, whose rows" \
    "docs/performance.md keeps; install them with scripts/install-deps.sh --bench" >&2
  exit 1
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  if [ "$build" = build/bench ]; then
    cmake --preset bench >/dev/null
  else
    cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLEXROCK_BUILD_BENCH=ON \
      -DFLEXROCK_BUILD_TESTS=OFF >/dev/null
  fi
fi
cmake --build "$build" -j2 --target flexrock_bench flexrock_run_case flexrock >/dev/null

# the measurements stay in $build/perf (bench.json, peers.json, studies.md): a failure of the
# writer does not lose half an hour of runs
perf="$build/perf"
mkdir -p "$perf"
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
"$build/bench/flexrock_bench" --benchmark_format=json --benchmark_out="$perf/bench.json" \
  --benchmark_out_format=json >/dev/null
mkdir -p docs/img
$py bench/peers/compare.py --run-case "$build/bench/flexrock_run_case" --out "$perf/peers.json" \
  --plot docs/img/work_precision.png --old-step "${quick[@]}"
# the flexible body's rocking step, DOP853 against DOPRI5 (flexrock only: no peer runs case (d))
$py bench/peers/compare.py --run-case "$build/bench/flexrock_run_case" \
  --out "$perf/flexible_steps.json" --plot docs/img/flexible_step.png --old-step --flexrock-only \
  --cases d1,d8 "${quick[@]}"
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

studies=""
if [ -x bench/study_timing.sh ] && [ -x "$build/apps/flexrock" ]; then
  studies=$(bench/study_timing.sh "$build/apps/flexrock" || true)
  printf '%s\n' "$studies" >"$perf/studies.md"
fi

$py bench/peers/write_performance_md.py --bench "$perf/bench.json" --peers "$perf/peers.json" \
  --load "$load_before / $load_after" --command "bench/make_performance_md.sh ${quick[*]}" \
  --studies "$studies" --flexible-steps "$perf/flexible_steps.json" --out docs/performance.md
echo "wrote docs/performance.md, docs/img/work_precision.png and docs/img/flexible_step.png"
