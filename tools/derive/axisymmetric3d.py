#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""A rigid body of revolution rolling on its rim without slip (docs/theory.md §27).

Body: mass M, c.g. on the axis at height h above the base centre, base radius R, inertia A about
a diameter through the c.g., C about the axis. Floor: accelerating a_f = (a_x, a_y, a_z), z up.
Euler angles R = Rz(phi) Ry(theta) Rz(psi): theta the tilt of the axis from the vertical, phi its
azimuth (the axis leans toward phi, and so does the contact point), psi the spin relative to the
tilt frame. Tilt frame (e1, e2, e3) = Rz(phi) Ry(theta) (x, y, z): e1 points from the base centre
to the contact point P, e2 is horizontal, e3 the axis.

Two derivations of the rolling equations, written differently:
 (1) Kane's equations in world components: v_G = omega x r_PG (no slip), a_G by differentiating
     v_G in time, the generalised inertia and active forces projected on the partial velocities of
     (theta, phi, psi); the contact force has zero partial velocity and drops out.
 (2) Newton-Euler about the contact point in the tilt frame (the form the C++ engine evaluates
     numerically, there with a quaternion and the world-frame omega):
     I_P omegadot = -omega x I omega - M r x (omega x rdot) - M r x (g e_z + a_f).
Checks: (1) == (2); energy conservation without base motion; the planar reduction (phi_dot =
psi_dot = 0, the floor along the tilt plane: stays in it, Housner's rocking with the cylinder's
inertia about the rim point); the steady wobble (c.g. at rest: psi_dot = phi_dot (h sin(theta)/R -
cos(theta)), phi_dot^2 from theta_ddot = 0) and its thin-disk limit phi_dot^2 = 4 g / (R
sin(theta)); the landing map (moment of momentum about the landing rim point in all three
components) and its planar ratio (A + M(h^2 - R^2)) / (A + M(h^2 + R^2)).
Reference values (omega_dot, floor force at random states) go to the JSON for the C++ tests.
"""
import random

import sympy as sp


def _frame(th, ph):
    c, s = sp.cos, sp.sin
    rz = sp.Matrix([[c(ph), -s(ph), 0], [s(ph), c(ph), 0], [0, 0, 1]])
    ry = sp.Matrix([[c(th), 0, s(th)], [0, 1, 0], [-s(th), 0, c(th)]])
    return rz * ry  # columns: e1, e2, e3 in world components


def _cross(a, b):
    return a.cross(b)


def _zero_at_points(expr, syms, trials=5, seed=11, inner=None):
    """expr == 0 identically, tested at random points in 60-digit arithmetic (a polynomial-
    trigonometric identity that fails leaves a residual of order 1 at a random point). `inner`:
    {symbol: expression} substituted after the point (the accelerations), each at the point."""
    rng = random.Random(seed)
    for _ in range(trials):
        pt = {s_: sp.Float(rng.randint(5, 150), 60) / 100 for s_ in syms}
        e = expr.subs(pt)
        if inner:
            e = e.subs({k: sp.N(v.subs(pt), 60) for k, v in inner.items()})
        v = sp.N(e, 60)
        if abs(v) > 1e-40:
            return False
    return True


def derive():
    t = sp.Symbol('t')
    M, h, R, A, C, g = sp.symbols('M h R A C g', positive=True)
    ax, ay, az = sp.symbols('a_x a_y a_z')
    th, ph, ps = [sp.Function(n)(t) for n in ('theta', 'phi', 'psi')]
    q = [th, ph, ps]
    qd = [sp.diff(v, t) for v in q]
    qdd = [sp.diff(v, t, 2) for v in q]
    T3 = _frame(th, ph)
    e1, e2, e3 = T3[:, 0], T3[:, 1], T3[:, 2]
    ez = sp.Matrix([0, 0, 1])
    # world angular velocity of the body: phi_dot e_z + theta_dot e2 + psi_dot e3
    om = qd[1] * ez + qd[0] * e2 + qd[2] * e3
    r = h * e3 - R * e1  # r_PG
    vG = _cross(om, r)
    aG = sp.diff(vG, t)
    Iw = A * sp.eye(3) + (C - A) * e3 * e3.T
    H = Iw * om
    Hd = sp.diff(H, t)
    af = sp.Matrix([ax, ay, az])
    # (1) Kane: sum over (M aG + M g ez + M af) . dvG/dqd_k + Hd . domega/dqd_k = 0
    kane = []
    for k in range(3):
        pv = vG.diff(qd[k])
        pw = om.diff(qd[k])
        kane.append((M * (aG + g * ez + af)).dot(pv) + Hd.dot(pw))

    # (2) Newton-Euler about P in tilt-frame components, with the frame's own rates
    Th, Ph, Ps, Thd, Phd, Psd, Thdd, Phdd, Psdd = sp.symbols(
        'Th Ph Ps Thd Phd Psd Thdd Phdd Psdd')
    sub = {qdd[0]: Thdd, qdd[1]: Phdd, qdd[2]: Psdd}
    sub2 = {qd[0]: Thd, qd[1]: Phd, qd[2]: Psd}
    sub3 = {th: Th, ph: Ph, ps: Ps}

    def plain(e):
        return e.subs(sub).subs(sub2).subs(sub3)

    # tilt frame: Omega = (-phd sin, thd, phd cos); omega = Omega + psd e3
    Om = sp.Matrix([-Phd * sp.sin(Th), Thd, Phd * sp.cos(Th)])
    w = Om + sp.Matrix([0, 0, Psd])
    rf = sp.Matrix([-R, 0, h])  # r_PG in the tilt frame (constant there)
    # d/dt of tilt-frame components: wdot_rel from the coordinates' rates
    wdot_rel = sp.Matrix([-Phdd * sp.sin(Th) - Phd * Thd * sp.cos(Th), Thdd,
                          Phdd * sp.cos(Th) - Phd * Thd * sp.sin(Th) + Psdd])
    wdot = wdot_rel + Om.cross(w)  # inertial derivative in tilt components
    If = sp.diag(A, A, C)
    rdot = Om.cross(rf)  # rf constant in the frame
    gf = T3.T.subs(sub3) * (g * ez + af)  # g e_z + a_f in the tilt frame
    # Hdot_G in the frame: If wdot_rel-ish is handled by wdot (If constant in the frame since
    # the body is axisymmetric): d/dt(If w) = If (dw/dt)_rel + Om x If w
    Hd_f = If * wdot_rel + Om.cross(If * w)
    ne = (Hd_f + M * rf.cross(wdot.cross(rf) + w.cross(rdot)) + M * rf.cross(gf))
    # linear in the accelerations: solve the 3x3 system
    Amat, bvec = sp.linear_eq_to_matrix(list(ne), [Thdd, Phdd, Psdd])
    sol2 = Amat.LUsolve(bvec)
    acc_ne = [sp.together(v) for v in sol2]
    accsub_ne = {Thdd: acc_ne[0], Phdd: acc_ne[1], Psdd: acc_ne[2]}

    import sys as _sys
    _sys.stderr.write('  axisymmetric3d: equations solved\n')
    res = {}
    # Kane's equations, written in world components, hold with Newton-Euler's accelerations: exact
    # rational arithmetic at random rational points (a polynomial identity test in the states and
    # parameters; a wrong term survives at a random point with probability ~0)
    rngk = random.Random(3)
    bad = []
    for trial in range(6):
        pt = {s_: sp.Rational(rngk.randint(1, 97), rngk.randint(1, 31)) for s_ in
              (M, h, R, A, C, g)}
        pt.update({s_: sp.Rational(rngk.randint(-50, 50), rngk.randint(1, 17)) for s_ in
                   (ax, ay, az, Thd, Phd, Psd, Ph, Ps)})
        pt[Th] = sp.Rational(rngk.randint(1, 150), 100)
        accp = {k: sp.N(v.subs(pt), 60) for k, v in accsub_ne.items()}
        for kk in kane:
            e = plain(kk).subs(pt).subs(accp)
            v = sp.N(e, 60)
            if abs(v) > 1e-40:
                bad.append((trial, float(v)))
    res['kane_equals_newton_euler'] = bad

    _sys.stderr.write('  axisymmetric3d: Kane checked\n')
    # energy without base motion: T + V constant along the equations
    T = sp.Rational(1, 2) * M * vG.dot(vG) + sp.Rational(1, 2) * om.dot(Iw * om)
    zG = h * sp.cos(th) + R * sp.sin(th)
    E = T + M * g * zG
    dE = plain(sp.diff(E, t)).subs({ax: 0, ay: 0, az: 0})
    accs0 = {Thdd: acc_ne[0].subs({ax: 0, ay: 0, az: 0}),
             Phdd: acc_ne[1].subs({ax: 0, ay: 0, az: 0}),
             Psdd: acc_ne[2].subs({ax: 0, ay: 0, az: 0})}
    allsyms = [M, h, R, A, C, g, ax, ay, az, Th, Ph, Ps, Thd, Phd, Psd]
    res['energy_conserved'] = _zero_at_points(dE, allsyms, inner=accs0)
    # with base motion the energy rate is the pseudo-force's power -M a_f . v_G
    dEa = plain(sp.diff(E, t))
    res['energy_rate_is_input_power'] = _zero_at_points(dEa + M * plain(af.dot(vG)), allsyms,
                                                        inner=accsub_ne)

    # planar reduction: phi_dot = psi_dot = 0, floor acceleration in the tilt plane
    pl = {Phd: 0, Psd: 0, ay: 0, Ph: sp.pi}
    res['planar_stays_in_plane'] = (_zero_at_points(acc_ne[1].subs(pl), allsyms) and
                                    _zero_at_points(acc_ne[2].subs(pl), allsyms))
    # planar engine, edge 1 (pivot at -R along x): I_O thdd = -M g (R cos + ... ) in its theta
    # = our theta with the contact at phi = pi: I_O th'' = M R_o [ -g sin(alpha - ... )]; written
    # out: I_O th'' = -M g (R cos(th) - h sin(th)) + M a_x (h cos(th) + R sin(th)) - M a_z (...)
    IO = A + M * (h ** 2 + R ** 2)
    planar = (-M * (g + az) * (R * sp.cos(Th) - h * sp.sin(Th)) +
              M * ax * (h * sp.cos(Th) + R * sp.sin(Th))) / IO
    res['planar_reduction'] = _zero_at_points(acc_ne[0].subs(pl) - planar, allsyms)

    _sys.stderr.write('  axisymmetric3d: energy, planar checked\n')
    # steady wobble with the c.g. at rest: omega parallel to r_PG, theta_dot = 0
    W = sp.Symbol('W', positive=True)  # precession rate phi_dot
    steady = {Thd: 0, Phd: W, Psd: W * (h * sp.sin(Th) / R - sp.cos(Th)), ax: 0, ay: 0, az: 0}
    vg_f = w.cross(rf).subs(steady)
    res['steady_cg_at_rest'] = all(sp.simplify(c) == 0 for c in vg_f)
    thdd_s = sp.factor(sp.together(acc_ne[0].subs(steady)))
    Wsol = sp.solve(sp.numer(sp.together(thdd_s)), W)
    Wsol = [s for s in Wsol if s != 0]
    W2 = sp.simplify(Wsol[0] ** 2)
    res['steady_phi_psi_rates_constant'] = (
        _zero_at_points(acc_ne[1].subs(steady), allsyms + [W]) and
        _zero_at_points(acc_ne[2].subs(steady), allsyms + [W]))
    # and theta_ddot vanishes at the derived rate (a check of the solve)
    res['steady_theta_ddot_zero'] = _zero_at_points(
        acc_ne[0].subs(steady).subs(W, sp.sqrt(W2)), allsyms)
    # thin uniform disk: h = 0, A = M R^2/4, C = M R^2/2: Euler's disk
    disk = sp.simplify(W2.subs({h: 0, A: M * R ** 2 / 4, C: M * R ** 2 / 2}))
    res['euler_disk_limit'] = sp.simplify(disk - 4 * g / (R * sp.sin(Th))) == 0

    # landing map at theta = 0: omega+ = I_P'^-1 H_P'(-)
    wx, wy, wz = sp.symbols('w_x w_y w_z')
    wm = sp.Matrix([wx, wy, wz])
    r_old = sp.Matrix([-R, 0, h])  # contact at +x before (e1 = x at theta = 0, phi = 0)
    r_new = sp.Matrix([R, 0, h])   # landing point at -x
    I0 = sp.diag(A, A, C)
    Hm = I0 * wm + M * r_new.cross(wm.cross(r_old))
    IPn = I0 + M * (r_new.dot(r_new) * sp.eye(3) - r_new * r_new.T)
    wp = sp.simplify(IPn.inv() * Hm)
    ratio = sp.simplify(wp[1].subs({wx: 0, wz: 0}) / wy)
    res['landing_planar_ratio'] = sp.simplify(
        ratio - (A + M * (h ** 2 - R ** 2)) / (A + M * (h ** 2 + R ** 2))) == 0
    res['landing_planar_stays_planar'] = (sp.simplify(wp[0].subs({wx: 0, wz: 0})) == 0 and
                                          sp.simplify(wp[2].subs({wx: 0, wz: 0})) == 0)
    Hp = I0 * wp + M * r_new.cross(wp.cross(r_new))
    res['landing_conserves_moment_about_landing_point'] = all(
        sp.simplify(a - b) == 0 for a, b in zip(Hp, Hm))
    Tm = sp.Rational(1, 2) * (wm.dot(I0 * wm) + M * wm.cross(r_old).dot(wm.cross(r_old)))
    Tp = sp.Rational(1, 2) * (wp.dot(I0 * wp) + M * wp.cross(r_new).dot(wp.cross(r_new)))
    # loss >= 0 for the solid cylinder at a sample of states
    rng = random.Random(5)
    loss_ok = True
    for _ in range(20):
        vals = {M: 1.0, h: rng.uniform(0.2, 3), R: rng.uniform(0.2, 2), wx: rng.uniform(-2, 2),
                wy: rng.uniform(-2, 2), wz: rng.uniform(-2, 2)}
        vals[A] = vals[M] * (3 * vals[R] ** 2 + 4 * vals[h] ** 2) / 12
        vals[C] = vals[M] * vals[R] ** 2 / 2
        loss_ok = loss_ok and float((Tm - Tp).subs(vals)) >= -1e-12
    res['landing_loses_energy'] = loss_ok

    # reference values for the C++ engine at random states (world frame)
    refs = []
    rng = random.Random(27)
    fz = (M * (aG + g * ez + af))
    for i in range(6):
        vals = {M: rng.uniform(500, 2e5), h: rng.uniform(0.3, 3.0), R: rng.uniform(0.2, 1.8),
                g: 9.80665, ax: rng.uniform(-5, 5), ay: rng.uniform(-5, 5), az: rng.uniform(-3, 3)}
        vals[A] = vals[M] * rng.uniform(0.3, 2.0)
        vals[C] = vals[M] * rng.uniform(0.3, 2.0)
        st = {Th: rng.uniform(0.01, 1.2), Ph: rng.uniform(-3, 3), Ps: rng.uniform(-3, 3),
              Thd: rng.uniform(-2, 2), Phd: rng.uniform(-3, 3), Psd: rng.uniform(-3, 3)}
        acc = [a.subs(vals).subs(st) for a in acc_ne]
        accsub = {Thdd: acc[0], Phdd: acc[1], Psdd: acc[2]}
        om_w = plain(om).subs(vals).subs(st)
        omd_w = plain(sp.diff(om, t)).subs(vals).subs(st).subs(accsub)
        F = plain(fz).subs(vals).subs(st).subs(accsub)
        refs.append({
            'mass': float(vals[M]), 'height': float(vals[h]), 'radius': float(vals[R]),
            'inertia_diameter': float(vals[A]), 'inertia_axis': float(vals[C]),
            'acc': [float(vals[ax]), float(vals[ay]), float(vals[az])],
            'theta': float(st[Th]), 'phi': float(st[Ph]), 'psi': float(st[Ps]),
            'omega': [float(sp.N(c, 30)) for c in om_w],
            'omega_dot': [float(sp.N(c, 30)) for c in omd_w],
            'force': [float(sp.N(c, 30)) for c in F],
        })
    # steady wobbles of uniform cylinders for the engine's test: phi_dot from the closed form
    wob = []
    for (rad, hh, mm, th0) in ((0.5, 0.3, 80.0, 0.25), (0.5, 0.3, 80.0, 0.6), (1.0, 0.05, 50.0, 0.4)):
        vals = {M: mm, h: hh / 2, R: rad, g: 9.80665, A: mm * (3 * rad ** 2 + hh ** 2) / 12,
                C: mm * rad ** 2 / 2, Th: th0}
        w2 = sp.N(W2.subs(vals), 30)
        if w2 > 0:
            wob.append({'radius': rad, 'full_height': hh, 'mass': mm, 'theta': th0,
                        'phi_dot': float(sp.sqrt(w2))})
    res['steady_wobble_cases'] = len(wob) == 3
    forms = {'steady_wobble_phi_dot_squared': str(W2),
             'landing_planar_ratio': str(ratio)}
    return res, {'references': refs, 'steady_wobble': wob, 'forms': forms}


if __name__ == '__main__':
    import json
    import sys
    r, ref = derive()
    print(r)
    print(ref['forms'])
    if len(sys.argv) > 1:
        json.dump(ref, open(sys.argv[1], 'w'), indent=1)
