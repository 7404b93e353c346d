# SPDX-License-Identifier: BSD-3-Clause
"""Rocking frames and stacked bodies (docs/theory.md §25), derived with sympy.

1. A rocking frame: `count` equal uniform rigid columns (half-width b, half-height h, mass m)
   capped by a freely supported rigid beam of mass m_b that rests on the columns' top corners and
   translates with them. Its equation of motion from the energies (Lagrange, horizontal and
   vertical base acceleration), its impact law from the momenta of every part when all columns
   land at once (impulses at the new base pivots and at the beam's new bearing corners, the old
   contacts released), and the equivalent single rigid body that the engine runs: the same
   slenderness alpha, the frame's frequency parameter p and impact ratio r under the body's own
   (Housner) law, the frame's moment of inertia and gravity moment about the pivots.

2. A two-block stack under a constant horizontal acceleration a = lambda g from rest: the
   first-uplift pattern (rest, the top alone rocks on the bottom, both rock as one, both rock
   separately) as the unique solution of the acceleration-level complementarity problem at
   theta = 0 (M thdd + grad V = Lambda, thdd >= 0, Lambda >= 0, thdd.Lambda = 0; M positive
   definite, so unique), and the bands of lambda over which each pattern is the consistent one.

`checks()` returns (dict of checks, reference values for the C++ tests).
"""

import random

import sympy as sp


def _rot(v, t):
    return sp.Matrix([v[0] * sp.cos(t) - v[1] * sp.sin(t), v[0] * sp.sin(t) + v[1] * sp.cos(t)])


def frame_closed_forms():
    """The frame's p^2, r and equivalent body as functions of g, b, h and gamma = m_b/(N m)."""
    g, b, h, gam = sp.symbols('g b h gamma', positive=True)
    R2 = b ** 2 + h ** 2
    c2a = (h ** 2 - b ** 2) / R2  # cos 2 alpha
    p2 = (1 + 2 * gam) / (1 + 3 * gam) * 3 * g / (4 * sp.sqrt(R2))
    r = (1 + 3 * (1 + 4 * gam) * c2a) / (4 * (1 + 3 * gam))
    h_eq = h * (1 + 4 * gam) / (1 + 2 * gam)
    zeta2_eq = (1 + b ** 2 / h ** 2) / (3 * (1 + 4 * gam))
    mass_eq_over_nm = (1 + 2 * gam) ** 2 / (1 + 4 * gam)
    return dict(g=g, b=b, h=h, gamma=gam, p2=p2, r=r, h_eq=h_eq, zeta2_eq=zeta2_eq,
                mass_eq_over_nm=mass_eq_over_nm)


def frame_checks():
    res = {}
    cf = frame_closed_forms()
    g, b, h, gam = cf['g'], cf['b'], cf['h'], cf['gamma']
    m, N, ax, ay = sp.symbols('m N a_x a_y', positive=True)
    mb = gam * N * m
    th, thd, thdd = sp.symbols('theta thetadot thetaddot')
    t = sp.Symbol('t')
    T_ = sp.Function('T')(t)
    # rocking on the left tipping point (edge 1, theta > 0): c.g. of a column from its pivot;
    # the beam rests on the diagonally opposite top corner, 2 rho from the pivot, and translates
    rho = _rot((b, h), T_)
    beam = 2 * rho
    Icg = m * (b ** 2 + h ** 2) / 3
    Tk = N * (m * (rho.diff(t).dot(rho.diff(t))) / 2 + Icg * T_.diff(t) ** 2 / 2) \
        + mb * beam.diff(t).dot(beam.diff(t)) / 2
    # base acceleration (a_x, a_y) in the base's frame: gravity plus the fictitious force
    V = N * m * ((g + ay) * rho[1] + ax * rho[0]) + mb * ((g + ay) * beam[1] + ax * beam[0])
    L = Tk - V
    EL = sp.diff(sp.diff(L, T_.diff(t)), t) - sp.diff(L, T_)
    EL = EL.subs(T_.diff(t, 2), thdd).subs(T_.diff(t), thd).subs(T_, th)
    thdd_frame = sp.solve(EL, thdd)[0]
    # the equivalent rigid body: mass M_e, c.g. (b_e, h_e) from the pivot, I_cg = M_e zeta2 h_e^2
    he, ze = cf['h_eq'], cf['zeta2_eq']
    be = b / h * he
    Me = N * m * cf['mass_eq_over_nm']
    rho_e = _rot((be, he), T_)
    Te = Me * rho_e.diff(t).dot(rho_e.diff(t)) / 2 + Me * ze * he ** 2 * T_.diff(t) ** 2 / 2
    Ve = Me * ((g + ay) * rho_e[1] + ax * rho_e[0])
    ELe = sp.diff(sp.diff(Te - Ve, T_.diff(t)), t) - sp.diff(Te - Ve, T_)
    ELe = ELe.subs(T_.diff(t, 2), thdd).subs(T_.diff(t), thd).subs(T_, th)
    thdd_eq = sp.solve(ELe, thdd)[0]
    res['frame_equals_equivalent_body_eom'] = sp.simplify(sp.expand_trig(thdd_frame - thdd_eq)) == 0
    # energies: the frame's kinetic energy and gravity potential equal the equivalent body's
    kin = lambda expr: sp.simplify(expr.subs(T_.diff(t), thd).subs(T_, th))
    res['frame_kinetic_equals_equivalent'] = sp.simplify(kin(Tk) - kin(Te)) == 0
    res['frame_potential_equals_equivalent'] = sp.simplify(
        (V - Ve).subs(T_, th).subs({ax: 0, ay: 0})) == 0
    # p^2 = (gravity moment at theta = 0) / (moment of inertia about the pivot), R = sqrt(b^2+h^2)
    I_O = sp.simplify(sp.diff(kin(Tk), thd, 2))
    # the gravity potential is A cos(theta + alpha) (edge 1): its amplitude A = g (N m + 2 m_b) R
    # is the gravity moment's scale, p^2 = A / I_O as for a block (M g R / I_O)
    Vg = V.subs(T_, th).subs({ax: 0, ay: 0})
    A = sp.sqrt(sp.simplify(Vg.subs(th, 0) ** 2 + sp.diff(Vg, th).subs(th, 0) ** 2))
    p2_frame = sp.simplify(A / I_O)
    res['frame_p2_closed_form'] = sp.simplify(p2_frame - cf['p2']) == 0
    # beam mass -> 0: one column (p^2 = 3 g / (4 R))
    res['frame_p2_one_column_limit'] = sp.simplify(
        cf['p2'].subs(gam, 0) - 3 * g / (4 * sp.sqrt(b ** 2 + h ** 2))) == 0
    # the impact: rocking on edge 2 (right corner, theta < 0) lands on edge 1 at theta = 0.
    # Unknowns: theta_dot+, the base impulse (Px, Py) at the new pivot (left corner) and the
    # impulse (Qx, Qy) of the beam on the column at the beam's new bearing corner (top right); the
    # beam takes -N Q. The old contacts (right base corner, top left corner) release.
    tm, tp, Px, Py, Qx, Qy = sp.symbols('thd_m thd_p P_x P_y Q_x Q_y')
    w = lambda om, r_: sp.Matrix([-om * r_[1], om * r_[0]])
    cross = lambda u, v: u[0] * v[1] - u[1] * v[0]
    G = sp.Matrix([0, h])                     # column c.g. (base centre at the origin)
    Oold, Onew = sp.Matrix([b, 0]), sp.Matrix([-b, 0])
    Told, Tnew = sp.Matrix([-b, 2 * h]), sp.Matrix([b, 2 * h])
    vg_m, vg_p = w(tm, G - Oold), w(tp, G - Onew)
    vb_m, vb_p = w(tm, Told - Oold), w(tp, Tnew - Onew)  # the beam moves with its bearing corner
    P, Q = sp.Matrix([Px, Py]), sp.Matrix([Qx, Qy])
    eqs = list(m * (vg_p - vg_m) - P - Q) + [Icg * (tp - tm) - cross(Onew - G, P) - cross(Tnew - G, Q)] \
        + list(mb * (vb_p - vb_m) + N * Q)
    sol = sp.solve(eqs, [tp, Px, Py, Qx, Qy], dict=True)[0]
    r_frame = sp.simplify(sol[tp] / tm)
    res['frame_impact_ratio_closed_form'] = sp.simplify(r_frame - cf['r']) == 0
    # the equivalent body's own law (Housner: moment of momentum about the landing corner)
    a2 = (b / h) ** 2
    r_housner = (1 + ze - a2) / (1 + ze + a2)
    res['frame_impact_ratio_is_equivalent_housner'] = sp.simplify(r_housner - cf['r']) == 0
    res['frame_impact_one_column_limit'] = sp.simplify(
        cf['r'].subs(gam, 0) - (1 - sp.Rational(3, 2) * b ** 2 / (b ** 2 + h ** 2))) == 0
    # the moment of momentum of the whole frame about the new pivot line is conserved: with the
    # beam's as a particle at its bearing corner, sum over columns (per column here)
    H = lambda om, vg, vb: Icg * om + m * cross(G - Onew, vg) + mb / N * cross(Tnew - Onew, vb)
    res['frame_moment_of_momentum_conserved'] = sp.simplify(
        H(sol[tp], vg_p.subs(tp, sol[tp]), vb_p.subs(tp, sol[tp])) - H(tm, vg_m, vb_m)) == 0
    # no impact gains energy: T+ / T- = r^2 with 1 - r >= 0 and 1 + r > 0 for any gamma >= 0
    c2a = (h ** 2 - b ** 2) / (b ** 2 + h ** 2)
    one_minus = sp.simplify(1 - cf['r'])
    res['frame_impact_dissipates'] = (
        sp.simplify(one_minus - 3 * (1 + 4 * gam) * (1 - c2a) / (4 * (1 + 3 * gam))) == 0
        and sp.simplify(1 + cf['r'] - (5 + 12 * gam + 3 * (1 + 4 * gam) * c2a) / (4 * (1 + 3 * gam))) == 0)
    # the floor's vertical impulse on each column presses (>= 0) and the beam's on it too, for every
    # slenderness and beam mass (rocking on edge 2, theta < 0, returns with theta_dot- > 0 and lands
    # on edge 1): the contacts
    # the law assumes are compressive
    bad = []
    for bb in (0.05, 0.3, 1.0, 3.0):
        for gg in (0, sp.Rational(1, 10), 1, 10):
            num = {b: bb, h: 1, gam: gg, N: 3, m: 1, tm: 1}
            if not (sol[Py].subs(num) >= 0 and sol[Qy].subs(num) <= 0):
                bad.append((bb, gg, float(sol[Py].subs(num)), float(sol[Qy].subs(num))))
    res['frame_impact_contacts_press'] = bad
    # and the frame's reaction exceeds the equivalent body's by dM (a_base + g), dM = N m g/(1+4g)
    return res


def frame_reference(seed=48):
    """Frames at random: the closed forms in floats for the C++ tests."""
    cf = frame_closed_forms()
    rng = random.Random(seed)
    refs = []
    for _ in range(6):
        b = rng.uniform(0.05, 0.6)
        h = rng.uniform(0.8, 4.0)
        n = rng.randint(2, 6)
        m = rng.uniform(50.0, 5000.0)
        gam = rng.choice([0.0, rng.uniform(0.05, 3.0)])
        num = {cf['g']: 9.80665, cf['b']: b, cf['h']: h, cf['gamma']: gam}
        refs.append(dict(column_width=2 * b, column_height=2 * h, column_mass=m, count=n,
                         beam_mass=gam * n * m, p=float(sp.sqrt(cf['p2'].subs(num))),
                         r=float(cf['r'].subs(num)), alpha=float(sp.atan(b / h)),
                         height_eq=float(cf['h_eq'].subs(num)),
                         zeta2_eq=float(cf['zeta2_eq'].subs(num)),
                         mass_eq=float(n * m * cf['mass_eq_over_nm'].subs(num))))
    return refs


def stack_matrices(top_right=False):
    """M(0) and grad V(0) = g (c - lambda d) of the stack: the bottom on its left corner (theta_1,
    counterclockwise), the top on its left corner (theta_2, counterclockwise) or, with top_right,
    on its right corner (theta_2 clockwise, so that it opens for theta_2 > 0 too)."""
    b1, h1, m1, b2, h2, m2, g, lam = sp.symbols('b1 h1 m1 b2 h2 m2 g lambda', positive=True)
    t = sp.Symbol('t')
    T1, T2 = sp.Function('T1')(t), sp.Function('T2')(t)
    G1 = _rot((b1, h1), T1)                           # from the bottom's left corner
    if not top_right:
        P2 = _rot((b1 - b2, 2 * h1), T1)              # the top's left corner on the bottom
        G2 = P2 + _rot((b2, h2), T1 + T2)
    else:
        P2 = _rot((b1 + b2, 2 * h1), T1)              # the top's right corner
        G2 = P2 + _rot((-b2, h2), T1 - T2)
    I1, I2 = m1 * (b1 ** 2 + h1 ** 2) / 3, m2 * (b2 ** 2 + h2 ** 2) / 3
    Tk = m1 * G1.diff(t).dot(G1.diff(t)) / 2 + m2 * G2.diff(t).dot(G2.diff(t)) / 2 \
        + I1 * T1.diff(t) ** 2 / 2 + I2 * (T1.diff(t) + (-1 if top_right else 1) * T2.diff(t)) ** 2 / 2
    V = m1 * (g * G1[1] + lam * g * G1[0]) + m2 * (g * G2[1] + lam * g * G2[0])
    w1, w2 = sp.symbols('w1 w2')
    at0 = {T1.diff(t): 0, T2.diff(t): 0}
    Tq = Tk.subs({T1.diff(t): w1, T2.diff(t): w2})
    M = sp.Matrix(2, 2, lambda i, j: sp.diff(Tq, [w1, w2][i], [w1, w2][j]))
    M = sp.simplify(M.subs({T1: 0, T2: 0}))
    gradV = sp.Matrix([sp.diff(V, T1), sp.diff(V, T2)]).subs(at0).subs({T1: 0, T2: 0})
    gradV = sp.simplify(gradV)
    c = sp.simplify(gradV.subs(lam, 0) / g)
    d = sp.simplify(-(gradV - gradV.subs(lam, 0)) / (g * lam))
    return dict(sym=(b1, h1, m1, b2, h2, m2, g, lam), M=M, c=c, d=d)


def stack_thresholds():
    """The pattern boundaries in lambda = a/g, closed forms."""
    s = stack_matrices()
    sr = stack_matrices(top_right=True)
    M, c, d = s['M'], s['c'], s['d']
    lam_top = sp.simplify(c[1] / d[1])        # the top alone, from rest
    lam_one = sp.simplify(c[0] / d[0])        # both as one, from rest
    # top rocking, bottom held: Lambda_1 = (grad V)_1 - M12/M22 (grad V)_2 >= 0
    lam_top_both = sp.simplify((c[0] * M[1, 1] - M[0, 1] * c[1]) / (d[0] * M[1, 1] - M[0, 1] * d[1]))
    # both as one, interface held: Lambda_2 = (grad V)_2 - M21/M11 (grad V)_1 >= 0
    lam_one_both = sp.simplify((c[1] * M[0, 0] - M[1, 0] * c[0]) / (d[1] * M[0, 0] - M[1, 0] * d[0]))
    return dict(s=s, sr=sr, lam_top=lam_top, lam_one=lam_one, lam_top_both=lam_top_both,
                lam_one_both=lam_one_both)


def stack_checks():
    res = {}
    th = stack_thresholds()
    b1, h1, m1, b2, h2, m2, g, lam = th['s']['sym']
    res['stack_top_alone_threshold'] = sp.simplify(th['lam_top'] - b2 / h2) == 0
    res['stack_as_one_threshold'] = sp.simplify(
        th['lam_one'] - b1 * (m1 + m2) / (m1 * h1 + m2 * (2 * h1 + h2))) == 0
    # identical blocks rocking as one: the single block of twice the height, b/(2h)
    b, hh, mm = sp.symbols('b h m', positive=True)
    same = {b1: b, b2: b, h1: hh, h2: hh, m1: mm, m2: mm}
    res['stack_identical_as_one_is_twice_height'] = sp.simplify(
        th['lam_one'].subs(same) - b / (2 * hh)) == 0
    # top mass -> 0: the bottom alone, b1/h1
    res['stack_massless_top_is_bottom_alone'] = sp.simplify(
        th['lam_one'].subs(m2, 0) - b1 / h1) == 0
    # the top on its right corner: the bottom's row is the same system, the top's own row differs
    sr, sl = th['sr'], th['s']
    res['stack_right_pivot_same_bottom_row'] = (sp.simplify(sr['M'][0, 0] - sl['M'][0, 0]) == 0
                                                and sp.simplify(sr['c'][0] - sl['c'][0]) == 0
                                                and sp.simplify(sr['d'][0] - sl['d'][0]) == 0)
    res['stack_right_pivot_top_row'] = (
        sp.simplify(sr['M'][1, 1] - sl['M'][1, 1]) == 0
        and sp.simplify(sr['M'][0, 1] - sp.Rational(1, 3) * m2 * (3 * b1 * b2 - b2 ** 2 - 6 * h1 * h2
                                                                 - 4 * h2 ** 2)) == 0
        and sp.simplify(sr['c'][1] - b2 * m2) == 0 and sp.simplify(sr['d'][1] + h2 * m2) == 0)
    # the closed-form bands against the complementarity problem solved by enumeration: at each
    # lambda exactly one of the four patterns is consistent, and it is the closed forms' one; the
    # bands cover lambda >= 0 without overlap
    s = th['s']
    fMr = sp.lambdify(s['sym'][:7], th['sr']['M'].tolist(), 'math')
    fcr = sp.lambdify(s['sym'][:7], th['sr']['c'].tolist(), 'math')
    fdr = sp.lambdify(s['sym'][:7], th['sr']['d'].tolist(), 'math')
    fM = sp.lambdify(s['sym'][:7], s['M'].tolist(), 'math')
    fc = sp.lambdify(s['sym'][:7], s['c'].tolist(), 'math')
    fd = sp.lambdify(s['sym'][:7], s['d'].tolist(), 'math')
    rng = random.Random(7)
    bad = []
    seen = set()
    for _ in range(300):
        x = [rng.uniform(0.1, 1), rng.uniform(0.2, 3), rng.uniform(0.1, 10), 0.0,
             rng.uniform(0.2, 3), rng.uniform(0.1, 10), 1.0]
        x[3] = rng.uniform(0.05, 1) * x[0]
        M = [list(map(float, row)) for row in fM(*x)]
        c = [float(v[0]) for v in fc(*x)]
        d = [float(v[0]) for v in fd(*x)]
        Mr = [list(map(float, row)) for row in fMr(*x)]
        cr = [float(v[0]) for v in fcr(*x)]
        dr = [float(v[0]) for v in fdr(*x)]
        bands = stack_bands_numeric(M, c, d, Mr, cr, dr)
        det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
        detr = Mr[0][0] * Mr[1][1] - Mr[0][1] * Mr[1][0]
        for k in range(1, 400):
            lam_v = 0.01 * k
            gv = [c[0] - lam_v * d[0], c[1] - lam_v * d[1]]
            ok = []
            if gv[0] >= 0 and gv[1] >= 0:
                ok.append('rest')
            a2 = -gv[1] / M[1][1]
            if a2 > 0 and M[0][1] * a2 + gv[0] >= 0:
                ok.append('top')
            gr = [cr[0] - lam_v * dr[0], cr[1] - lam_v * dr[1]]
            a1 = -gv[0] / M[0][0]
            if a1 > 0 and M[1][0] * a1 + gv[1] >= 0 and Mr[1][0] * a1 + gr[1] >= 0:
                ok.append('one')
            b1_ = -(M[1][1] * gv[0] - M[0][1] * gv[1]) / det
            b2_ = -(M[0][0] * gv[1] - M[1][0] * gv[0]) / det
            if b1_ > 0 and b2_ > 0:
                ok.append('both')
            r1_ = -(Mr[1][1] * gr[0] - Mr[0][1] * gr[1]) / detr
            r2_ = -(Mr[0][0] * gr[1] - Mr[1][0] * gr[0]) / detr
            if r1_ > 0 and r2_ > 0:
                ok.append('both_opposite')
            want = [p for p, (lo, hi) in bands.items() if lo <= lam_v < hi]
            near = any(abs(lam_v - e) < 1e-9 for iv in bands.values() for e in iv)
            if (len(ok) != 1 or ok != want) and not near:
                bad.append((x, lam_v, ok, want))
                break
            seen.add(ok[0] if ok else '-')
    if seen != {'rest', 'top', 'one', 'both', 'both_opposite'}:
        bad.append(('patterns seen', sorted(seen)))
    res['stack_bands_unique_pattern'] = bad
    return res


def stack_bands_numeric(M, c, d, Mr, cr, dr):
    """The band of lambda over which each pattern is consistent, from four linear functions of
    lambda (g = 1): f1 = c1 - lambda d1 and f2 = c2 - lambda d2 (the rest multipliers of the floor
    and the interface), F1 = M22 f1 - M12 f2 and F2 = M11 f2 - M21 f1 (M22 times the floor's
    multiplier while the top alone rocks, = -det M times the bottom's acceleration when both rock
    separately; F2 likewise for the interface). rest: f1 >= 0, f2 >= 0; top: f2 < 0 <= F1;
    one: f1 < 0 <= F2; both: F1 < 0, F2 < 0. Each is an interval (lo, hi)."""
    inf = float('inf')
    lin = dict(f1=(c[0], -d[0]), f2=(c[1], -d[1]),
               F1=(M[1][1] * c[0] - M[0][1] * c[1], -(M[1][1] * d[0] - M[0][1] * d[1])),
               F2=(M[0][0] * c[1] - M[1][0] * c[0], -(M[0][0] * d[1] - M[1][0] * d[0])),
               G1=(Mr[1][1] * cr[0] - Mr[0][1] * cr[1], -(Mr[1][1] * dr[0] - Mr[0][1] * dr[1])),
               G2=(Mr[0][0] * cr[1] - Mr[1][0] * cr[0], -(Mr[0][0] * dr[1] - Mr[1][0] * dr[0])))

    def where(name, nonneg):
        a0, a1 = lin[name]
        if a1 == 0:
            return (-inf, inf) if (a0 >= 0) == nonneg else (inf, inf)
        root = -a0 / a1
        return (-inf, root) if (a1 < 0) == nonneg else (root, inf)

    def meet(*iv):  # noqa: E306
        lo = max(x[0] for x in iv)
        hi = min(x[1] for x in iv)
        return (max(lo, 0.0), hi) if lo < hi else (inf, inf)

    return dict(rest=meet(where('f1', True), where('f2', True)),
                top=meet(where('f2', False), where('F1', True)),
                one=meet(where('f1', False), where('F2', True), where('G2', True)),
                both=meet(where('F1', False), where('F2', False)),
                both_opposite=meet(where('G1', False), where('G2', False)))


def stack_forms_text():
    th = stack_thresholds()
    s = th['s']
    return dict(M=s['M'], c=s['c'], d=s['d'], lam_top_both=th['lam_top_both'],
                lam_one_both=th['lam_one_both'])


def checks():
    res = frame_checks()
    res.update(stack_checks())
    return res, dict(frames=frame_reference())


if __name__ == '__main__':
    r, refs = checks()
    for k, v in r.items():
        print(k, v)
    for k, v in stack_forms_text().items():
        print(k, '=', v)
    print(refs)
