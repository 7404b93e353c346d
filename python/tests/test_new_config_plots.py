# SPDX-License-Identifier: BSD-3-Clause
"""Pictures of the newer configurations, read back from the figures and compared with the runs'
own files: a support's panel (docs/theory.md §24), the restraints' forces with their yields and
fractures (§26), the 3D body of revolution's tilt orbit and contact path (§27), and histories
without those columns drawn with the panels they always had."""

import csv
import shutil
import subprocess

import numpy as np
import pytest
from matplotlib.figure import Figure

from conftest import DATA
from flexrock import plots

PLANAR_PANELS = ["base acc. [m/s²]", "θ [rad]", "reaction [N]", "friction demand [-]", "energy [J]"]


def _gid(artists, gid):
    return [a for a in artists if a.get_gid() == gid]


def _run(cli, case, out):
    out.mkdir(parents=True, exist_ok=True)
    subprocess.run([str(cli), "run", "-q", "-o", str(out), str(case)], check=True, capture_output=True)


def _plot(cli, *args):
    return subprocess.run([str(cli), "plot", *map(str, args)], capture_output=True, text=True)


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def _panel(fig, title):
    (ax,) = [a for a in fig.axes if a.get_title(loc="left") == title]
    return ax


@pytest.fixture(scope="module")
def platform(cli, cases, tmp_path_factory):
    out = tmp_path_factory.mktemp("platform")
    _run(cli, cases / "statue_on_platform.toml", out)
    return out / "statue_on_platform.csv"


@pytest.fixture(scope="module")
def pier(cli, cases, tmp_path_factory):
    out = tmp_path_factory.mktemp("pier")
    _run(cli, cases / "post_tensioned_pier.toml", out)
    return out / "post_tensioned_pier.csv"


@pytest.fixture(scope="module")
def cask(cli, tmp_path_factory):
    # the cask-like cylinder of tests/cli/body_of_revolution.sh under the RSN 8884 pair: 3D
    out = tmp_path_factory.mktemp("cask")
    case = out / "cask.toml"
    case.write_text(
        '[body]\ntype = "cylinder"\nradius = 1.7\nheight = 5.9\nmass = 120000.0\n'
        "[excitation]\nscale = 3.0\n"
        f'[excitation.horizontal]\ntype = "record"\nfile = "{DATA / "RSN8884_14383980_13873090.AT2"}"\n'
        f'[excitation.horizontal2]\ntype = "record"\nfile = "{DATA / "RSN8884_14383980_13873360.AT2"}"\n'
        '[output]\ndt = 0.01\nevents = "cask.events.csv"\n'
    )
    _run(cli, case, out)
    return out / "cask.csv"


def test_a_support_gets_one_panel_of_its_displacement_and_force(platform):
    cols = plots.load_run(str(platform))[0]
    fig = plots.response_figure(str(platform), fig=Figure())
    ax = _panel(fig, "support displacement / force")
    assert ax.get_ylabel() == "support u [m]"
    # the planar panels keep their places; the support's sits after the reactions
    assert [a.get_ylabel() for a in fig.axes[:6]] == PLANAR_PANELS[:3] + ["support u [m]"] + PLANAR_PANELS[3:]
    (u,) = _gid(ax.lines, "support_u")
    np.testing.assert_array_equal(u.get_xdata(), cols["time_s"])
    np.testing.assert_array_equal(u.get_ydata(), cols["support_u_m"])
    # the force on a twin of the panel (the last of fig.axes), in its own unit
    (twin,) = [a for a in fig.axes if a.get_ylabel() == "support force [N]"]
    assert twin is fig.axes[-1] and len(fig.axes) == 7
    (force,) = _gid(twin.lines, "support_force")
    np.testing.assert_array_equal(force.get_ydata(), cols["support_force_N"])
    # the same history without the support's columns draws the planar figure
    bare = {k: v for k, v in cols.items() if not k.startswith("support_")}
    fig = plots.response_figure(bare, fig=Figure())
    assert [a.get_ylabel() for a in fig.axes] == PLANAR_PANELS


def test_restraints_get_a_line_each_with_their_yields_marked(pier):
    cols = plots.load_run(str(pier))[0]
    events = _rows(pier.parent / "post_tensioned_pier.events.restraints.csv")
    assert {e["event"] for e in events} >= {"yield"}  # the example's anchors yield
    fig = plots.response_figure(str(pier), fig=Figure())
    assert [a.get_ylabel() for a in fig.axes] == PLANAR_PANELS[:3] + ["restraint force [N]"] + PLANAR_PANELS[3:]
    ax = _panel(fig, "restraint forces")
    for i in (1, 2, 3):
        (line,) = _gid(ax.lines, f"restraint_{i}")
        assert line.get_label() == f"restraint {i}"
        np.testing.assert_array_equal(line.get_ydata(), cols[f"restraint_force_N_{i}"])
        mine = [e for e in events if int(e["restraint"]) == i and e["event"] == "yield"]
        marks = _gid(ax.lines, f"restraint_{i}_yield")
        if not mine:  # the tendon stays elastic: no mark
            assert not marks
            continue
        (marks,) = marks
        np.testing.assert_array_equal(marks.get_xdata(), [float(e["time_s"]) for e in mine])
        np.testing.assert_array_equal(marks.get_ydata(), [float(e["force_N"]) for e in mine])
    assert "yield" in [t.get_text() for t in ax.get_legend().get_texts()]
    # the ties' plastic work is not a column: the energy panel's residual says it holds it
    assert any("plastic" in ln.get_label() for ln in fig.axes[-1].lines)
    # the history alone (no summary, no event log next to it): the lines, no marks
    alone = pier.parent / "alone"
    alone.mkdir()
    shutil.copy(pier, alone / "pier.csv")
    ax = _panel(plots.response_figure(str(alone / "pier.csv"), fig=Figure()), "restraint forces")
    assert len(ax.lines) == 3 and not [ln for ln in ax.lines if ln.get_gid().endswith("_yield")]
    # the summary without the ties' event log: the summary's copy of the events marks them
    shutil.copy(pier.parent / "post_tensioned_pier.summary.json", alone / "pier.summary.json")
    ax = _panel(plots.response_figure(str(alone / "pier.csv"), fig=Figure()), "restraint forces")
    (marks,) = _gid(ax.lines, "restraint_3_yield")
    np.testing.assert_array_equal(
        marks.get_xdata(), [float(e["time_s"]) for e in events if e["restraint"] == "3" and e["event"] == "yield"])
    # without the restraints' columns: the planar figure
    bare = {k: v for k, v in cols.items() if not k.startswith("restraint_")}
    assert [a.get_ylabel() for a in plots.response_figure(bare, fig=Figure()).axes] == PLANAR_PANELS


def test_a_broken_anchor_is_marked_where_it_broke(cli, cases, tmp_path):
    # the pier with anchors that break after 4 mm: each anchor's fracture event, at its force
    text = (cases / "post_tensioned_pier.toml").read_text()
    text = text.replace("../../../shared/data", str(DATA)).replace("fracture_elongation = 0.025", "fracture_elongation = 0.004")
    (tmp_path / "brittle.toml").write_text(text)
    _run(cli, tmp_path / "brittle.toml", tmp_path)
    # the event log is named by the case ([output] events), the ties' beside it
    broken = [e for e in _rows(tmp_path / "post_tensioned_pier.events.restraints.csv") if e["event"] == "fracture"]
    assert sorted(int(e["restraint"]) for e in broken) == [2, 3]
    ax = _panel(plots.response_figure(str(tmp_path / "brittle.csv"), fig=Figure()), "restraint forces")
    for e in broken:
        (mark,) = _gid(ax.lines, f"restraint_{e['restraint']}_fracture")
        assert list(mark.get_xdata()) == [float(e["time_s"])]
        assert list(mark.get_ydata()) == [float(e["force_N"])]
    assert "fracture" in [t.get_text() for t in ax.get_legend().get_texts()]


def test_histories_without_the_new_columns_draw_as_before(cli, cases, tmp_path):
    _run(cli, cases / "museum_statue.toml", tmp_path)
    fig = plots.response_figure(str(tmp_path / "museum_statue.csv"), fig=Figure())
    assert [a.get_ylabel() for a in fig.axes] == PLANAR_PANELS
    assert all("plastic" not in ln.get_label() for ln in fig.axes[-1].lines)


def test_the_body_of_revolution_draws_its_orbit_and_contact_path(cask):
    cols, events, summary = plots.load_rim(str(cask))
    assert summary["engine"] == "3d_body_of_revolution" and events is not None
    fig = plots.rim_figure(str(cask), fig=Figure())
    axes = {a.get_label(): a for a in fig.axes}
    assert list(axes)[:5] == ["tilt", "tilt azimuth", "contact angle", "tilt orbit", "contact path"]
    (tilt,) = _gid(axes["tilt"].lines, "tilt")
    np.testing.assert_array_equal(tilt.get_xdata(), cols["time_s"])
    np.testing.assert_array_equal(tilt.get_ydata(), cols["tilt_rad"])
    (az,) = _gid(axes["tilt azimuth"].lines, "tilt_azimuth")
    np.testing.assert_array_equal(az.get_ydata(), cols["tilt_azimuth_deg"])
    (ca,) = _gid(axes["contact angle"].lines, "contact_angle")
    np.testing.assert_array_equal(ca.get_ydata(), cols["contact_angle_deg"])
    # the orbit: polar, angle = the tilt's azimuth, radius = its magnitude
    assert axes["tilt orbit"].name == "polar"
    (orbit,) = _gid(axes["tilt orbit"].lines, "orbit")
    np.testing.assert_allclose(orbit.get_xdata(), np.radians(cols["tilt_azimuth_deg"]), rtol=0, atol=1e-15)
    np.testing.assert_array_equal(orbit.get_ydata(), cols["tilt_rad"])
    assert max(orbit.get_ydata()) <= summary["max_tilt_rad"] * (1 + 1e-12)
    # the path: a dot a row on the rim, on the base circle of the summary's radius
    (path,) = _gid(axes["contact path"].collections, "contact_path")
    on_rim = cols["mode"] != 0
    assert 0 < on_rim.sum() < len(on_rim)  # it stood, then lifted off
    c = np.radians(cols["contact_angle_deg"][on_rim])
    radius = summary["body"]["base_radius_m"]
    np.testing.assert_allclose(path.get_offsets(), np.column_stack([radius * np.cos(c), radius * np.sin(c)]),
                               rtol=0, atol=1e-12)
    np.testing.assert_array_equal(path.get_array(), cols["time_s"][on_rim])
    (circle,) = _gid(axes["contact path"].lines, "base_circle")
    np.testing.assert_allclose(np.hypot(circle.get_xdata(), circle.get_ydata()), radius, rtol=1e-12)
    # the events at their times and tilts; the rolling shaded where the mode says
    uplifts = [i for i, k in enumerate(events["kind"]) if k == "uplift"]
    (marks,) = _gid(axes["tilt"].lines, "event_uplift")
    np.testing.assert_array_equal(marks.get_xdata(), events["time_s"][uplifts])
    assert _gid(axes["tilt"].patches, "mode1")
    # a planar history is not one
    with pytest.raises(ValueError, match="tilt_azimuth_deg"):
        plots.rim_figure({"time_s": cols["time_s"], "theta_rad": cols["tilt_rad"]}, fig=Figure())


def test_flexrock_plot_picks_each_figure_by_the_header(cli, cask, pier, platform, tmp_path):
    for csv_path, name in ((cask, "rim.png"), (pier, "pier.png"), (platform, "platform.svg")):
        out = tmp_path / name
        p = _plot(cli, csv_path, "-o", out)
        assert p.returncode == 0, p.stderr
        assert out.stat().st_size > 0
    p = _plot(cli, cask, "--kind", "rim", "--tlim", 20, 40, "-o", tmp_path / "w.pdf")
    assert p.returncode == 0, p.stderr
    # a planar history asked for as a rim figure: refused, naming the columns, nothing written
    p = _plot(cli, pier, "--kind", "rim", "-o", tmp_path / "no.png")
    assert p.returncode == 2 and "contact_angle_deg" in p.stderr
    assert not (tmp_path / "no.png").exists()
