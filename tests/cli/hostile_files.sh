#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Files planted or forged by someone else, and values past their range, through the CLI: a link
# at a study's journal name is refused and its target untouched (nothing of a foreign file is
# echoed); binary inputs are named as such; a [[suite]] glob that matches something that is no
# record file names it; fragility reads a sweep CSV through the journal's row checks and bounds
# --curve-points; solver values past their physical range are refused naming the key
source "$(dirname "$0")/common.sh"
cd "$WORK"

cat >block.toml <<'TOML'
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
printf '0.0\n0.1\n-0.2\n0.1\n0.0\n' >rec.txt
cat >m.toml <<'TOML'
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

bad2() {
  local what="$1"
  shift
  expect_rc 2 "$what"
  for m in "$@"; do expect_in "$WORK/err" "$m"; done
}

# --- a link at the journal's name: refused, not followed, its target's content not shown ------
printf 'secret first line\n' >victim.txt
ln -s "$WORK/victim.txt" s.csv.partial
run "$FLEXROCK" sweep m.toml -o s.csv -q
bad2 "journal is a link" "s.csv.partial: is a symbolic link" "not followed"
grep -q secret "$WORK/err" && fail "the link's target was echoed"
[ "$(cat victim.txt)" = "secret first line" ] || fail "the link's target was changed"
[ ! -e s.csv ] || fail "an output was written"
rm s.csv.partial
ln -s "$WORK/made_elsewhere" s.csv.partial
run "$FLEXROCK" sweep m.toml -o s.csv -q
bad2 "journal is a dangling link" "symbolic link"
[ ! -e made_elsewhere ] || fail "the dangling link's target was created"
rm s.csv.partial
# a regular file that is no journal: refused without its content
printf 'secret first line\n' >s.csv.partial
run "$FLEXROCK" sweep m.toml -o s.csv -q
bad2 "journal is a foreign file" "not a flexrock journal"
grep -q secret "$WORK/err" && fail "a foreign file was echoed"
rm s.csv.partial
run "$FLEXROCK" sweep m.toml -o s.csv -q
expect_rc 0 "the sweep once the name is free"

# --- binary inputs ------------------------------------------------------------------------
head -c 1048576 /dev/zero >zeros.txt
sed 's/rec.txt/zeros.txt/' m.toml >zm.toml
run "$FLEXROCK" sweep zm.toml -o z.csv -q
bad2 "a record of NULs" "zeros.txt: binary data (NUL byte at offset 0), expected a text record file"
head -c 1048576 /dev/zero >z.csv.partial
run "$FLEXROCK" sweep m.toml -o z.csv -q
bad2 "a journal of NULs" "z.csv.partial: binary data (NUL byte at offset 0)"
[ "$(stat -c %s z.csv.partial)" -eq 1048576 ] || fail "the journal of NULs was changed"
run "$FLEXROCK" check zeros.txt
bad2 "a case file of NULs" "binary data (NUL byte at offset 0), expected a text case file"

# --- [[suite]] globs: what matches must be a record file ------------------------------------
mkdir suite
for r in A B; do printf '0.0\n0.1\n-0.2\n0.1\n0.0\n' >"suite/$r.txt"; done
cat >suite.toml <<'TOML'
[[body]]
file = "block.toml"
[[suite]]
horizontal = "suite/*.txt"
format = "single_column"
dt = 0.01
units = "g"
[scales]
factors = [1.0]
TOML
run "$FLEXROCK" sweep suite.toml -o suite.csv -q
expect_rc 0 "a suite of two records"
[ "$(wc -l <suite.csv)" -eq 3 ] || fail "two runs expected"
ln -s "$WORK/gone.txt" suite/C.txt
run "$FLEXROCK" sweep suite.toml -o suite2.csv -q
bad2 "dangling link in a suite" "suite/C.txt, a symbolic link to nothing (dangling)"
rm suite/C.txt
mkdir suite/D.txt
run "$FLEXROCK" sweep suite.toml -o suite2.csv -q
bad2 "directory in a suite" "suite/D.txt, a directory"
rmdir suite/D.txt
mkfifo suite/E.txt
run timeout 20 "$FLEXROCK" sweep suite.toml -o suite2.csv -q
bad2 "FIFO in a suite" "suite/E.txt, a FIFO"
rm suite/E.txt
[ ! -e suite2.csv ] || fail "an output was written"

# --- fragility: --curve-points bounded, the sweep CSV checked as a journal is ---------------
run "$FLEXROCK" sweep "$SRC/examples/studies/sweep.toml" -o sweep.csv -q
expect_rc 0 "example sweep"
run "$FLEXROCK" fragility sweep.csv --curve c.csv --curve-points 1e7
bad2 "1e7 curve points" "--curve-points: expected an integer in [1, 10000], got 1e+07"
[ ! -e c.csv ] || fail "a curve was written"
run "$FLEXROCK" fragility sweep.csv --curve c.csv --curve-points 1e308
bad2 "1e308 curve points" "got 1e+308"
[ "$(wc -c <"$WORK/err")" -lt 200 ] || fail "a long message: $(cat "$WORK/err")"
run "$FLEXROCK" fragility sweep.csv --curve c.csv --curve-points 2.5
bad2 "fractional curve points" "got 2.5"
run "$FLEXROCK" fragility sweep.csv --curve c.csv --curve-points 10000 -q
expect_rc 0 "10000 curve points"
# an overturned row whose flag says 0, and a run given twice
awk -F, 'BEGIN{OFS=","} NR>1 && $11 ~ /^overturned/ && !done {$12=0; done=1} {print}' sweep.csv >flag.csv
run "$FLEXROCK" fragility flag.csv
bad2 "outcome against its flag" "flag.csv:" "overturned = 0 does not go with outcome overturned"
{ cat sweep.csv; sed -n 2p sweep.csv; } >twice.csv
run "$FLEXROCK" fragility twice.csv
bad2 "a run twice" "twice.csv:34:" "run index 0 twice, first at line 2"

# --- solver values past their physical range ------------------------------------------------
solver() {
  { cat block.toml; printf '[solver]\n%b\n' "$1"; } >bounds.toml
  run "$FLEXROCK" check bounds.toml
}
solver 'restitution_factor = 1e308'
bad2 "restitution_factor" "key 'solver.restitution_factor'" "[0, 2]"
solver 'impact_duration = 1e-300'
bad2 "impact_duration" "key 'solver.impact_duration'" "[1e-06, 1] s"
solver 'contact_model = "compliant"\ncontact_stiffness = 1e-300'
bad2 "tiny contact_stiffness" "key 'solver.contact_stiffness'" "[1000, 1e+15] N/m"
solver 'contact_model = "compliant"\ncontact_stiffness = 1e300'
bad2 "huge contact_stiffness" "key 'solver.contact_stiffness'" "[1000, 1e+15] N/m"
solver 'contact_model = "compliant"\ncontact_stiffness = 1e8\ncontact_damping_ratio = 1e300'
bad2 "contact_damping_ratio" "key 'solver.contact_damping_ratio'" "[0, 100]"
# a sampled restitution_factor must stay in the same range: an untruncated lognormal is refused
{ cat m.toml; printf '[[uncertain]]\nparameter = "restitution_factor"\ndistribution = "lognormal"\nmedian = 1.0\nbeta = 0.1\n'; } >um.toml
run "$FLEXROCK" sweep um.toml -o u.csv -q
bad2 "an unbounded sampled restitution_factor" "key 'uncertain.distribution'" "in [0, 2]"
sed 's/^period = 1.0/period = 1e-300/' block.toml >tiny_period.toml
run "$FLEXROCK" run -q -o out tiny_period.toml
bad2 "a one-sine pulse of period 1e-300 s" "key 'excitation.horizontal.period'" "[0.0001, 10000] s"
echo "hostile files: ok"
