# SPDX-License-Identifier: BSD-3-Clause
"""Uncertain parameters from Python: the same rows as `flexrock sweep`, the manifest's keys and
errors, quantiles against the standard library's NormalDist (an independent inverse CDF)."""

import math
import statistics
import subprocess

import pytest

import flexrock as fr


def test_manifest_rows_equal_the_cli_file(cli, source_dir, tmp_path):
    manifest = source_dir / "examples" / "studies" / "uncertain_sweep.toml"
    out = tmp_path / "u.csv"
    subprocess.run([str(cli), "sweep", str(manifest), "-o", str(out), "-q"], check=True)
    spec = fr.load_sweep_manifest(str(manifest)).spec
    assert [p.kind for p in spec.uncertainty.parameters] == [
        fr.UncertainKind.friction, fr.UncertainKind.size_scale, fr.UncertainKind.restitution_factor]
    assert spec.uncertainty.sampling.method == fr.SamplingMethod.lhs
    rows = fr.run_sweep(spec, [], 2)
    text = ",".join(fr.sweep_spec_columns(spec)) + "\n" + "".join(
        fr.sweep_row(spec, r) + "\n" for r in rows)
    assert text == out.read_text()
    # the row's values are the design's sample of its (record, level)
    design = fr.SampleDesign(spec.uncertainty, len(spec.records) * len(spec.scales))
    for r in rows:
        assert r.sampled == design.values(r.record * len(spec.scales) + r.scale_index)


def test_sweep_takes_an_uncertainty_and_threads_change_nothing():
    u = fr.Uncertainty(
        [fr.UncertainParameter("friction", "uniform", minimum=0.3, maximum=0.7),
         fr.UncertainParameter("size_scale", "lognormal", median=1.0, beta=0.05)],
        fr.Sampling(seed=11, method=fr.SamplingMethod.random, scope=fr.SamplingScope.record))
    bodies = {"block": fr.rigid_block(0.4, 2.0, 1000.0)}
    records = {"pulse": fr.one_sine_pulse(a_p=1.0, omega_p=5.0, duration=3.0)}
    one = fr.sweep(bodies, records, factors=[1.0, 2.0, 3.0], uncertainty=u, threads=1)
    two = fr.sweep(bodies, records, factors=[1.0, 2.0, 3.0], uncertainty=u, threads=2)
    for k in one:
        assert list(one[k]) == list(two[k]), k
    # one realisation per record: the same friction at every level
    assert len(set(one["friction_coefficient"])) == 1
    assert 0.3 <= one["friction_coefficient"][0] <= 0.7
    assert "max_offset_m" in one  # sampled friction: the sliding columns


def test_quantiles_match_an_independent_inverse_cdf():
    nd = statistics.NormalDist()
    # every parameter is bounded below: a cut ten standard deviations out changes no digit
    normal = fr.UncertainParameter("size_scale", "normal", mean=1.0, standard_deviation=0.1,
                                   lower=1e-9)
    lognormal = fr.UncertainParameter("friction", "lognormal", median=0.6, beta=0.25)
    for u in (1e-6, 0.01, 0.3, 0.5, 0.9, 0.999999):
        z = nd.inv_cdf(u)
        assert fr.uncertain_quantile(normal, u) == pytest.approx(1.0 + 0.1 * z, rel=1e-12)
        assert fr.uncertain_quantile(lognormal, u) == pytest.approx(0.6 * math.exp(0.25 * z), rel=1e-12)
    # truncated to [0.9, 1.3]: u maps into [F(0.9), F(1.3)]
    t = fr.UncertainParameter("size_scale", "normal", mean=1.0, standard_deviation=0.1, lower=0.9,
                              upper=1.3)
    fl, fu = nd.cdf(-1.0), nd.cdf(3.0)
    for u in (0.001, 0.5, 0.999):
        assert fr.uncertain_quantile(t, u) == pytest.approx(1.0 + 0.1 * nd.inv_cdf(fl + u * (fu - fl)),
                                                            rel=1e-12)


def test_bad_parameters_say_what_is_right():
    with pytest.raises(ValueError, match="needs mean and standard_deviation"):
        fr.UncertainParameter("friction", "normal", mean=0.5)
    with pytest.raises(ValueError, match="lower is not a key of a uniform"):
        fr.UncertainParameter("friction", "uniform", minimum=0.3, maximum=0.5, lower=0.4)
    with pytest.raises(ValueError, match="expected one of: friction"):
        fr.UncertainParameter("fricton", "uniform", minimum=0.3, maximum=0.5)
    with pytest.raises(ValueError, match="give a lower bound"):
        fr.UncertainParameter("friction", "normal", mean=0.5, standard_deviation=0.1)
    with pytest.raises(ValueError, match="given twice"):
        p = fr.UncertainParameter("mass_scale", "uniform", minimum=0.9, maximum=1.1)
        fr.Uncertainty([p, p])
    with pytest.raises(IndexError):
        fr.SampleDesign(fr.Uncertainty([p]), 4).values(4)
    # a rigid body has no modes to scale
    u = fr.Uncertainty([fr.UncertainParameter("frequency_scale", "uniform", minimum=0.9, maximum=1.1)])
    with pytest.raises(ValueError, match="rigid"):
        fr.sweep({"b": fr.rigid_block(0.4, 2.0, 1000.0)}, {"p": fr.one_sine_pulse(a_p=1.0, omega_p=5.0, duration=3.0)},
                 factors=[1.0], uncertainty=u)


def test_the_table_lists_every_kind():
    names = [k["name"] for k in fr.uncertain_parameters()]
    assert names == [k.name for k in fr.UncertainKind.__members__.values()]


def test_python_finishes_a_killed_uncertain_sweep_with_the_same_bytes(cli, source_dir, tmp_path):
    import os
    import signal
    import time

    data = source_dir.parent / "shared" / "data" / "elcentro_1940_ns.dat"
    if not data.exists():
        data = source_dir / "tests" / "data" / "elcentro_1940_ns.dat"
    block = source_dir / "examples" / "studies" / "slender_block.toml"
    # 30 slow runs (a small max_step: a friction limit far above any demand keeps the rocking
    # series on sampled steps, which max_step caps), so that the kill lands mid-way
    manifest = tmp_path / "m.toml"
    manifest.write_text(f"""free_periods = 1
[[body]]
file = "{block}"
[[record]]
file = "{data}"
format = "single_column"
dt = 0.02
units = "g"
[scales]
factors = {{ start = 0.5, stop = 3.4, step = 0.1 }}
[solver]
max_step = 0.0005
friction_coefficient = 100.0
[[uncertain]]
parameter = "size_scale"
distribution = "lognormal"
median = 1.0
beta = 0.1
[[uncertain]]
parameter = "restitution_factor"
distribution = "uniform"
minimum = 0.85
maximum = 1.0
[sampling]
seed = 5
method = "lhs"
""")
    ref = tmp_path / "ref.csv"
    subprocess.run([str(cli), "sweep", str(manifest), "-o", str(ref), "-q", "-j", "2"], check=True)
    out = tmp_path / "out.csv"
    journal = tmp_path / "out.csv.partial"
    p = subprocess.Popen([str(cli), "sweep", str(manifest), "-o", str(out), "-q", "-j", "1"])
    for _ in range(600):
        if journal.exists() and len(journal.read_text().splitlines()) > 4 or p.poll() is not None:
            break
        time.sleep(0.05)
    assert p.poll() is None, "the sweep ended before the kill (too fast to test)"
    os.kill(p.pid, signal.SIGKILL)
    p.wait()
    assert not out.exists() and journal.exists()
    arrays = fr.sweep_manifest(str(manifest), str(out), threads=2)
    assert out.read_bytes() == ref.read_bytes()
    # the sampled columns come back as floats, the design's values
    spec = fr.load_sweep_manifest(str(manifest)).spec
    design = fr.SampleDesign(spec.uncertainty, len(spec.scales))
    assert list(arrays["size_scale"]) == [design.values(i)[0] for i in range(len(spec.scales))]
    assert list(fr.read_sweep(str(manifest), str(out))["restitution_factor"]) == [
        design.values(i)[1] for i in range(len(spec.scales))]
