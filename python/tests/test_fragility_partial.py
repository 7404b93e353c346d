# SPDX-License-Identifier: BSD-3-Clause
"""One bad body or damage state does not abort a fragility study: `flexrock fragility` fits the
others and says which it could not and why (exit 0 unless nothing could be fitted); `flexrock
plot` draws a body or a state (--body, --state); Python fits and draws the same."""

import csv
import os
import subprocess
import warnings

import pytest
from matplotlib.figure import Figure

import flexrock as fr
from flexrock import plots

G = 9.80665


def _sweep(path, bodies):
    # rows (body, pga_g, overturned, max_theta_over_alpha)
    cols = fr.sweep_columns()
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        i = 0
        for body, runs in bodies.items():
            for k, (pga, over, tilt) in enumerate(runs):
                r = dict.fromkeys(cols, "0")
                r.update(index=i, body=body, record=f"r{k % 2}", requested_level=pga, requested_units="g",
                         pga_g=repr(pga), pga_m_per_s2=repr(pga * G), overturned=over,
                         max_theta_over_alpha=repr(tilt),
                         outcome="overturned_after_impacts" if over else "rocking" if tilt > 0 else "no_uplift",
                         status="overturned" if over else "completed", message="")
                w.writerow([r[c] for c in cols])
                i += 1


# "block" rocks from 0.1 g and overturns from about 0.3 g, not monotonically; "anchored" rocks (tilts
# beyond alpha/2 at 0.2 and 0.4 g) but never overturns
BLOCK = [(0.1, 0, 0.0), (0.15, 0, 0.6), (0.2, 0, 0.3), (0.25, 1, 1e9), (0.3, 0, 0.8), (0.35, 0, 0.9),
         (0.4, 1, 1e9), (0.45, 1, 1e9)]
ANCHORED = [(0.1, 0, 0.2), (0.2, 0, 0.7), (0.3, 0, 0.4), (0.4, 0, 0.9)]


@pytest.fixture()
def sweep(tmp_path):
    p = tmp_path / "sweep.csv"
    _sweep(p, {"block": BLOCK, "anchored": ANCHORED})
    return p


def _run(cli, *args):
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)


def test_a_never_failing_body_leaves_the_other_fitted(cli, sweep, tmp_path):
    fit, curve = tmp_path / "fit.csv", tmp_path / "curve.csv"
    p = _run(cli, "fragility", sweep, "--im", "pga_g", "-o", fit, "--curve", curve, "--curve-points", "5")
    assert p.returncode == 0, p.stderr
    assert "block: P(overturning | pga_g) = Phi" in p.stdout
    assert "anchored: P(overturning | pga_g): not fitted" in p.stdout
    assert "flexrock: warning: " in p.stderr and "body 'anchored'" in p.stderr and "is 0" in p.stderr
    assert "fitted 1 of 2 bodies" in p.stderr
    rows = list(csv.DictReader(open(fit)))
    assert [r["body"] for r in rows] == ["block"]
    # the same fit as the body alone
    alone = tmp_path / "alone.csv"
    assert _run(cli, "fragility", sweep, "--im", "pga_g", "--body", "block", "-o", alone).returncode == 0
    assert fit.read_text() == alone.read_text()
    assert {r["body"] for r in csv.DictReader(open(curve))} == {"block"}
    # nothing fitted: exit 2, the reason given
    p = _run(cli, "fragility", sweep, "--body", "anchored")
    assert p.returncode == 2 and "body 'anchored'" in p.stderr and "is 0" in p.stderr


def test_an_unfittable_state_leaves_the_others_fitted_and_plot_picks_body_and_state(cli, sweep, tmp_path):
    # theta:0.05: every run of block exceeds it but the first, which lies below them all (perfect
    # separation), as for anchored every run; anchored never overturns: three of the six fits remain
    fit, curve = tmp_path / "fam.csv", tmp_path / "famcurve.csv"
    p = _run(cli, "fragility", sweep, "--state", "theta:0.05", "--state", "theta:0.5", "--state", "overturned",
             "-o", fit, "--curve", curve)
    assert p.returncode == 0, p.stderr
    assert "body 'block', state 'theta:0.05'" in p.stderr and "perfectly separated" in p.stderr
    assert "body 'anchored', state 'overturned'" in p.stderr
    assert "fitted 3 of 6 bodies and damage states" in p.stderr
    rows = [(r["body"], r["state"]) for r in csv.DictReader(open(fit))]
    assert rows == [("block", "theta:0.5"), ("block", "overturned"), ("anchored", "theta:0.5")]
    env = dict(os.environ, MPLCONFIGDIR=str(tmp_path))
    (tmp_path / "matplotlibrc").write_text("svg.fonttype: none\n")
    for src in (fit, curve):
        out = tmp_path / "one.svg"
        p = _run(cli, "plot", src, "--body", "block", "--state", "overturned", "-o", out)
        assert p.returncode == 0, p.stderr
        ax = plots.fragility_curve(str(src), body="block", state="overturned", fig=Figure())
        labels = [ln.get_label() for ln in ax.lines if ln.get_gid() == "fit"]
        assert len(labels) == 1
        p = _run(cli, "plot", src, "--body", "block", "--state", "theta:0.05", "-o", out)
        assert p.returncode == 2 and "no fragility of body 'block' and state 'theta:0.05'" in p.stderr


def test_plot_of_a_sweep_draws_the_fitted_body_and_warns_of_the_other(cli, sweep, tmp_path):
    out = tmp_path / "s.png"
    p = _run(cli, "plot", sweep, "-o", out)
    assert p.returncode == 0, p.stderr
    assert "flexrock: warning: " in p.stderr and "body 'anchored'" in p.stderr
    p = _run(cli, "plot", sweep, "--body", "anchored", "-o", out)
    assert p.returncode == 2 and "body 'anchored'" in p.stderr
    # a sweep drawn for one damage state
    p = _run(cli, "plot", sweep, "--state", "theta:0.5", "-o", out)
    assert p.returncode == 0, p.stderr
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        pairs = fr.fragility_from_sweep(str(sweep), im="pga_g")
    assert [d.body for d, _ in pairs] == ["block"]
    assert any(issubclass(w.category, fr.studies.FragilityWarning) and "anchored" in str(w.message)
               for w in caught)
    s = fr.fragility_session(sweep, im="pga_g")
    assert s.fitted(0, 0) and not s.fitted(0, 1)
    ((state, body, reason),) = s.not_fitted()
    assert (state, body) == (0, 1) and "body 'anchored'" in reason
    with pytest.raises(fr.InputError, match="body 'anchored'"):
        s.fit(0, 1)
