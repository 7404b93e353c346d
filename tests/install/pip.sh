#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `pip install .` into a fresh virtual environment that uses the system site packages (Debian's
# numpy, matplotlib, setuptools), offline, then the module, `flexrock` and `python -m flexrock`
# from it. With FLEXROCK_BUILD_DIR the build's module and command are packaged (no second build).
# Usage: pip.sh SOURCE_DIR [BUILD_DIR]
set -euo pipefail
src="$1"
build="${2:-}"
work="$(mktemp -d "${TMPDIR:-/tmp}/flexrock_pip.XXXXXX")"
trap 'rm -rf "$work"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

/usr/bin/python3 -m venv --system-site-packages "$work/venv"
py="$work/venv/bin/python"
[ -n "$build" ] && export FLEXROCK_BUILD_DIR="$build"
"$py" -m pip install --no-build-isolation --no-index --disable-pip-version-check -q "$src" \
  >"$work/pip.log" 2>&1 || { cat "$work/pip.log" >&2; fail "pip install"; }

cd "$work"  # away from the sources: the installed package must be the one imported
declared="$(sed -nE 's/^project\(flexrock VERSION ([0-9.]+).*/\1/p' "$src/CMakeLists.txt")"
version="$("$py" -c 'import flexrock; print(flexrock.__version__)')"
[ "$version" = "$declared" ] || fail "flexrock.__version__ is '$version', CMake says '$declared'"
where="$("$py" -c 'import flexrock; print(flexrock.__file__)')"
case "$where" in "$work/venv/"*) ;; *) fail "flexrock imported from $where, not the venv" ;; esac
pkg="$(dirname "$where")"
for f in py.typed _flexrock.pyi __main__.py _bin/flexrock; do
  [ -e "$pkg/$f" ] || fail "not installed: flexrock/$f"
done
[ "$("$work/venv/bin/flexrock" --version)" = "flexrock $declared" ] || fail "flexrock --version"
[ "$("$py" -m flexrock --version)" = "flexrock $declared" ] || fail "python -m flexrock --version"

# a real run and its figure from the venv's command (plot: the venv's interpreter and package)
"$work/venv/bin/flexrock" run "$src/examples/cases/museum_statue.toml" -o "$work/out" -q
written="$("$py" -c 'import json, sys; print(json.load(open(sys.argv[1]))["flexrock_version"])' \
  "$work/out/museum_statue.summary.json")"
[ "$written" = "$declared" ] || fail "summary JSON says flexrock_version '$written'"
MPLBACKEND=Agg "$work/venv/bin/flexrock" plot "$work/out/museum_statue.csv" -o "$work/out/m.png"
[ -s "$work/out/m.png" ] || fail "flexrock plot wrote no figure"
# a usage error keeps its exit code through the entry point
set +e
"$work/venv/bin/flexrock" fly >/dev/null 2>&1
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "flexrock fly exited $rc, expected 2"
echo "pip: ok ($version in $pkg)"
