# SPDX-License-Identifier: BSD-3-Clause
"""A Python user's results equal the command line's, bit for bit."""

import json
import os
import subprocess

import numpy as np
import pytest

import flexrock as fr

CASES = ["museum_statue", "flexible_tank", "asymmetric_cabinet", "slender_column"]


def _run_both(cli, case, tmp_path):
    a, b = tmp_path / "cli", tmp_path / "py"
    a.mkdir()
    b.mkdir()
    # the same relative output directory from two working directories: identical summaries
    subprocess.run([str(cli), "run", "-q", "-o", "out", str(case)], cwd=a, check=True,
                   capture_output=True)
    cwd = os.getcwd()
    try:
        os.chdir(b)
        r = fr.run_case(str(case), "out")
    finally:
        os.chdir(cwd)
    return a / "out", b / "out", r


@pytest.mark.parametrize("name", CASES)
def test_run_case_writes_the_cli_files_byte_for_byte(cli, cases, tmp_path, name):
    cli_out, py_out, r = _run_both(cli, cases / f"{name}.toml", tmp_path)
    files = sorted(p.name for p in cli_out.iterdir())
    assert files == sorted(p.name for p in py_out.iterdir())
    assert f"{name}.csv" in files and f"{name}.summary.json" in files
    for f in files:
        assert (cli_out / f).read_bytes() == (py_out / f).read_bytes(), f

    # numpy arrays equal the CSV's values exactly (the CSV holds round-trip shortest text)
    header = (cli_out / f"{name}.csv").read_text().splitlines()[0].split(",")
    table = np.genfromtxt(cli_out / f"{name}.csv", delimiter=",", skip_header=1)
    col = {c: table[:, i] for i, c in enumerate(header)}
    h = r.history
    np.testing.assert_array_equal(col["time_s"], h.time)
    np.testing.assert_array_equal(col["theta_rad"], h.theta)
    np.testing.assert_array_equal(col["theta_dot_rad_per_s"], h.theta_dot)
    np.testing.assert_array_equal(col["phase"], h.phase)
    np.testing.assert_array_equal(col["base_acc_x_m_per_s2"], h.base_acc_x)
    np.testing.assert_array_equal(col["reaction_y_N"], h.reaction_y)
    np.testing.assert_array_equal(col["impact_loss_J"], h.impact_loss)
    for i in range(h.modes):
        np.testing.assert_array_equal(col[f"q{i + 1}"], h.q[:, i])
    for c, v in r.time_history().items():
        np.testing.assert_array_equal(col[c], v, err_msg=c)

    summary = json.loads((cli_out / f"{name}.summary.json").read_text())
    assert summary["outcome"]["status"] == r.status
    assert summary["peaks"]["impacts"] == r.extremes.impacts


def test_simulate_from_the_case_pieces_equals_the_cli(cli, cases, tmp_path):
    # the plain API (body, motion, initial state, options) gives the same numbers as the CLI
    name = "flexible_tank"
    subprocess.run([str(cli), "run", "-q", "-o", str(tmp_path), str(cases / f"{name}.toml")],
                   check=True, capture_output=True)
    c = fr.load_case(str(cases / f"{name}.toml"))
    r = fr.simulate(fr.Body(c.body), c.motion, c.initial, c.options)
    assert r.time_history_csv() == (tmp_path / f"{name}.csv").read_text()
    ref = json.loads((tmp_path / f"{name}.summary.json").read_text())
    s = r.summary()
    for part in ("outcome", "peaks", "energy", "warnings"):
        assert s[part] == ref[part], part
