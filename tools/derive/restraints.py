# SPDX-License-Identifier: BSD-3-Clause
"""Restraints of a rigid block: tendons and anchors (docs/theory.md, section 26).

A restraint is a tie between a point F = (x_f, y_f) of the floor (y_f <= 0: in the foundation) and
a point P = (x_b, y_b) of the body (body axes, origin on the base under the c.g., y up). Its
elongation is e = |P - F| - |P_0 - F| (P_0: P at rest), its force a tension T(e) >= 0 (never a
push), elastic-perfectly plastic:

    T = max(0, P_0 + k (e - s - e_p)),   capped at F_y while yielding (e_p grows with e),

with stiffness k, prestress P_0 (tendons), slack s (anchors) and plastic elongation e_p (state).
Its elastic energy U(e) with dU/de = T is U = P_0 e' + k e'^2 / 2 for T > 0 and -P_0^2 / (2 k)
once slack (e' = e - s - e_p).

Rocking on edge 1 (theta >= 0, pivot at (-b_1, 0), counter-clockwise) the body point is
P(theta) = (-b_1, 0) + R(theta) (x_b + b_1, y_b). Checked here, symbolically:
- the generalised force of the tie, Q = -T de/dtheta, is the virtual work of the tie's pull on P
  (the force -T (P - F)/|P - F| on the body) and the derivative of -U: the tie's force enters the
  equations from its potential;
- Lagrange's equation with the tie, I_O theta'' = -M g (b_1 cos - h sin) + M a (b_1 sin + h cos)
  - T e'(theta), is the engine's rigid rocking equation (theory, "Equations of motion") plus Q;
- the quasi-static pushover: the base acceleration that holds the body at theta,
  a(theta) = [M g (b_1 cos - h sin) + T e'(theta)] / [M (b_1 sin + h cos)], and the restoring
  moment about the pivot M_r(theta) = M g (b_1 cos - h sin) + T(e(theta)) e'(theta);
- the uplift threshold: a(0+) = g b_1/h + T_0 e'(0) / (M h); for a vertical tie e'(0) = x_b + b_1;
- the critical stiffness: dM_r/dtheta(0+) = -M g h + k e'(0)^2 + T_0 e''(0) = 0 gives
  k_c = (M g h - T_0 e''(0)) / e'(0)^2; for a vertical tie e''(0) = -y_b (1 - y_b / L)
  (L = y_b - y_f), so k_c = (M g h + P_0 y_b (-y_f) / L) / (x_b + b_1)^2;
- the anchors' rigid-plastic limit: as k -> oo the pushover's peak tends to
  (M g b_1 + F_y (x_b + b_1)) / (M h);
- the energy: U' = T in every state, so that with a = 0 the sum kinetic + gravity + U is
  constant along the rocking equations (its time derivative vanishes identically).
Reference values (mpmath, 30 digits) at sample points go to the JSON for
tests/unit/restraints_test.cpp."""

import json
import sys

import mpmath as mp
import sympy as sp

G_STD = '9.80665'


def _geometry():
    th, b1, b2, h, xb, yb, xf, yf = sp.symbols('theta b_1 b_2 h x_b y_b x_f y_f', real=True)
    R = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])
    P = sp.Matrix([-b1, 0]) + R * sp.Matrix([xb + b1, yb])
    F = sp.Matrix([xf, yf])
    d = P - F
    length = sp.sqrt(d.dot(d))
    L0 = length.subs(th, 0)
    e = length - L0
    return dict(th=th, b1=b1, b2=b2, h=h, xb=xb, yb=yb, xf=xf, yf=yf, P=P, F=F, e=e, L0=L0)


def restraints():
    """The checks (name -> True/False) and the reference values."""
    G = _geometry()
    th, b1, h, xb, yb, xf, yf, P, F, e = (G[k] for k in ('th', 'b1', 'h', 'xb', 'yb', 'xf', 'yf',
                                                        'P', 'F', 'e'))
    M, g, a, k, P0, s, ep, z2, T = sp.symbols('M g a k P_0 s e_p zeta2 T', positive=True)
    res = {}
    # the tie's pull on P, its virtual work, and -dU/dtheta for the elastic law (T > 0)
    d = P - F
    unit = d / sp.sqrt(d.dot(d))
    virtual = (-T * unit).dot(P.diff(th))
    res['generalised_force_is_virtual_work'] = sp.simplify(virtual + T * e.diff(th)) == 0
    ee = e - s - ep
    U = P0 * ee + k * ee ** 2 / 2
    Tel = P0 + k * ee
    res['force_is_potential_gradient'] = sp.simplify(sp.diff(U, th) - Tel * e.diff(th)) == 0
    # the slack branch: U = -P0^2/(2k) is continuous with the elastic branch where T = 0
    e0 = sp.Symbol('e0')
    Ue = (P0 * e0 + k * e0 ** 2 / 2).subs(e0, -P0 / k)
    res['slack_energy_continuous'] = sp.simplify(Ue + P0 ** 2 / (2 * k)) == 0
    # Lagrange's equation with the tie (rigid body about the pivot on edge 1)
    t = sp.Symbol('t')
    Th = sp.Function('Th')(t)
    I_O = M * h ** 2 * (1 + z2 + (b1 / h) ** 2)
    xcg = -b1 + b1 * sp.cos(Th) - h * sp.sin(Th)
    ycg = b1 * sp.sin(Th) + h * sp.cos(Th)
    Ttie = sp.Function('Ttie')(t)  # the tie's force, whatever its law
    Lag = I_O * Th.diff(t) ** 2 / 2 - M * g * ycg - M * a * xcg
    EL = sp.diff(Lag.diff(Th.diff(t)), t) - Lag.diff(Th) + Ttie * e.subs(th, Th).diff(Th)
    thdd = sp.solve(EL, Th.diff(t, 2))[0]
    engine = (-M * g * (b1 * sp.cos(Th) - h * sp.sin(Th)) + M * a * (b1 * sp.sin(Th) + h * sp.cos(Th))
              - Ttie * e.subs(th, Th).diff(Th)) / I_O
    res['rocking_equation_with_tie'] = sp.simplify(thdd - engine) == 0
    # energy: with a = 0 and an elastic tie, kinetic + gravity + U is a first integral
    thd = sp.Symbol('thd')
    Ue_th = U
    H = I_O * thd ** 2 / 2 + M * g * ycg.subs(Th, th) + Ue_th
    acc = engine.subs({a: 0, Ttie: Tel.subs(th, Th)}).subs(Th, th)
    dH = sp.diff(H, th) * thd + sp.diff(H, thd) * acc
    res['energy_first_integral'] = sp.simplify(dH) == 0
    # quasi-static pushover and the uplift threshold
    ep1 = e.diff(th)
    a_push = (M * g * (b1 * sp.cos(th) - h * sp.sin(th)) + T * ep1) / (M * (b1 * sp.sin(th) + h * sp.cos(th)))
    res['pushover_is_equilibrium'] = sp.simplify(engine.subs(Th, th).subs({Ttie: T, a: a_push})) == 0
    vert = {xf: xb}
    Lv = sp.Symbol('L', positive=True)
    vertL = {xf: xb, yf: yb - Lv}
    a_up = sp.simplify(a_push.subs(th, 0).subs(vertL))
    res['uplift_threshold_vertical'] = sp.simplify(a_up - (g * b1 / h + T * (xb + b1) / (M * h))) == 0
    # critical stiffness of a vertical tie (yf < 0 below the floor; L = yb - yf)
    Mr = M * g * (b1 * sp.cos(th) - h * sp.sin(th)) + Tel.subs({s: 0, ep: 0}) * ep1
    slope0 = sp.simplify(sp.diff(Mr, th).subs(th, 0).subs(vert))
    e2 = sp.simplify(e.diff(th, 2).subs(th, 0).subs(vert))
    res['second_derivative_vertical'] = sp.simplify(
        e2.subs(yf, yb - Lv) - (-yb * (1 - yb / Lv))) == 0
    kc = sp.solve(sp.Eq(slope0, 0), k)[0]
    kc_form = (M * g * h + P0 * yb * (-yf) / (yb - yf)) / (xb + b1) ** 2
    res['critical_stiffness_vertical'] = sp.simplify((kc - kc_form).subs(yf, yb - Lv)) == 0
    # rigid-plastic anchors: a(theta) at the yield rotation tends to the closed form as k -> oo
    Fy = sp.Symbol('F_y', positive=True)
    a_yield_limit = (M * g * b1 + Fy * (xb + b1)) / (M * h)
    res['rigid_plastic_anchor_limit'] = sp.simplify(
        sp.limit(a_push.subs(vertL).subs(T, Fy), th, 0) - a_yield_limit) == 0

    # reference values: three ties on a 2 m x 0.5 m (half-sizes) block and two unequal ones
    refs = []
    mp.mp.dps = 30
    gn = mp.mpf(G_STD)
    cases = [
        # a central vertical tendon through the body, anchored at the top and 3 m into the floor
        dict(name='central_tendon', M=2000, h=1.0, b1=0.25, b2=0.25, xb=0.0, yb=2.0, xf=0.0, yf=-3.0,
             k=2.0e6, P0=1.5e4, s=0.0),
        # an off-centre tendon anchored at mid-height, a shallow foundation point, an uneven base
        dict(name='offset_tendon', M=800, h=0.6, b1=0.2, b2=0.3, xb=0.05, yb=0.6, xf=0.02, yf=-0.4,
             k=5.0e5, P0=4.0e3, s=0.0),
        # an anchor bolt at the right corner (free length 0.2 m) with a slack of 1 mm
        dict(name='corner_anchor', M=300, h=0.9, b1=0.3, b2=0.3, xb=0.3, yb=0.0, xf=0.3, yf=-0.2,
             k=2.0e7, P0=0.0, s=1.0e-3),
    ]
    lam = {}
    for c in cases:
        num = {M: c['M'], g: gn, h: c['h'], b1: c['b1'], xb: c['xb'], yb: c['yb'], xf: c['xf'],
               yf: c['yf']}
        fe = sp.lambdify(th, e.subs(num), 'mpmath')
        fe1 = sp.lambdify(th, ep1.subs(num), 'mpmath')
        rows = []
        for tt in ('0.001', '0.01', '0.05', '0.1'):
            tv = mp.mpf(tt)
            ev = fe(tv)
            force = max(mp.mpf(0), c['P0'] + c['k'] * (ev - c['s']))
            M_r = c['M'] * gn * (c['b1'] * mp.cos(tv) - c['h'] * mp.sin(tv)) + force * fe1(tv)
            a_p = M_r / (c['M'] * (c['b1'] * mp.sin(tv) + c['h'] * mp.cos(tv)))
            rows.append(dict(theta=tv, elongation=ev, elongation_rate=fe1(tv), force=force,
                             restoring_moment=M_r, pushover_acceleration=a_p))
        e1_0 = fe1(mp.mpf(0))
        up = (c['M'] * gn * c['b1'] + c['P0'] * e1_0) / (c['M'] * c['h'])
        ref = dict(c, g=gn, points=rows, uplift_acceleration=up)
        if c['xb'] == c['xf'] and c['s'] == 0:
            ref['critical_stiffness'] = sp.N(kc_form.subs(num).subs(P0, c['P0']), 30)
        refs.append(ref)
    lam['cases'] = refs
    return res, lam


def _plain(x):
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, (mp.mpf, sp.Basic)):
        return float(x)
    return x


def main(argv):
    res, refs = restraints()
    bad = [k for k, v in res.items() if not v]
    print('restraints: %s' % ('ALL PASS' if not bad else 'FAILED %s' % bad), file=sys.stderr)
    if len(argv) >= 3 and argv[1] == '--out':
        with open(argv[2], 'w') as fh:
            json.dump(_plain(refs), fh, indent=1)
            fh.write('\n')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
