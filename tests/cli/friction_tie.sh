#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# a record whose peak sample equals mu_s g exactly (El Centro scaled to a PGA of 0.3 g, mu_s 0.3)
# under a cabinet that slides before it uplifts that way: the tie at the friction limit does not
# stop the run (docs/theory.md, "Sliding"), and the outcome is the same with rtol 10x finer
source "$(dirname "$0")/common.sh"

for rtol in 1e-9 1e-10; do
  cat >"$WORK/tie_$rtol.toml" <<TOML
[body]
type = "rigid_body"
mass = 300.0
inertia_cg = 108.0
height = 0.9
b1 = 0.2
b2 = 0.35
[excitation]
target_pga = 0.3
[excitation.horizontal]
type = "record"
file = "$SRC/../shared/data/elcentro_1940_ns.dat"
format = "single_column"
dt = 0.02
units = "g"
[solver]
friction_coefficient = 0.3
rtol = $rtol
[output]
events = "tie_$rtol.events.csv"
TOML
  run "$FLEXROCK" run -q -o "$WORK/res" "$WORK/tie_$rtol.toml"
  expect_rc 0 "a peak sample at mu_s g, rtol $rtol"
  s="$WORK/res/tie_$rtol.summary.json"
  [ "$(json_get "$s" outcome.status)" = '"completed"' ] || fail "status at rtol $rtol"
  # the floor holds at the tie: a slide of zero length, then the stick, at the peak sample
  grep -A1 '^2\.02,slip_start,' "$WORK/res/tie_$rtol.events.csv" | tail -1 | grep -q '^2\.02,stick,' ||
    fail "no stick at the tie at rtol $rtol"
  python3 -c "import json,sys; d=json.load(open(sys.argv[1]))
print(d['outcome']['final_phase'], d['outcome']['overturned'], d['sliding']['slips'],
      d['peaks']['impacts'], d['peaks']['chatter_cutoffs'], '%.6e' % d['peaks']['max_theta_rad'],
      '%.6e' % d['sliding']['final_offset_m'])" "$s" >"$WORK/outcome_$rtol"
done
cmp -s "$WORK/outcome_1e-9" "$WORK/outcome_1e-10" ||
  { cat "$WORK/outcome_1e-9" "$WORK/outcome_1e-10" >&2; fail "the outcome depends on rtol"; }
echo "ok: $(cat "$WORK/outcome_1e-9")"
