# SPDX-License-Identifier: BSD-3-Clause
"""A rigid block on a support that moves with it (docs/theory.md §24).

The support, of mass m_s, is driven by the ground X(t) through a horizontal spring k and dashpot
c; its displacement relative to the ground is u. The block (n = 0: mass M, c.g. height h, edges
at b1, b2, radius of gyration zeta^2 h^2 about the c.g.) stands on the support and rocks about a
tipping point that moves with it. The vertical is rigid: the support carries the ground's
Y(t) (a_y = 1 + Y''/g).

Checked here:
  * Lagrange's equations of T - V in (u, theta) with the dashpot's generalised force equal the
    closed form the engine uses (src/sim/support_sim.cpp): the 2 x 2 mass matrix
    [[M + m_s, M h C_x], [M h C_x, M h^2 (1 + zeta^2 + alpha^2)]] and its right-hand side;
  * with u == 0 the theta-row is the rigid floor's (§11); the floor's force on the block, and the
    support's row as m_s (X'' + u'') = -k u - c u' - F_x;
  * the energy rate: d/dt (T_rel + V) = -c u'^2 - (input power), the input power being the base
    acceleration's work on the relative momenta;
  * the impact map at theta = 0 (pivot pre -> landing corner post): the linear momentum of
    block + support and the block's moment of momentum about the landing corner, checked mass by
    mass on random bodies of point masses (exact rationals), the loss >= 0 and its closed form;
    the both-edges map (theta_dot+ = 0) from the linear momentum;
  * the limits of the map: m_s -> infinity gives Housner's ratio (the rigid floor), m_s -> 0 the
    block on a massless support (no horizontal impulse);
  * the full-contact threshold: the support in full contact is an SDOF of mass M + m_s; its
    steady absolute acceleration under X'' = A sin(w t) is |T(r)| A with the transmissibility
    T(r) = (1 + 2 i zeta r)/(1 - r^2 + 2 i zeta r), so the first uplift needs
    A >= g min(alpha_1, alpha_2)/|T(r)| (a_y = 1).
Returns (checks, refs): refs holds reference numbers for the C++ tests."""

import random

import sympy as sp


def _rigid_points(rng, n_pts=7):
    """A random rigid planar body of point masses (exact rationals): masses, positions relative to
    its c.g., and M, zeta^2 h^2 (I/M) about the c.g."""
    ms = [sp.Rational(rng.randint(1, 9), rng.randint(1, 5)) for _ in range(n_pts)]
    xs = [sp.Rational(rng.randint(-20, 20), 10) for _ in range(n_pts)]
    ys = [sp.Rational(rng.randint(-20, 20), 10) for _ in range(n_pts)]
    M = sum(ms)
    xc = sum(m * x for m, x in zip(ms, xs)) / M
    yc = sum(m * y for m, y in zip(ms, ys)) / M
    pts = [(m, x - xc, y - yc) for m, x, y in zip(ms, xs, ys)]
    J = sum(m * (x * x + y * y) for m, x, y in pts)
    return pts, M, J


def impact_map(M, ms, h, zeta2, a_pre, a_post, thd, ud):
    """The closed form: theta_dot+ and u_dot+ of an impact at theta = 0 landing on the corner of
    alpha_post, the block rocking before about the corner of alpha_pre (u_dot relative to the
    ground; the ground's velocity is continuous). With chi = M/(M + m_s):
      theta_dot+ / theta_dot- = (1 + zeta^2 + alpha_pre alpha_post - chi)/(1 + zeta^2 + alpha_post^2 - chi)
      u_dot+ = u_dot- + chi h (theta_dot+ - theta_dot-)."""
    chi = M / (M + ms)
    r = (1 + zeta2 + a_pre * a_post - chi) / (1 + zeta2 + a_post**2 - chi)
    thp = r * thd
    return thp, ud + chi * h * (thp - thd)


def support_checks():
    res = {}
    refs = {}
    t = sp.Symbol('t')
    M, ms, h, z2, g, k, c = sp.symbols('M m_s h zeta2 g k c', positive=True)
    al = sp.Symbol('alpha', real=True)
    X = sp.Function('X')(t)
    Y = sp.Function('Y')(t)
    u = sp.Function('u')(t)
    th = sp.Function('theta')(t)
    s, co = sp.sin(th), sp.cos(th)
    # c.g. of the block: pivot at X + u + h alpha, r1 = h(-alpha i + j) (§1)
    xcg = X + u + h * al - h * al * co - h * s
    ycg = Y + h * (co - al * s)
    T = (ms * sp.diff(X + u, t)**2 + M * (sp.diff(xcg, t)**2 + sp.diff(ycg, t)**2)
         + M * z2 * h**2 * sp.diff(th, t)**2) / 2
    V = k * u**2 / 2 + M * g * ycg
    L = T - V
    Q = {u: -c * sp.diff(u, t), th: 0}
    EL = {}
    for qq in (u, th):
        EL[qq] = sp.diff(sp.diff(L, sp.diff(qq, t)), t) - sp.diff(L, qq) - Q[qq]
    # the engine's closed form
    ud, thd, udd, thdd, Xdd, Ydd = sp.symbols('ud thd udd thdd Xdd Ydd')
    Cx = al * s - co
    Cy = -s - al * co
    Cxp = al * co + s
    sub = {sp.diff(u, t, 2): udd, sp.diff(th, t, 2): thdd, sp.diff(X, t, 2): Xdd,
           sp.diff(Y, t, 2): Ydd, sp.diff(u, t): ud, sp.diff(th, t): thd}

    def subs(e):
        return e.subs(sub)

    row_u = (M + ms) * udd + M * h * Cx * thdd + (M + ms) * Xdd + c * ud + k * u + M * h * Cxp * thd**2
    row_th = M * h * Cx * udd + M * h**2 * (1 + z2 + al**2) * thdd + M * h * Cx * Xdd + M * h * Cy * (g + Ydd)
    res['rocking rows from Lagrange'] = (sp.simplify(subs(EL[u]) - row_u) == 0
                                         and sp.simplify(subs(EL[th]) - row_th) == 0)
    # u == 0: the rigid floor's theta-row (§11, edge 1: alpha = -alpha_1)
    a1, ax, ay = sp.symbols('alpha_1 a_x a_y', positive=True)
    thdd_floor = sp.solve(row_th.subs({udd: 0, al: -a1, Xdd: g * ax, Ydd: g * (ay - 1)}), thdd)[0]
    s11 = (g / h) * (ay * (s - a1 * co) + ax * (co + a1 * s)) / (1 + z2 + a1**2)
    res['rigid floor limit of the theta-row'] = sp.simplify(thdd_floor - s11) == 0
    # the floor's force on the block F = M (r_cg'' + g J), and the support's row
    Fx = M * subs(sp.diff(xcg, t, 2))
    Fy = M * (subs(sp.diff(ycg, t, 2)) + g)
    res['support row is m_s (X + u)\'\' = -k u - c u\' - F_x'] = sp.simplify(
        row_u - (ms * (Xdd + udd) + k * u + c * ud + Fx)) == 0
    # the energy rate relative to the ground: E = T_rel + V_rel with the relative velocities, the
    # input power -X'' (m_s u' + M v_x) - Y'' M v_y (the d'Alembert force's work)
    vx = sp.diff(xcg - X, t)
    vy = sp.diff(ycg - Y, t)
    E = (ms * sp.diff(u, t)**2 + M * (vx**2 + vy**2) + M * z2 * h**2 * sp.diff(th, t)**2) / 2 \
        + k * u**2 / 2 + M * g * (ycg - Y)
    P_in = -sp.diff(X, t, 2) * (ms * sp.diff(u, t) + M * vx) - sp.diff(Y, t, 2) * M * vy
    dE = sp.diff(E, t)
    # on the motion: replace u'' and theta'' by the solution of the two rows
    sol = sp.solve([row_u, row_th], [udd, thdd], dict=True)[0]
    rate = subs(dE) - subs(P_in) + c * ud**2
    res['energy rate = input - dashpot'] = sp.simplify(rate.subs(sol)) == 0
    # the vertical reaction used for the flight guard (its closed form in the engine)
    Fy_closed = M * (g + Ydd) + M * h * (Cy * thdd - (co - al * s) * thd**2)
    res['vertical reaction closed form'] = sp.simplify(Fy - Fy_closed) == 0

    # impact maps, mass by mass on random bodies
    rng = random.Random(2024)
    fails = []
    losses = []
    for trial in range(12):
        pts, Mb, J = _rigid_points(rng)
        hh = sp.Rational(rng.randint(5, 30), 10)  # c.g. height above the base
        b1 = sp.Rational(rng.randint(1, 20), 10)
        b2 = sp.Rational(rng.randint(1, 20), 10)
        msv = sp.Rational(rng.randint(0, 40), rng.randint(1, 4))
        zeta2 = J / (Mb * hh**2)
        for landing in (1, 2):
            a_pre = b2 / hh if landing == 1 else -b1 / hh
            a_post = -b1 / hh if landing == 1 else b2 / hh
            # landing on edge 1 the block comes down from edge 2 turning positively (§8)
            thm = sp.Rational(rng.randint(1, 30), 10) * (1 if landing == 1 else -1)
            udm = sp.Rational(rng.randint(-20, 20), 10)
            thp, udp = impact_map(Mb, msv, hh, zeta2, a_pre, a_post, thm, udm)
            # velocities of each mass: base velocity u_dot (relative to the ground; the ground's
            # velocity is continuous and drops out), rotation about the pivot; positions at theta=0
            piv_pre = sp.Matrix([hh * a_pre, 0])
            piv_post = sp.Matrix([hh * a_post, 0])

            def vel(p, pivot, thdot, udot):
                r = sp.Matrix([p[0], p[1] + hh]) - pivot  # from the pivot (c.g. at (0, h))
                return sp.Matrix([udot - thdot * r[1], thdot * r[0]])

            Px_m = msv * udm + sum(m * vel((x, y), piv_pre, thm, udm)[0] for m, x, y in pts)
            Px_p = msv * udp + sum(m * vel((x, y), piv_post, thp, udp)[0] for m, x, y in pts)

            def H(pivot_vel, thdot, udot):
                tot = 0
                for m, x, y in pts:
                    r = sp.Matrix([x, y + hh]) - piv_post
                    v = vel((x, y), pivot_vel, thdot, udot)
                    tot += m * (r[0] * v[1] - r[1] * v[0])
                return tot

            Hm = H(piv_pre, thm, udm)
            Hp = H(piv_post, thp, udp)
            Tm = (msv * udm**2 + sum(m * (vel((x, y), piv_pre, thm, udm).dot(vel((x, y), piv_pre, thm, udm)))
                                     for m, x, y in pts)) / 2
            Tp = (msv * udp**2 + sum(m * (vel((x, y), piv_post, thp, udp).dot(vel((x, y), piv_post, thp, udp)))
                                     for m, x, y in pts)) / 2
            loss = sp.nsimplify(Tm - Tp)
            # the closed form of the loss: the kinetic energy of the jump in the system's metric
            chi = Mb / (Mb + msv)
            r_single = (1 + zeta2 + a_pre * a_post - chi) / (1 + zeta2 + a_post**2 - chi)
            if sp.simplify(Px_m - Px_p) != 0:
                fails.append(('linear momentum', trial, landing))
            if sp.simplify(Hm - Hp) != 0:
                fails.append(('moment of momentum', trial, landing))
            if r_single > 0 and loss < 0:
                fails.append(('energy gain', trial, landing, float(loss)))
            losses.append(float(loss / Tm) if Tm != 0 else 0.0)
            # both edges: theta_dot+ = 0, the block moving with the support, from the linear momentum
            udp0 = udm - chi * hh * thm
            Px_0 = (msv + Mb) * udp0
            if sp.simplify(Px_0 - Px_m) != 0:
                fails.append(('both-edges momentum', trial, landing))
            T0 = (msv + Mb) * udp0**2 / 2
            if T0 > Tm:
                fails.append(('both-edges energy gain', trial, landing))
            if trial < 4:  # 8 impacts (both landing edges) for the C++ test
                refs.setdefault('impacts', []).append({
                    'M': float(Mb), 'm_s': float(msv), 'h': float(hh), 'b1': float(b1), 'b2': float(b2),
                    'zeta2': float(zeta2), 'landing_edge': landing, 'theta_dot_minus': float(thm),
                    'u_dot_minus': float(udm), 'theta_dot_plus': float(thp), 'u_dot_plus': float(udp),
                    'energy_loss': float(loss)})
    res['impact map momenta mass by mass (24 impacts)'] = fails
    res['impact losses >= 0'] = all(x >= -1e-15 for x in losses)
    # limits of the map
    Ms, z, ap, aq = sp.symbols('M_s zeta2 a_pre a_post')
    r_sym = (1 + z + ap * aq - M / (M + Ms)) / (1 + z + aq**2 - M / (M + Ms))
    res['m_s -> oo: Housner ratio'] = sp.simplify(sp.limit(r_sym, Ms, sp.oo) - (1 + z + ap * aq) / (1 + z + aq**2)) == 0
    res['m_s -> 0: no horizontal impulse'] = sp.simplify(r_sym.subs(Ms, 0) - (z + ap * aq) / (z + aq**2)) == 0
    # transmissibility of the support's absolute acceleration (full contact, SDOF of mass M + m_s)
    w, A, zt, wn = sp.symbols('omega A zeta_h omega_n', positive=True)
    mt = M + ms
    uu = sp.Symbol('U')  # complex amplitude: u = U e^{i w t}, X'' = A e^{i w t}
    Usol = sp.solve(mt * (-w**2) * uu + 2 * zt * wn * mt * sp.I * w * uu + wn**2 * mt * uu + mt * A, uu)[0]
    Tr = sp.simplify((A - w**2 * Usol) / A)
    r = w / wn
    Tclosed = (1 + 2 * sp.I * zt * r) / (1 - r**2 + 2 * sp.I * zt * r)
    res['transmissibility'] = sp.simplify(Tr - Tclosed) == 0
    return res, refs


if __name__ == '__main__':
    import json
    out, refs = support_checks()
    print(out)
    print(json.dumps(refs, indent=1))
