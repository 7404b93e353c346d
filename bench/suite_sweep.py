#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Time of a record-suite sweep: N synthetic PEER-style pairs (horizontal + vertical) x 10 PGA
levels (0.1 g to 1.0 g) for the slender block and the flexible tank of examples/, each body
alone, with and without the verticals; prints wall and user seconds and runs per second per
core (user time). The records are seeded, enveloped sums of 40 sines (20 s at 0.01 s; horizontal
0.5-8 Hz, PGA 0.3 g; vertical 2-15 Hz, PGA 0.2 g), written to a temporary directory.

    python3 bench/suite_sweep.py build/release/apps/flexrock [N_RECORDS] [THREADS]
"""
import math
import os
import random
import resource
import subprocess
import sys
import tempfile
import time

flexrock = os.path.abspath(sys.argv[1])
n_records = int(sys.argv[2]) if len(sys.argv) > 2 else 20
threads = sys.argv[3] if len(sys.argv) > 3 else "1"
here = os.path.dirname(os.path.abspath(__file__))
bodies = {"block": os.path.join(here, "..", "examples", "studies", "slender_block.toml"),
          "tank": os.path.join(here, "..", "examples", "cases", "flexible_tank.toml")}
rng = random.Random(19)
dt, n = 0.01, 2000


def motion(pga, fmin, fmax):
    comps = [(rng.uniform(fmin, fmax), rng.uniform(0, 2 * math.pi), rng.uniform(0.5, 1))
             for _ in range(40)]
    a = []
    for i in range(n):
        t = i * dt
        env = min(1.0, t / 2.0) * (1.0 if t < 10 else math.exp(-(t - 10) / 3))
        a.append(env * sum(w * math.sin(2 * math.pi * f * t + p) for f, p, w in comps))
    s = pga / max(abs(x) for x in a)
    return [s * x for x in a]


def at2(path, vals):
    with open(path, "w") as f:
        f.write("PEER\nSYNTHETIC\nACCELERATION TIME SERIES IN UNITS OF G\n")
        f.write("NPTS= %d, DT= %.4f SEC\n" % (n, dt))
        for i in range(0, n, 5):
            f.write("".join("%15.7E" % v for v in vals[i:i + 5]) + "\n")


with tempfile.TemporaryDirectory() as d:
    os.mkdir(os.path.join(d, "peer"))
    for k in range(1, n_records + 1):
        at2(os.path.join(d, "peer", f"RSN{k:02d}_H1.AT2"), motion(0.3, 0.5, 8))
        at2(os.path.join(d, "peer", f"RSN{k:02d}_UP.AT2"), motion(0.2, 2, 15))
    print(f"{n_records} pairs x 10 levels, -j {threads}, load average {os.getloadavg()[0]:.1f}")
    for name, body in bodies.items():
        for vertical in (True, False):
            m = os.path.join(d, f"{name}_{vertical}.toml")
            with open(m, "w") as f:
                f.write(f'[[body]]\nname = "{name}"\nfile = "{os.path.abspath(body)}"\n')
                f.write('[[suite]]\nhorizontal = "peer/*_H1.AT2"\n')
                if vertical:
                    f.write('vertical = "peer/*_UP.AT2"\n')
                f.write('[scales]\ntarget_pga = { start = 0.1, stop = 1.0, count = 10 }\n'
                        'units = "g"\n')
            before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
            t0 = time.perf_counter()
            p = subprocess.run([flexrock, "sweep", m, "-o", os.path.join(d, "out.csv"), "-q",
                                "-j", threads], capture_output=True, text=True)
            wall = time.perf_counter() - t0
            user = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before
            if p.returncode != 0:
                sys.exit(p.stderr)
            runs = 10 * n_records
            print(f"{name:5s} {'with' if vertical else 'without'} vertical: {runs} runs, "
                  f"wall {wall:.2f} s, user {user:.2f} s, {runs / user:.0f} runs/s per core; "
                  f"{p.stdout.strip()}")
