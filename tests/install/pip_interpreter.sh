#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `pip install .` with a python3 first on PATH that is not Debian's (pyenv, conda): it has pip and
# setuptools but not wheel or numpy. A venv made without the system site packages stands in for
# it. setup.py must say what the interpreter lacks and what to do (not setuptools' "invalid
# command 'bdist_wheel'"), and scripts/pip-install.sh must pass over it, say why, and install with
# Debian's interpreter, packaging the given build (no second build).
# Usage: pip_interpreter.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src="$1"
build="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/flexrock_pipi.XXXXXX")"
trap 'rm -rf "$work"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

/usr/bin/python3 -m venv "$work/other"
other="$work/other/bin/python3"
"$other" -c 'import wheel' 2>/dev/null && fail "the stand-in interpreter has wheel: no test"

# pip install . in that interpreter's own environment: refused by setup.py, naming the cause
set +e
"$other" -m pip install --no-build-isolation --no-index --disable-pip-version-check "$src" \
  >"$work/pip.log" 2>&1
rc=$?
set -e
[ "$rc" -ne 0 ] || fail "pip install . with no wheel package succeeded?"
grep -q "cannot build flexrock: it lacks the \`wheel\` package" "$work/pip.log" ||
  { cat "$work/pip.log" >&2; fail "setup.py did not name the missing wheel package"; }
grep -q "/usr/bin/python3 -m venv --system-site-packages" "$work/pip.log" ||
  fail "setup.py did not say how to make a working environment"

# the script passes over it, saying what it lacks, and picks Debian's
out="$(PATH="$work/other/bin:$PATH" "$src/scripts/pip-install.sh" --check 2>&1)"
grep -q "passing over $work/other/bin/python3: it lacks" <<<"$out" || fail "not passed over: $out"
grep -q "  - wheel" <<<"$out" || fail "the missing wheel not named: $out"
grep -q "  - numpy" <<<"$out" || fail "the missing numpy not named: $out"
grep -q "using /usr/bin/python3" <<<"$out" || fail "Debian's interpreter not chosen: $out"

# asked for by name, it is refused with the reason and exit 2
set +e
out="$(PYTHON="$other" "$src/scripts/pip-install.sh" --check 2>&1)"
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "PYTHON=<lacking interpreter> exited $rc, expected 2"
grep -q "PYTHON=$other cannot build flexrock" <<<"$out" || fail "refusal not explained: $out"
set +e
"$src/scripts/pip-install.sh" --bogus >/dev/null 2>&1
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "an unknown option exited $rc, expected 2"

# and installs: the build's progress on screen, a working module and command
out="$(cd "$work" && PATH="$work/other/bin:$PATH" FLEXROCK_BUILD_DIR="$build" \
  "$src/scripts/pip-install.sh" "$work/venv" 2>&1)" || { echo "$out" >&2; fail "install"; }
grep -q "setup.py: cmake --build" <<<"$out" || fail "no build progress shown: $out"
grep -q "installed in [0-9]* min [0-9]* s" <<<"$out" || fail "no time: $out"
cd "$work"
"$work/venv/bin/python" -c 'import flexrock, numpy' || fail "the module does not import"
"$work/venv/bin/flexrock" --version | grep -q "^flexrock " || fail "flexrock --version"
echo "pip_interpreter: ok"
