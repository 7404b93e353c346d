# SPDX-License-Identifier: BSD-3-Clause
"""Elastic response spectra (`fr.response_spectrum`, `plots.response_spectrum`): against an
independent integration of the oscillator (scipy's lsim, a first-order hold: exact for a
piecewise-linear record), in either unit, and for a pair, RotD50/RotD100 against the angles."""

import numpy as np
import pytest
from matplotlib.figure import Figure

import flexrock as fr
from flexrock import plots

G = 9.80665


@pytest.fixture(scope="module")
def elcentro():
    from conftest import DATA

    r = fr.read_record(str(DATA / "elcentro_1940_ns.dat"), "single_column", dt=0.02, units="g")
    t, a = np.asarray(r.time), np.asarray(r.to_si())
    # padded with zeros past the longest period: the free vibration after the shaking is then
    # part of the record for both integrations
    n = int(round(10.5 / 0.02))
    return np.concatenate([t, t[-1] + 0.02 * np.arange(1, n + 1)]), np.concatenate([a, np.zeros(n)])


def test_one_component_agrees_with_an_independent_integration(elcentro):
    from scipy import signal

    t, a = elcentro
    periods = [0.05, 0.2, 0.5, 1.0, 2.0, 5.0]
    s = fr.response_spectrum((t, a), periods, zeta=0.05)
    for p, sa in zip(periods, s["sa"]):
        w = 2 * np.pi / p
        osc = signal.lti([-1.0], [1.0, 2 * 0.05 * w, w * w])  # u'' + 2 zeta w u' + w^2 u = -a
        _, u, _ = signal.lsim(osc, a, t)
        assert sa == pytest.approx(w * w * np.max(np.abs(u)), rel=1e-7)
    g = fr.response_spectrum((t, a), periods, zeta=0.05, units="g")
    np.testing.assert_allclose(g["sa"], s["sa"] / G, rtol=1e-15)
    assert g["units"] == "g"
    # the short-period end is the peak ground acceleration
    short = fr.response_spectrum((t, a), [0.001])["sa"][0]
    assert short == pytest.approx(np.max(np.abs(a)), rel=1e-3)


def test_a_pair_gives_each_component_and_rotd(elcentro):
    t, a = elcentro
    rng = np.random.default_rng(3)
    b = np.convolve(rng.standard_normal(a.size), np.ones(8) / 8, mode="same") * np.max(np.abs(a))
    periods = [0.1, 0.5, 2.0]
    s = fr.response_spectrum((t, a), periods, second=(t, b))
    np.testing.assert_array_equal(s["sa_h2"], fr.response_spectrum((t, b), periods)["sa"])
    for k, p in enumerate(periods):
        r = fr.rotd(t.tolist(), a.tolist(), b.tolist(), p, 0.05)
        assert s["rotd50"][k] == r["rotd50"] and s["rotd100"][k] == r["rotd100"]
        # the angles 0 and 90 degrees are the components themselves
        assert s["rotd100"][k] >= max(s["sa"][k], s["sa_h2"][k]) * (1 - 1e-12)
        assert s["rotd50"][k] <= s["rotd100"][k]
    with pytest.raises(ValueError, match="same samples"):
        fr.response_spectrum((t, a), periods, second=(t[:-1], b[:-1]))
    with pytest.raises(ValueError, match="units"):
        fr.response_spectrum((t, a), periods, units="gal")


def test_the_plot_draws_what_the_function_returns(elcentro):
    t, a = elcentro
    s = fr.response_spectrum((t, a), second=(t, 0.5 * a), units="g")
    ax = plots.response_spectrum(s, fig=Figure())
    for key in ("sa", "sa_h2", "rotd50", "rotd100"):
        (line,) = [ln for ln in ax.lines if ln.get_gid() == key]
        np.testing.assert_array_equal(line.get_ydata(), s[key])
        np.testing.assert_array_equal(line.get_xdata(), s["period_s"])
    assert ax.get_ylabel() == "Sa [g]" and ax.get_xscale() == "log"
