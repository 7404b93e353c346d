# SPDX-License-Identifier: BSD-3-Clause
"""A toppling block is overturned, on the same side, for every entry point: the command line, its
summary JSON, Python's simulate and summarize, and a spectrum cell (docs/theory.md §17)."""

import json
import math
import subprocess

import flexrock as fr

# a slender block (b/h = 0.2) thrown over by a one-sine pulse of 3 g at twice its frequency
# parameter: its pivot force vanishes on the way down, where the engine used to stop
WIDTH, HEIGHT, MASS = 0.4, 2.0, 600.0
R = math.hypot(WIDTH / 2, HEIGHT / 2)
P = math.sqrt(3 * 9.80665 / (4 * R))  # [rad/s] Housner's frequency parameter
CASE = f"""
[body]
type = "rigid_block"
width = {WIDTH}
height = {HEIGHT}
mass = {MASS}

[excitation.horizontal]
type = "one_sine"
amplitude = 3.0
units = "g"
period = {2 * math.pi / (2 * P)!r}
duration = 20.0
"""


def test_toppling_block_is_overturned_by_the_cli_python_and_the_spectrum(tmp_path, cli):
    case = tmp_path / "topple.toml"
    case.write_text(CASE)
    subprocess.run([cli, "run", "-q", "-o", str(tmp_path), str(case)], check=True)
    summary = json.loads((tmp_path / "topple.summary.json").read_text())
    assert summary["outcome"]["status"] == "overturned"
    assert summary["outcome"]["overturned"] is True
    edge = summary["outcome"]["overturn_edge"]
    assert edge in (1, 2)
    r = fr.run_case(str(case), None)
    assert r.overturned and r.status == "overturned"
    assert r.raw.extremes.overturn_edge == edge
    body = fr.Body(r.case.body)
    s = fr.summarize(body, r.raw)
    assert s.outcome.name.startswith("overturned") and s.overturn_edge == edge
    # the same pulse as a spectrum cell: a_p / (g tan alpha), omega_p / p
    spec = fr.spectrum(body, [3.0 / (WIDTH / HEIGHT)], [2.0], "one_sine", bisect=False,
                       free_periods=20.0 * P / (2 * math.pi), threads=1)
    cell = spec.cells[0]
    assert cell.run.outcome.name.startswith("overturned")
    assert cell.run.overturn_edge == edge
