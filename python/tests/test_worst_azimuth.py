# SPDX-License-Identifier: BSD-3-Clause
"""A sweep over record pairs ([[suite]] horizontal2: one row per azimuth) fitted for the worst
azimuth: one observation per pair and level, failed at any azimuth, its measure the median over
the azimuths; the fit records "rotd50:pga_g" and its figure says RotD50 PGA."""

import csv
import statistics
import subprocess

import numpy as np
from matplotlib.figure import Figure

import flexrock as fr
from flexrock import plots

AZIMUTHS = [0, 90, 180, 270]


def _pair_sweep(path):
    # 3 pairs x 4 levels x 4 azimuths; pair k fails at an azimuth when its PGA there, level x
    # (1 + k/10) x (1 + 0.2 cos beta), exceeds its capacity: the worst azimuth fails first
    cols = fr.sweep_columns()
    rows, i = [], 0
    for k in range(3):
        for level in (0.1, 0.2, 0.3, 0.4):
            for beta in AZIMUTHS:
                pga = level * (1 + k / 10) * (1 + 0.2 * np.cos(np.radians(beta)))
                y = int(pga > (0.25, 0.45, 0.33)[k])
                r = dict.fromkeys(cols, "0")
                r.update(index=i, body="block", record=f"H1_{k}+H2_{k}@{beta}", requested_level=level,
                         requested_units="-", scale=level, pga_g=repr(pga), pga_m_per_s2=repr(pga * 9.80665),
                         overturned=y, outcome="overturned_after_impacts" if y else "rocking",
                         status="overturned" if y else "completed", message="")
                rows.append(r)
                i += 1
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, cols, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    return rows


def test_worst_azimuth_observations_and_label(cli, tmp_path):
    sweep = tmp_path / "pairs.csv"
    rows = _pair_sweep(sweep)
    groups = {}
    for r in rows:
        groups.setdefault((r["record"].split("@")[0], r["requested_level"]), []).append(r)
    im = [statistics.median(float(r["pga_g"]) for r in g) for g in groups.values()]
    failed = [int(any(r["overturned"] for r in g)) for g in groups.values()]
    assert 0 < sum(failed) < len(failed)
    s = fr.FragilitySession(str(sweep), im="pga_g", worst_azimuth=True)
    d = s.data(0, 0)
    assert d.im_name == "rotd50:pga_g" and d.im_unit == "g"
    np.testing.assert_array_equal(d.im, im)
    assert list(d.failed) == failed and list(d.record) == [k[0] for k in groups]
    # the random-azimuth fit takes every row
    assert len(fr.FragilitySession(str(sweep), im="pga_g").data(0, 0).im) == len(rows)
    fit = tmp_path / "fit.csv"
    p = subprocess.run([str(cli), "fragility", str(sweep), "--worst-azimuth", "-o", str(fit), "-q"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    (row,) = list(csv.DictReader(open(fit)))
    assert (row["im_name"], row["im_unit"]) == ("rotd50:pga_g", "g")
    assert plots.fragility_curve(str(fit), fig=Figure()).get_xlabel() == "RotD50 PGA [g]"
