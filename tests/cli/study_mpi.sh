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
echo "ok"
