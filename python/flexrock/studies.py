# SPDX-License-Identifier: BSD-3-Clause
"""Studies from Python: overturning spectra, sweeps (incremental dynamic analysis) and lognormal
fragility fits. The engine's thread pool runs them with the GIL released; results and tables are
those of ``flexrock spectrum|sweep|fragility`` (docs/studies.md)."""

from __future__ import annotations

import os
from typing import Iterable, Mapping, Optional, Sequence, Tuple, Union

from . import _flexrock
from ._flexrock import (  # noqa: F401  (re-exported API)
    FragilityData,
    FragilityFit,
    FragilityQuery,
    Intensity,
    Outcome,
    OverturnBoundary,
    PulseType,
    RecordSpectrumSpec,
    RunSummary,
    ScaleKind,
    SpectrumCell,
    SpectrumResult,
    SpectrumSpec,
    SweepBody,
    SweepRecord,
    SweepRow,
    SweepSpec,
    boundary_columns,
    boundary_csv,
    compute_record_spectrum,
    compute_spectrum,
    fit_lognormal,
    fragility_band,
    fragility_probability,
    intensity,
    lognormal_log_likelihood,
    load_spectrum_file,
    load_sweep_manifest,
    pulse_motion,
    run_pulse_cell,
    run_record_cell,
    run_sweep,
    spectrum_columns,
    spectrum_csv,
    summarize,
    sweep_columns,
    sweep_row,
    fragility_columns,
    fragility_row,
)



def _solver(values: dict):
    from . import SimulationOptions, OverturnCriterion, InputError

    # a study's defaults: overturning at pi/2, as SpectrumSpec() and the CLI's study files
    o = SimulationOptions()
    o.overturn = OverturnCriterion.half_pi
    for key, value in values.items():
        if not hasattr(o, key) or key.startswith("_"):
            raise InputError(f"unknown solver option {key!r}")
        setattr(o, key, value)
    return o


def _body(body):
    from . import Body, BodyParameters

    return Body(body) if isinstance(body, BodyParameters) else body


def spectrum(
    body,
    amplitudes: Sequence[float],
    frequencies: Sequence[float],
    pulse: Union[str, PulseType] = "one_sine",
    *,
    normalized: bool = True,
    bisect: bool = True,
    free_periods: float = 4.0,
    bisection_tolerance: float = 1e-3,
    threads: int = 0,
    **solver,
) -> SpectrumResult:
    """The overturning spectrum of ``body`` under a pulse family over amplitudes x frequencies.
    Normalised (default): amplitudes a_p/(g tan alpha), frequencies omega_p/p; otherwise m/s^2
    and rad/s. ``threads=0``: every core. Solver options as keywords (rtol=...)."""
    spec = SpectrumSpec()
    spec.pulse = _flexrock.pulse_type_from_string(pulse) if isinstance(pulse, str) else pulse
    spec.normalized = normalized
    spec.amplitudes = [float(a) for a in amplitudes]
    spec.frequencies = [float(f) for f in frequencies]
    spec.bisect = bisect
    spec.free_periods = free_periods
    spec.bisection_tolerance = bisection_tolerance
    spec.solver = _solver(solver)
    return compute_spectrum(_body(body), spec, threads)


def record_spectrum(
    body,
    motion,
    scales: Sequence[float],
    *,
    bisect: bool = True,
    free_periods: float = 4.0,
    bisection_tolerance: float = 1e-3,
    threads: int = 0,
    **solver,
) -> SpectrumResult:
    """One record (a GroundMotion at scale 1) x scale factors: outcomes and the minimum
    overturning scale."""
    spec = RecordSpectrumSpec()
    spec.motion = motion
    spec.scales = [float(s) for s in scales]
    spec.bisect = bisect
    spec.free_periods = free_periods
    spec.bisection_tolerance = bisection_tolerance
    spec.solver = _solver(solver)
    return compute_record_spectrum(_body(body), spec, threads)


def spectrum_table(result: SpectrumResult, g: float = 9.80665) -> dict:
    """The spectrum CSV's columns (one row per cell) as numpy arrays."""
    from . import _parse_csv

    return _parse_csv(_flexrock.spectrum_csv(result, g))


def write_spectrum(
    result: SpectrumResult,
    path: str,
    *,
    normalized: bool = True,
    g: float = 9.80665,
    boundary_path: Optional[str] = None,
) -> Tuple[str, Optional[str]]:
    """Writes the spectrum CSV (and, with a bisection, the minimum-overturning CSV, by default
    "<stem>.boundary.csv", a ".spectrum" suffix of the stem dropped) as ``flexrock spectrum``
    lays them out; returns the paths."""
    path = os.fspath(path)

    def put(p, text):
        tmp = f"{p}.tmp.{os.getpid()}"
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, p)

    put(path, _flexrock.spectrum_csv(result, g))
    if len(result.boundary) == 0:
        return path, None
    if boundary_path is None:
        stem = path[:-4] if path.endswith(".csv") else path
        stem = stem[: -len(".spectrum")] if stem.endswith(".spectrum") else stem
        boundary_path = stem + ".boundary.csv"
    put(os.fspath(boundary_path), _flexrock.boundary_csv(result, normalized, g))
    return path, os.fspath(boundary_path)


def sweep(
    bodies: Union[Mapping[str, object], Iterable[Tuple[str, object]]],
    records: Union[Mapping[str, object], Iterable[Tuple[str, object]]],
    scales: Sequence[float],
    *,
    target_pga: bool = False,
    free_periods: float = 2.0,
    threads: int = 0,
    **solver,
) -> dict:
    """Bodies (name -> BodyParameters) x records (name -> GroundMotion at scale 1) x scales
    (factors, or target PGAs [m/s^2] with ``target_pga=True``). Returns the sweep CSV's columns
    (one row per run, in run order) as numpy arrays, the table ``flexrock sweep`` writes."""
    from . import _parse_csv

    spec = SweepSpec()
    items = bodies.items() if isinstance(bodies, Mapping) else bodies
    spec.bodies = [SweepBody(name, getattr(b, "params", b)) for name, b in items]
    items = records.items() if isinstance(records, Mapping) else records
    spec.records = [SweepRecord(name, m) for name, m in items]
    spec.scale_kind = ScaleKind.target_pga if target_pga else ScaleKind.factor
    spec.scales = [float(s) for s in scales]
    spec.free_periods = free_periods
    spec.solver = _solver(solver)
    rows = run_sweep(spec, [], threads)
    text = ",".join(sweep_columns()) + "\n" + "".join(_flexrock.sweep_row(spec, r) + "\n" for r in rows)
    return _parse_csv(text)


def fragility(im: Sequence[float], failed: Sequence[int], confidence: float = 0.95) -> FragilityFit:
    """Maximum-likelihood lognormal fragility P(failure | IM = x) = Phi(ln(x/theta)/beta)."""
    return fit_lognormal([float(x) for x in im], [int(f) for f in failed], confidence)


def fragility_from_sweep(
    path: str, im: str = "pga", outcome: str = "overturned", level: float = 0.0, body: str = ""
):
    """Fits a sweep CSV as ``flexrock fragility`` does: a list of (FragilityData, FragilityFit),
    one per body."""
    q = FragilityQuery()
    q.im, q.outcome, q.level, q.body = im, outcome, level, body
    table = _flexrock.read_csv_table(os.fspath(path))
    return [(d, fit_lognormal(d.im, d.failed)) for d in _flexrock.fragility_data(table, q)]


_NOT_API = ("annotations", "os", "Iterable", "Mapping", "Optional", "Sequence", "Tuple", "Union")
__all__ = [n for n in dir() if not n.startswith("_") and n not in _NOT_API]
__all__ += ["FragilityQuery", "FragilityData", "read_csv_table", "fragility_data"]
read_csv_table = _flexrock.read_csv_table
fragility_data = _flexrock.fragility_data
