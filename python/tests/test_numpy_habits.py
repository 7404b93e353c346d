# SPDX-License-Identifier: BSD-3-Clause
"""Arrays in and out, pandas, the case file's units and names in Python, and reprs."""

import csv
import io
import math
import subprocess

import numpy as np
import pytest

import flexrock as fr

G = 9.80665


@pytest.fixture(scope="module")
def fit():
    rng = np.random.default_rng(7)
    x = np.exp(rng.uniform(-2.0, 1.0, 300))
    failed = (rng.uniform(size=x.size) < 0.5 * (1 + np.vectorize(math.erf)(np.log(x / 0.4) / 0.5 / math.sqrt(2)))).astype(int)
    return fr.fragility(x, failed)


def test_fragility_probability_and_band_broadcast_over_arrays(fit):
    x = np.array([[0.05, 0.2, 0.4], [0.8, 1.6, 3.2]])
    p = fr.fragility_probability(fit, x)
    assert isinstance(p, np.ndarray) and p.shape == x.shape
    # elementwise the scalar function, which stays a float for a scalar
    for i, v in np.ndenumerate(x):
        s = fr.fragility_probability(fit, float(v))
        assert isinstance(s, float) and p[i] == s
    # independent: the normal CDF of ln(x/theta)/beta
    ref = 0.5 * (1 + np.vectorize(math.erf)(np.log(x / fit.theta) / fit.beta / math.sqrt(2)))
    np.testing.assert_allclose(p, ref, rtol=1e-12, atol=1e-15)
    lo, hi = fr.fragility_band(fit, x)
    assert lo.shape == hi.shape == x.shape
    assert np.all(lo < p) and np.all(p < hi)
    assert fr.fragility_band(fit, 0.4) == (lo[0, 2], hi[0, 2])
    # a list broadcasts too, and x <= 0 gives 0
    np.testing.assert_array_equal(fr.fragility_probability(fit, [0.0, -1.0]), [0.0, 0.0])


def test_time_history_is_built_from_the_engine_arrays_equal_to_the_csv():
    p = fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0)
    r = fr.simulate(p, fr.one_sine_pulse(amplitude=0.6, units="g", frequency_hz=1.0, duration=3.0))
    th = r.time_history()
    from flexrock import _parse_csv

    ref = _parse_csv(r.time_history_csv())
    assert list(th) == list(ref) == fr.time_history_columns(2)
    for name in ref:
        assert th[name].dtype == np.float64
        np.testing.assert_array_equal(th[name], ref[name], err_msg=name)  # nan == nan here
    assert np.any(th["uplift_m"] > 0.0)
    ev = r.events_table()
    ref = _parse_csv(r.events_csv())
    assert list(ev) == list(ref)
    for name in ref:
        np.testing.assert_array_equal(ev[name], ref[name], err_msg=name)
    # no event: the same columns, empty, with the kinds' column still an object array
    quiet = fr.simulate(p, fr.free_rocking(0.5)).events_table()
    assert list(quiet) == fr.event_columns()
    assert all(len(v) == 0 for v in quiet.values())
    assert quiet["event"].dtype == object and quiet["time_s"].dtype == np.float64


def test_to_dataframe_equals_pandas_reading_the_csv():
    pd = pytest.importorskip("pandas")
    r = fr.simulate(fr.rigid_block(0.4, 1.8, 800.0), fr.one_sine_pulse(amplitude_g=0.5, frequency_hz=2.0, duration=3.0))
    df = r.to_dataframe()
    ref = pd.read_csv(io.StringIO(r.time_history_csv()), float_precision="round_trip")
    assert list(df.columns) == list(ref.columns)
    assert len(df) == len(r.history)
    for c in ref.columns:
        np.testing.assert_array_equal(df[c].to_numpy(dtype=float), ref[c].to_numpy(dtype=float), err_msg=c)


def test_pulses_take_the_case_file_keys_and_units(tmp_path):
    # a case file's one-sine pulse in g and Hz, and the same from Python's keywords
    case = tmp_path / "c.toml"
    case.write_text(
        '[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 1.8\nmass = 800.0\n'
        '[excitation.horizontal]\ntype = "one_sine"\namplitude = 0.3\nunits = "g"\n'
        'frequency_hz = 2.5\nduration = 3.0\n'
    )
    from_file = fr.load_case(str(case)).motion
    spellings = [
        fr.one_sine_pulse(amplitude=0.3, units="g", frequency_hz=2.5, duration=3.0),
        fr.one_sine_pulse(amplitude_g=0.3, period=0.4, duration=3.0),
        fr.one_sine_pulse(amplitude=0.3 * G, units="m/s^2", frequency_hz=2.5, duration=3.0),
        fr.one_sine_pulse(a_p=0.3 * G, omega_p=2 * math.pi * 2.5, duration=3.0),  # the SI form
    ]
    t = np.linspace(0.0, 0.45, 37)
    ref = np.array([from_file.at(v)[0] for v in t])
    for m in spellings:
        np.testing.assert_allclose([m.at(v)[0] for v in t], ref, rtol=1e-13, atol=1e-13)
    # the extra keys by their case-file names
    r = fr.ricker_wavelet(amplitude_g=0.2, frequency_hz=1.0, center=1.5, duration=4.0)
    assert abs(r.at(1.5)[0]) == pytest.approx(0.2 * G, rel=1e-12)
    box = fr.rectangular_pulse(amplitude_g=0.1, length=0.5, duration=1.0)
    assert box.at(0.25)[0] == pytest.approx(0.1 * G) and box.at(0.75)[0] == 0.0
    # the SI form: a_p, omega_p, duration, the keys' engine names
    w = 2 * math.pi
    same = fr.ricker_wavelet(a_p=0.2 * G, omega_p=w, duration=4.0, t_c=1.5)
    assert same.at(1.5)[0] == r.at(1.5)[0]
    assert fr.rectangular_pulse(a_p=0.1 * G, duration=1.0, t_1=0.5).at(0.25)[0] == box.at(0.25)[0]
    cyc = fr.harmonic_cycles(amplitude_g=0.1, frequency_hz=1.0, cycles=2, duration=4.0)
    assert cyc.at(2.25)[0] == 0.0 and cyc.at(1.25)[0] == pytest.approx(0.1 * G)
    with pytest.raises(fr.InputError, match="cycles: missing"):
        fr.harmonic_cycles(amplitude_g=0.1, frequency_hz=1.0, duration=4.0)
    with pytest.raises(TypeError, match="unexpected keyword argument 'centre'"):
        fr.ricker_wavelet(amplitude_g=0.2, frequency_hz=1.0, centre=1.5, duration=4.0)
    # the summary says the amplitude in m/s^2 whatever the spelling
    s = fr.simulate(fr.rigid_block(0.4, 1.8, 800.0), spellings[0]).summary()
    assert s["excitation"]["horizontal"]["amplitude_m_per_s2"] == pytest.approx(0.3 * G)


def test_pulse_spellings_that_mix_units_are_refused_with_the_new_spelling():
    with pytest.raises(fr.InputError, match=r'units="g"'):
        fr.one_sine_pulse(amplitude=0.3, frequency_hz=2.0, duration=3.0)  # amplitude without units
    with pytest.raises(fr.InputError, match="do not mix"):
        fr.one_sine_pulse(amplitude_g=0.3, omega_p=6.0, duration=3.0)
    with pytest.raises(fr.InputError, match="frequency_hz .Hz. or period"):
        fr.one_sine_pulse(amplitude_g=0.3, frequency_hz=2.0, period=0.5, duration=3.0)
    with pytest.raises(fr.InputError, match="a_p= is in SI units"):
        fr.one_sine_pulse(a_p=0.3, frequency_hz=2.0, duration=3.0)
    with pytest.raises(fr.InputError, match="units"):
        fr.one_sine_pulse(amplitude=0.3, units="furlong", frequency_hz=2.0, duration=3.0)


def test_a_spectrum_asked_in_g_and_hz_comes_back_in_g_and_hz(tmp_path):
    from matplotlib.figure import Figure

    from flexrock import plots

    block = fr.Body(fr.rigid_block(0.5, 3.0, 1000.0))
    amps_g, freqs_hz = [0.2, 0.4, 0.8], [1.0, 2.0]
    s = fr.spectrum(block, amps_g, freqs_hz, amplitude_units="g", frequency_units="Hz",
                    threads=2, bisection_tolerance=0.05)
    t = fr.spectrum_table(s, g=block.g)
    # unit-suffixed columns, holding the values given
    np.testing.assert_allclose(np.unique(t["a_p_g"]), amps_g, rtol=1e-14)
    np.testing.assert_allclose(np.unique(t["f_p_hz"]), freqs_hz, rtol=1e-14)
    np.testing.assert_allclose(t["a_p_m_per_s2"], t["a_p_g"] * block.g, rtol=1e-14)
    # the same spectrum as the SI spelling: its cells are these without the g and Hz columns
    si = fr.spectrum(block, [a * block.g for a in amps_g], [2 * math.pi * f for f in freqs_hz],
                     axes="physical", threads=2, bisection_tolerance=0.05)
    t_si = fr.spectrum_table(si, g=block.g)
    assert list(t_si) == [c for c in t if c not in ("a_p_g", "f_p_hz")]
    for c in t_si:
        np.testing.assert_array_equal(t[c], t_si[c])
    assert list(t) == fr.spectrum_columns(False, s.units)
    b = fr.boundary_table(s, g=block.g)
    np.testing.assert_array_equal(b["f_p_hz"], freqs_hz)  # the grid's numbers, not converted back
    found = np.array([k != "none" for k in b["kind"]])
    np.testing.assert_allclose(b["min_overturning_g"][found], b["min_overturning_m_per_s2"][found] / block.g,
                               rtol=1e-14)
    # the CSV written keeps them, and its plot draws in g and Hz as the result's does
    cells = str(tmp_path / "g.spectrum.csv")
    fr.write_spectrum(s, cells, g=block.g)
    ax = plots.spectrum_map(cells, fig=Figure())
    assert "[g]" in ax.get_ylabel() and "[Hz]" in ax.get_xlabel()
    # and drawn in g and Hz
    ax = plots.spectrum_map(s, fig=Figure())
    assert "[g]" in ax.get_ylabel() and "[Hz]" in ax.get_xlabel()
    curve = [ln for ln in ax.lines if ln.get_gid() == "min_overturning"]
    if found.any():
        np.testing.assert_allclose(curve[0].get_ydata(), b["min_overturning_g"][found])
    with pytest.raises(fr.InputError, match="frequency_units"):
        fr.spectrum(block, amps_g, freqs_hz, frequency_units="kHz")
    with pytest.raises(fr.InputError, match="only with axes"):
        fr.spectrum(block, amps_g, freqs_hz, axes="normalized", amplitude_units="g")


def test_sweep_levels_as_a_manifest_gives_them():
    body = fr.rigid_block(0.4, 1.8, 800.0)
    t = np.arange(0.0, 4.0, 0.01)
    records = {"a": fr.motion_from_array(np.sin(7.0 * t), dt=0.01),
               "b": fr.motion_from_array(0.37 * np.sin(9.0 * t) * np.exp(-t), dt=0.01)}
    levels = [0.1, 0.2, 0.3, 0.7]
    table = fr.sweep({"s": body}, records, target_pga=levels, units="g", threads=2)
    # one requested level per level whatever the record, exactly as given; pga_g is computed
    assert list(table["requested_level"]) == levels * 2
    assert set(table["requested_units"]) == {"g"}
    np.testing.assert_allclose(table["pga_g"], table["requested_level"], rtol=1e-12)
    # the older spelling (target PGAs in m/s^2) still runs the same sweep
    old = fr.sweep({"s": body}, records, [v * G for v in levels], target_pga=True, threads=2)
    assert set(old["requested_units"]) == {"m/s^2"}
    np.testing.assert_array_equal(old["outcome"], table["outcome"])
    f = fr.sweep({"s": body}, records, factors=[0.5, 2.0], threads=2)
    assert list(f["requested_level"]) == [0.5, 2.0, 0.5, 2.0] and set(f["requested_units"]) == {"-"}
    with pytest.raises(fr.InputError, match="exactly one of factors"):
        fr.sweep({"s": body}, records, threads=2)
    with pytest.raises(fr.InputError, match="units: only with target_pga"):
        fr.sweep({"s": body}, records, factors=[1.0], units="g")


def test_reprs_say_what_the_object_is(fit):
    p = fr.rigid_block(0.4, 1.8, 800.0)
    assert "M = 800 kg" in repr(p) and "rigid" in repr(p)
    b = fr.Body(fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0))
    assert repr(b).startswith("<Body ") and "2 mode(s) at" in repr(b) and "Hz" in repr(b)
    m = fr.motion_from_array([0.0, 1.0, -2.0, 0.5], dt=0.01)
    assert "4 samples" in repr(m) and "PGA = 2 m/s^2" in repr(m)
    pulse = repr(fr.one_sine_pulse(amplitude_g=0.3, frequency_hz=2.0, duration=3.0))
    assert "analytic" in pulse and "no vertical" in pulse and "PGA = 2.942 m/s^2 (0.3 g)" in pulse
    # every analytic motion could shake vertically (has_vertical() is true): the repr tells
    up = fr.one_sine_pulse(amplitude_g=0.2, frequency_hz=2.0, duration=3.0, component=fr.Component.vertical)
    assert "PGA = 0 m/s^2" in repr(up) and "with vertical: peak 1.961 m/s^2 (0.2 g)" in repr(up)
    assert "no vertical" in repr(fr.free_rocking(1.0))
    assert "no vertical" in repr(m)  # sampled, horizontal only
    assert repr(fit).startswith("<FragilityFit theta = ") and "95% bounds" in repr(fit)
    s = fr.spectrum(fr.Body(p), [1.5, 3.0], [2.0], bisect=False, threads=1)
    assert repr(s).startswith("<SpectrumResult 2 x 1 cells")


def test_record_repr(tmp_path):
    f = tmp_path / "r.txt"
    f.write_text("0.0\n0.1\n-0.25\n")
    r = fr.read_record(str(f), "single_column", dt=0.02, units="g")
    assert repr(r) == f"<Record {f}: 3 samples every 0.02 s, 0.04 s, peak 0.25 g>"


def test_contact_lost_rows_are_sorted_by_outcome_in_fragility_fits(tmp_path):
    # docs/studies.md: rows whose outcome is contact_lost or stopped are left out; a run with
    # status contact_lost that was past its overturning angle has an overturned outcome: a failure
    cols = fr.sweep_columns()
    rows = [
        (0.1, "rocking", "completed", 0), (0.2, "rocking", "completed", 0),
        (0.3, "overturned_after_impacts", "overturned", 1), (0.25, "rocking", "completed", 0),
        (0.15, "overturned_without_impact", "overturned", 1),
        (0.4, "overturned_after_impacts", "contact_lost", 1),  # counted: a failure
        (0.5, "contact_lost", "contact_lost", 0),  # left out
        (0.6, "stopped", "stopped", 0),  # left out
    ]
    path = tmp_path / "s.csv"
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        for i, (x, outcome, status, over) in enumerate(rows):
            r = dict.fromkeys(cols, "0")
            r.update(index=i, body="b", record="r", requested_units="g", pga_g=x, outcome=outcome,
                     status=status, overturned=over, message="")
            w.writerow([r[c] for c in cols])
    ((data, fit),) = fr.fragility_from_sweep(str(path), im="pga_g")
    assert data.excluded == 2
    assert list(data.im) == [0.1, 0.2, 0.3, 0.25, 0.15, 0.4]
    assert list(data.failed) == [0, 0, 1, 0, 1, 1]
    assert fit.samples == 6 and fit.failures == 3


def test_cli_fragility_says_what_it_left_out(cli, tmp_path):
    test_contact_lost_rows_are_sorted_by_outcome_in_fragility_fits(tmp_path)
    p = subprocess.run([str(cli), "fragility", str(tmp_path / "s.csv"), "--im", "pga_g"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert "6 runs (3 with the outcome, 2 runs stopped or lost contact: left out)" in p.stdout


def test_every_body_type_with_number_keys_has_its_keyword_function():
    # the functions are made from the library's table of body types: the case file's keys, in
    # its order and units, with its defaults; a case file's [body] gives the same parameters
    import inspect

    made = 0
    for kind in fr._flexrock.body_kinds():
        if not kind.numbers:
            assert kind.function == ""
            continue
        fn = getattr(fr, kind.function)
        assert [p.name for p in inspect.signature(fn).parameters.values()] == [k.name for k in kind.keys]
        for k in kind.keys:
            assert f"{k.name} : " in fn.__doc__ and f"[{k.unit}]" in fn.__doc__
        values = {k.name: 1.5 + 0.25 * i for i, k in enumerate(k for k in kind.keys if k.required)}
        by_name = fn(**values)
        positional = fn(*values.values())
        table = fr._flexrock.make_body(kind.name, values)
        for a in (by_name, positional):
            assert (a.mass, a.height, a.b1, a.zeta2) == (table.mass, table.height, table.b1, table.zeta2)
            np.testing.assert_array_equal(a.kappa, table.kappa)
        made += 1
    assert made >= 4
    with pytest.raises(TypeError):
        fr.rigid_block(0.4, 1.8)  # mass missing, as for any Python function
    with pytest.raises(TypeError):
        fr.rigid_block(0.4, 1.8, 800.0, depth=1.0)
    with pytest.raises(fr.InputError, match="modes must be an integer >= 1"):
        fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=1.5)
    with pytest.raises(fr.InputError, match="width"):
        fr.rigid_block(-0.4, 1.8, 800.0)


def test_pulse_values_are_keyword_only_a_bare_number_has_no_unit():
    # 0.3 meant as g and 2.0 as Hz were once read as 0.3 m/s^2 and 2.0 rad/s without a word
    for call in (lambda: fr.one_sine_pulse(0.3, 2.0, 3.0),
                 lambda: fr.one_sine_pulse(0.3, frequency_hz=2.0, duration=3.0),
                 lambda: fr.rectangular_pulse(0.1, 1.0, 0.5),
                 lambda: fr.harmonic_cycles(0.1, 6.0, 4.0, cycles=2)):
        with pytest.raises(TypeError, match=r"by keyword, with their units, not positionally"):
            call()
    with pytest.raises(TypeError, match=r"as SI values: a_p=0.3, omega_p=2.0, duration=3.0"):
        fr.one_sine_pulse(0.3, 2.0, 3.0)
