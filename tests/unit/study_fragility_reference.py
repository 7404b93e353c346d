#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""`flexrock fragility` against an independent maximum-likelihood fit with scipy.optimize.

A synthetic sweep CSV (seeded) with a known lognormal fragility is fitted by flexrock and by
minimising the negative log-likelihood in (ln theta, beta) with Nelder-Mead; the two estimates
must agree to 1e-4 relative. Usage: study_fragility_reference.py FLEXROCK"""
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy import optimize, stats

flexrock = sys.argv[1]
rng = np.random.default_rng(20240601)
theta, beta, n = 0.35, 0.45, 600
pga_g = theta * np.exp(rng.uniform(-2.5, 2.5, n) * beta)
failed = (rng.uniform(size=n) < stats.norm.cdf(np.log(pga_g / theta) / beta)).astype(int)

columns = ("index,body,record,scale,pga_m_per_s2,pga_g,pgv_m_per_s,duration_s,outcome,overturned,"
           "overturn_edge,overturn_time_s,max_theta_rad,max_theta_over_alpha,impacts,"
           "first_uplift_time_s,max_uplift_m,max_impulse_N_s,energy_lost_J,max_friction_demand,"
           "status,message").split(",")
with tempfile.TemporaryDirectory() as work:
    sweep = os.path.join(work, "sweep.csv")
    with open(sweep, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(columns)
        for i, (x, y) in enumerate(zip(pga_g, failed)):
            row = dict.fromkeys(columns, "0")
            row.update(index=i, body="b", record="r", pga_g=repr(float(x)),
                       pga_m_per_s2=repr(float(x) * 9.80665), overturned=int(y),
                       outcome="overturned_after_impacts" if y else "rocking",
                       status="overturned" if y else "completed", message="")
            w.writerow([row[c] for c in columns])
    out = os.path.join(work, "fit.csv")
    subprocess.run([flexrock, "fragility", sweep, "--im", "pga_g", "-o", out, "-q"], check=True,
                   stdout=subprocess.DEVNULL)
    with open(out) as f:
        fit = next(csv.DictReader(f))

def nll(v):
    lt, b = v
    if b <= 0:
        return np.inf
    z = (np.log(pga_g) - lt) / b
    return -np.sum(np.where(failed == 1, stats.norm.logcdf(z), stats.norm.logcdf(-z)))

ref = optimize.minimize(nll, x0=[np.log(np.median(pga_g)), 0.3], method="Nelder-Mead",
                        options=dict(xatol=1e-10, fatol=1e-12, maxiter=20000))
theta_ref, beta_ref = np.exp(ref.x[0]), ref.x[1]
theta_fr, beta_fr = float(fit["theta"]), float(fit["beta"])
print(f"flexrock: theta = {theta_fr:.8g}, beta = {beta_fr:.8g}")
print(f"scipy:    theta = {theta_ref:.8g}, beta = {beta_ref:.8g}")
assert ref.success, ref.message
assert abs(theta_fr / theta_ref - 1) < 1e-4, "theta differs from scipy's"
assert abs(beta_fr / beta_ref - 1) < 1e-4, "beta differs from scipy's"
assert float(fit["log_likelihood"]) >= -ref.fun - 1e-7, "scipy found a higher likelihood"
print("ok")
