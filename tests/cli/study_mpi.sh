# SPDX-License-Identifier: BSD-3-Clause
# two MPI processes write the same sweep and spectrum files, byte for byte, as threads do
source "$(dirname "$0")/common.sh"
MPIEXEC="$3"
cd "$WORK"
mpi() { "$MPIEXEC" --allow-run-as-root --oversubscribe -n 2 "$@"; }

run "$FLEXROCK" sweep "$SRC/examples/studies/sweep.toml" -o threads.csv -j 2 -q
expect_rc 0 "threaded sweep"
run mpi "$FLEXROCK" sweep "$SRC/examples/studies/sweep.toml" -o mpi.csv -j 1 -q
expect_rc 0 "2-process sweep"
cmp threads.csv mpi.csv || fail "the 2-process sweep differs from the threaded one"
[ -z "$(ls mpi.csv.partial* 2>/dev/null)" ] || fail "journals left behind"

run "$FLEXROCK" spectrum "$SRC/examples/studies/one_sine_block.toml" -o t.csv -j 2 -q
expect_rc 0 "threaded spectrum"
run mpi "$FLEXROCK" spectrum "$SRC/examples/studies/one_sine_block.toml" -o m.csv -j 1 -q
expect_rc 0 "2-process spectrum"
cmp t.csv m.csv || fail "the 2-process spectrum differs"
cmp t.boundary.csv m.boundary.csv || fail "the 2-process boundary differs"
[ -z "$(ls m.csv.partial* 2>/dev/null)" ] || fail "spectrum journals left behind"

# a record spectrum: rows over the processes, the bisection on rank 0 from every row's outcome
run "$FLEXROCK" spectrum "$SRC/examples/studies/elcentro_scales.toml" -o rt.csv -j 2 -q
expect_rc 0 "threaded record spectrum"
run mpi "$FLEXROCK" spectrum "$SRC/examples/studies/elcentro_scales.toml" -o rm.csv -j 1 -q
expect_rc 0 "2-process record spectrum"
cmp rt.csv rm.csv || fail "the 2-process record spectrum differs"
cmp rt.boundary.csv rm.boundary.csv || fail "the 2-process record boundary differs"

# a journal another process left (an interrupted 2-process run) is merged on the next start:
# a complete journal (kept because an output could not be written: the boundary's directory does
# not exist) cut to half its cells and left as rank 1's
run "$FLEXROCK" spectrum "$SRC/examples/studies/one_sine_block.toml" -o k.csv \
  --boundary no_such_dir/k.boundary.csv -j 2 -q
expect_rc 1 "an output that cannot be written"
expect_in "$WORK/err" "the finished cells are kept in k.csv.partial"
rm -f k.csv
total=$(wc -l <k.csv.partial)
head -n $((total / 2)) k.csv.partial >k.csv.partial.rank1
rm k.csv.partial
run mpi "$FLEXROCK" spectrum "$SRC/examples/studies/one_sine_block.toml" -o k.csv -j 1
expect_rc 0 "2-process spectrum resumed from a rank journal"
expect_in "$WORK/out" "resuming: $((total / 2 - 1)) of"
cmp t.csv k.csv || fail "the spectrum resumed from a rank journal differs"
cmp t.boundary.csv k.boundary.csv || fail "the boundary resumed from a rank journal differs"
[ -z "$(ls k.csv.partial* 2>/dev/null)" ] || fail "journals left behind after a resume"
echo "ok"
