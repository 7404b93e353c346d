#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Python module and the `flexrock` command into a virtual environment with
# `pip install .`, offline, with an interpreter that can build it, showing the build's progress.
#
# Usage: scripts/pip-install.sh [--check] [VENV_DIR]     (VENV_DIR: default ~/venv/flexrock)
#   --check      say which interpreter would be used and why, and stop
#   PYTHON=...   use this interpreter (refused, saying what it lacks, if it cannot build)
#   FLEXROCK_BUILD_DIR, CMAKE_ARGS, CMAKE_BUILD_PARALLEL_LEVEL: as for pip install . (docs/python.md)
#
# Why a script: the environment sees the packages of the interpreter it is made from
# (--system-site-packages), and pip builds with --no-build-isolation from those. Debian's
# /usr/bin/python3 has them all after scripts/install-deps.sh; a python3 that comes first on PATH
# from pyenv or conda usually lacks `wheel` and numpy, and pip then fails deep in the build. This
# takes the first interpreter (PYTHON, else python3 on PATH, else /usr/bin/python3) that has what
# the build and the module need, and says what each one it passed over lacks.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"

check_only=0
venv=""
for arg in "$@"; do
  case "$arg" in
    --check) check_only=1 ;;
    -h | --help) sed -n '3,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "pip-install.sh: unknown option '$arg' (expected --check or a directory)" >&2; exit 2 ;;
    *) [ -z "$venv" ] || { echo "pip-install.sh: one directory only ('$venv', '$arg')" >&2; exit 2; }
       venv="$arg" ;;
  esac
done
venv="${venv:-$HOME/venv/flexrock}"

# what an interpreter lacks to make the environment, build flexrock and run it, one per line
# (each with the Debian package that provides it for /usr/bin/python3); empty when nothing
lacks() {
  "$1" - <<'EOF' 2>/dev/null || echo "a working Python 3.9 or newer"
import importlib.util as u, sys, sysconfig, pathlib
need = []
if sys.version_info < (3, 9): need.append("Python 3.9 or newer (it is %d.%d)" % sys.version_info[:2])
if u.find_spec("venv") is None or u.find_spec("ensurepip") is None: need.append("venv with ensurepip (Debian's python3-venv)")
if u.find_spec("pip") is None: need.append("pip (Debian's python3-pip)")
st = u.find_spec("setuptools")  # located, not imported: importing it here upsets its distutils shim
if st is None: need.append("setuptools (Debian's python3-setuptools)")
elif not any((pathlib.Path(d) / "command" / "bdist_wheel.py").is_file()
             for d in st.submodule_search_locations or []) and u.find_spec("wheel") is None:
    need.append("wheel (Debian's python3-wheel)")
if u.find_spec("numpy") is None: need.append("numpy (Debian's python3-numpy)")
inc = sysconfig.get_paths().get("include", "")
if not (pathlib.Path(inc) / "Python.h").is_file(): need.append("its C headers, Python.h (Debian's python3-dev)")
print("\n".join(need))
EOF
}

candidates=()
if [ -n "${PYTHON:-}" ]; then
  candidates=("$PYTHON")
else
  on_path="$(command -v python3 || true)"
  [ -n "$on_path" ] && candidates+=("$on_path")
  [ -x /usr/bin/python3 ] && candidates+=(/usr/bin/python3)
fi
py=""
for c in "${candidates[@]}"; do
  missing="$(lacks "$c")"
  real="$("$c" -c 'import sys; print(sys.executable)' 2>/dev/null || echo "$c")"
  if [ -z "$missing" ]; then
    py="$real"
    break
  fi
  echo "pip-install.sh: passing over $real: it lacks" >&2
  sed 's/^/  - /' <<<"$missing" >&2
done
if [ -z "$py" ]; then
  if [ -n "${PYTHON:-}" ]; then
    echo "pip-install.sh: PYTHON=$PYTHON cannot build flexrock; install what it lacks, or leave" \
      "PYTHON unset to use Debian's /usr/bin/python3 after scripts/install-deps.sh" >&2
  else
    echo "pip-install.sh: no interpreter can build flexrock; scripts/install-deps.sh installs" \
      "what /usr/bin/python3 needs" >&2
  fi
  exit 2
fi
echo "pip-install.sh: using $py ($("$py" -c 'import sys; print(sys.version.split()[0])'))"
[ "$check_only" -eq 1 ] && exit 0

start=$SECONDS
if [ ! -x "$venv/bin/python" ]; then
  "$py" -m venv --system-site-packages "$venv"
fi
log="$(mktemp "${TMPDIR:-/tmp}/flexrock_pip.XXXXXX.log")"
echo "pip-install.sh: building into $venv (the whole log: $log)"
# pip shows the build only with -v; of it, the terminal gets the build's progress lines (Ninja's
# [k/N], Make's [ p%]) and setup.py's own, the log everything
set +e
"$venv/bin/python" -m pip install -v --no-build-isolation --disable-pip-version-check "$src" 2>&1 |
  tee "$log" | grep --line-buffered -E '^ *(\[ *[0-9]+/[0-9]+\]|\[ *[0-9]+%\]|setup\.py:|Successfully)'
rc=${PIPESTATUS[0]}
set -e
if [ "$rc" -ne 0 ]; then
  echo "pip-install.sh: pip install failed (exit $rc); the end of $log:" >&2
  tail -n 30 "$log" >&2
  exit 1
fi
rm -f "$log"
elapsed=$((SECONDS - start))
echo "pip-install.sh: installed in $((elapsed / 60)) min $((elapsed % 60)) s:"
echo "  $venv/bin/flexrock run examples/cases/museum_statue.toml -o out"
echo "  $venv/bin/python -c 'import flexrock; print(flexrock.__version__)'"
