#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Siconos' event-driven scheme (LsodarOSI + LCP) on the rigid-block cases of compare.py.

The model: generalized coordinates q = (theta, y), theta the rotation (positive pivots on the
left corner, the side a positive base acceleration drives, as housner_scipy), y the height of
the c.g. The horizontal c.g. position is not a coordinate: x = X(theta) with

    X(theta) = -s b (1 - cos theta) - h sin theta,   s = sign(theta),

the exact path of the c.g. while the pivot corner sticks (no sliding built into the
coordinates). X is C1 at theta = 0 (X' = -h from both sides), so the mass matrix

    M(theta) = diag(I_c + m X'(theta)^2, m),   I_c = m (b^2 + h^2) / 3,

is continuous; only the curvature X'' jumps at theta = 0, where the impacts happen. Two
unilateral corner contacts g_L = y - b sin theta - h cos theta >= 0 (left corner) and
g_R = y + b sin theta - h cos theta >= 0 with a Newton impact law of zero restitution. While one
contact is closed the block rotates about that corner exactly (kinetic energy I_0 theta_dot^2/2,
I_0 = 4/3 m R^2): Housner's rocking. At the landing, theta = 0, M = diag(I_c + m h^2, m) and the
impact LCP gives the landing corner zero normal velocity and the old pivot a lift-off velocity
-2 b r theta_dot; theta_dot after/before = (I_0 - 2 m b^2) / I_0 = 1 - 1.5 sin^2(alpha), Housner's
ratio, with no restitution coefficient put in by hand. (With q = (x, y, theta) and frictionless
contacts the horizontal momentum would survive the impact and the block would slide instead.)

Base acceleration a(t) enters as the inertial force -m a(t) along x, i.e. the generalized force
-m a X'(theta) on theta. Overturning is |theta| = pi/2 (flexrock's rule), two more unilateral constraints whose
root Siconos locates (the run stops there). Housner's chatter cut-off of compare.py is kept: an
impact within CHATTER of the last uplift/impact puts the block at rest, which here restarts the
simulation from rest.

Siconos 4.4 details, as measured: LsodarOSI gets the analytic Jacobian (setJT(1); its
finite-difference default costs ~30x more right-hand sides); setMinMaxStepSizes(a, b) stores a
as the maximum step (and b as the minimum); setTol(itol, rtol, atol) stores rtol into atol, so
atol is written after it into lsodar's array; the event tolerance sits above the constraint
drift. All model functions are a small C plugin compiled once (Siconos' plugin mechanism), as a
C++ user writes them: the mass, the contact functions and their Jacobians (the curvature term of
the acceleration-level LCP is only read from a plugin), and the forces
FInt(t, q, v) = [m X' X'' theta_dot^2 + m a(t) X', m g] (M q'' + FInt = p) with their Jacobians
wrt q and v (FInt's plugin signature is the one that carries t). compare.py's a(t) is handed to
the plugin through ctypes on the same .so (the pulse parameters, or the record interpolated as
its np.interp) and checked against compare.py's before the timed runs; no Python runs inside
the integration (a Python override of computeFInt, called through SWIG at every right-hand
side, made case (c) at rtol 1e-8 cost ~95 s of CPU; compiled, ~30 s). What remains is Siconos'
own cost per right-hand side, ~17 us (the event-driven scheme solves the acceleration-level LCP
in each one), times ~1.6e6 right-hand sides on case (c): with setJT(1) lsodar takes steps of
~2e-4 s even while the block rests on both corners (the analytic Jacobian leaves out the contact
forces); setJT(2) rests with ~40x fewer, but then the runs stop in the index-set check at the
events.

Limits, as measured (rtol 1e-8): the impact ratio is Housner's r to 6 digits, but the event
times carry the drift of the closed contact (Siconos' event-driven scheme integrates the
contact at acceleration level, without projection): the landing is the root of the drifted gap,
so impact times err by ~1e-5 relative at rtol 1e-8, falling as rtol tightens. Some runs stop in
Siconos' index-set check after an event (EventDriven::updateIndexSetsWithDoubleCondition) or in
lsodar (case (c) completes only at rtol 1e-8 of 1e-5..1e-10); run() then raises, and
compare.py prints the case and rtol.
"""
import ctypes
import hashlib
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare  # noqa: E402  (one definition of the geometry, the motions and the chatter rule)

import siconos.kernel as sk  # noqa: E402

B, H, G, ALPHA, CHATTER = compare.B, compare.H, compare.G, compare.ALPHA, compare.CHATTER
MASS = 1.0  # [kg] the motion does not depend on it
I_C = MASS * (B * B + H * H) / 3.0  # [kg m^2] about the c.g.
TOL_ED = 1e2  # Siconos' event tolerance / rtol [m, m/s, m/s^2]: above the contact drift
# [m s^2] at an impact, times theta_dot^2: Siconos 4.4 checks the landing corner's
# acceleration (complementarity at acceleration level) with the pre-impact free acceleration: it
# does not recompute the velocity-dependent force m X' X'' theta_dot^2, whose sign flips with the
# pivot; that error is ~0.06 theta_dot^2 here (measured), the old pivot's lift-off velocity
# 2 b r theta_dot must stay above the tolerance (theta_dot < 2.5 rad/s)
TOL_ED_IMPACT = 0.15
RTOL_MIN = 1e-11  # lsodar's rtol below this is not practical here (see run)

_PLUGIN_C = r"""
#include <math.h>
#include <stdlib.h>
#include <string.h>
/* q = (theta, y); s = sign(theta) picks the pivot corner (left for theta >= 0) */
static double xp(double th) { double s = th >= 0 ? 1.0 : -1.0; return -s * B * sin(th) - H * cos(th); }

void mass(unsigned int n, double* q, double* m, unsigned int nz, double* z) {
  double x1 = xp(q[0]);
  m[0] = IC + MASS * x1 * x1; m[1] = 0.0; m[2] = 0.0; m[3] = MASS; /* column-major */
}
/* corner k = -1 (left) or +1 (right): gap, its Jacobian (1 x 2) and d/dt of the Jacobian */
/* q[1] is the c.g. height above its rest height h, so that atol bounds the contact drift */
static void h(int k, double* q, double* y) { y[0] = q[1] + k * B * sin(q[0]) + 2.0 * H * pow(sin(0.5 * q[0]), 2); }
static void jac(int k, double* q, double* j) { j[0] = k * B * cos(q[0]) + H * sin(q[0]); j[1] = 1.0; }
static void djac(int k, double* q, double* v, double* j) {
  j[0] = (-k * B * sin(q[0]) + H * cos(q[0])) * v[0]; j[1] = 0.0;
}
void h_left(unsigned int n, double* q, unsigned int m, double* y, unsigned int nz, double* z) { h(-1, q, y); }
void h_right(unsigned int n, double* q, unsigned int m, double* y, unsigned int nz, double* z) { h(1, q, y); }
void jac_left(unsigned int n, double* q, unsigned int m, double* j, unsigned int nz, double* z) { jac(-1, q, j); }
void jac_right(unsigned int n, double* q, unsigned int m, double* j, unsigned int nz, double* z) { jac(1, q, j); }
void djac_left(unsigned int n, double* q, unsigned int nv, double* v, double* j, unsigned int nz, double* z) { djac(-1, q, v, j); }
void djac_right(unsigned int n, double* q, unsigned int nv, double* v, double* j, unsigned int nz, double* z) { djac(1, q, v, j); }

/* base acceleration a(t): 0, a one-sine pulse, or a record interpolated as np.interp(t, rt, ra,
   left=0, right=0); set from Python through ctypes before a run */
static int kind = 0, rn = 0;
static double pa, pw, pend, *rt = 0, *ra = 0;
long nfint = 0; /* calls of fint, read from Python to check that Siconos uses the plugin */
void set_zero(void) { kind = 0; }
void set_pulse(double a, double w, double t_end) { kind = 1; pa = a; pw = w; pend = t_end; }
void set_record(int n, const double* t, const double* a) {
  free(rt); free(ra); rt = malloc(n * sizeof(double)); ra = malloc(n * sizeof(double));
  memcpy(rt, t, n * sizeof(double)); memcpy(ra, a, n * sizeof(double)); rn = n; kind = 2;
}
double accel(double t) {
  if (kind == 1) return 0.0 <= t && t <= pend ? pa * sin(pw * t) : 0.0;
  if (kind != 2 || !(t >= rt[0] && t <= rt[rn - 1])) return 0.0;
  if (t == rt[rn - 1]) return ra[rn - 1];
  /* uniform samples: guess the interval, then fix it on the stored times */
  long j = (long)((t - rt[0]) / (rt[1] - rt[0]));
  if (j > rn - 2) j = rn - 2;
  while (j > 0 && rt[j] > t) --j;
  while (j < rn - 2 && rt[j + 1] <= t) ++j;
  return (ra[j + 1] - ra[j]) / (rt[j + 1] - rt[j]) * (t - rt[j]) + ra[j];
}
/* FInt = [m X' X'' thd^2 + m a(t) X', m g] (M q'' + FInt = p) and its Jacobians (column-major) */
static void xd(double th, double* x) {
  double s = th >= 0 ? 1.0 : -1.0, sn = sin(th), cs = cos(th);
  x[0] = -s * B * sn - H * cs; x[1] = -s * B * cs + H * sn; x[2] = s * B * sn + H * cs;
}
void fint(double t, unsigned int n, double* q, double* v, double* f, unsigned int nz, double* z) {
  double x[3]; xd(q[0], x); ++nfint;
  f[0] = MASS * (x[0] * x[1] * v[0] * v[0] + accel(t) * x[0]); f[1] = MASS * G;
}
void fint_q(double t, unsigned int n, double* q, double* v, double* j, unsigned int nz, double* z) {
  double x[3]; xd(q[0], x);
  j[0] = MASS * ((x[1] * x[1] + x[0] * x[2]) * v[0] * v[0] + accel(t) * x[1]); j[1] = j[2] = j[3] = 0.0;
}
void fint_v(double t, unsigned int n, double* q, double* v, double* j, unsigned int nz, double* z) {
  double x[3]; xd(q[0], x);
  j[0] = 2.0 * MASS * x[0] * x[1] * v[0]; j[1] = j[2] = j[3] = 0.0;
}
"""


def _plugin():
    """Path (without .so) of the compiled plugin, built once per geometry."""
    defs = dict(B=B, H=H, G=G, IC=I_C, MASS=MASS)
    src = "".join(f"#define {k} {v!r}\n" for k, v in defs.items()) + _PLUGIN_C
    tag = hashlib.sha1(src.encode()).hexdigest()[:12]
    base = os.path.join(tempfile.gettempdir(), f"flexrock_siconos_block_{tag}")
    if not os.path.exists(base + ".so"):
        with open(base + ".c", "w") as f:
            f.write(src)
        subprocess.run(["cc", "-O2", "-shared", "-fPIC", "-o", base + ".so.tmp", base + ".c",
                        "-lm"], check=True)
        os.replace(base + ".so.tmp", base + ".so")
    return base


_LIB = {}


def _lib(plugin):
    """The plugin through ctypes: dlopen of the same file returns the handle Siconos loaded, so
    set_record / set_pulse here set the a(t) that its fint reads."""
    if plugin not in _LIB:
        lib = ctypes.CDLL(plugin + ".so")
        lib.set_pulse.argtypes = [ctypes.c_double] * 3
        lib.set_record.argtypes = [ctypes.c_int, ctypes.POINTER(ctypes.c_double),
                                   ctypes.POINTER(ctypes.c_double)]
        lib.accel.argtypes, lib.accel.restype = [ctypes.c_double], ctypes.c_double
        _LIB[plugin] = lib
    return _LIB[plugin]


def _set_accel(case, spec, plugin):
    """Give the plugin compare.py's a(t) of case: zero (a), the one-sine pulse (b2, b6), the
    Kobe record (c); then check it against spec["accel"], so that a change in compare.py's
    motions cannot go unnoticed."""
    lib = _lib(plugin)
    if case == "a":
        lib.set_zero()
    elif case in ("b2", "b6"):
        w = (2.0 if case == "b2" else 6.0) * math.pi
        lib.set_pulse(3.0 * G * math.tan(ALPHA), w, 2.0 * math.pi / w)
    elif case == "c":
        tk, ak = (np.ascontiguousarray(x, dtype=float) for x in compare.kobe_05g())
        ptr = ctypes.POINTER(ctypes.c_double)
        lib.set_record(tk.size, tk.ctypes.data_as(ptr), ak.ctypes.data_as(ptr))
    else:
        raise ValueError(f"no base acceleration for case {case!r} in the Siconos plugin")
    accel, t_end = spec["accel"], spec["t_end"]
    ts = np.concatenate([np.linspace(-1.0, t_end + 1.0, 20011), [0.0, t_end]])
    bad = [t for t in ts if abs(lib.accel(t) - accel(t)) > 1e-12 * (1.0 + abs(accel(t)))]
    if bad:
        raise RuntimeError(f"case {case}: the plugin's a(t) differs from compare.py's at t = {bad[0]}")


def _set_atol(osi, atol):
    """Write lsodar's scalar atol (LsodarOSI 4.4's setTol stores rtol there)."""
    sa = osi.getAtol()  # a copy of the boost::shared_array; its first word is the array
    sa.disown()  # the copy is not ours to free (SWIG knows no destructor for it)
    ctypes.c_double.from_address(ctypes.c_void_p.from_address(int(sa)).value).value = atol


def _episode(t0, t_end, theta0, thd0, rtol, hmax, plugin):
    """One Siconos event-driven run from (theta0, thd0) on its pivot; returns the samples
    [(t, theta, theta_dot, kind)] with kind 'step', 'impact', 'uplift' or 'overturn', and the
    state, and stops after the first impact so that the caller applies the chatter rule."""
    s0 = 1.0 if theta0 >= 0.0 else -1.0
    y0 = s0 * B * math.sin(theta0) + H * math.cos(theta0) - H  # pivot corner on the ground
    yd0 = (s0 * B * math.cos(theta0) - H * math.sin(theta0)) * thd0
    ds = sk.LagrangianDS(np.array([theta0, y0]), np.array([thd0, yd0]),
                         np.diag([I_C + MASS * H * H, MASS]))
    ds.setComputeMassFunction(plugin, "mass")
    ds.setComputeFIntFunction(plugin, "fint")  # FPtr6: (t, n, q, v, f, nz, z)
    ds.setComputeJacobianFIntqFunction(plugin, "fint_q")
    ds.setComputeJacobianFIntqDotFunction(plugin, "fint_v")
    ds.init_forces()
    nsds = sk.NonSmoothDynamicalSystem(t0, t_end)
    nsds.insertDynamicalSystem(ds)
    law = sk.NewtonImpactNSL(0.0)  # zero restitution at the landing corner
    for side in ("left", "right"):
        rel = sk.LagrangianScleronomousR(f"{plugin}:h_{side}", f"{plugin}:jac_{side}",
                                         f"{plugin}:djac_{side}")
        nsds.link(sk.Interaction(law, rel), ds)
    for sgn in (-1.0, 1.0):  # pi/2 -+ theta >= 0: overturn (flexrock's rule), by lsodar's roots
        rel = sk.LagrangianLinearTIR(np.array([[sgn, 0.0]]), np.array([compare.OVERTURN]))
        nsds.link(sk.Interaction(sk.NewtonImpactNSL(0.0), rel), ds)
    osi = sk.LsodarOSI()
    td = sk.TimeDiscretisation(t0, hmax)
    sim = sk.EventDriven(nsds, td)
    sim.insertIntegrator(osi)
    sim.insertNonSmoothProblem(sk.LCP(), sk.SICONOS_OSNSP_ED_IMPACT)
    sim.insertNonSmoothProblem(sk.LCP(), sk.SICONOS_OSNSP_ED_SMOOTH_ACC)
    sim.initialize()
    osi.setJT(1)  # analytic Jacobian
    osi.setTol(1, rtol, 0.0)
    _set_atol(osi, 1e-2 * rtol)  # as compare.py's scipy runs
    osi.setMinMaxStepSizes(hmax, 0.0)  # 4.4: the first argument is the maximum step
    osi.setMaxNstep(100000)
    sim.setToleranceED(TOL_ED * rtol)
    return sim, ds


def _thdd(t, th, thd, side, accel):
    """theta'' on pivot side (compare.py's Housner equation), for the dense output at peaks."""
    return -compare.P2 * (math.sin(side * ALPHA - th) - accel(t) / G * math.cos(side * ALPHA - th))


def _peak(a, b, side, accel):
    """|theta| at theta_dot = 0 between samples a, b = (t, theta, theta_dot): quintic Hermite
    on theta, theta_dot, theta'' at both ends."""
    (t0, x0, v0), (t1, x1, v1) = a, b
    hh = t1 - t0
    c0, c1 = _thdd(t0, x0, v0, side, accel), _thdd(t1, x1, v1, side, accel)
    # theta(t0 + hh s) = sum k_i s^i with the six end conditions
    A = np.array([[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0], [0, 0, 2, 0, 0, 0],
                  [1, 1, 1, 1, 1, 1], [0, 1, 2, 3, 4, 5], [0, 0, 2, 6, 12, 20]], float)
    k = np.linalg.solve(A, [x0, v0 * hh, c0 * hh * hh, x1, v1 * hh, c1 * hh * hh])
    p = np.polynomial.Polynomial(k)
    r = [z.real for z in p.deriv().roots() if abs(z.imag) < 1e-9 and -1e-9 <= z.real <= 1 + 1e-9]
    return max([abs(p(z)) for z in r] + [abs(x0), abs(x1)])


def simulate(spec, rtol):
    """Housner's block in Siconos for one case spec of compare.cases(); compare.housner_scipy's
    outcome tuple (first uplift, impacts, status, overturn edge, max |theta|, overturn time).
    The plugin's a(t) is the one _set_accel gave it."""
    accel, t_end = spec["accel"], spec["t_end"]
    hmax = spec["max_step"] if math.isfinite(spec["max_step"]) else 0.05
    plugin = _plugin()
    t, theta, thd = 0.0, spec["theta0"], 0.0
    side = 1 if theta > 0 else (-1 if theta < 0 else 0)
    impacts, first_uplift, max_theta, last_change = [], None, abs(theta), -1e9
    while t < t_end:
        sim, ds = _episode(t, t_end, theta, thd, rtol, hmax, plugin)
        q, v = ds.q(), ds.velocity()
        em = sim.eventsManager()
        prev = (t, float(q[0]), float(v[0]))
        rest = False
        while sim.hasNextEvent():
            sim.advanceToEvent()
            ns = em.nextEvent().getType() == 2  # nonsmooth: impact, release or overturn
            tn = sim.nextTime()
            cur = (tn, float(q[0]), float(v[0]))
            if side != 0 and prev[2] * cur[2] < 0.0:
                max_theta = max(max_theta, _peak(prev, cur, side, accel))
            if ns and abs(cur[1]) >= compare.OVERTURN * (1.0 - 1e-6):
                return first_uplift, impacts, "overturned", 1 if cur[1] > 0 else 2, compare.OVERTURN, tn
            if ns:  # see TOL_ED_IMPACT
                sim.setToleranceED(max(TOL_ED * rtol, TOL_ED_IMPACT * cur[2] * cur[2]))
            sim.processEvents()
            sim.setToleranceED(TOL_ED * rtol)
            if ns and tn > t:
                if side == 0:  # a contact force reached zero: uplift, away from the released corner
                    side = 1 if accel(tn) > 0 else -1
                    first_uplift = tn if first_uplift is None else first_uplift
                    last_change = tn
                elif abs(cur[1]) < 1e-3 * ALPHA:  # the other corner landed
                    impacts.append(tn)
                    if tn - last_change < CHATTER:  # impacts faster than the chatter criterion
                        rest = True
                        break
                    side, last_change = -side, tn
            prev = (tn, float(q[0]), float(v[0]))
        if not rest:
            break
        t, theta, thd, side = impacts[-1], 0.0, 0.0, 0
    return first_uplift, impacts, "completed", 0, max_theta, -1.0


def run(case, rtol, reps):
    """compare.py's peer entry: the outcome of case at rtol and the median CPU time per run."""
    if rtol < RTOL_MIN:
        raise ValueError(f"rtol {rtol:g} below {RTOL_MIN:g}: not practical with LsodarOSI here")
    spec = compare.cases()[case]
    _set_accel(case, spec, _plugin())
    times, res = [], None
    for _ in range(reps):
        t0 = time.process_time()
        try:
            res = simulate(spec, rtol)
        except Exception as e:  # Siconos 4.4 raises a bare std::exception
            raise RuntimeError(f"Siconos event-driven run failed ({e}): an index-set check after "
                               "an event or lsodar (see its message above)") from None
        times.append(time.process_time() - t0)
    fu, imp, status, edge, mt, tov = res
    return dict(first_uplift=fu, impacts=imp, status=status, overturn_edge=edge, max_theta=mt,
                overturn_time=tov, cpu_s=statistics.median(times))
