# SPDX-License-Identifier: BSD-3-Clause
"""Two horizontal components from Python: the azimuth sweep is the command line's (the same
numbers as `flexrock azimuths`), typed as numpy arrays; RotD of one component is Sa and Sa times
cos 45 deg."""

import csv
import math
import subprocess

import numpy as np

import flexrock as fr
from conftest import DATA

H1 = DATA / "RSN8884_14383980_13873090.AT2"
H2 = DATA / "RSN8884_14383980_13873360.AT2"


def write_pair(tmp_path, extra=""):
    p = tmp_path / "pair.toml"
    p.write_text(
        '[body]\ntype = "rigid_block"\nwidth = 0.5\nheight = 3.0\nmass = 1000.0\n'
        f'[excitation]\nscale = 3.0\n{extra}\n[excitation.horizontal]\ntype = "record"\n'
        f'file = "{H1}"\n[excitation.horizontal2]\ntype = "record"\nfile = "{H2}"\n'
        "[solver]\nt_end = 30.0\n"
    )
    return p


def test_run_azimuths_is_the_command_lines_table(tmp_path, cli):
    path = write_pair(tmp_path, "azimuth_step_deg = 30")
    c = fr.load_case(str(path))
    assert c.has_pair and c.azimuth_step_deg == 30.0 and c.azimuth_deg is None
    table, env = fr.run_azimuths(c, threads=2)
    assert table["azimuth_deg"].dtype == np.float64
    assert list(table["azimuth_deg"]) == [30.0 * k for k in range(12)]
    out = subprocess.run([str(cli), "azimuths", "-q", "-o", str(tmp_path), str(path)],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    rows = list(csv.DictReader(open(tmp_path / "pair.azimuths.csv")))
    assert [float(r["max_theta_rad"]) for r in rows] == list(table["max_theta_rad"])
    assert [r["outcome"] for r in rows] == table["outcome"]
    k = int(np.argmax(table["max_theta_rad"]))
    assert env["max_theta_rad"] == table["max_theta_rad"][k]
    assert env["max_theta_azimuth_deg"] == table["azimuth_deg"][k]


def test_azimuth_motion_projects_the_pair(tmp_path):
    c = fr.load_case(str(write_pair(tmp_path)))
    a1 = fr.read_record(H1).values * 9.80665 * 3.0
    a2 = fr.read_record(H2).values * 9.80665 * 3.0
    m = fr.azimuth_motion(c, 60.0)
    np.testing.assert_allclose(np.asarray(m.horizontal), 0.5 * a1 + math.sqrt(0.75) * a2,
                               rtol=0, atol=1e-13)


def test_rotd_of_one_component_is_sa_and_its_median_over_angles():
    r = fr.read_record(H1)
    t, a = np.asarray(r.time), np.asarray(r.values) * 9.80665
    d = fr.rotd(t, a, np.zeros_like(a), period=1.0)
    sa = fr.intensity_measure("sa", t, a, period=1.0)
    assert d["by_angle"].shape == (180,)
    assert d["rotd100"] == sa
    assert math.isclose(d["rotd50"], sa * math.sqrt(0.5), rel_tol=1e-12)


def test_worst_and_random_azimuth_outcomes(tmp_path):
    # a slender block (b = 0.25 m, h = 1.5 m) under the Anaheim pair: at 6 times the record it
    # overturns at some azimuths, not at others; at 1 it overturns nowhere
    p = tmp_path / "anaheim.toml"
    p.write_text(
        '[body]\ntype = "rigid_block"\nwidth = 0.5\nheight = 3.0\nmass = 1000.0\n'
        '[excitation.horizontal]\ntype = "record"\n'
        f'file = "{DATA / "RSN8883_14383980_13849090.AT2"}"\n'
        '[excitation.horizontal2]\ntype = "record"\n'
        f'file = "{DATA / "RSN8883_14383980_13849360.AT2"}"\n'
    )
    rows, runs = fr.azimuth_outcomes([p], [1.0, 6.0], step_deg=30, threads=2)
    assert list(rows["scale"]) == [1.0, 6.0]
    assert rows["worst_overturned"].dtype == np.int64
    c = fr.load_case(str(p))
    for k, s in enumerate([1.0, 6.0]):
        c.excitation_scale = s
        table, env = fr.run_azimuths(c, 30.0, 2)
        over = [o.startswith("overturned") for o in table["outcome"]]
        assert rows["worst_overturned"][k] == int(any(over))
        assert rows["overturned_fraction"][k] == sum(over) / len(over)
        assert len(env["overturned_azimuths_deg"]) == sum(over)
    assert rows["worst_overturned"][0] == 0 and rows["worst_overturned"][1] == 1
    assert 0 < rows["overturned_fraction"][1] < 1
    # the IM: RotD50 of the peak acceleration of the scaled pair, linear in the scale
    r1 = fr.read_record(DATA / "RSN8883_14383980_13849090.AT2")
    r2 = fr.read_record(DATA / "RSN8883_14383980_13849360.AT2")
    t = np.asarray(r1.time)
    im6 = fr.rotd(t, 6 * 9.80665 * np.asarray(r1.values), 6 * 9.80665 * np.asarray(r2.values), 1e-6)
    assert math.isclose(rows["rotd50_m_per_s2"][1], im6["rotd50"], rel_tol=1e-12)
    # RotD100 of the peak acceleration is the peak of the horizontal vector's largest projection
    peak = 6 * 9.80665 * max(max(abs(math.cos(math.radians(a)) * x + math.sin(math.radians(a)) * y)
                                 for x, y in zip(r1.values, r2.values)) for a in range(180))
    assert math.isclose(rows["rotd100_m_per_s2"][1], peak, rel_tol=1e-6)
    # the random-azimuth observations: one per azimuth run
    assert len(runs["im"]) == 24 and runs["overturned"].sum() == round(12 * rows["overturned_fraction"][1])
