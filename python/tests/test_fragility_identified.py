# SPDX-License-Identifier: BSD-3-Clause
"""A fragility the data cannot identify is refused, never reported with a made-up beta."""

import csv
import subprocess

import flexrock as fr
import pytest


def _sweep_csv(path, rows):
    cols = fr.sweep_columns()
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        for i, (rec, lv, y) in enumerate(rows):
            r = dict.fromkeys(cols, "0")
            r.update(index=i, body="b", record=rec, requested_level=repr(lv), requested_units="g",
                     pga_g=repr(lv), outcome="overturned_after_impacts" if y else "rocking",
                     overturned=y, status="overturned" if y else "completed", message="")
            w.writerow([r[c] for c in cols])


def test_ida_at_one_level_is_refused_beta_unidentified(cli, tmp_path):
    # one level, one record failing at it and one surviving: only the median is known
    path = tmp_path / "one.csv"
    _sweep_csv(path, [("r0", 0.3, 1), ("r1", 0.3, 0)])
    out = tmp_path / "ida.csv"
    p = subprocess.run([str(cli), "fragility", str(path), "--analysis", "ida", "--im", "pga_g",
                        "-o", str(out), "-q"], capture_output=True, text=True)
    assert p.returncode == 2, (p.returncode, p.stdout, p.stderr)
    assert "beta is not identified" in p.stderr and "add levels" in p.stderr, p.stderr
    assert not out.exists()
    with pytest.raises(fr.InputError, match="beta is not identified"):
        fr.fit_capacity_intervals([0.0, 0.3], [0.3, float("inf")])
