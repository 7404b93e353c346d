#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""`flexrock fragility --analysis msa` and `--analysis ida` against known parameters and an
independent maximum-likelihood fit with scipy.optimize (Baker 2015).

Multiple-stripe analysis: seeded stripes at known levels, a different number of runs per stripe
(records that were not run at a level), failures drawn from a lognormal fragility; flexrock's fit
must recover the parameters (within 4 of its standard errors) and agree with scipy's minimum of
the binomial negative log-likelihood sum_j -[z_j ln p_j + (n_j - z_j) ln(1 - p_j)] to 1e-4.
Truncated IDA: seeded lognormal capacities, every record run at increasing levels up to a highest
one below many capacities; the first failure bounds each capacity to an interval, records that
never fail are truncated there; the same two checks against scipy's minimum of
-sum ln(Phi(b_i) - Phi(a_i)) with the intervals found here.
Usage: study_fragility_msa_reference.py FLEXROCK"""
import csv
import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy import optimize, stats

flexrock = sys.argv[1]
columns = ("index,body,record,requested_level,requested_units,scale,pga_m_per_s2,pga_g,pgv_m_per_s,"
           "duration_s,outcome,overturned,overturn_edge,overturn_time_s,max_theta_rad,"
           "max_theta_over_alpha,impacts,first_uplift_time_s,max_uplift_m,max_impulse_N_s,"
           "energy_lost_J,max_friction_demand,status,message").split(",")


def write(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(columns)
        for i, (record, level, pga_g, failed) in enumerate(rows):
            row = dict.fromkeys(columns, "0")
            row.update(index=i, body="b", record=record, requested_level=repr(level),
                       requested_units="g", pga_g=repr(pga_g), pga_m_per_s2=repr(pga_g * 9.80665),
                       overturned=int(failed),
                       outcome="overturned_after_impacts" if failed else "rocking",
                       status="overturned" if failed else "completed", message="")
            w.writerow([row[c] for c in columns])


def fit(work, sweep, *args):
    out = os.path.join(work, "fit.csv")
    p = subprocess.run([flexrock, "fragility", sweep, "-o", out, *args], capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr
    with open(out) as f:
        return next(csv.DictReader(f)), p.stdout


def check(name, got, nll, truth, x0):
    ref = optimize.minimize(nll, x0=x0, method="Nelder-Mead",
                            options=dict(xatol=1e-11, fatol=1e-13, maxiter=40000))
    assert ref.success, ref.message
    theta_ref, beta_ref = math.exp(ref.x[0]), ref.x[1]
    theta, beta = float(got["theta"]), float(got["beta"])
    print(f"{name}: flexrock theta = {theta:.8g}, beta = {beta:.8g}; scipy theta = "
          f"{theta_ref:.8g}, beta = {beta_ref:.8g}; true {truth}")
    assert abs(theta / theta_ref - 1) < 1e-4, "theta differs from scipy's"
    assert abs(beta / beta_ref - 1) < 1e-4, "beta differs from scipy's"
    assert abs(math.log(theta / truth[0])) < 4 * float(got["se_ln_theta"]), "theta not recovered"
    assert abs(beta - truth[1]) < 4 * float(got["se_beta"]), "beta not recovered"
    return ref


with tempfile.TemporaryDirectory() as work:
    # --- multiple stripes
    rng = np.random.default_rng(20251124)
    theta, beta = 0.45, 0.4
    levels = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0]
    runs = [200, 190, 180, 170, 160, 150, 140, 120]  # fewer records reach the higher levels
    rows, n, z = [], [], []
    for level, nj in zip(levels, runs):
        p = stats.norm.cdf(math.log(level / theta) / beta)
        failed = rng.uniform(size=nj) < p
        n.append(nj)
        z.append(int(failed.sum()))
        for k, f in enumerate(failed):
            # the record's own PGA differs in the last digits: the stripe is the requested level
            rows.append((f"r{k}", level, level * (1 + 1e-13 * k), bool(f)))
    sweep = os.path.join(work, "msa.csv")
    write(sweep, rows)
    got, out = fit(work, sweep, "--analysis", "msa")
    assert f"stripe 0.1 g: {z[0]} of {n[0]} runs failed" in out, out
    n, z, x = np.array(n), np.array(z), np.array(levels)

    def nll_msa(v):
        lt, b = v
        if b <= 0:
            return np.inf
        e = (np.log(x) - lt) / b
        return -np.sum(z * stats.norm.logcdf(e) + (n - z) * stats.norm.logcdf(-e))

    ref = check("msa", got, nll_msa, (theta, beta), [math.log(0.5), 0.3])
    # the fit CSV's log-likelihood is the binomial one, with ln C(n, z)
    log_c = sum(math.lgamma(a + 1) - math.lgamma(b + 1) - math.lgamma(a - b + 1) for a, b in zip(n, z))
    assert abs(float(got["log_likelihood"]) - (log_c - ref.fun)) < 1e-6, "binomial log-likelihood"
    # --im other than the stripes is refused
    p = subprocess.run([flexrock, "fragility", sweep, "--analysis", "msa", "--im", "pga"],
                       capture_output=True, text=True)
    assert p.returncode == 2 and "leave --im out" in p.stderr, p.stderr

    # --- truncated IDA
    theta, beta, records = 0.5, 0.35, 400
    capacity = theta * np.exp(beta * rng.standard_normal(records))
    levels = [0.05 * k for k in range(1, 13)]  # up to 0.6 g: a third of the records never fail
    rows, lower, upper = [], [], []
    for i, c in enumerate(capacity):
        first = next((lv for lv in levels if lv >= c), None)
        lower.append(0.0 if first == levels[0] else (levels[levels.index(first) - 1] if first else levels[-1]))
        upper.append(first if first else math.inf)
        for lv in levels:
            rows.append((f"r{i}", lv, lv, lv >= c))
    assert 0.2 < np.mean(np.isinf(upper)) < 0.5
    sweep = os.path.join(work, "ida.csv")
    write(sweep, rows)
    got, out = fit(work, sweep, "--analysis", "ida", "--im", "pga_g")
    assert f"capacities of {records} records" in out, out
    lo, hi = np.array(lower), np.array(upper)

    def nll_ida(v):
        lt, b = v
        if b <= 0:
            return np.inf
        with np.errstate(divide="ignore"):
            a = np.where(lo > 0, (np.log(np.where(lo > 0, lo, 1)) - lt) / b, -np.inf)
        u = np.where(np.isfinite(hi), (np.log(np.where(np.isfinite(hi), hi, 1)) - lt) / b, np.inf)
        return -np.sum(np.log(stats.norm.cdf(u) - stats.norm.cdf(a)))

    check("truncated ida", got, nll_ida, (theta, beta), [math.log(0.4), 0.3])
print("ok")
