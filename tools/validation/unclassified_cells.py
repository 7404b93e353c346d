#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Outcome counts of the pulse maps of a rigid block: how many cells are left unclassified?

Two families of maps, both on the grid of docs/validation.md section 2 (omega_p/p in 1..10, 37
columns x a_p/(g tan alpha) in 1..20, 58 rows = 2146 cells), blocks of R = 1 m, alpha the angle
(b/h = tan alpha), restitution as the paper's law:

1. "validation": the Zhang & Makris maps as tools/validation/validate.cpp computes them (pulses
   cycloidal_a = one-sine, type A, and cycloidal_b, type B; 30/p of free motion after the pulse;
   rtol 1e-9, atol 1e-11, max_step 0.05/p; overturning at pi/2). Counted twice: by the
   engine's status (overturned, completed as safe, stopped as unresolved) and by the study
   outcome of the engine (flexrock.summarize).
2. "spectrum": `flexrock spectrum` on a study file with a [body] table (rigid_block, width
   2 sin alpha, height 2 cos alpha), pulse one_sine, the same normalized grid, the study
   defaults (no bisection): the outcome column of its cells CSV.

Prints the count of every outcome per map, and of every engine status with the overturned cells
whose status was not "overturned" (reclassified by the study rule). Outcomes and statuses are read
by name, so new ones appear.

    PYTHONPATH=build/release/python /usr/bin/python3 tools/validation/unclassified_cells.py \
        [--alpha 0.25] [--cli build/release/apps/flexrock] [--quick] [--md FILE]
"""

import argparse
import collections
import csv
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import flexrock as fr

ROOT = Path(__file__).resolve().parents[2]
G = 9.80665


def grid(quick):
    ws = np.linspace(1.0, 10.0, 10 if quick else 37)
    As = np.linspace(1.0, 20.0, 12 if quick else 58)
    return ws, As


def name_of(x):
    return getattr(x, "name", str(x))


def validation_maps(alpha, quick):
    """{map name: (Counter by the validation's rule, Counter by the study outcome)}."""
    body = fr.Body(fr.BodyParameters.rectangular_block(1000.0, math.sin(alpha), math.cos(alpha)))
    p = body.rocking_frequency
    g = body.g
    ws, As = grid(quick)
    out = {}
    for kind, pulse in (("A", fr.cycloidal_pulse_a), ("B", fr.cycloidal_pulse_b)):
        rule, study, status = collections.Counter(), collections.Counter(), collections.Counter()
        for A in As:
            for w in ws:
                wp = w * p
                dur = 2 * math.pi / wp + 30.0 / p
                m = pulse(A * g * math.tan(alpha), wp, dur)
                o = fr.SimulationOptions()
                o.rtol, o.atol, o.max_step = 1e-9, 1e-11, 0.05 / p
                o.t_end = m.duration
                o.overturn = fr.OverturnCriterion.half_pi
                raw = fr.simulate(body, m, options=o).raw
                st = name_of(raw.status)
                x = raw.extremes
                # the engine's statuses: completed, overturned (in any contact mode), stopped
                if st == "overturned":
                    rule["overturned_after_impacts" if x.impacts > 0 else "overturned_without_impact"] += 1
                elif st == "completed":
                    rule["safe"] += 1
                else:
                    rule[st] += 1
                outcome = name_of(fr.summarize(body, raw).outcome)
                study[outcome] += 1
                status[st] += 1
                if outcome.startswith("overturned") and st != "overturned":
                    status[f"overturned by reclassification of {st}"] += 1
        out[f"validation type {kind} (cycloidal_{kind.lower()})"] = (rule, study, status)
    return out


def spectrum_map(alpha, quick, cli):
    ws, As = grid(quick)
    text = f"""# one-sine overturning map of a rigid block, alpha = {alpha} (b/h = tan alpha), R = 1 m
name = "one-sine block alpha {alpha}"
[body]
type = "rigid_block"
width = {2 * math.sin(alpha)!r}
height = {2 * math.cos(alpha)!r}
mass = 1000.0

[spectrum]
pulse = "one_sine"
axes = "normalized"
amplitudes = {{ start = {As[0]!r}, stop = {As[-1]!r}, count = {len(As)} }}
frequencies = {{ start = {ws[0]!r}, stop = {ws[-1]!r}, count = {len(ws)} }}
bisect = false
"""
    with tempfile.TemporaryDirectory() as d:
        spec = Path(d) / "spectrum.toml"
        spec.write_text(text)
        cells = Path(d) / "cells.csv"
        cmd = [str(cli), "spectrum", str(spec), "-o", str(cells), "--no-bisect", "-j", "2"]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        with open(cells, newline="") as f:
            rows = list(csv.DictReader(r for r in f if not r.startswith("#")))
    status = collections.Counter(r.get("status", "?") for r in rows)
    for r in rows:
        if r["outcome"].startswith("overturned") and r.get("status", "overturned") != "overturned":
            status[f"overturned by reclassification of {r['status']}"] += 1
    return collections.Counter(r["outcome"] for r in rows), status, " ".join(cmd[:2] + ["SPEC", "-o", "CELLS", "--no-bisect", "-j", "2"]), text


def fmt(counter):
    total = sum(v for k, v in counter.items() if not k.startswith("overturned by"))
    return ", ".join(f"{k} {v}" for k, v in sorted(counter.items())) + f" (of {total})"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--alpha", type=float, action="append",
                    help="tipping angle [rad] (repeatable; default 0.25)")
    ap.add_argument("--cli", default=str(ROOT / "build" / "release" / "apps" / "flexrock"),
                    help="the flexrock binary for the spectrum map")
    ap.add_argument("--no-validation", action="store_true", help="only the `flexrock spectrum` map")
    ap.add_argument("--quick", action="store_true", help="a 10 x 12 grid (smoke run)")
    ap.add_argument("--md", help="also write the counts as a markdown fragment")
    a = ap.parse_args(argv)
    alphas = a.alpha or [0.25]
    md = ["| map | α | counting | outcomes |", "|---|---|---|---|"]
    for alpha in alphas:
        print(f"alpha = {alpha} (b/h = {math.tan(alpha):.4f})")
        if not a.no_validation:
            for name, (rule, study, status) in validation_maps(alpha, a.quick).items():
                print(f"  {name}, validation's rule: {fmt(rule)}")
                print(f"  {name}, study outcome:     {fmt(study)}")
                print(f"  {name}, engine status:     {fmt(status)}")
                md.append(f"| {name} | {alpha} | validation's rule | {fmt(rule)} |")
                md.append(f"| {name} | {alpha} | study outcome | {fmt(study)} |")
                md.append(f"| {name} | {alpha} | engine status | {fmt(status)} |")
        counts, status, cmd, _ = spectrum_map(alpha, a.quick, a.cli)
        print(f"  flexrock spectrum, one_sine ({cmd}): {fmt(counts)}")
        print(f"  flexrock spectrum, one_sine, engine status: {fmt(status)}")
        md.append(f"| flexrock spectrum one_sine | {alpha} | study outcome | {fmt(counts)} |")
        md.append(f"| flexrock spectrum one_sine | {alpha} | engine status | {fmt(status)} |")
    if a.md:
        Path(a.md).write_text("\n".join(md) + "\n")
        print(f"wrote {a.md}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
