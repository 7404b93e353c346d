# SPDX-License-Identifier: BSD-3-Clause
"""The Python API round trip: bodies, motions, simulate, results as numpy arrays and dicts."""

import math

import numpy as np
import pytest

import flexrock as fr


def test_rigid_block_builder_matches_housner_block_parameters():
    # a uniform block of full width 2b and height 2h is Housner's block of half-sizes b, h
    p = fr.rigid_block(width=0.4, height=1.8, mass=800.0)
    q = fr.BodyParameters.rectangular_block(800.0, 0.2, 0.9)
    assert (p.mass, p.height, p.b1, p.b2, p.zeta2) == (q.mass, q.height, q.b1, q.b2, q.zeta2)
    # zeta^2 = I/(M h^2) with I = M (w^2 + H^2)/12 of a uniform rectangle about its c.g.
    assert p.zeta2 == pytest.approx((0.4**2 + 1.8**2) / 12.0 / 0.9**2, rel=1e-14)
    body = fr.Body(p)
    assert body.modes == 0 and p.modes == 0
    assert body.alpha1 == pytest.approx(0.2 / 0.9, rel=1e-15)
    # Housner: p^2 = M g R / I_O = 3 g / (4 R) for a uniform block, R the half-diagonal
    R = math.hypot(0.2, 0.9)
    assert body.rocking_frequency == pytest.approx(math.sqrt(3 * 9.80665 / (4 * R)), rel=1e-12)


def test_every_builder_gives_a_valid_body_with_its_modes():
    assert fr.Body(fr.rigid_body(100.0, 20.0, 1.0, 0.3, 0.4)).modes == 0
    slab = fr.Body(fr.oscillator_on_slab(1000.0, 2.0, 500.0, 3.0, 1.5, damping_ratio=0.05))
    assert slab.modes == 1
    # the top mass on its spring, with the base pinned on both edges, keeps its fixed-base
    # frequency: the slab cannot move
    assert slab.natural_frequencies[0] == pytest.approx(2 * math.pi * 2.0, rel=1e-12)
    assert slab.damping_ratios[0] == pytest.approx(0.05, rel=1e-12)
    tank = fr.Body(fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0))
    assert tank.modes == 2 and tank.natural_frequencies[0] < tank.natural_frequencies[1]


def test_modal_data_input_equals_the_slab_builder():
    # the oscillator on a slab written as a lumped model: a top node and the slab as a node with
    # the slab's rotary inertia (the same body, so the same parameters)
    top, base, h, w, f = 1000.0, 500.0, 3.0, 1.5, 2.0
    m = fr.LumpedModel()
    m.nodes = [fr.LumpedNode(0.0, h, top), fr.LumpedNode(0.0, 0.0, base, base * w**2 / 12.0)]
    m.tip1_x, m.tip2_x = -w / 2, w / 2
    m.phi_x = np.array([[1.0], [0.0]])
    m.phi_y = np.array([[0.0], [0.0]])
    m.frequencies = np.array([2 * math.pi * f])
    p = fr.from_lumped_model(m)
    q = fr.oscillator_on_slab(top, f, base, h, w)
    assert p.mass == pytest.approx(q.mass) and p.height == pytest.approx(q.height)
    assert p.zeta2 == pytest.approx(q.zeta2, rel=1e-12)
    np.testing.assert_allclose(p.kappa, q.kappa, rtol=1e-12)
    np.testing.assert_allclose(p.mu, q.mu, rtol=1e-12)
    np.testing.assert_allclose(p.psi_x, q.psi_x, rtol=1e-12, atol=1e-15)


def test_parameters_round_trip_through_numpy():
    p = fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0)
    kappa = np.array(p.kappa)
    p2 = fr.BodyParameters()
    for name in ("mass", "height", "b1", "b2", "zeta2", "gravity"):
        setattr(p2, name, getattr(p, name))
    for name in ("mu", "kappa", "gamma", "psi_x", "psi_y", "delta", "beta"):
        setattr(p2, name, np.array(getattr(p, name)))
    np.testing.assert_array_equal(p2.kappa, kappa)
    b1, b2 = fr.Body(p), fr.Body(p2)
    np.testing.assert_array_equal(b1.natural_frequencies, b2.natural_frequencies)


def test_simulate_returns_numpy_histories_and_a_summary_with_the_cli_keys(cases, cli, tmp_path):
    body = fr.rigid_block(0.4, 1.8, 800.0)
    motion = fr.one_sine_pulse(a_p=0.5 * 9.80665, omega_p=2 * math.pi * 2.0, duration=3.0)
    r = fr.simulate(body, motion, name="pulse", output_dt=0.01)
    h = r.history
    assert isinstance(h.theta, np.ndarray) and h.theta.dtype == np.float64
    assert len(h) == h.time.size == h.theta.size == h.base_acc_x.size > 50
    # rows every 0.01 s up to where the run ended
    assert h.time[-1] == pytest.approx(r.t_end, abs=1e-12)
    np.testing.assert_allclose(np.diff(h.time)[:-1], 0.01, rtol=1e-9)
    assert h.q.shape == (len(h), 0)
    th = r.time_history()
    assert list(th) == fr.time_history_columns(0)
    np.testing.assert_array_equal(th["theta_rad"], h.theta)
    assert r.status in ("completed", "overturned")
    s = r.summary()
    assert s["schema"] == "flexrock.summary"
    assert s["case"]["name"] == "pulse"
    assert s["excitation"]["horizontal"] == {"type": "one_sine", "amplitude_m_per_s2": 0.5 * 9.80665}
    assert s["peaks"]["impacts"] == r.extremes.impacts
    # the same keys, at every level, as the summary `flexrock run` writes
    import json
    import subprocess

    subprocess.run([cli, "run", "-q", "-o", tmp_path, cases / "slender_column.toml"], check=True)
    ref = json.loads((tmp_path / "slender_column.summary.json").read_text())

    def keys(d, prefix=""):
        out = set()
        for k, v in d.items():
            out.add(prefix + k)
            if isinstance(v, dict) and k not in ("horizontal", "vertical"):
                out |= keys(v, prefix + k + ".")
        return out

    assert keys(s) == keys(ref)


def test_motion_from_array_in_g_equals_the_si_motion():
    acc_g = np.array([0.0, 0.1, -0.2, 0.05, 0.0])
    m = fr.motion_from_array(acc_g, dt=0.02, units="g")
    assert m.duration == pytest.approx(0.08)
    assert m.at(0.02) == (0.1 * 9.80665, 0.0)
    m2 = fr.motion_from_array(acc_g * 9.80665, time=np.arange(5) * 0.02)
    np.testing.assert_allclose(m2.horizontal, m.horizontal, rtol=1e-15)


def test_motion_from_file_equals_the_case_file_motion(cases):
    c = fr.load_case(str(cases / "museum_statue.toml"))
    m = fr.motion_from_file(str(cases.parent.parent.parent / "shared/data/elcentro_1940_ns.dat"),
                            "single_column", dt=0.02, units="g")
    np.testing.assert_array_equal(m.horizontal, c.motion.horizontal)
    np.testing.assert_array_equal(m.times, c.motion.times)


def test_mirror_symmetry_of_a_symmetric_block():
    # -ag gives -theta for a symmetric body: an independent check that the binding passes the
    # motion through unchanged
    body = fr.rigid_block(0.4, 1.8, 800.0)
    t = np.arange(0.0, 2.0, 0.01)
    a = 3.0 * np.sin(2 * math.pi * 1.5 * t)
    r1 = fr.simulate(body, fr.motion_from_array(a, dt=0.01))
    r2 = fr.simulate(body, fr.motion_from_array(-a, dt=0.01))
    assert r1.extremes.impacts == r2.extremes.impacts > 0
    np.testing.assert_allclose(r1.history.theta, -r2.history.theta, rtol=0, atol=1e-9)


def test_flexible_body_history_has_one_column_per_mode():
    p = fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0)
    r = fr.simulate(p, fr.harmonic(a_p=2.0, omega_p=10.0, duration=1.0), output_dt=0.01)
    assert r.history.q.shape == (len(r.history), 2)
    th = r.time_history()
    np.testing.assert_array_equal(th["q2"], r.history.q[:, 1])
    np.testing.assert_array_equal(th["q1_dot_per_s"], r.history.q_dot[:, 0])


def test_a_run_whose_energy_balance_does_not_close_says_so():
    # a cantilever rocking under 0.5 g: the default tolerances close the balance to ~1e-8 of
    # the scale; rtol = atol = 1e-3 leaves a residual of 2 % of it, above 1e-5 scale + 1e-10 M g h
    p = fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0)
    motion = fr.harmonic(a_p=0.5 * 9.81, omega_p=2.0, duration=4.0)
    ok = fr.simulate(p, motion)
    assert ok.extremes.impacts > 0
    assert not ok.energy_unbalanced
    assert all(e.kind != fr.EventKind.energy_unbalanced for e in ok.events)
    bad = fr.simulate(p, motion, rtol=1e-3, atol=1e-3)
    assert abs(bad.energy.residual) > 1e-3 * bad.energy.scale
    assert bad.energy_unbalanced
    assert bad.events[-1].kind == fr.EventKind.energy_unbalanced
    assert bad.events[-1].energy_loss == bad.energy.residual


def test_options_by_keyword_and_initial_state():
    body = fr.rigid_block(0.4, 1.8, 800.0)
    init = fr.InitialState(theta=0.1)
    r = fr.simulate(body, fr.free_rocking(2.0), init, output_dt=0.05, overturn="half_pi")
    assert r.case.options.overturn == fr.OverturnCriterion.half_pi
    assert r.history.theta[0] == 0.1
    assert r.extremes.impacts > 0
    # released from rest at theta0 < alpha the block cannot climb higher: energy is lost only
    assert np.max(np.abs(r.history.theta)) <= 0.1 + 1e-9
    with pytest.raises(fr.InputError, match="unknown option 'rtoll'"):
        fr.simulate(body, fr.free_rocking(1.0), rtoll=1e-9)


def test_result_write_produces_the_files(tmp_path):
    r = fr.simulate(fr.rigid_block(0.4, 1.8, 800.0), fr.one_sine_pulse(a_p=5.0, omega_p=12.0, duration=2.0))
    paths = r.write(tmp_path, time_history="a.csv", summary="a.summary.json", events="a.events.csv")
    assert (tmp_path / "a.csv").read_text() == r.time_history_csv()
    assert (tmp_path / "a.events.csv").read_text() == r.events_csv()
    import json

    s = json.loads((tmp_path / "a.summary.json").read_text())
    assert s["outputs"]["time_history"] == paths.time_history == str(tmp_path / "a.csv")


def test_load_body_reads_the_body_table(cases):
    p, kind = fr.load_body(str(cases / "museum_statue.toml"))
    q = fr.rigid_block(0.4, 1.8, 800.0)
    assert kind == "rigid_block"
    assert (p.mass, p.height, p.b1, p.b2, p.zeta2) == (q.mass, q.height, q.b1, q.b2, q.zeta2)


def test_impact_laws_by_name_and_the_restitution_ratio_exactly():
    body = fr.Body(fr.BodyParameters.rectangular_block(400.0, 0.2, 1.0))
    r = fr.simulate(body, fr.GroundMotion.none(5.0), fr.InitialState(theta=0.1), impact_law="restitution",
                    restitution_ratio_edge1=0.8, restitution_ratio_edge2=0.7)
    impacts = [e for e in r.raw.events if e.kind == fr.EventKind.impact]
    assert len(impacts) >= 4
    for e in impacts:
        assert e.theta_dot_after / e.theta_dot_before == pytest.approx(0.8 if e.edge == 1 else 0.7, rel=1e-14)
        # the force estimate: a half-sine pulse of the impulse over the assumed 2 ms
        assert e.force_estimate == pytest.approx(math.pi * math.hypot(e.impulse_x, e.impulse_y) / (2 * 0.002), rel=1e-12)
    assert r.raw.extremes.max_impact_force == pytest.approx(max(e.force_estimate for e in r.raw.events))
    with pytest.raises(fr.InputError, match="impact_law 'elastic'"):
        fr.simulate(body, fr.GroundMotion.none(1.0), impact_law="elastic")


def test_compliant_contact_by_name_resolves_the_contact_force():
    body = fr.Body(fr.BodyParameters.rectangular_block(400.0, 0.2, 1.0))
    p = body.params
    wv = 1000.0 * body.rocking_frequency  # omega_v = sqrt(2 k / M)
    k = 0.5 * p.mass * wv * wv
    r = fr.simulate(body, fr.GroundMotion.none(3.0), fr.InitialState(theta=0.1),
                    contact_model="compliant", contact_stiffness=k, contact_damping_ratio=4.0)
    touches = [e for e in r.raw.events if e.kind in (fr.EventKind.impact, fr.EventKind.landing)]
    assert len(touches) >= 4
    # the largest corner force of the run is the largest touch's peak or a resting share above it
    assert r.raw.extremes.max_contact_force >= max(e.force_estimate for e in touches) > p.mass * p.gravity
    assert abs(r.raw.energy.residual) < 1e-6 * r.raw.energy.scale
    # at rest the springs carry the weight, and the history is the force history
    rest = fr.simulate(body, fr.GroundMotion.none(1.0), contact_model="compliant", contact_stiffness=k)
    assert not rest.raw.events
    assert rest.raw.history.reaction_y == pytest.approx(p.mass * p.gravity, rel=1e-7)  # rtol 1e-9 noise
    with pytest.raises(fr.InputError, match="contact_model 'springs'"):
        fr.simulate(body, fr.GroundMotion.none(1.0), contact_model="springs")
    with pytest.raises(fr.InputError, match="contact_stiffness"):
        fr.simulate(body, fr.GroundMotion.none(1.0), contact_model="compliant")
