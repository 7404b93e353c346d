# SPDX-License-Identifier: BSD-3-Clause
"""Studies from Python: overturning spectra, sweeps (incremental dynamic analysis) and lognormal
fragility fits. The engine's thread pool runs them with the GIL released; results and tables are
those of ``flexrock spectrum|sweep|fragility`` (docs/studies.md)."""

from __future__ import annotations

import os
import warnings
from typing import Iterable, Mapping, Optional, Sequence, Tuple, Union

from . import _flexrock
from ._flexrock import (  # noqa: F401  (re-exported API)
    FragilityData,
    FragilityFit,
    FragilityQuery,
    GridUnits,
    Intensity,
    Outcome,
    OverturnBoundary,
    RecordSpectrumSpec,
    Regime,
    RunSummary,
    ScaleKind,
    SpectrumCell,
    SpectrumResult,
    SpectrumSession,
    SpectrumSpec,
    SweepBody,
    SweepRecord,
    SweepRow,
    SweepSession,
    SweepSpec,
    boundary_columns,
    boundary_csv,
    compute_record_spectrum,
    compute_spectrum,
    capacity_intervals,
    crossing_intensity,
    fit_capacity_intervals,
    fit_lognormal,
    fit_stripes,
    fragility_band,
    fragility_probability,
    MeasureRequest,
    intensity,
    intensity_measure,
    intensity_measures,
    measure_request,
    require_spectral_period,
    lognormal_log_likelihood,
    load_spectrum_file,
    load_sweep_manifest,
    pulse_motion,
    spectrum_pulse_names,
    run_pulse_cell,
    run_record_cell,
    run_sweep,
    spectrum_columns,
    spectrum_csv,
    summarize,
    sweep_columns,
    sweep_has_friction,
    read_sweep_csv,
    spectrum_arrays,
    sweep_arrays,
    sweep_column_info,
    sweep_row,
    sweep_spec_columns,
    fragility_columns,
    fragility_row,
    Distribution,
    SampleDesign,
    Sampling,
    SamplingMethod,
    SamplingScope,
    UncertainKind,
    UncertainParameter,
    Uncertainty,
    uncertain_parameters,
    uncertain_quantile,
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


_ACCEL_UNITS = {"g": None, "m/s^2": 1.0, "cm/s^2": 0.01}  # g: the body's gravity
_FREQ_UNITS = {"rad/s": 1.0, "Hz": 2.0 * 3.141592653589793}


def unit_suffix(unit: str) -> str:
    """The column-name suffix of a unit.

    Parameters
    ----------
    unit : str
        "g", "m/s^2", "cm/s^2", "rad/s" or "Hz".

    Returns
    -------
    str
        "g", "m_per_s2", "cm_per_s2", "rad_per_s" or "hz".
    """
    return {"m/s^2": "m_per_s2", "cm/s^2": "cm_per_s2", "rad/s": "rad_per_s", "Hz": "hz"}.get(unit, unit)


def _choice(key: str, value: str, allowed) -> str:
    from . import InputError

    if value not in allowed:
        raise InputError(f"{key}: expected one of {', '.join(repr(a) for a in allowed)}, got {value!r}")
    return value


def spectrum(
    body,
    amplitudes: Sequence[float],
    frequencies: Sequence[float],
    pulse: str = "one_sine",
    *,
    axes: Optional[str] = None,
    amplitude_units: Optional[str] = None,
    frequency_units: Optional[str] = None,
    normalized: Optional[bool] = None,
    bisect: bool = True,
    free_periods: float = 4.0,
    bisection_tolerance: float = 1e-3,
    threads: int = 0,
    progress: bool = True,
    callback=None,
    **solver,
) -> SpectrumResult:
    """The overturning spectrum of a body under a pulse family: amplitudes x frequencies.

    The keywords are those of a spectrum file's ``[spectrum]`` table (docs/studies.md).

    Parameters
    ----------
    body : Body or BodyParameters
    amplitudes : array_like
        Strictly increasing pulse amplitudes: a_p/(g tan alpha) [-] with
        ``axes="normalized"`` (default), otherwise in ``amplitude_units``.
    frequencies : array_like
        Pulse frequencies: omega_p/p [-] normalised, otherwise in ``frequency_units``.
    pulse : str
        A pulse type of spectra: ``flexrock.spectrum_pulse_names()`` ("one_sine", "half_sine",
        ...; docs/case-file.md lists them).
    axes : {"normalized", "physical"}, optional
        Default "normalized"; giving a unit implies "physical".
    amplitude_units : {"g", "m/s^2", "cm/s^2"}, optional
        Physical axes only; default "m/s^2".
    frequency_units : {"Hz", "rad/s"}, optional
        Physical axes only; default "rad/s".
    normalized : bool, optional
        The older spelling of ``axes`` (True: "normalized", False: "physical" in m/s^2, rad/s).
    bisect : bool
        Bisect each column for its minimum overturning amplitude.
    free_periods : float
        [-] free motion after the pulse, in rocking periods 2 pi/p.
    bisection_tolerance : float
        [-] relative.
    threads : int
        0: every core. The GIL is released while it runs.
    progress : bool
        A progress bar on stderr once it runs longer than a second (tqdm where installed, a plain
        line otherwise); False: none.
    callback : callable, optional
        ``callback(done, total)``, runs done of the runs to do, called on this thread while it
        runs (every 20 ms at most, when the count moved) and once at the end: for a notebook's
        own display. An exception it raises stops the runs, as Ctrl-C does, and is raised here.
    target_im : str, optional
        Stripes: each record scaled so that this measure ("sa:1", "sa:1:0.02", "pgv", "arias",
        ...) equals each of ``targets`` (in ``units`` for Sa, else the measure's SI unit), as a
        manifest's ``[scales] target_im``.
    targets : array_like, optional
        The levels of ``target_im``.
    measures : sequence of str
        Intensity measures every row gets besides PGA and PGV, as a manifest's ``[intensity]
        measures`` (names of ``intensity_measures()``: "pgd", "arias", ...).
    sa_periods : sequence of float
        [s] a pseudo-spectral acceleration column for each period.
    sa_damping : float
        [-] damping ratio of the ``sa_periods`` columns.
    sa_units : {"m/s^2", "g", "cm/s^2"}
        The unit of the ``sa_periods`` columns, which end with it (``sa_T1_z0.05_g``).
    **solver
        Solver options (``rtol=...``, see :class:`SimulationOptions`).

    Returns
    -------
    SpectrumResult
        Cells and boundary in the units asked for (``result.units``; the cells' ``amplitude_si``
        and ``omega_si`` in SI) or normalised: :func:`spectrum_table`, :func:`boundary_table`,
        :func:`write_spectrum` and :func:`flexrock.plots.spectrum_map` give and draw them in
        those units (e.g. columns ``a_p_g`` and ``f_p_hz`` beside the SI ones).
    """
    from . import InputError

    if axes is None:
        physical = amplitude_units is not None or frequency_units is not None
        axes = "physical" if (physical or normalized is False) else "normalized"
    _choice("axes", axes, ("normalized", "physical"))
    if normalized is not None and normalized != (axes == "normalized"):
        raise InputError(f"normalized={normalized} contradicts axes={axes!r}: give axes only")
    a_unit = w_unit = None
    b = _body(body)
    spec = SpectrumSpec()
    if axes == "physical":
        a_unit = _choice("amplitude_units", amplitude_units or "m/s^2", tuple(_ACCEL_UNITS))
        w_unit = _choice("frequency_units", frequency_units or "rad/s", tuple(_FREQ_UNITS))
        # the grid stays in these units: its cells, bisection and columns keep them
        spec.units = GridUnits(a_unit, _ACCEL_UNITS[a_unit] or b.g, w_unit, _FREQ_UNITS[w_unit])
    elif amplitude_units is not None or frequency_units is not None:
        raise InputError("amplitude_units, frequency_units: only with axes=\"physical\"")
    spec.pulse = _choice("pulse", pulse, tuple(spectrum_pulse_names()))
    spec.normalized = axes == "normalized"
    spec.amplitudes = [float(a) for a in amplitudes]
    spec.frequencies = [float(f) for f in frequencies]
    spec.bisect = bisect
    spec.free_periods = free_periods
    spec.bisection_tolerance = bisection_tolerance
    spec.solver = _solver(solver)
    result = compute_spectrum(b, spec, threads, progress=progress, callback=callback)
    if a_unit is not None:
        result._flexrock_units = (a_unit, w_unit)  # physical axes, for the plot
    return result


def record_spectrum(
    body,
    motion,
    scales: Sequence[float],
    *,
    bisect: bool = True,
    free_periods: float = 4.0,
    bisection_tolerance: float = 1e-3,
    threads: int = 0,
    progress: bool = True,
    callback=None,
    **solver,
) -> SpectrumResult:
    """One record times scale factors: the outcome at each and the minimum overturning scale.

    Parameters
    ----------
    body : Body or BodyParameters
    motion : GroundMotion
        The record at scale 1 (accelerations [m/s^2]).
    scales : array_like
        [-] strictly increasing factors on the record.
    bisect : bool
        Bisect for the minimum overturning scale.
    free_periods : float
        [-] free motion after the record, in rocking periods 2 pi/p.
    bisection_tolerance : float
        [-] relative.
    threads : int
        0: every core.
    progress : bool
        A progress bar on stderr once it runs longer than a second (tqdm where installed, a plain
        line otherwise); False: none.
    callback : callable, optional
        ``callback(done, total)``, runs done of the runs to do, called on this thread while it
        runs (every 20 ms at most, when the count moved) and once at the end: for a notebook's
        own display. An exception it raises stops the runs, as Ctrl-C does, and is raised here.
    **solver
        Solver options.

    Returns
    -------
    SpectrumResult
        One column; ``boundary[0].overturning`` is the bisected minimum overturning scale.
    """
    spec = RecordSpectrumSpec()
    spec.motion = motion
    spec.scales = [float(s) for s in scales]
    spec.bisect = bisect
    spec.free_periods = free_periods
    spec.bisection_tolerance = bisection_tolerance
    spec.solver = _solver(solver)
    return compute_record_spectrum(_body(body), spec, threads, progress=progress,
                                   callback=callback)


def spectrum_table(result: SpectrumResult, g: float = 9.80665) -> dict:
    """The spectrum CSV's columns, one row per cell, as numpy arrays.

    Parameters
    ----------
    result : SpectrumResult
    g : float
        [m/s^2] gravity for the normalised columns.

    Returns
    -------
    dict of str to numpy.ndarray
        The columns of ``flexrock spectrum`` (``a_p_m_per_s2``, ``omega_p_rad_per_s``, ...),
        typed by the column table: int64 indices and counts, float64 reals (nan where the CSV
        is empty), str objects;
        for a spectrum asked for in other units, also those: ``a_p_g`` [g] or
        ``a_p_cm_per_s2``, and ``f_p_hz`` [Hz].
    """
    return _flexrock.spectrum_arrays(result, g)  # typed by the column table, no CSV text


def boundary_table(result: SpectrumResult, g: float = 9.80665) -> dict:
    """The minimum-overturning CSV's columns, one row per frequency column.

    Parameters
    ----------
    result : SpectrumResult
    g : float
        [m/s^2] gravity for the normalised columns.

    Returns
    -------
    dict of str to numpy.ndarray
        The columns of the boundary CSV (``min_overturning_m_per_s2``, ``omega_p_rad_per_s``,
        ...), typed as in spectrum_table; for a spectrum asked for in other units, also
        ``min_overturning_g`` [g] and ``f_p_hz`` [Hz].
    """
    normalized = getattr(result, "_flexrock_units", None) is None
    return _flexrock.boundary_arrays(result, normalized, g)  # typed, no CSV text


def write_spectrum(
    result: SpectrumResult,
    path: str,
    *,
    normalized: Optional[bool] = None,
    g: float = 9.80665,
    boundary_path: Optional[str] = None,
) -> Tuple[str, Optional[str]]:
    """Writes the spectrum CSVs as ``flexrock spectrum`` lays them out.

    Parameters
    ----------
    result : SpectrumResult
    path : str
        The cells CSV.
    normalized : bool, optional
        Whether the grid was normalised (the units of the boundary's ``frequency`` and
        ``min_overturning``); default: as :func:`spectrum` made it (physical axes when units
        were asked for).
    g : float
        [m/s^2] gravity for the normalised columns.
    boundary_path : str, optional
        The minimum-overturning CSV (with a bisection); default "<stem>.boundary.csv", a
        ".spectrum" suffix of the stem dropped.

    Returns
    -------
    (str, str or None)
        The paths written.
    """
    path = os.fspath(path)
    if normalized is None:
        normalized = getattr(result, "_flexrock_units", None) is None

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
    scales: Optional[Sequence[float]] = None,
    *,
    factors: Optional[Sequence[float]] = None,
    target_pga=None,
    units: Optional[str] = None,
    free_periods: float = 2.0,
    threads: int = 0,
    progress: bool = True,
    callback=None,
    target_im: Optional[str] = None,
    targets: Optional[Sequence[float]] = None,
    measures: Sequence[str] = (),
    sa_periods: Sequence[float] = (),
    sa_damping: float = 0.05,
    sa_units: str = "m/s^2",
    uncertainty: Optional[Uncertainty] = None,
    **solver,
) -> dict:
    """Bodies x records x levels: an incremental dynamic analysis, as ``flexrock sweep`` runs it.

    The levels are given as in a sweep manifest's ``[scales]`` table: ``factors=[...]`` on the
    records, or ``target_pga=[...]`` in ``units`` (default "g", as the manifest's).

    Parameters
    ----------
    bodies : mapping or iterable of (str, BodyParameters)
        Name -> body.
    records : mapping or iterable of (str, GroundMotion)
        Name -> record at scale 1 (accelerations [m/s^2]).
    scales : array_like, optional
        The older spelling of ``factors`` (with ``target_pga=True``: target PGAs in m/s^2).
    factors : array_like, optional
        [-] factors on each record.
    target_pga : array_like, optional
        Target PGAs in ``units``: each record is scaled to each.
    units : {"g", "m/s^2", "cm/s^2"}, optional
        Units of ``target_pga``; default "g".
    free_periods : float
        [-] free motion after each record, in rocking periods 2 pi/p.
    threads : int
        0: every core. The GIL is released while it runs.
    progress : bool
        A progress bar on stderr once it runs longer than a second (tqdm where installed, a plain
        line otherwise); False: none.
    callback : callable, optional
        ``callback(done, total)``, runs done of the runs to do, called on this thread while it
        runs (every 20 ms at most, when the count moved) and once at the end: for a notebook's
        own display. An exception it raises stops the runs, as Ctrl-C does, and is raised here.
    uncertainty : Uncertainty, optional
        Parameters each run samples (a manifest's ``[[uncertain]]`` and ``[sampling]``); their
        values are columns after the intensity measures.
    **solver
        Solver options.

    Returns
    -------
    dict of str to numpy.ndarray
        The sweep CSV's columns, one row per run in run order: ``requested_level`` (the level
        as given, equal for every record at that level), ``requested_units``, ``scale``,
        ``pga_m_per_s2``, ``pga_g``, ``outcome``, ``overturned``, ...
    """
    from . import InputError

    spec = SweepSpec()
    if uncertainty is not None:
        spec.uncertainty = uncertainty
    items = bodies.items() if isinstance(bodies, Mapping) else bodies
    spec.bodies = [SweepBody(name, getattr(b, "params", b)) for name, b in items]
    items = records.items() if isinstance(records, Mapping) else records
    spec.records = [SweepRecord(name, m) for name, m in items]
    if isinstance(target_pga, bool):  # the older spelling: scales in m/s^2
        if scales is None or factors is not None:
            raise InputError("sweep: target_pga=True needs scales=[...] in m/s^2; "
                             "better: target_pga=[...], units=\"m/s^2\"")
        if units is not None:
            raise InputError("sweep: units: only with target_pga=[...]")
        if target_pga:
            target_pga, units = scales, "m/s^2"
        else:
            target_pga, factors = None, scales
    elif scales is not None:
        if factors is not None or target_pga is not None:
            raise InputError("sweep: give one of factors=[...] or target_pga=[...], not scales as well")
        factors = scales
    if (target_im is None) != (targets is None):
        raise InputError("sweep: target_im and targets=[...] go together")
    if (factors is not None) + (target_pga is not None) + (target_im is not None) != 1:
        raise InputError("sweep: expected exactly one of factors=[...] [-], target_pga=[...] "
                         "(in units, default \"g\") or target_im with targets=[...]")
    if target_im is not None:
        # stripes at levels of a measure: as a manifest's [scales] target_im
        spec.target = _flexrock.measure_request(str(target_im))
        spec.scale_kind = ScaleKind.target_measure
        spec.levels = [float(s) for s in targets]
        if spec.target.name == "sa":
            unit = _choice("units", units or "g", tuple(_ACCEL_UNITS))
            factor = _ACCEL_UNITS[unit] or 9.80665
        else:
            if units is not None:
                raise InputError(f"sweep: units: only for an acceleration target, not {target_im}")
            unit = next(m["unit"] for m in intensity_measures() if m["name"] == spec.target.name)
            factor = 1.0
        spec.level_units = unit
        spec.scales = [v * factor for v in spec.levels]
    elif factors is not None:
        if units is not None:
            raise InputError("sweep: units: only with target_pga=[...] (factors have no unit)")
        spec.scale_kind = ScaleKind.factor
        spec.scales = [float(s) for s in factors]
    else:
        unit = _choice("units", units or "g", tuple(_ACCEL_UNITS))
        factor = _ACCEL_UNITS[unit] or 9.80665  # the manifest's g: standard gravity
        spec.scale_kind = ScaleKind.target_pga
        spec.levels = [float(s) for s in target_pga]
        spec.level_units = unit
        spec.scales = [v * factor for v in spec.levels]
    spec.free_periods = free_periods
    spec.solver = _solver(solver)
    for t in sa_periods:
        _flexrock.require_spectral_period(float(t), "sweep: sa_periods")
    spec.measures = [MeasureRequest(str(m)) for m in measures] + [
        MeasureRequest("sa", float(t), float(sa_damping),
                       unit=_choice("sa_units", sa_units, _ACCEL_UNITS) if sa_units != "m/s^2" else "")
        for t in sa_periods
    ]
    return sweep_arrays(spec, run_sweep(spec, [], threads, progress=progress, callback=callback))


def sweep_manifest(manifest, output=None, *, threads: int = 0, progress: bool = True,
                   callback=None) -> dict:
    """Runs a sweep manifest to its CSV, as ``flexrock sweep MANIFEST -o OUTPUT`` does, through the
    same session: the runs finished so far are kept in the journal ``OUTPUT.partial``, and an
    interrupted sweep, whether the command line or Python started it, goes on from there. The
    CSV has the same bytes as an uninterrupted ``flexrock sweep``.

    Parameters
    ----------
    manifest : str or os.PathLike
        Sweep manifest (TOML, docs/studies.md).
    output : str or os.PathLike, optional
        The CSV; default ``<manifest stem>.sweep.csv`` in the working directory, as the command
        line's.
    threads : int
        0: every core. The GIL is released while the runs go.
    progress : bool
        A progress bar on stderr once it runs longer than a second (tqdm where installed, a plain
        line otherwise); False: none.
    callback : callable, optional
        ``callback(done, total)``, runs done of the runs to do (those left at the start; a
        resumed study counts only those), called on this thread while it
        runs (every 20 ms at most, when the count moved) and once at the end: for a notebook's
        own display. An exception it raises stops the runs, as Ctrl-C does, and is raised here.

    Returns
    -------
    dict of str to numpy.ndarray
        Every run's row by column, typed by the sweep's column table (:func:`sweep_column_info`):
        int64, float64 (nan where the CSV leaves a field empty) or str objects.
    """
    manifest = os.fspath(manifest)
    if output is None:
        output = os.path.splitext(os.path.basename(manifest))[0] + ".sweep.csv"
    session = SweepSession(load_sweep_manifest(manifest), os.fspath(output))
    session.run(threads, progress=progress, callback=callback)
    return sweep_arrays(session.manifest.spec, session.finish())


def spectrum_file(spec, output=None, boundary=None, *, threads: int = 0,
                  bisect: bool = True, progress: bool = True, callback=None) -> SpectrumResult:
    """Runs a spectrum file to its CSVs, as ``flexrock spectrum SPEC -o OUTPUT --boundary
    BOUNDARY`` does, through the same session: the cells and boundaries finished so far are kept
    in the journal ``OUTPUT.partial``, and an interrupted spectrum, whether the command line or
    Python started it, goes on from there with the same bytes.

    Parameters
    ----------
    spec : str or os.PathLike
        Spectrum file (TOML, docs/studies.md).
    output : str or os.PathLike, optional
        The cells CSV; default ``<spec stem>.spectrum.csv`` in the working directory.
    boundary : str or os.PathLike, optional
        The boundary CSV (with the bisection); default next to ``output``:
        ``x.spectrum.csv`` -> ``x.boundary.csv``.
    threads : int
        0: every core. The GIL is released while the runs go.
    progress : bool
        A progress bar on stderr once it runs longer than a second (tqdm where installed, a plain
        line otherwise); False: none.
    callback : callable, optional
        ``callback(done, total)``, runs done of the runs to do (those left at the start; a
        resumed study counts only those), called on this thread while it
        runs (every 20 ms at most, when the count moved) and once at the end: for a notebook's
        own display. An exception it raises stops the runs, as Ctrl-C does, and is raised here.
    bisect : bool
        False: the grid only, as ``--no-bisect``.

    Returns
    -------
    SpectrumResult
        Every cell and boundary, read back from the journal as data.
    """
    spec = os.fspath(spec)
    if output is None:
        output = os.path.splitext(os.path.basename(spec))[0] + ".spectrum.csv"
    output = os.fspath(output)
    if boundary is None:
        head, name = os.path.split(output)
        stem = os.path.splitext(name)[0]
        if stem.endswith(".spectrum"):
            stem = stem[: -len(".spectrum")]
        boundary = os.path.join(head, stem + ".boundary.csv")
    session = SpectrumSession(load_spectrum_file(spec), output, os.fspath(boundary), bisect)
    session.run(threads, progress=progress, callback=callback)
    return session.finish()


def read_sweep(manifest, path) -> dict:
    """A sweep CSV read back through the manifest's column table: the arrays
    :func:`sweep_manifest` returns. Every line must be the one its run writes (index, body,
    record, level, a known outcome with its flag, numbers where numbers belong); otherwise an
    InputError names the file, line and field.

    Parameters
    ----------
    manifest : str or os.PathLike
        The sweep manifest that wrote it.
    path : str or os.PathLike
        The sweep CSV.

    Returns
    -------
    dict of str to numpy.ndarray
    """
    spec = load_sweep_manifest(os.fspath(manifest)).spec
    return sweep_arrays(spec, read_sweep_csv(spec, os.fspath(path)))


def fragility(im: Sequence[float], failed: Sequence[int], confidence: float = 0.95) -> FragilityFit:
    """Maximum-likelihood lognormal fragility P(failure | IM = x) = Phi(ln(x/theta)/beta).

    Parameters
    ----------
    im : array_like
        Intensity measure of each run (> 0, any unit: theta comes out in it).
    failed : array_like of int
        1 where the run failed, else 0.
    confidence : float
        Level of the bounds, in (0, 1).

    Returns
    -------
    FragilityFit
        theta (the median, in the IM's unit), beta [-], their bounds and covariance.
    """
    return fit_lognormal([float(x) for x in im], [int(f) for f in failed], confidence)


def azimuth_outcomes(cases, scales: Sequence[float], *, step_deg: Optional[float] = None,
                     im_period: Optional[float] = None, zeta: float = 0.05,
                     threads: int = 0) -> Tuple[dict, dict]:
    """Worst-azimuth and random-azimuth outcomes of record pairs at several scales: the data of
    a fragility over azimuths (docs/studies.md, "Two horizontal components").

    Each case (a ``Case`` with a record pair, or its path) is run at every azimuth of its grid
    (``run_azimuths``) with its ``excitation.scale`` times each of ``scales``. The intensity
    measure is RotD50 of the scaled pair (``rotd``): of Sa at ``im_period`` [s] and ``zeta``, or,
    without a period, of the peak acceleration (Sa at 1e-6 s, where the oscillator follows the
    ground). RotD50 of s a is s RotD50(a): it is computed once per pair.

    Returns
    -------
    (dict, dict)
        Per (pair, scale), numpy arrays: ``record`` (the case's name), ``scale``,
        ``rotd50_m_per_s2``, ``rotd100_m_per_s2``, ``worst_overturned`` (int64: 1 if the body
        overturns at any azimuth: the worst-azimuth outcome), ``overturned_fraction`` (the
        share of azimuths that overturn: the probability for an azimuth drawn uniformly) and
        ``worst_max_theta_over_alpha``. And per azimuth run, ``im`` and ``overturned`` (int64):
        the random-azimuth outcomes, every azimuth one equally likely observation.
        ``fragility(rows["rotd50_m_per_s2"], rows["worst_overturned"])`` fits the worst-azimuth
        fragility, ``fragility(runs["im"], runs["overturned"])`` the random-azimuth one.
    """
    import numpy as np

    from ._flexrock import InputError, azimuth_motion, load_case, rotd, run_azimuths

    rows = {k: [] for k in ("record", "scale", "rotd50_m_per_s2", "rotd100_m_per_s2",
                            "worst_overturned", "overturned_fraction",
                            "worst_max_theta_over_alpha")}
    runs = {"im": [], "overturned": []}
    period = 1e-6 if im_period is None else float(im_period)
    for case in cases:
        c = load_case(os.fspath(case)) if not hasattr(case, "has_pair") else case
        if not c.has_pair:
            raise InputError(f"{c.source}: expected a record pair ([excitation.horizontal2])")
        base = c.excitation_scale
        # the IM of the pair as the case scales it, then linear in the scale
        c.excitation_scale = 1.0
        m = azimuth_motion(c, 0.0)
        m90 = azimuth_motion(c, 90.0)
        t = np.asarray(m.times)
        im = rotd(t, np.asarray(m.horizontal) * base, np.asarray(m90.horizontal) * base, period,
                  zeta)
        try:
            for s in scales:
                c.excitation_scale = base * float(s)
                table, _ = run_azimuths(c, step_deg, threads)
                over = np.array([o.startswith("overturned") for o in table["outcome"]])
                rows["record"].append(c.name)
                rows["scale"].append(float(s))
                rows["rotd50_m_per_s2"].append(float(s) * im["rotd50"])
                rows["rotd100_m_per_s2"].append(float(s) * im["rotd100"])
                rows["worst_overturned"].append(int(over.any()))
                rows["overturned_fraction"].append(float(over.mean()))
                rows["worst_max_theta_over_alpha"].append(float(table["max_theta_over_alpha"].max()))
                runs["im"].extend([float(s) * im["rotd50"]] * len(over))
                runs["overturned"].extend(int(v) for v in over)
        finally:
            c.excitation_scale = base
    out = {k: np.array(v, dtype=object if k == "record" else None) for k, v in rows.items()}
    out["worst_overturned"] = out["worst_overturned"].astype(np.int64)
    return out, {"im": np.array(runs["im"]), "overturned": np.array(runs["overturned"],
                                                                     dtype=np.int64)}


def fragility_session(
    path: str,
    im: Optional[str] = None,
    outcome: str = "overturned",
    level: float = 0.0,
    body: str = "",
    *,
    states: Sequence[str] = (),
    analysis: str = "runs",
    confidence: float = 0.95,
):
    """Fits a sweep CSV as ``flexrock fragility`` does: the same checks, observations, fits and
    fit CSV, every damage state and body at once.

    Parameters
    ----------
    path : str or os.PathLike
        A sweep CSV.
    im : str, optional
        Intensity measure (``--im``): pga_g [g] (the default, as the plots'), pga [m/s^2],
        pgv [m/s], scale
        [-], requested_level, or one of the sweep's [intensity] table (pgd, arias, cav, d5_95,
        pgv_over_pga, sa:T[:zeta]). ``analysis="msa"`` takes the requested levels.
    outcome : {"overturned", "uplift", "theta", "energy", "offset", "residual_offset"}
        Failure (``--outcome``), with ``level`` for the last four.
    level : float
        Threshold of theta [-], energy [J], offset or residual_offset [m].
    body : str
        Only this body (default: each).
    states : sequence of str
        A family of damage states fitted at once (``--state``, least severe first:
        "uplift", "theta:0.5", ...); not with ``outcome`` or ``level``.
    analysis : {"runs", "msa", "ida"}
        Every run an observation, a multiple-stripe analysis, or each record's capacity.
    confidence : float
        Level of the bounds, in (0, 1).

    Returns
    -------
    FragilitySession
        ``states``, ``bodies``, ``data(state, body)`` (a FragilityData), ``fit(state, body)``
        (a FragilityFit), ``fitted(state, body)``, ``not_fitted()`` (the states and bodies
        that could not be fitted, with the reason: the others are fitted), ``stripes``,
        ``order_notes()``, ``unit``, ``measure`` and ``fit_csv()`` (the bytes of ``flexrock
        fragility -o``). Errors name the options as the
        command line does (``--state``, ``--level``, ``--im``).
    """
    if states and (outcome != "overturned" or level != 0.0):
        raise ValueError("--state: give the damage states either with --state or with --outcome "
                         "and --level, not both")
    kinds = {o.name: o for o in FragilityOutcome.__members__.values()}
    if outcome not in kinds:
        raise ValueError(f"outcome {outcome!r}: expected one of: {', '.join(kinds)}")
    analyses = FragilityAnalysis.__members__
    if analysis not in analyses:
        raise ValueError(f"analysis {analysis!r}: expected one of: {', '.join(analyses)}")
    return FragilitySession(
        os.fspath(path), im=im if im is not None else "pga_g", im_given=im is not None,
        states=[damage_state(s) for s in states], outcome=kinds[outcome], level=float(level),
        analysis=analyses[analysis], body=body, confidence=float(confidence))


def fragility_from_sweep(
    path: str, im: str = "pga_g", outcome: str = "overturned", level: float = 0.0, body: str = ""
):
    """Fits a sweep CSV as ``flexrock fragility`` does, one damage state (see fragility_session
    for several, stripes and capacities).

    Parameters
    ----------
    path : str
        A sweep CSV.
    im : str
        Intensity measure, as fragility_session takes it.
    outcome : {"overturned", "uplift", "theta", "energy", "offset", "residual_offset"}
        Failure, with ``level`` for the last four.
    level : float
        Threshold of theta [-], energy [J], offset or residual_offset [m].
    body : str
        Only this body (default: each).

    Returns
    -------
    list of (FragilityData, FragilityFit)
        One per body that could be fitted (a FragilityWarning says why for each other one; an
        InputError when none could); rows whose outcome is ``stopped`` or ``contact_lost`` are
        left out and counted in ``FragilityData.excluded``.
    """
    s = fragility_session(path, im, outcome, level, body)
    for _, _, reason in s.not_fitted():
        warnings.warn(reason + " (not fitted; the other bodies are)", FragilityWarning, stacklevel=2)
    return [(s.data(0, k), s.fit(0, k)) for k in range(s.bodies) if s.fitted(0, k)]


def qualify(path, output_dir=None, *, threads: int = 0, render: bool = True) -> dict:
    """Qualifies an unanchored body, as ``flexrock qualify PATH -o OUTPUT_DIR`` does, through the
    same session (docs/qualify.md): the bounding cases x records at the design level and the IDA
    journaled in ``<stem>.runs/`` (an interrupted qualification goes on from there), then the
    report's JSON and pelicun demand CSV, and with ``render`` its HTML and PDF. The files have the
    same bytes as the command line's.

    Parameters
    ----------
    path : str or os.PathLike
        Qualification file (TOML).
    output_dir : str or os.PathLike, optional
        Where the report goes (default: the working directory).
    threads : int
        0: every core. The GIL is released while the runs go; Ctrl-C raises KeyboardInterrupt.
    render : bool
        Also the HTML and PDF (needs matplotlib).

    Returns
    -------
    dict
        ``report`` (the JSON as a dict), ``pass`` (bool) and ``files`` (the paths written, by
        kind: json, csv, html, pdf).
    """
    import json

    from . import report as _report

    path = os.fspath(path)
    out = os.fspath(output_dir) if output_dir is not None else "."
    stem = os.path.splitext(os.path.basename(path))[0]
    files = {k: os.path.join(out, stem + suffix) for k, suffix in
             (("json", ".qualify.json"), ("csv", ".demands.csv"), ("html", ".html"), ("pdf", ".pdf"))}
    session = _flexrock.QualifySession(path, os.path.join(out, stem + ".runs"))
    session.run(threads)
    text, csv_text, passes = session.finish()
    _report._write(files["json"], text)
    _report._write(files["csv"], csv_text)
    if render:
        _report.render(files["json"], files["html"], files["pdf"])
    else:
        del files["html"], files["pdf"]
    return {"report": json.loads(text), "pass": bool(passes), "files": files}


class FragilityWarning(UserWarning):
    """A body or damage state of a fragility study that could not be fitted (the others are)."""


_NOT_API = ("annotations", "os", "warnings", "Iterable", "Mapping", "Optional", "Sequence", "Tuple", "Union")
__all__ = [n for n in dir() if not n.startswith("_") and n not in _NOT_API]
__all__ += ["FragilityQuery", "FragilityData", "read_csv_table", "fragility_data",
            "FragilitySession", "FragilityOutcome", "FragilityAnalysis", "DamageState",
            "damage_state", "fragility_measure", "FragilityMeasure", "FragilityMeasureKind",
            "FragilityOrderNote", "QualifySession", "qualify_key_reference", "newmark_sliding"]
QualifySession = _flexrock.QualifySession
qualify_key_reference = _flexrock.qualify_key_reference
newmark_sliding = _flexrock.newmark_sliding
read_csv_table = _flexrock.read_csv_table
fragility_data = _flexrock.fragility_data
FragilitySession = _flexrock.FragilitySession
FragilityOutcome = _flexrock.FragilityOutcome
FragilityAnalysis = _flexrock.FragilityAnalysis
DamageState = _flexrock.DamageState
damage_state = _flexrock.damage_state
fragility_measure = _flexrock.fragility_measure
FragilityMeasure = _flexrock.FragilityMeasure
FragilityMeasureKind = _flexrock.FragilityMeasureKind
FragilityOrderNote = _flexrock.FragilityOrderNote
