# SPDX-License-Identifier: BSD-3-Clause
"""flexrock: uplift, rocking, impacts and overturning of free-standing deformable bodies.

The engine is C++ (the private extension ``_flexrock``); this package adds what a Python user
needs around it: motions from numpy arrays and files, ``simulate`` returning a :class:`Result`
with numpy time histories and a summary dict with the same keys as the command line's JSON, and
``run_case``, which reproduces ``flexrock run`` byte for byte. Units are SI (m, kg, s, rad, N, J).

Bad input raises :class:`InputError` (a ``ValueError``) with the message the command line prints
after ``flexrock: error:``. The GIL is released while simulating: Python threads run in parallel.
"""

from __future__ import annotations

import csv
import functools
import io
import json
from typing import Optional, Sequence, Union

import numpy as np

from . import _csv, _flexrock
from ._flexrock import (  # noqa: F401  (re-exported API)
    AccelUnit,
    Body,
    BodyParameters,
    Case,
    Component,
    Damping,
    DampingKind,
    EnergyBalance,
    Event,
    EventKind,
    ExcitationComponent,
    Extremes,
    GroundMotion,
    History,
    InitialState,
    InputError,
    LumpedModel,
    LumpedNode,
    OutputPaths,
    OutputSettings,
    OverturnCriterion,
    Phase,
    Record,
    SimulationOptions,
    SimulationResult,
    Status,
    combine,
    cycloidal_c_phase,
    event_columns,
    from_lumped_model,
    load_body,
    load_case,
    oscillator_on_slab,
    read_at2,
    read_single_column,
    read_time_series,
    rigid_block,
    rigid_body,
    time_history_columns,
    uniform_cantilever,
)

__all__ = [name for name in dir() if not name.startswith("_")] + [
    "Result",
    "motion_from_array",
    "motion_from_file",
    "read_record",
    "simulate",
    "run_case",
    "simulate_case",
]

STANDARD_GRAVITY = 9.80665  # [m/s^2], as in the engine

_UNITS = {
    "g": (AccelUnit.g, STANDARD_GRAVITY),
    "m/s^2": (AccelUnit.m_per_s2, 1.0),
    "cm/s^2": (AccelUnit.cm_per_s2, 0.01),
}


def _unit(units: str):
    try:
        return _UNITS[units]
    except KeyError:
        raise InputError(
            f"units: expected one of {', '.join(repr(u) for u in _UNITS)}, got {units!r}"
        ) from None


def _note(motion: GroundMotion, horizontal: dict, vertical: Optional[dict] = None):
    # how a motion was made, for the summary's "excitation" (the engine does not keep it)
    motion._flexrock_excitation = (horizontal, vertical)
    return motion


# --- motions -----------------------------------------------------------------------------------


def motion_from_array(
    horizontal: Sequence[float],
    dt: Optional[float] = None,
    *,
    time: Optional[Sequence[float]] = None,
    vertical: Optional[Sequence[float]] = None,
    units: str = "m/s^2",
    scale: float = 1.0,
) -> GroundMotion:
    """A sampled ground motion from numpy arrays: either every ``dt`` [s] from t = 0, or at the
    given ``time`` [s]. Values are in ``units`` ("g", "m/s^2", "cm/s^2") times ``scale``."""
    _, factor = _unit(units)
    f = factor * scale
    ax = (np.asarray(horizontal, dtype=float) * f).tolist()
    ay = [] if vertical is None else (np.asarray(vertical, dtype=float) * f).tolist()
    if (dt is None) == (time is None):
        raise InputError("motion_from_array: give exactly one of dt or time")
    if time is None:
        m = GroundMotion.uniform(float(dt), ax, ay)
    else:
        m = GroundMotion.sampled(np.asarray(time, dtype=float).tolist(), ax, ay)
    comp = {"type": "record", "file": "", "format": "array", "units": units, "scale": scale}
    return _note(m, comp, dict(comp) if vertical is not None else None)


def read_record(
    path: str, format: Optional[str] = None, *, dt: Optional[float] = None, units: Optional[str] = None
) -> Record:
    """Reads a record file as a case file's ``[excitation.horizontal]`` would: ``format`` is
    "at2" (default for names ending in .AT2), "single_column" (needs ``dt``) or "time_series";
    ``units`` is required unless AT2 (the file states them)."""
    if format is None:
        if str(path).lower().endswith(".at2"):
            format = "at2"
        else:
            raise InputError(
                f"{path}: format: expected 'at2', 'single_column' or 'time_series' "
                "(only .AT2 files are recognised by name)"
            )
    if format == "at2":
        return read_at2(str(path))
    if units is None:
        raise InputError(f"{path}: units: required for format {format!r} ('g', 'm/s^2', 'cm/s^2')")
    unit, _ = _unit(units)
    if format == "single_column":
        if dt is None:
            raise InputError(f"{path}: dt: required for format 'single_column'")
        return read_single_column(str(path), float(dt), unit)
    if format == "time_series":
        return read_time_series(str(path), unit)
    raise InputError(
        f"{path}: format: expected 'at2', 'single_column' or 'time_series', got {format!r}"
    )


def motion_from_file(
    path: str,
    format: Optional[str] = None,
    *,
    dt: Optional[float] = None,
    units: Optional[str] = None,
    scale: float = 1.0,
    vertical: Optional[str] = None,
    vertical_format: Optional[str] = None,
    vertical_dt: Optional[float] = None,
    vertical_units: Optional[str] = None,
) -> GroundMotion:
    """A ground motion from a record file (see :func:`read_record`), times ``scale``; with an
    optional vertical record, combined on the horizontal's time grid as the case file does."""
    rec = read_record(path, format, dt=dt, units=units)
    fmt = format or "at2"
    comp = {"type": "record", "file": str(path), "format": fmt, "units": _unit_name(rec), "scale": 1.0}
    if vertical is None:
        return _note(rec.to_motion(scale), comp)
    vrec = read_record(vertical, vertical_format, dt=vertical_dt, units=vertical_units)
    vcomp = {
        "type": "record",
        "file": str(vertical),
        "format": vertical_format or "at2",
        "units": _unit_name(vrec),
        "scale": 1.0,
    }
    return _note(combine(rec, vrec, scale), comp, vcomp)


def _unit_name(rec: Record) -> str:
    return {AccelUnit.g: "g", AccelUnit.m_per_s2: "m/s^2", AccelUnit.cm_per_s2: "cm/s^2"}[rec.units]


def _synthetic(fn, type_name: str):
    # a pulse builder that notes its type and amplitude (the first argument) for the summary
    @functools.wraps(fn)
    def make(*args, **kwargs):
        m = fn(*args, **kwargs)
        amplitude = args[0] if args else kwargs.get("amplitude", kwargs.get("a_p"))
        comp = {"type": type_name, "amplitude_m_per_s2": float(amplitude)}
        if kwargs.get("component") == Component.vertical:
            return _note(m, {"type": "none"}, comp)
        return _note(m, comp)

    return make


harmonic = _synthetic(_flexrock.harmonic, "harmonic")
harmonic_cycles = _synthetic(_flexrock.harmonic_cycles, "harmonic")
one_sine_pulse = _synthetic(_flexrock.one_sine_pulse, "one_sine")
half_sine_pulse = _synthetic(_flexrock.half_sine_pulse, "half_sine")
cycloidal_pulse_a = _synthetic(_flexrock.cycloidal_pulse_a, "cycloidal_a")
cycloidal_pulse_b = _synthetic(_flexrock.cycloidal_pulse_b, "cycloidal_b")
cycloidal_pulse_c = _synthetic(_flexrock.cycloidal_pulse_c, "cycloidal_c")
ricker_wavelet = _synthetic(_flexrock.ricker_wavelet, "ricker")
rectangular_pulse = _synthetic(_flexrock.rectangular_pulse, "rectangular")
__all__ += [
    "harmonic",
    "harmonic_cycles",
    "one_sine_pulse",
    "half_sine_pulse",
    "cycloidal_pulse_a",
    "cycloidal_pulse_b",
    "cycloidal_pulse_c",
    "ricker_wavelet",
    "rectangular_pulse",
    "free_rocking",
]


def free_rocking(duration: float) -> GroundMotion:
    """No base motion, lasting ``duration`` [s] (start from an initial tilt or rate)."""
    return _note(GroundMotion.none(duration), {"type": "none"})


def _component(d: Optional[dict]) -> ExcitationComponent:
    e = ExcitationComponent()
    if d is None:
        return e
    e.type = d["type"]
    e.file = d.get("file", "")
    e.format = d.get("format", "")
    e.units = d.get("units", "")
    e.amplitude = d.get("amplitude_m_per_s2", 0.0)
    e.scale = d.get("scale", 1.0)
    return e


# --- results -----------------------------------------------------------------------------------


def _parse_csv(text: str) -> dict:
    # the CLI's CSV text as columns
    return _csv.columns(list(csv.reader(io.StringIO(text))), "time history")


class Result:
    """The result of one simulation: the engine's :class:`SimulationResult` (``raw``), the body and
    the case it came from. Time histories are numpy arrays (``history.theta``, ...,
    :meth:`time_history` with the CSV's columns); :meth:`summary` is the command line's JSON as a
    dict. Other attributes (``extremes``, ``energy``, ``events``, ``t_end``, ...) are the
    engine's."""

    def __init__(self, raw: SimulationResult, body: Body, case: Case, paths: Optional[OutputPaths] = None):
        self.raw = raw
        self.body = body
        self.case = case
        self.paths = paths if paths is not None else OutputPaths()
        self._time_history = None

    def __getattr__(self, name):
        if name == "raw":  # not yet set (copy/pickle): no recursion
            raise AttributeError(name)
        return getattr(self.raw, name)

    def __repr__(self):
        return f"<flexrock.Result {self.status} at t = {self.raw.t_end:.4g} s, {len(self.raw.history)} rows>"

    @property
    def status(self) -> str:
        """"completed", "overturned", "contact_lost" or "stopped"."""
        return self.raw.status.name

    @property
    def overturned(self) -> bool:
        return self.raw.status == Status.overturned

    def time_history_csv(self) -> str:
        """The time-history CSV text, as ``flexrock run`` writes it."""
        return _flexrock.time_history_csv(self.raw, self.body)

    def events_csv(self) -> str:
        """The event-log CSV text, as ``flexrock run`` writes it."""
        return _flexrock.events_csv(self.raw)

    def summary_json(self) -> str:
        """The summary JSON text, as ``flexrock run`` writes it."""
        return _flexrock.summary_json(self.case, self.body, self.raw, self.paths)

    def summary(self) -> dict:
        """The summary as a dict: the keys of the command line's summary JSON (docs/case-file.md);
        ``case`` and ``excitation`` say what the caller gave."""
        return json.loads(self.summary_json())

    def time_history(self) -> dict:
        """Columns of the time-history CSV (docs/case-file.md) as numpy arrays, by column name:
        time_s, phase, theta_rad, ..., uplift_m, q1..., impact_loss_J. Equal to the CSV's values
        bit for bit."""
        if self._time_history is None:
            self._time_history = _parse_csv(self.time_history_csv())
        return self._time_history

    def events_table(self) -> dict:
        """Columns of the event log (``event`` holds the kind's name)."""
        return _parse_csv(self.events_csv())

    def write(
        self,
        output_dir: str = "",
        *,
        time_history: Optional[str] = None,
        summary: Optional[str] = None,
        events: Optional[str] = None,
    ) -> OutputPaths:
        """Writes the CSV and JSON files as ``flexrock run`` does (atomically, summary last).
        Without names, a loaded case's [output] table is used; otherwise "result.csv",
        "result.summary.json" and no event log. Relative names are relative to output_dir."""
        c = self.case
        if time_history is not None or summary is not None or events is not None:
            c.output.time_history = time_history or ""
            c.output.summary = summary or ""
            c.output.events = events or ""
            self.case = c
        try:
            self.paths = _flexrock.write_outputs(self.case, self.body, self.raw, str(output_dir))
        except InputError:
            raise
        except RuntimeError as e:
            raise RuntimeError(f"could not write the outputs: {e}") from None
        return self.paths


def _options(options: Optional[SimulationOptions], kwargs: dict) -> SimulationOptions:
    if options is None:
        options = SimulationOptions()
        options.output_dt = 0.01  # the case file's default: a time history every 10 ms
    for key, value in kwargs.items():
        if not hasattr(options, key) or key.startswith("_"):
            raise InputError(f"simulate: unknown option {key!r}")
        if key == "overturn" and isinstance(value, str):
            value = getattr(OverturnCriterion, value)
        setattr(options, key, value)
    return options


def simulate(
    body: Union[Body, BodyParameters],
    motion: GroundMotion,
    initial: Optional[InitialState] = None,
    options: Optional[SimulationOptions] = None,
    *,
    name: str = "",
    description: str = "",
    body_type: str = "python",
    **option_values,
) -> Result:
    """Simulates ``body`` (a Body or BodyParameters) on a base moving with ``motion``.

    Solver options come as a :class:`SimulationOptions` or as keywords (``rtol=1e-10``,
    ``output_dt=0.005``, ``overturn="half_pi"``, ``t_end=...``); without either, the time history
    is kept every 0.01 s as in a case file. ``name``, ``description`` and ``body_type`` only fill
    the summary. The GIL is released while the engine runs."""
    if isinstance(body, BodyParameters):
        body = Body(body)
    initial = initial if initial is not None else InitialState()
    options = _options(options, option_values)
    raw = _flexrock.simulate(body, motion, initial, options)

    c = Case()
    c.name = name
    c.description = description
    c.body_type = body_type
    c.body = body.params
    c.motion = motion
    h, v = getattr(motion, "_flexrock_excitation", (None, None))
    if h is None:
        h = {"type": "record", "format": "array", "units": "m/s^2"} if motion.is_sampled else {
            "type": "analytic",
            "amplitude_m_per_s2": 0.0,
        }
    c.horizontal = _component(h)
    c.vertical = _component(v)
    c.initial = initial
    c.options = options
    out = OutputSettings()
    out.dt = options.output_dt
    out.time_history = "result.csv" if options.output_dt > 0 else ""
    out.summary = "result.summary.json"
    out.events = ""
    c.output = out
    return Result(raw, body, c)


def simulate_case(case: Case) -> Result:
    """Runs a loaded case (:func:`load_case`) without writing anything; the result's
    :meth:`Result.write` writes what the case's [output] table asks for."""
    body = Body(case.body)
    try:
        raw = _flexrock.simulate(body, case.motion, case.initial, case.options)
    except InputError as e:
        raise InputError(f"{case.source}: {e}") from None
    return Result(raw, body, case)


def run_case(path: str, output_dir: Optional[str] = "") -> Result:
    """``flexrock run PATH -o OUTPUT_DIR`` from Python: loads the case, simulates it and writes
    the same files, byte for byte (``output_dir=None``: write nothing). Errors raise
    InputError/RuntimeError with the command line's messages."""
    r = simulate_case(load_case(str(path)))
    if output_dir is not None:
        r.write(str(output_dir))
    return r


# the studies (spectrum, sweep, fragility): built in when the library provides them
if hasattr(_flexrock, "compute_spectrum"):
    from .studies import *  # noqa: F401,F403,E402
    from .studies import __all__ as _study_all  # noqa: E402

    __all__ += _study_all
