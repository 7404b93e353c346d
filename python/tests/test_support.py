# SPDX-License-Identifier: BSD-3-Clause
"""A rigid block on a support that moves with it (docs/theory.md §24) from Python: the same run as
`flexrock run`, and a case with [support] is not run on the rigid floor by simulate_case."""

import csv
import json
import subprocess

import numpy as np
import pytest

import flexrock as fr


def test_support_run_matches_the_command_line(cli, cases, tmp_path):
    path = cases / "statue_on_platform.toml"
    subprocess.run([str(cli), "run", "-q", "-o", str(tmp_path), str(path)], check=True)
    summary = json.load(open(tmp_path / "statue_on_platform.summary.json"))
    c = fr.load_case(str(path))
    assert c.support is not None
    r = fr.simulate_on_support(fr.Body(c.body), c.support, c.motion, c.initial, c.options)
    assert r.max_support_displacement == summary["support"]["max_displacement_m"]
    assert r.body.status == fr.Status.completed
    rows = list(csv.DictReader(open(tmp_path / "statue_on_platform.csv")))
    u = np.array([float(row["support_u_m"]) for row in rows])
    assert len(u) == len(r.support_displacement)
    assert np.max(np.abs(u - r.support_displacement)) <= 1e-12 * np.max(np.abs(u))


def test_simulate_case_does_not_put_a_supported_body_on_the_floor(cases):
    c = fr.load_case(str(cases / "statue_on_platform.toml"))
    with pytest.raises(fr.InputError, match=r"\[support\]"):
        fr.simulate_case(c)


def test_support_from_frequency_and_sliding_refused():
    body = fr.Body(fr.BodyParameters.rectangular_block(800.0, 0.2, 0.9))
    s = fr.SupportParameters.from_frequency(1500.0, 800.0, 0.5, 0.1)
    assert s.stiffness == pytest.approx(2300.0 * (2 * np.pi * 0.5) ** 2, rel=1e-14)
    o = fr.SimulationOptions()
    o.friction_coefficient = 0.4
    with pytest.raises(fr.InputError, match="sliding on a support is not modelled"):
        fr.simulate_on_support(body, s, fr.GroundMotion.none(1.0), fr.InitialState(), o)
