#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Cost of the azimuth sweep of a record pair, and the envelope against each component alone.

1. Cost: 72 azimuths (5 deg) of a slender rigid block (b = 0.25 m, h = 1.5 m) and of a one-mode
   uniform cantilever under the Chino Hills pair RSN 8884 (x 3), against one planar run of the
   same case at azimuth 30 deg (the engine alone, no time history): the best of REPEATS of wall
   and CPU time, 1 and 2 threads.
2. Outcomes: the block under both Chino Hills pairs (RSN 8884 Brea, RSN 8883 Anaheim) scaled by
   2, 4 and 6: theta/alpha at beta = 0 (H1 alone), beta = 90 (H2 alone) and the envelope, the
   overturning azimuths and the largest impact forces. Prints Markdown tables.

    PYTHONPATH=build/release/python python3 bench/azimuth_cost.py [REPEATS]
"""
import atexit
import os
import shutil
import sys
import tempfile
import time

import flexrock as fr

here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, "..", "..", "shared", "data")
repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
pairs = {"RSN8884": ("RSN8884_14383980_13873090.AT2", "RSN8884_14383980_13873360.AT2"),
         "RSN8883": ("RSN8883_14383980_13849090.AT2", "RSN8883_14383980_13849360.AT2")}
bodies = {
    "rigid block b = 0.25 m, h = 1.5 m": 'type = "rigid_block"\nwidth = 0.5\nheight = 3.0\n'
                                         'mass = 1000.0\n',
    "uniform cantilever, 1 mode": 'type = "uniform_cantilever"\nheight = 3.0\nwidth = 0.8\n'
                                  'mass_per_length = 500.0\nbending_stiffness = 2.0e6\n'
                                  'modes = 1\nbase_mass = 200.0\ndamping_ratio = 0.02\n',
}
work = tempfile.mkdtemp(prefix="flexrock_azimuth_cost.")
atexit.register(shutil.rmtree, work, True)


def case(body, pair, scale, extra=""):
    h1, h2 = (os.path.join(data, f) for f in pairs[pair])
    path = os.path.join(work, f"c{abs(hash((body, pair, scale, extra)))}.toml")
    with open(path, "w") as f:
        f.write(f"[body]\n{body}[excitation]\nscale = {scale}\n{extra}\n"
                f'[excitation.horizontal]\ntype = "record"\nfile = "{h1}"\n'
                f'[excitation.horizontal2]\ntype = "record"\nfile = "{h2}"\n')
    return fr.load_case(path)


def best(f):
    w, p = [], []
    for _ in range(repeats):
        w0, p0 = time.perf_counter(), time.process_time()
        f()
        w.append(time.perf_counter() - w0)
        p.append(time.process_time() - p0)
    return min(w), min(p)


print("| body | one run: wall, CPU (ms) | 72 azimuths, 1 thread: wall, CPU (ms) | 2 threads: wall, "
      "CPU (ms) | CPU ratio (1 thread) |")
print("|---|---|---|---|---|")
for name, body in bodies.items():
    c = case(body, "RSN8884", 3)
    one = case(body, "RSN8884", 3, "azimuth_deg = 30")
    b = fr.Body(one.body)
    o = one.options
    o.output_dt = 0.0
    w1, p1 = best(lambda: fr._flexrock.simulate(b, one.motion, one.initial, o))
    wa, pa = best(lambda: fr.run_azimuths(c, threads=1))
    wb, pb = best(lambda: fr.run_azimuths(c, threads=2))
    print(f"| {name} | {1e3 * w1:.2f}, {1e3 * p1:.2f} | {1e3 * wa:.1f}, {1e3 * pa:.1f} | "
          f"{1e3 * wb:.1f}, {1e3 * pb:.1f} | {pa / p1:.0f} |")

print()
print("| pair | scale | H1 only: theta/alpha, outcome | H2 only: theta/alpha, outcome | "
      "envelope: theta/alpha @ azimuth | overturning azimuths (of 72) | impact force H1 / H2 / "
      "envelope (kN) |")
print("|---|---|---|---|---|---|---|")
block = bodies["rigid block b = 0.25 m, h = 1.5 m"]
for pair in pairs:
    for scale in (2, 4, 6):
        t, e = fr.run_azimuths(case(block, pair, scale), threads=2)
        az = list(t["azimuth_deg"])
        i0, i90 = az.index(0.0), az.index(90.0)

        def o(i):
            return f'{t["max_theta_over_alpha"][i]:.3f}, {t["outcome"][i]}'

        ov = e["overturned_azimuths_deg"]
        ovs = f"{len(ov)}" + (f" ({min(ov):g}..{max(ov):g} deg)" if ov else "")
        f = t["max_impact_force_N"]
        print(f"| {pair} | {scale} | {o(i0)} | {o(i90)} | {e['max_theta_over_alpha']:.3f} @ "
              f"{e['max_theta_azimuth_deg']:g} deg | {ovs} | {f[i0] / 1e3:.1f} / "
              f"{f[i90] / 1e3:.1f} / {e['max_impact_force_N'] / 1e3:.1f} |")
