# SPDX-License-Identifier: BSD-3-Clause
"""SimulationOptions.methods: the engine's method switches, kept for comparisons. A rigid block's
rocking stepped by its Taylor series and by DOPRI5 must agree within the tolerances (two
integrations written differently), and the group is set in place."""
import math

import numpy as np

import flexrock as fr


def test_methods_are_a_group_set_in_place():
    o = fr.SimulationOptions()
    assert o.methods.series_rocking and o.methods.rocking_integrator == fr.ContactIntegrator.auto
    o.methods.series_rocking = False
    o.methods.rocking_integrator = fr.ContactIntegrator.explicit
    assert not o.methods.series_rocking
    assert o.methods.rocking_integrator == fr.ContactIntegrator.explicit
    assert not hasattr(o, "series_rocking")  # not a [solver] key


def test_series_and_dopri5_rocking_agree():
    body = fr.rigid_block(0.4, 1.8, 800.0)
    t = np.arange(0.0, 3.0, 0.01)
    motion = fr.motion_from_array(3.0 * np.sin(2 * math.pi * 1.5 * t), dt=0.01)
    series = fr.SimulationOptions()
    series.rtol, series.atol = 1e-10, 1e-12
    dopri5 = fr.SimulationOptions()
    dopri5.rtol, dopri5.atol = 1e-10, 1e-12
    dopri5.methods.series_rocking = False
    a = fr.simulate(body, motion, options=series)
    b = fr.simulate(body, motion, options=dopri5)
    assert a.extremes.impacts == b.extremes.impacts > 0
    assert math.isclose(a.extremes.max_theta_edge1, b.extremes.max_theta_edge1, rel_tol=1e-6)
    assert math.isclose(a.extremes.max_theta_edge2, b.extremes.max_theta_edge2, rel_tol=1e-6)
