# SPDX-License-Identifier: BSD-3-Clause
"""A rigid body of revolution in 3D from Python (docs/theory.md §27): the same run as `flexrock
run`, the planar limit against the planar engine, and bad input refused."""

import json
import subprocess

import numpy as np
import pytest

import flexrock as fr
from conftest import DATA

H1 = DATA / "RSN8884_14383980_13873090.AT2"
H2 = DATA / "RSN8884_14383980_13873360.AT2"
CASK = {"radius": 1.7, "height": 5.9, "mass": 120000.0}


def _cask_case(path):
    path.write_text(
        '[body]\ntype = "cylinder"\nradius = 1.7\nheight = 5.9\nmass = 120000.0\n'
        "[excitation]\nscale = 3.0\n"
        f'[excitation.horizontal]\ntype = "record"\nfile = "{H1}"\n'
        f'[excitation.horizontal2]\ntype = "record"\nfile = "{H2}"\n'
        '[output]\ndt = 0.01\nevents = "events.csv"\n'
    )
    return path


@pytest.fixture(scope="module")
def cli_run(cli, tmp_path_factory):
    # the command line's run of a cylinder under a record pair (the 3D engine)
    d = tmp_path_factory.mktemp("rim")
    case = _cask_case(d / "cask.toml")
    out = d / "cli"
    subprocess.run([str(cli), "run", "-q", "-o", str(out), str(case)], check=True)
    return case, out


def test_python_run_equals_the_command_line(cli_run, tmp_path):
    case, out = cli_run
    s = json.loads((out / "cask.summary.json").read_text())
    assert s["engine"] == "3d_body_of_revolution"
    r = fr.simulate_case(fr.load_case(str(case)))
    assert isinstance(r, fr.BodyOfRevolutionResult)
    assert r.status.name == s["status"] and r.message == s["message"]
    # the numbers the summary reports, to the last digit
    assert r.t_end == s["t_end_s"]
    assert r.max_tilt == s["max_tilt_rad"]
    assert r.max_tilt_azimuth * 180.0 / np.pi == pytest.approx(s["max_tilt_azimuth_deg"], rel=1e-12, abs=1e-12)
    assert (r.uplifts, r.landings) == (s["uplifts"], s["landings"])
    assert r.closest_pass == s["closest_pass_rad"]
    assert r.max_offset == s["max_offset_m"] and r.max_friction_demand == s["max_friction_demand"]
    assert r.min_normal_force == s["min_normal_force_N"]
    e = s["energy"]
    assert (r.energy.input_work, r.energy.impact_loss, r.energy.residual) == (
        e["input_work_J"], e["impact_loss_J"], e["residual_J"])
    assert (r.steps, r.rhs_evaluations) == (s["steps"], s["rhs_evaluations"])
    assert r.uplifts >= 1 and r.max_tilt > 0  # a run that rocked, not a trivial one
    # the sampled history as numpy arrays, the CLI's CSV to its printed digits
    h = r.history
    assert isinstance(h.tilt, np.ndarray) and h.tilt.shape == h.time.shape == (len(h),)
    assert h.tilt.max() <= r.max_tilt * (1 + 1e-12)
    csv = np.genfromtxt(out / "cask.csv", delimiter=",", names=True)
    assert len(csv) == len(h)
    np.testing.assert_allclose(h.tilt, csv["tilt_rad"], rtol=1e-9, atol=1e-15)
    assert [str(k.name) for k in (ev.kind for ev in r.events)][0] == "uplift"
    # the summary and the files written from Python are the command line's, byte for byte
    py_out = tmp_path / "py"
    r.write(str(py_out))
    for name in ("cask.csv", "events.csv"):
        assert (py_out / name).read_bytes() == (out / name).read_bytes(), name
    ps = json.loads((py_out / "cask.summary.json").read_text())
    for key in ("files", "source"):
        ps.pop(key), s.pop(key)
    assert ps == s


def test_run_case_writes_the_3d_outputs(cli_run, tmp_path):
    case, out = cli_run
    r = fr.run_case(str(case), str(tmp_path))
    assert isinstance(r, fr.BodyOfRevolutionResult)
    assert (tmp_path / "cask.csv").read_bytes() == (out / "cask.csv").read_bytes()
    assert r.summary()["engine"] == "3d_body_of_revolution"


def test_simulate_case_never_runs_the_planar_section_of_a_3d_case(tmp_path):
    # a pair and a body of revolution: the 3D engine, whose H2 moves the body out of H1's plane
    r = fr.simulate_case(fr.load_case(str(_cask_case(tmp_path / "cask.toml"))))
    assert isinstance(r, fr.BodyOfRevolutionResult)
    assert r.uplifts >= 1 and np.abs(r.history.y).max() > 1e-3  # [m] off H1's line


def test_planar_limit_equals_the_planar_engine():
    # H2 = 0: the cylinder rocks in H1's plane, the planar engine's run of its section
    h1 = fr.motion_from_file(str(H1), scale=3.0)
    t = np.asarray(h1.times)
    zero = fr.GroundMotion.sampled(t, np.zeros_like(t))
    body = fr.axisymmetric_body("cylinder", **CASK)
    r3 = fr.simulate_body_of_revolution(body, h1, zero, output_dt=0.01)
    r2 = fr.simulate(fr.cylinder(**CASK), h1, output_dt=0.0)
    planar = max(r2.extremes.max_theta_edge1, r2.extremes.max_theta_edge2)
    assert r3.status == fr.RimStatus.completed and r3.uplifts >= 1 and r3.landings >= 1
    assert np.abs(r3.history.y).max() == 0.0  # it stayed in H1's plane
    assert r3.max_tilt == pytest.approx(planar, abs=1e-9)
    assert r3.max_tilt > 1e-3  # a rocking response, not two zeros
    # the same with no H2 at all, and the cylinder's own builder
    r3b = fr.simulate_body_of_revolution(fr.uniform_cylinder(1.7, 5.9, 120000.0), h1, output_dt=0.0)
    assert r3b.max_tilt == pytest.approx(planar, abs=1e-9)


def test_max_tilt_is_located_not_sampled():
    # the peak tilt does not depend on how many points a step the guards are checked at (the
    # largest sample lagged the peak by 3e-8 rad here); 32, the most, ran past the full contact's
    # samples once
    h1 = fr.motion_from_file(str(H1), scale=3.0)
    h2 = fr.motion_from_file(str(H2), scale=3.0)
    body = fr.axisymmetric_body("cylinder", **CASK)
    a, b = (fr.simulate_body_of_revolution(body, h1, h2, output_dt=0.0, event_samples=n) for n in (4, 32))
    assert a.uplifts >= 1 and a.max_tilt > 1e-3
    assert b.max_tilt == pytest.approx(a.max_tilt, rel=1e-12)


def test_body_from_the_table_matches_its_planar_section():
    b = fr.axisymmetric_body("cylinder", **CASK)
    p = fr.cylinder(**CASK)
    q = b.planar_equivalent()
    assert (q.mass, q.height, q.b1, q.b2) == (p.mass, p.height, p.b1, p.b2)
    assert b.height == pytest.approx(5.9 / 2, rel=1e-15)
    assert b.inertia_axis == pytest.approx(120000.0 * 1.7**2 / 2, rel=1e-15)


@pytest.mark.parametrize(
    "make, words",
    [
        (lambda: fr.axisymmetric_body("body_of_revolution", mass=1000.0, cg_height=1.0, base_radius=0.5,
                                      inertia_diameter=100.0, inertia_axis=300.0), "C <= 2 A"),
        (lambda: fr.axisymmetric_body("cylinder", radius=1.0, height=2.0), "mass"),
        (lambda: fr.axisymmetric_body("cylinder", radius=1.0, height=2.0, mass=1.0, colour=3.0), "colour"),
        (lambda: fr.axisymmetric_body("rigid_block", width=1.0, height=2.0, mass=1.0), "not a body of revolution"),
        (lambda: fr.AxisymmetricBody(mass=-1.0, height=1.0, radius=0.5, inertia_diameter=1.0,
                                     inertia_axis=1.0), "mass"),
        (lambda: fr.simulate_body_of_revolution(fr.cylinder(**CASK), fr.GroundMotion.none(1.0)),
         "AxisymmetricBody"),
        (lambda: fr.simulate_body_of_revolution(fr.axisymmetric_body("cylinder", **CASK),
                                                fr.GroundMotion.none(1.0), rtol=-1.0), "rtol"),
        (lambda: fr.simulate_body_of_revolution(fr.axisymmetric_body("cylinder", **CASK),
                                                fr.GroundMotion.none(1.0), event_samples=40),
         r"event_samples must be an integer in \[1, 32\]"),
    ],
)
def test_bad_input_raises_input_error(make, words):
    with pytest.raises(fr.InputError, match=words):
        make()
