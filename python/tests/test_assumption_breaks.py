# SPDX-License-Identifier: BSD-3-Clause
"""Where the sticking contact breaks without a friction limit, Python says so with the magnitudes:
a landing that needs a pulling impulse (tensile_landing) in the result's extremes, events,
summary and study summary; a finite friction coefficient removes it."""

import math

import flexrock as fr

G = 9.80665
# slenderness 0.25 rad (b/h = tan 0.25 to 6 digits), 2 m tall, 1 t; A = 20 g tan(alpha) at
# omega_p = 2 p, the period given to 7 digits as a case file would (tests/cli/assumption_breaks.sh)
HEIGHT, MASS, WIDTH = 2.0, 1000.0, 0.510684


def one_sine(body):
    return fr.one_sine_pulse(a_p=5.10684 * G, omega_p=2.0 * math.pi / 1.176638, duration=8.0)


def test_a_tensile_landing_is_reported_with_its_impulse():
    body = fr.rigid_block(width=WIDTH, height=HEIGHT, mass=MASS)
    r = fr.simulate(body, one_sine(body), name="one sine")
    x = r.raw.extremes
    pulls = [e.impulse_y for e in r.raw.events if e.kind == fr.EventKind.tensile_landing]
    assert x.tensile_landings == len(pulls) >= 1
    assert min(pulls) < 0.0
    assert x.max_tensile_impulse == -min(pulls)
    w = r.summary()["warnings"]
    assert w["tensile_landing"] is True
    assert w["tensile_landings"] == x.tensile_landings
    assert w["max_tensile_impulse_N_s"] == x.max_tensile_impulse
    table = r.events_table()
    kinds = list(table["event"])
    rows = [i for i, k in enumerate(kinds) if k == "tensile_landing"]
    assert [table["impulse_y_N_s"][i] for i in rows] == pulls
    s = fr.summarize(fr.Body(body), r.raw)
    assert s.tensile_landings == x.tensile_landings
    assert s.max_tensile_impulse == x.max_tensile_impulse
    # a finite friction coefficient: the landing slides, and nothing pulls
    f = fr.simulate(body, one_sine(body), name="one sine", friction_coefficient=0.5)
    assert f.raw.extremes.tensile_landings == 0
    assert f.raw.extremes.max_tensile_impulse == 0.0
    assert f.raw.extremes.max_pivot_pull == 0.0
    assert f.summary()["warnings"]["tensile_landing"] is False
