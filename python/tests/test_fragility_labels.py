# SPDX-License-Identifier: BSD-3-Clause
"""Fragility outputs record their intensity measure and its unit, and every figure labels its axis
from them: an Sa(1 s) fit is not drawn as PGA, from the command line or from Python."""

import csv
import os
import subprocess

import numpy as np
import pytest
from matplotlib.figure import Figure

import flexrock as fr
from flexrock import plots

G = 9.80665
SA = "sa_T1_z0.05_m_per_s2"


def _sweep_with_sa(path):
    # one body, 4 records x 5 levels; Sa(1 s) is 3.1 x PGA: a median near 7.9 m/s^2
    cols = fr.sweep_columns()
    at = cols.index("pgv_m_per_s") + 1
    cols = cols[:at] + [SA] + cols[at:]
    fails = {0.1: [0, 0, 0, 0], 0.2: [0, 1, 0, 0], 0.25: [1, 0, 0, 1], 0.3: [1, 1, 0, 1], 0.4: [1, 1, 1, 1]}
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        i = 0
        for level, flags in fails.items():
            for k, y in enumerate(flags):
                r = dict.fromkeys(cols, "0")
                pga = level * (1 + 0.01 * k)
                r.update(index=i, body="block", record=f"r{k}", requested_level=level, requested_units="g",
                         pga_g=repr(pga), pga_m_per_s2=repr(pga * G), **{SA: repr(3.1 * pga * G)},
                         overturned=y, outcome="overturned_after_impacts" if y else "rocking",
                         status="overturned" if y else "completed", message="")
                w.writerow([r[c] for c in cols])
                i += 1


@pytest.fixture()
def outputs(cli, tmp_path):
    sweep = tmp_path / "sweep.csv"
    _sweep_with_sa(sweep)
    fit, curve = tmp_path / "fit.csv", tmp_path / "curve.csv"
    p = subprocess.run([str(cli), "fragility", str(sweep), "--im", "sa:1", "-o", str(fit), "--curve", str(curve),
                        "-q"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return sweep, fit, curve


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_fit_and_curve_csvs_record_the_measure_and_its_unit(outputs):
    _, fit, curve = outputs
    (row,) = _rows(fit)
    assert (row["im_name"], row["im_unit"]) == ("sa:1", "m/s^2")
    assert 5 < float(row["theta"]) < 12  # in m/s^2, not g
    assert {(r["im_name"], r["im_unit"]) for r in _rows(curve)} == {("sa:1", "m/s^2")}


@pytest.mark.parametrize("which", ["fit", "curve"])
def test_flexrock_plot_labels_the_axis_from_the_file(cli, outputs, tmp_path, which):
    src = outputs[1] if which == "fit" else outputs[2]
    out = tmp_path / f"{which}.svg"
    env = dict(os.environ, MPLCONFIGDIR=str(tmp_path))
    (tmp_path / "matplotlibrc").write_text("svg.fonttype: none\n")  # labels as text, not paths
    p = subprocess.run([str(cli), "plot", str(src), "-o", str(out)], capture_output=True, text=True, env=env)
    assert p.returncode == 0, p.stderr
    text = out.read_text()
    assert "Sa(1 s, 5 %) [m/s²]" in text
    assert "PGA" not in text
    # an --im that disagrees with the file is refused, not drawn under the wrong label
    p = subprocess.run([str(cli), "plot", str(src), "--im", "pga_g", "-o", str(out)], capture_output=True, text=True)
    assert p.returncode == 2 and "a fit against sa:1 [m/s^2], not pga_g" in p.stderr


def test_python_labels_from_the_file_and_from_the_fit(outputs):
    sweep, fit, curve = outputs
    for src in (fit, curve):
        ax = plots.fragility_curve(str(src), fig=Figure())
        assert ax.get_xlabel() == "Sa(1 s, 5 %) [m/s²]"
    # the median in the legend carries the unit too
    (line,) = [a for a in plots.fragility_curve(str(fit), fig=Figure()).lines if a.get_gid() == "fit"]
    assert line.get_label().startswith("fit, θ = ") and "m/s², β = " in line.get_label()
    # a sweep CSV fitted in Python against Sa: the data carry the measure
    pairs = fr.fragility_from_sweep(str(sweep), im="sa:1")
    assert (pairs[0][0].im_name, pairs[0][0].im_unit) == ("sa:1", "m/s^2")
    assert plots.fragility_curve(pairs, fig=Figure()).get_xlabel() == "Sa(1 s, 5 %) [m/s²]"
    assert plots.fragility_curve(str(sweep), im="sa:1", fig=Figure()).get_xlabel() == "Sa(1 s, 5 %) [m/s²]"
    # the sweep's default stays PGA in g
    assert plots.fragility_curve(str(sweep), fig=Figure()).get_xlabel() == "PGA [g]"


def test_a_fit_csv_without_the_columns_is_not_labelled_pga(outputs, tmp_path):
    # an output of an older flexrock: the measure is unknown, and the label says so
    _, fit, _ = outputs
    rows = _rows(fit)
    old = tmp_path / "old.csv"
    keep = [c for c in rows[0] if c not in ("im_name", "im_unit")]
    with open(old, "w", newline="") as f:
        w = csv.DictWriter(f, keep, extrasaction="ignore", lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    assert plots.fragility_curve(str(old), fig=Figure()).get_xlabel() == "intensity measure (not recorded in the file)"
    assert np.isfinite(float(rows[0]["theta"]))
