#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""`flexrock fragility --state ...`: several damage states fitted at once, against known data.

A synthetic sweep CSV (seeded) whose demand is D = a x^b eps, ln eps ~ N(0, s), x the IM: the
run uplifts when D > 0.05, its max theta/alpha is D, it overturns when D > 1. Then
P(D > c | x) = Phi((ln x - ln x_c) / beta) with x_c = (c/a)^(1/b) and beta = s/b for every
threshold c: each state's fit must recover its median and the common beta (within 4 of the fit's
own standard errors), the family must come out in one fit CSV and one curve CSV with a state
column, states given out of order must be reported as crossing medians, and bad states refused.
Usage: study_fragility_states.py FLEXROCK"""
import csv
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

flexrock = sys.argv[1]
rng = np.random.default_rng(20251124)
a, b, s, n = 0.8, 1.5, 0.6, 4000
x = np.exp(rng.uniform(math.log(0.02), math.log(3.0), n))
d = a * x**b * np.exp(rng.normal(0.0, s, n))
thresholds = {"uplift": 0.05, "theta:0.3": 0.3, "theta:0.6": 0.6, "overturned": 1.0}

columns = ("index,body,record,scale,pga_m_per_s2,pga_g,pgv_m_per_s,duration_s,outcome,overturned,"
           "overturn_edge,overturn_time_s,max_theta_rad,max_theta_over_alpha,impacts,"
           "first_uplift_time_s,max_uplift_m,max_impulse_N_s,energy_lost_J,max_friction_demand,"
           "status,message").split(",")


def run(*args):
    return subprocess.run([flexrock, *args], capture_output=True, text=True)


with tempfile.TemporaryDirectory() as work:
    sweep = os.path.join(work, "sweep.csv")
    with open(sweep, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(columns)
        for i, (xi, di) in enumerate(zip(x, d)):
            row = dict.fromkeys(columns, "0")
            over = di > 1.0
            outcome = ("overturned_after_impacts" if over else "rocking" if di > 0.05 else "no_uplift")
            row.update(index=i, body="b", record="r", pga_g=repr(float(xi)), outcome=outcome,
                       overturned=int(over), max_theta_over_alpha=repr(float(min(di, 1.0) if di > 0.05 else 0.0)),
                       status="overturned" if over else "completed", message="")
            w.writerow([row[c] for c in columns])
    fit_csv, curve_csv = os.path.join(work, "fit.csv"), os.path.join(work, "curve.csv")
    args = ["fragility", sweep, "--im", "pga_g", "-o", fit_csv, "--curve", curve_csv,
            "--curve-points", "5"]
    for state in thresholds:
        args += ["--state", state]
    p = run(*args)
    assert p.returncode == 0, p.stderr
    assert "warning" not in p.stdout, p.stdout
    with open(fit_csv) as f:
        fits = list(csv.DictReader(f))
    assert [r["state"] for r in fits] == list(thresholds), fits
    assert list(fits[0])[:3] == ["body", "state", "samples"]
    for r in fits:
        c = thresholds[r["state"]]
        median, beta = (c / a) ** (1 / b), s / b
        theta, se_lt = float(r["theta"]), float(r["se_ln_theta"])
        assert abs(math.log(theta / median)) < 4 * se_lt, (r["state"], theta, median, se_lt)
        assert abs(float(r["beta"]) - beta) < 4 * float(r["se_beta"]), (r["state"], r["beta"], beta)
        # the failures are the rows above the threshold, counted here
        assert int(r["failures"]) == int(np.count_nonzero(d > c)), r["state"]
    with open(curve_csv) as f:
        curve = list(csv.DictReader(f))
    assert len(curve) == 5 * len(thresholds) and list(curve[0])[:2] == ["body", "state"]
    assert [r["state"] for r in curve[::5]] == list(thresholds)

    # flexrock plot draws the family: one curve per state (labelled "body: state")
    # (where the build has its Python package, which flexrock plot runs)
    if os.environ.get("FLEXROCK_TEST_PLOT") == "1":
        for src in (fit_csv, curve_csv):
            fig = os.path.join(work, "family.svg")
            p = run("plot", src, "-o", fig)
            assert p.returncode == 0, p.stderr
            # each fitted curve is a path with the id "fit" (its gid)
            assert open(fig).read().count('id="fit') == len(thresholds), src

    # the more severe state given first: its median is above the next one's, which is reported
    p = run("fragility", sweep, "--im", "pga_g", "--state", "theta:0.6", "--state", "theta:0.3")
    assert p.returncode == 0, p.stderr
    assert "warning: the fitted medians cross: theta:0.3" in p.stdout, p.stdout

    # bad states: exit 2 with what is expected
    for bad, why in [("theta", "a level is missing"), ("theta:-1", "is not a number > 0"),
                     ("uplift:2", "takes no level"), ("tilt:0.5", "expected overturned, uplift")]:
        p = run("fragility", sweep, "--state", bad)
        assert p.returncode == 2 and why in p.stderr, (bad, p.stderr)
    p = run("fragility", sweep, "--state", "uplift", "--outcome", "theta", "--level", "0.5")
    assert p.returncode == 2 and "not both" in p.stderr, p.stderr
    p = run("fragility", sweep, "--state", "uplift", "--state", "uplift")
    assert p.returncode == 2 and "given twice" in p.stderr, p.stderr
print("ok")
