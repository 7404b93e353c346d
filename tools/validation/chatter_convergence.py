#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Does the chatter cut-off decide outcomes? Every run at chatter_ratio r, r/10 and r/100.

Rigid blocks (the museum statue 0.4 m x 1.8 m, a slender 0.4 m x 2.0 m block, a squat cabinet)
and two flexible bodies of contact_grid.py under El Centro 1940 NS and Kobe 1995 at scales
0.25 ... 3. r is the engine's default SimulationOptions().chatter_ratio unless --ratio gives
another. Overturning is declared at |theta| = pi/2, as in the studies (spectra, sweeps);
--engine-overturn uses the engine's default criterion instead. One line a (body, record,
scale): the outcome at each ratio (no_uplift, rocking, overturned on edge 1 or 2, or whatever
the run ended with), the chatter cut-offs of each run, and whether the outcome changed; then the
number of changed outcomes.

    PYTHONPATH=build/release/python /usr/bin/python3 tools/validation/chatter_convergence.py \
        [--ratio R] [--engine-overturn] [--md FILE] [--bodies NAME,...]
"""

import argparse
import collections
import sys
from pathlib import Path

import flexrock as fr

sys.path.insert(0, str(Path(__file__).resolve().parent))
import contact_grid as grid  # noqa: E402

FACTORS = [1.0, 0.1, 0.01]


def bodies():
    """name -> BodyParameters."""
    flexible = grid.bodies()
    return {
        "statue": fr.rigid_block(0.4, 1.8, 800.0),        # examples/cases/museum_statue.toml
        "slender_block": fr.rigid_block(0.4, 2.0, 1000.0),  # examples/studies/slender_block.toml
        "squat_cabinet": fr.rigid_block(0.8, 1.4, 300.0),   # a low cabinet, b/h = 0.57
        "oscillator_2hz": flexible["oscillator_2hz"][0],
        "tank": flexible["tank"][0],
    }


def label(run):
    """The outcome of one run in words: overturned with its side, else the study outcome."""
    if run["status"] == "overturned" or run["outcome"].startswith("overturned"):
        side = run["side"] or (1 if run["final_theta"] >= 0 else 2)
        return f"overturned_{side}"
    return run["outcome"]


def options(ratio, engine_overturn):
    o = fr.SimulationOptions()
    if not engine_overturn:
        o.overturn = fr.OverturnCriterion.half_pi
    o.chatter_ratio = ratio
    return o


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ratio", type=float, help="the coarsest chatter_ratio r (default: the engine's)")
    ap.add_argument("--engine-overturn", action="store_true",
                    help="the engine's default overturning criterion instead of |theta| = pi/2")
    ap.add_argument("--md", help="also write the table and totals as a markdown fragment")
    ap.add_argument("--bodies", help="comma-separated subset of: " + ",".join(bodies()))
    ap.add_argument("--records", help="comma-separated subset of: elcentro,kobe")
    ap.add_argument("--scales", help="comma-separated scales (default 0.25,0.5,1,1.5,2,2.5,3)")
    a = ap.parse_args(argv)

    r0 = a.ratio if a.ratio is not None else fr.SimulationOptions().chatter_ratio
    ratios = [r0 * f for f in FACTORS]
    all_bodies = bodies()
    names = grid.parse_list(a.bodies) if a.bodies else list(all_bodies)
    for n in names:
        if n not in all_bodies:
            ap.error(f"--bodies: unknown body {n!r}; expected one of {', '.join(all_bodies)}")
    recs = grid.parse_list(a.records) if a.records else list(grid.records())
    scales = grid.parse_list(a.scales, float) if a.scales else grid.SCALES
    crit = name_of_default() if a.engine_overturn else "half_pi"
    print(f"chatter ratios {', '.join(f'{r:g}' for r in ratios)}; overturning criterion {crit}")

    header = (["body", "record", "scale"] + [f"outcome r={r:g}" for r in ratios]
              + [f"cut-offs r={r:g}" for r in ratios] + ["changed"])
    cells, changed = [], collections.Counter()
    for n in names:
        for rec in recs:
            for s in scales:
                runs = [grid.run_one(all_bodies[n], rec, s, options(r, a.engine_overturn)) for r in ratios]
                labels = [label(x) for x in runs]
                cuts = [str(x["events"].get("chatter_cutoff", 0)) for x in runs]
                ch = len(set(labels)) > 1
                if ch:
                    changed[n] += 1
                cells.append([n, rec, f"{s:g}"] + labels + cuts + ["CHANGED" if ch else ""])
    print(grid.text_table(header, cells))
    total = sum(changed.values())
    lines = [f"runs: {len(cells)} (body, record, scale) x {len(ratios)} ratios",
             f"outcome changed between the ratios: {total}"
             + (" (" + ", ".join(f"{k} {v}" for k, v in changed.items()) + ")" if total else "")]
    # against the finest ratio, as the reference
    coarse = sum(1 for c in cells if c[3] != c[3 + len(ratios) - 1])
    lines.append(f"outcome at r={ratios[0]:g} differs from r={ratios[-1]:g}: {coarse}")
    print()
    print("\n".join(lines))
    if a.md:
        text = (f"Chatter ratios {', '.join(f'{r:g}' for r in ratios)}; overturning {crit}.\n\n"
                + grid.md_table(header, cells) + "\n\n" + "\n".join(f"- {t}" for t in lines) + "\n")
        Path(a.md).write_text(text)
        print(f"\nwrote {a.md}")
    return 0


def name_of_default():
    return grid.name_of(fr.SimulationOptions().overturn)


if __name__ == "__main__":
    sys.exit(main())
