# SPDX-License-Identifier: BSD-3-Clause
"""Figures render with the Agg backend and hold the expected artists."""

import subprocess

import numpy as np
import pytest
from matplotlib.collections import QuadMesh
from matplotlib.figure import Figure

import flexrock as fr
from flexrock import plots


@pytest.fixture(scope="module")
def statue(cli, cases, tmp_path_factory):
    out = tmp_path_factory.mktemp("statue")
    subprocess.run([str(cli), "run", "-q", "-o", str(out), str(cases / "museum_statue.toml")],
                   check=True, capture_output=True)
    return out / "museum_statue.csv"


def _gid(artists, gid):
    return [a for a in artists if a.get_gid() == gid]


def test_response_figure_from_the_cli_outputs(statue):
    cols, events, summary = plots.load_run(str(statue))
    assert events is not None and summary is not None
    fig = plots.response_figure(str(statue), fig=Figure())
    assert len(fig.axes) == 5  # a rigid body: no deformation panel
    acc, th, r, f, e = fig.axes
    # one shaded span per stretch of rocking, on each edge it rocked on
    phase = cols["phase"]
    for edge in (1, 2):
        runs = np.count_nonzero((phase[1:] == edge) & (phase[:-1] != edge)) + (phase[0] == edge)
        assert len(_gid(th.patches, f"phase_edge{edge}")) == runs > 0
    # one marker per impact of the event log
    n_impacts = sum(1 for k in events["event"] if k == "impact")
    (marks,) = _gid(th.lines, "impacts")
    assert len(marks.get_xdata()) == n_impacts > 0
    np.testing.assert_array_equal(marks.get_xdata(), [t for t, k in zip(events["time_s"], events["event"]) if k == "impact"])
    assert len(acc.lines) == 1  # no vertical excitation in this case
    assert len(r.lines) == 2 and len(e.lines) == 6
    # the energy panel's residual closes: input work = stored + dissipated to 1e-6 relative
    res = e.lines[5].get_ydata()
    assert np.max(np.abs(res)) < 1e-6 * np.max(np.abs(e.lines[0].get_ydata()))


def test_response_figure_from_a_python_result_with_modes_and_vertical():
    p = fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0)
    t = np.arange(0.0, 3.0, 0.01)
    m = fr.motion_from_array(3.0 * np.sin(9.0 * t), dt=0.01, vertical=1.0 * np.sin(20.0 * t))
    r = fr.simulate(p, m)
    fig = plots.response_figure(r, fig=Figure())
    assert len(fig.axes) == 6
    assert len(fig.axes[0].lines) == 2  # horizontal and vertical
    assert len(fig.axes[2].lines) == 2  # q1, q2


def test_moment_rotation_loop(statue):
    ax = plots.moment_rotation_loop(str(statue), fig=Figure())
    loop = ax.lines[0]
    cols, _, summary = plots.load_run(str(statue))
    np.testing.assert_array_equal(loop.get_xdata(), cols["theta_rad"])
    # while rocking the moment about the c.g. projection is F_J times the pivot's lever b
    rocking = cols["phase"] == 1
    np.testing.assert_allclose(np.asarray(loop.get_ydata())[rocking],
                               -cols["reaction_y_N"][rocking] * summary["body"]["b1_m"], rtol=1e-12)


def _toy_spectrum(path):
    # a 3 x 2 grid in the `flexrock spectrum` layout with every outcome class
    cols = fr.spectrum_columns()
    rows = []
    outcomes = [["no_uplift", "no_uplift"], ["rocking", "overturned_after_impacts"],
                ["overturned_without_impact", "overturned_without_impact"]]
    for i, a in enumerate([0.5, 1.5, 2.5]):
        for j, w in enumerate([2.0, 4.0]):
            o = outcomes[i][j]
            row = {c: "0" for c in cols}
            row.update(row=str(i), column=str(j), a_p_over_g_tan_alpha=str(a), omega_p_over_p=str(w),
                       outcome=o, overturned="1" if o.startswith("overturned") else "0",
                       status="overturned" if o.startswith("overturned") else "completed", scale="")
            rows.append(",".join(row[c] for c in cols))
    path.write_text(",".join(cols) + "\n" + "\n".join(rows) + "\n")


def test_spectrum_map_cells_and_minimum_overturning_curve(tmp_path):
    f = tmp_path / "toy.csv"
    _toy_spectrum(f)
    ax = plots.spectrum_map(str(f), fig=Figure())
    (mesh,) = [c for c in ax.collections if isinstance(c, QuadMesh)]
    assert mesh.get_array().size == 6
    (curve,) = _gid(ax.lines, "min_overturning")
    np.testing.assert_array_equal(curve.get_xdata(), [2.0, 4.0])
    np.testing.assert_array_equal(curve.get_ydata(), [2.5, 1.5])
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    # the two overturning modes have their own legend entries and colours
    assert "overturned without impact" in labels and "overturned after impacts" in labels
    h = {t.get_text(): p for t, p in zip(ax.get_legend().get_texts(), ax.get_legend().legendHandles)}
    assert h["overturned without impact"].get_facecolor() != h["overturned after impacts"].get_facecolor()


@pytest.mark.parametrize("ext,magic", [("png", b"\x89PNG"), ("svg", b"<?xml")])
def test_save_png_and_svg(statue, tmp_path, ext, magic):
    out = tmp_path / f"fig.{ext}"
    plots.save(plots.moment_rotation_loop(str(statue), fig=Figure()), str(out))
    assert out.read_bytes().startswith(magic)
    with pytest.raises(ValueError, match=r"\.png, \.svg or \.pdf"):
        plots.save(plots.moment_rotation_loop(str(statue), fig=Figure()), str(tmp_path / "fig.jpg"))


def test_flexrock_plot_command(cli, statue, tmp_path):
    out = tmp_path / "statue.svg"
    p = subprocess.run([str(cli), "plot", str(statue), "-o", str(out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert out.read_bytes().startswith(b"<?xml") and b"<svg" in out.read_bytes()[:2000]
    p = subprocess.run([str(cli), "plot", str(statue), "--kind", "loop", "-o", str(tmp_path / "l.png")],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    spectrum = tmp_path / "toy.csv"
    _toy_spectrum(spectrum)
    p = subprocess.run([str(cli), "plot", str(spectrum)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "toy.png").read_bytes().startswith(b"\x89PNG")


def test_flexrock_plot_bad_input(cli, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("a,b\n1,2\n")
    p = subprocess.run([str(cli), "plot", str(bad)], capture_output=True, text=True)
    assert p.returncode == 2
    assert p.stderr.startswith("flexrock: error: ") and "bad.csv" in p.stderr
    assert not (tmp_path / "bad.png").exists()
    p = subprocess.run([str(cli), "plot", str(tmp_path / "missing.csv")], capture_output=True, text=True)
    assert p.returncode == 2 and "no such file" in p.stderr


def test_flexrock_plot_without_python(cli, statue, tmp_path):
    # no interpreter: a clear error and exit 1, nothing written
    import os

    env = dict(os.environ, FLEXROCK_PYTHON=str(tmp_path / "no-python3"))
    p = subprocess.run([str(cli), "plot", str(statue), "-o", str(tmp_path / "x.png")],
                       capture_output=True, text=True, env=env)
    assert p.returncode == 1
    assert "flexrock plot needs Python 3 with numpy and matplotlib" in p.stderr
    assert not (tmp_path / "x.png").exists()


def test_response_figure_from_a_lone_csv_marks_pivot_changes(statue, tmp_path):
    # without the event log next to it, impacts are taken where the pivot changes edge or the
    # impact loss rises: within one output interval after each landing of the event log
    import shutil

    lone = tmp_path / "alone.csv"
    shutil.copy(statue, lone)
    cols, events, summary = plots.load_run(str(lone))
    assert events is None and summary is None
    fig = plots.response_figure(str(lone), fig=Figure())
    (marks,) = _gid(fig.axes[1].lines, "impacts")
    _, logged, _ = plots.load_run(str(statue))
    landings = [t for t, k in zip(logged["time_s"], logged["event"]) if k in ("impact", "rocking_ended")]
    t = cols["time_s"]
    rows = sorted({int(np.searchsorted(t, x, side="right")) for x in landings})  # the row after each
    np.testing.assert_array_equal(marks.get_xdata(), t[rows])
    assert len(rows) > 0
