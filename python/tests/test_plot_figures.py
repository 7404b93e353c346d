# SPDX-License-Identifier: BSD-3-Clause
"""The figures engineers expect: a flexible body's landings marked from its history alone, a rigid
body's response without an empty panel, a time window on `flexrock plot`, and the IDA curves of a
sweep with each record's overturning margin, each checked against the run's own files."""

import csv
import subprocess

import numpy as np
import pytest
from matplotlib.figure import Figure

import flexrock as fr
from flexrock import plots


def _gid(artists, gid):
    return [a for a in artists if a.get_gid() == gid]


def _plot(cli, *args):
    return subprocess.run([str(cli), "plot", *map(str, args)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def tank(cli, cases, tmp_path_factory):
    # the shipped flexible tank as `flexrock run` writes it: a history and a summary, no event log
    out = tmp_path_factory.mktemp("tank")
    subprocess.run([str(cli), "run", "-q", "-o", str(out), str(cases / "flexible_tank.toml")],
                   check=True, capture_output=True)
    return out / "flexible_tank.csv"


@pytest.fixture(scope="module")
def sweep(cli, source_dir, tmp_path_factory):
    out = tmp_path_factory.mktemp("sweep") / "ida.csv"
    subprocess.run([str(cli), "sweep", "-q", str(source_dir / "examples/studies/sweep.toml"), "-o", str(out)],
                   check=True, capture_output=True)
    return out


def test_a_flexible_body_landings_are_marked_from_its_history(tank, cases):
    cols, events, summary = plots.load_run(str(tank))
    assert events is None and summary["peaks"]["impacts"] == 24
    fig = plots.response_figure(str(tank), fig=Figure())
    (marks,) = _gid(fig.axes[1].lines, "impacts")
    # against the event log of the same case run from Python: one mark at the first history row
    # after each landing (the tank lands on its base, rocking_ended: the pivot never changes edge)
    r = fr.run_case(str(cases / "flexible_tank.toml"), output_dir=None)
    impacts = [e.time for e in r.raw.events if e.kind.name in ("impact", "rocking_ended")]
    assert len(impacts) == r.raw.extremes.impacts == 24
    t = cols["time_s"]
    dt = summary["outputs"]["output_dt_s"]
    rows = sorted({int(np.searchsorted(t, x, side="right")) for x in impacts})
    np.testing.assert_array_equal(marks.get_xdata(), t[rows])
    assert all(0.0 < t[k] - max(x for x in impacts if x < t[k]) <= dt + 1e-12 for k in rows)
    assert "from the history" in marks.get_label()


def test_rigid_and_flexible_bodies_get_the_panels_they_have(tank, cases):
    rigid = fr.run_case(str(cases / "museum_statue.toml"), output_dir=None)
    fig = plots.response_figure(rigid, fig=Figure())
    assert [a.get_ylabel() for a in fig.axes] == [
        "base acc. [m/s²]", "θ [rad]", "reaction [N]", "friction demand [-]", "energy [J]"]
    fig = plots.response_figure(str(tank), fig=Figure())
    assert len(fig.axes) == 6 and fig.axes[2].get_ylabel() == "q [-]"
    assert [ln.get_label() for ln in fig.axes[2].lines] == ["q1", "q2"]


def test_flexrock_plot_takes_a_time_window(cli, tank, tmp_path):
    out = tmp_path / "w.svg"
    p = _plot(cli, tank, "--tlim", 1.5, 3, "-o", out)
    assert p.returncode == 0, p.stderr
    fig = plots.response_figure(str(tank), xlim=(1.5, 3.0), fig=Figure())
    assert fig.axes[-1].get_xlim() == (1.5, 3.0)
    # the loop keeps only the window's rows
    ax = plots.moment_rotation_loop(str(tank), tlim=(1.5, 3.0), fig=Figure())
    (loop,) = _gid(ax.lines, "loop")
    t = plots.load_run(str(tank))[0]["time_s"]
    assert len(loop.get_xdata()) == np.count_nonzero((t >= 1.5) & (t <= 3.0))
    p = _plot(cli, tank, "--kind", "loop", "--xlim", 1.5, 3, "-o", tmp_path / "l.png")
    assert p.returncode == 0, p.stderr
    # refused: a window backwards, or on a figure that has no time axis
    p = _plot(cli, tank, "--tlim", 3, 1, "-o", tmp_path / "x.png")
    assert p.returncode == 2 and "expected T0 < T1" in p.stderr
    assert not (tmp_path / "x.png").exists()


def test_ida_curves_follow_the_sweep_and_mark_each_record_margin(cli, sweep, tmp_path):
    with open(sweep, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["body"] == "statue"]
    ax = plots.ida_curves(str(sweep), body="statue", fig=Figure())
    margins = []
    for rec in ("elcentro", "kobe"):
        mine = sorted((float(r["pga_g"]), float(r["max_theta_over_alpha"]), r["overturned"] == "1")
                      for r in rows if r["record"] == rec)
        (curve,) = _gid(ax.lines, f"ida:{rec}")
        np.testing.assert_array_equal(curve.get_ydata(), [m[0] for m in mine if not m[2]])
        np.testing.assert_array_equal(curve.get_xdata(), [m[1] for m in mine if not m[2]])
        fallen = [m[0] for m in mine if m[2]]
        assert fallen, "the example sweep overturns the statue under both records"
        (marks,) = _gid(ax.lines, f"overturned:{rec}")
        np.testing.assert_array_equal(marks.get_ydata(), fallen)
        (margin,) = _gid(ax.lines, f"margin:{rec}")
        assert margin.get_ydata()[0] == min(fallen)
        margins.append(min(fallen))
    assert f"median {np.median(margins):.3g} g" in ax.get_title()
    # overturned runs stand in a column right of every standing run
    standing = [float(r["max_theta_over_alpha"]) for r in rows if r["overturned"] == "0"]
    assert min(marks.get_xdata()) > max(max(standing), 1.0)
    # the command line draws it; a sweep of two bodies needs --body
    p = _plot(cli, sweep, "--kind", "ida", "--body", "block", "--measure", "max_uplift_m", "-o", tmp_path / "i.png")
    assert p.returncode == 0, p.stderr
    p = _plot(cli, sweep, "--kind", "ida", "-o", tmp_path / "j.png")
    assert p.returncode == 2 and "choose one (body=, or --body" in p.stderr
    p = _plot(cli, sweep, "--kind", "ida", "--body", "statue", "--measure", "tilt", "-o", tmp_path / "k.png")
    assert p.returncode == 2 and "unknown response measure" in p.stderr
