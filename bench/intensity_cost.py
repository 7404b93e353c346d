#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Cost of the intensity measures of one record, as a sweep computes them (once per record).

Times flexrock.intensity(motion, measures) on a record (default: El Centro 1940 NS, 1559 samples
at 0.02 s) for PGA and PGV alone, each further measure alone, all of them with Sa at one period,
and all with Sa at ten periods; prints the median of REPEATS calls of each.

    PYTHONPATH=build/release/python python3 bench/intensity_cost.py [RECORD] [REPEATS]
"""
import os
import statistics
import sys
import time

import flexrock as fr

here = os.path.dirname(os.path.abspath(__file__))
path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "shared", "data",
                                                          "elcentro_1940_ns.dat")
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 200
values = [float(x) for line in open(path) if not line.startswith("#") for x in line.split()]
motion = fr.motion_from_array([9.80665 * v for v in values], dt=0.02)
M = fr.MeasureRequest
plain = ["pgd", "arias", "cav", "d5_95", "pgv_over_pga"]
cases = [("pga + pgv only", [])] + [(n, [M(n)]) for n in plain] + [
    ("sa at 1 period", [M("sa", 1.0)]),
    ("all, sa at 1 period", [M(n) for n in plain] + [M("sa", 1.0)]),
    ("all, sa at 10 periods", [M(n) for n in plain] + [M("sa", 0.1 * k) for k in range(1, 11)]),
]
print(f"{os.path.basename(path)}: {len(values)} samples, median of {repeats} calls")
for name, measures in cases:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fr.intensity(motion, measures)
        times.append(time.perf_counter() - t0)
    print(f"  {name:24s} {1e6 * statistics.median(times):9.1f} us")
