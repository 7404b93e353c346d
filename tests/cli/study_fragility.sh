# SPDX-License-Identifier: BSD-3-Clause
# flexrock fragility: a fit of a sweep CSV written by flexrock sweep, its outputs and its errors
source "$(dirname "$0")/common.sh"

cd "$WORK"
run "$FLEXROCK" sweep "$SRC/examples/studies/sweep.toml" -o sweep.csv -q
expect_rc 0 "example sweep"
[ "$(wc -l <sweep.csv)" -eq 33 ] || fail "expected 32 rows + header"
head -1 sweep.csv | grep -q "^index,body,record,requested_level,requested_units,scale,pga_m_per_s2,pga_g,pgv_m_per_s,duration_s,outcome,overturned," ||
  fail "sweep columns: $(head -1 sweep.csv)"
# the requested level is one number per level of the manifest (8), whatever the record; it is
# the value pandas can group by (pga_g is computed from each record and differs in the last bits)
[ "$(tail -n +2 sweep.csv | cut -d, -f4 | sort -u | wc -l)" -eq 8 ] ||
  fail "requested levels: $(tail -n +2 sweep.csv | cut -d, -f4 | sort -u | tr '\n' ' ')"
[ "$(tail -n +2 sweep.csv | cut -d, -f5 | sort -u)" = "g" ] || fail "requested units"
run "$FLEXROCK" fragility sweep.csv --im requested_level --body statue
expect_rc 0 "fragility against the requested level"
expect_in "$WORK/out" "statue: P(overturning | requested_level)"
expect_in "$WORK/out" " g  ["

run "$FLEXROCK" fragility sweep.csv --im pga_g -o fit.csv --curve curve.csv --curve-points 20
expect_rc 0 "fragility of the example sweep"
expect_in "$WORK/out" "statue: P(overturning | pga_g)"
expect_in "$WORK/out" "theta = "
[ "$(wc -l <fit.csv)" -eq 3 ] || fail "expected one fit per body"
[ "$(wc -l <curve.csv)" -eq 41 ] || fail "expected 20 curve points per body"
head -1 fit.csv | grep -q "^body,samples,failures,excluded,theta,beta,se_ln_theta,se_beta" || fail "fit columns"

# no body exceeds theta/alpha 1e9 without overturning, so only overturned rows count: same fit
run "$FLEXROCK" fragility sweep.csv --im pga_g --outcome theta --level 1e9 --body statue
expect_rc 0 "theta outcome"
# all outcomes equal, or perfectly separated by the IM: clear errors, exit 2
grep -E "^index|,no_uplift," sweep.csv >none.csv
run "$FLEXROCK" fragility none.csv
expect_rc 2 "no failures"
expect_in "$WORK/err" "outcomes is 0: the curve cannot be fitted"
printf '%s\n' "$(head -1 sweep.csv)" >sep.csv
grep -E ",no_uplift," sweep.csv | head -2 >>sep.csv
grep -E ",overturned_" sweep.csv | sort -t, -k5 -g | tail -2 >>sep.csv
run "$FLEXROCK" fragility sep.csv
expect_rc 2 "perfect separation"
expect_in "$WORK/err" "perfectly separated by the intensity measure"
run "$FLEXROCK" fragility sweep.csv --body nobody
expect_rc 2 "unknown body"
expect_in "$WORK/err" "no rows of body 'nobody'"
run "$FLEXROCK" fragility sweep.csv --outcome theta
expect_rc 2 "theta without level"
expect_in "$WORK/err" "--level: expected a number > 0"

# with friction on one body: the sliding columns end every row; fragility of the sliding offset
# (against the PGV: the PGAs of the two records are the same targets, whose outcomes would tie)
sed -e "s#\"../cases/#\"$SRC/examples/cases/#" -e "s#\"../../../shared/#\"$SRC/../shared/#" \
  -e "s#^file = \"slender_block.toml\"#file = \"$SRC/examples/studies/slender_block.toml\"\nfriction_coefficient = 0.15#" \
  "$SRC/examples/studies/sweep.toml" >friction.toml
run "$FLEXROCK" sweep friction.toml -o friction.csv -q
expect_rc 0 "sweep with friction"
head -1 friction.csv | grep -q ",status,message,regime,max_offset_m,final_offset_m,sliding_time_s,slips$" ||
  fail "sliding columns: $(head -1 friction.csv)"
[ "$(awk -F, '{print NF}' friction.csv | sort -u)" = "34" ] || fail "fields per row"
grep -q "^[0-9]*,block,.*,sliding,[0-9.e-]*,[-0-9.e]*,[0-9.e-]*,[0-9]*$" friction.csv || fail "no sliding row"
grep -q "^[0-9]*,statue,.*,none,0,0,0,0$" friction.csv || fail "the statue has no friction: none"
run "$FLEXROCK" fragility friction.csv --im pgv --outcome offset --level 0.12 --body block
expect_rc 0 "fragility of the sliding offset"
expect_in "$WORK/out" "block: P(peak sliding offset > 0.12 m | pgv)"
run "$FLEXROCK" fragility friction.csv --outcome offset
expect_rc 2 "offset without level"
run "$FLEXROCK" fragility sweep.csv --outcome residual_offset --level 0.01
expect_rc 2 "a sweep without friction has no offsets"
expect_in "$WORK/err" "finite friction coefficient"
echo "ok"
