#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Regime at initiation of a rigid uniform block under a step acceleration, over mu and b/h: the
engine against the closed form of docs/theory.md §20, cell by cell.

A uniform rectangle of half-width b and half-height h (alpha = b/h, zeta^2 = (1 + alpha^2)/3),
at rest on a floor with Coulomb friction mu (static = kinetic), under a horizontal step a g
(a rectangular pulse of 0.02 s; only what happens at t = 0 is read). The engine's regime comes
from its events at t = 0: an uplift, a slip_start, both, or neither (rest / slide / rock /
slide-rock). The closed form (§20):

    rest        a <= min(mu, alpha)
    slide       mu < alpha and a > mu
    rock        mu >= alpha, a > alpha, and a <= a*(mu) or mu >= (zeta^2 + alpha^2)/alpha
    slide-rock  alpha <= mu < (zeta^2 + alpha^2)/alpha and a > a*(mu)

with a*(mu) = (mu (1 + zeta^2) - alpha) / (zeta^2 + alpha^2 - mu alpha). Prints the map (engine
regime per cell, a cell where the two differ marked) and the count of agreements; --md writes the
Markdown table of docs/validation.md.

    PYTHONPATH=build/release/python /usr/bin/python3 tools/validation/regime_map.py \\
        [--a 0.45] [--alphas 0.1:1.0:0.1] [--mus 0.1:1.5:0.1] [--md FILE]
"""

import argparse
import sys

import flexrock as fr

G = 9.80665
CODES = {"rest": ".", "slide": "S", "rock": "R", "slide-rock": "SR"}


def closed_form(a, alpha, mu):
    """The regime at initiation of docs/theory.md §20 (uniform block)."""
    z2 = (1.0 + alpha * alpha) / 3.0
    if a <= min(mu, alpha):
        return "rest"
    if mu < alpha:
        return "slide"
    # mu >= alpha and a > alpha
    always_rocks = mu >= (z2 + alpha * alpha) / alpha
    a_star = (mu * (1.0 + z2) - alpha) / (z2 + alpha * alpha - mu * alpha)
    return "rock" if always_rocks or a <= a_star else "slide-rock"


def engine(a, alpha, mu):
    """The regime the engine enters at t = 0: from its first events."""
    body = fr.Body(fr.BodyParameters.rectangular_block(100.0, 0.5 * alpha, 0.5))
    o = fr.SimulationOptions()
    o.friction_coefficient = mu
    r = fr.simulate(body, fr.rectangular_pulse(a_p=a * G, duration=0.02, t_1=0.02), fr.InitialState(), o)
    if r.status == fr.Status.stopped:
        raise RuntimeError(f"a {a} alpha {alpha} mu {mu}: the run stopped: {r.message}")
    at_start = {e.kind for e in r.events if e.time == 0.0}
    up = fr.EventKind.uplift in at_start
    slip = fr.EventKind.slip_start in at_start
    return {(False, False): "rest", (False, True): "slide", (True, False): "rock",
            (True, True): "slide-rock"}[(up, slip)]


def grid(text):
    """"start:stop:step" (stop included) or "x,y,z"."""
    if ":" in text:
        start, stop, step = (float(x) for x in text.split(":"))
        n = int(round((stop - start) / step))
        return [round(start + i * step, 12) for i in range(n + 1)]
    return [float(x) for x in text.split(",")]


def regime_map(a, alphas, mus):
    """[(alpha, mu, engine regime, closed-form regime)] over the grid."""
    return [(alpha, mu, engine(a, alpha, mu), closed_form(a, alpha, mu))
            for alpha in alphas for mu in mus]


def markdown(a, alphas, mus, cells):
    lines = ["| b/h \\ mu | " + " | ".join(f"{m:g}" for m in mus) + " |",
             "|---|" + "---|" * len(mus)]
    by = {(al, m): (e, c) for al, m, e, c in cells}
    for al in alphas:
        row = []
        for m in mus:
            e, c = by[(al, m)]
            row.append(CODES[e] if e == c else f"**{CODES[e]}** ({CODES[c]})")
        lines.append(f"| {al:g} | " + " | ".join(row) + " |")
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--a", type=float, default=0.45, help="step acceleration over g")
    p.add_argument("--alphas", default="0.1:1.0:0.1", help="b/h values: start:stop:step or a,b,c")
    p.add_argument("--mus", default="0.1:1.5:0.1", help="friction coefficients, likewise")
    p.add_argument("--md", help="write the Markdown table here")
    args = p.parse_args()
    alphas, mus = grid(args.alphas), grid(args.mus)
    cells = regime_map(args.a, alphas, mus)
    agree = sum(1 for _, _, e, c in cells if e == c)
    table = markdown(args.a, alphas, mus, cells)
    print(table, end="")
    counts = {k: sum(1 for _, _, e, _ in cells if e == k) for k in CODES}
    print(f"a = {args.a:g} g; cells: {len(cells)}; agree: {agree}; disagree: {len(cells) - agree}")
    print("engine regimes: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    for al, m, e, c in cells:
        if e != c:
            print(f"  differs: b/h {al:g} mu {m:g}: engine {e}, closed form {c}")
    if args.md:
        with open(args.md, "w") as f:
            f.write(table)
    return 0 if agree == len(cells) else 1


if __name__ == "__main__":
    sys.exit(main())
