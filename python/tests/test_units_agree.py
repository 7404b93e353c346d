# SPDX-License-Identifier: BSD-3-Clause
"""One unit rule: a default intensity measure is the same for `flexrock fragility`, its Python
session and the plots (PGA in g), so that a fit drawn without --im is labelled and scaled as it
was fitted; a pulse function takes no bare number whose unit it would have to guess."""

import csv
import math
import subprocess

import pytest

import flexrock as fr
from flexrock import plots


@pytest.fixture(scope="module")
def sweep_csv(cli, source_dir, tmp_path_factory):
    d = tmp_path_factory.mktemp("units")
    out = d / "sweep.csv"
    p = subprocess.run([str(cli), "sweep", str(source_dir / "examples/studies/sweep.toml"), "-o",
                        str(out), "-q"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return out


def test_fragility_without_im_fits_what_plot_draws_without_im(cli, sweep_csv, tmp_path):
    fit = tmp_path / "fit.csv"
    p = subprocess.run([str(cli), "fragility", str(sweep_csv), "--body", "statue", "-o", str(fit)],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert "statue: P(overturning | pga_g)" in p.stdout
    row = next(csv.DictReader(open(fit)))
    assert (row["im_name"], row["im_unit"]) == ("pga_g", "g")
    # Python's default: the same measure and the same median
    (data, f), = fr.fragility_from_sweep(str(sweep_csv), body="statue")
    assert (data.im_name, data.im_unit) == ("pga_g", "g")
    assert f.theta == pytest.approx(float(row["theta"]), rel=1e-12)
    # the plot of the sweep without im: the same measure on its axis, the same median
    ax = plots.fragility_curve(str(sweep_csv), body="statue", band=False)
    assert ax.get_xlabel() == "PGA [g]"
    (x, prob), = [(l.get_xdata(), l.get_ydata()) for l in ax.lines if l.get_gid() == "fit"]
    k = min(range(len(x)), key=lambda i: abs(prob[i] - 0.5))
    assert x[k] == pytest.approx(f.theta, rel=0.05)
    # and the session's own default
    s = fr.fragility_session(str(sweep_csv), body="statue")
    assert s.data(0, 0).im_name == "pga_g"


def test_a_pulse_takes_no_positional_physical_value():
    with pytest.raises(TypeError, match="not positionally"):
        fr.one_sine_pulse(0.3, 2.0, 3.0)
    # the spelled-out forms agree
    a = fr.one_sine_pulse(amplitude_g=0.3, frequency_hz=2.0, duration=3.0)
    b = fr.one_sine_pulse(a_p=0.3 * 9.80665, omega_p=2 * math.pi * 2.0, duration=3.0)
    assert a.at(0.1)[0] == b.at(0.1)[0]
