# SPDX-License-Identifier: BSD-3-Clause
"""Figures follow matplotlib's habits (ax=, fig=, pyplot, PDF), the fragility plot, and
regressions: the loop's uplift moments, landings of flexible bodies, the bisected record
boundary, and `flexrock plot` on files that are empty, truncated or hold nan."""

import csv
import subprocess

import numpy as np
import pytest
from matplotlib.figure import Figure

import flexrock as fr
from flexrock import plots

G = 9.80665


def _gid(artists, gid):
    return [a for a in artists if a.get_gid() == gid]


@pytest.fixture(scope="module")
def cabinet(cases):
    # asymmetric: b1 != b2, and it rocks on both edges
    return fr.run_case(str(cases / "asymmetric_cabinet.toml"), output_dir=None)


def test_the_uplift_moments_lie_where_the_loop_does_on_an_asymmetric_body(cabinet):
    s = cabinet.summary()
    b = s["body"]
    assert b["b1_m"] != b["b2_m"]
    ax = plots.moment_rotation_loop(cabinet, fig=Figure())
    (g1,) = _gid(ax.lines, "uplift_moment_edge1")
    (g2,) = _gid(ax.lines, "uplift_moment_edge2")
    g = b["uplift_acceleration_edge1_m_per_s2"] / b["alpha1"]
    assert g1.get_ydata()[0] == pytest.approx(-b["mass_kg"] * g * b["b1_m"], rel=1e-12)
    assert g2.get_ydata()[0] == pytest.approx(b["mass_kg"] * g * b["b2_m"], rel=1e-12)
    # the data: on edge 1 the moment is -F_J b1, near -M g b1; on edge 2 +F_J b2, near +M g b2
    th = cabinet.time_history()
    moment = th["reaction_y_N"] * th["resultant_m"]
    for edge, guide, other in ((1, g1, g2), (2, g2, g1)):
        on = th["phase"] == edge
        assert np.count_nonzero(on) > 10
        mid = np.median(moment[on])
        assert abs(mid - guide.get_ydata()[0]) < abs(mid - other.get_ydata()[0])
        assert abs(mid - guide.get_ydata()[0]) < 0.2 * abs(guide.get_ydata()[0])


def test_landings_of_a_flexible_body_are_marked_apart_from_impacts(cases):
    r = fr.run_case(str(cases / "flexible_tank.toml"), output_dir=None)
    kinds = [e.kind.name for e in r.raw.events]
    fig = plots.response_figure(r, fig=Figure())
    th = fig.axes[1]
    marked = 0
    for kind in ("impact", "rocking_ended", "chatter_cutoff"):
        times = [e.time for e in r.raw.events if e.kind.name == kind]
        lines = _gid(th.lines, "impacts" if kind == "impact" else kind)
        if times:
            (line,) = lines
            np.testing.assert_array_equal(line.get_xdata(), times)
            marked += len(times)
        else:
            assert not lines
    # the case ends its rocking by landings that are no impacts: they must show
    assert "rocking_ended" in kinds or "chatter_cutoff" in kinds, kinds
    assert marked >= r.raw.extremes.impacts > 0
    styles = {ln.get_gid(): (ln.get_marker(), ln.get_color()) for ln in th.lines if ln.get_gid()}
    assert len(set(styles.values())) == len(styles)  # distinguishable


def test_the_record_spectrum_draws_the_bisected_minimum_scale(tmp_path):
    block = fr.Body(fr.rigid_block(0.4, 1.8, 800.0))
    t = np.arange(0.0, 3.0, 0.01)
    motion = fr.motion_from_array(np.sin(2 * np.pi * 1.5 * t) * (t < 1.0), dt=0.01, units="g")
    scales = [0.25, 0.5, 1.0, 1.5, 2.0]
    s = fr.record_spectrum(block, motion, scales, threads=2, bisection_tolerance=1e-3)
    (b,) = s.boundary
    assert b.kind.name == "found" and b.overturning not in scales
    ax = plots.spectrum_map(s, fig=Figure())
    (line,) = _gid(ax.lines, "min_overturning")
    assert line.get_ydata()[0] == pytest.approx(b.overturning, rel=1e-15)
    # the same from the CSV files `flexrock spectrum` would write
    csv_path, _ = fr.write_spectrum(s, tmp_path / "r.spectrum.csv", g=block.g)
    ax = plots.spectrum_map(csv_path, fig=Figure())
    (line,) = _gid(ax.lines, "min_overturning")
    assert line.get_ydata()[0] == pytest.approx(b.overturning, rel=1e-15)


def test_functions_draw_into_the_given_axes_or_a_pyplot_figure(cabinet, tmp_path):
    import matplotlib.pyplot as plt

    fig = Figure()
    ax = fig.add_subplot(1, 2, 2)
    assert plots.moment_rotation_loop(cabinet, ax=ax) is ax
    assert len(ax.lines) >= 3 and fig.axes == [ax]
    f = Figure()
    assert plots.response_figure(cabinet, fig=f) is f and len(f.axes) == 5  # rigid: no q panel
    # neither: a new pyplot figure, so that plt.show() shows it
    before = set(plt.get_fignums())
    ax = plots.moment_rotation_loop(cabinet)
    assert set(plt.get_fignums()) - before == {ax.figure.number}
    plt.close("all")


@pytest.mark.parametrize("ext,magic", [("png", b"\x89PNG"), ("svg", b"<?xml"), ("pdf", b"%PDF")])
def test_save_png_svg_and_pdf(cabinet, tmp_path, ext, magic):
    out = tmp_path / f"fig.{ext}"
    plots.save(plots.moment_rotation_loop(cabinet, fig=Figure()), out)
    assert out.read_bytes().startswith(magic)


def _sweep_csv(path, rows):
    cols = fr.sweep_columns()
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        for i, (level, pga_g, over) in enumerate(rows):
            r = dict.fromkeys(cols, "0")
            r.update(index=i, body="b", record=f"r{i % 2}", requested_level=level, requested_units="g",
                     pga_g=repr(pga_g), pga_m_per_s2=repr(pga_g * G), overturned=over,
                     outcome="overturned_after_impacts" if over else "rocking",
                     status="overturned" if over else "completed", message="")
            w.writerow([r[c] for c in cols])


@pytest.fixture()
def sweep_csv(tmp_path):
    # 4 levels x 4 records; pga_g carries the noise of a computed value
    rows = []
    fails = {0.1: [0, 0, 0, 1], 0.2: [0, 1, 0, 0], 0.3: [1, 1, 0, 1], 0.4: [1, 1, 1, 0]}
    for level, flags in fails.items():
        for k, y in enumerate(flags):
            rows.append((level, level * (1 + (k - 1.5) * 1e-15), y))
    path = tmp_path / "sweep.csv"
    _sweep_csv(path, rows)
    return path


def test_fragility_curve_draws_fit_band_and_observed_fractions(sweep_csv):
    ax = plots.fragility_curve(str(sweep_csv), im="pga_g", fig=Figure())
    ((data, fit),) = fr.fragility_from_sweep(str(sweep_csv), im="pga_g")
    (curve,) = _gid(ax.lines, "fit")
    x = np.asarray(curve.get_xdata())
    np.testing.assert_allclose(curve.get_ydata(), fr.fragility_probability(fit, x), rtol=1e-14)
    (band,) = _gid(ax.collections, "band")
    lo, hi = fr.fragility_band(fit, x)
    verts = band.get_paths()[0].vertices
    assert verts[:, 1].min() == pytest.approx(lo.min()) and verts[:, 1].max() == pytest.approx(hi.max())
    (obs,) = _gid(ax.collections, "observed")
    # one point per requested level, at the fraction of its runs that failed
    np.testing.assert_allclose(obs.get_offsets(), [[0.1, 0.25], [0.2, 0.25], [0.3, 0.75], [0.4, 0.75]], rtol=1e-12)


def test_flexrock_plot_draws_a_fragility_from_a_sweep_and_from_fragility_outputs(cli, sweep_csv, tmp_path):
    p = subprocess.run([str(cli), "plot", str(sweep_csv)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "sweep.fragility.png").read_bytes().startswith(b"\x89PNG")
    fit, curve = tmp_path / "fit.csv", tmp_path / "curve.csv"
    p = subprocess.run([str(cli), "fragility", str(sweep_csv), "--im", "pga_g", "-o", str(fit),
                        "--curve", str(curve), "-q"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    for src in (fit, curve):
        out = tmp_path / f"{src.stem}.pdf"
        p = subprocess.run([str(cli), "plot", str(src), "-o", str(out)], capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        assert out.read_bytes().startswith(b"%PDF")


def test_flexrock_plot_refuses_a_header_without_rows(cli, tmp_path):
    for header in (",".join(fr.time_history_columns(0)), ",".join(fr.spectrum_columns()),
                   ",".join(fr.sweep_columns())):
        f = tmp_path / "empty.csv"
        f.write_text(header + "\n")
        p = subprocess.run([str(cli), "plot", str(f)], capture_output=True, text=True)
        assert p.returncode == 2, p.stderr
        assert "Traceback" not in p.stderr
        assert p.stderr.startswith(f"flexrock: error: {f}") and "no data rows" in p.stderr, p.stderr
        assert not (tmp_path / "empty.png").exists()


def test_flexrock_plot_warns_of_truncated_rows_and_nan(cli, cases, tmp_path):
    subprocess.run([str(cli), "run", "-q", "-o", str(tmp_path), str(cases / "museum_statue.toml")],
                   check=True, capture_output=True)
    lines = (tmp_path / "museum_statue.csv").read_text().splitlines()
    cut = tmp_path / "cut.csv"
    cut.write_text("\n".join(lines[:200] + [lines[200][:30]]) + "\n")  # a run killed mid-write
    p = subprocess.run([str(cli), "plot", str(cut)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert f"flexrock: warning: {cut}:201:" in p.stderr and "left out" in p.stderr, p.stderr
    fields = lines[50].split(",")
    fields[2] = "nan"  # theta_rad
    bad = tmp_path / "nan.csv"
    bad.write_text("\n".join(lines[:50] + [",".join(fields)] + lines[51:]) + "\n")
    p = subprocess.run([str(cli), "plot", str(bad)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert "flexrock: warning:" in p.stderr and "theta_rad: 1 row(s) are nan" in p.stderr, p.stderr
