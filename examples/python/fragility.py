#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""A fragility curve: a statue (rigid block) under two records scaled to a range of PGAs (an
incremental dynamic analysis), then the lognormal fragility of overturning against PGA fitted by
maximum likelihood, with its 95 % band.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/fragility.py -o build/example
"""

import argparse
import pathlib

import numpy as np
from matplotlib.figure import Figure

import flexrock as fr
from flexrock import plots

DATA = pathlib.Path(__file__).resolve().parents[3] / "shared" / "data"  # beside the repository

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("-o", "--output-dir", default=".", help="where the figure goes")
parser.add_argument("--levels", type=int, default=16, help="PGA levels per record")
parser.add_argument("--duration", type=float, default=0.0, help="[s] cut records to this (0: all)")
parser.add_argument("--threads", type=int, default=0, help="0: every core")
args = parser.parse_args()

body = fr.rigid_block(width=0.3, height=1.8, mass=600.0)  # alpha = 0.165 rad

# two records at scale 1, optionally cut short (for a quick try)
def cut(motion):
    if args.duration <= 0:
        return motion
    n = int(args.duration / 0.01)
    t = np.asarray(motion.times)[:n]
    return fr.motion_from_array(np.asarray(motion.horizontal)[:n], time=t)

records = {
    "elcentro": cut(fr.motion_from_file(str(DATA / "elcentro_1940_ns.dat"), "single_column",
                                        dt=0.02, units="g")),
    "kobe": cut(fr.motion_from_file(str(DATA / "kobe_1995_nishi_akashi_090.AT2"))),
}

# every record scaled to target PGAs from 0.1 g to 1.2 g, as a manifest's [scales] says it
levels = np.round(np.linspace(0.1, 1.2, args.levels), 6)
table = fr.sweep({"statue": body}, records, target_pga=levels, units="g", threads=args.threads)
failed = table["overturned"].astype(int)
print(f"{len(failed)} runs, {failed.sum()} overturned")

fit = fr.fragility(table["pga_g"], failed)
print(f"median PGA to overturn theta = {fit.theta:.3f} g "
      f"[{fit.theta_lower:.3f}, {fit.theta_upper:.3f}], beta = {fit.beta:.3f}")
x = np.array([0.25, 0.5, 1.0])
print("P(overturning) at", x, "g:", np.round(fr.fragility_probability(fit, x), 3))

# the fitted curve, its band and the observed fraction at each level
fig = Figure(figsize=(6, 4), layout="constrained")
plots.fragility_curve(fit, table["pga_g"], failed, fig=fig)
out = pathlib.Path(args.output_dir)
out.mkdir(parents=True, exist_ok=True)
print("wrote", plots.save(fig, out / "statue_fragility.png"))
