# SPDX-License-Identifier: BSD-3-Clause
"""Sa at any period from 1e-6 s up, at a cost that does not grow with it, and a shorter period
refused naming its key, in every entry point: a case file's sa_period, a manifest's sa_periods
and target_im, Python's period= and sa_periods= (docs/studies.md, Intensity measures)."""

import math
import os
import subprocess
import sys

import numpy as np
import pytest

import flexrock as fr

# each call below takes milliseconds; before, a period of 1e308 s stepped its free vibration at
# the record's step without end: the timeouts are the guard against that, not a measurement
GUARD = 120


def _record(tmp_path):
    dt = 0.01
    vals = [0.2 * math.sin(2 * math.pi * 1.3 * i * dt) * math.exp(-0.2 * i * dt) for i in range(1000)]
    (tmp_path / "rec.dat").write_text("".join(f"{v:.8e}\n" for v in vals))
    return np.arange(1000) * dt, np.array(vals) * 9.80665


def _case(tmp_path, period):
    _record(tmp_path)
    p = tmp_path / f"case_{period}.toml"
    p.write_text('[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 1.8\nmass = 800.0\n'
                 f'[excitation]\ntarget_sa = 0.3\nsa_period = {period}\n'
                 '[excitation.horizontal]\ntype = "record"\nfile = "rec.dat"\n'
                 'format = "single_column"\ndt = 0.01\nunits = "g"\n')
    return p


def _manifest(tmp_path, name, tail):
    _record(tmp_path)
    (tmp_path / "block.toml").write_text(
        '[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 1.8\nmass = 800.0\n')
    m = tmp_path / name
    m.write_text('[[body]]\nfile = "block.toml"\n'
                 '[[record]]\nname = "r"\nfile = "rec.dat"\nformat = "single_column"\n'
                 'dt = 0.01\nunits = "g"\n' + tail + '[solver]\nmax_step = 0.01\n')
    return m


def _cli(cli, *args, cwd):
    return subprocess.run([os.path.abspath(cli), *args], capture_output=True, text=True, cwd=cwd,
                          timeout=GUARD)


def test_case_file_periods(cli, tmp_path):
    huge, tiny = _case(tmp_path, "1e308"), _case(tmp_path, "1e-300")
    for cmd in (["check"], ["params"], ["run", "-q", "-o", str(tmp_path / "out")]):
        # Sa at 1e308 s is about omega |v_end|: no finite factor reaches 0.3 g, and it says so
        p = _cli(cli, *cmd, str(huge), cwd=tmp_path)
        assert p.returncode == 2 and "target_sa" in p.stderr and "no finite factor" in p.stderr, p.stderr
        p = _cli(cli, *cmd, str(tiny), cwd=tmp_path)
        assert p.returncode == 2, p.stderr
        assert "sa_period" in p.stderr and ">= 1e-06" in p.stderr and "1e-300" in p.stderr, p.stderr
    # a long period that can be reached: scaled, quickly
    p = _cli(cli, "check", str(_case(tmp_path, "1e4")), cwd=tmp_path)
    assert p.returncode == 0, p.stderr


def test_manifest_periods(cli, tmp_path):
    ok = _manifest(tmp_path, "huge.toml", "[scales]\nfactors = [0.5]\n[intensity]\nsa_periods = [1e308]\n")
    out = tmp_path / "huge.csv"
    p = _cli(cli, "sweep", str(ok), "-o", str(out), "-q", "-j", "1", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    table = fr.read_sweep(ok, out)
    sa = table["sa_T1e+308_z0.05_m_per_s2"][0]
    assert 0.0 < sa < 1e-300
    bad = _manifest(tmp_path, "tiny.toml", "[scales]\nfactors = [0.5]\n[intensity]\nsa_periods = [1e-300]\n")
    p = _cli(cli, "sweep", str(bad), "-o", str(tmp_path / "t.csv"), "-q", cwd=tmp_path)
    assert p.returncode == 2 and "intensity.sa_periods" in p.stderr and ">= 1e-06" in p.stderr, p.stderr
    # stripes of Sa at 1e308 s: factors near 1e300 on this record, which the runs refuse or stop
    # on; what matters here is that the sweep ends
    m = _manifest(tmp_path, "stripes.toml", '[scales]\ntarget_im = "sa:1e308"\ntargets = [0.1]\n')
    p = _cli(cli, "sweep", str(m), "-o", str(tmp_path / "s.csv"), "-q", cwd=tmp_path)
    assert p.returncode in (0, 2), p.stderr
    m = _manifest(tmp_path, "stripes.toml", '[scales]\ntarget_im = "sa:1e-300"\ntargets = [0.1]\n')
    p = _cli(cli, "sweep", str(m), "-o", str(tmp_path / "s.csv"), "-q", cwd=tmp_path)
    assert p.returncode == 2, p.stderr
    assert "scales.target_im" in p.stderr and '"sa:1e-300"' in p.stderr and ">= 1e-06" in p.stderr


def test_python_periods(tmp_path):
    t, a = _record(tmp_path)
    # in a process of its own, so that a hang ends at the timeout
    code = ("import flexrock as fr, numpy as np\n"
            "t = np.arange(1000) * 0.01; a = 2.0 * np.sin(8.0 * t)\n"
            "print(repr(fr.intensity_measure('sa', t, a, period=1e308)))\n")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=GUARD)
    assert p.returncode == 0, p.stderr
    assert 0.0 < float(p.stdout) < 1e-300
    with pytest.raises(fr.InputError, match=r"intensity_measure: period.*>= 1e-06"):
        fr.intensity_measure("sa", t, a, period=1e-300)
    body = fr.rigid_block(0.4, 1.8, 800.0)
    rec = fr.motion_from_array(a, dt=0.01)
    with pytest.raises(fr.InputError, match=r"sweep: sa_periods.*>= 1e-06"):
        fr.sweep({"b": body}, {"r": rec}, factors=[1.0], sa_periods=[1e-300])
    with pytest.raises(fr.InputError, match=r'"sa:1e-300".*>= 1e-06'):
        fr.sweep({"b": body}, {"r": rec}, target_im="sa:1e-300", targets=[0.1])
    # the shortest period taken: the oscillator follows the ground, Sa is the PGA
    pga = fr.intensity_measure("pga", t, a)
    assert fr.intensity_measure("sa", t, a, period=1e-6) == pytest.approx(pga, rel=1e-4)
