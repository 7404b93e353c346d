#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The cost of a rocking frame's run against its equivalent single block (docs/theory.md §25)
under the Kobe record at several scales: median CPU time per run of `flexrock.simulate_case` on a
`rocking_frame` case and on a `rigid_body` case holding the frame's equivalent body, both with a
time history at 0.005 s (the spacing the frame's contact check uses when none is asked for) and,
for the frame, without one.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/frame_cost.py [repetitions]
"""
import os
import statistics
import sys
import tempfile
import time

import flexrock as fr

HERE = os.path.dirname(os.path.abspath(__file__))
KOBE = os.path.join(HERE, "..", "..", "shared", "data", "kobe_1995_nishi_akashi_090.AT2")

FRAME = """
[body]
type = "rocking_frame"
column_width = 0.4
column_height = 4.0
column_mass = 2000.0
count = 3
beam_mass = 9000.0
"""


def case_text(body, scale, dt):
    return body + f"""
[excitation.horizontal]
type = "record"
file = "{KOBE}"
format = "at2"
scale = {scale}
[output]
dt = {dt}
"""


def median_cpu(case, reps):
    times = []
    for _ in range(reps):
        t0 = time.process_time()
        r = fr.simulate_case(case)
        times.append(time.process_time() - t0)
    return statistics.median(times), r


def main():
    reps = int(sys.argv[1]) if len(sys.argv) > 1 else 21
    eq = fr.rocking_frame(0.4, 4.0, 2000.0, 3, 9000.0)
    block = (f'\n[body]\ntype = "rigid_body"\nmass = {eq.mass!r}\n'
             f'inertia_cg = {eq.zeta2 * eq.mass * eq.height ** 2!r}\nheight = {eq.height!r}\n'
             f'b1 = {eq.b1!r}\nb2 = {eq.b2!r}\n')
    print("| Kobe scale | frame [ms] | frame, no history [ms] | equivalent block [ms] | ratio | "
          "frame outcome |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as d:
        for scale in (0.5, 1.0, 1.5, 2.0):
            paths = {}
            for name, body, dt in (("frame", FRAME, 0.005), ("frame0", FRAME, 0.0),
                                   ("block", block, 0.005)):
                paths[name] = os.path.join(d, f"{name}_{scale}.toml")
                with open(paths[name], "w") as fh:
                    fh.write(case_text(body, scale, dt))
            tf, rf = median_cpu(fr.load_case(paths["frame"]), reps)
            t0, _ = median_cpu(fr.load_case(paths["frame0"]), reps)
            tb, rb = median_cpu(fr.load_case(paths["block"]), reps)
            what = rf.status + (f" ({rf.raw.message[:60]}...)" if rf.status == "stopped" else "")
            print(f"| {scale:g} | {1e3 * tf:.3f} | {1e3 * t0:.3f} | {1e3 * tb:.3f} | "
                  f"{tf / tb:.3f} | {what} |")


if __name__ == "__main__":
    main()
