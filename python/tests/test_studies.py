# SPDX-License-Identifier: BSD-3-Clause
"""Spectra, sweeps and fragility fits from Python (thin: the library tests the physics)."""

import math

import numpy as np
import pytest
from matplotlib.figure import Figure

import flexrock as fr


@pytest.fixture(scope="module")
def block():
    return fr.Body(fr.rigid_block(0.5, 3.0, 1000.0))


def test_spectrum_cells_equal_single_simulations(block):
    amps, freqs = [0.8, 2.0, 6.0], [2.0, 6.0]
    r = fr.spectrum(block, amps, freqs, bisect=False, threads=2)
    assert len(r.cells) == 6 and len(r.boundary) == 0
    # below the static uplift acceleration (a_p < g tan alpha) nothing uplifts
    assert all(c.run.outcome.name == "no_uplift" for c in r.cells if c.amplitude == 0.8)
    # every cell equals the library's single-cell entry point (the threads change nothing)
    spec = fr.SpectrumSpec()
    spec.amplitudes, spec.frequencies = amps, freqs
    for c in r.cells:
        one = fr.run_pulse_cell(block, spec, c.amplitude_si, c.omega_si)
        assert (one.outcome, one.impacts, one.max_theta) == (c.run.outcome, c.run.impacts, c.run.max_theta)
    c = r.cells[1 * 2 + 1]
    # normalised units: a_p/(g tan alpha) and omega_p/p
    assert c.amplitude_si == pytest.approx(2.0 * block.g * block.alpha1, rel=1e-14)
    assert c.omega_si == pytest.approx(6.0 * block.rocking_frequency, rel=1e-14)


def test_spectrum_table_has_the_cli_columns_and_the_map_draws_it(block, tmp_path):
    r = fr.spectrum(block, [1.5, 4.0, 8.0], [1.5, 4.0], threads=2, bisection_tolerance=0.05)
    t = fr.spectrum_table(r, block.g)
    assert list(t) == fr.spectrum_columns()
    csv, boundary = fr.write_spectrum(r, tmp_path / "s.csv", g=block.g)
    assert boundary is not None
    from flexrock import plots

    ax = plots.spectrum_map(csv, fig=Figure())
    assert ax.figure.axes == [ax]
    ax2 = plots.spectrum_map(r, g=block.g, fig=Figure())
    assert ax2.figure.axes == [ax2]


def test_threads_do_not_change_a_spectrum(block):
    a = fr.spectrum(block, [1.5, 3.0, 6.0], [2.0, 5.0], threads=1, bisection_tolerance=0.05)
    b = fr.spectrum(block, [1.5, 3.0, 6.0], [2.0, 5.0], threads=3, bisection_tolerance=0.05)
    assert fr.spectrum_table(a).keys() == fr.spectrum_table(b).keys()
    assert fr._flexrock.spectrum_csv(a, 9.80665) == fr._flexrock.spectrum_csv(b, 9.80665)


def test_sweep_rows_and_fragility_fit():
    body = fr.rigid_block(0.3, 1.8, 600.0)
    t = np.arange(0.0, 4.0, 0.01)
    records = {"sine": fr.motion_from_array(np.sin(2 * math.pi * 1.0 * t), dt=0.01)}
    table = fr.sweep({"b": body}, records, [0.5, 1.0, 2.0, 4.0, 8.0], threads=2)
    assert list(table) == fr.sweep_columns()
    assert list(table["scale"]) == [0.5, 1.0, 2.0, 4.0, 8.0]
    np.testing.assert_allclose(table["pga_m_per_s2"], table["scale"] * 1.0, rtol=1e-6)
    # a fit of hand-made data: the lognormal model's median is where half fail
    im = np.array([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8])
    failed = [0, 0, 1, 0, 1, 0, 1, 1]
    fit = fr.fragility(im, failed)
    assert fit.samples == 8 and fit.failures == 4
    assert fr.fragility_probability(fit, fit.theta) == pytest.approx(0.5, abs=1e-12)
    lo, hi = fr.fragility_band(fit, 0.4)
    assert lo < fr.fragility_probability(fit, 0.4) < hi
    # the maximum: the log-likelihood drops when theta or beta moves
    ll = fr.lognormal_log_likelihood(im.tolist(), failed, fit.theta, fit.beta)
    assert ll == pytest.approx(fit.log_likelihood, rel=1e-10)
    assert fr.lognormal_log_likelihood(im.tolist(), failed, fit.theta * 1.05, fit.beta) < ll


def test_study_input_errors_are_input_errors(block):
    with pytest.raises(fr.InputError):
        fr.spectrum(block, [2.0, 1.0], [1.0])  # amplitudes must increase
    with pytest.raises(fr.InputError):
        fr.fragility([0.1, 0.2], [0, 0])  # all outcomes equal


def test_spectrum_file_from_python_equals_flexrock_spectrum(cli, source_dir, tmp_path):
    # the same spec through `flexrock spectrum` and through Python: the same CSV bytes; then
    # `flexrock plot` draws the map with the boundary file found next to the cells
    import subprocess

    spec = source_dir / "examples" / "studies" / "one_sine_block.toml"
    cells = tmp_path / "block.spectrum.csv"
    p = subprocess.run([str(cli), "spectrum", str(spec), "-o", str(cells), "-q", "-j", "2"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    f = fr.load_spectrum_file(str(spec))
    r = fr.compute_spectrum(fr.Body(f.body), f.pulse, 2)
    g = f.body.gravity
    assert fr.spectrum_csv(r, g) == cells.read_text()
    assert fr.boundary_csv(r, f.pulse.normalized, g) == (tmp_path / "block.boundary.csv").read_text()

    from flexrock import plots

    ax = plots.spectrum_map(str(cells), fig=Figure())
    (curve,) = [ln for ln in ax.lines if ln.get_gid() == "min_overturning"]
    found = [k != "none" for k in plots._read_columns(str(tmp_path / "block.boundary.csv"))["kind"]]
    assert len(curve.get_xdata()) == sum(found) > 0
    p = subprocess.run([str(cli), "plot", str(cells), "-o", str(tmp_path / "map.svg")],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "map.svg").exists()


def test_sweep_and_fragility_from_python_equal_the_cli(cli, source_dir, tmp_path):
    import subprocess

    manifest = source_dir / "examples" / "studies" / "sweep.toml"
    out = tmp_path / "sweep.csv"
    p = subprocess.run([str(cli), "sweep", str(manifest), "-o", str(out), "-q", "-j", "2"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    m = fr.load_sweep_manifest(str(manifest))
    rows = fr.run_sweep(m.spec, [], 2)
    text = ",".join(fr.sweep_columns()) + "\n" + "".join(fr.sweep_row(m.spec, r) + "\n" for r in rows)
    assert text == out.read_text()

    fit_csv = tmp_path / "fit.csv"
    p = subprocess.run([str(cli), "fragility", str(out), "--im", "pga_g", "-o", str(fit_csv)],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    fits = fr.fragility_from_sweep(str(out), im="pga_g")
    text = ",".join(fr.fragility_columns()) + "\n" + "".join(
        fr.fragility_row(d, f) + "\n" for d, f in fits)
    assert text == fit_csv.read_text()


def test_suite_manifest_from_python_equals_the_cli(cli, source_dir, tmp_path):
    import subprocess

    # two PEER-style pairs: a small horizontal sine, a vertical step of 1.5 g down at 0.5 s
    d = tmp_path / "peer"
    d.mkdir()
    n, dt = 200, 0.01
    for k in (1, 2):
        for comp, vals in (("H1", [0.05 * k * math.sin(4 * math.pi * i * dt) for i in range(n)]),
                           ("UP", [-1.5 if 50 <= i < 70 else 0.0 for i in range(n)])):
            lines = ["PEER", "SYNTHETIC", "ACCELERATION TIME SERIES IN UNITS OF G",
                     f"NPTS= {n}, DT= {dt:.4f} SEC"] + ["%15.7E" % v for v in vals]
            (d / f"RSN{k}_{comp}.AT2").write_text("\n".join(lines) + "\n")
    manifest = tmp_path / "suite.toml"
    body = source_dir / "examples" / "studies" / "slender_block.toml"
    manifest.write_text(f'free_periods = 1\n[[body]]\nfile = "{body}"\n[[suite]]\n'
                        'horizontal = "peer/*_H1.AT2"\nvertical = "peer/*_UP.AT2"\n'
                        "[scales]\nfactors = [0.5, 1.0]\n")
    out = tmp_path / "suite.csv"
    p = subprocess.run([str(cli), "sweep", str(manifest), "-o", str(out), "-q", "-j", "2"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    m = fr.load_sweep_manifest(str(manifest))
    assert [r.name for r in m.spec.records] == ["RSN1_H1+RSN1_UP", "RSN2_H1+RSN2_UP"]
    assert all(r.motion.has_vertical for r in m.spec.records)
    rows = fr.run_sweep(m.spec, [], 1)
    text = ",".join(fr.sweep_columns()) + "\n" + "".join(fr.sweep_row(m.spec, r) + "\n" for r in rows)
    assert text == out.read_text()
    # the vertical, scaled with its horizontal: 0.75 g down keeps the block down, 1.5 g lifts it
    assert [r.run.first_uplift_time >= 0 for r in rows] == [False, True, False, True]


def test_intensity_measures_table_and_a_sweep_with_them():
    names = [m["name"] for m in fr.intensity_measures()]
    assert names[:2] == ["pga", "pgv"] and "arias" in names and "sa" in names
    # Arias intensity and CAV by hand: a = 0, 2, -2, 0 at 1 s steps
    t, a = [0.0, 1.0, 2.0, 3.0], [0.0, 2.0, -2.0, 0.0]
    assert fr.intensity_measure("arias", t, a) == pytest.approx(math.pi / (2 * 9.80665) * 4.0, rel=1e-14)
    assert fr.intensity_measure("cav", t, a) == pytest.approx(3.0, rel=1e-14)
    with pytest.raises(fr.InputError):
        fr.intensity_measure("pgx", t, a)
    # a sweep with measures: the columns after pgv, each scaled with its power
    body = fr.rigid_block(0.2, 1.0, 600.0)
    tt = np.arange(0.0, 4.0, 0.01)
    rec = fr.motion_from_array(3.0 * np.sin(9.0 * tt), dt=0.01)
    table = fr.sweep({"b": body}, {"r": rec}, factors=[1.0, 2.0], measures=["arias", "d5_95"],
                     sa_periods=[0.5])
    cols = list(table)
    i = cols.index("pgv_m_per_s")
    assert cols[i + 1:i + 4] == ["arias_m_per_s", "d5_95_s", "sa_T0.5_z0.05_m_per_s2"]
    assert table["arias_m_per_s"][1] == pytest.approx(4.0 * table["arias_m_per_s"][0], rel=1e-14)
    assert table["d5_95_s"][1] == table["d5_95_s"][0]
    assert table["sa_T0.5_z0.05_m_per_s2"][1] == pytest.approx(2.0 * table["sa_T0.5_z0.05_m_per_s2"][0], rel=1e-14)


def test_stripe_and_capacity_fits_equal_the_cli(cli, tmp_path):
    import csv
    import subprocess

    # a sweep-like CSV of three records at five stripes, written here, fitted both ways
    rng = np.random.default_rng(5)
    levels, rows = [0.1, 0.2, 0.3, 0.4, 0.5], []
    cap = {f"r{k}": 0.28 * math.exp(0.4 * rng.standard_normal()) for k in range(30)}
    for rec, c in cap.items():
        for lv in levels:
            rows.append((rec, lv, int(lv >= c)))
    cols = fr.sweep_columns()
    path = tmp_path / "s.csv"
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        for i, (rec, lv, y) in enumerate(rows):
            r = dict.fromkeys(cols, "0")
            r.update(index=i, body="b", record=rec, requested_level=repr(lv), requested_units="g",
                     pga_g=repr(lv), outcome="overturned_after_impacts" if y else "rocking",
                     overturned=y, status="overturned" if y else "completed", message="")
            w.writerow([r[c] for c in cols])
    for analysis in ("msa", "ida"):
        out = tmp_path / f"{analysis}.csv"
        args = [str(cli), "fragility", str(path), "--analysis", analysis, "-o", str(out), "-q"]
        if analysis == "ida":
            args += ["--im", "pga_g"]
        p = subprocess.run(args, capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        got = next(csv.DictReader(open(out)))
        if analysis == "msa":
            n = [sum(1 for r in rows if r[1] == lv) for lv in levels]
            z = [sum(r[2] for r in rows if r[1] == lv) for lv in levels]
            fit = fr.fit_stripes(levels, n, z)
        else:
            lower, upper = fr.capacity_intervals([r[1] for r in rows], [r[2] for r in rows],
                                                 [r[0] for r in rows])
            assert len(lower) == 30 and all(u > lo for lo, u in zip(lower, upper))
            fit = fr.fit_capacity_intervals(lower, upper)
        assert float(got["theta"]) == pytest.approx(fit.theta, rel=1e-12)
        assert float(got["beta"]) == pytest.approx(fit.beta, rel=1e-12)


def test_sweep_at_sa_stripes_reaches_its_targets():
    body = fr.rigid_block(0.2, 1.0, 600.0)
    t = np.arange(0.0, 4.0, 0.01)
    rec = fr.motion_from_array(3.0 * np.sin(9.0 * t) * np.exp(-0.3 * t), dt=0.01)
    table = fr.sweep({"b": body}, {"r": rec}, target_im="sa:0.5", targets=[0.1, 0.3],
                     sa_periods=[0.5])
    assert list(table["requested_units"]) == ["g", "g"]
    np.testing.assert_allclose(table["sa_T0.5_z0.05_m_per_s2"], [0.1 * 9.80665, 0.3 * 9.80665],
                               rtol=1e-12)
    with pytest.raises(fr.InputError):
        fr.sweep({"b": body}, {"r": rec}, target_im="d5_95", targets=[1.0])
