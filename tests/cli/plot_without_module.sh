#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `flexrock plot` draws a run's time history where the Python package's compiled module is not
# built (scripts/quickstart.sh builds the command alone): with numpy and matplotlib only. A figure
# that needs the module (a sweep's fragility) says so, exit 1, and writes nothing.
# Usage: plot_without_module.sh FLEXROCK SOURCE_DIR BUILD_DIR
set -euo pipefail
flexrock="$1"
src="$2"
build="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
mkdir -p "$work/py/flexrock"
cp "$build"/python/flexrock/*.py "$work/py/flexrock/"
ls "$work"/py/flexrock/_flexrock* >/dev/null 2>&1 && fail "the compiled module was copied"
export FLEXROCK_PYTHON_DIR="$work/py"
"$flexrock" run -q -o "$work/out" "$src/examples/cases/flexible_tank.toml" >/dev/null
MPLBACKEND=Agg "$flexrock" plot "$work/out/flexible_tank.csv" -o "$work/tank.png" >"$work/log" 2>&1 ||
  { cat "$work/log" >&2; fail "a time history's figure without the compiled module"; }
[ -s "$work/tank.png" ] || fail "no figure written"
MPLBACKEND=Agg "$flexrock" plot "$work/out/flexible_tank.csv" --kind loop -o "$work/loop.svg" >/dev/null 2>&1 ||
  fail "the loop figure without the compiled module"
# a sweep's fragility needs the module: refused with the reason, nothing written
"$flexrock" sweep -q "$src/examples/studies/sweep.toml" -o "$work/sweep.csv" >/dev/null
set +e
MPLBACKEND=Agg "$flexrock" plot "$work/sweep.csv" -o "$work/frag.png" >"$work/log" 2>&1
rc=$?
set -e
[ "$rc" -eq 1 ] || { cat "$work/log" >&2; fail "a fragility figure without the module exited $rc, expected 1"; }
grep -q "needs flexrock's compiled module" "$work/log" || { cat "$work/log" >&2; fail "no reason given"; }
[ ! -e "$work/frag.png" ] || fail "a figure was written"
echo "plot_without_module: ok"
