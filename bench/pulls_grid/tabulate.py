#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The pulls-and-tensile-landings grid as Markdown tables, from the CSV of
`flexrock sweep bench/pulls_grid/pulls_grid.toml -o pulls_grid.csv`.

    python3 bench/pulls_grid/tabulate.py pulls_grid.csv [--flexrock build/release/apps/flexrock]

Body names are `<body>_<friction>` (friction: none, mu03, mu05, mu08); a body's weight M g comes
from `flexrock params` of its file (read from the study file next to this script)."""
import argparse
import csv
import re
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

HERE = Path(__file__).resolve().parent
FRICTION = [("none", "none"), ("mu03", "0.3"), ("mu05", "0.5"), ("mu08", "0.8")]


def body_files():
    # name -> file, from the study's [[body]] tables
    text = (HERE / "pulls_grid.toml").read_text()
    out = {}
    for name, file in re.findall(r'name = "([^"]+)"\nfile = "([^"]+)"', text):
        out[name] = HERE / file
    return out


def weight(flexrock, path):
    txt = subprocess.run([flexrock, "params", str(path)], capture_output=True, text=True,
                         check=True).stdout
    mass = float(re.search(r"mass M\s+([0-9.eE+-]+) kg", txt).group(1))
    g = float(re.search(r"gravity g\s+([0-9.eE+-]+) m/s\^2", txt).group(1))
    return mass * g


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("--flexrock", default=str(HERE.parent.parent / "build/release/apps/flexrock"))
    a = ap.parse_args()
    rows = list(csv.DictReader(open(a.csv)))
    files = body_files()
    w = {}
    runs = defaultdict(dict)  # (body, record, level) -> friction -> row
    for r in rows:
        body, fr = r["body"].rsplit("_", 1)
        if body not in w:
            w[body] = weight(a.flexrock, files[r["body"]])
        runs[(body, r["record"], float(r["requested_level"]))][fr] = r
    keys = sorted(runs, key=lambda k: (list(w).index(k[0]), k[1], k[2]))
    print("## Without friction: what the run reports where the sticking contact breaks\n")
    print("| body | record | PGA [g] | status | max θ/α | pulls (episodes) | largest pull [N] | "
          "[M g] | time under tension [s] | tensile landings | largest tensile impulse [N s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for k in keys:
        r = runs[k]["none"]
        pull = float(r["max_pivot_pull_N"])
        print(f"| {k[0]} | {k[1]} | {k[2]:g} | {r['status']} | {float(r['max_theta_over_alpha']):.3g} | "
              f"{r['pivot_tension_episodes']} | {pull:.4g} | {pull / w[k[0]]:.3g} | "
              f"{float(r['tension_time_s']):.4g} | {r['tensile_landings']} | "
              f"{float(r['max_tensile_impulse_N_s']):.4g} |")
    print("\n## Outcomes with friction coefficients none, 0.3, 0.5, 0.8\n")
    print("Each cell: status (overturned, completed, stopped), max θ/α, and in brackets where the "
          "floor pulled: the largest pull over M g, the pivot_tension episodes, the tensile landings.\n")
    print("| body | record | PGA [g] | " + " | ".join(f"μ = {m}" for _, m in FRICTION) + " |")
    print("|---|---|---|" + "---|" * len(FRICTION))
    for k in keys:
        cells = []
        for f, _ in FRICTION:
            r = runs[k].get(f)
            if r is None:
                cells.append("-")
                continue
            mark = "overturned" if r["overturned"] == "1" else r["status"]
            extra = ""
            pull = float(r["max_pivot_pull_N"]) / w[k[0]]
            if pull > 0.0 or int(r["tensile_landings"]):
                extra = (f" (pull {pull:.2g} M g, {r['pivot_tension_episodes']} episodes"
                         f", {r['tensile_landings']} tensile)")
            cells.append(f"{mark} {float(r['max_theta_over_alpha']):.3g}{extra}")
        print(f"| {k[0]} | {k[1]} | {k[2]:g} | " + " | ".join(cells) + " |")
    print("\n## Counts over the runs, per friction coefficient\n")
    print("| friction | runs | with pulls | pull episodes | largest pull [M g] | with tensile landings | "
          "overturned | stopped | completed |")
    print("|---|---|---|---|---|---|---|---|---|")
    for f, m in FRICTION:
        rs = [(k, runs[k][f]) for k in keys if f in runs[k]]
        pulls = [x for x in rs if int(x[1]["pivot_tension_episodes"]) > 0 or float(x[1]["max_pivot_pull_N"]) > 0]
        worst = max([float(r["max_pivot_pull_N"]) / w[k[0]] for k, r in rs] + [0.0])
        print(f"| {m} | {len(rs)} | {len(pulls)} | "
              f"{sum(int(r['pivot_tension_episodes']) for _, r in rs)} | {worst:.3g} | "
              f"{sum(1 for _, r in rs if int(r['tensile_landings']) > 0)} | "
              f"{sum(1 for _, r in rs if r['overturned'] == '1')} | "
              f"{sum(1 for _, r in rs if r['status'] == 'stopped')} | "
              f"{sum(1 for _, r in rs if r['status'] == 'completed')} |")
    changed = defaultdict(int)
    for k in keys:
        base = runs[k].get("none")
        for f, m in FRICTION[1:]:
            r = runs[k].get(f)
            if base and r and (base["overturned"] != r["overturned"]):
                changed[m] += 1
    print("\nRuns whose overturning changes against no friction: " +
          ", ".join(f"μ = {m}: {changed[m]}" for _, m in FRICTION[1:]) + ".")


if __name__ == "__main__":
    sys.exit(main())
