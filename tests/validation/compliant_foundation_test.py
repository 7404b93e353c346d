# SPDX-License-Identifier: BSD-3-Clause
"""The independent compliant-foundation model of docs/validation.md (tools/validation/compliant.py)
against closed forms: its static settlement, and its uplift time under a one-sine pulse, which
must approach the rigid block's asin(1/A)/omega_p as the foundation stiffens."""

import math
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "validation"))
import compliant  # noqa: E402


class CompliantFoundation(unittest.TestCase):
    def test_block_rests_at_its_static_settlement(self):
        body = compliant.CompliantBody.block(0.2, 1.0)
        r = compliant.simulate(body, lambda t: 0.0, 0.5, 100, 1.0, 0.2)
        self.assertEqual(r["impacts"], 0)
        self.assertEqual(r["first_uplift"], -1.0)
        self.assertLess(r["max_theta"], 1e-12)

    def test_uplift_time_converges_to_the_rigid_closed_form(self):
        alpha, A, W = 0.15, 1.5, 4.0
        body = compliant.CompliantBody.block(alpha, 1.0)
        p = body.rocking_frequency()
        self.assertAlmostEqual(p, math.sqrt(3 * compliant.G / 4), places=12)
        wp, ap = W * p, A * compliant.G * math.tan(alpha)
        t_rigid = math.asin(1 / A) / wp
        errors = []
        for k in (100, 300, 1000):
            r = compliant.simulate(body, lambda t: ap * math.sin(wp * t), 2 * t_rigid, k, 1.0,
                                   alpha)
            self.assertGreater(r["first_uplift"], 0.0)
            errors.append(abs(r["first_uplift"] - t_rigid) / t_rigid)
        # the delay is the time the springs need to unload: it shrinks as they stiffen
        self.assertLess(errors[2], errors[0])
        self.assertLess(errors[2], 0.03)

    def test_oscillator_body_has_the_rigid_rocking_frequency_of_its_masses(self):
        # slab m0 (width w) and top mass m at H: I_O = m0 (w^2/12 + b^2) + m (b^2 + H^2)
        body = compliant.CompliantBody.oscillator(1000, 2.0, 500, 3.0, 0.6, 0.05)
        b, h = 0.3, 2.0
        i_o = 500 * (0.36 / 12 + b * b) + 1000 * (b * b + 9.0)
        self.assertAlmostEqual(body.cg_height(), h, places=12)
        self.assertAlmostEqual(body.rocking_frequency(),
                               math.sqrt(1500 * compliant.G * math.hypot(b, h) / i_o), places=12)
        self.assertTrue(np.isfinite(body.rocking_frequency()))


if __name__ == "__main__":
    unittest.main()
