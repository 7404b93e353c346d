# SPDX-License-Identifier: BSD-3-Clause
"""Restraints from Python (docs/theory.md §26): the run, its statics, and a case's tables."""
import math

import flexrock as fr
import pytest


def block():
    return fr.Body(fr.BodyParameters.rectangular_block(1000.0, 0.25, 1.0))


def test_a_prestressed_tendon_raises_the_uplift_threshold_by_its_moment():
    b = block()
    t = fr.Restraint(kind=fr.RestraintKind.tendon, body_y=2.0, floor_y=-1.0, stiffness=1e6,
                     prestress=5000.0)
    g = b.params.gravity
    # g b / h + P0 b / (M h), the closed form of a central vertical tendon
    want = g * 0.25 / 1.0 + 5000.0 * 0.25 / (1000.0 * 1.0)
    assert fr.uplift_acceleration(b, [t], 1) == pytest.approx(want, rel=1e-12)
    assert fr.self_centring_stiffness(b, [], 1) == pytest.approx(-1000.0 * g * 1.0, rel=1e-12)


def test_a_restrained_run_reports_its_ties():
    b = block()
    anchors = [fr.Restraint(kind=fr.RestraintKind.anchor, body_x=x, floor_x=x, floor_y=-0.2,
                            stiffness=5e7, slack=2e-4, yield_force=1e4, fracture_elongation=0.01)
               for x in (-0.25, 0.25)]
    motion = fr.one_sine_pulse(a_p=0.9 * 9.80665, omega_p=2 * math.pi / 0.6, duration=3.0)
    opt = fr.SimulationOptions()
    opt.output_dt = 0.01
    r = fr.simulate_restrained(b, anchors, motion, fr.InitialState(), opt)
    assert r.force.shape == (len(r.result.history), 2)
    assert any(s.yielded for s in r.restraints)
    kinds = {e.kind for e in r.events}
    assert fr.RestraintEventKind.yield_ in kinds
    assert r.plastic_work > 0
    assert abs(r.result.energy.residual) < 1e-6 * r.result.energy.scale


def test_bad_restraints_are_a_value_error():
    with pytest.raises(ValueError, match="restraint 1: a slack and a prestress"):
        fr.simulate_restrained(block(), [fr.Restraint(body_y=1.0, floor_y=-1.0, prestress=10.0,
                                                      slack=1e-3)], fr.GroundMotion.none(1.0))


def test_a_case_file_carries_its_restraints(source_dir):
    c = fr.load_case(str(source_dir / "examples" / "cases" / "post_tensioned_pier.toml"))
    assert [t.kind for t in c.restraints] == [fr.RestraintKind.tendon, fr.RestraintKind.anchor,
                                              fr.RestraintKind.anchor]
    assert c.restraints[1].body_x == pytest.approx(-0.6)  # corner = 1: the left tipping point
    assert c.restraints[0].body_y == pytest.approx(6.0)   # a tendon's default: the top, 2 h
    body = fr.Body(c.body)
    r = fr.simulate_restrained(body, c.restraints, c.motion, c.initial, c.options)
    assert r.result.status == fr.Status.completed
    assert [s.yielded for s in r.restraints] == [False, True, True]


def test_run_case_refuses_restraints_rather_than_drop_them(source_dir, tmp_path):
    # the free body's run under the restrained case's name would be a wrong answer
    case = str(source_dir / "examples" / "cases" / "post_tensioned_pier.toml")
    with pytest.raises(fr.InputError, match=r"\[\[restraint\]\]: run it with flexrock.simulate_restrained"):
        fr.run_case(case, output_dir=str(tmp_path))
    with pytest.raises(fr.InputError, match="simulate_restrained"):
        fr.simulate_case(fr.load_case(case))
    assert not any(tmp_path.iterdir())
