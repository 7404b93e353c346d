# SPDX-License-Identifier: BSD-3-Clause
"""The measurement scripts of tools/validation run on small subsets and write their tables."""

import os
import subprocess
import sys

from conftest import CLI, SOURCE_DIR

TOOLS = SOURCE_DIR / "tools" / "validation"


def run(script, *args):
    p = subprocess.run([sys.executable, str(TOOLS / script), *args], capture_output=True, text=True,
                       env=dict(os.environ), timeout=240)
    assert p.returncode == 0, p.stdout + p.stderr
    return p.stdout


def test_contact_grid(tmp_path):
    md = tmp_path / "grid.md"
    out = run("contact_grid.py", "--bodies", "oscillator_2hz,cabinet", "--records", "elcentro",
              "--scales", "0.25,1", "--md", str(md))
    assert "runs: 4" in out
    lines = md.read_text().splitlines()
    assert lines[0].startswith("| body | record | scale | status | outcome |")
    assert len([x for x in lines if x.startswith("| oscillator_2hz") or x.startswith("| cabinet")]) == 4
    # a 0.25 x El Centro does not lift the 2 Hz oscillator (0.36 g static threshold, PGA 0.08 g)
    assert "| oscillator_2hz | elcentro | 0.25 | completed | no_uplift |" in md.read_text()


def test_chatter_convergence(tmp_path):
    md = tmp_path / "chatter.md"
    out = run("chatter_convergence.py", "--bodies", "statue", "--records", "kobe", "--scales", "1",
              "--ratio", "0.02", "--md", str(md))
    assert "chatter ratios 0.02, 0.002, 0.0002" in out
    assert "runs: 1 (body, record, scale) x 3 ratios" in out
    assert "| statue | kobe | 1 |" in md.read_text()


def test_unclassified_cells():
    out = run("unclassified_cells.py", "--quick", "--no-validation", "--cli", str(CLI))
    assert "flexrock spectrum, one_sine" in out
    assert "(of 120)" in out  # the quick grid: 10 x 12 cells, each counted once


def test_regime_map_agrees_with_the_closed_form():
    # a coarse grid of the regime map of docs/validation.md §8 at two step levels, off the
    # closed form's ties: every cell as docs/theory.md §20 says, and all four regimes met
    seen = set()
    for a in ("0.42", "1.5"):
        out = run("regime_map.py", "--a", a, "--alphas", "0.1,0.3,0.6,1.0",
                  "--mus", "0.05,0.15,0.25,0.35,0.5,0.9,1.45")
        assert "cells: 28; agree: 28; disagree: 0" in out, out
        counts = out.split("engine regimes: ")[1].splitlines()[0]
        for part in counts.split(", "):
            name, n = part.rsplit(" ", 1)
            if int(n) > 0:
                seen.add(name)
    assert seen == {"rest", "slide", "rock", "slide-rock"}, seen
