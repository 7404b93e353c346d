# SPDX-License-Identifier: BSD-3-Clause
# shared by the CLI tests: FLEXROCK (the binary), SRC (the source tree), a scratch directory
set -euo pipefail
FLEXROCK="$1"
SRC="$2"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/flexrock_cli.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# runs the command, keeping stdout, stderr and the exit code in $WORK/{out,err} and $rc
run() {
  set +e
  "$@" >"$WORK/out" 2>"$WORK/err"
  rc=$?
  set -e
}

expect_rc() {
  [ "$rc" -eq "$1" ] || { cat "$WORK/out" "$WORK/err" >&2; fail "exit code $rc, expected $1: $2"; }
}

# the file holds the fixed string
expect_in() {
  grep -qF -- "$2" "$1" || { cat "$1" >&2; fail "'$2' not in $(basename "$1")"; }
}

# a key of the summary JSON has a value (python3 reads it)
json_get() {
  python3 -c "import json,sys; d=json.load(open(sys.argv[1]))
for k in sys.argv[2].split('.'): d=d[k]
print(json.dumps(d))" "$1" "$2"
}
