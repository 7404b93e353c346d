#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Derivation and reference values for flexrock (Moran & McLennan 1995 model).

Part (a): symbolic, general body.  A generic material point (rho_x, rho_y,
phi_kx, phi_ky) is moved with the rocking kinematics; |Rdot|^2, gravity,
momenta, moments are expanded as polynomials in the material-point symbols and
each monomial's mass integral is replaced by the linear functional fixed by the
parameter definitions (M, zeta2, mu, gamma, psi, delta, beta).  Integrals not
fixed by the parameters get auxiliary symbols (Jxx, Jxy, Dxx_k, Dxy_k, Pxx_ij,
Sxy_ij); the script checks that they cancel.  Lagrange's equations, the floor
reaction, the resultant, the impact map, the energy identities and the uplift
identity are derived and compared with the closed forms used by the C++ code
("conventions", implemented in conv_* below) by exact polynomial reduction
modulo cos^2+sin^2-1.  For n <= --symbolic-flight-n (default 2) the same is done
for free flight in the c.g. coordinates (x_c, y_c, theta, q), for lift-off (the
rocking and flight descriptions of one motion; rocking = flight + the floor
reaction at the corner), for plastic landing on a corner at any tilt (general
alpha_e) and for the flat landing; and Coulomb friction: Lagrange's equations in (d, theta, q)
with the pivot (or the base) sliding, the floor force, the resultant and the energy rate of the
sliding modes, and the impact of a corner that may slide afterwards (plus rigid-block closed forms).

Part (b): numeric, realizable bodies.  Random discrete bodies (point masses,
massless tipping points at base level so phi = 0 there), parameters computed by
their definitions as sums; T, V, reaction, resultant, impacts computed DIRECTLY
from the point masses (per-mass Lagrange terms derived symbolically with sin/cos
and summed) in 30-digit mpmath, compared with the closed forms (assert 1e-12).
Flight uses its own per-mass kernel in the coordinates (u, v, theta, q) of the
base point O'; landings are solved from the momentum balances over the masses
and checked against the closed forms and against A_f dnu = J_e^T Lambda.  Friction: the sliding
modes' accelerations solved from the masses' rows and Coulomb's law, energy rates with the friction
power, impacts with Coulomb's law on the impulse (stick or slip, loss >= 0), the rigid block's regime
at initiation (every candidate mode tried) and pure sliding under pulses (exact piecewise solution
against a fixed-step integration).

Usage:  derive.py --out FILE.json [--seed 12345] [--print]
"""
import argparse
import json
import os
import sys
import time

import mpmath as mp
import numpy as np
import sympy as sp

import support
import assemblies
import os as _os
sys.path.insert(0, _os.path.dirname(_os.path.abspath(__file__)))
import axisymmetric3d  # noqa: E402  (the 3D body of revolution, docs/theory.md §27)

G_STD = 9.80665
mp.mp.dps = 30

# ---------------------------------------------------------------------------
# Closed forms used by the code (backend-agnostic: sympy expressions or mpf)
# P: dict with n, M, h, zeta2, mu, kappa, gamma, psi_x, psi_y, delta, beta
# ---------------------------------------------------------------------------


def dot(a, b):
    return sum((x * y for x, y in zip(a, b)), 0)


def matvec(A, v):
    return [dot(row, v) for row in A]


def conv_w(P, alpha, q):
    return (-alpha + dot(P['psi_x'], q), 1 + dot(P['psi_y'], q))


def conv_c(P, alpha, q):
    muq = matvec(P['mu'], q)
    return [P['delta'][j] - alpha * P['psi_x'][j] + P['psi_y'][j] + muq[j]
            for j in range(P['n'])]


def conv_b(P, alpha, q):
    n = P['n']
    return [P['beta'][j] + sum((P['gamma'][i][j] * q[i] for i in range(n)), 0)
            - alpha * P['psi_y'][j] - P['psi_x'][j] for j in range(n)]


def conv_A(P, alpha, q):
    n = P['n']
    m = (1 + P['zeta2'] + alpha ** 2
         + 2 * dot([P['delta'][j] - alpha * P['psi_x'][j] + P['psi_y'][j] for j in range(n)], q)
         + dot(q, matvec(P['mu'], q)))
    b = conv_b(P, alpha, q)
    A = [[m] + list(b)]
    for j in range(n):
        A.append([b[j]] + list(P['mu'][j]))
    return A


def conv_G(ax, ay, s, c):
    return (ax * c + ay * s, ay * c - ax * s)


def conv_f(P, alpha, q, thd, qd, s, c, ax, ay, g):
    n, h = P['n'], P['h']
    w = conv_w(P, alpha, q)
    G = conv_G(ax, ay, s, c)
    cc = conv_c(P, alpha, q)
    f = [-2 * dot(cc, qd) * thd - (g / h) * (w[0] * G[1] - w[1] * G[0])]
    kq = matvec(P['kappa'], q)
    for j in range(n):
        gq = sum((P['gamma'][i][j] * qd[i] for i in range(n)), 0)
        f.append(-2 * thd * gq + thd ** 2 * cc[j]
                 - (g / h) * (kq[j] + P['psi_x'][j] * G[0] + P['psi_y'][j] * G[1]))
    return f


def kx(v):
    return (-v[1], v[0])


def conv_F_body(P, alpha, q, thd, qd, thdd, qdd, s, c, ax, ay, g):
    h, M = P['h'], P['M']
    w = conv_w(P, alpha, q)
    G = conv_G(ax, ay, s, c)
    pq = (dot(P['psi_x'], qd), dot(P['psi_y'], qd))
    pqq = (dot(P['psi_x'], qdd), dot(P['psi_y'], qdd))
    kw, kp = kx(w), kx(pq)
    return tuple(M * g * (G[i] + (h / g) * (pqq[i] + thdd * kw[i] + 2 * thd * kp[i] - thd ** 2 * w[i]))
                 for i in range(2))


def body_to_inertial(v, s, c):
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def conv_alpha_star_parts(P, q, qdd, ax, ay, g):
    """returns (numerator, denominator) of alpha_star."""
    n, h = P['n'], P['h']
    bq = [P['beta'][j] + sum((P['gamma'][i][j] * q[i] for i in range(n)), 0) - P['psi_x'][j]
          for j in range(n)]
    num = dot(bq, qdd) * (h / g) + ay * dot(P['psi_x'], q) - ax * (1 + dot(P['psi_y'], q))
    den = ay + dot(P['psi_y'], qdd) * (h / g)
    return num, den


def conv_impact_system(P, a_pre, a_post, q, thdm, qdm):
    """A_post nu+ = rhs."""
    A = conv_A(P, a_post, q)
    nu = [thdm] + list(qdm)
    rhs = matvec(A, nu)
    w = conv_w(P, a_post, q)
    d = a_pre - a_post
    rhs[0] -= d * thdm * w[0]
    for j in range(P['n']):
        rhs[j + 1] -= d * thdm * P['psi_y'][j]
    return A, rhs


def conv_impulse(P, a_pre, a_post, q, thdm, qdm, thdp, qdp):
    M, h = P['M'], P['h']
    dq = [a - b for a, b in zip(qdp, qdm)]
    kwp, kwm = kx(conv_w(P, a_post, q)), kx(conv_w(P, a_pre, q))
    return tuple(M * h * (dot(P['psi_x' if i == 0 else 'psi_y'], dq) + thdp * kwp[i] - thdm * kwm[i])
                 for i in range(2))


def conv_Trel(P, alpha, q, thd, qd):
    A = conv_A(P, alpha, q)
    nu = [thd] + list(qd)
    return P['M'] * P['h'] ** 2 * dot(nu, matvec(A, nu)) / 2


def conv_V(P, alpha, q, s, c, g):
    w = conv_w(P, alpha, q)
    return P['M'] * g * P['h'] * (s * w[0] + c * w[1] + dot(q, matvec(P['kappa'], q)) / 2)


def conv_vcm_body(P, alpha, q, thd, qd):
    w = conv_w(P, alpha, q)
    kw = kx(w)
    return (P['h'] * (dot(P['psi_x'], qd) + thd * kw[0]), P['h'] * (dot(P['psi_y'], qd) + thd * kw[1]))


# --- flight, lift-off and landing (docs/theory.md, Flight / Landing) -------------------------
# Flight coordinates: (x_c, y_c) the deformed c.g. relative to the base origin, theta, q.
# vt = R(theta)^T v_c / h: the c.g. velocity relative to the base, body components, over h.


def conv_B(P, alpha, q):
    """c.g. velocity Jacobian about the point h(alpha, 0) of the base line (body components,
    over h): v_cm = h B nu.  Rows x, y; columns theta, q_1..q_n."""
    kw = kx(conv_w(P, alpha, q))
    return [[kw[0]] + list(P['psi_x']), [kw[1]] + list(P['psi_y'])]


def conv_Gamma(P):
    n = P['n']
    return [[P['gamma'][i][j] + P['psi_y'][i] * P['psi_x'][j] - P['psi_x'][i] * P['psi_y'][j]
             for j in range(n)] for i in range(n)]


def conv_c_cg(P, q):
    n = P['n']
    px, py = dot(P['psi_x'], q), dot(P['psi_y'], q)
    muq = matvec(P['mu'], q)
    return [P['delta'][j] + muq[j] - px * P['psi_x'][j] - py * P['psi_y'][j] for j in range(n)]


def conv_A_cg(P, q):
    """inertia about the deformed c.g. over M h^2 (Koenig): [[m_cg, b_cg^T], [b_cg, mu_cg]]."""
    n = P['n']
    px, py = dot(P['psi_x'], q), dot(P['psi_y'], q)
    m = P['zeta2'] + 2 * dot(P['delta'], q) + dot(q, matvec(P['mu'], q)) - px ** 2 - py ** 2
    Gm = conv_Gamma(P)
    b = [P['beta'][j] + sum((Gm[i][j] * q[i] for i in range(n)), 0) for j in range(n)]
    A = [[m] + b]
    for i in range(n):
        A.append([b[i]] + [P['mu'][i][j] - P['psi_x'][i] * P['psi_x'][j] - P['psi_y'][i] * P['psi_y'][j]
                           for j in range(n)])
    return A


def conv_f_flight(P, q, thd, qd, g):
    """A_cg [thdd; qdd] = f (no gravity: a uniform field does not act on the motion about the c.g.)."""
    n, h = P['n'], P['h']
    cc = conv_c_cg(P, q)
    Gm = conv_Gamma(P)
    kq = matvec(P['kappa'], q)
    f = [-2 * dot(cc, qd) * thd]
    for j in range(n):
        gq = sum((Gm[i][j] * qd[i] for i in range(n)), 0)
        f.append(thd * (thd * cc[j] - 2 * gq) - (g / h) * kq[j])
    return f


def conv_cg_acc_flight(Xdd, Ydd, g):
    """c.g. acceleration relative to the base (inertial components): ballistic."""
    return (-Xdd, -g - Ydd)


def conv_T_flight(P, q, vc, thd, qd):
    """T_rel = 1/2 M |v_c|^2 + 1/2 M h^2 nu^T A_cg nu (v_c relative to the base)."""
    A = conv_A_cg(P, q)
    nu = [thd] + list(qd)
    return P['M'] * (vc[0] ** 2 + vc[1] ** 2) / 2 + P['M'] * P['h'] ** 2 * dot(nu, matvec(A, nu)) / 2


def conv_V_flight(P, yc, q, g):
    return P['M'] * g * yc + P['M'] * g * P['h'] * dot(q, matvec(P['kappa'], q)) / 2


def conv_corner(P, alpha_e, xc, yc, q, s, c):
    """corner position relative to the base origin: c.g. + h R(theta) [(alpha_e, 0) - w0]."""
    w0 = conv_w(P, 0, q)
    r = body_to_inertial((alpha_e - w0[0], -w0[1]), s, c)
    return (xc + P['h'] * r[0], yc + P['h'] * r[1])


def conv_corner_vel(P, alpha_e, q, vc, thd, qd, s, c):
    """v_e = v_c - h R(theta) B_e nu (B_e = conv_B at alpha_e)."""
    B = conv_B(P, alpha_e, q)
    nu = [thd] + list(qd)
    r = body_to_inertial((dot(B[0], nu), dot(B[1], nu)), s, c)
    return (vc[0] - P['h'] * r[0], vc[1] - P['h'] * r[1])


def conv_corner_acc(P, alpha_e, q, ac, thd, qd, thdd, qdd, s, c):
    """corner acceleration: y_e = y_c + h [s a - c b], a = alpha_e - psi_x.q, b = 1 + psi_y.q."""
    h = P['h']
    a, b = alpha_e - dot(P['psi_x'], q), 1 + dot(P['psi_y'], q)
    ad, bd = -dot(P['psi_x'], qd), dot(P['psi_y'], qd)
    add, bdd = -dot(P['psi_x'], qdd), dot(P['psi_y'], qdd)
    # x_e = x_c + h [c a + s b]
    ax = ac[0] + h * (thdd * (-s * a + c * b) - thd ** 2 * (c * a + s * b) + 2 * thd * (-s * ad + c * bd)
                      + c * add + s * bdd)
    ay = ac[1] + h * (thdd * (c * a + s * b) + thd ** 2 * (-s * a + c * b) + 2 * thd * (c * ad + s * bd)
                      + s * add - c * bdd)
    return (ax, ay)


def conv_liftoff(P, alpha_e, xP, q, thd, qd, s, c):
    """rocking on the edge alpha_e with pivot at xP -> flight: (x_c, y_c), v_c (relative to the base)."""
    h = P['h']
    w = conv_w(P, alpha_e, q)
    r = body_to_inertial(w, s, c)
    v = body_to_inertial(conv_vcm_body(P, alpha_e, q, thd, qd), s, c)
    return (xP + h * r[0], h * r[1]), v


def conv_landing_system(P, alpha_e, q, vt, thd, qd):
    """plastic landing on the corner alpha_e (sticks): A(alpha_e) nu+ = rhs = A_cg nu- + B_e^T vt-,
    rhs = [H_P-; p-] / (M h^2): angular momentum about the corner and the modal momenta."""
    n = P['n']
    Acg = conv_A_cg(P, q)
    nu = [thd] + list(qd)
    rhs = matvec(Acg, nu)
    B = conv_B(P, alpha_e, q)
    for i in range(n + 1):
        rhs[i] += B[0][i] * vt[0] + B[1][i] * vt[1]
    return conv_A(P, alpha_e, q), rhs


def conv_landing_impulse(P, alpha_e, q, vt, thdp, qdp, s, c):
    """impulse on the body (inertial components): M (v_c+ - v_c-), v_c+ = h R B_e nu+."""
    B = conv_B(P, alpha_e, q)
    nu = [thdp] + list(qdp)
    d = (dot(B[0], nu) - vt[0], dot(B[1], nu) - vt[1])
    r = body_to_inertial(d, s, c)
    return (P['M'] * P['h'] * r[0], P['M'] * P['h'] * r[1])


def conv_landing_loss(P, q, vt_m, nu_m, vt_p, nu_p):
    """E = 1/2 M h^2 (|vt- - vt+|^2 + (nu- - nu+)^T A_cg (nu- - nu+)) >= 0 (the jump's own kinetic
    energy: the impulse does no work on the post-impact velocities)."""
    Acg = conv_A_cg(P, q)
    dn = [a - b for a, b in zip(nu_m, nu_p)]
    dv = (vt_m[0] - vt_p[0], vt_m[1] - vt_p[1])
    return P['M'] * P['h'] ** 2 * (dv[0] ** 2 + dv[1] ** 2 + dot(dn, matvec(Acg, dn))) / 2


def conv_flat_landing_rhs(P, q, vt, thd, qd):
    """flat landing: theta_dot+ = 0, base stuck, mu qd+ = p- / (M h^2) = psi^T vt + b_cg thd + mu_cg qd."""
    return conv_landing_system(P, 0, q, vt, thd, qd)[1][1:]


# --- Coulomb friction: sliding and impacts with friction (docs/theory.md, Sliding) ------------
# d: offset of the base along I relative to the floor (the pivot at X + d + h alpha); sg = +-1 the
# slip sign (sign of d_dot); mu_k kinetic, mu_s static friction coefficients.


def conv_e_I(s, c):
    """the inertial unit vector I in body components."""
    return (c, -s)


def conv_dfdax(P, alpha, q, s, c, g):
    """d f / d a_x = -(g/h) B^T e_I: the sliding acceleration enters the rocking rows as a_x + d_ddot/g."""
    B = conv_B(P, alpha, q)
    e = conv_e_I(s, c)
    return [-(g / P['h']) * (B[0][i] * e[0] + B[1][i] * e[1]) for i in range(P['n'] + 1)]


def conv_T_slide(P, alpha, q, thd, qd, dd, s, c):
    """kinetic energy relative to the floor: T_rel + M d_dot v_cm,I + 1/2 M d_dot^2."""
    vin = body_to_inertial(conv_vcm_body(P, alpha, q, thd, qd), s, c)
    return conv_Trel(P, alpha, q, thd, qd) + P['M'] * dd * vin[0] + P['M'] * dd ** 2 / 2


def conv_L(P, alpha_e, q, V):
    """L(V) = (1/h) [w_e x V ; psi . V], V a velocity of the tipping point (body components)."""
    w = conv_w(P, alpha_e, q)
    return [(w[0] * V[1] - w[1] * V[0]) / P['h']] + [(P['psi_x'][j] * V[0] + P['psi_y'][j] * V[1]) / P['h']
                                                     for j in range(P['n'])]


# ---------------------------------------------------------------------------
# Part (a): symbolic derivation for a general body
# ---------------------------------------------------------------------------

S, C = sp.symbols('s c')  # sin(theta), cos(theta)
TRIG = C ** 2 + S ** 2 - 1


def is_zero(expr):
    e = sp.expand(sp.together(sp.expand(expr)))
    num, den = sp.fraction(e)
    num = sp.expand(num)
    if num == 0:
        return True
    if num.has(C):
        num = sp.rem(num, TRIG, C)
    return sp.expand(num) == 0


class General:
    def __init__(self, n):
        self.n = n
        self.M, self.h, self.g = sp.symbols('M h g', positive=True)
        self.alpha, self.zeta2 = sp.symbols('alpha zeta2')
        self.thd, self.thdd = sp.symbols('thd thdd')
        self.Xd, self.Yd, self.Xdd, self.Ydd, self.Y = sp.symbols('Xd Yd Xdd Ydd Y')
        r = range(1, n + 1)
        self.q = [sp.Symbol('q%d' % k) for k in r]
        self.qd = [sp.Symbol('qd%d' % k) for k in r]
        self.qdd = [sp.Symbol('qdd%d' % k) for k in r]
        self.psi_x = [sp.Symbol('psix%d' % k) for k in r]
        self.psi_y = [sp.Symbol('psiy%d' % k) for k in r]
        self.delta = [sp.Symbol('delta%d' % k) for k in r]
        self.beta = [sp.Symbol('beta%d' % k) for k in r]
        sym = lambda name, i, j: sp.Symbol('%s%d%d' % (name, min(i, j) + 1, max(i, j) + 1))
        self.mu = [[sym('mu', i, j) for j in range(n)] for i in range(n)]
        self.kappa = [[sym('kappa', i, j) for j in range(n)] for i in range(n)]
        self.gamma = [[(0 if i == j else (sym('gamma', i, j) if i < j else -sym('gamma', i, j)))
                       for j in range(n)] for i in range(n)]
        # auxiliary integrals not fixed by the parameters
        self.Jxx, self.Jxy = sp.symbols('Jxx Jxy')
        self.Dxx = [sp.Symbol('Dxx%d' % k) for k in r]
        self.Dxy = [sp.Symbol('Dxy%d' % k) for k in r]
        self.Pxx = [[sym('Pxx', i, j) for j in range(n)] for i in range(n)]
        self.Sxy = [[sym('Sxy', i, j) for j in range(n)] for i in range(n)]
        self.aux = ({self.Jxx, self.Jxy} | set(self.Dxx) | set(self.Dxy)
                    | {x for row in self.Pxx for x in row} | {x for row in self.Sxy for x in row})
        # material point
        self.rx, self.ry = sp.symbols('rho_x rho_y')
        self.fx = [sp.Symbol('phix%d' % k) for k in r]
        self.fy = [sp.Symbol('phiy%d' % k) for k in r]
        self.point = [self.rx, self.ry] + self.fx + self.fy
        self.P = dict(n=n, M=self.M, h=self.h, zeta2=self.zeta2, mu=self.mu, kappa=self.kappa,
                      gamma=self.gamma, psi_x=self.psi_x, psi_y=self.psi_y, delta=self.delta,
                      beta=self.beta)
        self._build_table()

    def _build_table(self):
        n, M, h = self.n, self.M, self.h
        Mh2 = M * h ** 2
        t = {}
        e = lambda **kw: tuple(kw.get(str(p), 0) for p in self.point)
        idx = {str(p): i for i, p in enumerate(self.point)}

        def key(*syms):
            k = [0] * len(self.point)
            for s_ in syms:
                k[idx[str(s_)]] += 1
            return tuple(k)
        t[key()] = M
        t[key(self.rx)] = 0
        t[key(self.ry)] = 0
        t[key(self.rx, self.rx)] = self.Jxx
        t[key(self.ry, self.ry)] = Mh2 * self.zeta2 - self.Jxx
        t[key(self.rx, self.ry)] = self.Jxy
        for k in range(n):
            t[key(self.fx[k])] = M * h * self.psi_x[k]
            t[key(self.fy[k])] = M * h * self.psi_y[k]
            t[key(self.rx, self.fx[k])] = self.Dxx[k]
            t[key(self.ry, self.fy[k])] = Mh2 * self.delta[k] - self.Dxx[k]
            t[key(self.rx, self.fy[k])] = self.Dxy[k]
            t[key(self.ry, self.fx[k])] = self.Dxy[k] - Mh2 * self.beta[k]
            for j in range(n):
                t[key(self.fx[k], self.fx[j])] = self.Pxx[k][j]
                t[key(self.fy[k], self.fy[j])] = Mh2 * self.mu[k][j] - self.Pxx[k][j]
                # int phix_k phiy_j = Sxy_kj + Mh2 gamma_kj / 2 (gamma antisymmetric)
                t[key(self.fx[k], self.fy[j])] = self.Sxy[k][j] + Mh2 * self.gamma[k][j] / 2
        self.table = t

    def integrate(self, expr):
        """mass integral of a polynomial in the material-point symbols."""
        poly = sp.Poly(sp.expand(expr), *self.point)
        out = 0
        for mon, coeff in poly.terms():
            out += coeff * self.table[mon]
        return sp.expand(out)

    # kinematics of the generic point -------------------------------------------------
    def s_body(self, alpha):
        """position of the point relative to the pivot, body components."""
        return (-self.h * alpha + self.rx + dot(self.fx, self.q),
                self.h + self.ry + dot(self.fy, self.q))

    def u_body(self, alpha, thd, qd):
        """velocity relative to the base, body components."""
        s_ = self.s_body(alpha)
        return (-thd * s_[1] + dot(self.fx, qd), thd * s_[0] + dot(self.fy, qd))

    def vb_body(self):
        return (self.Xd * C + self.Yd * S, -self.Xd * S + self.Yd * C)

    def d_th(self, e):
        return sp.diff(e, S) * C - sp.diff(e, C) * S

    def ddt(self, e):
        """total time derivative of a function of (theta, q, thd, qd, Xd, Yd)."""
        out = self.d_th(e) * self.thd
        for k in range(self.n):
            out += sp.diff(e, self.q[k]) * self.qd[k] + sp.diff(e, self.qd[k]) * self.qdd[k]
        out += sp.diff(e, self.thd) * self.thdd + sp.diff(e, self.Xd) * self.Xdd + sp.diff(e, self.Yd) * self.Ydd
        return out

    def derive(self):
        n, M, h, g, alpha = self.n, self.M, self.h, self.g, self.alpha
        res = {}
        vb = self.vb_body()
        u = self.u_body(alpha, self.thd, self.qd)
        v = (vb[0] + u[0], vb[1] + u[1])
        T_in = self.integrate((v[0] ** 2 + v[1] ** 2) / 2)
        s_ = self.s_body(alpha)
        k = [[M * g * h * self.kappa[i][j] for j in range(n)] for i in range(n)]
        V = self.integrate(g * (self.Y + S * s_[0] + C * s_[1])) + dot(self.q, matvec(k, self.q)) / 2
        res['aux_in_T'] = sorted(str(x) for x in T_in.free_symbols & self.aux)
        res['aux_in_V'] = sorted(str(x) for x in V.free_symbols & self.aux)
        self.T_in, self.V = T_in, V
        # Lagrange
        coords = [(None, self.thd, self.thdd)] + list(zip(self.q, self.qd, self.qdd))
        EL = []
        for (x, xd, xdd) in coords:
            dTdxd = sp.diff(T_in, xd)
            dTdx = self.d_th(T_in) if x is None else sp.diff(T_in, x)
            dVdx = self.d_th(V) if x is None else sp.diff(V, x)
            EL.append(sp.expand(self.ddt(dTdxd) - dTdx + dVdx))
        self.EL = EL
        acc = [self.thdd] + self.qdd
        A_der = [[sp.expand(sp.diff(e, a) / (M * h ** 2)) for a in acc] for e in EL]
        # forces include base acceleration terms: f = -(EL - A acc)/(M h^2)
        f_der = [sp.expand(-(EL[i] - dot(A_der[i], acc) * M * h ** 2) / (M * h ** 2)) for i in range(n + 1)]
        self.A_der, self.f_der = A_der, f_der
        ax, ay = self.Xdd / g, 1 + self.Ydd / g
        A_c = conv_A(self.P, alpha, self.q)
        f_c = conv_f(self.P, alpha, self.q, self.thd, self.qd, S, C, ax, ay, g)
        res['mass_matrix'] = all(is_zero(A_der[i][j] - A_c[i][j]) for i in range(n + 1) for j in range(n + 1))
        res['forces'] = all(is_zero(f_der[i] - f_c[i]) for i in range(n + 1))
        # kinetic energy split: T_in = 1/2 M |Vb|^2 + M Vb.vcm_rel + T_rel
        vcm = conv_vcm_body(self.P, alpha, self.q, self.thd, self.qd)
        T_rel = conv_Trel(self.P, alpha, self.q, self.thd, self.qd)
        res['kinetic_energy'] = is_zero(T_in - (M * (self.Xd ** 2 + self.Yd ** 2) / 2
                                                + M * dot(vb, vcm) + T_rel))
        res['potential_energy'] = is_zero(V - M * g * self.Y - conv_V(self.P, alpha, self.q, S, C, g))
        # reaction F = d/dt(int Rdot dm) + M g J  (body components)
        P_body = [self.integrate(v[0]), self.integrate(v[1])]
        P_in = body_to_inertial(P_body, S, C)
        F_in = [sp.expand(self.ddt(P_in[0])), sp.expand(self.ddt(P_in[1]) + M * g)]
        F_c = body_to_inertial(conv_F_body(self.P, alpha, self.q, self.thd, self.qd, self.thdd, self.qdd,
                                           S, C, ax, ay, g), S, C)
        res['reaction'] = all(is_zero(F_in[i] - F_c[i]) for i in range(2))
        self.F_in = F_in
        # resultant in full contact: moment about the c.g. projection (base frame)
        vin = body_to_inertial(v, S, C)
        acc_pt = [self.ddt(vin[0]), self.ddt(vin[1])]
        full = {S: 0, C: 1, self.thd: 0, self.thdd: 0}
        r_in = body_to_inertial(s_, S, C)
        r_in = (h * alpha + r_in[0], r_in[1])
        mom = self.integrate(sp.expand((r_in[0] * (acc_pt[1] + g) - r_in[1] * acc_pt[0]).subs(full)))
        Fy0 = F_in[1].subs(full)
        num, den = conv_alpha_star_parts(self.P, self.q, self.qdd, ax, ay, g)
        res['resultant'] = is_zero(mom - M * g * h * num) and is_zero(Fy0 - M * g * den)
        self.mom_fc, self.Fy_fc = mom, Fy0
        # full-contact equations = q rows at theta=thd=thdd=0
        res['full_contact'] = all(is_zero((f_der[j + 1] - f_c[j + 1]).subs(full)) for j in range(n))
        # energy rate: d/dt(T_rel + V) = -M a_b . v_cm along the equations
        nu = [self.thd] + self.qd
        Tr = conv_Trel(self.P, alpha, self.q, self.thd, self.qd)
        Vr = conv_V(self.P, alpha, self.q, S, C, g)
        dTr = self.ddt(Tr)
        # replace nu^T A acc by nu^T f
        nuAacc = M * h ** 2 * dot(nu, matvec(A_c, acc))
        dE = sp.expand(dTr - nuAacc + M * h ** 2 * dot(nu, f_c) + self.ddt(Vr))
        vcm_in = body_to_inertial(vcm, S, C)
        res['energy_rate'] = is_zero(dE + M * (self.Xdd * vcm_in[0] + self.Ydd * vcm_in[1]))
        # uplift identity: (h/g)(f_th - b.qdd) = -U1 (alpha=-alpha1), = +U2 (alpha=alpha2), at theta=thd=0
        a1, a2 = sp.symbols('alpha1 alpha2', positive=True)
        ok = True
        for a, sign in ((-a1, -1), (a2, 1)):
            fc = conv_f(self.P, a, self.q, 0, self.qd, 0, 1, ax, ay, g)
            b = conv_b(self.P, a, self.q)
            lhs = (h / g) * (fc[0] - dot(b, self.qdd))
            U = den * (num / den + a1) if sign < 0 else den * (a2 - num / den)
            ok = ok and is_zero(lhs - sign * U)
        res['uplift_identity'] = ok
        # impact: general alpha_pre -> alpha_post at theta = 0
        ap, aq = sp.symbols('alpha_pre alpha_post')
        thm, thp = sp.symbols('thd_m thd_p')
        qdm = [sp.Symbol('qdm%d' % k) for k in range(1, n + 1)]
        qdp = [sp.Symbol('qdp%d' % k) for k in range(1, n + 1)]
        vb0 = (self.Xd, self.Yd)
        um, up = self.u_body(ap, thm, qdm), self.u_body(aq, thp, qdp)
        Rm = (vb0[0] + um[0], vb0[1] + um[1])
        Rp = (vb0[0] + up[0], vb0[1] + up[1])
        s_post = self.s_body(aq)
        H = lambda R_: self.integrate(s_post[0] * R_[1] - s_post[1] * R_[0])
        pmod = lambda R_, j: self.integrate(self.fx[j] * R_[0] + self.fy[j] * R_[1])
        Ai, rhs = conv_impact_system(self.P, ap, aq, self.q, thm, qdm)
        nup = [thp] + qdp
        resid = [dot(Ai[i], nup) - rhs[i] for i in range(n + 1)]
        cons = [H(Rp) - H(Rm)] + [pmod(Rp, j) - pmod(Rm, j) for j in range(n)]
        res['impact_map'] = all(is_zero(cons[i] - M * h ** 2 * resid[i]) for i in range(n + 1))
        self.impact_cons = cons
        I_der = [self.integrate(Rp[i] - Rm[i]) for i in range(2)]
        I_c = conv_impulse(self.P, ap, aq, self.q, thm, qdm, thp, qdp)
        res['impulse'] = all(is_zero(I_der[i] - I_c[i]) for i in range(2))
        Tin = lambda R_: self.integrate((R_[0] ** 2 + R_[1] ** 2) / 2)
        loss = self.Xd * I_der[0] + self.Yd * I_der[1] - (Tin(Rp) - Tin(Rm))
        res['energy_loss_identity'] = is_zero(loss - (conv_Trel(self.P, ap, self.q, thm, qdm)
                                                       - conv_Trel(self.P, aq, self.q, thp, qdp)))
        # both edges: thd+ = 0 and modal momenta conserved -> mu qd+ = mu qd- + b_pre thd-
        if n > 0:
            bpre = conv_b(self.P, ap, self.q)
            eqs = [sp.expand(pmod(Rp, j) - pmod(Rm, j)).subs(thp, 0) for j in range(n)]
            target = [dot(self.mu[j], qdp) - dot(self.mu[j], qdm) - bpre[j] * thm for j in range(n)]
            res['both_edges_modal'] = all(is_zero(eqs[j] - M * h ** 2 * target[j]) for j in range(n))
        # impact laws (theory "Impact laws"). rigid_body: qd+ = qd- (the velocity jump is a rigid
        # field), and the moment of momentum about the landing point alone is conserved:
        #   m_post thd+ = (m_post - Dalpha w_post,x) thd-
        Rr = (vb0[0] + self.u_body(aq, thp, qdm)[0], vb0[1] + self.u_body(aq, thp, qdm)[1])
        sol_r = sp.solve(sp.expand(H(Rr) - H(Rm)), thp)
        wpx, mpost = conv_w(self.P, aq, self.q)[0], conv_A(self.P, aq, self.q)[0][0]
        res['rigid_body_map'] = len(sol_r) == 1 and is_zero(sol_r[0] - thm * (1 - (ap - aq) * wpx / mpost))
        # in the rigid limit (q = 0, any modes) it is Housner's ratio, landing on edge 1
        a1s, a2s = sp.symbols('alpha1 alpha2', positive=True)
        lim = (sol_r[0] / thm).subs({q_: 0 for q_ in self.q}).subs({ap: a2s, aq: -a1s})
        res['rigid_body_housner_limit'] = is_zero(lim - (1 + self.zeta2 - a1s * a2s) / (1 + self.zeta2 + a1s ** 2))
        # its loss is the difference of T_rel, and the energy identity holds for it as for any jump
        loss_r = self.Xd * self.integrate(Rr[0] - Rm[0]) + self.Yd * self.integrate(Rr[1] - Rm[1]) - (Tin(Rr) - Tin(Rm))
        res['rigid_body_energy_identity'] = is_zero(loss_r - (conv_Trel(self.P, ap, self.q, thm, qdm)
                                                             - conv_Trel(self.P, aq, self.q, thp, qdm)))
        # restitution: thd+ = r thd-, the modal momenta conserved; loss = M h^2/2 (S_pre - r^2 S_post) thd-^2
        if n > 0:
            r_ = sp.Symbol('r')
            Rs = (vb0[0] + self.u_body(aq, r_ * thm, qdp)[0], vb0[1] + self.u_body(aq, r_ * thm, qdp)[1])
            eqs_s = [sp.expand(pmod(Rs, j) - pmod(Rm, j)) for j in range(n)]
            sol_s = sp.solve(eqs_s, qdp, dict=True)[0]
            bpre, bpost = conv_b(self.P, ap, self.q), conv_b(self.P, aq, self.q)
            mom = [dot(self.mu[j], qdm) + bpre[j] * thm - bpost[j] * r_ * thm for j in range(n)]
            res['restitution_modal'] = all(is_zero(dot(self.mu[j], [sol_s[v] for v in qdp]) - mom[j]) for j in range(n))
        if n == 0:
            sol = sp.solve(cons[0], thp)[0]
            a1s, a2s = sp.symbols('alpha1 alpha2', positive=True)
            ratio = sp.simplify(sol.subs({ap: a2s, aq: -a1s}) / thm)
            res['rigid_ratio'] = is_zero(ratio - (1 + self.zeta2 - a1s * a2s) / (1 + self.zeta2 + a1s ** 2))
            self.rigid_ratio = ratio
            # Housner's ratio never adds energy under the restitution law: r^2 S_post <= S_pre,
            # as (1+z2+a1^2)(1+z2+a2^2) - (1+z2-a1 a2)^2 = (1+z2)(a1+a2)^2 >= 0
            z = 1 + self.zeta2
            res['housner_ratio_dissipative'] = is_zero((z + a1s ** 2) * (z + a2s ** 2) - (z - a1s * a2s) ** 2
                                                       - z * (a1s + a2s) ** 2)
        # static overturning: at rest, ax=0, ay=1, the rocking forces vanish iff the conv. conditions hold
        fst = conv_f(self.P, alpha, self.q, 0, [0] * n, S, C, 0, 1, g)
        w = conv_w(self.P, alpha, self.q)
        res['static_theta_row'] = is_zero(fst[0] + (g / h) * (w[0] * C - w[1] * S))
        return res

    # flight, lift-off and landing -------------------------------------------------------
    def derive_flight(self):
        """Free flight in the c.g. coordinates (x_c, y_c, theta, q); lift-off; landing on a corner
        (general alpha_e, any theta); flat landing."""
        n, M, h, g = self.n, self.M, self.h, self.g
        P, q, qd, thd, thdd = self.P, self.q, self.qd, self.thd, self.thdd
        res = {}
        xc, yc, xcd, ycd, xcdd, ycdd = sp.symbols('xc yc xcd ycd xcdd ycdd')
        psq = (dot(self.psi_x, q), dot(self.psi_y, q))
        # the point relative to the deformed c.g. (body components); int rho_c dm = 0
        rho_c = (self.rx + dot(self.fx, q) - h * psq[0], self.ry + dot(self.fy, q) - h * psq[1])

        def u_cg(thd_, qd_):
            return (-thd_ * rho_c[1] + dot(self.fx, qd_) - h * dot(self.psi_x, qd_),
                    thd_ * rho_c[0] + dot(self.fy, qd_) - h * dot(self.psi_y, qd_))
        ub = body_to_inertial(u_cg(thd, qd), S, C)
        v = (self.Xd + xcd + ub[0], self.Yd + ycd + ub[1])
        T_in = self.integrate((v[0] ** 2 + v[1] ** 2) / 2)
        k = [[M * g * h * self.kappa[i][j] for j in range(n)] for i in range(n)]
        pos_y = body_to_inertial(rho_c, S, C)[1]
        V = self.integrate(g * (self.Y + yc + pos_y)) + dot(q, matvec(k, q)) / 2
        res['flight_aux'] = sorted(str(x) for x in (T_in.free_symbols | V.free_symbols) & self.aux)

        def ddt(e):
            out = self.d_th(e) * thd + sp.diff(e, thd) * thdd
            for a, b_, c_ in [(xc, xcd, xcdd), (yc, ycd, ycdd)] + list(zip(q, qd, self.qdd)):
                out += sp.diff(e, a) * b_ + sp.diff(e, b_) * c_
            return out + sp.diff(e, self.Xd) * self.Xdd + sp.diff(e, self.Yd) * self.Ydd
        coords = [(xc, xcd), (yc, ycd), (None, thd)] + list(zip(q, qd))
        EL = []
        for (x, xd) in coords:
            dTdx = self.d_th(T_in) if x is None else sp.diff(T_in, x)
            dVdx = self.d_th(V) if x is None else sp.diff(V, x)
            EL.append(sp.expand(ddt(sp.diff(T_in, xd)) - dTdx + dVdx))
        acc = [xcdd, ycdd, thdd] + self.qdd
        Mfull = [[sp.expand(sp.diff(e, a)) for a in acc] for e in EL]
        Acg = conv_A_cg(P, q)
        Mc = [[0] * (n + 3) for _ in range(n + 3)]
        Mc[0][0] = Mc[1][1] = M
        for i in range(n + 1):
            for j in range(n + 1):
                Mc[i + 2][j + 2] = M * h ** 2 * Acg[i][j]
        res['flight_mass_matrix'] = all(is_zero(Mfull[i][j] - Mc[i][j])
                                        for i in range(n + 3) for j in range(n + 3))
        rest = [sp.expand(EL[i] - dot(Mfull[i], acc)) for i in range(n + 3)]
        cga = conv_cg_acc_flight(self.Xdd, self.Ydd, g)
        f_c = conv_f_flight(P, q, thd, qd, g)
        res['flight_ballistic'] = is_zero(rest[0] + M * cga[0]) and is_zero(rest[1] + M * cga[1])
        res['flight_forces'] = all(is_zero(rest[i + 2] + M * h ** 2 * f_c[i]) for i in range(n + 1))
        # Koenig: T_in = 1/2 M |Vb + v_c|^2 + 1/2 M h^2 nu^T A_cg nu, and A_cg = A(alpha) - B^T B any alpha
        vc = (xcd, ycd)
        Tf = conv_T_flight(P, q, vc, thd, qd)
        res['flight_kinetic_energy'] = is_zero(T_in - Tf - M * (self.Xd ** 2 + self.Yd ** 2) / 2
                                               - M * (self.Xd * xcd + self.Yd * ycd))
        Aa, Ba = conv_A(P, self.alpha, q), conv_B(P, self.alpha, q)
        res['flight_koenig'] = all(is_zero(Aa[i][j] - Ba[0][i] * Ba[0][j] - Ba[1][i] * Ba[1][j] - Acg[i][j])
                                   for i in range(n + 1) for j in range(n + 1))
        res['flight_potential_energy'] = is_zero(V - M * g * self.Y - conv_V_flight(P, yc, q, g))
        # energy rate along the flight equations: d/dt(T_rel + V) = -M a_b . v_c
        nu = [thd] + qd
        onflight = {xcdd: cga[0], ycdd: cga[1]}
        dE = (ddt(Tf) + ddt(conv_V_flight(P, yc, q, g))).subs(onflight)
        dE = sp.expand(dE - M * h ** 2 * dot(nu, matvec(Acg, [thdd] + self.qdd)) + M * h ** 2 * dot(nu, f_c))
        res['flight_energy_rate'] = is_zero(dE + M * (self.Xdd * xcd + self.Ydd * ycd))
        # compliant contact (theory "Compliant contact"): a force F (inertial components) at the
        # tipping point alpha_k adds F/M to the c.g. acceleration and -B_k^T R^T F / (M h) to
        # A_cg [thdd; qdd]; then d/dt(T_rel + V) = -M a_b . v_c + F . v_k, with v_k the tipping
        # point's velocity of theory "Flight": the corner force's generalised forces are right
        Fx, Fy, ak = sp.symbols('F_x F_y alpha_k')
        Bk = conv_B(P, ak, q)
        Fbx, Fby = C * Fx + S * Fy, -S * Fx + C * Fy  # R^T F
        g_nu = [-(Bk[0][i] * Fbx + Bk[1][i] * Fby) / (M * h) for i in range(n + 1)]
        onc = {xcdd: cga[0] + Fx / M, ycdd: cga[1] + Fy / M}
        dEc = (ddt(Tf) + ddt(conv_V_flight(P, yc, q, g))).subs(onc)
        dEc = sp.expand(dEc - M * h ** 2 * dot(nu, matvec(Acg, [thdd] + self.qdd))
                        + M * h ** 2 * dot(nu, [f_c[i] + g_nu[i] for i in range(n + 1)]))
        vk = conv_corner_vel(P, ak, q, vc, thd, qd, S, C)
        res['compliant_corner_force_power'] = is_zero(
            dEc + M * (self.Xdd * xcd + self.Ydd * ycd) - (Fx * vk[0] + Fy * vk[1]))
        # and v_k is the time derivative of the tipping point's position (conv_corner)
        xk = conv_corner(P, ak, xc, yc, q, S, C)
        res['compliant_corner_velocity'] = all(
            is_zero(sp.expand(ddt(xk[i]).subs({xc: 0}) - vk[i])) for i in range(2))
        ae = sp.Symbol('alpha_e')
        # lift-off: rocking on alpha_e and flight describe the same motion (positions and velocities)
        s_e = self.s_body(ae)
        we = conv_w(P, ae, q)
        Be = conv_B(P, ae, q)
        vt_e = (dot(Be[0], nu), dot(Be[1], nu))
        ur, uf = self.u_body(ae, thd, qd), u_cg(thd, qd)
        res['liftoff_continuity'] = (all(is_zero(s_e[i] - rho_c[i] - h * we[i]) for i in range(2))
                                     and all(is_zero(ur[i] - h * vt_e[i] - uf[i]) for i in range(2)))
        # rocking = flight + the floor reaction at the corner (for any accelerations):
        #   (A_e acc - f_e) - (A_cg acc - f_cg) = B_e^T F_body / (M h)
        ax, ay = self.Xdd / g, 1 + self.Ydd / g
        accn = [thdd] + self.qdd
        Ae = conv_A(P, ae, q)
        fe = conv_f(P, ae, q, thd, qd, S, C, ax, ay, g)
        Fb = conv_F_body(P, ae, q, thd, qd, thdd, self.qdd, S, C, ax, ay, g)
        res['rocking_is_flight_plus_reaction'] = all(
            is_zero(dot(Ae[i], accn) - fe[i] - dot(Acg[i], accn) + f_c[i]
                    - (Be[0][i] * Fb[0] + Be[1][i] * Fb[1]) / (M * h)) for i in range(n + 1))
        # landing on the corner alpha_e: pre flight (vt, thd-, qd-), post rocking on alpha_e
        vtx, vty, vbx, vby = sp.symbols('vtx vty vbx vby')  # vt and the base velocity, body comps
        thm, thp = sp.symbols('thd_m thd_p')
        qdm = [sp.Symbol('qdm%d' % j) for j in range(1, n + 1)]
        qdp = [sp.Symbol('qdp%d' % j) for j in range(1, n + 1)]
        uf = u_cg(thm, qdm)
        um = (vbx + h * vtx + uf[0], vby + h * vty + uf[1])
        ur = self.u_body(ae, thp, qdp)
        up = (vbx + ur[0], vby + ur[1])
        H = lambda u_: self.integrate(s_e[0] * u_[1] - s_e[1] * u_[0])
        pm = lambda u_, j: self.integrate(self.fx[j] * u_[0] + self.fy[j] * u_[1])
        Ae_, rhs = conv_landing_system(P, ae, q, (vtx, vty), thm, qdm)
        nup = [thp] + qdp
        resid = [dot(Ae_[i], nup) - rhs[i] for i in range(n + 1)]
        cons = [H(up) - H(um)] + [pm(up, j) - pm(um, j) for j in range(n)]
        res['landing_map'] = all(is_zero(cons[i] - M * h ** 2 * resid[i]) for i in range(n + 1))
        Lam = [self.integrate(up[i] - um[i]) for i in range(2)]
        Lc = conv_landing_impulse(P, ae, q, (vtx, vty), thp, qdp, 0, 1)  # body components
        res['landing_impulse'] = all(is_zero(Lam[i] - Lc[i]) for i in range(2))
        Tin = lambda u_: self.integrate((u_[0] ** 2 + u_[1] ** 2) / 2)
        E = vbx * Lam[0] + vby * Lam[1] - (Tin(up) - Tin(um))
        vtp = (dot(Be[0], nup), dot(Be[1], nup))
        Ec = conv_landing_loss(P, q, (vtx, vty), [thm] + qdm, vtp, nup)
        # E = E_closed on the map (E - E_closed = -M h^2 nu+ . residual identically)
        res['landing_energy_loss'] = is_zero(E - Ec + M * h ** 2 * dot(nup, resid))
        # key check: flight state taken from rocking on alpha_pre at theta = 0 gives the impact map
        apre = sp.Symbol('alpha_pre')
        Bp = conv_B(P, apre, q)
        num_ = [thm] + qdm
        _, rhs_r = conv_landing_system(P, ae, q, (dot(Bp[0], num_), dot(Bp[1], num_)), thm, qdm)
        _, rhs8 = conv_impact_system(P, apre, ae, q, thm, qdm)
        res['landing_reduces_to_impact_map'] = all(is_zero(rhs_r[i] - rhs8[i]) for i in range(n + 1))
        # flat landing: theta_dot+ = 0, base stuck, modal momenta conserved
        if n:
            upf = (vbx + dot(self.fx, qdp), vby + dot(self.fy, qdp))
            prhs = conv_flat_landing_rhs(P, q, (vtx, vty), thm, qdm)
            residf = [dot(self.mu[j], qdp) - prhs[j] for j in range(n)]
            res['flat_landing_modal'] = all(is_zero(pm(upf, j) - pm(um, j) - M * h ** 2 * residf[j])
                                            for j in range(n))
            Lf = [self.integrate(upf[i] - um[i]) for i in range(2)]
            Lfc = conv_landing_impulse(P, 0, q, (vtx, vty), 0, qdp, 0, 1)
            res['flat_landing_impulse'] = all(is_zero(Lf[i] - Lfc[i]) for i in range(2))
            Ef = vbx * Lf[0] + vby * Lf[1] - (Tin(upf) - Tin(um))
            vtf = (dot(self.psi_x, qdp), dot(self.psi_y, qdp))
            Efc = conv_landing_loss(P, q, (vtx, vty), [thm] + qdm, vtf, [0] + qdp)
            res['flat_landing_energy_loss'] = is_zero(Ef - Efc + M * h ** 2 * dot(qdp, residf))
        return res

    # Coulomb friction: sliding modes and impacts with friction ---------------------------
    def derive_sliding(self):
        """Rocking with a sliding pivot and full-contact sliding in (d, theta, q); the floor force,
        the resultant, the energy rate with friction; impacts with a sliding landing corner."""
        n, M, h, g, alpha = self.n, self.M, self.h, self.g, self.alpha
        P, q, qd, thd, thdd = self.P, self.q, self.qd, self.thd, self.thdd
        res = {}
        dd, ddd = sp.symbols('dd ddd')  # d_dot, d_ddot (T and V do not depend on d itself)
        vb = ((self.Xd + dd) * C + self.Yd * S, -(self.Xd + dd) * S + self.Yd * C)
        u = self.u_body(alpha, thd, qd)
        v = (vb[0] + u[0], vb[1] + u[1])
        T_in = self.integrate((v[0] ** 2 + v[1] ** 2) / 2)
        V = self.V

        def ddt(e):
            return sp.expand(self.ddt(e) + sp.diff(e, dd) * ddd)
        coords = [(None, dd), (None, thd)] + list(zip(q, qd))
        EL = []
        for i, (x, xd) in enumerate(coords):
            if i == 0:  # d: cyclic in T and V
                EL.append(ddt(sp.diff(T_in, xd)))
                continue
            dTdx = self.d_th(T_in) if x is None else sp.diff(T_in, x)
            dVdx = self.d_th(V) if x is None else sp.diff(V, x)
            EL.append(sp.expand(ddt(sp.diff(T_in, xd)) - dTdx + dVdx))
        ax, ay = self.Xdd / g, 1 + self.Ydd / g
        axs = ax + ddd / g  # the sliding base: a_x -> a_x + d_ddot / g
        acc = [thdd] + self.qdd
        A_c = conv_A(P, alpha, q)
        f_s = conv_f(P, alpha, q, thd, qd, S, C, axs, ay, g)
        # (i) theta- and q-rows: those of rocking with a_x -> a_x + d_ddot/g
        res['slide_rows'] = all(is_zero(EL[i + 1] - M * h ** 2 * (dot(A_c[i], acc) - f_s[i])) for i in range(n + 1))
        # (ii) d-row: the generalized force of the floor force at the pivot, F_I of theory 5 (same replacement)
        Fs = body_to_inertial(conv_F_body(P, alpha, q, thd, qd, thdd, self.qdd, S, C, axs, ay, g), S, C)
        res['slide_d_row_is_F_I'] = is_zero(EL[0] - Fs[0] + M * g * 0)
        # and the whole floor force from dP/dt + M g J
        vin = body_to_inertial(v, S, C)
        Pm = [self.integrate(vin[0]), self.integrate(vin[1])]
        res['slide_reaction'] = is_zero(ddt(Pm[0]) - Fs[0]) and is_zero(ddt(Pm[1]) + M * g - Fs[1])
        # the reaction's dependence on the accelerations: dF_body/da_x = M g e_I, dF_body/dnu_dd = M h B,
        # and df/da_x = -(g/h) B^T e_I, so dF/dd_ddot = M (I - B A^-1 B^T) e_I = W^-1 I (theory 15)
        axsym = sp.Symbol('ax_')
        Fb = conv_F_body(P, alpha, q, thd, qd, thdd, self.qdd, S, C, axsym, ay, g)
        Bm, eI = conv_B(P, alpha, q), conv_e_I(S, C)
        ok = all(is_zero(sp.diff(Fb[r], axsym) - M * g * eI[r]) for r in range(2))
        ok = ok and all(is_zero(sp.diff(Fb[r], acc[i]) - M * h * Bm[r][i]) for r in range(2) for i in range(n + 1))
        fa = conv_f(P, alpha, q, thd, qd, S, C, axsym, ay, g)
        dfa = conv_dfdax(P, alpha, q, S, C, g)
        ok = ok and all(is_zero(sp.diff(fa[i], axsym) - dfa[i]) for i in range(n + 1))
        res['slide_affine_structure'] = ok
        # (iii) full contact sliding: q-rows and d-row at theta = thd = thdd = 0
        full = {S: 0, C: 1, thd: 0, thdd: 0}
        res['slide_full_contact'] = (all(is_zero((EL[j + 2] - M * h ** 2 * (dot(A_c[j + 1], acc) - f_s[j + 1])).subs(full))
                                         for j in range(n))
                                     and is_zero((EL[0] - Fs[0]).subs(full)))
        # (iv) kinetic energy relative to the floor and the energy rate with friction
        Tb = conv_T_slide(P, alpha, q, thd, qd, dd, S, C)
        vcm_in = body_to_inertial(conv_vcm_body(P, alpha, q, thd, qd), S, C)
        res['slide_kinetic_energy'] = is_zero(T_in - M * (self.Xd ** 2 + self.Yd ** 2) / 2
                                              - M * (self.Xd * (vcm_in[0] + dd) + self.Yd * vcm_in[1]) - Tb)
        nu = [thd] + qd
        Vr = conv_V(P, alpha, q, S, C, g)
        dE = ddt(Tb + Vr) - M * h ** 2 * dot(nu, [dot(A_c[i], acc) - f_s[i] for i in range(n + 1)])
        res['slide_energy_rate'] = is_zero(dE + M * (self.Xdd * (vcm_in[0] + dd) + self.Ydd * vcm_in[1])
                                           - Fs[0] * dd)
        # (v) resultant of a sliding base: moment about the moving projection of the c.g.
        acc_pt = [ddt(vin[0]), ddt(vin[1])]
        s_ = self.s_body(alpha)
        r_in = body_to_inertial(s_, S, C)
        r_in = (h * alpha + r_in[0], r_in[1])
        mom = self.integrate(sp.expand((r_in[0] * (acc_pt[1] + g) - r_in[1] * acc_pt[0]).subs(full)))
        num, den = conv_alpha_star_parts(P, q, self.qdd, axs, ay, g)
        res['slide_resultant'] = is_zero(mom - M * g * h * num) and is_zero(Fs[1].subs(full) - M * g * den)
        self.slide_EL = EL
        # (vi) impact with friction: flight (or any) state -> rocking on alpha_e with the corner sliding
        ae = sp.Symbol('alpha_e')
        vtx, vty, vbx, vby, ddp = sp.symbols('vtx vty vbx vby ddp')
        thm, thp = sp.symbols('thd_m thd_p')
        qdm = [sp.Symbol('qdm%d' % j) for j in range(1, n + 1)]
        qdp = [sp.Symbol('qdp%d' % j) for j in range(1, n + 1)]
        psq = (dot(self.psi_x, q), dot(self.psi_y, q))
        rho_c = (self.rx + dot(self.fx, q) - h * psq[0], self.ry + dot(self.fy, q) - h * psq[1])
        uf = (-thm * rho_c[1] + dot(self.fx, qdm) - h * dot(self.psi_x, qdm),
              thm * rho_c[0] + dot(self.fy, qdm) - h * dot(self.psi_y, qdm))
        um = (vbx + h * vtx + uf[0], vby + h * vty + uf[1])
        Vp = (ddp * C, -ddp * S)  # the corner's velocity after: d_dot+ I, body components
        ur = self.u_body(ae, thp, qdp)
        up = (vbx + Vp[0] + ur[0], vby + Vp[1] + ur[1])
        s_e = self.s_body(ae)
        H = lambda u_: self.integrate(s_e[0] * u_[1] - s_e[1] * u_[0])
        pm = lambda u_, j: self.integrate(self.fx[j] * u_[0] + self.fy[j] * u_[1])
        Ae_, rhs = conv_landing_system(P, ae, q, (vtx, vty), thm, qdm)  # A_e nu- + L(V-)
        nup = [thp] + qdp
        Lp = conv_L(P, ae, q, Vp)
        resid = [dot(Ae_[i], nup) + Lp[i] - rhs[i] for i in range(n + 1)]
        cons = [H(up) - H(um)] + [pm(up, j) - pm(um, j) for j in range(n)]
        res['friction_impact_map'] = all(is_zero(cons[i] - M * h ** 2 * resid[i]) for i in range(n + 1))
        # A_e nu- + L(V-) with V- the corner's velocity before: the right-hand side of the landing map
        Be = conv_B(P, ae, q)
        Vm = (h * (vtx - dot(Be[0], [thm] + qdm)), h * (vty - dot(Be[1], [thm] + qdm)))
        Lm = conv_L(P, ae, q, Vm)
        res['friction_impact_rhs'] = all(is_zero(dot(Ae_[i], [thm] + qdm) + Lm[i] - rhs[i]) for i in range(n + 1))
        Lam = [self.integrate(up[i] - um[i]) for i in range(2)]
        vcp = (Vp[0] + h * dot(Be[0], nup), Vp[1] + h * dot(Be[1], nup))
        res['friction_impact_impulse'] = all(is_zero(Lam[i] - M * (vcp[i] - h * (vtx, vty)[i])) for i in range(2))
        Tin = lambda u_: self.integrate((u_[0] ** 2 + u_[1] ** 2) / 2)
        E = vbx * Lam[0] + vby * Lam[1] - (Tin(up) - Tin(um))
        # E = kinetic energy of the jump - Lambda . V+ (= + mu_k Lambda_J |d_dot+| when sliding)
        vtp = (vcp[0] / h, vcp[1] / h)
        Ec = conv_landing_loss(P, q, (vtx, vty), [thm] + qdm, vtp, nup) - (Lam[0] * Vp[0] + Lam[1] * Vp[1])
        res['friction_impact_energy_loss'] = is_zero(E - Ec + M * h ** 2 * dot(nup, resid))
        # flat landing with sliding: theta_dot+ = 0, modal momenta mu qd+ + psi_x d_dot+/h = r_q
        if n:
            upf = (vbx + Vp[0] + dot(self.fx, qdp), vby + Vp[1] + dot(self.fy, qdp))
            upf = tuple(sp.expand(x.subs({S: 0, C: 1})) for x in upf)
            umf = tuple(sp.expand(x.subs({S: 0, C: 1})) for x in um)
            prhs = conv_flat_landing_rhs(P, q, (vtx, vty), thm, qdm)
            residf = [dot(self.mu[j], qdp) + self.psi_x[j] * ddp / h - prhs[j] for j in range(n)]
            res['flat_friction_modal'] = all(is_zero(pm(upf, j) - pm(umf, j) - M * h ** 2 * residf[j])
                                             for j in range(n))
            Lf = [self.integrate(upf[i] - umf[i]) for i in range(2)]
            res['flat_friction_impulse'] = (is_zero(Lf[0] - M * (ddp + h * dot(self.psi_x, qdp) - h * vtx))
                                            and is_zero(Lf[1] - M * (h * dot(self.psi_y, qdp) - h * vty)))
        return res


def walk_bound_checks(n=2):
    """The record walk's bound on the full-contact guards between samples (docs/theory.md, "Exact
    propagation in full contact"): the energy coordinates' flow is a contraction, the second
    derivative of the reaction and of the contact moment is the one the engine bounds
    (ContactPropagator::walk_curvature), and a function vanishing at both ends of [0, h] with
    |f''| <= M stays within M tau (h - tau)/2 <= M h^2/8 there."""
    out = {}
    w, c = sp.symbols('omega c', nonnegative=True)
    B = sp.Matrix([[0, w], [-w, -c]])
    out['walk_B_dissipative'] = all(is_zero(e) for e in (B + B.T) - sp.diag(0, -2 * c))
    t, al, gh, ax0, ax1, ay0, ay1 = sp.symbols('t alpha gh ax0 ax1 ay0 ay1')
    q = sp.Matrix([sp.Function('q%d' % (k + 1))(t) for k in range(n)])
    beta = sp.Matrix(sp.symbols('beta1:%d' % (n + 1)))
    px = sp.Matrix(sp.symbols('psx1:%d' % (n + 1)))
    py = sp.Matrix(sp.symbols('psy1:%d' % (n + 1)))
    Gam = sp.Matrix(n, n, sp.symbols('Gam1:%d' % (n * n + 1)))
    ax, ay = ax0 + ax1 * t, ay0 + ay1 * t  # a sampled record is linear between samples
    d = lambda v, k: v.diff(t, k)
    b = beta + Gam.T * q - al * py - px
    R = (b.T * d(q, 2))[0] / gh + (-al + (px.T * q)[0]) * ay - (1 + (py.T * q)[0]) * ax
    R2 = ((beta - al * py - px).T * d(q, 4) + q.T * Gam * d(q, 4) + 2 * d(q, 1).T * Gam * d(q, 3)
          + d(q, 2).T * Gam * d(q, 2))[0] / gh + (px.T * d(q, 2))[0] * ay + 2 * (px.T * d(q, 1))[0] * ay1 \
        - (py.T * d(q, 2))[0] * ax - 2 * (py.T * d(q, 1))[0] * ax1
    out['walk_moment_curvature'] = is_zero(sp.expand(d(sp.Matrix([R]), 2)[0] - R2))
    FI = ax + (px.T * d(q, 2))[0] / gh
    # the moment about a point alpha is R(0) - alpha F_J, so U1 = R(-alpha1) = R(0) + alpha1 F_J and
    # U2 = -R(alpha2) = alpha2 F_J - R(0): bounds on |R(0)| and F_J bound both uplift functions
    # (Simulator::walk_quiet)
    FJ = ay + (py.T * d(q, 2))[0] / gh
    out['walk_uplift_from_moment'] = is_zero(sp.expand(R - (R.subs(al, 0) - al * FJ)))
    out['walk_reaction_curvature'] = is_zero(sp.expand(d(sp.Matrix([FI]), 2)[0] - (px.T * d(q, 4))[0] / gh))
    # the first derivatives that the search for the extremes uses (Dynamics::full_contact_reaction_rates)
    R1 = (b.T * d(q, 3) + d(q, 1).T * Gam * d(q, 2))[0] / gh + (px.T * d(q, 1))[0] * ay \
        + (-al + (px.T * q)[0]) * ay1 - (py.T * d(q, 1))[0] * ax - (1 + (py.T * q)[0]) * ax1
    out['walk_moment_rate'] = is_zero(sp.expand(d(sp.Matrix([R]), 1)[0] - R1))
    out['walk_reaction_rate'] = is_zero(sp.expand(d(sp.Matrix([FI]), 1)[0] - ax1 - (px.T * d(q, 3))[0] / gh))
    # and a mode's eta''' and eta'''' from its equation s' = B s + (0, g0 + g1 t), s = (s_d, s_v):
    # eta' = s_v, eta'' = -w s_d - c s_v + g0 + g1 t (ContactPropagator::walk_q_derivatives)
    g0, g1 = sp.symbols('g0 g1')
    sd, sv = sp.Function('sd')(t), sp.Function('sv')(t)
    flow = {sd.diff(t): w * sv, sv.diff(t): -w * sd - c * sv + g0 + g1 * t}
    e2 = -w * sd - c * sv + g0 + g1 * t
    e3 = e2.diff(t).subs(flow)
    e4 = e3.diff(t).subs(flow)
    out['walk_mode_rates'] = is_zero(sp.expand(e3 - (-w ** 2 * sv - c * e2 + g1))) and \
        is_zero(sp.expand(e4 - (-w ** 2 * e2 - c * (-w ** 2 * sv - c * e2 + g1))))
    h, M, tau = sp.symbols('h M tau', positive=True)
    env = M * tau * (h - tau) / 2
    # env'' = -M: env -/+ e is concave where |e''| <= M and vanishes at both ends, so it is >= 0
    out['walk_envelope'] = is_zero(env.diff(tau, 2) + M) and is_zero(env.subs(tau, 0)) and \
        is_zero(env.subs(tau, h)) and is_zero(env.subs(tau, h / 2) - M * h ** 2 / 8) and \
        is_zero(env.diff(tau).subs(tau, h / 2))
    return out


def modal_coordinate_checks(n=2):
    """The pinned-base modal coordinates (docs/theory.md, "Modal coordinates"): with q = Phi eta
    for any invertible Phi, the energies, the generalized forces and the floor reaction keep their
    forms in eta with the parameters mu' = Phi^T mu Phi, kappa' = Phi^T kappa Phi, gamma' =
    Phi^T gamma Phi, psi' = Phi^T psi, delta' = Phi^T delta, beta' = Phi^T beta, so the equations
    of motion (and every guard and impact map built on them) hold in eta; and the damping that the
    engine sets diagonal there is Phi^T C Phi for both damping forms."""
    out = {}
    sym = lambda name: sp.Symbol(name)
    mu = sp.Matrix(n, n, lambda i, j: sym('m%d%d' % (min(i, j), max(i, j))))
    kappa = sp.Matrix(n, n, lambda i, j: sym('k%d%d' % (min(i, j), max(i, j))))
    gamma = sp.Matrix(n, n, lambda i, j: 0 if i == j else (1 if i < j else -1) * sym('g%d%d' % (min(i, j), max(i, j))))
    vec = lambda name: sp.Matrix([sym('%s%d' % (name, i)) for i in range(n)])
    P = dict(n=n, M=sym('M'), h=sym('h'), zeta2=sym('zeta2'), mu=mu.tolist(), kappa=kappa.tolist(),
             gamma=gamma.tolist(), psi_x=list(vec('px')), psi_y=list(vec('py')), delta=list(vec('dl')),
             beta=list(vec('bt')))
    Phi = sp.Matrix(n, n, lambda i, j: sym('f%d%d' % (i, j)))
    Pm = dict(P)
    Pm.update(mu=(Phi.T * mu * Phi).tolist(), kappa=(Phi.T * kappa * Phi).tolist(),
              gamma=(Phi.T * gamma * Phi).tolist())
    for k in ('psi_x', 'psi_y', 'delta', 'beta'):
        Pm[k] = list(Phi.T * sp.Matrix(P[k]))
    eta, etad, etadd = vec('e'), vec('ed'), vec('edd')
    q, qd, qdd = list(Phi * eta), list(Phi * etad), list(Phi * etadd)
    alpha, thd, thdd, ax, ay, g = sp.symbols('alpha thd thdd ax ay g')
    s, c = S, C
    out['modal_gamma_antisymmetric'] = all(is_zero(e) for e in (sp.Matrix(Pm['gamma']) + sp.Matrix(Pm['gamma']).T))
    out['modal_kinetic'] = is_zero(conv_Trel(P, alpha, q, thd, qd) - conv_Trel(Pm, alpha, list(eta), thd, list(etad)))
    out['modal_potential'] = is_zero(conv_V(P, alpha, q, s, c, g) - conv_V(Pm, alpha, list(eta), s, c, g))
    # generalized forces: the theta row equal, the q rows mapped by Phi^T; the mass matrix by
    # diag(1, Phi): A' = D^T A D, f' = D^T f, so A' nu' = f' is A nu = f for nu = D nu'
    f = conv_f(P, alpha, q, thd, qd, s, c, ax, ay, g)
    fm = conv_f(Pm, alpha, list(eta), thd, list(etad), s, c, ax, ay, g)
    D = sp.diag(1, Phi)
    out['modal_forces'] = all(is_zero(e) for e in (D.T * sp.Matrix(f) - sp.Matrix(fm)))
    A = sp.Matrix(conv_A(P, alpha, q))
    Am = sp.Matrix(conv_A(Pm, alpha, list(eta)))
    out['modal_mass_matrix'] = all(is_zero(e) for e in (D.T * A * D - Am))
    F = conv_F_body(P, alpha, q, thd, qd, thdd, qdd, s, c, ax, ay, g)
    Fm = conv_F_body(Pm, alpha, list(eta), thd, list(etad), thdd, list(etadd), s, c, ax, ay, g)
    out['modal_reaction'] = all(is_zero(a - b) for a, b in zip(F, Fm))
    # the damping: Phi^T C Phi with Phi^T mu Phi = I and Phi^T K Phi = Omega^2 (a numeric
    # generalized eigenproblem, exact rationals): Rayleigh a mu + b K gives a + b omega^2 =
    # 2 zeta omega for zeta = a/(2 omega) + b omega/2; modal mu Phi diag(2 zeta omega) Phi^T mu
    # gives diag(2 zeta omega)
    a_r, b_r, w = sp.symbols('a b omega', positive=True)
    zeta = a_r / (2 * w) + b_r * w / 2
    out['modal_rayleigh_ratio'] = is_zero(2 * zeta * w - (a_r + b_r * w ** 2))
    Ph = sp.Matrix([[1, 1], [1, -1]]) / sp.sqrt(2)  # orthonormal for mu = I
    Mu = sp.Matrix([[2, 0], [0, 3]])
    Ph = sp.diag(1 / sp.sqrt(2), 1 / sp.sqrt(3)) * Ph  # then Ph^T Mu Ph = I
    cdiag = sp.diag(sym('c0'), sym('c1'))
    Cm = Mu * Ph * cdiag * Ph.T * Mu
    out['modal_damping_diagonal'] = all(sp.simplify(e) == 0 for e in (Ph.T * Mu * Ph - sp.eye(2))) and \
        all(sp.simplify(e) == 0 for e in (Ph.T * Cm * Ph - cdiag))
    return out


def walk_exact_checks():
    """The record walk's exact pieces (docs/theory.md, "Walking the record"): the particular
    solution of a mode under linear forcing, the closed form of e^{B tau}, the energies of a piece
    from its ends alone, and the excursion of a quadratic from its chord."""
    out = {}
    w, c, g0, g1, tau, h = sp.symbols('omega c g0 g1 tau h', positive=True)
    B = sp.Matrix([[0, w], [-w, -c]])
    e2 = sp.Matrix([0, 1])
    # s_p = P0 + P1 tau solves s' = B s + e2 (g0 + g1 tau), and eta_p'' = (s_p')_v ' = 0
    P1 = sp.Matrix([g1 / w, 0])
    P0 = sp.Matrix([g0 / w - c * g1 / w ** 3, g1 / w ** 2])
    sp_ = P0 + P1 * tau
    out['walk_particular'] = all(is_zero(e) for e in (sp_.diff(tau) - B * sp_ - e2 * (g0 + g1 * tau)))
    out['walk_particular_no_acceleration'] = is_zero(sp_[1].diff(tau, 1))
    # e^{B tau} = e^{-c tau/2} (cos k tau I + sin(k tau)/k (B + c/2 I)), k^2 = w^2 - c^2/4: E(0) = I
    # and E' = B E (k > 0; with cosh/sinh for k^2 < 0 the same algebra holds with k -> i k)
    k = sp.symbols('k', positive=True)
    Bk = B.subs(w, sp.sqrt(k ** 2 + c ** 2 / 4))
    for name, (cs, sn) in {'under': (sp.cos(k * tau), sp.sin(k * tau) / k),
                           'over': (sp.cosh(k * tau), sp.sinh(k * tau) / k)}.items():
        Bn = Bk if name == 'under' else B.subs(w, sp.sqrt(c ** 2 / 4 - k ** 2))
        E = sp.exp(-c * tau / 2) * (cs * sp.eye(2) + sn * (Bn + c / 2 * sp.eye(2)))
        out['walk_exponential_' + name] = all(sp.simplify(e) == 0 for e in (E.diff(tau) - Bn * E)) \
            and all(sp.simplify(e) == 0 for e in (E.subs(tau, 0) - sp.eye(2)))
    Ecrit = sp.exp(-c * tau / 2) * (sp.eye(2) + tau * (B.subs(w, c / 2) + c / 2 * sp.eye(2)))
    out['walk_exponential_critical'] = all(sp.simplify(e) == 0 for e in
                                           (Ecrit.diff(tau) - B.subs(w, c / 2) * Ecrit))
    # the energies from the ends: along any solution (sd, sv) of the mode's equations, the
    # engine's closed forms have the integrands' derivatives
    sd, sv = sp.Function('sd')(tau), sp.Function('sv')(tau)
    sd0, sv0 = sp.symbols('sd0 sv0')
    g = g0 + g1 * tau
    ode = {sd.diff(tau): w * sv, sv.diff(tau): -w * sd - c * sv + g}
    int_sd = (g0 * tau + g1 * tau ** 2 / 2 - c * (sd - sd0) / w - (sv - sv0)) / w
    inp = (g * sd - g0 * sd0 - g1 * int_sd) / w
    loss = inp - sp.Rational(1, 2) * ((sd ** 2 + sv ** 2) - (sd0 ** 2 + sv0 ** 2))
    d = lambda e: e.diff(tau).subs(ode)
    out['walk_energy_int_sd'] = is_zero(d(int_sd) - sd)
    out['walk_energy_input'] = is_zero(d(inp) - g * sv)
    out['walk_energy_loss'] = is_zero(d(loss) - c * sv ** 2)
    at0 = {sd: sd0, sv: sv0}
    out['walk_energy_zero_at_start'] = all(is_zero(e.subs(tau, 0).subs(at0).subs(
        {sp.Function('sd')(0): sd0, sp.Function('sv')(0): sv0})) for e in (int_sd, inp, loss))
    # a quadratic's excursion from its chord on [0, h] is |its tau^2 coefficient| h^2/4
    a2 = sp.symbols('a2')
    dev = a2 * tau ** 2 - a2 * h * tau
    out['walk_quadratic_excursion'] = is_zero(dev.subs(tau, h / 2) + a2 * h ** 2 / 4) and \
        is_zero(dev.diff(tau).subs(tau, h / 2))
    return out


def symbolic_checks(nlist, verbose=False, flight_n=2):
    allres = {}
    gens = {}
    for n in nlist:
        t0 = time.time()
        G = General(n)
        r = G.derive()
        if n <= flight_n:
            r.update(G.derive_flight())
            r.update(G.derive_sliding())
        allres[n] = r
        gens[n] = G
        if verbose:
            print('  symbolic n=%d (%.1f s): %s' % (n, time.time() - t0, r), file=sys.stderr)
    return allres, gens


# ---------------------------------------------------------------------------
# Part (b): realizable discrete bodies, direct point-mass mechanics
# ---------------------------------------------------------------------------

class PointMassKernel:
    """Per-point-mass mechanics derived with explicit sin/cos (independent of part (a))."""

    def __init__(self, n):
        self.n = n
        th, thd, thdd = sp.symbols('th thd thdd')
        Xd, Yd, Xdd, Ydd, g = sp.symbols('Xd Yd Xdd Ydd g')
        m, sx, sy, ex = sp.symbols('m sx sy ex')  # sx, sy: undeformed position rel. to pivot
        q = list(sp.symbols('q1:%d' % (n + 1))) if n else []
        qd = list(sp.symbols('qd1:%d' % (n + 1))) if n else []
        qdd = list(sp.symbols('qdd1:%d' % (n + 1))) if n else []
        fx = list(sp.symbols('fx1:%d' % (n + 1))) if n else []
        fy = list(sp.symbols('fy1:%d' % (n + 1))) if n else []
        X, Y = sp.symbols('X Y')
        bx = sx + sum((fx[k] * q[k] for k in range(n)), 0)
        by = sy + sum((fy[k] * q[k] for k in range(n)), 0)
        # inertial position: base + pivot + rotation(theta) of body vector
        R = sp.Matrix([X + ex + sp.cos(th) * bx - sp.sin(th) * by,
                       Y + sp.sin(th) * bx + sp.cos(th) * by])
        xs, xds, xdds = [th] + q, [thd] + qd, [thdd] + qdd

        def ddt(e):
            out = sp.diff(e, X) * Xd + sp.diff(e, Y) * Yd + sp.diff(e, Xd) * Xdd + sp.diff(e, Yd) * Ydd
            for a, b_, c_ in zip(xs, xds, xdds):
                out += sp.diff(e, a) * b_ + sp.diff(e, b_) * c_
            return out
        Rd = R.applyfunc(ddt)
        Rdd = Rd.applyfunc(ddt)
        T = m * (Rd[0] ** 2 + Rd[1] ** 2) / 2
        V = m * g * (R[1] - Y)
        EL = [ddt(sp.diff(T, xd)) - sp.diff(T, x) + sp.diff(V, x) for x, xd in zip(xs, xds)]
        args = [m, sx, sy, ex] + fx + fy + xs + xds + xdds + [Xd, Yd, Xdd, Ydd, g]
        self.args = args
        lam = lambda e: sp.lambdify(args, e, modules='mpmath')
        zero_acc = {a: 0 for a in xdds}
        self.EL0 = lam(sp.Matrix([e.subs(zero_acc) for e in EL]))
        self.ELA = lam(sp.Matrix([[sp.diff(e, a) for a in xdds] for e in EL]))
        self.Rd = lam(Rd.subs({X: 0, Y: 0}))
        self.Rdd = lam(Rdd)
        self.Rrel = lam(R.subs({X: 0, Y: 0}))  # relative to the base origin (c.g. projection)

    def call(self, fn, pt, pivot_x, th, q, thd, qd, thdd, qdd, base):
        m, px, py, phx, phy = pt
        a = ([m, px - pivot_x, py, pivot_x] + list(phx) + list(phy) + [th] + list(q) + [thd] + list(qd)
             + [thdd] + list(qdd) + list(base))
        return fn(*a)


def mpf(x):
    return mp.mpf(float(x))


class Body:
    def __init__(self, n, masses, pos, modes, k, b1, b2, name):
        """pos: list of (x, y) relative to the c.g. projection on the base (y up from base).
        modes[a][k] = (phix, phiy)."""
        self.n, self.name = n, name
        self.m = masses
        self.M = sum(masses)
        self.xc = sum(mi * p[0] for mi, p in zip(masses, pos)) / self.M
        self.h = sum(mi * p[1] for mi, p in zip(masses, pos)) / self.M
        assert abs(self.xc) < mp.mpf('1e-25')
        self.pos = pos
        self.modes = modes
        self.k = k
        self.b1, self.b2 = b1, b2
        self.params()

    def params(self):
        n, M, h = self.n, self.M, self.h
        Mh2 = M * h * h
        rho = [(p[0], p[1] - h) for p in self.pos]
        self.rho = rho
        P = dict(n=n, M=M, h=h)
        P['zeta2'] = sum(mi * (r[0] ** 2 + r[1] ** 2) for mi, r in zip(self.m, rho)) / Mh2
        ph = self.modes
        P['mu'] = [[sum(mi * (ph[a][i][0] * ph[a][j][0] + ph[a][i][1] * ph[a][j][1])
                        for a, mi in enumerate(self.m)) / Mh2 for j in range(n)] for i in range(n)]
        P['gamma'] = [[sum(mi * (ph[a][i][0] * ph[a][j][1] - ph[a][i][1] * ph[a][j][0])
                           for a, mi in enumerate(self.m)) / Mh2 for j in range(n)] for i in range(n)]
        P['kappa'] = [[self.k[i][j] / (M * G * h) for j in range(n)] for i in range(n)]
        P['psi_x'] = [sum(mi * ph[a][i][0] for a, mi in enumerate(self.m)) / (M * h) for i in range(n)]
        P['psi_y'] = [sum(mi * ph[a][i][1] for a, mi in enumerate(self.m)) / (M * h) for i in range(n)]
        P['delta'] = [sum(mi * (rho[a][0] * ph[a][i][0] + rho[a][1] * ph[a][i][1])
                          for a, mi in enumerate(self.m)) / Mh2 for i in range(n)]
        P['beta'] = [sum(mi * (rho[a][0] * ph[a][i][1] - rho[a][1] * ph[a][i][0])
                         for a, mi in enumerate(self.m)) / Mh2 for i in range(n)]
        self.P = P
        self.alpha1, self.alpha2 = self.b1 / h, self.b2 / h

    def pts(self):
        for a, mi in enumerate(self.m):
            yield (mi, self.pos[a][0], self.pos[a][1],
                   [self.modes[a][k][0] for k in range(self.n)], [self.modes[a][k][1] for k in range(self.n)])


G = mp.mpf('9.80665')


def rel(a, b):
    a, b = mp.mpf(a), mp.mpf(b)
    return abs(a - b) / max(mp.mpf(1), abs(a), abs(b))


class Checker:
    def __init__(self):
        self.maxerr = mp.mpf(0)
        self.tol = mp.mpf('1e-12')
        self.where = ''

    def eq(self, a, b, what):
        a, b = (list(x) if isinstance(x, mp.matrix) else x for x in (a, b))
        if isinstance(a, (list, tuple)):
            assert len(a) == len(b), what
            for x, y in zip(a, b):
                self.eq(x, y, what)
            return
        e = rel(a, b)
        if e > self.maxerr:
            self.maxerr, self.where = e, what
        assert e < self.tol, 'mismatch %s: %s vs %s' % (what, a, b)


def direct_dynamics(K, body, pivot_x, th, q, thd, qd, base, g):
    n = body.n
    zero = [0] * n
    EL0 = mp.matrix(n + 1, 1)
    ELA = mp.matrix(n + 1, n + 1)
    for pt in body.pts():
        EL0 += K.call(K.EL0, pt, pivot_x, th, q, thd, qd, 0, zero, [0, 0] + list(base) + [g])
        ELA += K.call(K.ELA, pt, pivot_x, th, q, thd, qd, 0, zero, [0, 0] + list(base) + [g])
    # strain energy
    for j in range(n):
        EL0[j + 1] += sum(body.k[j][i] * q[i] for i in range(n))
    return ELA, EL0


def solve_lin(A, b):
    return mp.lu_solve(A, b)


def rocking_state(K, body, edge, th, q, thd, qd, base, chk):
    n, P, M, h, g = body.n, body.P, body.M, body.h, G
    pivot_x = -body.b1 if edge == 1 else body.b2
    alpha = -body.alpha1 if edge == 1 else body.alpha2
    ELA, EL0 = direct_dynamics(K, body, pivot_x, th, q, thd, qd, base, g)
    acc = solve_lin(ELA, -EL0)
    acc = [acc[i] for i in range(n + 1)]
    A_dir = [[ELA[i, j] / (M * h * h) for j in range(n + 1)] for i in range(n + 1)]
    f_dir = [-EL0[i] / (M * h * h) for i in range(n + 1)]
    s, c = mp.sin(th), mp.cos(th)
    ax, ay = base[0] / g, 1 + base[1] / g
    A_c = conv_A(P, alpha, q)
    f_c = conv_f(P, alpha, q, thd, qd, s, c, ax, ay, g)
    chk.eq([x for r in A_dir for x in r], [x for r in A_c for x in r], 'mass matrix')
    chk.eq(f_dir, f_c, 'forces')
    thdd, qdd = acc[0], acc[1:]
    # reaction, energies, power directly from the point masses
    F = [mp.mpf(0), M * g]
    T = mp.mpf(0)
    V = sum(q[i] * body.k[i][j] * q[j] for i in range(n) for j in range(n)) / 2
    pw = mp.mpf(0)
    dE = sum(q[i] * body.k[i][j] * qd[j] for i in range(n) for j in range(n))
    for pt in body.pts():
        m = pt[0]
        Rdd = K.call(K.Rdd, pt, pivot_x, th, q, thd, qd, thdd, qdd, [0, 0] + list(base) + [g])
        Rd = K.call(K.Rd, pt, pivot_x, th, q, thd, qd, thdd, qdd, [0, 0] + list(base) + [g])
        Rr = K.call(K.Rrel, pt, pivot_x, th, q, thd, qd, thdd, qdd, [0, 0] + list(base) + [g])
        F[0] += m * Rdd[0]
        F[1] += m * Rdd[1]
        T += m * (Rd[0] ** 2 + Rd[1] ** 2) / 2
        V += m * g * Rr[1]
        pw -= m * (base[0] * Rd[0] + base[1] * Rd[1])
        dE += m * (Rd[0] * (Rdd[0] - base[0]) + Rd[1] * (Rdd[1] - base[1]) + g * Rd[1])
    chk.eq(dE, pw, 'energy rate (direct)')
    Fc = body_to_inertial(conv_F_body(P, alpha, q, thd, qd, thdd, qdd, s, c, ax, ay, g), s, c)
    chk.eq(F, Fc, 'reaction')
    chk.eq(T, conv_Trel(P, alpha, q, thd, qd), 'T_rel')
    chk.eq(V, conv_V(P, alpha, q, s, c, g), 'V')
    vcm = body_to_inertial(conv_vcm_body(P, alpha, q, thd, qd), s, c)
    chk.eq(pw, -M * (base[0] * vcm[0] + base[1] * vcm[1]), 'input power')
    return dict(edge=edge, theta=th, q=q, theta_dot=thd, q_dot=qd, base_acc=list(base),
                mass_matrix=A_dir, forces=f_dir, accelerations=acc, reaction=F,
                kinetic_energy=T, potential_energy=V, input_power=pw)


def full_contact_state(K, body, q, qd, base, chk):
    n, P, M, h, g = body.n, body.P, body.M, body.h, G
    pivot_x = -body.b1
    ELA, EL0 = direct_dynamics(K, body, pivot_x, 0, q, 0, qd, base, g)
    if n:
        A = mp.matrix([[ELA[i + 1, j + 1] for j in range(n)] for i in range(n)])
        b = mp.matrix([-EL0[i + 1] for i in range(n)])
        qdd = solve_lin(A, b)
        qdd = [qdd[i] for i in range(n)]
    else:
        qdd = []
    ax, ay = base[0] / g, 1 + base[1] / g
    # closed form mu qdd = -(g/h)(kappa q + psi_x ax + psi_y ay)
    if n:
        rhs = [-(g / h) * (dot(P['kappa'][j], q) + P['psi_x'][j] * ax + P['psi_y'][j] * ay) for j in range(n)]
        qc = solve_lin(mp.matrix(P['mu']), mp.matrix(rhs))
        chk.eq(qdd, [qc[i] for i in range(n)], 'full contact qdd')
    F = [mp.mpf(0), M * g]
    mom = mp.mpf(0)
    for pt in body.pts():
        m = pt[0]
        Rdd = K.call(K.Rdd, pt, pivot_x, 0, q, 0, qd, 0, qdd, [0, 0] + list(base) + [g])
        Rr = K.call(K.Rrel, pt, pivot_x, 0, q, 0, qd, 0, qdd, [0, 0] + list(base) + [g])
        F[0] += m * Rdd[0]
        F[1] += m * Rdd[1]
        mom += m * (Rr[0] * (Rdd[1] + g) - Rr[1] * Rdd[0])
    alpha_star = mom / (h * F[1])
    Fc = conv_F_body(P, 0, q, 0, qd, 0, qdd, 0, 1, ax, ay, g)
    chk.eq(F, Fc, 'full contact reaction')
    num, den = conv_alpha_star_parts(P, q, qdd, ax, ay, g)
    chk.eq(alpha_star, num / den, 'resultant')
    return dict(q=q, q_dot=qd, base_acc=list(base), q_ddot=qdd, reaction=F, resultant=alpha_star)


def impact(K, body, landing, q, thdm, qdm, vb, chk, stats):
    n, P, M, h, g = body.n, body.P, body.M, body.h, G
    if landing == 1:
        xpre, xpost, apre, apost, sign_post = body.b2, -body.b1, body.alpha2, -body.alpha1, 1
    else:
        xpre, xpost, apre, apost, sign_post = -body.b1, body.b2, -body.alpha1, body.alpha2, -1
    pts = list(body.pts())
    base = [vb[0], vb[1], 0, 0, g]

    def vel(pt, pivot, thd, qd):
        return K.call(K.Rd, pt, pivot, 0, q, thd, qd, 0, [0] * n, base)

    def rel_pos(pt):
        return K.call(K.Rrel, pt, xpost, 0, q, 0, [0] * n, 0, [0] * n, base)

    def conserved(pivot, thd, qd):
        """[H about landing point, p_1..p_n]"""
        out = [mp.mpf(0)] * (n + 1)
        for pt in pts:
            m, v, r = pt[0], vel(pt, pivot, thd, qd), rel_pos(pt)
            out[0] += m * ((r[0] - xpost) * v[1] - r[1] * v[0])
            for j in range(n):
                out[j + 1] += m * (pt[3][j] * v[0] + pt[4][j] * v[1])
        return out
    pre = conserved(xpre, thdm, qdm)
    # unknowns enter linearly: build the matrix column by column
    base0 = conserved(xpost, 0, [0] * n)
    cols = []
    for k in range(n + 1):
        e = [0] * (n + 1)
        e[k] = 1
        ck = conserved(xpost, e[0], e[1:])
        cols.append([ck[i] - base0[i] for i in range(n + 1)])
    A = mp.matrix([[cols[j][i] for j in range(n + 1)] for i in range(n + 1)])
    sol = solve_lin(A, mp.matrix([pre[i] - base0[i] for i in range(n + 1)]))
    thdp, qdp = sol[0], [sol[i + 1] for i in range(n)]
    Ac, rhs = conv_impact_system(P, apre, apost, q, thdm, qdm)
    solc = solve_lin(mp.matrix(Ac), mp.matrix(rhs))
    chk.eq([sol[i] for i in range(n + 1)], [solc[i] for i in range(n + 1)], 'impact map')

    def impulse_energy(thdp_, qdp_):
        I = [mp.mpf(0), mp.mpf(0)]
        dT = mp.mpf(0)
        for pt in pts:
            m = pt[0]
            vm, vp = vel(pt, xpre, thdm, qdm), vel(pt, xpost, thdp_, qdp_)
            I[0] += m * (vp[0] - vm[0])
            I[1] += m * (vp[1] - vm[1])
            dT += m * (vp[0] ** 2 + vp[1] ** 2 - vm[0] ** 2 - vm[1] ** 2) / 2
        return I, vb[0] * I[0] + vb[1] * I[1] - dT
    I, E = impulse_energy(thdp, qdp)
    chk.eq(I, conv_impulse(P, apre, apost, q, thdm, qdm, thdp, qdp), 'impulse')
    chk.eq(E, conv_Trel(P, apre, q, thdm, qdm) - conv_Trel(P, apost, q, thdp, qdp), 'energy loss')
    assert E > -mp.mpf('1e-20'), 'negative single-edge impact loss'
    # both edges: thd+ = 0, modal momenta conserved
    if n:
        Am = mp.matrix([[A[i + 1, j + 1] for j in range(n)] for i in range(n)])
        qdb = solve_lin(Am, mp.matrix([pre[i + 1] - base0[i + 1] for i in range(n)]))
        qdb = [qdb[i] for i in range(n)]
        bpre = conv_b(P, apre, q)
        qc = solve_lin(mp.matrix(P['mu']), mp.matrix([dot(P['mu'][j], qdm) + bpre[j] * thdm for j in range(n)]))
        chk.eq(qdb, [qc[i] for i in range(n)], 'both-edges qd+')
    else:
        qdb = []
    Ib, Eb = impulse_energy(0, qdb)
    chk.eq(Ib, conv_impulse(P, apre, apost, q, thdm, qdm, 0, qdb), 'both-edges impulse')
    chk.eq(Eb, conv_Trel(P, apre, q, thdm, qdm) - conv_Trel(P, apost, q, 0, qdb), 'both-edges loss')
    assert Eb > -mp.mpf('1e-20'), 'negative both-edges loss'
    # closed form of the single-edge map: thd+ does not depend on qd-
    #   thd+/thd- = (m_post - Dalpha w_post_x - b_post mu^-1 b_pre) / S_post
    Dal = apre - apost
    S_post, S_pre = schur(P, apost, q), schur(P, apre, q)
    Apost, bpost, bpre = conv_A(P, apost, q), conv_b(P, apost, q), conv_b(P, apre, q)
    num = Apost[0][0] - Dal * conv_w(P, apost, q)[0] - (dot(bpost, mu_solve(P, bpre)) if n else 0)
    chk.eq(thdp, num / S_post * thdm, 'closed-form thd+')
    # losses via the Schur complements (modal momentum p conserved)
    chk.eq(E, M * h * h / 2 * (S_pre * thdm ** 2 - S_post * thdp ** 2), 'loss via Schur')
    chk.eq(Eb, M * h * h / 2 * S_pre * thdm ** 2, 'both-edges loss via Schur')
    # split of the vertical impulse: moment about the landing edge of the other edge's impulse
    post = conserved(xpost, 0, qdb)
    I_other_y = (post[0] - pre[0]) / (xpre - xpost)
    I_land_y = Ib[1] - I_other_y
    # closed forms: I_other_y = -M h S_post thd+ / Dalpha,  I_land_y = M h S_pre thd- / Dalpha
    chk.eq(I_other_y, -M * h * S_post * thdp / Dal, 'both-edges I_other_y')
    chk.eq(I_land_y, M * h * S_pre * thdm / Dal, 'both-edges I_land_y')
    # impact laws (theory "Impact laws"), mass by mass. rigid_body: every mass keeps its modal
    # velocity (the jump is a rigid field) and the moment of momentum about the landing point,
    # summed over the masses, is conserved; the impulse is the change of the summed momenta
    frozen = conserved(xpost, 0, qdm)
    thdr = (pre[0] - frozen[0]) / cols[0][0]
    chk.eq(thdr, thdm * (1 - Dal * conv_w(P, apost, q)[0] / Apost[0][0]), 'rigid_body thd+')
    Ir, Er = impulse_energy(thdr, qdm)
    chk.eq(Ir, conv_impulse(P, apre, apost, q, thdm, qdm, thdr, qdm), 'rigid_body impulse')
    chk.eq(Er, conv_Trel(P, apre, q, thdm, qdm) - conv_Trel(P, apost, q, thdr, qdm), 'rigid_body loss')
    Irb, Erb = impulse_energy(0, qdm)  # its both-edges stop: thd+ = 0, qd+ = qd-
    stats['rigid_gain'] = stats.get('rigid_gain', 0) + int((Er if thdr * sign_post > 0 else Erb) < 0)
    # restitution: thd+ = r thd-, the modal momenta (summed over the masses) conserved
    ratio = mpf('0.7')
    if n:
        rest = conserved(xpost, ratio * thdm, [0] * n)
        qdr = solve_lin(Am, mp.matrix([pre[i + 1] - rest[i + 1] for i in range(n)]))
        qdr = [qdr[i] for i in range(n)]
        p_ = [dot(P['mu'][j], qdm) + bpre[j] * thdm - bpost[j] * ratio * thdm for j in range(n)]
        chk.eq(qdr, mu_solve(P, p_), 'restitution qd+')
    else:
        qdr = []
    Ie, Ee = impulse_energy(ratio * thdm, qdr)
    chk.eq(Ee, M * h * h / 2 * (S_pre - ratio ** 2 * S_post) * thdm ** 2, 'restitution loss via Schur')
    applies = thdp * sign_post < 0
    stats['impacts'] += 1
    if applies:
        stats['both_applies'] += 1
        if I_other_y < 0 or I_land_y < 0:
            stats['both_negative'].append((body.name, landing, float(I_land_y), float(I_other_y)))
    stats['min_ratio'] = min(stats['min_ratio'], float(thdp / thdm))
    return dict(landing_edge=landing, q=q, theta_dot_minus=thdm, q_dot_minus=qdm,
                theta_dot_plus=thdp, q_dot_plus=qdp, impulse=I, energy_loss=E,
                both_edges=dict(q_dot_plus=qdb, impulse=Ib, energy_loss=Eb),
                rigid_body=dict(theta_dot_plus=thdr, impulse=Ir, energy_loss=Er,
                                both_edges=dict(impulse=Irb, energy_loss=Erb)),
                restitution=dict(ratio=ratio, theta_dot_plus=ratio * thdm, q_dot_plus=qdr, impulse=Ie,
                                 energy_loss=Ee))


def mu_solve(P, v):
    x = solve_lin(mp.matrix(P['mu']), mp.matrix(list(v)))
    return [x[i] for i in range(P['n'])]


def schur(P, alpha, q):
    """S = m - b^T mu^-1 b  (> 0: A is positive definite)."""
    A, b = conv_A(P, alpha, q), conv_b(P, alpha, q)
    return A[0][0] - (dot(b, mu_solve(P, b)) if P['n'] else 0)


def tipping_angles(K, body, chk):
    n, P = body.n, body.P
    out = []
    for edge in (1, 2):
        alpha = -body.alpha1 if edge == 1 else body.alpha2
        pivot_x = -body.b1 if edge == 1 else body.b2

        def qstat(th):
            if not n:
                return []
            rhs = [-(P['psi_x'][j] * mp.sin(th) + P['psi_y'][j] * mp.cos(th)) for j in range(n)]
            x = solve_lin(mp.matrix(P['kappa']), mp.matrix(rhs))
            return [x[i] for i in range(n)]

        def fun(th):
            q = qstat(th)
            w = conv_w(P, alpha, q)
            return mp.tan(th) - w[0] / w[1]
        th0 = mp.atan(body.alpha1) if edge == 1 else -mp.atan(body.alpha2)
        th = mp.findroot(fun, th0)
        # direct check: all generalized forces vanish at rest under gravity alone
        q = qstat(th)
        ELA, EL0 = direct_dynamics(K, body, pivot_x, th, q, 0, [0] * n, [0, 0], G)
        for i in range(n + 1):
            chk.eq(EL0[i] / (body.M * G * body.h), 0, 'static overturning')
        out.append(abs(th))
    return out


# --- flight, lift-off, landing: direct point-mass mechanics -------------------------------------

class FlightKernel:
    """Per-point-mass mechanics of the free body in the coordinates (u, v, theta, q): (u, v) is the
    base point O' (below the undeformed c.g.) relative to the base origin.  Independent of the
    closed forms: the c.g. and its velocity are sums over the masses."""

    def __init__(self, n):
        self.n = n
        u, v, th, ud, vd, thd, udd, vdd, thdd = sp.symbols('u v th ud vd thd udd vdd thdd')
        Xd, Yd, Xdd, Ydd, g = sp.symbols('Xd Yd Xdd Ydd g')
        m, sx, sy = sp.symbols('m sx sy')  # undeformed position relative to O'
        q = list(sp.symbols('q1:%d' % (n + 1))) if n else []
        qd = list(sp.symbols('qd1:%d' % (n + 1))) if n else []
        qdd = list(sp.symbols('qdd1:%d' % (n + 1))) if n else []
        fx = list(sp.symbols('fx1:%d' % (n + 1))) if n else []
        fy = list(sp.symbols('fy1:%d' % (n + 1))) if n else []
        X, Y = sp.symbols('X Y')
        bx = sx + sum((fx[k] * q[k] for k in range(n)), 0)
        by = sy + sum((fy[k] * q[k] for k in range(n)), 0)
        R = sp.Matrix([X + u + sp.cos(th) * bx - sp.sin(th) * by, Y + v + sp.sin(th) * bx + sp.cos(th) * by])
        xs, xds, xdds = [u, v, th] + q, [ud, vd, thd] + qd, [udd, vdd, thdd] + qdd

        def ddt(e):
            out = sp.diff(e, X) * Xd + sp.diff(e, Y) * Yd + sp.diff(e, Xd) * Xdd + sp.diff(e, Yd) * Ydd
            for a, b_, c_ in zip(xs, xds, xdds):
                out += sp.diff(e, a) * b_ + sp.diff(e, b_) * c_
            return out
        Rd = R.applyfunc(ddt)
        Rdd = Rd.applyfunc(ddt)
        T = m * (Rd[0] ** 2 + Rd[1] ** 2) / 2
        V = m * g * (R[1] - Y)
        EL = [ddt(sp.diff(T, xd)) - sp.diff(T, x) + sp.diff(V, x) for x, xd in zip(xs, xds)]
        args = [m, sx, sy] + fx + fy + xs + xds + xdds + [Xd, Yd, Xdd, Ydd, g]
        lam = lambda e: sp.lambdify(args, e, modules='mpmath')
        zero_acc = {a: 0 for a in xdds}
        self.EL0 = lam(sp.Matrix([e.subs(zero_acc) for e in EL]))
        self.ELA = lam(sp.Matrix([[sp.diff(e, a) for a in xdds] for e in EL]))
        self.Rd = lam(Rd.subs({X: 0, Y: 0}))
        self.Rdd = lam(Rdd)
        self.Rrel = lam(R.subs({X: 0, Y: 0}))
        self.Jac = lam(R.jacobian(sp.Matrix(xs)))

    def call(self, fn, pt, x, xd, xdd, base):
        m, px, py, phx, phy = pt
        return fn(*([m, px, py] + list(phx) + list(phy) + list(x) + list(xd) + list(xdd) + list(base)))


def kcall(K, fn, pt, sx_off, ex, th, q, thd, qd, thdd, qdd, base):
    """rocking kernel with the pivot at body abscissa sx_off (relative to O') and at ex on the floor."""
    m, px, py, phx, phy = pt
    return fn(*([m, px - sx_off, py, ex] + list(phx) + list(phy) + [th] + list(q) + [thd] + list(qd)
                + [thdd] + list(qdd) + list(base)))


def rot(v, th):
    return body_to_inertial(v, mp.sin(th), mp.cos(th))


def rotT(v, th):
    s, c = mp.sin(th), mp.cos(th)
    return (c * v[0] + s * v[1], -s * v[0] + c * v[1])


def alpha_of(body, edge):
    return -body.alpha1 if edge == 1 else body.alpha2


def flight_direct(FK, body, x, xd, base):
    """accelerations (u, v, theta, q) and c.g. position / velocity / acceleration from the masses."""
    n, M = body.n, body.M
    zero = [0] * (n + 3)
    b = [base[0], base[1], base[2], base[3], G]
    EL0 = mp.matrix(n + 3, 1)
    ELA = mp.matrix(n + 3, n + 3)
    for pt in body.pts():
        EL0 += FK.call(FK.EL0, pt, x, xd, zero, b)
        ELA += FK.call(FK.ELA, pt, x, xd, zero, b)
    q = x[3:]
    for j in range(n):
        EL0[j + 3] += sum(body.k[j][i] * q[i] for i in range(n))
    acc = solve_lin(ELA, -EL0)
    acc = [acc[i] for i in range(n + 3)]
    rc, vc, ac = [mp.mpf(0)] * 2, [mp.mpf(0)] * 2, [mp.mpf(0)] * 2
    for pt in body.pts():
        m = pt[0]
        r_ = FK.call(FK.Rrel, pt, x, xd, acc, b)
        v_ = FK.call(FK.Rd, pt, x, xd, acc, b)
        a_ = FK.call(FK.Rdd, pt, x, xd, acc, b)
        for i in range(2):
            rc[i] += m * r_[i] / M
            vc[i] += m * (v_[i] - base[i]) / M  # relative to the base
            ac[i] += m * (a_[i] - base[2 + i]) / M
    return acc, ELA, rc, vc, ac


def flight_state(FK, body, th, q, u, v, ud, vd, thd, qd, base, chk):
    """base = (Xd, Yd, Xdd, Ydd)."""
    n, P, M, h = body.n, body.P, body.M, body.h
    x, xd = [u, v, th] + list(q), [ud, vd, thd] + list(qd)
    acc, ELA, rc, vc, ac = flight_direct(FK, body, x, xd, base)
    s, c = mp.sin(th), mp.cos(th)
    nu = [thd] + list(qd)
    # c.g. position / velocity from O' (closed form) vs the masses
    w0 = conv_w(P, 0, q)
    B0 = conv_B(P, 0, q)
    r0 = rot(w0, th)
    chk.eq(rc, [u + h * r0[0], v + h * r0[1]], 'flight c.g. position')
    vb = rot((dot(B0[0], nu), dot(B0[1], nu)), th)
    chk.eq(vc, [ud + h * vb[0], vd + h * vb[1]], 'flight c.g. velocity')
    # ballistic c.g.; theta, q from the closed form
    chk.eq(ac, conv_cg_acc_flight(base[2], base[3], G), 'flight c.g. acceleration')
    Acg = conv_A_cg(P, q)
    f = conv_f_flight(P, q, thd, qd, G)
    nudd = solve_lin(mp.matrix(Acg), mp.matrix(f))
    chk.eq(acc[2:], [nudd[i] for i in range(n + 1)], 'flight accelerations')
    # mass matrix about the c.g. = Schur complement of the translation block of the direct one
    Mt = mp.matrix([[ELA[i, j] for j in range(2)] for i in range(2)])
    for i in range(n + 1):
        for j in range(n + 1):
            corr = sum(ELA[i + 2, a] * (mp.inverse(Mt))[a, b_] * ELA[b_, j + 2] for a in range(2) for b_ in range(2))
            chk.eq((ELA[i + 2, j + 2] - corr) / (M * h * h), Acg[i][j], 'A_cg')
    # energies and input power, directly
    b = [base[0], base[1], base[2], base[3], G]
    T = mp.mpf(0)
    V = sum(q[i] * body.k[i][j] * q[j] for i in range(n) for j in range(n)) / 2
    pw = mp.mpf(0)
    dE = sum(q[i] * body.k[i][j] * qd[j] for i in range(n) for j in range(n))
    for pt in body.pts():
        m = pt[0]
        Rd = FK.call(FK.Rd, pt, x, xd, acc, b)
        Rdd = FK.call(FK.Rdd, pt, x, xd, acc, b)
        Rr = FK.call(FK.Rrel, pt, x, xd, acc, b)
        vr = (Rd[0] - base[0], Rd[1] - base[1])
        T += m * (vr[0] ** 2 + vr[1] ** 2) / 2
        V += m * G * Rr[1]
        pw -= m * (base[2] * vr[0] + base[3] * vr[1])
        dE += m * (vr[0] * (Rdd[0] - base[2]) + vr[1] * (Rdd[1] - base[3]) + G * vr[1])
    chk.eq(T, conv_T_flight(P, q, vc, thd, qd), 'flight T_rel')
    chk.eq(V, conv_V_flight(P, rc[1], q, G), 'flight V')
    chk.eq(dE, pw, 'flight energy rate (direct)')
    chk.eq(pw, -M * (base[2] * vc[0] + base[3] * vc[1]), 'flight input power')
    corners = []
    for edge in (1, 2):
        ae = alpha_of(body, edge)
        # the corner is the massless body point h(alpha_e, 0) from O'
        ce = rot((h * ae, 0), th)
        pos = (u + ce[0], v + ce[1])
        vel = (ud - thd * ce[1], vd + thd * ce[0])
        a_ = (acc[0] - acc[2] * ce[1] - thd ** 2 * ce[0], acc[1] + acc[2] * ce[0] - thd ** 2 * ce[1])
        chk.eq(pos, conv_corner(P, ae, rc[0], rc[1], q, s, c), 'corner position')
        chk.eq(vel, conv_corner_vel(P, ae, q, vc, thd, qd, s, c), 'corner velocity')
        chk.eq(a_, conv_corner_acc(P, ae, q, ac, thd, qd, acc[2], acc[3:], s, c), 'corner acceleration')
        corners.append(dict(position=pos, velocity=vel, acceleration=a_))
    return dict(theta=th, q=q, theta_dot=thd, q_dot=qd, base=list(base), cg=rc, cg_velocity=vc,
                cg_acceleration=ac, accelerations=acc[2:], mass_matrix_cg=Acg, kinetic_energy=T,
                potential_energy=V, input_power=pw, corners=corners)


def W_corner(P, alpha_e, q, th):
    """2x2 inverse effective mass of the corner (inertial components): a_e = a_free + W F."""
    n, M = P['n'], P['M']
    Acg = mp.matrix(conv_A_cg(P, q))
    B = conv_B(P, alpha_e, q)
    Bm = mp.matrix([[B[i][j] for j in range(n + 1)] for i in range(2)])
    Wb = mp.eye(2) + Bm * mp.inverse(Acg) * Bm.T
    s, c = mp.sin(th), mp.cos(th)
    R = mp.matrix([[c, -s], [s, c]])
    return (R * Wb * R.T) / M


def liftoff(K, FK, body, edge, d, th, q, thd, qd, base, chk, stats):
    """rocking on `edge`, its pivot d to the right of where it stood -> flight; base = (Xdd, Ydd)."""
    n, P, M, h = body.n, body.P, body.M, body.h
    ae = alpha_of(body, edge)
    x0 = h * ae  # the edge's abscissa from O'
    xP = x0 + d
    b = [0, 0, base[0], base[1], G]
    ELA, EL0 = direct_dynamics(K, body, x0, th, q, thd, qd, base, G)
    acc_r = solve_lin(ELA, -EL0)
    acc_r = [acc_r[i] for i in range(n + 1)]
    rc, vc, F = [mp.mpf(0)] * 2, [mp.mpf(0)] * 2, [mp.mpf(0), M * G]
    for pt in body.pts():
        m = pt[0]
        r_ = kcall(K, K.Rrel, pt, x0, xP, th, q, thd, qd, acc_r[0], acc_r[1:], b)
        v_ = kcall(K, K.Rd, pt, x0, xP, th, q, thd, qd, acc_r[0], acc_r[1:], b)
        a_ = kcall(K, K.Rdd, pt, x0, xP, th, q, thd, qd, acc_r[0], acc_r[1:], b)
        for i in range(2):
            rc[i] += m * r_[i] / M
            vc[i] += m * v_[i] / M
            F[i] += m * a_[i]
    s, c = mp.sin(th), mp.cos(th)
    pos, vel = conv_liftoff(P, ae, xP, q, thd, qd, s, c)
    chk.eq(rc, pos, 'lift-off c.g. position')
    chk.eq(vc, vel, 'lift-off c.g. velocity')
    # the same state in the flight coordinates (O' = pivot - R h(alpha_e, 0))
    ce = rot((x0, 0), th)
    x = [xP - ce[0], -ce[1], th] + list(q)
    xd = [thd * ce[1], -thd * ce[0], thd] + list(qd)
    for pt in body.pts():
        chk.eq(FK.call(FK.Rd, pt, x, xd, [0] * (n + 3), b),
               kcall(K, K.Rd, pt, x0, xP, th, q, thd, qd, 0, [0] * n, b), 'lift-off point velocity')
    acc_f, _, rcf, vcf, acf = flight_direct(FK, body, x, xd, [0, 0, base[0], base[1]])
    # rocking = flight + the floor reaction at the corner
    Acg = conv_A_cg(P, q)
    Be = conv_B(P, ae, q)
    Fb = rotT(F, th)
    corr = solve_lin(mp.matrix(Acg), mp.matrix([-(Be[0][i] * Fb[0] + Be[1][i] * Fb[1]) / (M * h)
                                                  for i in range(n + 1)]))
    chk.eq(acc_r, [acc_f[2 + i] + corr[i] for i in range(n + 1)], 'rocking = flight + reaction')
    ac_r = [sum(pt[0] * kcall(K, K.Rdd, pt, x0, xP, th, q, thd, qd, acc_r[0], acc_r[1:], b)[i]
                for pt in body.pts()) / M - base[i] for i in range(2)]
    chk.eq(ac_r, [acf[i] + F[i] / M for i in range(2)], 'rocking c.g. = flight + F/M')
    # the corner's acceleration in flight at this state: a_e = -W F
    ae_f = conv_corner_acc(P, ae, q, acf, thd, qd, acc_f[2], acc_f[3:], s, c)
    W = W_corner(P, ae, q, th)
    chk.eq(ae_f, [-(W[i, 0] * F[0] + W[i, 1] * F[1]) for i in range(2)], 'flight corner acc = -W F')
    # the closed-form reaction (theory 5) is the F here
    ax, ay = base[0] / G, 1 + base[1] / G
    Fc = body_to_inertial(conv_F_body(P, ae, q, thd, qd, acc_r[0], acc_r[1:], s, c, ax, ay, G), s, c)
    chk.eq(F, Fc, 'lift-off reaction')
    stats['liftoff'] += 1
    # at F_J = 0 the corner's flight acceleration is -W_yx F_I: record its sign for the tilt range
    return dict(edge=edge, pivot_x=xP, theta=th, q=q, theta_dot=thd, q_dot=qd, base_acc=list(base),
                cg=rc, cg_velocity=vc, reaction=F, rocking_accelerations=acc_r,
                flight_accelerations=acc_f[2:], flight_cg_acceleration=acf, flight_corner_acceleration=ae_f,
                W=[[W[0, 0], W[0, 1]], [W[1, 0], W[1, 1]]])


def landing(K, FK, body, edge, d, th, q, x, xd, vb, chk, stats, what='landing'):
    """flight state (x, xd) in (u, v, theta, q) with the corner `edge` on the floor at d + ...;
    plastic landing, the corner sticks; post state rocking on `edge`.  vb: base velocity."""
    n, P, M, h = body.n, body.P, body.M, body.h
    ae = alpha_of(body, edge)
    x0 = h * ae
    ce = rot((x0, 0), th)
    xe = x[0] + ce[0]
    assert abs(x[1] + ce[1]) < mp.mpf('1e-25')
    b = [vb[0], vb[1], 0, 0, G]
    pts = list(body.pts())
    s, c = mp.sin(th), mp.cos(th)

    def phi_in(pt, j):
        return rot((pt[3][j], pt[4][j]), th)

    def conserved(vels):
        out = [mp.mpf(0)] * (n + 1)
        for pt, v_ in zip(pts, vels):
            m = pt[0]
            r = FK.call(FK.Rrel, pt, x, xd, [0] * (n + 3), b)
            out[0] += m * ((r[0] - xe) * v_[1] - r[1] * v_[0])
            for j in range(n):
                ph = phi_in(pt, j)
                out[j + 1] += m * (ph[0] * v_[0] + ph[1] * v_[1])
        return out
    vm = [FK.call(FK.Rd, pt, x, xd, [0] * (n + 3), b) for pt in pts]
    post_v = lambda thd_, qd_: [kcall(K, K.Rd, pt, x0, xe, th, q, thd_, qd_, 0, [0] * n, b) for pt in pts]
    pre = conserved(vm)
    base0 = conserved(post_v(0, [0] * n))
    cols = []
    for kk in range(n + 1):
        e = [0] * (n + 1)
        e[kk] = 1
        ck = conserved(post_v(e[0], e[1:]))
        cols.append([ck[i] - base0[i] for i in range(n + 1)])
    A = mp.matrix([[cols[j][i] for j in range(n + 1)] for i in range(n + 1)])
    sol = solve_lin(A, mp.matrix([pre[i] - base0[i] for i in range(n + 1)]))
    thdp, qdp = sol[0], [sol[i + 1] for i in range(n)]
    # closed form from the flight state (c.g. velocity from the masses)
    vc = [sum(pt[0] * (v_[i] - vb[i]) for pt, v_ in zip(pts, vm)) / M for i in range(2)]
    vt = tuple(a / h for a in rotT(vc, th))
    thdm, qdm = xd[2], xd[3:]
    Ae, rhs = conv_landing_system(P, ae, q, vt, thdm, qdm)
    solc = solve_lin(mp.matrix(Ae), mp.matrix(rhs))
    chk.eq([thdp] + qdp, [solc[i] for i in range(n + 1)], what + ' map')
    # H_P- relative to the base (the base velocity's share, M (r_c - r_P) x V_b, is the same after)
    rc = [sum(pt[0] * FK.call(FK.Rrel, pt, x, xd, [0] * (n + 3), b)[i] for pt in pts) / M for i in range(2)]
    chk.eq(pre[0] - M * ((rc[0] - xe) * vb[1] - rc[1] * vb[0]), M * h * h * rhs[0], what + ' H_P-')
    vp = post_v(thdp, qdp)
    Lam = [sum(pt[0] * (vp_[i] - vm_[i]) for pt, vp_, vm_ in zip(pts, vp, vm)) for i in range(2)]
    dT = sum(pt[0] * (vp_[0] ** 2 + vp_[1] ** 2 - vm_[0] ** 2 - vm_[1] ** 2) / 2 for pt, vp_, vm_ in zip(pts, vp, vm))
    E = vb[0] * Lam[0] + vb[1] * Lam[1] - dT
    chk.eq(Lam, conv_landing_impulse(P, ae, q, vt, thdp, qdp, s, c), what + ' impulse')
    Be = conv_B(P, ae, q)
    nup = [thdp] + qdp
    vtp = (dot(Be[0], nup), dot(Be[1], nup))
    chk.eq(E, conv_landing_loss(P, q, vt, [thdm] + list(qdm), vtp, nup), what + ' energy loss')
    assert E > -mp.mpf('1e-20') * M * G * h, 'negative landing loss'
    # the generic form: the generalized momenta of the flight coordinates jump by J_e^T Lambda
    xdp = [thdp * ce[1], -thdp * ce[0], thdp] + qdp
    for pt, v_ in zip(pts, vp):
        chk.eq(FK.call(FK.Rd, pt, x, xdp, [0] * (n + 3), b), v_, what + ' post velocity (flight coords)')
    dpi = [mp.mpf(0)] * (n + 3)
    for pt, vp_, vm_ in zip(pts, vp, vm):
        Jm = FK.call(FK.Jac, pt, x, xd, [0] * (n + 3), b)
        for i in range(n + 3):
            dpi[i] += pt[0] * ((vp_[0] - vm_[0]) * Jm[0, i] + (vp_[1] - vm_[1]) * Jm[1, i])
    JT = [Lam[0], Lam[1], -ce[1] * Lam[0] + ce[0] * Lam[1]] + [0] * n
    chk.eq(dpi, JT, what + ' A_f dnu = J_e^T Lambda')
    # Schur form: S_e thd+ = H^_e = rhs_0 - b_e^T mu^-1 rhs_q
    be = conv_b(P, ae, q)
    Hhat = rhs[0] - (dot(be, mu_solve(P, rhs[1:])) if n else 0)
    chk.eq(thdp * schur(P, ae, q), Hhat, what + ' Schur form')
    # sticking: the impulse stops the corner, Lambda = -W^-1 v_e- (v_e- relative to the base)
    ve = conv_corner_vel(P, ae, q, vc, thdm, qdm, s, c)
    chk.eq(solve_lin(W_corner(P, ae, q, th), mp.matrix([-ve[0], -ve[1]])), Lam, what + ' Lambda = -W^-1 v_e')
    stats['landings'] += 1
    if Lam[1] < 0:
        stats['tensile_landing'] += 1
    return dict(edge=edge, theta=th, q=q, cg_velocity=vc, theta_dot_minus=thdm, q_dot_minus=list(qdm),
                base_velocity=list(vb), theta_dot_plus=thdp, q_dot_plus=qdp, impulse=Lam, energy_loss=E)


def flat_landing(K, FK, body, d, q, vd_, thd, qd, vb, chk, stats):
    """flight at theta = 0 with both corners on the floor; O' at (d, 0); vd_ = (ud, vd)."""
    n, P, M, h = body.n, body.P, body.M, body.h
    x, xd = [d, 0, 0] + list(q), [vd_[0], vd_[1], thd] + list(qd)
    b = [vb[0], vb[1], 0, 0, G]
    pts = list(body.pts())
    vm = [FK.call(FK.Rd, pt, x, xd, [0] * (n + 3), b) for pt in pts]
    pvel = lambda qd_: [FK.call(FK.Rd, pt, x, [0, 0, 0] + list(qd_), [0] * (n + 3), b) for pt in pts]

    def moms(vels, xe):
        out = [mp.mpf(0)] * (n + 1)
        for pt, v_ in zip(pts, vels):
            m = pt[0]
            r = FK.call(FK.Rrel, pt, x, xd, [0] * (n + 3), b)
            out[0] += m * ((r[0] - xe) * v_[1] - r[1] * v_[0])
            for j in range(n):
                out[j + 1] += m * (pt[3][j] * v_[0] + pt[4][j] * v_[1])
        return out
    vc = [sum(pt[0] * (v_[i] - vb[i]) for pt, v_ in zip(pts, vm)) / M for i in range(2)]
    vt = (vc[0] / h, vc[1] / h)
    prhs = conv_flat_landing_rhs(P, q, vt, thd, qd)
    if n:
        pre = moms(vm, 0)
        b0 = moms(pvel([0] * n), 0)
        cols = []
        for kk in range(n):
            e = [0] * n
            e[kk] = 1
            ck = moms(pvel(e), 0)
            cols.append([ck[i + 1] - b0[i + 1] for i in range(n)])
        A = mp.matrix([[cols[j][i] for j in range(n)] for i in range(n)])
        sol = solve_lin(A, mp.matrix([pre[i + 1] - b0[i + 1] for i in range(n)]))
        qdp = [sol[i] for i in range(n)]
        chk.eq(qdp, mu_solve(P, prhs), 'flat landing qd+')
    else:
        qdp = []
    vp = pvel(qdp)
    Lam = [sum(pt[0] * (vp_[i] - vm_[i]) for pt, vp_, vm_ in zip(pts, vp, vm)) for i in range(2)]
    dT = sum(pt[0] * (vp_[0] ** 2 + vp_[1] ** 2 - vm_[0] ** 2 - vm_[1] ** 2) / 2 for pt, vp_, vm_ in zip(pts, vp, vm))
    E = vb[0] * Lam[0] + vb[1] * Lam[1] - dT
    chk.eq(Lam, conv_landing_impulse(P, 0, q, vt, 0, qdp, 0, 1), 'flat landing impulse')
    vtp = (dot(P['psi_x'], qdp), dot(P['psi_y'], qdp))
    chk.eq(E, conv_landing_loss(P, q, vt, [thd] + list(qd), vtp, [0] + qdp), 'flat landing loss')
    assert E > -mp.mpf('1e-20') * M * G * h, 'negative flat landing loss'
    # split of the vertical impulse: moments about each corner
    Hh = {}
    for e in (1, 2):
        ae = alpha_of(body, e)
        Ae, rhs = conv_landing_system(P, ae, q, vt, thd, qd)
        Hh[e] = rhs[0] - (dot(conv_b(P, ae, q), mu_solve(P, rhs[1:])) if n else 0)
    L = {}
    for e, o in ((1, 2), (2, 1)):
        xe, xo = d + h * alpha_of(body, e), d + h * alpha_of(body, o)
        L[o] = (moms(vp, xe)[0] - moms(vm, xe)[0]) / (xo - xe)  # vertical impulse at corner o
        chk.eq(L[o], -M * h * Hh[e] / (alpha_of(body, o) - alpha_of(body, e)), 'flat landing corner impulse')
    chk.eq(L[1] + L[2], Lam[1], 'flat landing vertical impulse split')
    Vhat = vt[1] - (dot(P['psi_y'], mu_solve(P, prhs)) if n else 0)
    chk.eq(Lam[1], -M * h * Vhat, 'flat landing vertical impulse = -M h Vhat')
    chk.eq(Hh[1] - Hh[2], (body.alpha1 + body.alpha2) * Vhat, 'H^_1 - H^_2 = (alpha1 + alpha2) Vhat')
    both_comp = L[1] >= 0 and L[2] >= 0
    assert both_comp == (Hh[1] <= 0 <= Hh[2]), 'flat landing rule'
    stats['flat'] += 1
    if both_comp:
        stats['flat_compressive'] += 1
    if Hh[1] > 0 and Hh[2] < 0:
        stats['both_single_admissible'] += 1
    return dict(d=d, q=q, cg_velocity=vc, theta_dot_minus=thd, q_dot_minus=list(qd), base_velocity=list(vb),
                q_dot_plus=qdp, impulse=Lam, corner_impulse_y=[L[1], L[2]], H_hat=[Hh[1], Hh[2]],
                energy_loss=E)


def rigid_liftoff_condition(K, FK, chk):
    """a rigid block rocking on edge 1 with F_J = 0: the corner's flight acceleration is
    h thdd_rock X = -g X (X a_y - Y a_x) / (1 + zeta2 + alpha1^2), (X, Y) = R(theta) w_1;
    <= 0 under gravity alone (no consistent lift-off with a sticking corner)."""
    sq = squat_block()
    b = Body(0, sq.m, [(p[0] / 4, p[1]) for p in sq.pos], [[] for _ in range(4)], [], sq.b1 / 4, sq.b2 / 4,
             'rigid block b/h=0.5')
    st = dict(liftoff=0)
    out = []
    for th, ax in ((mp.mpf('0.6'), mp.mpf('-0.3')), (mp.mpf('1.0'), mp.mpf(0)), (mp.mpf('1.4'), mp.mpf(0))):
        base = [ax * G, 0]
        FJ = lambda thd: liftoff(K, FK, b, 1, 0, th, [], thd, [], base, chk, st)['reaction'][1] / (b.M * G)
        thd = mp.findroot(FJ, mp.mpf(3))
        r = liftoff(K, FK, b, 1, 0, th, [], thd, [], base, chk, st)
        w = rot(conv_w(b.P, -b.alpha1, []), th)
        k_ = 1 + b.P['zeta2'] + b.alpha1 ** 2
        yddot = r['flight_corner_acceleration'][1]
        chk.eq(yddot, b.h * r['rocking_accelerations'][0] * w[0], 'rigid lift-off: h thdd X')
        chk.eq(yddot, -G * w[0] * (w[0] - w[1] * ax) / k_, 'rigid lift-off corner acceleration')
        assert (yddot < 0) == (ax == 0), 'rigid lift-off sign'
        out.append((float(th), float(ax), float(yddot)))
    return out


def flight_cases(K, FK, body, rng, chk, stats):
    n, P, h = body.n, body.P, body.h
    u = lambda a, b: mpf(rng.uniform(a, b))
    sgh = mp.sqrt(G * h)
    fl, lo, la, fla = [], [], [], []
    for i in range(3):
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        fl.append(flight_state(FK, body, u(-0.5, 0.5), q, u(-0.3, 0.3) * h, u(0, 0.2) * h, u(-0.5, 0.5) * sgh,
                               u(-0.5, 0.5) * sgh, u(-1.5, 1.5), qd,
                               [u(-0.5, 0.5), u(-0.5, 0.5), u(-0.3, 0.3) * G, u(-0.3, 0.3) * G], chk))
    for edge in (1, 2):
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        th = u(0.005, 0.6) * (1 if edge == 1 else -1)
        lo.append(liftoff(K, FK, body, edge, u(-0.2, 0.2) * h, th, q, u(-1.5, 1.5), qd,
                          [u(-0.3, 0.3) * G, u(-0.3, 0.3) * G], chk, stats))
    for i in range(4):
        edge = 1 + i % 2
        sg = 1 if edge == 1 else -1
        ae = alpha_of(body, edge)
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        vb = [u(-0.5, 0.5), u(-0.5, 0.5)]
        if i < 2:  # a free landing at a tilt, the corner coming down
            th = u(0.0, 0.4) * sg
            thd = u(-1.5, 1.5)
            ce = rot((h * ae, 0), th)
            vd = -thd * ce[0] - u(0.05, 1.0) * sgh
            x = [u(-0.2, 0.2) * h - ce[0], -ce[1], th] + q
            xd = [u(-0.5, 0.5) * sgh, vd, thd] + qd
            la.append(landing(K, FK, body, edge, 0, th, q, x, xd, vb, chk, stats))
        else:  # rocking on the other edge at theta = 0 -> the impact map of theory 8
            other = 2 if edge == 1 else 1
            thdm = u(0.05, 1.5) * sg
            d = u(-0.2, 0.2) * h
            ao = alpha_of(body, other)
            (xc, yc), vc = conv_liftoff(P, ao, d + h * ao, q, thdm, qd, 0, 1)
            x = [d, 0, 0] + q
            xd = [thdm * 0, -thdm * h * ao, thdm] + qd
            r = landing(K, FK, body, edge, d, 0, q, x, xd, vb, chk, stats, 'landing at theta=0')
            chk.eq(r['cg_velocity'], vc, 'rocking state as flight state')
            Ai, rhs = conv_impact_system(P, ao, ae, q, thdm, qd)
            s8 = solve_lin(mp.matrix(Ai), mp.matrix(rhs))
            chk.eq([r['theta_dot_plus']] + r['q_dot_plus'], [s8[k] for k in range(n + 1)],
                   'landing = impact map of theory 8')
            la.append(r)
    for i in range(2):
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        thd = u(-1.0, 1.0)
        vd = min(h * body.alpha1 * thd, -h * body.alpha2 * thd) - u(0.05, 1.0) * sgh
        fla.append(flat_landing(K, FK, body, u(-0.2, 0.2) * h, q, (u(-0.5, 0.5) * sgh, vd), thd, qd,
                                [u(-0.5, 0.5), u(-0.5, 0.5)], chk, stats))
    return dict(flight=fl, liftoff=lo, landings=la, flat_landings=fla)


# --- Coulomb friction: direct point-mass mechanics of the sliding modes and impacts ---------------

def mu_quad(P, a, b):
    """a^T mu^-1 b."""
    return dot(a, mu_solve(P, b)) if P['n'] else mp.mpf(0)


def conv_k_slide_full(P, sg, mu_k):
    """k_s / M in full contact: (1 - psi_x^T mu^-1 psi_x) - s mu_k psi_y^T mu^-1 psi_x."""
    return 1 - mu_quad(P, P['psi_x'], P['psi_x']) - sg * mu_k * mu_quad(P, P['psi_y'], P['psi_x'])


def conv_Winv(P, alpha, q, th):
    """W^-1 = M (I - R B A^-1 B^T R^T): the floor force per unit acceleration of the tipping point."""
    n, M = P['n'], P['M']
    A = mp.matrix(conv_A(P, alpha, q))
    B = conv_B(P, alpha, q)
    Bm = mp.matrix([[B[i][j] for j in range(n + 1)] for i in range(2)])
    s, c = mp.sin(th), mp.cos(th)
    R = mp.matrix([[c, -s], [s, c]])
    return M * (mp.eye(2) - R * Bm * mp.inverse(A) * Bm.T * R.T)


def conv_k_slide_rock(P, alpha, q, th, sg, mu_k):
    """k_s / M while rocking: (W^-1_II + s mu_k W^-1_JI) / M."""
    Wi = conv_Winv(P, alpha, q, th)
    return (Wi[0, 0] + sg * mu_k * Wi[1, 0]) / P['M']


def conv_slide_rock(P, alpha, q, th, thd, qd, ax, ay, g, sg, mu_k):
    """rocking with the pivot sliding (sign sg): d_ddot = -(F_I0 + s mu_k F_J0) / k_s, then theory 4
    and 5 with a_x -> a_x + d_ddot / g."""
    n, M = P['n'], P['M']
    s, c = mp.sin(th), mp.cos(th)
    A = mp.matrix(conv_A(P, alpha, q))

    def state(axx):
        nudd = solve_lin(A, mp.matrix(conv_f(P, alpha, q, thd, qd, s, c, axx, ay, g)))
        nudd = [nudd[i] for i in range(n + 1)]
        F = body_to_inertial(conv_F_body(P, alpha, q, thd, qd, nudd[0], nudd[1:], s, c, axx, ay, g), s, c)
        return nudd, F
    _, F0 = state(ax)
    k = M * conv_k_slide_rock(P, alpha, q, th, sg, mu_k)
    ddd = -(F0[0] + sg * mu_k * F0[1]) / k
    nudd, F = state(ax + ddd / g)
    return ddd, nudd, F, k


def conv_slide_full(P, q, qd, ax, ay, g, sg, mu_k):
    """full contact sliding: mu qdd = -(g/h)(kappa q + psi_x (a_x + d_ddot/g) + psi_y a_y)."""
    n, M, h = P['n'], P['M'], P['h']

    def state(axx):
        qdd = mu_solve(P, [-(g / h) * (dot(P['kappa'][j], q) + P['psi_x'][j] * axx + P['psi_y'][j] * ay)
                           for j in range(n)]) if n else []
        F = (M * g * axx + M * h * dot(P['psi_x'], qdd), M * g * ay + M * h * dot(P['psi_y'], qdd))
        return qdd, F
    _, F0 = state(ax)
    k = M * conv_k_slide_full(P, sg, mu_k)
    ddd = -(F0[0] + sg * mu_k * F0[1]) / k
    qdd, F = state(ax + ddd / g)
    return ddd, qdd, F, k


def conv_friction_impact(P, alpha_e, q, th, nu_m, Vm, mu_s, mu_k):
    """impact of the tipping point alpha_e with Coulomb friction (plastic normal part).
    nu_m = (theta_dot, q_dot) before, Vm the tipping point's velocity before (inertial components,
    relative to the floor).  A_e nu+ + L(V+) = A_e nu- + L(V-), V+ = d_dot+ I; the impulse
    Lambda = M (v_c+ - v_c-) is affine in d_dot+.  Returns (mode, sg, d_dot+, nu+, Lambda)."""
    n, M, h = P['n'], P['M'], P['h']
    s, c = mp.sin(th), mp.cos(th)
    A = mp.matrix(conv_A(P, alpha_e, q))
    B = conv_B(P, alpha_e, q)
    Vmb = rotT(Vm, th)
    rhs0 = [dot(conv_A(P, alpha_e, q)[i], nu_m) + conv_L(P, alpha_e, q, Vmb)[i] for i in range(n + 1)]
    vcm = [Vm[i] + h * rot((dot(B[0], nu_m), dot(B[1], nu_m)), th)[i] for i in range(2)]

    def post(ddp):
        Vp = (ddp * c, -ddp * s)
        Lp = conv_L(P, alpha_e, q, Vp)
        nu = solve_lin(A, mp.matrix([rhs0[i] - Lp[i] for i in range(n + 1)]))
        nu = [nu[i] for i in range(n + 1)]
        vr = rot((dot(B[0], nu), dot(B[1], nu)), th)
        Lam = [M * ((ddp if i == 0 else 0) + h * vr[i] - vcm[i]) for i in range(2)]
        return nu, Lam
    nu0, L0 = post(0)
    if L0[1] >= 0 and abs(L0[0]) <= mu_s * L0[1]:
        return 'stick', 0, mp.mpf(0), nu0, L0
    sg = -1 if L0[0] > 0 else 1
    Wi = conv_Winv(P, alpha_e, q, th)
    k = Wi[0, 0] + sg * mu_k * Wi[1, 0]  # d Lambda / d d_dot+ = W^-1 I
    ddp = -(L0[0] + sg * mu_k * L0[1]) / k
    nu, Lam = post(ddp)
    return 'slip', sg, ddp, nu, Lam


def slide_direct(K, body, x0, ex, th, q, thd, qd, dd, base, sg, mu_k, full=False):
    """sliding state from the point masses: unknowns (d_ddot, theta_ddot, q_ddot) [full contact:
    (d_ddot, q_ddot)]; the theta- and q-rows of the masses with the base acceleration X_ddot + d_ddot,
    and Coulomb F_I + s mu_k F_J = 0 with F = sum m R_ddot + M g J.  x0: the pivot's abscissa from O'."""
    n, M = body.n, body.M
    pts = list(body.pts())

    # everything is affine in the accelerations: evaluate at the origin and the unit vectors
    def residual(xacc):
        ddd, thdd, qdd = xacc[0], xacc[1], list(xacc[2:])
        b = [dd, 0, base[0] + ddd, base[1], G]
        EL = [mp.mpf(0)] * (n + 1)
        F = [mp.mpf(0), M * G]
        for pt in pts:
            e0 = kcall(K, K.EL0, pt, x0, ex, th, q, thd, qd, 0, [0] * n, b)
            eA = kcall(K, K.ELA, pt, x0, ex, th, q, thd, qd, 0, [0] * n, b)
            acc = [thdd] + qdd
            for i in range(n + 1):
                EL[i] += e0[i] + sum(eA[i, j] * acc[j] for j in range(n + 1))
            a_ = kcall(K, K.Rdd, pt, x0, ex, th, q, thd, qd, thdd, qdd, b)
            F[0] += pt[0] * a_[0]
            F[1] += pt[0] * a_[1]
        for j in range(n):
            EL[j + 1] += sum(body.k[j][i] * q[i] for i in range(n))
        out = ([EL[i] for i in range(1 if full else 0, n + 1)] + [F[0] + sg * mu_k * F[1]])
        return out, F
    N = n + 2
    z = [mp.mpf(0)] * N
    r0, _ = residual(z)
    cols = []
    for kk in range(N):
        if full and kk == 1:
            continue
        e = list(z)
        e[kk] = mp.mpf(1)
        rk, _ = residual(e)
        cols.append([rk[i] - r0[i] for i in range(len(r0))])
    Am = mp.matrix([[cols[j][i] for j in range(len(cols))] for i in range(len(r0))])
    sol = solve_lin(Am, mp.matrix([-x for x in r0]))
    sol = [sol[i] for i in range(len(cols))]
    xacc = [sol[0], mp.mpf(0)] + sol[1:] if full else sol
    _, F = residual(xacc)
    return xacc, F


def slide_energy_direct(K, body, x0, ex, th, q, thd, qd, dd, base, xacc):
    """T relative to the floor, V, and d/dt (T + V) from the masses."""
    n, M = body.n, body.M
    ddd, thdd, qdd = xacc[0], xacc[1], list(xacc[2:])
    b = [dd, 0, base[0] + ddd, base[1], G]
    T = mp.mpf(0)
    V = sum(q[i] * body.k[i][j] * q[j] for i in range(n) for j in range(n)) / 2
    dE = sum(q[i] * body.k[i][j] * qd[j] for i in range(n) for j in range(n))
    vcm = [mp.mpf(0)] * 2
    for pt in body.pts():
        m = pt[0]
        v_ = kcall(K, K.Rd, pt, x0, ex, th, q, thd, qd, thdd, qdd, b)  # relative to the floor
        a_ = kcall(K, K.Rdd, pt, x0, ex, th, q, thd, qd, thdd, qdd, b)  # inertial
        r_ = kcall(K, K.Rrel, pt, x0, ex, th, q, thd, qd, thdd, qdd, b)
        T += m * (v_[0] ** 2 + v_[1] ** 2) / 2
        V += m * G * r_[1]
        dE += m * (v_[0] * (a_[0] - base[0]) + v_[1] * (a_[1] - base[1]) + G * v_[1])
        vcm = [vcm[i] + m * v_[i] / M for i in range(2)]
    return T, V, dE, vcm


def sliding_cases(K, body, rng, chk, stats):
    """rocking with a sliding pivot and full-contact sliding: closed forms against the masses."""
    n, P, M, h = body.n, body.P, body.M, body.h
    u = lambda a, b: mpf(rng.uniform(a, b))
    sgh = mp.sqrt(G * h)
    out_r, out_f = [], []
    for i in range(4):
        edge = 1 + i % 2
        ae = alpha_of(body, edge)
        x0 = h * ae
        th = u(0.0, 0.4) * (1 if edge == 1 else -1)
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        thd = u(-1.5, 1.5)
        sg = 1 if i < 2 else -1
        dd = sg * u(0.01, 0.5) * sgh
        mu_k = u(0.05, 0.6)
        base = [u(-0.3, 0.3) * G, u(-0.3, 0.3) * G]
        xacc, F = slide_direct(K, body, x0, x0 + u(-0.2, 0.2) * h, th, q, thd, qd, dd, base, sg, mu_k)
        ax, ay = base[0] / G, 1 + base[1] / G
        ddd, nudd, Fc, k = conv_slide_rock(P, ae, q, th, thd, qd, ax, ay, G, sg, mu_k)
        chk.eq(xacc, [ddd] + nudd, 'sliding rocking accelerations')
        chk.eq(F, Fc, 'sliding rocking reaction')
        chk.eq(F[0], -sg * mu_k * F[1], 'sliding rocking Coulomb')
        # k_s: the d_ddot-coefficient of F_I + s mu_k F_J with the rows solved, from the closed forms
        d1 = conv_slide_rock(P, ae, q, th, thd, qd, ax + 1 / G, ay, G, sg, mu_k)
        _, _, Fa, _ = conv_slide_rock(P, ae, q, th, thd, qd, ax, ay, G, sg, mu_k)
        # W^-1 = M (I - R B A^-1 B^T R^T) = (M W_corner)^-1 ... (theory 15): Woodbury
        chk.eq([x for x in conv_Winv(P, ae, q, th)], [x for x in mp.inverse(W_corner(P, ae, q, th))], 'W^-1 (Woodbury)')
        if n == 0:  # rigid: k_s = (M / A)(zeta^2 + X^2 + s mu_k X Y), (X, Y) = R(theta) w
            X, Y = rot(conv_w(P, ae, []), th)
            chk.eq(k, M * (P['zeta2'] + X ** 2 + sg * mu_k * X * Y) / (1 + P['zeta2'] + ae ** 2), 'rigid k_s')
        # energy: d/dt (T + V) = -M a_b . (v_cm + d_dot I) + F_I d_dot = input - mu_k F_J |d_dot|
        T, V, dE, vcm = slide_energy_direct(K, body, x0, x0, th, q, thd, qd, dd, base, xacc)
        s, c = mp.sin(th), mp.cos(th)
        chk.eq(T, conv_T_slide(P, ae, q, thd, qd, dd, s, c), 'sliding T')
        vc_rel = body_to_inertial(conv_vcm_body(P, ae, q, thd, qd), s, c)
        chk.eq(vcm, [vc_rel[0] + dd, vc_rel[1]], 'sliding c.g. velocity')
        inp = -M * (base[0] * (vc_rel[0] + dd) + base[1] * vc_rel[1])
        chk.eq(dE, inp + F[0] * dd, 'sliding energy rate')
        chk.eq(dE, inp - mu_k * F[1] * abs(dd), 'sliding energy rate (friction dissipation)')
        stats['slide_rock'] += 1
        if k <= 0:
            stats['k_nonpositive'] += 1
        out_r.append(dict(edge=edge, theta=th, q=q, theta_dot=thd, q_dot=qd, d_dot=dd, slip_sign=sg, mu_k=mu_k,
                          base_acc=base, d_ddot=ddd, accelerations=nudd, reaction=F, k_s=k, kinetic_energy=T,
                          energy_rate=dE))
    for i in range(2):
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        sg = 1 - 2 * i
        dd = sg * u(0.01, 0.5) * sgh
        mu_k = u(0.05, 0.6)
        base = [u(-0.3, 0.3) * G, u(-0.3, 0.3) * G]
        x0 = -body.b1
        xacc, F = slide_direct(K, body, x0, x0, 0, q, 0, qd, dd, base, sg, mu_k, full=True)
        ax, ay = base[0] / G, 1 + base[1] / G
        ddd, qdd, Fc, k = conv_slide_full(P, q, qd, ax, ay, G, sg, mu_k)
        chk.eq([xacc[0]] + xacc[2:], [ddd] + qdd, 'full contact sliding accelerations')
        chk.eq(F, Fc, 'full contact sliding reaction')
        # the resultant of the sliding base (moment about the moving c.g. projection) = theory 6, a_x + d_ddot/g
        mom = mp.mpf(0)
        b = [dd, 0, base[0] + ddd, base[1], G]
        for pt in body.pts():
            a_ = kcall(K, K.Rdd, pt, x0, x0, 0, q, 0, qd, 0, qdd, b)
            r_ = kcall(K, K.Rrel, pt, x0, x0, 0, q, 0, qd, 0, qdd, b)
            mom += pt[0] * (r_[0] * (a_[1] + G) - r_[1] * a_[0])
        num, den = conv_alpha_star_parts(P, q, qdd, ax + ddd / G, ay, G)
        chk.eq(mom / (h * F[1]), num / den, 'sliding resultant')
        U1 = den * (num / den + body.alpha1)
        U2 = den * (body.alpha2 - num / den)
        # uplift while sliding: rocking-sliding on edge e at theta = thd = 0 has
        #   theta_ddot = -+ (g/h) U_e k_fc / (S_e k_rock)  (U_e, k_fc of full-contact sliding)
        for edge, U, sgn in ((1, U1, -1), (2, U2, 1)):
            ae = alpha_of(body, edge)
            dr, nr, _, kr = conv_slide_rock(P, ae, q, 0, 0, qd, ax, ay, G, sg, mu_k)
            chk.eq(nr[0], sgn * (G / h) * U * k / (schur(P, ae, q) * kr), 'uplift while sliding')
        T, V, dE, vcm = slide_energy_direct(K, body, x0, x0, 0, q, 0, qd, dd, base, xacc)
        chk.eq(T, conv_T_slide(P, 0, q, 0, qd, dd, 0, 1), 'full contact sliding T')
        inp = -M * (base[0] * vcm[0] + base[1] * vcm[1])
        chk.eq(dE, inp - mu_k * F[1] * abs(dd), 'full contact sliding energy rate')
        stats['slide_full'] += 1
        out_f.append(dict(q=q, q_dot=qd, d_dot=dd, slip_sign=sg, mu_k=mu_k, base_acc=base, d_ddot=ddd,
                          q_ddot=qdd, reaction=F, k_s=k, resultant=num / den, kinetic_energy=T, energy_rate=dE))
    return out_r, out_f


def friction_landing(K, FK, body, edge, th, q, x, xd, vb, mu_s, mu_k, chk, stats, what='friction landing'):
    """flight state (x, xd) in (u, v, theta, q) with corner `edge` on the floor; plastic impact with
    Coulomb friction.  From the masses: for a given d_dot+ the post state (rocking on `edge`, the corner
    sliding at d_dot+ I) follows from the moment of momentum about the corner and the modal momenta;
    the impulse is the change of momentum (affine in d_dot+); Coulomb's law picks d_dot+."""
    n, P, M, h = body.n, body.P, body.M, body.h
    ae = alpha_of(body, edge)
    x0 = h * ae
    ce = rot((x0, 0), th)
    xe = x[0] + ce[0]
    b = [vb[0], vb[1], 0, 0, G]
    pts = list(body.pts())

    def phi_in(pt, j):
        return rot((pt[3][j], pt[4][j]), th)

    def conserved(vels):
        out = [mp.mpf(0)] * (n + 1)
        for pt, v_ in zip(pts, vels):
            r = FK.call(FK.Rrel, pt, x, xd, [0] * (n + 3), b)
            out[0] += pt[0] * ((r[0] - xe) * v_[1] - r[1] * v_[0])
            for j in range(n):
                ph = phi_in(pt, j)
                out[j + 1] += pt[0] * (ph[0] * v_[0] + ph[1] * v_[1])
        return out
    vm = [FK.call(FK.Rd, pt, x, xd, [0] * (n + 3), b) for pt in pts]
    pre = conserved(vm)

    def post(ddp):
        bp = [vb[0] + ddp, vb[1], 0, 0, G]
        pv = lambda thd_, qd_: [kcall(K, K.Rd, pt, x0, xe, th, q, thd_, qd_, 0, [0] * n, bp) for pt in pts]
        b0 = conserved(pv(0, [0] * n))
        cols = []
        for kk in range(n + 1):
            e = [0] * (n + 1)
            e[kk] = 1
            ck = conserved(pv(e[0], e[1:]))
            cols.append([ck[i] - b0[i] for i in range(n + 1)])
        A = mp.matrix([[cols[j][i] for j in range(n + 1)] for i in range(n + 1)])
        sol = solve_lin(A, mp.matrix([pre[i] - b0[i] for i in range(n + 1)]))
        nu = [sol[i] for i in range(n + 1)]
        vp = pv(nu[0], nu[1:])
        Lam = [sum(pt[0] * (vp_[i] - vm_[i]) for pt, vp_, vm_ in zip(pts, vp, vm)) for i in range(2)]
        dT = sum(pt[0] * (vp_[0] ** 2 + vp_[1] ** 2 - vm_[0] ** 2 - vm_[1] ** 2) / 2
                 for pt, vp_, vm_ in zip(pts, vp, vm))
        return nu, Lam, vb[0] * Lam[0] + vb[1] * Lam[1] - dT
    nu0, L0, E0 = post(0)
    nu1, L1, _ = post(1)
    dL = [L1[i] - L0[i] for i in range(2)]
    Wi = conv_Winv(P, ae, q, th)
    chk.eq(dL, [Wi[0, 0], Wi[1, 0]], what + ': dLambda/dd_dot+ = W^-1 I')
    if L0[1] >= 0 and abs(L0[0]) <= mu_s * L0[1]:
        mode, sg, ddp, nu, Lam, E = 'stick', 0, mp.mpf(0), nu0, L0, E0
    else:
        mode, sg = 'slip', (-1 if L0[0] > 0 else 1)
        ks = dL[0] + sg * mu_k * dL[1]
        ddp = -(L0[0] + sg * mu_k * L0[1]) / ks
        nu, Lam, E = post(ddp)
        if ks > 0:
            assert ddp * sg > 0 and Lam[1] > 0, what + ': sliding impact inconsistent with k_s > 0'
            # Moreau: the slip solution is unique (the other slip sign gives no solution)
            ko = dL[0] - sg * mu_k * dL[1]
            do = -(L0[0] - sg * mu_k * L0[1]) / ko
            assert not (do * (-sg) > 0 and (L0[1] + do * dL[1]) > 0 and ko > 0), what + ': two slip solutions'
        else:
            stats['impact_k_nonpositive'] += 1
    # the closed-form law (design: A_e nu+ + L(V+) = A_e nu- + L(V-))
    vc = [sum(pt[0] * (v_[i] - vb[i]) for pt, v_ in zip(pts, vm)) / M for i in range(2)]
    thdm, qdm = xd[2], list(xd[3:])
    s, c = mp.sin(th), mp.cos(th)
    Vm = conv_corner_vel(P, ae, q, vc, thdm, qdm, s, c)
    mode_c, sg_c, ddp_c, nu_c, Lam_c = conv_friction_impact(P, ae, q, th, [thdm] + qdm, Vm, mu_s, mu_k)
    assert mode_c == mode and sg_c == sg, what + ': stick / slip decision'
    chk.eq([ddp] + nu + Lam, [ddp_c] + nu_c + Lam_c, what + ' map and impulse')
    # loss: E = 1/2 Lambda^T W Lambda - Lambda . V+ = 1/2 Lambda^T W Lambda + mu_k Lambda_J |d_dot+| >= 0
    W = W_corner(P, ae, q, th)
    quad = sum(Lam[i] * W[i, j] * Lam[j] for i in range(2) for j in range(2)) / 2
    chk.eq(E, quad - Lam[0] * ddp, what + ' energy loss')
    if mode == 'slip':
        chk.eq(E, quad + mu_k * Lam[1] * abs(ddp), what + ' energy loss (friction)')
    assert E > -mp.mpf('1e-20') * M * G * h, what + ': negative loss'
    # mu = infinity: the sticking law of theory 16
    Ae, rhs = conv_landing_system(P, ae, q, tuple(a / h for a in rotT(vc, th)), thdm, qdm)
    sl = solve_lin(mp.matrix(Ae), mp.matrix(rhs))
    chk.eq(nu0, [sl[i] for i in range(n + 1)], what + ': stick = theory 16')
    stats['friction_landings'] += 1
    stats['mode_' + mode] += 1
    if L0[1] < 0:
        stats['tensile_stick'] += 1
        if mode == 'slip' and Lam[1] > 0:
            stats['tensile_resolved'] += 1
    # the rigid_body law (theory 21) at the same state: the body is rigid during the impact, q_dot+ = q_dot-,
    # and only the moment of momentum about the corner is conserved (the rigidifying impulses are internal);
    # for each d_dot+ from the masses, then Coulomb's law on the impulse as above
    def post_rigid(ddp_):
        bp = [vb[0] + ddp_, vb[1], 0, 0, G]
        pv = lambda thd_: [kcall(K, K.Rd, pt, x0, xe, th, q, thd_, qdm, 0, [0] * n, bp) for pt in pts]
        h0, h1 = conserved(pv(0))[0], conserved(pv(1))[0]
        thdp = (pre[0] - h0) / (h1 - h0)
        vp = pv(thdp)
        Lr = [sum(pt[0] * (vp_[i] - vm_[i]) for pt, vp_, vm_ in zip(pts, vp, vm)) for i in range(2)]
        dT = sum(pt[0] * (vp_[0] ** 2 + vp_[1] ** 2 - vm_[0] ** 2 - vm_[1] ** 2) / 2
                 for pt, vp_, vm_ in zip(pts, vp, vm))
        return thdp, Lr, vb[0] * Lr[0] + vb[1] * Lr[1] - dT
    rt0, rL0, rE0 = post_rigid(0)
    _, rL1, _ = post_rigid(1)
    rdL = [rL1[i] - rL0[i] for i in range(2)]
    rmode, rsg, rddp, rthd, rLam, rE, rok = 'stick', 0, mp.mpf(0), rt0, rL0, rE0, True
    if not (rL0[1] >= 0 and abs(rL0[0]) <= mu_s * rL0[1]):
        rmode, rsg = 'slip', (-1 if rL0[0] > 0 else 1)
        ks = rdL[0] + rsg * mu_k * rdL[1]
        rddp = -(rL0[0] + rsg * mu_k * rL0[1]) / ks
        rok = ks > 0
        rthd, rLam, rE = post_rigid(rddp)
        chk.eq(rLam[0], -rsg * mu_k * rLam[1], what + ' (rigid_body): impulse on the cone')
    stats['rigid_body_' + rmode] += 1
    stats['rigid_body_gain'] += rE < 0
    rigid = dict(mode=rmode, slip_sign=rsg, consistent=int(bool(rok)), d_dot_plus=rddp, theta_dot_plus=rthd,
                 impulse=rLam, stick_impulse=rL0, energy_loss=rE)
    return dict(edge=edge, theta=th, q=q, cg_velocity=vc, theta_dot_minus=thdm, q_dot_minus=qdm,
                corner_velocity_minus=Vm, base_velocity=list(vb), mu_s=mu_s, mu_k=mu_k, mode=mode, slip_sign=sg,
                d_dot_plus=ddp, theta_dot_plus=nu[0], q_dot_plus=nu[1:], impulse=Lam, stick_impulse=L0,
                energy_loss=E, rigid_body=rigid)


def flat_friction_landing(K, FK, body, d, q, vd_, thd, qd, vb, mu_s, mu_k, chk, stats):
    """flat landing (theta = 0, theta_dot+ = 0) with the base sliding at d_dot+ after: modal momenta
    mu qd+ + psi_x d_dot+/h = r_q, Coulomb's law on the total impulse."""
    n, P, M, h = body.n, body.P, body.M, body.h
    x, xd = [d, 0, 0] + list(q), [vd_[0], vd_[1], thd] + list(qd)
    b = [vb[0], vb[1], 0, 0, G]
    pts = list(body.pts())
    vm = [FK.call(FK.Rd, pt, x, xd, [0] * (n + 3), b) for pt in pts]

    def pvel(ddp, qd_):
        return [FK.call(FK.Rd, pt, x, [ddp, 0, 0] + list(qd_), [0] * (n + 3), b) for pt in pts]

    def moms(vels):
        return [sum(pt[0] * (pt[3][j] * v_[0] + pt[4][j] * v_[1]) for pt, v_ in zip(pts, vels)) for j in range(n)]
    pre = moms(vm)

    def post(ddp):
        if n:
            b0 = moms(pvel(ddp, [0] * n))
            cols = []
            for kk in range(n):
                e = [0] * n
                e[kk] = 1
                ck = moms(pvel(ddp, e))
                cols.append([ck[i] - b0[i] for i in range(n)])
            A = mp.matrix([[cols[j][i] for j in range(n)] for i in range(n)])
            sol = solve_lin(A, mp.matrix([pre[i] - b0[i] for i in range(n)]))
            qdp = [sol[i] for i in range(n)]
        else:
            qdp = []
        vp = pvel(ddp, qdp)
        Lam = [sum(pt[0] * (vp_[i] - vm_[i]) for pt, vp_, vm_ in zip(pts, vp, vm)) for i in range(2)]
        dT = sum(pt[0] * (vp_[0] ** 2 + vp_[1] ** 2 - vm_[0] ** 2 - vm_[1] ** 2) / 2
                 for pt, vp_, vm_ in zip(pts, vp, vm))
        return qdp, Lam, vb[0] * Lam[0] + vb[1] * Lam[1] - dT, vp
    q0, L0, E0, vp0 = post(0)
    q1, L1, _, _ = post(1)
    dL = [L1[i] - L0[i] for i in range(2)]
    chk.eq(dL, [M * conv_k_slide_full(P, 1, 0), -M * mu_quad(P, P['psi_y'], P['psi_x'])],
           'flat friction landing dLambda/dd_dot+')
    if L0[1] >= 0 and abs(L0[0]) <= mu_s * L0[1]:
        mode, sg, ddp, qdp, Lam, E, vp = 'stick', 0, mp.mpf(0), q0, L0, E0, vp0
    else:
        mode, sg = 'slip', (-1 if L0[0] > 0 else 1)
        ks = M * conv_k_slide_full(P, sg, mu_k)
        chk.eq(ks, dL[0] + sg * mu_k * dL[1], 'flat friction landing k_s')
        ddp = -(L0[0] + sg * mu_k * L0[1]) / ks
        qdp, Lam, E, vp = post(ddp)
        if ks > 0:
            assert ddp * sg > 0 and Lam[1] > 0, 'flat sliding impact inconsistent'
    vt = [sum(pt[0] * (v_[i] - vb[i]) for pt, v_ in zip(pts, vm)) / (M * h) for i in range(2)]
    prhs = conv_flat_landing_rhs(P, q, vt, thd, qd)
    if n:
        chk.eq(qdp, mu_solve(P, [prhs[j] - P['psi_x'][j] * ddp / h for j in range(n)]), 'flat friction landing qd+')
    chk.eq(Lam, [M * (ddp + h * dot(P['psi_x'], qdp) - h * vt[0]), M * (h * dot(P['psi_y'], qdp) - h * vt[1])],
           'flat friction landing impulse')
    assert E > -mp.mpf('1e-20') * M * G * h, 'negative flat friction loss'
    assert E + mp.mpf('1e-20') * M * G * h >= -Lam[0] * ddp, 'flat friction loss below the friction work'
    # split of the vertical impulse (moments about each corner; horizontal impulses have no moment there)
    split = []
    for e, o in ((1, 2), (2, 1)):
        xe, xo = d + h * alpha_of(body, e), d + h * alpha_of(body, o)
        Hm = sum(pt[0] * ((FK.call(FK.Rrel, pt, x, xd, [0] * (n + 3), b)[0] - xe) * v_[1]
                          - FK.call(FK.Rrel, pt, x, xd, [0] * (n + 3), b)[1] * v_[0]) for pt, v_ in zip(pts, vm))
        Hp = sum(pt[0] * ((FK.call(FK.Rrel, pt, x, xd, [0] * (n + 3), b)[0] - xe) * v_[1]
                          - FK.call(FK.Rrel, pt, x, xd, [0] * (n + 3), b)[1] * v_[0]) for pt, v_ in zip(pts, vp))
        Lo = (Hp - Hm) / (xo - xe)
        # closed form: -M h H^_e(V+) / (alpha_o - alpha_e), H^_e with the corner's L(V+) moved to the right
        ae = alpha_of(body, e)
        Ae, rhs = conv_landing_system(P, ae, q, vt, thd, qd)
        Lp = conv_L(P, ae, q, (ddp, 0))
        r = [rhs[i] - Lp[i] for i in range(n + 1)]
        Hh = r[0] - (dot(conv_b(P, ae, q), mu_solve(P, r[1:])) if n else 0)
        chk.eq(Lo, -M * h * Hh / (alpha_of(body, o) - ae), 'flat friction landing corner impulse')
        split.append(Lo)
    chk.eq(split[0] + split[1], Lam[1], 'flat friction landing vertical split')
    stats['flat_friction'] += 1
    stats['flat_' + mode] += 1
    return dict(d=d, q=q, cg_velocity=[v * h for v in vt], theta_dot_minus=thd, q_dot_minus=list(qd),
                base_velocity=list(vb), mu_s=mu_s, mu_k=mu_k, mode=mode, slip_sign=sg, d_dot_plus=ddp,
                q_dot_plus=qdp, impulse=Lam, energy_loss=E, corner_impulse_y=[split[1], split[0]])


def friction_cases(K, FK, body, rng, chk, stats):
    n, P, h = body.n, body.P, body.h
    u = lambda a, b: mpf(rng.uniform(a, b))
    sgh = mp.sqrt(G * h)
    sr, sf = sliding_cases(K, body, rng, chk, stats)
    la, fla = [], []
    for i in range(6):
        edge = 1 + i % 2
        sg = 1 if edge == 1 else -1
        ae = alpha_of(body, edge)
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        vb = [u(-0.5, 0.5), u(-0.5, 0.5)]
        mu_s = u(0.05, 0.8)
        mu_k = mu_s * u(0.6, 1.0)
        if i < 4:  # a free landing at a tilt, the corner coming down, fast sideways at times
            th = u(0.0, 0.4) * sg
            thd = u(-1.5, 1.5)
            ce = rot((h * ae, 0), th)
            x = [u(-0.2, 0.2) * h - ce[0], -ce[1], th] + q
            xd = [u(-1.5, 1.5) * sgh, -thd * ce[0] - u(0.05, 1.0) * sgh, thd] + qd
            la.append(friction_landing(K, FK, body, edge, th, q, x, xd, vb, mu_s, mu_k, chk, stats))
        else:  # rocking (the pivot sliding at d_dot-) on the other edge at theta = 0: the impact of theory 8
            other = 2 if edge == 1 else 1
            thdm = u(0.05, 1.5) * sg
            ddm = u(-0.5, 0.5) * sgh
            ao = alpha_of(body, other)
            x = [u(-0.2, 0.2) * h, 0, 0] + q
            xd = [ddm, -thdm * h * ao, thdm] + qd
            r = friction_landing(K, FK, body, edge, 0, q, x, xd, vb, mu_s, mu_k, chk, stats,
                                 'friction impact at theta=0')
            # the landing corner's velocity before: d_dot- I + theta_dot- h (alpha_e - alpha_pre) J
            chk.eq(r['corner_velocity_minus'], [ddm, thdm * h * (ae - ao)], 'impact corner velocity')
            la.append(r)
    for i in range(2):
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        thd = u(-1.0, 1.0)
        vd = min(h * body.alpha1 * thd, -h * body.alpha2 * thd) - u(0.05, 1.0) * sgh
        mu_s = u(0.05, 0.8)
        fla.append(flat_friction_landing(K, FK, body, u(-0.2, 0.2) * h, q, (u(-1.0, 1.0) * sgh, vd), thd, qd,
                                         [u(-0.5, 0.5), u(-0.5, 0.5)], mu_s, mu_s * u(0.6, 1.0), chk, stats))
    return dict(sliding_rocking=sr, sliding_full_contact=sf, friction_landings=la, flat_friction_landings=fla)


# --- rigid-block closed forms with friction (docs/theory.md, Sliding: rigid block) ----------------

def rigid_friction_demand(alpha, zeta2, a):
    """|F_I|/F_J of a rigid block sticking on edge 1 at theta = theta_dot = 0 under a_x = a >= alpha, a_y = 1
    (rocking just begun): (a (zeta^2 + alpha^2) + alpha) / (1 + zeta^2 + alpha a); alpha at a = alpha."""
    return (a * (zeta2 + alpha ** 2) + alpha) / (1 + zeta2 + alpha * a)


def rigid_slide_rock_acc(alpha, zeta2, mu):
    """a_x + d_ddot/g while rocking on edge 1 with the pivot sliding backwards at theta = 0 (mu_k = mu):
    a* = (mu (1 + zeta^2) - alpha) / (zeta^2 + alpha^2 - mu alpha), the a at which the demand equals mu."""
    return (mu * (1 + zeta2) - alpha) / (zeta2 + alpha ** 2 - mu * alpha)


def rigid_regime(alpha, zeta2, a, mu):
    """regime at initiation from rest under a step a_x = a > 0 (a_y = 1), mu_s = mu_k = mu."""
    if a <= alpha and a <= mu:
        return 'rest'
    if mu < alpha:
        return 'slide'
    if mu >= (zeta2 + alpha ** 2) / alpha or a <= rigid_slide_rock_acc(alpha, zeta2, mu):
        return 'rock'
    return 'slide_rock'


def rigid_block(alpha):
    """uniform rectangle, half-width alpha h, height 2h (h = 1 m), four Gauss-point masses (zeta^2 exact)."""
    h, M = mp.mpf(1), mp.mpf(1000)
    b = mp.mpf(alpha) * h
    r3 = 1 / mp.sqrt(3)
    pos = [(sx * b * r3, h + sy * h * r3) for sx in (-1, 1) for sy in (-1, 1)]
    return Body(0, [M / 4] * 4, pos, [[] for _ in range(4)], [], b, b, 'rigid block b/h=%s' % alpha)


def rigid_friction_checks(K, chk):
    """the regime at initiation from the general machinery (every candidate mode tried, its
    consistency conditions checked) against the closed forms; the demand at and after uplift."""
    out = []
    for al in ('0.25', '0.5', '1.0'):
        body = rigid_block(al)
        P, M = body.P, body.M
        alpha, z2 = body.alpha1, P['zeta2']
        chk.eq(z2, (1 + alpha ** 2) / 3, 'uniform rectangle zeta^2')
        ae = -alpha
        D = 1 + z2 + alpha ** 2
        mu_P = (z2 + alpha ** 2) / alpha
        grid_a = [alpha * mp.mpf(f) for f in ('0.5', '0.99', '1.01', '1.3', '2', '4')]
        grid_mu = [alpha * mp.mpf(f) for f in ('0.5', '0.99', '1.01', '1.2', '2', '4')] + [mu_P * mp.mpf('1.01')]
        table = []
        for a in grid_a:
            # the demand right after uplift: sticking rocking at theta = thd = 0 (theory 4, 5 and 11)
            if a >= alpha:
                ELA, EL0 = direct_dynamics(K, body, -body.b1, 0, [], 0, [], [a * G, 0], G)
                thdd = -EL0[0] / ELA[0, 0]
                chk.eq(thdd, (G / body.h) * (a - alpha) / D, 'rigid uplift theta_ddot (theory 11)')
                F = body_to_inertial(conv_F_body(P, ae, [], 0, [], thdd, [], 0, 1, a, 1, G), 0, 1)
                chk.eq(F[0] / F[1], rigid_friction_demand(alpha, z2, a), 'rigid friction demand after uplift')
            for mu in grid_mu:
                cands = []
                # stick, full contact: |F_I| <= mu F_J, U1 >= 0
                if a <= mu and a <= alpha:
                    cands.append('rest')
                # full-contact sliding backwards (s = -1): a + d_ddot/g = mu; no uplift: U1 = alpha - mu >= 0;
                # the slip grows: s d_ddot > 0
                ddd, _, Fs, k = conv_slide_full(P, [], [], a, 1, G, -1, mu)
                chk.eq(a + ddd / G, mu, 'rigid full-contact sliding')
                if -ddd > 0 and alpha - (a + ddd / G) >= 0:
                    cands.append('slide')
                # sticking rocking on edge 1: theta_ddot > 0 and |F_I| <= mu F_J
                if a > alpha and rigid_friction_demand(alpha, z2, a) <= mu:
                    cands.append('rock')
                # rocking with the pivot sliding backwards: k_s > 0, s d_ddot > 0, theta_ddot > 0
                ddd, nudd, Fr, k = conv_slide_rock(P, ae, [], 0, 0, [], a, 1, G, -1, mu)
                if k > 0 and -ddd > 0 and nudd[0] > 0:
                    cands.append('slide_rock')
                    chk.eq(a + ddd / G, rigid_slide_rock_acc(alpha, z2, mu), 'rigid slide-rock a*')
                    chk.eq(k, M * (z2 + alpha ** 2 - mu * alpha) / D, 'rigid k_s at theta = 0')
                reg = rigid_regime(alpha, z2, a, mu)
                assert cands == [reg], 'regime at initiation: candidates %s, closed form %s (a=%s, mu=%s)' % (
                    cands, reg, a, mu)
                table.append(dict(a=a, mu=mu, regime=reg))
        out.append(dict(b_over_h=alpha, zeta2=z2, painleve_mu=mu_P, demand_at_uplift=alpha,
                        demand_after_uplift=[dict(a=a, demand=rigid_friction_demand(alpha, z2, a))
                                             for a in grid_a if a >= alpha],
                        regimes=table))
    return out


# --- pure sliding of a rigid block under pulses: the exact piecewise solution ---------------------

def pulse_integrals(kind, A, t1, t):
    """base acceleration X_ddot(t) and its first two integrals from 0 (rect: A on [0, t1); half-sine:
    A sin(pi t/t1); one-sine: A sin(2 pi t/t1); zero after t1)."""
    if kind == 'rect':
        if t <= t1:
            return (A if t < t1 else mp.mpf(0)), A * t, A * t ** 2 / 2
        return mp.mpf(0), A * t1, A * t1 ** 2 / 2 + A * t1 * (t - t1)
    w = (mp.pi if kind == 'half_sine' else 2 * mp.pi) / t1
    tt = min(t, t1)
    a = A * mp.sin(w * tt) if t < t1 else mp.mpf(0)
    I1 = A / w * (1 - mp.cos(w * tt))
    I2 = A / w * (tt - mp.sin(w * tt) / w)
    if t > t1:
        I2 += I1 * (t - t1)
    return a, I1, I2


def slide_pulse_exact(kind, A, t1, mu_s, mu_k, g=G):
    """the rigid block on the floor (no rocking): stick while |X_ddot| <= mu_s g; slip with
    d_ddot = -X_ddot - s mu_k g, s = sign(d_dot); d relative to the floor.  Phases in closed form,
    their ends by root finding on the closed forms.  Returns the phase list and the final offset."""
    Xdd = lambda t: pulse_integrals(kind, A, t1, t)[0]
    phases = []
    t, d, dd, s = mp.mpf(0), mp.mpf(0), mp.mpf(0), 0
    nscan = 4000
    while True:
        if s == 0:  # stuck: wait until |X_ddot| exceeds mu_s g (only while the pulse lasts)
            f = lambda tt: abs(Xdd(tt)) - mu_s * g
            grid = [t + (t1 - t) * i / nscan for i in range(nscan + 1)] if t < t1 else []
            start = None
            for ta, tb in zip(grid, grid[1:]):
                if f(tb) > 0:
                    start = tb if f(ta) > 0 else (mp.findroot(f, (ta, tb), solver='anderson') if kind != 'rect'
                                                   else ta)
                    break
            if start is None:
                phases.append(dict(kind='stick', t0=t, d=d))
                return phases, d
            if kind == 'rect':
                start = t
            phases.append(dict(kind='stick', t0=t, t1=start, d=d))
            t = start
            s = -1 if Xdd(t + (t1 - t) * mp.mpf('1e-20')) > 0 else 1
            continue
        # slipping from (t, d, dd) with sign s
        ta, da, dda = t, d, dd
        _, I1a, I2a = pulse_integrals(kind, A, t1, ta)

        def vel(tt):
            return dda - (pulse_integrals(kind, A, t1, tt)[1] - I1a) - s * mu_k * g * (tt - ta)

        def pos(tt):
            _, I1, I2 = pulse_integrals(kind, A, t1, tt)
            return da + dda * (tt - ta) - (I2 - I2a - I1a * (tt - ta)) - s * mu_k * g * (tt - ta) ** 2 / 2
        stop = None
        if ta < t1:
            grid = [ta + (t1 - ta) * i / nscan for i in range(1, nscan + 1)]
            prev = ta
            for tb in grid:
                if s * vel(tb) <= 0:
                    stop = mp.findroot(lambda tt: vel(tt), (prev, tb), solver='anderson') if prev > ta else \
                        mp.findroot(lambda tt: vel(tt), (ta + (tb - ta) * mp.mpf('1e-12'), tb), solver='anderson')
                    break
                prev = tb
        if stop is None:  # after the pulse: d_ddot = -s mu_k g
            v1 = vel(max(ta, t1))
            stop = max(ta, t1) + s * v1 / (mu_k * g)
        phases.append(dict(kind='slip', sign=s, t0=ta, t1=stop, d0=da, d1=pos(stop)))
        t, d, dd = stop, pos(stop), mp.mpf(0)
        a = Xdd(t)
        s = 0 if (t >= t1 or abs(a) <= mu_s * g) else (-1 if a > 0 else 1)


def slide_pulse_stepping(kind, A, t1, mu_s, mu_k, g=9.80665, n=200000):
    """an independent fixed-step integration (floats, velocity-level stick test each step)."""
    import math
    A, t1, mu_s, mu_k = float(A), float(t1), float(mu_s), float(mu_k)
    w = (math.pi if kind == 'half_sine' else 2 * math.pi) / t1
    acc = (lambda t: A if t < t1 else 0.0) if kind == 'rect' else (lambda t: A * math.sin(w * t) if t < t1 else 0.0)
    T = t1 * (1 + 2 * A / (mu_k * g)) + t1
    dt = T / n
    d, v, t = 0.0, 0.0, 0.0
    for i in range(n):
        a = acc(t + dt / 2)
        if v == 0.0:
            if abs(a) <= mu_s * g:
                t += dt
                continue
            s = -1.0 if a > 0 else 1.0
        else:
            s = 1.0 if v > 0 else -1.0
        vn = v + (-a - s * mu_k * g) * dt
        if vn * s < 0:  # the slip stops inside the step
            tau = v / (a + s * mu_k * g)
            d += v * tau / 2
            vn = 0.0
        else:
            d += (v + vn) / 2 * dt
        v = vn
        t += dt
    return d


def pulse_checks(chk):
    out = []
    g = G
    for kind in ('rect', 'half_sine', 'one_sine'):
        for A, mu_s, mu_k, t1 in ((mp.mpf('0.5') * g, mp.mpf('0.2'), mp.mpf('0.2'), mp.mpf('0.5')),
                                  (mp.mpf('0.5') * g, mp.mpf('0.2'), mp.mpf('0.15'), mp.mpf('0.5')),
                                  (mp.mpf('0.3') * g, mp.mpf('0.1'), mp.mpf('0.1'), mp.mpf('1.0'))):
            phases, d = slide_pulse_exact(kind, A, t1, mu_s, mu_k)
            if kind == 'rect':
                chk.eq(d, -A * (A - mu_k * g) * t1 ** 2 / (2 * mu_k * g), 'rectangular pulse slip distance')
            ds = slide_pulse_stepping(kind, A, t1, mu_s, mu_k)
            peak = max([abs(p.get('d1', 0)) for p in phases] + [abs(d)])
            # the stepping converges at first order (its error is a few 1e-4 of the peak at 2e5 steps)
            assert abs(ds - float(d)) < 1e-3 * float(peak), 'pulse %s: exact %s vs stepping %s' % (kind, d, ds)
            out.append(dict(kind=kind, A=A, t1=t1, mu_s=mu_s, mu_k=mu_k, final_offset=d, peak_offset=peak,
                            phases=phases, stepping_final_offset=ds))
    return out


def derive_rigid_friction():
    """rigid block (n = 0) closed forms with friction, derived from the general closed forms with
    sympy and compared with the formulas of docs/theory.md (Sliding: rigid block)."""
    al, z2, a, mu, g, h, M, th = sp.symbols('alpha zeta2 a mu g h M theta', positive=True)
    P = dict(n=0, M=M, h=h, zeta2=z2, mu=[], kappa=[], gamma=[], psi_x=[], psi_y=[], delta=[], beta=[])
    res, out = {}, {}
    D = 1 + z2 + al ** 2
    # sticking on edge 1 (alpha = -alpha_1) at theta = thd = 0 under a_x = a: theta_ddot from theory 4
    thdd = conv_f(P, -al, [], 0, [], 0, 1, a, 1, g)[0] / conv_A(P, -al, [])[0][0]
    F = conv_F_body(P, -al, [], 0, [], thdd, [], 0, 1, a, 1, g)
    demand = sp.simplify(F[0] / F[1])
    res['rigid_demand_after_uplift'] = is_zero(demand - rigid_friction_demand(al, z2, a))
    res['rigid_demand_at_uplift'] = is_zero(demand.subs(a, al) - al)
    out['friction demand after uplift |F_I|/F_J'] = sp.factor(demand)
    # rocking with the pivot sliding backwards (s = -1): F_I = mu F_J with a -> a_eff
    ae = sp.Symbol('a_eff')
    thdd_e = conv_f(P, -al, [], 0, [], 0, 1, ae, 1, g)[0] / D
    Fe = conv_F_body(P, -al, [], 0, [], thdd_e, [], 0, 1, ae, 1, g)
    sol = sp.solve(sp.Eq(Fe[0], mu * Fe[1]), ae)
    res['rigid_slide_rock_acc'] = len(sol) == 1 and is_zero(sol[0] - rigid_slide_rock_acc(al, z2, mu))
    out['slide-rock: a + d_ddot/g'] = sp.factor(sol[0])
    # k_s at theta = 0 for s = -1: d(F_I - mu F_J)/d(a_eff) / g ... per unit d_ddot
    ks = sp.diff(Fe[0] - mu * Fe[1], ae) / g
    res['rigid_k_s_theta0'] = is_zero(ks - M * (z2 + al ** 2 - mu * al) / D)
    out['k_s (rocking on edge 1, s = -1, theta = 0)'] = sp.factor(ks)
    # rigid k_s at any tilt: (M / A)(zeta^2 + X^2 + s mu X Y), (X, Y) = R(theta) w
    s_, c_, sg = sp.symbols('s c sg')
    A = D
    w = conv_w(P, -al, [])
    fa = conv_dfdax(P, -al, [], s_, c_, g)[0] / A  # d theta_ddot / d a_x
    dFb = [M * g * conv_e_I(s_, c_)[i] + M * h * conv_B(P, -al, [])[i][0] * fa for i in range(2)]
    dF = body_to_inertial(dFb, s_, c_)
    X, Y = body_to_inertial(w, s_, c_)
    res['rigid_k_s'] = is_zero((dF[0] + sg * mu * dF[1]) / g - M * (z2 + X ** 2 + sg * mu * X * Y) / A)
    # pure sliding under a rectangular pulse: slip during the pulse, then decelerate at mu g
    A_, t1, t = sp.symbols('A t1 t', positive=True)
    v1 = -(A_ - mu * g) * t1
    d1 = -(A_ - mu * g) * t1 ** 2 / 2
    dist = d1 - v1 ** 2 / (2 * mu * g)
    res['rect_pulse_distance'] = is_zero(sp.simplify(dist + A_ * (A_ - mu * g) * t1 ** 2 / (2 * mu * g)))
    out['rectangular pulse: final offset'] = sp.factor(dist)
    return res, out


def theta0_rule_with_friction(seed, trials, stats):
    """at theta = 0 with both corners coming down: the three candidates (corner 1, corner 2, flat), each
    with Coulomb's law of theory 19; a corner is consistent if the body then turns away from the other
    corner, the flat one if both corners press (H^_1(V+) <= 0 <= H^_2(V+)).  Counts how many are
    consistent and how often the frictionless choice of theory 16 (sticking H^) is one of them."""
    rng = np.random.RandomState(seed)
    for trial in range(trials):
        n = trial % 3
        b = random_body(rng, n, 'theta=0 rule n=%d' % n)
        if trial % 2:
            b.b1, b.b2 = b.h * mpf(rng.uniform(0.1, 2.5)), b.h * mpf(rng.uniform(0.1, 2.5))
            b.params()
        P, h, M = b.P, b.h, b.M
        sgh = mp.sqrt(G * h)
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        thd = mpf(rng.uniform(-1.0, 1.0))
        nu = [thd] + qd
        vO = (mpf(rng.uniform(-2, 2)) * sgh,
              min(h * b.alpha1 * thd, -h * b.alpha2 * thd) - mpf(rng.uniform(0.02, 1.0)) * sgh)
        B0 = conv_B(P, 0, q)
        vt = ((vO[0] + h * dot(B0[0], nu)) / h, (vO[1] + h * dot(B0[1], nu)) / h)
        mu_s = mpf(10 ** rng.uniform(-1.3, 0.3))
        mu_k = mu_s * mpf(rng.uniform(0.6, 1))
        ok = []
        for e in (1, 2):
            ae = alpha_of(b, e)
            Be = conv_B(P, ae, q)
            Vm = (h * (vt[0] - dot(Be[0], nu)), h * (vt[1] - dot(Be[1], nu)))
            assert Vm[1] < 0
            mode, sg, ddp, nup, Lam = conv_friction_impact(P, ae, q, 0, nu, Vm, mu_s, mu_k)
            if (1 if e == 1 else -1) * nup[0] > 0:
                ok.append('corner%d' % e)
        prhs = conv_flat_landing_rhs(P, q, vt, thd, qd)

        def flat(ddp):
            qdp = mu_solve(P, [prhs[j] - P['psi_x'][j] * ddp / h for j in range(n)]) if n else []
            return [M * (ddp + h * dot(P['psi_x'], qdp) - h * vt[0]), M * (h * dot(P['psi_y'], qdp) - h * vt[1])]
        L0 = flat(0)
        ddp = mp.mpf(0)
        if not (L0[1] >= 0 and abs(L0[0]) <= mu_s * L0[1]):
            sg = -1 if L0[0] > 0 else 1
            ddp = -(L0[0] + sg * mu_k * L0[1]) / (M * conv_k_slide_full(P, sg, mu_k))

        def Hhat(e, ddp_):
            ae = alpha_of(b, e)
            _, rhs = conv_landing_system(P, ae, q, vt, thd, qd)
            Lp = conv_L(P, ae, q, (ddp_, 0))
            r = [rhs[i] - Lp[i] for i in range(n + 1)]
            return r[0] - (dot(conv_b(P, ae, q), mu_solve(P, r[1:])) if n else 0)
        if Hhat(1, ddp) <= 0 <= Hhat(2, ddp):
            ok.append('flat')
        choice = 'corner1' if Hhat(1, 0) > 0 else ('corner2' if Hhat(2, 0) < 0 else 'flat')
        assert ok, 'theta = 0 with friction: no consistent outcome'
        stats['cases'] += 1
        stats['consistent_%d' % len(ok)] += 1
        if choice not in ok:
            stats['frictionless_choice_inconsistent'] += 1
        if len(ok) > 1:
            stats['ambiguous_min_mu_s'] = min(stats['ambiguous_min_mu_s'], float(mu_s))
            if choice in ok:
                stats['ambiguous_frictionless_choice_consistent'] += 1


def theta0_friction_outcome(body, e, q, qd, thd, vt, mu_s, mu_k):
    """a body landing level (theta = 0) from flight on corner e with Coulomb friction (theory 19): the three
    outcomes (corner 1, corner 2, flat), each resolved by Coulomb's law, whether each is consistent (a corner:
    a slide with k_s > 0, and the body turns up about it; flat: both corners press, H^_1 <= 0 <= H^_2 at the
    slip velocity after), and the one taken: the sticking rule of theory 16 (corner e if its sticking map
    turns the body up about it, else the other corner if its does, else flat) where that one is consistent,
    else the last consistent one of corner 1, corner 2, flat.  vt: the c.g. velocity over h."""
    n, P, M, h = body.n, body.P, body.M, body.h
    nu = [thd] + list(qd)
    sgn = {1: 1, 2: -1}

    def Hhat(c, ddp_):
        ac = alpha_of(body, c)
        _, rhs = conv_landing_system(P, ac, q, vt, thd, qd)
        Lp = conv_L(P, ac, q, (ddp_, 0))
        r = [rhs[i] - Lp[i] for i in range(n + 1)]
        return r[0] - (dot(conv_b(P, ac, q), mu_solve(P, r[1:])) if n else 0)
    cand = []
    for c in (1, 2):
        ac = alpha_of(body, c)
        Bc = conv_B(P, ac, q)
        Vm = (h * (vt[0] - dot(Bc[0], nu)), h * (vt[1] - dot(Bc[1], nu)))
        mode, sg, ddp, nup, Lam = conv_friction_impact(P, ac, q, 0, nu, Vm, mu_s, mu_k)
        ok = True
        if mode == 'slip':
            Wi = conv_Winv(P, ac, q, 0)
            ok = Wi[0, 0] + sg * mu_k * Wi[1, 0] > 0
        chk_turn = Hhat(c, ddp) / schur(P, ac, q)
        assert abs(chk_turn - nup[0]) < mp.mpf('1e-25') * (1 + abs(nup[0])), 'theta = 0: corner map vs H^'
        cand.append(dict(outcome='corner%d' % c, mode=mode, slip_sign=sg, d_dot_plus=ddp, theta_dot_plus=nup[0],
                         q_dot_plus=nup[1:], impulse=Lam, fits=int(bool(ok and sgn[c] * nup[0] > 0))))
    prhs = conv_flat_landing_rhs(P, q, vt, thd, qd)

    def flat(ddp_):
        qdp = mu_solve(P, [prhs[j] - P['psi_x'][j] * ddp_ / h for j in range(n)]) if n else []
        return qdp, [M * (ddp_ + h * dot(P['psi_x'], qdp) - h * vt[0]), M * (h * dot(P['psi_y'], qdp) - h * vt[1])]
    _, L0 = flat(0)
    mode, sg, ddp, ok = 'stick', 0, mp.mpf(0), True
    if not (L0[1] >= 0 and abs(L0[0]) <= mu_s * L0[1]):
        mode, sg = 'slip', (-1 if L0[0] > 0 else 1)
        k = M * conv_k_slide_full(P, sg, mu_k)
        ddp = -(L0[0] + sg * mu_k * L0[1]) / k
        ok = k > 0
    qdp, Lam = flat(ddp)
    cand.append(dict(outcome='flat', mode=mode, slip_sign=sg, d_dot_plus=ddp, theta_dot_plus=mp.mpf(0), q_dot_plus=qdp,
                     impulse=Lam, fits=int(bool(ok and Hhat(1, ddp) <= 0 <= Hhat(2, ddp)))))
    o = 2 if e == 1 else 1
    pick = 2
    if sgn[e] * Hhat(e, 0) > 0:
        pick = e - 1
    elif sgn[o] * Hhat(o, 0) > 0:
        pick = o - 1
    if not cand[pick]['fits']:
        for j in range(3):
            if cand[j]['fits']:
                pick = j
    out = dict(cand[pick])
    vc = [h * vt[0], h * vt[1]]
    vcp = [vc[i] + out['impulse'][i] / M for i in range(2)]
    out['energy_loss'] = conv_T_flight(P, q, vc, thd, qd) - conv_T_flight(P, q, vcp, out['theta_dot_plus'],
                                                                         out['q_dot_plus'])
    assert not out['fits'] or out['energy_loss'] > -mp.mpf('1e-20') * M * G * h, 'theta = 0: energy gained'
    return dict(n=n, params=dict(M=body.M, h=body.h, b1=body.b1, b2=body.b2, zeta2=P['zeta2'], mu=P['mu'],
                                 kappa=P['kappa'], gamma=P['gamma'], psi_x=P['psi_x'], psi_y=P['psi_y'],
                                 delta=P['delta'], beta=P['beta']),
                edge=e, q=q, q_dot_minus=list(qd), theta_dot_minus=thd, cg_velocity=vc, mu_s=mu_s, mu_k=mu_k,
                consistent=[c_['fits'] for c_ in cand], outcome=out)


def theta0_friction_cases(seed, count):
    """level landings with friction for the engine's whole map at theta = 0 (written): bodies n = 0, 1, 2, wide
    and narrow, both corners coming down, mu_s from 0.05 to 2"""
    rng = np.random.RandomState(seed)
    cases, taken = [], dict(corner1=0, corner2=0, flat=0, inconsistent=0)
    for trial in range(count):
        n = trial % 3
        b = random_body(rng, n, 'theta=0 map n=%d' % n)
        if trial % 2:
            b.b1, b.b2 = b.h * mpf(rng.uniform(0.1, 2.5)), b.h * mpf(rng.uniform(0.1, 2.5))
            b.params()
        h = b.h
        sgh = mp.sqrt(G * h)
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        thd = mpf(rng.uniform(-1.0, 1.0))
        nu = [thd] + qd
        vO = (mpf(rng.uniform(-2, 2)) * sgh,
              min(h * b.alpha1 * thd, -h * b.alpha2 * thd) - mpf(rng.uniform(0.02, 1.0)) * sgh)
        B0 = conv_B(b.P, 0, q)
        vt = ((vO[0] + h * dot(B0[0], nu)) / h, (vO[1] + h * dot(B0[1], nu)) / h)
        mu_s = mpf(10 ** rng.uniform(-1.3, 0.3))
        r = theta0_friction_outcome(b, 1 + trial % 2, q, qd, thd, vt, mu_s, mu_s * mpf(rng.uniform(0.6, 1)))
        taken[r['outcome']['outcome'] if r['outcome']['fits'] else 'inconsistent'] += 1
        cases.append(r)
    return cases, taken


# ---------------------------------------------------------------------------
# body generation
# ---------------------------------------------------------------------------

def random_body(rng, n, name):
    N = int(rng.randint(6, 9))
    h_target = rng.uniform(0.5, 3.0)
    M_target = 10 ** rng.uniform(1, 4)
    w = rng.uniform(0.5, 2.0, N)
    w = w / w.sum() * M_target
    masses = [mpf(x) for x in w]
    xs = rng.uniform(-0.5, 0.5, N) * rng.uniform(0.5, 1.5)
    ys = rng.uniform(0.05, 1.0, N)
    M = sum(masses)
    xc = sum(mi * mpf(x) for mi, x in zip(masses, xs)) / M
    yc = sum(mi * mpf(y) for mi, y in zip(masses, ys)) / M
    scale = mpf(h_target) / yc
    pos = [((mpf(x) - xc) * scale, mpf(y) * scale) for x, y in zip(xs, ys)]
    h = yc * scale
    b1 = h * mpf(rng.uniform(0.15, 0.7))
    b2 = h * mpf(rng.uniform(0.15, 0.7))
    modes = [[(mpf(rng.uniform(-0.4, 0.4)) * h, mpf(rng.uniform(-0.4, 0.4)) * h) for _ in range(n)]
             for _ in range(N)]
    k = [[mp.mpf(0)] * n for _ in range(n)]
    if n:
        mu = np.array([[float(sum(mi * (modes[a][i][0] * modes[a][j][0] + modes[a][i][1] * modes[a][j][1])
                                  for a, mi in enumerate(masses))) for j in range(n)] for i in range(n)])
        L = np.linalg.cholesky(mu)
        Q, _ = np.linalg.qr(rng.normal(size=(n, n)))
        om2 = rng.uniform(15.0, 80.0, n) ** 2
        kk = L @ Q @ np.diag(om2) @ Q.T @ L.T  # N/m (q dimensionless)
        k = [[(mpf(kk[i][j]) + mpf(kk[j][i])) / 2 for j in range(n)] for i in range(n)]
    return Body(n, masses, pos, modes, k, b1, b2, name)


def squat_block():
    """rigid uniform rectangle, half-width b, height 2h, b/h = 2, by 4 Gauss-point masses."""
    h, b, M = mp.mpf(1), mp.mpf(2), mp.mpf(1000)
    r3 = 1 / mp.sqrt(3)
    pos = [(sx * b * r3, h + sy * h * r3) for sx in (-1, 1) for sy in (-1, 1)]
    return Body(0, [M / 4] * 4, pos, [[] for _ in range(4)], [], b, b, 'squat block b/h=2')


# ---------------------------------------------------------------------------

def compliant_potential():
    """The compliant corner's contact potential (theory "Compliant contact").

    V(delta, u) = k delta^(p+1)/(p+1) + k_t phi(delta) u^2 / 2 with phi = k delta^p / f_ref: the
    tangential spring's stiffness scales with the normal spring's force (f_ref = M g / 2, so that
    phi = 1 at rest on both corners). Checked symbolically: the forces the engine applies are the
    potential's gradient (F_t = -dV/du, the elastic normal force dV/ddelta with its push
    k_t phi' u^2 / 2); along any motion the elastic forces' power on the body is -dV/dt, so that a
    contact without dashpots stores and returns energy exactly; V and the tangential force vanish as
    delta -> 0+ for every u (the release discards nothing); phi(delta_st) = 1; the dashpots'
    power is -(c delta'^2 + c_t phi u'^2) <= 0. Then reference values of V and of the sticking
    corner's forces (with dashpots) at sample points, for tests/unit/sympy_reference_test.cpp."""
    k, kt, fref, d, u, c, ct, dd, ud = sp.symbols('k k_t f_ref delta u c c_t deltadot udot', positive=True)
    res = {}
    refs = []
    for p in (sp.Integer(1), sp.Rational(3, 2), sp.Rational(11, 5)):
        phi = k * d ** p / fref
        V = k * d ** (p + 1) / (p + 1) + kt * phi * u ** 2 / 2
        ft_el = -kt * phi * u                                       # the engine's elastic F_t
        fn_el = k * d ** p + kt * (p * k * d ** (p - 1) / fref) * u ** 2 / 2  # and elastic F_n
        tag = 'p=%s' % p
        res['gradient_' + tag] = (sp.simplify(-sp.diff(V, u) - ft_el) == 0
                                  and sp.simplify(sp.diff(V, d) - fn_el) == 0)
        # power along a motion delta(t), u(t): the corner's velocity is (u', -delta')
        t = sp.Symbol('t')
        D, U = sp.Function('D')(t), sp.Function('U')(t)
        on = {d: D, u: U}
        power = ft_el.subs(on) * U.diff(t) + fn_el.subs(on) * (-D.diff(t))
        res['conservative_' + tag] = sp.simplify(power + V.subs(on).diff(t)) == 0
        # with the dashpots (linear normal dashpot c delta', tangential c_t phi u'; unclipped)
        ft = -phi * (kt * u + ct * ud)
        fn = k * d ** p + c * dd + kt * (p * k * d ** (p - 1) / fref) * u ** 2 / 2
        pw = ft * ud + fn * (-dd) + sp.diff(V, d) * dd + sp.diff(V, u) * ud
        res['dashpots_dissipate_' + tag] = sp.simplify(pw + c * dd ** 2 + ct * phi * ud ** 2) == 0
        res['vanishes_at_release_' + tag] = (sp.limit(V, d, 0, '+') == 0
                                             and sp.limit(ft_el, d, 0, '+') == 0)
        dst = (fref / k) ** (1 / p)
        res['unit_scale_at_rest_' + tag] = sp.simplify(phi.subs(d, dst) - 1) == 0
        # reference values: a 1000 kg body, delta_st = 5e-5 m, at three penetrations
        M, g = mp.mpf(1000), mp.mpf(G_STD)
        f_ref = M * g / 2
        d_st = mp.mpf('5e-5')
        kk = f_ref / d_st ** mp.mpf(p)
        k_t = f_ref / d_st
        zeta, e = mp.mpf('0.3'), mp.mpf('0.6')
        c_t = 2 * zeta * mp.sqrt(k_t * M / 2)
        law = 'linear' if p == 1 else 'hunt_crossley'
        cn = c_t if law == 'linear' else mp.mpf(0)
        hc = mp.mpf(0) if law == 'linear' else mp.mpf(3) / 4 * (1 - e ** 2)
        v_floor = mp.sqrt(g * d_st)
        v_in = mp.mpf('0.3')
        num = {k: kk, kt: k_t, fref: f_ref, ct: c_t, c: cn}
        Vn = sp.lambdify((d, u), V.subs(num), 'mpmath')
        ftn = sp.lambdify((d, u), ft_el.subs(num), 'mpmath')
        fnn = sp.lambdify((d, u), (fn_el - k * d ** p).subs(num), 'mpmath')
        for (rd, ru, rdd, rud) in ((mp.mpf('0.3'), mp.mpf('-0.7'), mp.mpf('0.05'), mp.mpf('-0.02')),
                                   (mp.mpf(1), mp.mpf('1.3'), mp.mpf('-0.01'), mp.mpf('0.04')),
                                   (mp.mpf('2.5'), mp.mpf('0.4'), mp.mpf('-0.2'), mp.mpf('0.1'))):
            dl, uu = rd * d_st, ru * d_st
            phin = kk * dl ** mp.mpf(p) / f_ref
            spring = kk * dl ** mp.mpf(p)
            if law == 'linear':
                normal = max(spring + cn * rdd, mp.mpf(0))
            else:
                normal = max(spring * (1 + hc * rdd / max(v_in, v_floor)), mp.mpf(0))
            refs.append(dict(law=law, p=float(p), k=kk, k_t=k_t, c=cn, c_t=c_t, hc=hc, v_floor=v_floor,
                             f_ref=f_ref, v_in=v_in, delta=dl, delta_dot=rdd, u=uu, u_dot=rud,
                             potential=Vn(dl, uu), force_t=ftn(dl, uu) - phin * c_t * rud,
                             force_n=normal + fnn(dl, uu)))
    return res, refs


def fmt(x):
    if isinstance(x, str):
        return json.dumps(x)
    if isinstance(x, dict):
        return '{' + ', '.join('"%s": %s' % (k, fmt(v)) for k, v in x.items()) + '}'
    if isinstance(x, (list, tuple)):
        return '[' + ', '.join(fmt(v) for v in x) + ']'
    if isinstance(x, (int, np.integer)) and not isinstance(x, bool):
        return str(int(x))
    t = '%.17g' % float(x)
    return t if any(ch in t for ch in '.eEn') else t + '.0'


def case_json(body, K, rng, chk, stats):
    n, P = body.n, body.P
    params = dict(M=body.M, h=body.h, b1=body.b1, b2=body.b2, zeta2=P['zeta2'], mu=P['mu'],
                  kappa=P['kappa'], gamma=P['gamma'], psi_x=P['psi_x'], psi_y=P['psi_y'],
                  delta=P['delta'], beta=P['beta'])
    u = lambda a, b: mpf(rng.uniform(a, b))
    rocking = []
    for i in range(6):
        edge = 1 if i % 2 == 0 else 2
        th = u(0.005, 0.3) * (1 if edge == 1 else -1)
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        base = [u(-0.3, 0.3) * G, u(-0.3, 0.3) * G]
        rocking.append(rocking_state(K, body, edge, th, q, u(-1.5, 1.5), qd, base, chk))
    full = []
    for i in range(3):
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        base = [u(-0.3, 0.3) * G, u(-0.3, 0.3) * G]
        full.append(full_contact_state(K, body, q, qd, base, chk))
    imp = []
    for i in range(4):
        landing = 1 if i % 2 == 0 else 2
        q = [mpf(0.05 * rng.normal()) for _ in range(n)]
        qd = [mpf(rng.normal()) for _ in range(n)]
        thdm = u(0.05, 1.5) * (1 if landing == 1 else -1)
        vb = [u(-0.5, 0.5), u(-0.5, 0.5)]
        imp.append(impact(K, body, landing, q, thdm, qd, vb, chk, stats))
    return dict(n=n, params=params, tipping_angle=tipping_angles(K, body, chk), rocking=rocking,
                full_contact=full, impacts=imp)


def trig_reduce(e):
    """reduce modulo cos^2 + sin^2 = 1 (c = cos(theta), s = sin(theta))."""
    e = sp.expand(e)
    return sp.expand(sp.rem(e, TRIG, C)) if e.has(C) else e


def print_equations(gens):
    print('Notation: s = sin(theta), c = cos(theta), thd = dtheta/dt, qd = dq/dt, dd = second derivative;')
    print('Xd, Yd, Xdd, Ydd: base velocity / acceleration; alpha = -alpha1 (pivot 1) or alpha2 (pivot 2).')
    for n, Gn in sorted(gens.items()):
        if n not in (0, 1, 2):
            continue
        print('=' * 72)
        print('n = %d   (alpha: tipping parameter of the current pivot; thd = dtheta/dt)' % n)
        print('T_inertial =', sp.collect(trig_reduce(Gn.T_in), [Gn.Xd, Gn.Yd]))
        print('V =', sp.factor_terms(Gn.V))
        print('A (mass matrix over M h^2):')
        for row in Gn.A_der:
            print('   ', [sp.factor_terms(x) for x in row])
        print('f (forces, A acc = f):')
        for x in Gn.f_der:
            print('   ', sp.collect(trig_reduce(x), [Gn.thd, Gn.g, Gn.Xdd, Gn.Ydd]))
        print('floor reaction (inertial I, J):')
        for x in Gn.F_in:
            print('   ', sp.collect(trig_reduce(x), [Gn.thd, Gn.thdd, Gn.g, Gn.Xdd, Gn.Ydd]))
        print('full contact: moment of floor force about c.g. projection =', sp.factor_terms(Gn.mom_fc))
        print('              vertical reaction =', sp.factor_terms(Gn.Fy_fc))
        print('impact conservation [H_landing; p_j] (post - pre):')
        for x in Gn.impact_cons:
            print('   ', sp.collect(sp.expand(x), [sp.Symbol('thd_p'), sp.Symbol('thd_m')]))
        if n == 0:
            print('rigid ratio thd+/thd- =', Gn.rigid_ratio)


def sincos_term(th, s, c, j):
    """the terms of power j > 0 of sin and cos of theta's series th, from s' = c theta' and
    c' = -s theta' and the lower terms in s, c"""
    s[j] = sum((i * th[i] * c[j - i] for i in range(1, j + 1)), 0) / j
    c[j] = -sum((i * th[i] * s[j - i] for i in range(1, j + 1)), 0) / j


def rocking_series_recurrence(P, Q, th0, om0, order):
    """the Taylor coefficients of the rigid rocking motion by the recurrence of docs/theory.md
    (Rocking of a rigid body by its Taylor series), as src/sim/rocking_series.hpp computes them:
    theta to power order + 1, sin and cos of theta to power order - 1; P and Q are the series of
    k (alpha v + u) and k (v - alpha u), two terms under a record, more under sinusoids"""
    P, Q = list(P) + [0] * order, list(Q) + [0] * order
    th, s, c = [th0, om0] + [0] * order, [sp.sin(th0)] + [0] * order, [sp.cos(th0)] + [0] * order
    for j in range(order):
        if j > 0:
            sincos_term(th, s, c, j)
        a = sum((P[i] * c[j - i] + Q[i] * s[j - i] for i in range(j + 1)), 0)
        th[j + 2] = a / ((j + 1) * (j + 2))
    return th, s, c


def rocking_work_recurrence(a, b, thc, sc, cc, order):
    """the input work's terms W_1..W_order as src/sim/rocking_series.hpp computes them: with a and
    b the series of M h g (u + alpha (v - 1)) and M h g ((v - 1) - alpha u), W' = theta' (a cos +
    b sin) = a sin' - b cos' (theta' cos = sin', theta' sin = -cos'), whose term k - 1 gives
    W_k = sum_{i<k} (k - i) (a_i s_{k-i} - b_i c_{k-i}) / k; sin and cos (known to power order - 1)
    are carried to power order by their recurrence first"""
    s, c = list(sc[:order]) + [0], list(cc[:order]) + [0]
    sincos_term(thc, s, c, order)
    a, b = list(a) + [0] * order, list(b) + [0] * order
    return [sum(((k - i) * (a[i] * s[k - i] - b[i] * c[k - i]) for i in range(k)), 0) / k
            for k in range(1, order + 1)]


def rocking_reaction_recurrence(us, vs, al, gh, thc, sc, cc, order):
    """the reaction's terms F_I, F_J (over M g) and the overturning moment (over M g h) to power
    order - 1 as src/sim/rocking_series.hpp (reaction_series) forms them from the forcing's terms
    us, vs, theta's terms thc and the recurrence's sin and cos terms sc, cc"""
    us, vs = list(us) + [0] * order, list(vs) + [0] * order
    A, B = [], []
    for k in range(order):
        w2 = sum(((i + 1) * thc[i + 1] * (k - i + 1) * thc[k - i + 1] for i in range(k + 1)), 0)
        dd = (k + 1) * (k + 2) * thc[k + 2]
        A.append((al * w2 - dd) / gh)
        B.append((al * dd + w2) / gh)
    fi = [us[k] + sum((A[i] * cc[k - i] + B[i] * sc[k - i] for i in range(k + 1)), 0) for k in range(order)]
    fj = [vs[k] + sum((A[i] * sc[k - i] - B[i] * cc[k - i] for i in range(k + 1)), 0) for k in range(order)]
    mo = [al * (sum((vs[i] * cc[k - i] - us[i] * sc[k - i] for i in range(k + 1)), 0) - B[k]) for k in range(order)]
    return fi, fj, mo


def sinusoid_series(A, w, sc, cc, order):
    """the Taylor coefficients of A sin(w tau + c) at tau = 0 as src/sim/rocking_series.hpp forms
    them: A w^k / k! times sin c, cos c, -sin c, -cos c in turn (sc = sin c, cc = cos c)"""
    cyc = [sc, cc, -sc, -cc]
    return [A * w ** k / sp.factorial(k) * cyc[k % 4] for k in range(order)]


def derive_rocking_series(order=5):
    """a rigid body's rocking by its Taylor series (docs/theory.md): the equation and the input
    power as the series uses them against the general equations of theory 4 and the c.g.'s
    kinematics, and the recurrence against the series of the equation's right-hand side."""
    al, z2, g, h, M, tau = sp.symbols('alpha zeta2 g h M tau', real=True)
    u0, u1, v0, v1, th0, om0, s, c, thd = sp.symbols('u0 u1 v0 v1 theta0 omega0 s c thd', real=True)
    P = dict(n=0, M=M, h=h, zeta2=z2, mu=[], kappa=[], gamma=[], psi_x=[], psi_y=[], delta=[], beta=[])
    res = {}
    u, v = sp.Symbol('u'), sp.Symbol('v')
    k = (g / h) / (1 + z2 + al ** 2)
    # the equation: theta'' = k ((alpha v + u) cos + (v - alpha u) sin) from theory 4 at n = 0
    thdd = conv_f(P, al, [], thd, [], s, c, u, v, g)[0] / conv_A(P, al, [])[0][0]
    res['series_equation'] = is_zero(thdd - k * ((al * v + u) * c + (v - al * u) * s))
    # the input power -M a_base . v_cm, the c.g. at h R(theta) (-alpha, 1) from the pivot, the base
    # accelerating by (g u, g (v - 1))
    th = sp.Function('th')(tau)
    r = [h * (-al * sp.cos(th) - sp.sin(th)), h * (-al * sp.sin(th) + sp.cos(th))]
    vel = [sp.diff(x, tau) for x in r]
    power = -M * (g * u * vel[0] + g * (v - 1) * vel[1])
    series_power = M * h * g * sp.diff(th, tau) * ((u + al * (v - 1)) * sp.cos(th)
                                                   + ((v - 1) - al * u) * sp.sin(th))
    res['series_power'] = is_zero(sp.expand(power - series_power))
    # the floor reaction over M g (floor axes) and the overturning moment about the c.g.'s
    # projection over M g h that the series step bounds (docs/theory.md, "Guards of the series step
    # by bounds"), against theory 5 at n = 0: with A = (alpha thd^2 - thdd)/(g/h) and
    # B = (alpha thdd + thd^2)/(g/h), F_I = u + A c + B s, F_J = v + A s - B c and
    # M = alpha (v c - u s - B), the moment alpha h times the body-frame J component
    thdd_ = sp.Symbol('thdd', real=True)
    Fb = conv_F_body(P, al, [], thd, [], thdd_, [], S, C, u, v, g)
    Fi, Fj = body_to_inertial(Fb, S, C)
    A_ = (al * thd ** 2 - thdd_) / (g / h)
    B_ = (al * thdd_ + thd ** 2) / (g / h)
    res['series_reaction_forms'] = (is_zero(Fi / (M * g) - (u + A_ * C + B_ * S))
                                    and is_zero(Fj / (M * g) - (v + A_ * S - B_ * C))
                                    and is_zero(al * Fb[1] / (M * g) - al * (v * C - u * S - B_)))
    # the same with theta'' = k (a1 u + b1 v) put in (the equation above), a1 = C - alpha S,
    # b1 = alpha C + S, k/(g/h) = 1/m, as RockingSeries::reaction_range encloses them by interval
    # arithmetic over a step: u, v and thd^2 each once per form
    gh_ = g / h
    m_ = 1 + z2 + al ** 2
    a1, b1 = C - al * S, al * C + S
    thdd_eq = k * (a1 * u + b1 * v)
    on_eq = {thdd_: thdd_eq}
    res['series_reaction_enclosure_forms'] = (
        is_zero(thdd_eq - k * ((al * v + u) * C + (v - al * u) * S))
        and is_zero((u + A_ * C + B_ * S).subs(on_eq)
                    - (u * (1 - a1 ** 2 / m_) - v * a1 * b1 / m_ + thd ** 2 * b1 / gh_))
        and is_zero((v + A_ * S - B_ * C).subs(on_eq)
                    - (v * (1 - b1 ** 2 / m_) - u * a1 * b1 / m_ - thd ** 2 * a1 / gh_))
        and is_zero((al * (v * C - u * S - B_)).subs(on_eq)
                    - al * (u * (-S - al * a1 / m_) + v * (C - al * b1 / m_) - thd ** 2 / gh_)))
    # the recurrence: the polynomial's residual in the equation, and sin, cos, the work, vanish to
    # the powers the series claims; the parameters as exact rationals (symbols make the series
    # expansion slow), the initial state symbolic
    num = {al: sp.Rational(-3, 11), z2: sp.Rational(2, 5), g: sp.Rational(49, 5), h: sp.Rational(13, 10),
           M: sp.Rational(800), u0: sp.Rational(3, 10), u1: sp.Rational(-47, 10), v0: sp.Rational(9, 10),
           v1: sp.Rational(23, 10)}
    al, z2, g, h, M, u0, u1, v0, v1 = [num[x] for x in (al, z2, g, h, M, u0, u1, v0, v1)]
    k = (g / h) / (1 + z2 + al ** 2)
    uu, vv = u0 + u1 * tau, v0 + v1 * tau
    Pk, Qk = k * (al * vv + uu), k * (vv - al * uu)
    thc, sc, cc = rocking_series_recurrence([sp.expand(k * (al * v0 + u0)), sp.expand(k * (al * v1 + u1))],
                                            [sp.expand(k * (v0 - al * u0)), sp.expand(k * (v1 - al * u1))],
                                            th0, om0, order)
    poly = sum((thc[i] * tau ** i for i in range(order + 2)), 0)
    resid = sp.diff(poly, tau, 2) - (Pk * sp.cos(poly) + Qk * sp.sin(poly))
    ser = sp.series(resid, tau, 0, order).removeO()
    res['series_recurrence'] = all(is_zero(ser.coeff(tau, i)) for i in range(order))
    sin_ser = sp.series(sp.sin(poly), tau, 0, order).removeO()
    cos_ser = sp.series(sp.cos(poly), tau, 0, order).removeO()
    res['series_sincos'] = all(is_zero(sin_ser.coeff(tau, i) - sc[i]) and is_zero(cos_ser.coeff(tau, i) - cc[i])
                               for i in range(order))
    # the work's terms, from a linear forcing
    a0, a1 = M * h * g * (u0 + al * (v0 - 1)), M * h * g * (u1 + al * v1)
    b0, b1 = M * h * g * ((v0 - 1) - al * u0), M * h * g * (v1 - al * u1)
    W = [0] + rocking_work_recurrence([a0, a1], [b0, b1], thc, sc, cc, order)
    wpoly = sum((W[i] * tau ** i for i in range(order + 1)), 0)
    dpoly = sp.diff(poly, tau)
    wres = sp.diff(wpoly, tau) - M * h * g * dpoly * ((uu + al * (vv - 1)) * sp.cos(poly)
                                                     + ((vv - 1) - al * uu) * sp.sin(poly))
    wser = sp.series(wres, tau, 0, order).removeO()
    res['series_work'] = all(is_zero(wser.coeff(tau, i)) for i in range(order))
    # the reaction's terms as src/sim/rocking_series.hpp forms them (Cauchy products of the
    # recurrence's sin, cos, theta_dot^2 and theta'') against sympy's series of the closed forms
    # above on theta's polynomial, to the power the series knows them (order - 1)
    fi, fj, mo = rocking_reaction_recurrence([u0, u1], [v0, v1], al, g / h, thc, sc, cc, order)
    dpoly2 = sp.diff(poly, tau, 2)
    A_t = (al * dpoly ** 2 - dpoly2) / (g / h)
    B_t = (al * dpoly2 + dpoly ** 2) / (g / h)
    # (sympy's own series of sin and cos of the polynomial, sin_ser and cos_ser above; the rest are
    # polynomials in tau), sin theta0 and cos theta0 as S and C so that is_zero knows S^2 + C^2 = 1
    closed = [uu + A_t * cos_ser + B_t * sin_ser, vv + A_t * sin_ser - B_t * cos_ser,
              al * (vv * cos_ser - uu * sin_ser - B_t)]
    trig = {sp.sin(th0): S, sp.cos(th0): C}
    ok = True
    for terms, expr in zip((fi, fj, mo), closed):
        ser_ = sp.expand(expr)
        ok = ok and all(is_zero((ser_.coeff(tau, i) - terms[i]).subs(trig)) for i in range(order))
    res['series_reaction'] = ok
    # a pulse of sinusoids, one per component (u = A sin(w tau + c) / g, v = 1 + B sin(w2 tau +
    # c2) / g): the sinusoid's coefficients against sympy's series, then the recurrence and the
    # work with those series for P and Q. The residuals are formed on coefficient lists, exact
    # polynomials in sin theta0, cos theta0, omega0 and sin c, cos c of each sinusoid (the identities
    # are linear in the forcing): sin(theta0 + d) = sin theta0 cos d + cos theta0 sin d with
    # d = O(tau) by Maclaurin's series, independent of the recurrence (sympy's series is slow here).
    n = order
    A, w, B, w2 = sp.Rational(31, 10), sp.Rational(9), sp.Rational(-19, 10), sp.Rational(14)
    S0, C0, sA, cA, sB, cB, c_ = sp.symbols('S0 C0 sA cA sB cB c_', real=True)
    gens = (S0, C0, om0, sA, cA, sB, cB)
    us = [x / g for x in sinusoid_series(A, w, sA, cA, n + 1)]
    vs = [x / g for x in sinusoid_series(B, w2, sB, cB, n + 1)]
    vs[0] += 1
    useries = sp.series(A * sp.sin(w * tau + c_), tau, 0, n + 1).removeO()
    res['series_sinusoid'] = all(
        is_zero(useries.coeff(tau, i).subs({sp.sin(c_): sA, sp.cos(c_): cA}) - us[i] * g) for i in range(n + 1))

    def poly_(e):  # an exact polynomial in gens
        return sp.Poly(sp.expand(sp.sympify(e).subs({sp.sin(th0): S0, sp.cos(th0): C0})), *gens, domain='QQ')

    def mul(a, b):  # Cauchy product to power n - 1
        return [sum((a[i] * b[j - i] for i in range(j + 1)), poly_(0)) for j in range(n)]

    def sin_cos(s0, c0, d):  # sin and cos of x0 + d from sin x0, cos x0; d[0] = 0
        sd, cd, term = [poly_(0)] * n, [poly_(0)] * n, [poly_(1)] + [poly_(0)] * (n - 1)
        for m in range(n):
            if m > 0:
                term = [x * poly_(sp.Rational(1, m)) for x in mul(term, d)]
            acc, sgn = (sd if m % 2 else cd), (-1) ** (m // 2)
            for j in range(n):
                acc[j] = acc[j] + term[j] * poly_(sgn)
        sx = [x * poly_(s0) + y * poly_(c0) for x, y in zip(cd, sd)]
        cx = [x * poly_(c0) - y * poly_(s0) for x, y in zip(cd, sd)]
        return sx, cx

    su, cu = sin_cos(0, 1, [poly_(0), poly_(w)] + [poly_(0)] * (n - 2))
    sv, cv = sin_cos(0, 1, [poly_(0), poly_(w2)] + [poly_(0)] * (n - 2))
    uu = [(x * poly_(sA) + y * poly_(cA)) * poly_(A / g) for x, y in zip(cu, su)]
    vv = [(x * poly_(sB) + y * poly_(cB)) * poly_(B / g) for x, y in zip(cv, sv)]
    vv[0] = vv[0] + poly_(1)
    Pk = [(poly_(al) * y + x) * poly_(k) for x, y in zip(uu, vv)]
    Qk = [(y - poly_(al) * x) * poly_(k) for x, y in zip(uu, vv)]
    thc, sc, cc = rocking_series_recurrence([k * (al * vs[i] + us[i]) for i in range(n + 1)],
                                            [k * (vs[i] - al * us[i]) for i in range(n + 1)],
                                            th0, om0, n)
    th = [poly_(x) for x in thc[1:n + 2]]  # theta - theta0, powers 1..n+1
    d = [poly_(0)] + th[:n - 1]
    sp_, cp_ = sin_cos(S0, C0, d)
    acc = [poly_((j + 2) * (j + 1)) * th[j + 1] for j in range(n)]  # theta'' to power n - 1
    rhs = [x + y for x, y in zip(mul(Pk, cp_), mul(Qk, sp_))]
    res['series_recurrence_sinusoids'] = all((x - y).is_zero for x, y in zip(acc, rhs))
    res['series_sincos_sinusoids'] = all((sp_[i] - poly_(sc[i])).is_zero and (cp_[i] - poly_(cc[i])).is_zero
                                         for i in range(n))
    # the work's bracket: a_i c + b_i s summed over the forcing's terms, the constant -1 in v's first
    ai = [M * h * g * (us[i] + al * (vs[i] - (1 if i == 0 else 0))) for i in range(n)]
    bi = [M * h * g * ((vs[i] - (1 if i == 0 else 0)) - al * us[i]) for i in range(n)]
    W = rocking_work_recurrence(ai, bi, thc, sc, cc, n)
    dW = [poly_((kk + 1) * W[kk]) for kk in range(n)]  # W' to power n - 1
    vm1 = list(vv)
    vm1[0] = vm1[0] - poly_(1)
    bracket = [a + b for a, b in zip(mul([x + poly_(al) * y for x, y in zip(uu, vm1)], cp_),
                                     mul([y - poly_(al) * x for x, y in zip(uu, vm1)], sp_))]
    dth = [poly_(j + 1) * th[j] for j in range(n)]  # theta' to power n - 1
    power = [x * poly_(M * h * g) for x in mul(dth, bracket)]
    res['series_work_sinusoids'] = all((x - y).is_zero for x, y in zip(dW, power))
    return res


def derive_free_rocking_arc():
    """a rigid body rocking freely on a floor at rest, in closed form (docs/theory.md, "Free
    rocking in closed form"): the series' equation with u = 0, v = 1 as phi'' = P^2 sin(phi), phi =
    alpha_t - |theta|; the floor reaction and the moment as functions of phi on an arc of energy cm;
    their critical points; Jacobi's solution sin(phi/2) = s/dn(P (t - t_peak), k) against the energy
    integral, and its times against an independent integration (mpmath's Taylor ODE solver)."""
    be, c, kk, G, mt, sg, cm, Sp, Cp, P2 = sp.symbols('beta c k G mt sg cm Sp Cp P2', real=True)
    res = {}

    def red(expr):
        # exact reduction with c^2 = 1 + beta^2, Sp^2 + Cp^2 = 1, sg^2 = 1
        num, den = sp.fraction(sp.together(sp.expand(expr)))
        num = sp.expand(num)
        for sym, rel_ in ((c, c ** 2 - 1 - be ** 2), (Sp, Sp ** 2 + Cp ** 2 - 1), (sg, sg ** 2 - 1)):
            num = sp.rem(num, rel_, sym)
        return sp.expand(num) == 0

    al = -sg * be                        # the pivot's alpha: restoring towards theta = 0
    cth = (Cp + be * Sp) / c             # cos(theta), theta = sg (alpha_t - phi), tan alpha_t = beta
    sth = sg * (be * Cp - Sp) / c        # sin(theta)
    k = G / mt                           # the series' k = (g/h)/m, mt = 1 + zeta^2 + beta^2
    # theta'' = k (alpha cos + sin) (u = 0, v = 1) is phi'' = -sg theta'' = P^2 sin(phi), P^2 = k c
    res['arc_equation'] = red(-sg * k * (al * cth + sth) - k * c * Sp)
    # on an arc of energy phi'^2/2 + P^2 cos(phi) = P^2 cm: theta_dot^2 and theta''
    thd2 = 2 * k * c * (cm - Cp)
    thdd = -sg * k * c * Sp
    A_ = (al * thd2 - thdd) / G
    B_ = (al * thdd + thd2) / G
    kap = mt / c ** 2                    # I_O / (M R^2)
    lam = c / mt
    Fi = A_ * cth + B_ * sth
    Fj = 1 + A_ * sth - B_ * cth
    Mo = al * (cth - B_)
    res['arc_reaction'] = (red(Fi - sg * Sp * (3 * Cp - 2 * cm) / kap)
                           and red(Fj - (1 - (1 - 3 * Cp ** 2 + 2 * cm * Cp) / kap))
                           and red(Mo + sg * be * ((Cp + be * Sp) / c - lam * (be * Sp + 2 * cm - 2 * Cp))))
    # critical points in phi: F_I's factor sin(phi) (3 cos(phi) - 2 cm) has derivative
    # 6 cos^2 - 2 cm cos - 3, zero at cos = (cm + sqrt(cm^2 + 18))/6; the moment's bracket has
    # derivative cos (beta/c - lambda beta) - sin (1/c + 2 lambda)
    ph = sp.Symbol('phi', real=True)
    f = sp.sin(ph) * (3 * sp.cos(ph) - 2 * cm)
    df = sp.expand(sp.expand_trig(sp.diff(f, ph))).subs(sp.sin(ph) ** 2, 1 - sp.cos(ph) ** 2)
    x = sp.Symbol('x')
    root = (cm + sp.sqrt(cm ** 2 + 18)) / 6
    res['arc_shear_critical'] = (sp.expand(df - (6 * sp.cos(ph) ** 2 - 2 * cm * sp.cos(ph) - 3)) == 0
                                 and sp.simplify((6 * x ** 2 - 2 * cm * x - 3).subs(x, root)) == 0)
    m_ = (sp.cos(ph) + be * sp.sin(ph)) / c - lam * (be * sp.sin(ph) + 2 * cm - 2 * sp.cos(ph))
    res['arc_moment_critical'] = sp.simplify(
        sp.diff(m_, ph) - (sp.cos(ph) * (be / c - lam * be) - sp.sin(ph) * (1 / c + 2 * lam))) == 0
    # Jacobi's solution: sin(phi/2) = s/dn(v), cos(phi/2) = k cn/dn, phi' = 2 P s k sn/dn, v = P (t -
    # t_peak), k^2 = 1 - s^2; sn' = cn dn, dn' = -k^2 sn cn. The two halves' squares sum to 1, the
    # derivative of s/dn is cos(phi/2) phi'/2, and phi'^2 = 2 P^2 (cm - cos(phi)) with
    # cm = 1 - 2 s^2, cos(phi) = 1 - 2 s^2/dn^2
    sn, cn, dn, s, P = sp.symbols('sn cn dn s P', positive=True)
    km = sp.sqrt(1 - s ** 2)
    on = {cn ** 2: 1 - sn ** 2, dn ** 2: 1 - km ** 2 * sn ** 2}

    def zero_jac(e):
        num = sp.expand(sp.fraction(sp.together(sp.expand(e)))[0])
        num = sp.rem(num, cn ** 2 - 1 + sn ** 2, cn)
        num = sp.rem(sp.expand(num), dn ** 2 - 1 + km ** 2 * sn ** 2, dn)
        return sp.simplify(num) == 0

    dphi = 2 * P * s * km * sn / dn
    res['arc_jacobi'] = (zero_jac((s / dn) ** 2 + (km * cn / dn) ** 2 - 1)
                         and zero_jac(-s * (-km ** 2 * sn * cn) * P / dn ** 2 - (km * cn / dn) * dphi / 2)
                         and zero_jac(dphi ** 2 - 2 * P ** 2 * ((1 - 2 * s ** 2) - (1 - 2 * s ** 2 / dn ** 2))))
    # Carlson's form F(asin(sn), k) = sn R_F(1 - sn^2, 1 - k^2 sn^2, 1) with sn^2 = (S^2 - s^2)/(k^2
    # S^2), S = sin(phi/2): its arguments are s^2 C^2/(k^2 S^2) and s^2/S^2 (C^2 = 1 - S^2), as
    # src/sim/free_rocking_arc.hpp forms them
    S_ = sp.Symbol('S', positive=True)
    sn2 = (S_ ** 2 - s ** 2) / (km ** 2 * S_ ** 2)
    res['arc_carlson_arguments'] = (sp.simplify(1 - sn2 - s ** 2 * (1 - S_ ** 2) / (km ** 2 * S_ ** 2)) == 0
                                    and sp.simplify(1 - km ** 2 * sn2 - s ** 2 / S_ ** 2) == 0)
    # the times, numerically: from (phi0, phi0') the peak comes after v0/P, sn(v0) = |phi0'|/(2 P k
    # sin(phi0/2)), and the impact (phi = alpha_t) v_I/P after the peak, sn(v_I)^2 = (sin(theta0/2)
    # sin(alpha_t - theta0/2) + phi0'^2/(4 P^2))/(k^2 sin^2(alpha_t/2)); against mpmath's ODE solver
    worst = mp.mpf(0)
    for (alt, Pn, th0, om0) in ((0.2, 2.7, 0.05, 0.3), (0.6, 1.9, 0.3, -0.2), (0.1, 4.0, 0.0, 0.35),
                                (0.35, 3.1, 0.34, 0.0)):
        alt, Pn, th0, om0 = mp.mpf(alt), mp.mpf(Pn), mp.mpf(th0), mp.mpf(om0)
        ph0 = alt - th0
        s2 = mp.sin(ph0 / 2) ** 2 - om0 ** 2 / (4 * Pn ** 2)
        sv, kv = mp.sqrt(s2), mp.sqrt(1 - s2)
        v0 = mp.ellipf(mp.asin(abs(om0) / (2 * Pn * kv * mp.sin(ph0 / 2))), kv ** 2)
        t_peak = (v0 if om0 > 0 else -v0) / Pn
        snI = mp.sqrt((mp.sin(th0 / 2) * mp.sin(alt - th0 / 2) + om0 ** 2 / (4 * Pn ** 2))
                      / (kv ** 2 * mp.sin(alt / 2) ** 2))
        t_imp = t_peak + mp.ellipf(mp.asin(snI), kv ** 2) / Pn
        sol = mp.odefun(lambda t, y: [y[1], Pn ** 2 * mp.sin(y[0])], 0, [ph0, -om0])
        worst = max(worst, abs(sol(t_imp)[0] - alt))
        for frac in (0.25, 0.5, 0.9):
            t = frac * t_imp
            closed = 2 * mp.asin(sv / mp.ellipfun('dn', Pn * (t - t_peak), kv ** 2))
            dclosed = 2 * Pn * sv * kv * mp.ellipfun('sn', Pn * (t - t_peak), kv ** 2) / \
                mp.ellipfun('dn', Pn * (t - t_peak), kv ** 2)
            y = sol(t)
            worst = max(worst, abs(y[0] - closed), abs(y[1] - dclosed) / Pn)
    res['arc_times_against_integration'] = bool(worst < mp.mpf(10) ** -12)
    res['arc_times_worst'] = float(worst)
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--out')
    ap.add_argument('--seed', type=int, default=12345)
    ap.add_argument('--print', action='store_true', dest='do_print')
    ap.add_argument('--symbolic-n', type=int, default=3, help='largest n for the symbolic checks')
    ap.add_argument('--symbolic-flight-n', type=int, default=2,
                    help='largest n for the symbolic flight / landing checks')
    args = ap.parse_args()
    t0 = time.time()
    sres, gens = symbolic_checks(range(0, args.symbolic_n + 1), verbose=True, flight_n=args.symbolic_flight_n)
    rres, rforms = derive_rigid_friction()
    sres['rigid_friction'] = rres
    sres['walk_bound'] = walk_bound_checks()
    print('  symbolic record-walk bound: %s' % sres['walk_bound'], file=sys.stderr)
    sres['walk_exact'] = walk_exact_checks()
    print('  symbolic record-walk pieces: %s' % sres['walk_exact'], file=sys.stderr)
    print('  symbolic rigid block with friction: %s' % rres, file=sys.stderr)
    sres['modal_coordinates'] = modal_coordinate_checks()
    print('  symbolic modal coordinates: %s' % sres['modal_coordinates'], file=sys.stderr)
    sres['rocking_series'] = derive_rocking_series()
    print('  rigid rocking by its Taylor series: %s' % sres['rocking_series'], file=sys.stderr)
    sres['free_rocking_arc'] = derive_free_rocking_arc()
    print('  free rocking in closed form: %s' % sres['free_rocking_arc'], file=sys.stderr)
    sres['compliant_potential'], compliant_refs = compliant_potential()
    sres['axisymmetric3d'], axisymmetric_refs = axisymmetric3d.derive()
    print('  compliant contact potential: %s' % sres['compliant_potential'], file=sys.stderr)
    sres['restraints'] = __import__('restraints').restraints()[0]
    print('  restraints (tendons, anchors): %s' % sres['restraints'], file=sys.stderr)
    sres['support'], support_refs = support.support_checks()
    print('  block on a moving support: %s' % sres['support'], file=sys.stderr)
    sres['assemblies'], assembly_refs = assemblies.checks()  # theory §25: frames and stacks
    print('  rocking frames and stacked bodies: %s' % sres['assemblies'], file=sys.stderr)
    failed = [(n, k) for n, r in sres.items() for k, v in r.items()
              if (isinstance(v, bool) and not v) or (isinstance(v, list) and v)]
    print('symbolic checks (n=0..%d): %s  [%.1f s]' % (args.symbolic_n, 'ALL PASS' if not failed else
                                                      'FAILED %s' % failed, time.time() - t0), file=sys.stderr)
    if args.do_print:
        print_equations(gens)
        print('=' * 72)
        print('Coulomb friction (n <= %d): Lagrange in (d, theta, q) with the pivot at X + d + h alpha;' %
              args.symbolic_flight_n)
        for n, Gn in sorted(gens.items()):
            if hasattr(Gn, 'slide_EL') and n <= 1:
                print('n = %d: d-row (= F_I, the floor force at the pivot):' % n)
                print('   ', sp.collect(trig_reduce(Gn.slide_EL[0]), [Gn.thd, Gn.thdd, sp.Symbol('ddd')]))
        print('rigid block (uniform or not; a = a_x, a_y = 1, edge 1, alpha = b_1/h):')
        for k, v in rforms.items():
            print('   %s = %s' % (k, v))
    if not args.out:
        return 1 if failed else 0
    rng = np.random.RandomState(args.seed)
    chk = Checker()
    stats = dict(impacts=0, both_applies=0, both_negative=[], min_ratio=1e9)
    fstats = dict(liftoff=0, landings=0, tensile_landing=0, flat=0, flat_compressive=0,
                  both_single_admissible=0)
    xstats = dict(slide_rock=0, slide_full=0, k_nonpositive=0, friction_landings=0, mode_stick=0, mode_slip=0,
                  impact_k_nonpositive=0, tensile_stick=0, tensile_resolved=0, flat_friction=0, flat_stick=0,
                  flat_slip=0, rigid_body_stick=0, rigid_body_slip=0, rigid_body_gain=0)
    cases = []
    kernels, fkernels = {}, {}
    for n in range(4):
        K = kernels.setdefault(n, PointMassKernel(n))
        FK = fkernels.setdefault(n, FlightKernel(n))
        bodies = [random_body(rng, n, 'random n=%d #%d' % (n, i)) for i in range(3)]
        if n == 0:
            bodies.append(squat_block())
        for b in bodies:
            cases.append(case_json(b, K, rng, chk, stats))
        # flight, lift-off and landings: a separate random stream, so the cases above stay as they were
        frng = np.random.RandomState(args.seed + 1 + n)
        for b, c in zip(bodies, cases[-len(bodies):]):
            c.update(flight_cases(K, FK, b, frng, chk, fstats))
        # Coulomb friction: sliding modes and impacts with friction (another separate stream)
        xrng = np.random.RandomState(args.seed + 101 + n)
        for b, c in zip(bodies, cases[-len(bodies):]):
            c['friction'] = friction_cases(K, FK, b, xrng, chk, xstats)
    # extra impacts (not written): wide-base flexible bodies, large modal rates, to exercise
    # the both-edges rule and check that both edge impulses are compressive where it applies
    st2 = dict(impacts=0, both_applies=0, both_negative=[], min_ratio=1e9)
    for n in (1, 2, 3):
        K = kernels[n]
        for i in range(4):
            b = random_body(rng, n, 'stress n=%d #%d' % (n, i))
            b.b1, b.b2 = b.h * mpf(rng.uniform(0.1, 2.5)), b.h * mpf(rng.uniform(0.1, 2.5))
            b.params()
            for k in range(6):
                q = [mpf(0.1 * rng.normal()) for _ in range(n)]
                qd = [mpf(rng.normal() * rng.choice([0.1, 1.0, 10.0])) for _ in range(n)]
                land = 1 + k % 2
                thdm = mpf(rng.uniform(0.05, 1.5)) * (1 if land == 1 else -1)
                impact(K, b, land, q, thdm, qd, [0, 0], chk, st2)
    # extra landings (not written): fast horizontal corner velocities, as after a flight over a base
    # that kept accelerating; a sticking corner can then need a tensile normal impulse
    fst2 = dict(liftoff=0, landings=0, tensile_landing=0)
    for n in (0, 1, 2):
        K, FK = kernels[n], fkernels[n]
        for i in range(2):
            b = random_body(rng, n, 'landing stress n=%d #%d' % (n, i))
            h = b.h
            for k in range(6):
                edge = 1 + k % 2
                sg = 1 if edge == 1 else -1
                q = [mpf(0.05 * rng.normal()) for _ in range(n)]
                qd = [mpf(rng.normal()) for _ in range(n)]
                th = mpf(rng.uniform(0.0, 0.4)) * sg
                thd = mpf(rng.uniform(-1.5, 1.5))
                ce = rot((h * alpha_of(b, edge), 0), th)
                sgh = mp.sqrt(G * h)
                x = [-ce[0], -ce[1], th] + q
                xd = [mpf(rng.uniform(-2, 2)) * sgh, -thd * ce[0] - mpf(rng.uniform(0.02, 0.5)) * sgh, thd] + qd
                landing(K, FK, b, edge, 0, th, q, x, xd, [0, 0], chk, fst2, 'stress landing')
    # extra landings with friction (not written): the same fast corners; with Coulomb friction a
    # sticking corner that would need a tensile impulse slides instead
    for n in (0, 1, 2):
        K, FK = kernels[n], fkernels[n]
        for i in range(2):
            b = random_body(rng, n, 'friction landing stress n=%d #%d' % (n, i))
            h = b.h
            for k in range(6):
                edge = 1 + k % 2
                sg = 1 if edge == 1 else -1
                q = [mpf(0.05 * rng.normal()) for _ in range(n)]
                qd = [mpf(rng.normal()) for _ in range(n)]
                th = mpf(rng.uniform(0.0, 0.4)) * sg
                thd = mpf(rng.uniform(-1.5, 1.5))
                ce = rot((h * alpha_of(b, edge), 0), th)
                sgh = mp.sqrt(G * h)
                x = [-ce[0], -ce[1], th] + q
                xd = [mpf(rng.uniform(-2, 2)) * sgh, -thd * ce[0] - mpf(rng.uniform(0.02, 0.5)) * sgh, thd] + qd
                mu_s = mpf(rng.uniform(0.05, 1.0))
                friction_landing(K, FK, b, edge, th, q, x, xd, [0, 0], mu_s, mu_s * mpf(rng.uniform(0.6, 1.0)),
                                 chk, xstats, 'friction stress landing')
    t0r = dict(cases=0, consistent_1=0, consistent_2=0, consistent_3=0, frictionless_choice_inconsistent=0,
               ambiguous_min_mu_s=1e9, ambiguous_frictionless_choice_consistent=0)
    theta0_rule_with_friction(args.seed + 7, 600, t0r)
    print('theta = 0 with friction (corner 1 / corner 2 / flat, each with Coulomb): %d cases, one consistent '
          'outcome in %d, two in %d (smallest mu_s %.3g; the frictionless choice among them in %d), three in %d; '
          'the frictionless choice of theory 16 is inconsistent in %d' %
          (t0r['cases'], t0r['consistent_1'], t0r['consistent_2'], t0r['ambiguous_min_mu_s'],
           t0r['ambiguous_frictionless_choice_consistent'], t0r['consistent_3'],
           t0r['frictionless_choice_inconsistent']), file=sys.stderr)
    theta0_friction, t0taken = theta0_friction_cases(args.seed + 211, 72)
    print('theta = 0 with friction, the engine\'s rule (written): %d landings, taken corner 1 in %d, corner 2 in %d, '
          'flat in %d, none consistent in %d' % (len(theta0_friction), t0taken['corner1'], t0taken['corner2'],
                                                t0taken['flat'], t0taken['inconsistent']), file=sys.stderr)
    rigid_friction = rigid_friction_checks(kernels[0], chk)
    pulses = pulse_checks(chk)
    for rb in rigid_friction:
        print('rigid block b/h = %.2f: friction demand at uplift b/h, after uplift %s; Painleve mu = %.4f' %
              (rb['b_over_h'], ', '.join('%.2f -> %.4f' % (x['a'], x['demand']) for x in rb['demand_after_uplift']),
               rb['painleve_mu']), file=sys.stderr)
    for pu in pulses:
        print('sliding under a %s pulse A = %.3g g, t1 = %.3g s, mu_s = %.3g, mu_k = %.3g: final offset %.9g m '
              '(fixed-step integration %.9g m), %d phases' %
              (pu['kind'], pu['A'] / G, pu['t1'], pu['mu_s'], pu['mu_k'], pu['final_offset'],
               pu['stepping_final_offset'], len(pu['phases'])), file=sys.stderr)
    rl = rigid_liftoff_condition(kernels[0], fkernels[0], chk)
    print('rigid lift-off at F_J = 0 (theta, a_x/g, corner ydd in flight): %s' %
          ', '.join('(%.1f, %+.1f, %+.3f)' % x for x in rl), file=sys.stderr)
    print('stress landings: %d, tensile normal impulse with a sticking corner in %d' %
          (fst2['landings'], fst2['tensile_landing']), file=sys.stderr)
    print('stress impacts: %d, both-edges rule applies in %d, negative edge impulse in: %s; the rigid_body '
          'law would add energy in %d (the engine then takes the paper\'s law)' %
          (st2['impacts'], st2['both_applies'], st2['both_negative'] or 'none', st2.get('rigid_gain', 0)),
          file=sys.stderr)
    sq = cases[3]
    ratio = sq['impacts'][0]['theta_dot_plus'] / sq['impacts'][0]['theta_dot_minus']
    chk.eq(ratio, mp.mpf(1) - mp.mpf(3) / 2 * mp.sin(mp.atan(2)) ** 2, 'Housner ratio')
    with open(args.out, 'w') as fh:
        fh.write('{"g": 9.80665, "seed": %d, "cases": [\n' % args.seed)
        fh.write(',\n'.join(fmt(c) for c in cases))
        fh.write('\n], "rigid_block_friction": %s, "sliding_pulses": %s, "compliant_potential": %s, '
                 '"friction_theta0": %s, "support": %s}\n' %
                 (fmt(rigid_friction), fmt(pulses), fmt(compliant_refs), fmt(theta0_friction),
                  json.dumps(support_refs)))
    json.load(open(args.out))
    with open(os.path.join(os.path.dirname(os.path.abspath(args.out)), 'assemblies_reference.json'), 'w') as fh:
        json.dump(assembly_refs, fh, indent=1)
    # the 3D body of revolution's references, next to the main file
    axi_out = (args.out[:-5] if args.out.endswith('.json') else args.out) + '_axisymmetric3d.json'
    with open(axi_out, 'w') as fh:
        json.dump(axisymmetric_refs, fh, indent=1)
    print('numeric cases: %d, max relative (a)-vs-(b) difference %.2e (%s)' %
          (len(cases), float(chk.maxerr), chk.where), file=sys.stderr)
    print('impacts: %d, both-edges rule applies in %d, negative edge impulse in: %s; min thd+/thd- = %.4f' %
          (stats['impacts'], stats['both_applies'], stats['both_negative'] or 'none', stats['min_ratio']),
          file=sys.stderr)
    print('flight: lift-offs %d, landings %d (tensile normal impulse with a sticking corner in %d), flat landings '
          '%d (both corners compressive in %d, both single-corner maps admissible in %d)' %
          (fstats['liftoff'], fstats['landings'], fstats['tensile_landing'], fstats['flat'],
           fstats['flat_compressive'], fstats['both_single_admissible']), file=sys.stderr)
    print('friction: sliding states %d rocking, %d full contact (k_s <= 0 in %d); impacts %d (stick %d, slip %d, '
          'k_s <= 0 in %d; a sticking corner would need a tensile impulse in %d, all resolved by sliding: %d); '
          'flat %d (stick %d, slip %d); under the rigid_body law stick %d, slip %d, energy gained in %d' %
          (xstats['slide_rock'], xstats['slide_full'], xstats['k_nonpositive'], xstats['friction_landings'],
           xstats['mode_stick'], xstats['mode_slip'], xstats['impact_k_nonpositive'], xstats['tensile_stick'],
           xstats['tensile_resolved'], xstats['flat_friction'], xstats['flat_stick'], xstats['flat_slip'],
           xstats['rigid_body_stick'], xstats['rigid_body_slip'], xstats['rigid_body_gain']),
          file=sys.stderr)
    print('total %.1f s' % (time.time() - t0), file=sys.stderr)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
