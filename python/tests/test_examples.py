# SPDX-License-Identifier: BSD-3-Clause
"""Every script in examples/python runs (with small sizes) and writes its figures."""

import os
import subprocess
import sys

from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run(script, tmp_path, *args):
    env = dict(os.environ, MPLBACKEND="Agg")
    p = subprocess.run([sys.executable, str(EXAMPLES / script), "-o", str(tmp_path), *args],
                       capture_output=True, text=True, env=env, timeout=240)
    assert p.returncode == 0, p.stdout + p.stderr
    return p.stdout


def test_run_record(tmp_path):
    out = run("run_record.py", tmp_path, "--t-end", "8")
    assert "outcome: completed" in out
    assert (tmp_path / "statue_response.png").stat().st_size > 10000
    assert (tmp_path / "statue_loop.svg").exists()


def test_spectrum(tmp_path):
    out = run("spectrum.py", tmp_path, "--amplitudes", "5", "--frequencies", "3", "--threads", "2")
    assert "wrote" in out
    assert (tmp_path / "block_spectrum.csv").exists()
    assert (tmp_path / "block_spectrum.png").exists()


def test_fragility(tmp_path):
    out = run("fragility.py", tmp_path, "--levels", "10", "--duration", "10", "--threads", "2")
    assert "median PGA to overturn" in out
    assert (tmp_path / "statue_fragility.png").exists()
