#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Times Result.time_history() and Result.to_dataframe() against the simulation itself.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python/time_history.py [CASE ...]

Each case (default: the four example cases, with a history every 1 ms) is loaded, simulated,
then its time history built REPEATS times on fresh Result objects (no cache); the best time of
each is printed. "csv round trip" is how time_history() was built before it read the engine's
arrays (the CSV text, parsed back), timed in the same process for comparison. Timings only:
nothing here is a pass/fail test.
"""

import argparse
import os
import sys
import time

import flexrock as fr

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "..", "..", "examples", "cases")


def best(fn, repeats):
    t = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        t = min(t, time.perf_counter() - t0)
    return t


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cases", nargs="*")
    ap.add_argument("--output-dt", type=float, default=0.001, help="history spacing [s]")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    names = args.cases or sorted(
        os.path.join(CASES, f) for f in os.listdir(CASES) if f.endswith(".toml")
    )
    print(f"{'case':28s} {'rows':>8s} {'simulate':>10s} {'time_history':>13s} {'to_dataframe':>13s}"
          f" {'csv round trip':>15s}")
    for path in names:
        case = fr.load_case(path)
        case.options.output_dt = args.output_dt
        t_sim = best(lambda: fr.simulate_case(case), args.repeats)
        r = fr.simulate_case(case)
        t_th = best(lambda: fr.Result(r.raw, r.body, r.case).time_history(), args.repeats)
        if hasattr(fr.Result, "to_dataframe"):
            t_df = best(lambda: fr.Result(r.raw, r.body, r.case).to_dataframe(), args.repeats)
            df = f"{t_df:12.4f}s"
        else:
            df = f"{'(none)':>13s}"
        t_csv = best(lambda: fr._parse_csv(fr.Result(r.raw, r.body, r.case).time_history_csv()), args.repeats)
        print(f"{os.path.basename(path):28s} {len(r.raw.history):8d} {t_sim:9.4f}s {t_th:12.4f}s {df}"
              f" {t_csv:14.4f}s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
