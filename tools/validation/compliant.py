# SPDX-License-Identifier: BSD-3-Clause
"""An independent model of docs/validation.md, section 5: a body on a compliant foundation.

The body is a rigid base (a block, or a slab carrying an elastic oscillator) with free planar
motion (x, y, theta) and, for the oscillator, the top mass's displacement u along the body. At
each base corner a spring-dashpot pushes up (no tension) and a horizontal spring-dashpot holds the
corner where it stood while the corner is in contact (no sliding). Nothing here comes from the
engine: the equations are written from the kinematics of the points, M(q) q'' = Q(q, q', t), and
integrated as one smooth system (LSODA), so uplift and impacts are outcomes of the springs.
"""

import math

import numpy as np
from scipy.integrate import solve_ivp

G = 9.80665


class CompliantBody:
    """A base of half-width b with its corners at the base line, y = 0 in the body frame.

    rigid part: mass m_r, c.g. at (0, h_r) in the body frame, rotary inertia i_r about its c.g.
    oscillator (optional): top mass m_top at (u, H), lateral spring k_top, dashpot c_top.
    """

    def __init__(self, b, m_r, h_r, i_r, m_top=0.0, H=0.0, k_top=0.0, c_top=0.0):
        self.b, self.m_r, self.h_r, self.i_r = b, m_r, h_r, i_r
        self.m_top, self.H, self.k_top, self.c_top = m_top, H, k_top, c_top
        self.n = 4 if m_top > 0 else 3
        self.M = m_r + m_top

    @staticmethod
    def block(alpha, R, mass=1000.0):
        b, h = R * math.sin(alpha), R * math.cos(alpha)
        return CompliantBody(b, mass, h, mass * (b * b + h * h) / 3.0)

    @staticmethod
    def oscillator(m, f_hz, m0, H, width, zeta):
        b = 0.5 * width
        k = m * (2 * math.pi * f_hz) ** 2
        c = 2 * zeta * math.sqrt(k * m)
        return CompliantBody(b, m0, 0.0, m0 * width * width / 12.0, m, H, k, c)

    def cg_height(self):
        return (self.m_r * self.h_r + self.m_top * self.H) / self.M

    def rocking_frequency(self):
        # p = sqrt(M g R / I_O) about a corner, for the rigid body
        hc = self.cg_height()
        i_o = self.i_r + self.m_r * (self.b**2 + self.h_r**2) + self.m_top * (self.b**2 + self.H**2)
        return math.sqrt(self.M * G * math.hypot(self.b, hc) / i_o)


def rot(t):
    c, s = math.cos(t), math.sin(t)
    return c, s


def make_rhs(body, acc, kv, cv):
    """q = (x, y, theta[, u]), relative to the ground; acc(t) the ground acceleration [m/s^2]."""
    n = body.n
    b = body.b

    def rhs(t, z):
        q, v = z[:n], z[n:]
        x, y, th = q[0], q[1], q[2]
        xd, yd, thd = v[0], v[1], v[2]
        c, s = rot(th)
        ag = acc(t)
        M = np.zeros((n, n))
        Q = np.zeros(n)

        # a point at body-frame (px, py): position (x, y) + R (px, py); J = [1 0 dR(p); 0 1 ...]
        def add_point(m, px, py, extra_col=None, extra_dcol=None):
            # dR/dtheta (px, py) and d2R/dtheta2 (px, py) = -R (px, py)
            dx, dy = -s * px - c * py, c * px - s * py
            J = np.zeros((2, n))
            J[0, 0] = 1.0
            J[1, 1] = 1.0
            J[0, 2], J[1, 2] = dx, dy
            # J' q' (centripetal, and Coriolis with the mode)
            jd = np.array([-(c * px - s * py) * thd * thd, -(s * px + c * py) * thd * thd])
            if extra_col is not None:
                J[0, 3], J[1, 3] = extra_col
                jd += 2 * thd * v[3] * np.array(extra_dcol)
            f = np.array([-m * ag, -m * G])
            M[:, :] += m * J.T @ J
            Q[:] += J.T @ (f - m * jd)

        add_point(body.m_r, 0.0, body.h_r)
        M[2, 2] += body.i_r
        if n == 4:
            u = q[3]
            # top mass at (u, H): d/du = R e_x = (c, s); d/dtheta of that = (-s, c)
            add_point(body.m_top, u, body.H, (c, s), (-s, c))
            Q[3] -= body.k_top * u + body.c_top * v[3]
        # corners (-b, 0) and (b, 0): spring-dashpots, no tension, no sliding while in contact
        for sx in (-1.0, 1.0):
            px = sx * b
            cx, cy = x + c * px, y + s * px
            vx, vy = xd - s * px * thd, yd + c * px * thd
            d = -cy
            if d <= 0.0:
                continue
            fy = max(0.0, kv * d - cv * vy)
            fx = -kv * (cx - px) - cv * vx
            Q[0] += fx
            Q[1] += fy
            Q[2] += (-s * px) * fx + (c * px) * fy
        a = np.linalg.solve(M, Q)
        return np.concatenate([v, a])

    return rhs


def simulate(body, acc, t_end, stiffness_ratio, zeta_f, alpha, overturn_angle=math.pi / 2,
             rtol=1e-8):
    """Runs the body from rest on the springs; stiffness_ratio = omega_v/p with omega_v the
    vertical frequency sqrt(2 kv/M) on both corners; zeta_f the vertical damping ratio; alpha
    the tipping angle (impacts are sign changes of theta between excursions above alpha/100);
    the run stops as overturned when |theta| reaches overturn_angle."""
    p = body.rocking_frequency()
    wv = stiffness_ratio * p
    kv = 0.5 * body.M * wv * wv
    cv = zeta_f * math.sqrt(2 * kv * body.M)  # per corner: critical of the vertical mode times zeta
    n = body.n
    z0 = np.zeros(2 * n)
    z0[1] = -body.M * G / (2 * kv)  # static settlement
    rhs = make_rhs(body, acc, kv, cv)

    def over(t, z):
        return overturn_angle - abs(z[2])

    over.terminal = True
    sol = solve_ivp(rhs, (0.0, t_end), z0, method="LSODA", rtol=rtol, atol=1e-10,
                    max_step=min(0.2 / wv, 0.01), dense_output=False, events=over)
    t, th = sol.t, sol.y[2]
    y, b = sol.y[1], body.b
    # a corner is up when it stands above the base line
    up1 = y - np.sin(th) * b > 0  # left corner (-b)
    up2 = y + np.sin(th) * b > 0
    lifted = up1 | up2
    first_uplift = float(t[np.argmax(lifted)]) if lifted.any() else -1.0
    # impacts: theta passes through zero between excursions larger than 1% of alpha
    impacts, sign, tol = 0, 0, 0.01 * alpha
    impact_times = []
    for ti, v in zip(t, th):
        if v > tol:
            if sign < 0:
                impacts += 1
                impact_times.append(float(ti))
            sign = 1
        elif v < -tol:
            if sign > 0:
                impacts += 1
                impact_times.append(float(ti))
            sign = -1
    return {
        "stiffness_ratio": stiffness_ratio,
        "first_uplift": first_uplift,
        "max_theta": float(np.max(np.abs(th))),
        "impacts": impacts,
        "impact_times": impact_times,
        "overturned": bool(sol.status == 1),
        "t": t[:: max(1, len(t) // 2000)].tolist(),
        "theta": th[:: max(1, len(t) // 2000)].tolist(),
    }
