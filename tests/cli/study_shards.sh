# SPDX-License-Identifier: BSD-3-Clause
# flexrock sweep|spectrum --shard k/N and flexrock merge: N independent processes (an array job)
# and a merge write the files a single run writes, byte for byte, for N = 1, 3, 4 and N above the
# number of runs or columns; a shard is resumable from its own journal; bad merges are refused
# with nothing written; progress lines reach a stdout that is no terminal as the work goes.
source "$(dirname "$0")/common.sh"
cd "$WORK"
STUDIES="$SRC/examples/studies"

# runs every shard of a split, one after another, then merges them
shards() {  # verb spec out N [options...]
  local verb="$1" spec="$2" out="$3" n="$4"
  shift 4
  for k in $(seq 1 "$n"); do
    run "$FLEXROCK" "$verb" "$spec" -o "$out" --shard "$k/$n" -j 1 "$@"
    expect_rc 0 "$verb shard $k/$n"
    [ -f "$out.shard${k}of$n" ] || fail "no shard file $out.shard${k}of$n"
    [ -z "$(ls "$out".shard*.partial 2>/dev/null)" ] || fail "a shard's journal left behind"
  done
  run "$FLEXROCK" merge "$out".shard*"of$n"
  expect_rc 0 "merge of $n $verb shards"
  expect_in "$WORK/out" "wrote $out"
}

# a sweep of 32 runs
run "$FLEXROCK" sweep "$STUDIES/sweep.toml" -o one.csv -j 2 -q
expect_rc 0 "single sweep"
for n in 1 3 4 40; do
  shards sweep "$STUDIES/sweep.toml" "s$n.csv" "$n"
  cmp one.csv "s$n.csv" || fail "the sweep merged from $n shards differs from the single run"
done

# a pulse spectrum of 12 columns with its boundary
run "$FLEXROCK" spectrum "$STUDIES/one_sine_block.toml" -o p.csv -j 2 -q
expect_rc 0 "single spectrum"
for n in 1 3 4 13; do
  shards spectrum "$STUDIES/one_sine_block.toml" "p$n.csv" "$n"
  cmp p.csv "p$n.csv" || fail "the spectrum merged from $n shards differs"
  cmp p.boundary.csv "p$n.boundary.csv" || fail "the boundary merged from $n shards differs"
done

# a record spectrum: split by rows without its bisection; with it, refused before any journal
run "$FLEXROCK" spectrum "$STUDIES/elcentro_scales.toml" -o r.csv --no-bisect -j 2 -q
expect_rc 0 "single record spectrum"
shards spectrum "$STUDIES/elcentro_scales.toml" r3.csv 3 --no-bisect
cmp r.csv r3.csv || fail "the record spectrum merged from 3 shards differs"
[ ! -e r3.boundary.csv ] || fail "a boundary written for a spectrum without bisection"
run "$FLEXROCK" spectrum "$STUDIES/elcentro_scales.toml" -o rb.csv --shard 1/2
expect_rc 2 "a record spectrum's bisection split in shards"
expect_in "$WORK/err" "split it with --no-bisect"
[ -z "$(ls rb.csv* 2>/dev/null)" ] || fail "files left by a refused shard"

# --shard itself
for bad in 0/3 4/3 3 a/b 1/0 -1/2 "1/2/3"; do
  run "$FLEXROCK" sweep "$STUDIES/sweep.toml" -o bad.csv --shard "$bad"
  expect_rc 2 "--shard $bad"
  expect_in "$WORK/err" "--shard: expected k/N"
done

# bad merges: nothing written, a message naming the file and what is wrong
refused() {  # what, expected text, merge arguments...
  local what="$1" text="$2"
  shift 2
  rm -f merged.csv
  run "$FLEXROCK" merge -o merged.csv "$@"
  expect_rc 2 "$what"
  expect_in "$WORK/err" "$text"
  [ ! -e merged.csv ] || fail "$what: an output was written"
}
refused "a missing shard" "missing shard 2 of 3" s3.csv.shard1of3 s3.csv.shard3of3
refused "a shard given twice" "given twice" s3.csv.shard1of3 s3.csv.shard2of3 s3.csv.shard3of3 \
  s3.csv.shard2of3
refused "shards of two splits" "of a split into 4" s3.csv.shard1of3 s4.csv.shard2of4 \
  s3.csv.shard3of3
refused "shards of two studies" "a shard of another study" s3.csv.shard1of3 p3.csv.shard2of3 \
  s3.csv.shard3of3
sed '3s/$/0/' s3.csv.shard2of3 >edited.shard2of3
refused "an edited line" "checksum mismatch" s3.csv.shard1of3 edited.shard2of3 s3.csv.shard3of3
head -n 4 s3.csv.shard2of3 >cut.shard2of3
printf '12 00' >>cut.shard2of3
refused "a cut shard file" "no line end" s3.csv.shard1of3 cut.shard2of3 s3.csv.shard3of3
refused "a CSV as a shard" "not a flexrock shard file" one.csv
run "$FLEXROCK" merge s3.csv.shard1of3 s3.csv.shard2of3 s3.csv.shard3of3 -o s3.csv.shard1of3
expect_rc 2 "a merge onto one of its shards"
cp s3.csv.shard1of3 keep && cmp keep s3.csv.shard1of3 || fail "a shard file was overwritten"

# a shard is resumable: interrupted, the same command goes on from its journal; its progress
# lines are in its log (stdout a file) while it runs, flushed as written
DATA="$SRC/../shared/data"
[ -f "$DATA/elcentro_1940_ns.dat" ] || DATA="$SRC/tests/data"
cat >block.toml <<'TOML'
[body]
type = "rigid_block"
width = 0.4
height = 2.0
mass = 1000.0
TOML
# 60 slow runs (see study_sweep_resume.sh; a tenth of its max_step): a signal arrives mid-way
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
factors = { start = 0.1, stop = 6.0, step = 0.1 }
[solver]
max_step = 0.00005
friction_coefficient = 100.0
TOML
run "$FLEXROCK" sweep m.toml -o ref.csv -j 2 -q
expect_rc 0 "the slow sweep whole"
"$FLEXROCK" sweep m.toml -o m.csv --shard 1/2 -j 1 --progress-every 0.2 >log 2>err &
pid=$!
# the first line at the start, the next one after a tenth of the runs or 0.2 s
for _ in $(seq 1 600); do
  grep -q "^progress: [0-9]* of 30 runs (" log && break
  sleep 0.05
done
grep -q "^progress: 0 of 30 runs  (shard 1 of 2)" log || fail "no first progress line: $(cat log)"
grep -q "^progress: [0-9]* of 30 runs (" log || fail "no progress line while the shard runs: $(cat log)"
kill -INT "$pid" 2>/dev/null || fail "the shard ended before SIGINT (too fast to test)"
set +e
wait "$pid"
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "interrupted shard: exit code $rc, expected 1"
expect_in err "finished runs are kept in m.csv.shard1of2.partial"
[ ! -e m.csv.shard1of2 ] || fail "an interrupted shard wrote its shard file"
run "$FLEXROCK" sweep m.toml -o m.csv --shard 1/2 -j 1
expect_rc 0 "the shard resumed"
expect_in "$WORK/out" "resuming:"
expect_in "$WORK/out" " runs done in "
run "$FLEXROCK" sweep m.toml -o m.csv --shard 2/2 -j 1 -q
expect_rc 0 "the second shard"
! grep -q "^progress:" "$WORK/out" || fail "progress lines with --quiet"
run "$FLEXROCK" merge m.csv.shard2of2 m.csv.shard1of2
expect_rc 0 "merge in any order"
cmp ref.csv m.csv || fail "the resumed shards merge into another file than the single run"
echo "ok"
