# SPDX-License-Identifier: BSD-3-Clause
"""Bodies, motions, options and results pickle and come back with the same state: every field
they show, and the same answers when run again, also in another process (multiprocessing)."""

import multiprocessing
import pickle

import numpy as np
import pytest

import flexrock as fr
from conftest import DATA


def _round(obj):
    return pickle.loads(pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL))


def _state(obj, seen=0):
    # every public attribute that is data (not a method), recursively for the library's structs
    if seen > 4:
        return obj
    if isinstance(obj, np.ndarray):
        return ("array", obj.dtype.str, obj.shape, obj.tobytes())
    if isinstance(obj, (list, tuple)):
        return [_state(v, seen + 1) for v in obj]
    if type(obj).__module__.startswith("flexrock") and not hasattr(type(obj), "__members__"):
        out = {}
        for name in dir(type(obj)):
            if name.startswith("_") or not isinstance(getattr(type(obj), name, None), property):
                continue
            out[name] = _state(getattr(obj, name), seen + 1)
        return out
    return obj


def _assert_same(a, b):
    assert type(a) is type(b)
    sa, sb = _state(a), _state(b)
    assert sa and sa == sb


def _body():
    return fr.Body(fr.BodyParameters.rectangular_block(mass=120.0, half_width=0.2, half_height=1.0))


def _cases():
    from conftest import CASES

    return CASES


def test_bodies_and_their_parameters():
    b = _body()
    r = _round(b)
    _assert_same(b, r)
    assert r.rocking_frequency == b.rocking_frequency and r.alpha1 == b.alpha1
    flexible = fr.load_body(str(_cases() / "flexible_tank.toml"))[0]
    assert flexible.kappa.size > 0
    _assert_same(flexible, _round(flexible))
    fb = fr.Body(flexible)
    rb = _round(fb)
    np.testing.assert_array_equal(rb.natural_frequencies, fb.natural_frequencies)
    np.testing.assert_array_equal(rb.params.kappa, fb.params.kappa)


def test_options_and_initial_state():
    o = fr.SimulationOptions()
    o.restitution_factor = 0.9
    o.t_end = 3.5
    o.friction_coefficient = 0.6
    m = fr.SimulationMethods()
    m.series_rocking = False
    o.methods = m
    r = _round(o)
    _assert_same(o, r)
    assert r.restitution_factor == 0.9 and r.methods.series_rocking is False
    assert r.friction_coefficient == 0.6
    s = fr.InitialState(theta=0.01, theta_dot=-0.2)
    _assert_same(s, _round(s))


@pytest.mark.parametrize("make", [
    lambda: fr.motion_from_file(DATA / "kobe_1995_nishi_akashi_090.AT2", scale=0.5),
    lambda: fr.motion_from_file(DATA / "A-CAT090.AT2.smc", vertical=DATA / "A-CAT180.AT2.smc"),
    lambda: fr.motion_from_array([0.0, 1.0, -0.5, 0.25], dt=0.01, units="g"),
    lambda: fr.one_sine_pulse(amplitude=0.3, units="g", frequency_hz=2.0, duration=3.0),
    lambda: fr.ricker_wavelet(amplitude_g=0.2, frequency_hz=1.5, duration=4.0).scaled(2.0),
    lambda: fr.free_rocking(2.0),
], ids=["at2", "smc_pair", "array", "one_sine", "ricker_scaled", "free"])
def test_motions_give_the_same_accelerations_and_runs(make):
    m = make()
    r = _round(m)
    assert (r.duration, r.samples, r.is_sampled, r.has_vertical) == (m.duration, m.samples, m.is_sampled,
                                                                     m.has_vertical)
    ts = np.linspace(0.0, m.duration * 1.01, 997)
    assert [r.at(t) for t in ts] == [m.at(t) for t in ts]
    assert getattr(r, "_flexrock_excitation", None) == getattr(m, "_flexrock_excitation", None)
    a, b = fr.simulate(_body(), m, t_end=min(m.duration, 3.0)), fr.simulate(_body(), r, t_end=min(m.duration, 3.0))
    assert a.time_history_csv() == b.time_history_csv()
    assert a.summary() == b.summary()


def test_a_motion_whose_function_cannot_be_saved_is_refused():
    with pytest.raises(TypeError, match="cannot pickle a synthetic GroundMotion"):
        pickle.dumps(fr.GroundMotion.none(1.0))


def test_results_of_simulate_and_of_a_case_file():
    m = fr.one_sine_pulse(amplitude=0.4, units="g", frequency_hz=1.5, duration=3.0)
    res = fr.simulate(_body(), m, output_dt=0.01)
    back = _round(res)
    _assert_same(res.raw, back.raw)
    assert back.time_history_csv() == res.time_history_csv()
    assert back.events_csv() == res.events_csv()
    assert back.summary() == res.summary()
    np.testing.assert_array_equal(back.history.theta, res.history.theta)
    assert [e.kind for e in back.events] == [e.kind for e in res.events] and len(res.events) > 0
    # a flexible body from a case file, its pulse rebuilt from the file
    case = fr.run_case(str(_cases() / "flexible_tank.toml"), output_dir=None)
    back = _round(case)
    _assert_same(case.raw, back.raw)
    assert back.summary() == case.summary() and back.time_history_csv() == case.time_history_csv()
    assert back.case.motion.at(0.5) == case.case.motion.at(0.5)
    _assert_same(case.case.options, back.case.options)


def _run(args):
    body, motion, options = args
    return fr.simulate(body, motion, options=options)


def test_multiprocessing_passes_them_between_processes():
    o = fr.SimulationOptions()
    o.t_end = 2.0
    o.output_dt = 0.02
    jobs = [(_body(), fr.one_sine_pulse(amplitude=a, units="g", frequency_hz=2.0, duration=2.0), o)
            for a in (0.2, 0.4)]
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        results = pool.map(_run, jobs)
    for job, r in zip(jobs, results):
        assert r.time_history_csv() == _run(job).time_history_csv()


def test_study_results_fits_and_run_summaries(tmp_path):
    f = fr.fragility([0.1, 0.2, 0.3, 0.4, 0.5, 0.6], [0, 1, 0, 1, 1, 1])
    g = _round(f)
    _assert_same(f, g)
    assert np.array_equal(fr.fragility_probability(f, [0.15, 0.3]), fr.fragility_probability(g, [0.15, 0.3]))
    for a, b in zip(fr.fragility_band(f, [0.15, 0.3]), fr.fragility_band(g, [0.15, 0.3])):
        np.testing.assert_array_equal(a, b)
    body = _body()
    res = fr.simulate(body, fr.one_sine_pulse(amplitude=0.5, units="g", frequency_hz=1.0, duration=3.0))
    s = fr.summarize(body, res.raw)
    _assert_same(s, _round(s))
    # what fragility_from_sweep returns: (FragilityData, FragilityFit) pairs
    sweep = tmp_path / "sweep.csv"
    cols = fr.sweep_columns()
    rows = [(0.1, 0), (0.2, 1), (0.3, 0), (0.4, 1), (0.5, 1), (0.6, 1)]
    with open(sweep, "w") as out:
        out.write(",".join(cols) + "\n")
        for i, (pga, over) in enumerate(rows):
            r = dict.fromkeys(cols, "0")
            r.update(index=str(i), body="b", record="r", requested_level=str(pga), requested_units="g",
                     pga_g=str(pga), pga_m_per_s2=str(pga * 9.80665), overturned=str(over),
                     outcome="overturned_after_impacts" if over else "rocking",
                     status="overturned" if over else "completed", message="")
            out.write(",".join(r[c] for c in cols) + "\n")
    ((data, fit),) = fr.fragility_from_sweep(str(sweep), im="pga_g")
    d2, f2 = _round((data, fit))
    _assert_same(data, d2)
    _assert_same(fit, f2)
    assert (d2.im_name, d2.im_unit) == ("pga_g", "g")
