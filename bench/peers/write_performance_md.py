#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes docs/performance.md from Google Benchmark's JSON and the peer comparison's JSON
(called by bench/make_performance_md.sh)."""
import argparse
import datetime
import json
import os
import platform
import re
import subprocess

ACCURACY = 1e-6  # the accuracy every timed configuration must reach (relative)
CASES = {
    "a": "(a) rigid block, free rocking from 0.8 alpha, 20 s",
    "b2": "(b) one-sine pulse, omega_p = 2 pi (overturns), 10 s",
    "b6": "(b) one-sine pulse, omega_p = 6 pi (rocks, settles), 10 s",
    "c": "(c) Kobe 1995 at PGA 0.5 g, 40.95 s",
    "d1": "(d) oscillator on a rocking slab, n = 1, Kobe 0.5 g",
    "d8": "(d) cantilever, n = 8, Kobe 0.5 g",
}
WHOLE = {
    "BM_A_RigidFreeRocking": ("(a) rigid, free rocking 20 s", 50.0),
    "BM_B_RigidPulse2pi": ("(b) rigid, one-sine 2 pi (overturns)", 100.0),
    "BM_B_RigidPulse6pi": ("(b) rigid, one-sine 6 pi, 10 s", 100.0),
    "BM_C_RigidKobe": ("(c) rigid, Kobe 0.5 g", 100.0),
    "BM_D_OscillatorKobe": ("(d) oscillator on a rocking slab, n = 1, Kobe", 300.0),
    "BM_D_Cantilever4Kobe": ("(d) cantilever, n = 4, Kobe", 1000.0),
    "BM_D_Cantilever8Kobe": ("(d) cantilever, n = 8, Kobe", 3000.0),
}


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def to_us(b):
    f = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[b["time_unit"]]
    return b["cpu_time"] * f


def micro_table(bench):
    rows = {}
    for b in bench["benchmarks"]:
        m = re.match(r"(BM_(?:Rhs|Dopri5Step|EventLocation|ImpactMap|RockingAcceleration))/n([:/])(\d+)", b["name"])
        if not m or b.get("run_type") == "aggregate":
            continue
        # a fixed size (n:K) is what the event loop runs up to 8 modes; the dynamic one (n/K) beyond
        row, n = rows.setdefault(m.group(1), {}), int(m.group(3))
        if m.group(2) == ":" or n not in row:
            row[n] = to_us(b) * 1e3
    out = ["| operation | n = 0 | n = 1 | n = 2 | n = 4 | n = 8 | n = 10 |", "|---|---|---|---|---|---|---|"]
    labels = {"BM_Rhs": "right-hand side (rocking)", "BM_Dopri5Step": "one DOPRI5 step (6 rhs + 1 start)",
              "BM_EventLocation": "one event location (TOMS 748 on the dense output)",
              "BM_ImpactMap": "one impact map", "BM_RockingAcceleration": "rocking accelerations only"}
    for k, v in rows.items():
        out.append(f"| {labels.get(k, k)} [ns] | " + " | ".join(
            f"{v[n]:.0f}" if n in v else "-" for n in (0, 1, 2, 4, 8, 10)) + " |")
    return "\n".join(out)


def whole_table(bench):
    med = {}
    for b in bench["benchmarks"]:
        if b.get("aggregate_name") == "median":
            med[b["run_name"].split("/")[0]] = b
    out = ["| case | median CPU per run [us] | steps | rhs | events | impacts | max theta [rad] "
           "| err max theta | err robust | target [us] | met |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    verdicts = []
    for name, (label, target) in WHOLE.items():
        b = med.get(name)
        if not b:
            continue
        t = to_us(b)
        met = "-" if target is None else ("yes" if t < target else "**no**")
        if target is not None:
            verdicts.append((label, t, target, t < target))
        out.append(f"| {label} | {t:.1f} | {b['steps']:.0f} | {b['rhs']:.0f} | {b['events']:.0f} "
                   f"| {b['impacts']:.0f} | {b['max_theta']:.6f} | {b['err_max_theta']:.1e} "
                   f"| {b['err_robust']:.1e} | {target if target else '-'} | {met} |")
    return "\n".join(out), verdicts


def modes_table(bench):
    """The n-mode cantilever under Kobe (BM_ModesKobe/n:K): cost per record interval and per
    right-hand side against n."""
    med = {}
    for b in bench["benchmarks"]:
        m = re.match(r"BM_ModesKobe/n:(\d+)", b.get("run_name", ""))
        if m and b.get("aggregate_name") == "median":
            med[int(m.group(1))] = b
    if not med:
        return ""
    out = ["| n | median CPU per run [us] | steps | rhs | CPU per record interval [us] "
           "| ratio to n = 1 | CPU per rhs [us] | err max theta | err robust |",
           "|---|---|---|---|---|---|---|---|---|"]
    one = to_us(med[1]) if 1 in med else None
    for n in sorted(med):
        b = med[n]
        t = to_us(b)
        per = t / b["intervals"]
        ratio = f"{t / one:.1f}" if one else "-"
        # a rigid body's rocking is a series step: no right-hand side to share the cost out
        per_rhs = f"{t / b['rhs']:.3f}" if b["rhs"] > 0 else "-"
        out.append(f"| {n} | {t:.1f} | {b['steps']:.0f} | {b['rhs']:.0f} | {per:.3f} | {ratio} "
                   f"| {per_rhs} | {b['err_max_theta']:.1e} | {b['err_robust']:.1e} |")
    return "\n".join(out)


def stiff_table(bench):
    """Case (e), the stiff slab, with the stiff rocking switch and with DOPRI5 alone (the engine
    before it; run once, it stops at max_steps)."""
    rows = {}
    for b in bench["benchmarks"]:
        name = b.get("run_name", b["name"]).split("/")[0]
        if name == "BM_E_StiffSlabKobe" and b.get("aggregate_name") == "median":
            rows["stiff switch (default)"] = b
        elif name == "BM_E_StiffSlabKobe_Explicit" and b.get("run_type") != "aggregate":
            rows["DOPRI5 alone"] = b
    if not rows:
        return ""
    out = ["| rocking integrator | CPU per run [us] | steps | rhs | impacts | reached t [s] "
           "| completed | max theta [rad] |", "|---|---|---|---|---|---|---|---|"]
    for label, b in rows.items():
        out.append(f"| {label} | {to_us(b):.1f} | {b['steps']:.0f} | {b['rhs']:.0f} "
                   f"| {b['impacts']:.0f} | {b['t_reached']:.2f} | "
                   f"{'yes' if b['completed'] else '**no**'} | {b['max_theta']:.6g} |")
    return "\n".join(out)


def peer_tables(peers):
    out, ratios = [], {}
    for case, data in peers["cases"].items():
        rows = data["rows"]
        out.append(f"\n#### {CASES.get(case, case)}\n")
        out.append(f"Reference check: {'exact solution vs flexrock at rtol 1e-13' if case == 'a' else 'DOP853 at rtol 1e-13 vs flexrock at rtol 1e-13'}"
                   f": relative difference {data['reference_agreement']:.1e}.\n")
        out.append("| solver | rtol | CPU per run [s] | error |")
        out.append("|---|---|---|---|")
        for r in rows:
            out.append(f"| {r['solver']} | {r['rtol']:.0e} | {r['cpu_s']:.3g} | {r['error']:.1e} |")
        fr = [r for r in rows if r["solver"] == "flexrock"]
        for solver in sorted({r["solver"] for r in rows} - {"flexrock"}):
            pr = [r for r in rows if r["solver"] == solver]
            ok = [r for r in pr if r["error"] <= ACCURACY]
            p = min(ok, key=lambda r: r["cpu_s"]) if ok else min(pr, key=lambda r: r["error"])
            cand = [r for r in fr if r["error"] <= max(p["error"], 1e-15) and r["error"] <= ACCURACY]
            if not cand:
                continue
            f = min(cand, key=lambda r: r["cpu_s"])
            ratios[(case, solver)] = (p["cpu_s"] / f["cpu_s"], p, f)
    return "\n".join(out), ratios


def flexible_step_section(steps):
    """The flexible body's rocking stepped by DOP853 (the engine) and by DOPRI5 (before it), from
    compare.py --cases d1,d8 --flexrock-only --old-step."""
    out = ["### The flexible body's rocking step", "",
           "Cases (d) with n = 1 and n = 8 at each tolerance, their rocking stepped by DOP853 "
           "(`flexrock`, the engine's default) and by DOPRI5 (`flexrock DOPRI5 rocking`, "
           "`methods.high_order_rocking = false`: the engine before it), in one session. The error is "
           "the largest relative difference of max |theta|, the first uplift time and the first "
           "five impact times from the run at rtol = 1e-13 (1 when the outcome differs); `steps` "
           "counts every step of the run (the record walk's included).", "",
           "![flexible rocking step](img/flexible_step.png)"]
    for case, data in steps["cases"].items():
        out.append(f"\n#### {CASES.get(case, case)}\n")
        out.append("Reference check: DOPRI5 at rtol 1e-13 vs DOP853 at rtol 1e-13: relative "
                   f"difference {data['reference_agreement']:.1e}.\n")
        out.append("| rocking step | rtol | CPU per run [s] | error | steps |")
        out.append("|---|---|---|---|---|")
        for r in data["rows"]:
            name = "DOP853" if r["solver"] == "flexrock" else "DOPRI5"
            out.append(f"| {name} | {r['rtol']:.0e} | {r['cpu_s']:.3g} | {r['error']:.1e} "
                       f"| {r.get('steps', 0):.0f} |")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bench", required=True)
    ap.add_argument("--peers", required=True)
    ap.add_argument("--load", default="")
    ap.add_argument("--command", default="bench/make_performance_md.sh")
    ap.add_argument("--studies", default="")
    ap.add_argument("--flexible-steps", default="",
                    help="compare.py's JSON for --cases d1,d8 --flexrock-only --old-step")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    with open(a.bench) as f:
        bench = json.load(f)
    with open(a.peers) as f:
        peers = json.load(f)
    whole, verdicts = whole_table(bench)
    ptab, ratios = peer_tables(peers)
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    try:
        rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                             text=True).stdout.strip()
    except OSError:
        rev = "?"
    lines = [
        "# Performance",
        "",
        "Generated by `" + a.command.strip() + "` (do not edit by hand). "
        f"Date: {now}; commit {rev} plus the working tree; machine: {cpu_model()}, "
        f"{os.cpu_count()} CPUs, load average (1, 5, 15 min) before / after: {a.load}. "
        "The machine may be shared: times are medians of repetitions, and the ratios are taken "
        "side by side in one session.",
        "",
        "## Commands",
        "",
        "```sh",
        "scripts/install-deps.sh --bench          # Google Benchmark, scipy, matplotlib, siconos",
        "cmake --preset bench && cmake --build --preset bench",
        "build/bench/bench/flexrock_bench          # micro-benchmarks and whole runs",
        "build/bench/bench/flexrock_bench --benchmark_filter=BM_C --benchmark_format=json",
        "/usr/bin/python3 bench/peers/compare.py --run-case build/bench/bench/flexrock_run_case \\",
        "    --out peers.json --plot docs/img/work_precision.png",
        "bench/make_performance_md.sh             # all of the above, then this file",
        "```",
        "",
        "## Micro-benchmarks (CPU time per call)",
        "",
        micro_table(bench),
        "",
        "## Whole runs",
        "",
        "Median CPU time per run of 7 repetitions (each many runs). Each case runs at the "
        "tolerance in bench/cases.hpp (rtol = 1e-8, atol = 1e-10); `err max theta` is the relative "
        "difference of the largest |theta| from a run at rtol = 1e-13, `err robust` the largest "
        "relative difference of the first uplift time and the first five impact times (and 1 if "
        "the outcome or overturning side differs). Both must be at most 1e-6. `rhs` counts "
        "right-hand side evaluations: a rigid body's rocking is stepped by its Taylor series, "
        "whose coefficients come from a recurrence, so cases (a)-(c) evaluate none.",
        "",
        whole,
        "",
        "### Cost against the number of modes",
        "",
        "The cantilever of case (d) with n = 0 (the same body taken as rigid), 1, 2, 4 and 8 "
        "modes under the Kobe record (4,095 record intervals), at the same tolerance: "
        "`CPU per rhs` is the whole run's CPU over its right-hand sides, an upper bound on one "
        "right-hand side's cost that includes the exact steps of full contact.",
        "",
        modes_table(bench),
        "",
    ]
    if a.flexible_steps and os.path.exists(a.flexible_steps):
        with open(a.flexible_steps) as f:
            lines += [flexible_step_section(json.load(f)), ""]
    lines += [
        "### Stiff rocking",
        "",
        "Case (e): a slab of b/h = 0.01 under a 980 Hz oscillator with 5 % damping (its coupled "
        "motion near 128 kHz while rocking) under Kobe at 0.02 g, with the stiff rocking switch "
        "(docs/theory.md, \"Stiff rocking integrator\") and with DOPRI5 alone, the engine before "
        "it (one run; it stops at max_steps). The largest tilt is reached before the explicit run "
        "stops.",
        "",
        stiff_table(bench),
        "",
        "## Peers",
        "",
        "Rigid block cases (a)-(c): flexrock (bench/run_case.cpp), scipy `solve_ivp` DOP853 and "
        "RK45 with terminal event functions for uplift, impact and overturning (Housner's "
        "equation with his restitution, as a Python user writes it: bench/peers/compare.py), all "
        "in one session. The error is relative: for (a) the impact times against the exact "
        "solution (energy quadrature between impacts); for (b) max |theta|, or the overturning "
        "time when it overturns, "
        "and the first uplift and impact times; for (c) the first uplift time, the first five "
        "impact times, and whether and to which side it overturns (1 when that differs). Like "
        "with like: every solver ends an overturning run where flexrock does, at |theta| = pi/2 "
        "(not at alpha, where the c.g. passes over the pivot), and the peers run with one BLAS "
        "thread (OPENBLAS_NUM_THREADS=1, set by compare.py): an idle OpenBLAS worker spinning on "
        "the second core was counted as their CPU time before.",
        "",
        "![work-precision](img/work_precision.png)",
        ptab,
        "",
        "### Time ratios at equal or better accuracy",
        "",
        "For each peer: its fastest run with an error <= 1e-6 (else its most accurate), against "
        "flexrock's fastest run with an error no larger.",
        "",
        "| case | peer | peer CPU [s] | peer error | flexrock CPU [s] | flexrock error | ratio |",
        "|---|---|---|---|---|---|---|",
    ]
    for (case, solver), (ratio, p, f) in ratios.items():
        lines.append(f"| {case} | {solver} | {p['cpu_s']:.3g} | {p['error']:.1e} | "
                     f"{f['cpu_s']:.3g} | {f['error']:.1e} | {ratio:.0f} |")
    lines += ["", "## Targets", ""]
    for label, t, target, ok in verdicts:
        lines.append(f"- {label}: {t:.1f} us per run, target < {target:.0f} us: "
                     f"{'met' if ok else 'NOT met'}")
    for solver in ("scipy DOP853", "siconos event-driven"):
        r = ratios.get(("c", solver))
        if r:
            lines.append(f"- case (c), flexrock vs {solver}: {r[0]:.0f} times faster, target >= "
                         f"1000: {'met' if r[0] >= 1000 else 'NOT met'}")
        else:
            lines.append(f"- case (c), flexrock vs {solver}: not measured in this run")
    notes = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bounds.md")
    if os.path.exists(notes):
        with open(notes) as f:
            lines += ["", f.read().rstrip()]
    if a.studies.strip():
        lines += ["", a.studies.rstrip()]
    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, a.out)


if __name__ == "__main__":
    main()
