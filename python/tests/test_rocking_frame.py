# SPDX-License-Identifier: BSD-3-Clause
"""Rocking frames (docs/theory.md §25) from Python: the body table's keyword function, the
refusals, and a case run within the frame's model."""

import math

import pytest

import flexrock as fr

G = 9.80665


def test_rocking_frame_from_the_table_is_the_equivalent_body():
    b, h, n, m, mb = 0.2, 2.0, 3, 2000.0, 9000.0
    p = fr.rocking_frame(column_width=2 * b, column_height=2 * h, column_mass=m, count=n,
                         beam_mass=mb)
    gam = mb / (n * m)
    # the closed forms of theory §25, written out independently here
    assert p.height == pytest.approx(h * (1 + 4 * gam) / (1 + 2 * gam), rel=1e-14)
    assert p.b1 == pytest.approx(b * (1 + 4 * gam) / (1 + 2 * gam), rel=1e-14)
    assert p.mass == pytest.approx(n * m * (1 + 2 * gam) ** 2 / (1 + 4 * gam), rel=1e-14)
    body = fr.Body(p)
    R = math.hypot(b, h)
    assert body.rocking_frequency == pytest.approx(
        math.sqrt((1 + 2 * gam) / (1 + 3 * gam) * 3 * G / (4 * R)), rel=1e-13)
    # Housner's ratio of the equivalent body is the frame's impact ratio
    a2 = (p.b1 / p.height) ** 2
    housner = (1 + p.zeta2 - a2) / (1 + p.zeta2 + a2)
    c2a = (h * h - b * b) / (R * R)
    assert housner == pytest.approx((1 + 3 * (1 + 4 * gam) * c2a) / (4 * (1 + 3 * gam)), rel=1e-13)
    # the default beam is none: the columns side by side
    q = fr.rocking_frame(2 * b, 2 * h, m)
    r = fr.rigid_block(2 * b, 2 * h, 2 * m)
    assert (q.mass, q.height, q.b1, q.zeta2) == (r.mass, r.height, r.b1, r.zeta2)


def test_one_column_is_not_a_frame():
    with pytest.raises(fr.InputError, match="count"):
        fr.rocking_frame(0.4, 4.0, 2000.0, count=1)


CASE = """
[body]
type = "rocking_frame"
column_width = 1.5
column_height = 3.0
column_mass = 2000.0
count = 2
beam_mass = 300.0
[excitation.horizontal]
type = "one_sine"
amplitude = 1.2
units = "g"
period = 0.6
duration = 4.0
[excitation.vertical]
type = "harmonic"
amplitude = 0.7
units = "g"
frequency_hz = 4.0
duration = 4.0
[output]
dt = 0.005
"""


def test_a_frame_case_stops_where_its_beam_would_lift_off(tmp_path):
    path = tmp_path / "bent.toml"
    path.write_text(CASE)
    r = fr.simulate_case(fr.load_case(str(path)))
    assert r.status == "stopped"
    assert "beam's contact force" in r.raw.message


def test_a_frame_case_refuses_friction(tmp_path):
    path = tmp_path / "bent.toml"
    path.write_text(CASE + "[solver]\nfriction_coefficient = 0.6\n")
    with pytest.raises(fr.InputError, match="sliding of a rocking frame"):
        fr.load_case(str(path))


def test_studies_refuse_a_frame(cli, tmp_path):
    import subprocess

    (tmp_path / "bent.toml").write_text(CASE)
    spectrum = tmp_path / "spectrum.toml"
    spectrum.write_text('body = "bent.toml"\n[spectrum]\npulse = "one_sine"\naxes = "normalized"\n'
                        'amplitudes = { start = 1.0, stop = 2.0, count = 2 }\n'
                        'frequencies = { start = 1.0, stop = 2.0, count = 2 }\n')
    p = subprocess.run([str(cli), "spectrum", str(spectrum), "-o", str(tmp_path / "s.csv")],
                       capture_output=True, text=True)
    assert p.returncode == 2, p.stderr
    assert "do not run rocking frames yet" in p.stderr
    assert not (tmp_path / "s.csv").exists()


def test_stack_uplift_bands():
    # identical blocks start as one at b/(2h), the single block of twice the height
    bands = {p: (lo, hi) for p, lo, hi in fr.stack_uplift_bands(0.5, 2.0, 300.0, 0.5, 2.0, 300.0)}
    assert bands["rest"] == (0.0, pytest.approx(0.125, rel=1e-15))
    assert bands["as_one"][0] == pytest.approx(0.125, rel=1e-15)
    assert bands["top_alone"] == (math.inf, math.inf)
    # a slender top on a squat bottom: the top alone at its own b/h
    bands = {p: (lo, hi) for p, lo, hi in fr.stack_uplift_bands(2.0, 1.0, 1000.0, 0.2, 2.0, 50.0)}
    assert bands["top_alone"][0] == pytest.approx(0.1, rel=1e-15)
    with pytest.raises(fr.InputError, match="top width"):
        fr.stack_uplift_bands(0.5, 1.0, 1.0, 0.6, 1.0, 1.0)
