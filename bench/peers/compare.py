#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Side-by-side timing and accuracy of flexrock and its peers on the rigid-block cases (a)-(c).

Peers: scipy's solve_ivp (DOP853 and RK45) with event functions, written as a Python user
writes Housner's rocking block; Siconos' event-driven scheme (peers/siconos_block.py) when the
python3-siconos package is installed. flexrock runs through bench's flexrock_run_case.

    /usr/bin/python3 bench/peers/compare.py --run-case build/bench/bench/flexrock_run_case \
        --out build/bench/peers.json [--plot docs/img/work_precision.png] [--quick]

With --old-step each rtol also runs flexrock with the rocking stepped by DOPRI5
(flexrock_run_case ... dopri5): a rigid body's instead of its Taylor series, a flexible body's
instead of DOP853; --cases a,c and --flexrock-only give the work-precision comparison of the two
steps alone (docs/img/rocking_step.png), --cases d1,d8 --flexrock-only that of the flexible
body's two steps (docs/img/flexible_step.png; the flexible cases have no peer here).

Accuracy: case (a) against the exact solution (energy quadrature between impacts); (b) and (c)
against flexrock at rtol = 1e-13, checked against DOP853 at rtol = 1e-13. Times are the median
CPU time per run (time.process_time) of a few repetitions, all in this one process session.

Like with like: every solver ends an overturning run where flexrock does, at |theta| = pi/2 (the
c.g. passes over the pivot at alpha, and Housner's equation holds until the block lies on its
side); and the BLAS under numpy runs one thread (OPENBLAS_NUM_THREADS=1, set here before numpy
loads, unless given): an idle OpenBLAS worker spinning on the second core was counted as the
peer's CPU time (Siconos' case (c) took 30.3 s with it against 10.3 s without).
"""
import os

# before numpy loads OpenBLAS: its worker threads would otherwise spin on the other cores
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np
from scipy.integrate import quad, solve_ivp

G = 9.80665  # [m/s^2] standard gravity, as flexrock (and the record's unit g)
B, H = 0.2, 1.0  # [m] half-width, half-height of the slender block
ALPHA = math.atan(B / H)  # [rad] slenderness
OVERTURN = 0.5 * math.pi  # [rad] overturned: flexrock's one rule, |theta| = pi/2
R = math.hypot(B, H)  # [m] c.g. to a corner
P2 = 3.0 * G / (4.0 * R)  # [1/s^2] Housner's p^2
RESTITUTION = 1.0 - 1.5 * math.sin(ALPHA) ** 2  # Housner's theta_dot ratio at impact
CHATTER = 0.01 * 2.0 * math.pi / math.sqrt(P2)  # [s] flexrock's default chatter interval
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def kobe_05g():
    """Kobe 1995 Nishi-Akashi 090 scaled to PGA 0.5 g: times [s], accelerations [m/s^2]."""
    path = os.environ.get("FLEXROCK_DATA", os.path.join(ROOT, "..", "shared", "data"))
    with open(os.path.join(path, "kobe_1995_nishi_akashi_090.AT2")) as f:
        lines = f.read().splitlines()
    npts, dt = lines[3].split()[:2]
    vals = np.array([float(v) for line in lines[4:] for v in line.split()])
    assert vals.size == int(npts)
    acc = vals * (0.5 / np.abs(vals).max()) * G
    return np.arange(acc.size) * float(dt), acc


# ---------------------------------------------------------------------------------------------
# scipy: Housner's block as a Python user writes it
def housner_scipy(accel, t_end, method, rtol, theta0=0.0, max_step=np.inf, breaks=None):
    """Rocking of the rigid block; accel(t) is the horizontal base acceleration [m/s^2]. Returns
    (first uplift, impact times, status, overturn side, max |theta|, overturn time)."""
    atol = 1e-2 * rtol
    t, theta, thd = 0.0, theta0, 0.0
    side = 1 if theta0 > 0 else (-1 if theta0 < 0 else 0)
    impacts, first_uplift, max_theta, last_change = [], None, abs(theta0), -1e9

    def rocking(t, y, s):
        a = accel(t)
        return [y[1], -P2 * (math.sin(s * ALPHA - y[0]) - a / G * math.cos(s * ALPHA - y[0]))]

    while t < t_end:
        if side == 0:
            # at rest: uplift when |a| exceeds g tan(alpha)
            def up1(t, y):
                return accel(t) - G * math.tan(ALPHA)

            def up2(t, y):
                return -accel(t) - G * math.tan(ALPHA)

            up1.terminal = up2.terminal = True
            up1.direction = up2.direction = 1
            sol = solve_ivp(lambda t, y: [0.0], (t, t_end), [0.0], method=method, rtol=rtol,
                            atol=atol, events=(up1, up2), max_step=max_step)
            if sol.status != 1:
                break
            t = sol.t[-1]
            side = 1 if sol.t_events[0].size else -1
            first_uplift = t if first_uplift is None else first_uplift
            last_change = t
            theta, thd = 0.0, 0.0
            continue

        def impact(t, y):
            return y[0]

        def overturn(t, y):
            return abs(y[0]) - OVERTURN

        def peak(t, y):
            return y[1]

        impact.terminal = overturn.terminal = True
        impact.direction = -side
        sol = solve_ivp(lambda t, y: rocking(t, y, side), (t, t_end), [theta, thd],
                        method=method, rtol=rtol, atol=atol, events=(impact, overturn, peak),
                        max_step=max_step)
        # amplitudes at the peaks (theta_dot = 0), located on the dense output
        if sol.y_events[2].size:
            max_theta = max(max_theta, float(np.abs(sol.y_events[2][:, 0]).max()))
        if sol.status != 1:
            break
        t = sol.t[-1]
        if sol.t_events[1].size:
            return first_uplift, impacts, "overturned", 1 if side > 0 else 2, OVERTURN, t
        impacts.append(t)
        thd = RESTITUTION * sol.y[1][-1]
        theta = 0.0
        if t - last_change < CHATTER:
            side, thd = 0, 0.0  # impacts faster than the chatter criterion end rocking
        else:
            side = -side
        last_change = t
    return first_uplift, impacts, "completed", 0, max_theta, -1.0


# ---------------------------------------------------------------------------------------------
# the exact free rocking of case (a)
def exact_free_rocking(theta0, t_end):
    """Impact times of free rocking from theta0 at rest: energy quadrature of each half-cycle."""
    def quarter(amp):
        # time from amp to 0; theta = amp - s^2 removes the square-root singularity
        def f(s):
            if s == 0.0:  # the limit of the integrand
                return 2.0 / math.sqrt(2.0 * P2 * math.sin(ALPHA - amp))
            # cos A - cos(A + u) = 2 sin(A + u/2) sin(u/2), free of cancellation
            u = s * s
            d = 2.0 * math.sin(ALPHA - amp + 0.5 * u) * math.sin(0.5 * u)
            return 2.0 * s / math.sqrt(2.0 * P2 * d)

        return quad(f, 0.0, math.sqrt(amp), epsabs=1e-15, epsrel=1e-13, limit=200)[0]

    times, t, amp, last = [], 0.0, theta0, -1e9
    t += quarter(amp)
    while t < t_end:
        times.append(t)
        thd0 = math.sqrt(2.0 * P2 * (math.cos(ALPHA - amp) - math.cos(ALPHA)))
        thd = RESTITUTION * thd0
        if t - last < CHATTER:
            break
        last = t
        # the energy after the impact sets the next amplitude
        amp = ALPHA - math.acos(math.cos(ALPHA) + thd * thd / (2.0 * P2))
        t += 2.0 * quarter(amp)
    return times


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def error(res, ref, case, n_impacts=5):
    """Relative error of the judged quantities: impact times (a), max theta or overturn (b), first
    uplift and first impacts (c); 1 when the outcome differs."""
    if res["status"] != ref["status"] or res["overturn_edge"] != ref["overturn_edge"]:
        return 1.0
    e = 0.0
    if case != "a" and ref["first_uplift"] is not None:
        e = max(e, rel(res["first_uplift"], ref["first_uplift"]))
    if ref["status"] == "overturned":
        e = max(e, rel(res["overturn_time"], ref["overturn_time"]))
    elif case in ("b2", "b6") or case.startswith("d"):
        e = max(e, rel(res["max_theta"], ref["max_theta"]))
    k = 10 if case == "a" else n_impacts
    for x, y in zip(res["impacts"][:k], ref["impacts"][:k]):
        e = max(e, rel(x, y))
    return e


# ---------------------------------------------------------------------------------------------
def cases():
    tk, ak = kobe_05g()
    a_p = 3.0 * G * math.tan(ALPHA)

    def pulse(w):
        return lambda t: a_p * math.sin(w * t) if 0.0 <= t <= 2.0 * math.pi / w else 0.0

    kobe = lambda t: float(np.interp(t, tk, ak, left=0.0, right=0.0))
    return {
        "a": dict(accel=lambda t: 0.0, t_end=20.0, theta0=0.8 * ALPHA, max_step=np.inf),
        "b2": dict(accel=pulse(2.0 * math.pi), t_end=10.0, theta0=0.0, max_step=0.01),
        "b6": dict(accel=pulse(6.0 * math.pi), t_end=10.0, theta0=0.0, max_step=0.01),
        "c": dict(accel=kobe, t_end=float(tk[-1]), theta0=0.0, max_step=float(tk[1] - tk[0])),
        # flexible bodies under Kobe (bench/cases.hpp): flexrock only
        "d1": dict(flexible=True),
        "d8": dict(flexible=True),
    }


def time_scipy(case, spec, method, rtol, reps):
    times, out = [], None
    for _ in range(reps):
        t0 = time.process_time()
        fu, imp, status, edge, mt, tov = housner_scipy(spec["accel"], spec["t_end"], method,
                                                       rtol, spec["theta0"], spec["max_step"])
        times.append(time.process_time() - t0)
        out = dict(first_uplift=fu, impacts=imp, status=status, overturn_edge=edge, max_theta=mt,
                   overturn_time=tov)
    out["cpu_s"] = statistics.median(times)
    return out


def time_flexrock(run_case, case, rtol, reps, extra=()):
    line = subprocess.run([run_case, case, repr(rtol), str(reps), *extra], check=True,
                          capture_output=True, text=True).stdout
    r = json.loads(line)
    if r["first_uplift"] < 0:
        r["first_uplift"] = None
    # scipy's side convention: overturn edge 1 is theta > 0 in both
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--run-case", required=True, help="path to flexrock_run_case")
    ap.add_argument("--out", required=True, help="JSON results")
    ap.add_argument("--plot", help="work-precision plot (PNG or SVG)")
    ap.add_argument("--quick", action="store_true", help="fewer tolerances and repetitions")
    ap.add_argument("--old-step", action="store_true",
                    help="also flexrock with the rocking stepped by DOPRI5")
    ap.add_argument("--flexrock-only", action="store_true", help="no scipy or Siconos runs")
    ap.add_argument("--cases", default="a,b2,b6,c", help="comma-separated cases")
    args = ap.parse_args()
    specs = {k: v for k, v in cases().items() if k in args.cases.split(",")}
    if not args.flexrock_only and any(v.get("flexible") for v in specs.values()):
        ap.error("the flexible cases (d1, d8) have no peer here: add --flexrock-only")
    results = {"cases": {}, "machine": os.uname().nodename, "load": os.getloadavg()}
    reps_fast, reps_slow = (3, 1) if args.quick else (7, 3)
    tols = [1e-6, 1e-8, 1e-10] if args.quick else [1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11]
    # Siconos' event-driven block is run by bench/peers/siconos_block.py (run(case, rtol, reps)
    # -> dict like time_scipy's) when that file and python3-siconos are present
    siconos = None
    if args.flexrock_only:
        pass
    elif os.path.exists(os.path.join(HERE, "siconos_block.py")):
        try:
            sys.path.insert(0, HERE)
            import siconos_block  # noqa: E402  (needs python3-siconos)
            siconos = siconos_block
        except Exception as e:  # the peer is optional: say why it is missing
            print(f"siconos: not run ({e})", file=sys.stderr)
    else:
        print("siconos: not run (bench/peers/siconos_block.py is not written yet)", file=sys.stderr)
    results["siconos"] = siconos is not None
    for case, spec in specs.items():
        print(f"case {case} ...", file=sys.stderr)
        ref = time_flexrock(args.run_case, case, 1e-13, 1)
        exact = None
        if case == "a":
            exact = dict(first_uplift=None, impacts=exact_free_rocking(spec["theta0"], 20.0),
                         status="completed", overturn_edge=0, max_theta=spec["theta0"],
                         overturn_time=-1.0)
            ref_used = exact
        else:
            ref_used = ref
        # the reference checked against DOP853, or (flexrock only) against the DOPRI5 step
        chk = (time_flexrock(args.run_case, case, 1e-13, 1, ("dopri5",)) if args.flexrock_only
               else time_scipy(case, spec, "DOP853", 1e-13, 1))
        rows = []
        for rtol in tols:
            fr = time_flexrock(args.run_case, case, rtol, reps_fast)
            rows.append(dict(solver="flexrock", rtol=rtol, cpu_s=fr["cpu_s"],
                             error=error(fr, ref_used, case), steps=fr["steps"]))
            if args.old_step:
                fo = time_flexrock(args.run_case, case, rtol, reps_fast, ("dopri5",))
                rows.append(dict(solver="flexrock DOPRI5 rocking", rtol=rtol, cpu_s=fo["cpu_s"],
                                 error=error(fo, ref_used, case), steps=fo["steps"]))
            for method in () if args.flexrock_only else ("DOP853", "RK45"):
                if method == "RK45" and rtol < 1e-9:
                    continue  # RK45 needs tens of thousands of steps there: minutes per run
                sp = time_scipy(case, spec, method, rtol, reps_slow)
                rows.append(dict(solver="scipy " + method, rtol=rtol, cpu_s=sp["cpu_s"],
                                 error=error(sp, ref_used, case)))
            if siconos is not None:
                try:
                    sc = siconos.run(case, rtol, reps_slow)
                    rows.append(dict(solver="siconos event-driven", rtol=rtol,
                                     cpu_s=sc["cpu_s"], error=error(sc, ref_used, case)))
                except Exception as e:
                    print(f"siconos case {case} rtol {rtol}: {e}", file=sys.stderr)
        results["cases"][case] = dict(
            rows=rows,
            reference_agreement=error(chk, ref, case) if case != "a" else error(ref, exact, case),
            reference=ref_used)
    with open(args.out + ".tmp", "w") as f:
        json.dump(results, f, indent=1)
    os.replace(args.out + ".tmp", args.out)
    if args.plot:
        plot(results, args.plot)


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = list(results["cases"])
    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names), 3.8))
    styles = {"flexrock": "o-", "flexrock DOPRI5 rocking": "v-", "scipy DOP853": "s--",
              "scipy RK45": "^:",
              "siconos event-driven": "d-."}
    for ax, case in zip(axes, names):
        rows = results["cases"][case]["rows"]
        for solver, style in styles.items():
            pts = [(r["cpu_s"], max(r["error"], 1e-16)) for r in rows if r["solver"] == solver]
            if pts:
                x, y = zip(*pts)
                ax.loglog(x, y, style, label=solver, ms=4)
        ax.set_title(f"case {case}")
        ax.set_xlabel("CPU time per run [s]")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("relative error (impact/uplift times, max theta)")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    tmp = path + ".tmp" + os.path.splitext(path)[1]
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, path)


if __name__ == "__main__":
    main()
