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


def _sa_manifest(tmp_path, source_dir, units):
    data = source_dir.parent / "shared" / "data"
    m = tmp_path / f"sa_{units.replace('/', '_')}.toml"
    text = (f'[[body]]\nname = "statue"\nfile = "{source_dir / "examples/cases/museum_statue.toml"}"\n'
            f'[[record]]\nname = "elcentro"\nfile = "{data / "elcentro_1940_ns.dat"}"\n'
            'format = "single_column"\ndt = 0.02\nunits = "g"\n'
            f'[[record]]\nname = "kobe"\nfile = "{data / "kobe_1995_nishi_akashi_090.AT2"}"\n'
            '[scales]\ntarget_pga = { start = 0.1, stop = 0.8, step = 0.1 }\nunits = "g"\n'
            '[intensity]\nsa_periods = [1.0]\n')
    if units:
        text += f'sa_units = "{units}"\n'
    m.write_text(text)
    return m


def test_sa_is_written_and_fitted_in_the_unit_asked_for(cli, source_dir, tmp_path):
    out = {}
    for units in ("", "g"):
        csv_path = tmp_path / f"sweep_{units or 'si'}.csv"
        p = subprocess.run([str(cli), "sweep", str(_sa_manifest(tmp_path, source_dir, units)),
                            "-o", str(csv_path), "-q"], capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        fit = tmp_path / f"fit_{units or 'si'}.csv"
        p = subprocess.run([str(cli), "fragility", str(csv_path), "--im", "sa:1", "-o", str(fit)],
                           capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        out[units] = (list(csv.DictReader(open(csv_path))), next(csv.DictReader(open(fit))), p.stdout)
    rows_si, fit_si, _ = out[""]
    rows_g, fit_g, text_g = out["g"]
    assert "sa_T1_z0.05_m_per_s2" in rows_si[0] and "sa_T1_z0.05_g" in rows_g[0]
    assert "sa_T1_z0.05_m_per_s2" not in rows_g[0]
    for a, b in zip(rows_si, rows_g):
        assert float(b["sa_T1_z0.05_g"]) == pytest.approx(float(a["sa_T1_z0.05_m_per_s2"]) / 9.80665,
                                                          rel=1e-14)
    assert (fit_si["im_unit"], fit_g["im_unit"]) == ("m/s^2", "g")
    assert float(fit_g["theta"]) == pytest.approx(float(fit_si["theta"]) / 9.80665, rel=1e-6)
    assert float(fit_g["beta"]) == pytest.approx(float(fit_si["beta"]), rel=1e-6)
    assert " g  [" in text_g  # the console says the unit with the median


def test_sa_units_in_python_and_refused_where_they_mean_nothing(tmp_path):
    body = fr.rigid_block(width=0.4, height=2.0, mass=100.0)
    rec = {"p": fr.one_sine_pulse(amplitude_g=0.3, frequency_hz=2.0, duration=3.0)}
    si = fr.sweep({"b": body}, rec, factors=[0.5, 1.0], sa_periods=[0.5], progress=False)
    g = fr.sweep({"b": body}, rec, factors=[0.5, 1.0], sa_periods=[0.5], sa_units="g",
                 progress=False)
    assert "sa_T0.5_z0.05_g" in g and "sa_T0.5_z0.05_m_per_s2" not in g
    assert g["sa_T0.5_z0.05_g"] == pytest.approx(si["sa_T0.5_z0.05_m_per_s2"] / 9.80665, rel=1e-14)
    with pytest.raises(fr.InputError, match="sa_units: expected one of"):
        fr.sweep({"b": body}, rec, factors=[1.0], sa_periods=[0.5], sa_units="furlong/s^2")
    m = tmp_path / "m.toml"
    (tmp_path / "rec.dat").write_text("0.0\n0.1\n-0.1\n0.0\n")
    m.write_text('[[body]]\nfile = "b.toml"\n[[record]]\nfile = "rec.dat"\nformat = "single_column"\n'
                 'dt = 0.02\nunits = "g"\n[scales]\nfactors = [1.0]\n'
                 '[intensity]\nmeasures = ["pgd"]\nsa_units = "g"\n')
    (tmp_path / "b.toml").write_text('[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 2.0\n'
                                     'mass = 100.0\n')
    with pytest.raises(fr.InputError, match="sa_units.*expected only with sa_periods"):
        fr.load_sweep_manifest(str(m))
