# SPDX-License-Identifier: BSD-3-Clause
"""The fragility session from Python: typed states, measures and analyses, the fits of every
state and body, and the fit CSV with the bytes of ``flexrock fragility -o``."""

import subprocess

import pytest

import flexrock as fr


@pytest.fixture(scope="module")
def sweep(cli, source_dir, tmp_path_factory):
    out = tmp_path_factory.mktemp("fragility") / "uncertain.csv"
    manifest = source_dir / "examples" / "studies" / "uncertain_sweep.toml"
    subprocess.run([str(cli), "sweep", str(manifest), "-o", str(out), "-q"], check=True,
                   capture_output=True)
    return out


CASES = [
    ([], {}),
    (["--im", "pga_g", "--outcome", "theta", "--level", "0.5"],
     dict(im="pga_g", outcome="theta", level=0.5)),
    (["--state", "theta:0.5", "--state", "overturned"], dict(states=["theta:0.5", "overturned"])),
    (["--analysis", "msa", "--state", "theta:0.5", "--state", "overturned"],
     dict(analysis="msa", states=["theta:0.5", "overturned"])),
    (["--confidence", "0.9", "--outcome", "energy", "--level", "100"],
     dict(confidence=0.9, outcome="energy", level=100.0)),
]


@pytest.mark.parametrize("args,kwargs", CASES)
def test_the_session_writes_the_fit_csv_of_the_command_line(cli, sweep, tmp_path, args, kwargs):
    fit = tmp_path / "fit.csv"
    subprocess.run([str(cli), "fragility", str(sweep), *args, "-o", str(fit), "-q"], check=True,
                   capture_output=True)
    s = fr.fragility_session(sweep, **kwargs)
    assert s.fit_csv() == fit.read_text()


def test_states_measures_and_analyses_are_typed(sweep):
    s = fr.fragility_session(sweep, states=["theta:0.5", "overturned"], analysis="msa")
    assert [st.outcome for st in s.states] == [fr.FragilityOutcome.theta,
                                                fr.FragilityOutcome.overturned]
    assert s.states[0].level == 0.5 and s.states[0].label == "theta:0.5"
    assert s.several and s.bodies == 1
    # a multiple-stripe analysis fits over the requested levels, in the manifest's units
    assert s.measure.kind == fr.FragilityMeasureKind.requested_level
    assert s.unit == "g"
    stripes = s.stripes(1, 0)
    data = s.data(1, 0)
    assert sum(n for _, n, _ in stripes) == len(data.im)
    assert sum(k for _, _, k in stripes) == sum(data.failed) == s.fit(1, 0).failures
    # a more severe state fails no more often than a less severe one, run by run
    assert all(a >= b for a, b in zip(s.data(0, 0).failed, data.failed))
    m = fr.fragility_measure("sa:0.5")
    assert m.kind == fr.FragilityMeasureKind.intensity
    assert (m.column, m.unit) == ("sa_T0.5_z0.05_m_per_s2", "m/s^2")


def test_the_session_refuses_what_the_command_line_refuses(sweep):
    with pytest.raises(ValueError, match="--state 'uplift': given twice"):
        fr.fragility_session(sweep, states=["uplift", "uplift"])
    with pytest.raises(ValueError, match="--level: expected a number > 0 with --outcome theta"):
        fr.fragility_session(sweep, outcome="theta")
    with pytest.raises(ValueError, match="--analysis msa: .* leave --im out"):
        fr.fragility_session(sweep, analysis="msa", im="pga")
    with pytest.raises(ValueError, match=r"--confidence: expected a number in \(0, 1\), got 1.5"):
        fr.fragility_session(sweep, confidence=1.5)
    with pytest.raises(ValueError, match="theta:X"):
        fr.damage_state("theta")


def test_fragility_from_sweep_keeps_its_pairs(sweep):
    ((data, fit),) = fr.fragility_from_sweep(str(sweep), im="pga_g")
    s = fr.fragility_session(sweep, im="pga_g")
    assert (data.im, data.failed) == (s.data(0, 0).im, s.data(0, 0).failed)
    assert fit.theta == s.fit(0, 0).theta
