#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Files that are not what they seem, and outputs that would overwrite inputs: every one is bad
# input (exit 2, a message naming the path), nothing blocks, no input is touched.
source "$(dirname "$0")/common.sh"

cat >"$WORK/block.toml" <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 100.0
[excitation.horizontal]
type = "one_sine"
amplitude = 0.3
units = "g"
period = 1.0
duration = 2.0
TOML
printf '0.0\n0.1\n-0.2\n0.1\n0.0\n' >"$WORK/rec.txt"
cat >"$WORK/m.toml" <<'TOML'
[[body]]
file = "block.toml"
[[record]]
file = "rec.txt"
format = "single_column"
dt = 0.01
units = "g"
[scales]
factors = [0.5, 1.0]
TOML
cp "$WORK/m.toml" "$WORK/m.orig"

# bad2 WHAT MESSAGE... -- the last `run` exited 2 with every message on stderr
bad2() {
  local what="$1"
  shift
  expect_rc 2 "$what"
  for m in "$@"; do expect_in "$WORK/err" "$m"; done
}

# --- FIFOs and devices: refused at once (timeout: a blocked read would hang here) -----------
mkfifo "$WORK/pipe.toml"
run timeout 20 "$FLEXROCK" run "$WORK/pipe.toml"
bad2 "FIFO as case" "pipe.toml" "FIFO"
run timeout 20 "$FLEXROCK" check "$WORK/pipe.toml"
bad2 "FIFO checked" "FIFO"
run timeout 20 "$FLEXROCK" sweep "$WORK/pipe.toml" -o "$WORK/s.csv"
bad2 "FIFO as manifest" "FIFO"
run timeout 20 "$FLEXROCK" spectrum /dev/zero -o "$WORK/sp.csv"
bad2 "/dev/zero as spectrum" "/dev/zero" "device"
run timeout 20 "$FLEXROCK" sweep /dev/zero -o "$WORK/s.csv"
bad2 "/dev/zero as manifest" "/dev/zero" "device"
run timeout 20 "$FLEXROCK" fragility "$WORK/pipe.toml"
bad2 "FIFO as sweep CSV" "FIFO"

# --- symbolic-link loops and over-long names: input errors, not filesystem exceptions --------
ln -s "$WORK/loop_b" "$WORK/loop_a"
ln -s "$WORK/loop_a" "$WORK/loop_b"
run "$FLEXROCK" run "$WORK/loop_a"
bad2 "symlink loop as case" "loop_a" "symbolic links"
run "$FLEXROCK" sweep "$WORK/loop_a"
bad2 "symlink loop as manifest" "symbolic links"
run "$FLEXROCK" run -o "$WORK/loop_a" "$WORK/block.toml"
bad2 "symlink loop as output directory" "symbolic links"
long="$WORK/$(printf 'x%.0s' $(seq 1 300)).toml"
run "$FLEXROCK" check "$long"
bad2 "over-long case name" "File name too long"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$long.csv"
bad2 "over-long output name" "File name too long"

# a legal long output name (250 bytes): its temporary must fit NAME_MAX too
name250="$(printf 'y%.0s' $(seq 1 246)).csv"
printf '[output]\ntime_history = "%s"\nsummary = ""\n' "$name250" >"$WORK/longout.toml"
cat "$WORK/block.toml" "$WORK/longout.toml" >"$WORK/longcase.toml"
run "$FLEXROCK" run -q -o "$WORK/res" "$WORK/longcase.toml"
expect_rc 0 "a 250-byte output name"
[ -s "$WORK/res/$name250" ] || fail "the 250-byte output was not written"

# --- outputs that are inputs, or each other ---------------------------------------------
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/m.toml"
bad2 "sweep -o its manifest" "output $WORK/m.toml is the same file as the input"
cmp -s "$WORK/m.toml" "$WORK/m.orig" || fail "the manifest was changed"
run "$FLEXROCK" sweep "$WORK/m.toml" -o "$WORK/./rec.txt"
bad2 "sweep -o its record" "is the same file as the input"
printf '[output]\ntime_history = "rec.txt"\n' >"$WORK/o1.toml"
cat "$WORK/block.toml" >"$WORK/c1.toml"
sed -i 's/type = "one_sine"/type = "record"\nfile = "rec.txt"\nformat = "single_column"\ndt = 0.01/; /amplitude\|period\|duration/d' "$WORK/c1.toml"
cat "$WORK/o1.toml" >>"$WORK/c1.toml"
run "$FLEXROCK" run -o "$WORK" "$WORK/c1.toml"
bad2 "time history onto the record" "time history $WORK/rec.txt is the same file as the input"
pushd "$WORK" >/dev/null
run "$FLEXROCK" check c1.toml
popd >/dev/null
bad2 "check sees it too" "is the same file as the input"
printf '0.0\n0.1\n-0.2\n0.1\n0.0\n' | cmp -s - "$WORK/rec.txt" || fail "the record was changed"
printf '[output]\ntime_history = "a.csv"\nevents = "sub/../a.csv"\n' >"$WORK/o2.toml"
cat "$WORK/block.toml" "$WORK/o2.toml" >"$WORK/c2.toml"
run "$FLEXROCK" run -o "$WORK/res2" "$WORK/c2.toml"
bad2 "two outputs one file" "event log" "is the same file as the time history"
[ ! -e "$WORK/res2/a.csv" ] || fail "an output was written"
printf 'body = "block.toml"\n[spectrum]\namplitudes = [1.0]\nfrequencies = [1.0]\n' >"$WORK/sp.toml"
run "$FLEXROCK" spectrum "$WORK/sp.toml" -o "$WORK/x.csv" --boundary "$WORK/x.csv"
bad2 "spectrum cells = boundary" "is the same file as the output"
printf 'a,b\n1,2\n' >"$WORK/f.csv"
run "$FLEXROCK" fragility "$WORK/f.csv" -o "$WORK/f.csv"
bad2 "fragility -o its input" "is the same file as the sweep CSV"

# --- caps and decimal commas: refused naming the key, the file and the line ---------------
printf '[output]\ndt = 1e-300\n' | cat "$WORK/block.toml" - >"$WORK/tiny_dt.toml"
run "$FLEXROCK" check "$WORK/tiny_dt.toml"
bad2 "output.dt = 1e-300" "tiny_dt.toml:13:" "key 'output.dt'" "at most 10000000"
printf '0,000\n-0,050\n0,020\n' >"$WORK/eu.txt"
sed 's/rec.txt/eu.txt/' "$WORK/m.toml" >"$WORK/eu.toml"
run "$FLEXROCK" sweep "$WORK/eu.toml" -o "$WORK/eu.csv"
bad2 "decimal commas" "eu.txt:1:" "decimal comma"
[ ! -e "$WORK/eu.csv" ] && [ ! -e "$WORK/eu.csv.partial" ] || fail "outputs written"
echo "io safety: ok"
