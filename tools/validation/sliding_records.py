#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The record table of docs/validation/sliding.md: El Centro 1940 at scales 1 and 2 with Coulomb
friction mu = 0.1, 0.2, 0.3 (and none) for a squat rigid block and the example flexible tank, each
at the default tolerances and at rtol / 10 (the offsets must not depend on the tolerance).

Usage: tools/validation/sliding_records.py FLEXROCK [WORKDIR]   (prints the markdown table)
"""
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RECORD = os.path.join(ROOT, "..", "shared", "data", "elcentro_1940_ns.dat")

BLOCK = """name = "squat block"
[body]
type = "rigid_block"
width = 1.2
height = 1.6
mass = 1000.0
"""


def tank_body():
    # the [body] table of the example tank, as the example writes it
    with open(os.path.join(ROOT, "examples", "cases", "flexible_tank.toml")) as fh:
        lines = fh.read().split("\n[excitation")[0]
    return lines + "\n"


def run(flexrock, work, name, body, scale, mu, rtol):
    case = os.path.join(work, name + ".toml")
    with open(case, "w") as fh:
        fh.write(body)
        fh.write(f"""
[excitation.horizontal]
type = "record"
file = "{RECORD}"
format = "single_column"
dt = 0.02
units = "g"
scale = {scale}

[solver]
friction_coefficient = {mu}
rtol = {rtol}
atol = {rtol * 1e-2}
""")
    out = os.path.join(work, name)
    subprocess.run([flexrock, "run", case, "-o", out, "-q"], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, name + ".summary.json")) as fh:
        return json.load(fh)


def main():
    flexrock = sys.argv[1]
    work = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp()
    os.makedirs(work, exist_ok=True)
    rows = []
    worst = 0.0
    for body_name, body in (("squat rigid block, 1.2 m x 1.6 m", BLOCK), ("flexible tank (example)", tank_body())):
        for scale in (1, 2):
            for mu in ("0.1", "0.2", "0.3", "inf"):
                tag = f"{'block' if 'block' in body_name else 'tank'}_{scale}_{mu}"
                j = run(flexrock, work, tag, body, scale, mu, 1e-9)
                k = run(flexrock, work, tag + "_fine", body, scale, mu, 1e-10)
                s, sk = j.get("sliding", {}), k.get("sliding", {})
                for key in ("max_offset_m", "final_offset_m"):
                    worst = max(worst, abs(s.get(key, 0.0) - sk.get(key, 0.0)))
                o, p, e = j["outcome"], j["peaks"], j["energy"]
                rows.append(
                    f"| {body_name} | {scale} | {mu} | {'overturned' if o['overturned'] else o['status']}"
                    f" | {p['max_theta_rad']:.3g} | {1e3 * s.get('max_offset_m', 0.0):.1f}"
                    f" | {1e3 * s.get('final_offset_m', 0.0):.1f} | {s.get('sliding_time_s', 0.0):.2f}"
                    f" | {s.get('slips', 0)} | {s.get('friction_loss_J', 0.0):.4g}"
                    f" | {e['relative_residual']:.1e} | {1e3 * sk.get('max_offset_m', 0.0):.1f} |")
    print("| body | scale | mu | outcome | max tilt [rad] | peak offset [mm] | residual offset [mm]"
          " | time sliding [s] | slips | friction work [J] | energy residual / scale"
          " | peak offset at rtol/10 [mm] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    print(f"\nLargest change of a peak or residual offset when rtol and atol are made 10 times"
          f" finer: {worst:.2g} m.")


if __name__ == "__main__":
    main()
