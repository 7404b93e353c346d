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
import inspect
import io
import json
import math
from typing import Optional, Sequence, Union

import numpy as np

from . import _csv, _flexrock, _pickling, _reprs

_reprs.install(_flexrock)
from ._flexrock import (  # noqa: F401  (re-exported API)
    AxisymmetricBody,
    RimEvent,
    RimEventKind,
    RimHistory,
    RimInitialState,
    RimMode,
    RimResult,
    RimStatus,
    uniform_cylinder,
    RestrainedResult,
    Restraint,
    RestraintEvent,
    RestraintEventKind,
    RestraintKind,
    RestraintSummary,
    critical_stiffness,
    pushover_acceleration,
    restoring_moment,
    self_centring_stiffness,
    simulate_restrained,
    uplift_acceleration,
    AccelUnit,
    Body,
    BodyKeyValue,
    BodyParameters,
    Case,
    Component,
    ContactForceLaw,
    ContactIntegrator,
    ContactModel,
    Damping,
    DampingKind,
    EnergyBalance,
    Event,
    EventKind,
    ExcitationComponent,
    Extremes,
    GroundMotion,
    History,
    ImpactLaw,
    InitialState,
    InputError,
    LumpedModel,
    LumpedNode,
    OutputPaths,
    OutputSettings,
    OverturnCriterion,
    Phase,
    Record,
    RecordFormat,
    SimulationMethods,
    SimulationOptions,
    SimulationResult,
    Status,
    SupportParameters,
    SupportRunResult,
    simulate_on_support,
    azimuth_motion,
    combine,
    cycloidal_c_phase,
    event_columns,
    from_lumped_model,
    load_body,
    load_case,
    _read_record,
    read_at2,
    read_cosmos,
    read_esm,
    read_knet,
    read_single_column,
    read_smc,
    read_time_series,
    record_formats,
    rotd,
    run_azimuths,
    stack_uplift_bands,
    time_history_columns,
)

# the library's version, set once in CMake's project(VERSION) (also `flexrock --version`)
__version__: str = _flexrock.__version__

__all__ = [name for name in dir() if not name.startswith("_") and name not in ("Optional", "Sequence", "Union", "annotations")] + [
    "Result",
    "motion_from_array",
    "motion_from_file",
    "read_record",
    "simulate",
    "run_case",
    "simulate_case",
    "BodyOfRevolutionResult",
    "axisymmetric_body",
    "simulate_body_of_revolution",
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
    """A sampled ground motion from numpy arrays.

    Parameters
    ----------
    horizontal : array_like
        Horizontal base accelerations, in ``units``.
    dt : float, optional
        [s] sample spacing from t = 0; or give ``time``.
    time : array_like, optional
        [s] sample times, increasing.
    vertical : array_like, optional
        Vertical base accelerations (upward positive), in ``units``.
    units : {"m/s^2", "g", "cm/s^2"}
        Units of the values, as a case file's ``units``.
    scale : float
        [-] factor on the values.

    Returns
    -------
    GroundMotion
        Accelerations [m/s^2], linear between samples.
    """
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
    """Reads a record file as a case file's ``[excitation.horizontal]`` would.

    Parameters
    ----------
    path : str
    format : str, optional
        A name of :func:`record_formats` ("at2", "smc", "knet", "esm", "cosmos",
        "single_column", "time_series"). Default: the format the file name's ending selects
        (.AT2, .smc, .NS/.EW/.UD, .ACC.ASC, .V1/.V2).
    dt : float, optional
        [s] sample spacing; "single_column" only.
    units : {"g", "m/s^2", "cm/s^2"}, optional
        Units of the file's values: required for "single_column" and for a "time_series"
        file without a units row; for a file that states its units, they must agree.

    Returns
    -------
    Record
        Values in the file's units as numpy arrays (``Record.to_motion(scale)`` gives m/s^2).
    """
    unit = None if units is None else _unit(units)[0]
    return _read_record(str(path), format or "", 0.0 if dt is None else float(dt), unit)


def _format_for(path) -> str:
    # the format the file name's ending selects (the table of formats), "" if none
    name = str(path).lower()
    for f in record_formats():
        if any(name.endswith(x) and len(name) > len(x) for x in f.suffixes):
            return f.name
    return ""


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
    """A ground motion from a record file, as a case file's ``[excitation]`` makes it.

    Parameters
    ----------
    path, format, dt, units
        As for :func:`read_record`.
    scale : float
        [-] factor on the record (and the vertical one).
    vertical, vertical_format, vertical_dt, vertical_units : optional
        A vertical record, combined on the horizontal's time grid.

    Returns
    -------
    GroundMotion
        Accelerations [m/s^2].
    """
    rec = read_record(path, format, dt=dt, units=units)
    fmt = format or _format_for(path)
    comp = {"type": "record", "file": str(path), "format": fmt, "units": _unit_name(rec), "scale": 1.0}
    if vertical is None:
        return _note(rec.to_motion(scale), comp)
    vrec = read_record(vertical, vertical_format, dt=vertical_dt, units=vertical_units)
    vcomp = {
        "type": "record",
        "file": str(vertical),
        "format": vertical_format or _format_for(vertical),
        "units": _unit_name(vrec),
        "scale": 1.0,
    }
    return _note(combine(rec, vrec, scale), comp, vcomp)


def _unit_name(rec: Record) -> str:
    return {AccelUnit.g: "g", AccelUnit.m_per_s2: "m/s^2", AccelUnit.cm_per_s2: "cm/s^2"}[rec.units]


def _table_body(kind):
    # the keyword function of a body type with a builder, from the table of body types: its keys
    # in the table's order (required ones first), positional or by name, defaults from the table
    params = []
    for k in kind.keys:
        default = inspect.Parameter.empty
        if not k.required:
            default = int(k.default) if k.value == BodyKeyValue.integer else k.default
        params.append(inspect.Parameter(k.name, inspect.Parameter.POSITIONAL_OR_KEYWORD, default=default))
    sig = inspect.Signature(params, return_annotation="BodyParameters")

    def fn(*args, **kwargs):
        bound = sig.bind(*args, **kwargs)  # a TypeError for a missing or unknown argument
        bound.apply_defaults()
        return _flexrock.make_body(kind.name, {k: float(v) for k, v in bound.arguments.items()})

    def line(k):
        kind_of = "int" if k.value == BodyKeyValue.integer else "float"
        default = k.default_text if k.required else f"default {k.default_text}"
        return f"{k.name} : {kind_of}\n    [{k.unit}] {k.doc} ({default}).\n"

    fn.__signature__ = sig
    fn.__name__ = fn.__qualname__ = kind.function
    fn.__module__ = __name__
    fn.__doc__ = (
        f"A ``{kind.name}`` body: {kind.doc}, as a case file's ``type = \"{kind.name}\"`` makes it\n"
        "(docs/case-file.md; the keys and units of the library's table of body types).\n\n"
        "Parameters\n----------\n" + "".join(line(k) for k in kind.keys)
        + "\nReturns\n-------\nBodyParameters\n"
    )
    return fn


_BODY_KINDS = {k.name: k for k in _flexrock.body_kinds()}  # the library's table of body types
rigid_block = _table_body(_BODY_KINDS["rigid_block"])
rigid_body = _table_body(_BODY_KINDS["rigid_body"])
oscillator_on_slab = _table_body(_BODY_KINDS["oscillator_on_slab"])
uniform_cantilever = _table_body(_BODY_KINDS["uniform_cantilever"])
for _kind in _BODY_KINDS.values():
    # a body type of the table without a function above gets one here
    if _kind.numbers and _kind.function not in globals():
        globals()[_kind.function] = _table_body(_kind)
    if _kind.numbers:
        __all__.append(_kind.function)


_PULSE_KINDS = {k.name: k for k in _flexrock.pulse_kinds()}  # the library's table of pulse types


def _synthetic(kind, function: Optional[str] = None, needs: tuple = ()):
    # a pulse builder from the table of pulse types: the case file's keys and units (amplitude=
    # with units=, or amplitude_g= / amplitude_m_per_s2=; frequency_hz= or period=; the extra keys
    # by their case-file names) as well as the SI form the table gives: a_p [m/s^2], omega_p
    # [rad/s] (types with a frequency), duration [s], the extra keys' engine arguments,
    # component, by those names. Every argument is keyword-only: a bare number says nothing of
    # its unit (0.3 read as a_p = 0.3 m/s^2 where g was meant). It notes its type and amplitude
    # [m/s^2] for the summary. `needs`: extra keys this function requires (harmonic_cycles:
    # cycles)
    type_name, function = kind.name, function or kind.function
    args = ("a_p",) + (("omega_p",) if kind.frequency else ()) + ("duration",)
    args += tuple(k.argument for k in kind.keys) + ("component",)
    key_of = {k.argument: k.name for k in kind.keys}  # engine argument -> case-file key
    names = {k.name: k.argument for k in kind.keys}

    def make(*pos, amplitude=None, units=None, amplitude_g=None, amplitude_m_per_s2=None,
             frequency_hz=None, period=None, **kwargs):
        if pos:
            freq = (", frequency_hz=2.0" if kind.frequency else "")
            si = ", ".join(f"{a}={v!r}" for a, v in zip(args, pos))
            raise TypeError(
                f"{function}() takes its physical values by keyword, with their units, not "
                f"positionally: got {pos!r} (as SI values: {si}); e.g. "
                f"{function}(amplitude=0.3, units=\"g\"{freq}, duration=4.0), or the SI form "
                f"{function}({', '.join(a + '=...' for a in args[:-1])})")
        for key, arg in names.items():
            if key != arg and key in kwargs:
                if arg in kwargs:
                    raise InputError(f"{type_name}: give {key}= or {arg}=, not both")
                kwargs[arg] = kwargs.pop(key)
        for key in kwargs:
            if key not in args:
                raise TypeError(f"{function}() got an unexpected keyword argument {key!r}; it takes "
                                + ", ".join(["amplitude", "units", "amplitude_g", "amplitude_m_per_s2"]
                                            + (["frequency_hz", "period"] if kind.frequency else [])
                                            + ["duration"] + list(names) + ["component"]))
        values = dict(kwargs)
        given = [k for k, v in (("amplitude", amplitude if units is not None else None),
                                ("amplitude_g", amplitude_g),
                                ("amplitude_m_per_s2", amplitude_m_per_s2)) if v is not None]
        new_freq = [k for k, v in (("frequency_hz", frequency_hz), ("period", period)) if v is not None]
        if units is not None and amplitude is None:
            raise InputError(f"{type_name}: units={units!r} without amplitude=")
        if len(given) > 1:
            raise InputError(f"{type_name}: give one of {', '.join(given)}")
        if len(new_freq) > 1:
            raise InputError(f"{type_name}: give one of frequency_hz [Hz] or period [s], not both")
        if new_freq and not kind.frequency:
            raise InputError(f"{type_name}: no frequency (it takes {', '.join(args[1:-1])})")
        if amplitude is not None and units is None:
            raise InputError(
                f"{type_name}: amplitude={amplitude!r} needs its units, as in a case file: "
                f"amplitude={amplitude!r}, units=\"g\" (or \"m/s^2\", \"cm/s^2\"), or "
                f"amplitude_g= / amplitude_m_per_s2="
            )
        if given or new_freq:
            for old in ("a_p", "omega_p"):
                if old in kwargs:
                    raise InputError(
                        f"{type_name}: {old}= is in SI units ({'m/s^2' if old == 'a_p' else 'rad/s'}); "
                        "do not mix it with amplitude=/units=, amplitude_g=, frequency_hz= or period="
                    )
            if amplitude_g is not None:
                values["a_p"] = float(amplitude_g) * STANDARD_GRAVITY
            elif amplitude_m_per_s2 is not None:
                values["a_p"] = float(amplitude_m_per_s2)
            elif amplitude is not None:
                values["a_p"] = float(amplitude) * _unit(units)[1]
            if new_freq:
                f = float(frequency_hz) if frequency_hz is not None else 1.0 / float(period)
                values["omega_p"] = 2.0 * math.pi * f
        if values.get("a_p") is None:
            raise InputError(f"{type_name}: amplitude: missing; give amplitude= with units=, or amplitude_g=")
        if kind.frequency and values.get("omega_p") is None:
            raise InputError(f"{type_name}: frequency: missing; give frequency_hz= [Hz] or period= [s]")
        if values.get("duration") is None:
            raise InputError(f"{type_name}: duration: missing; give duration= [s]")
        keys = {key_of[a]: float(values[a]) for a in key_of if values.get(a) is not None}
        for key in needs:
            if key not in keys:
                raise InputError(f"{function}: {key}: missing; give {key}=")
        component = values.get("component", Component.horizontal)
        # a member of the Component table or its name; anything else is named with the allowed
        if isinstance(component, str) and component in Component.__members__:
            component = Component.__members__[component]
        if not isinstance(component, Component):
            raise InputError(f"{type_name}: component {component!r}: expected one of "
                             f"{', '.join(repr(n) for n in Component.__members__)}")
        a_si = float(values["a_p"])
        recipe = ("pulse", type_name, a_si, float(values.get("omega_p", 0.0)), float(values["duration"]),
                  component, keys)
        m = _flexrock.make_pulse(*recipe[1:])
        m._flexrock_recipe = recipe  # the call that made it: how it pickles
        comp = {"type": type_name, "amplitude_m_per_s2": a_si}
        if component == Component.vertical:
            return _note(m, {"type": "none"}, comp)
        return _note(m, comp)

    def key_doc(k) -> str:
        return f"{k.name} : float\n    [{k.unit}] {k.doc} (default: {k.default_text}).\n"

    make.__name__ = make.__qualname__ = function
    make.__module__ = __name__
    make.__doc__ = (
        f"A ``{type_name}`` motion, as a case file's ``type = \"{type_name}\"`` makes it: {kind.doc}.\n\n"
        "Parameters\n----------\n"
        "amplitude : float\n    Peak acceleration in ``units``; or ``amplitude_g`` [g] or\n"
        "    ``amplitude_m_per_s2`` [m/s^2].\n"
        "units : {\"g\", \"m/s^2\", \"cm/s^2\"}\n"
        + ("frequency_hz : float\n    [Hz]; or ``period`` [s].\n" if kind.frequency else "")
        + "duration : float\n    [s] length of the motion (free vibration after the pulse).\n"
        + "".join(key_doc(k) for k in kind.keys)
        + "component : Component\n    horizontal (default) or vertical.\n\n"
        f"The SI form ``{function}({', '.join(a + '=' for a in args)})`` (m/s^2, rad/s, s; the\n"
        "keys by their engine names) is accepted too. Every argument is keyword-only: a\n"
        "positional number, whose unit nothing says, raises TypeError.\n\n"
        "Returns\n-------\nGroundMotion\n"
    )
    return make


harmonic = _synthetic(_PULSE_KINDS["harmonic"])
# harmonic with `cycles` required: `cycles` cycles, then free vibration
harmonic_cycles = _synthetic(_PULSE_KINDS["harmonic"], "harmonic_cycles", needs=("cycles",))
one_sine_pulse = _synthetic(_PULSE_KINDS["one_sine"])
half_sine_pulse = _synthetic(_PULSE_KINDS["half_sine"])
cycloidal_pulse_a = _synthetic(_PULSE_KINDS["cycloidal_a"])
cycloidal_pulse_b = _synthetic(_PULSE_KINDS["cycloidal_b"])
cycloidal_pulse_c = _synthetic(_PULSE_KINDS["cycloidal_c"])
ricker_wavelet = _synthetic(_PULSE_KINDS["ricker"])
rectangular_pulse = _synthetic(_PULSE_KINDS["rectangular"])
for _kind in _PULSE_KINDS.values():
    # a pulse type of the table without a function above gets one here
    if _kind.function not in globals():
        globals()[_kind.function] = _synthetic(_kind)
        __all__.append(_kind.function)
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
    """No base motion (free rocking from an initial tilt or rate).

    Parameters
    ----------
    duration : float
        [s]

    Returns
    -------
    GroundMotion
    """
    m = GroundMotion.none(duration)
    m._flexrock_recipe = ("none", float(duration))  # how it pickles
    return _note(m, {"type": "none"})


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

    def __getstate__(self):
        # the case with the motion it was made from (a synthetic one pickles by its recipe)
        d = dict(self.__dict__)
        d["case"] = _pickling.case_state(self.case, d.pop("_motion", None))
        d["_time_history"] = None
        return d

    def __setstate__(self, d):
        d = dict(d)
        d["case"] = _pickling.rebuild_case(d["case"])
        self.__dict__.update(d)

    def __repr__(self):
        return f"<flexrock.Result {self.status} at t = {self.raw.t_end:.4g} s, {len(self.raw.history)} rows>"

    @property
    def status(self) -> str:
        """"completed", "overturned" or "stopped"."""
        return self.raw.status.name

    @property
    def overturned(self) -> bool:
        """The engine's one overturning rule (|theta| reached the criterion's angle, rocking or
        in flight), as ``flexrock run``, sweeps and spectra report it."""
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
        """The time history as numpy arrays, by the CSV's column names.

        Returns
        -------
        dict of str to numpy.ndarray
            ``time_s`` [s], ``phase`` (0 full contact, 1 and 2 rocking on edge 1 and 2, 3 flight),
            ``theta_rad`` [rad], ``theta_dot_rad_per_s`` [rad/s], ``uplift_m`` [m], ``q1``...
            [-], ``q1_dot_per_s``... [1/s], ``base_acc_x_m_per_s2``, ``base_acc_y_m_per_s2``
            [m/s^2], ``reaction_x_N``, ``reaction_y_N`` [N], ``resultant_m`` [m],
            ``friction_demand`` [-], ``kinetic_J``, ``potential_J``, ``input_work_J``,
            ``damping_loss_J``, ``impact_loss_J`` [J], ``offset_m``, ``lift_m`` [m]
            (docs/case-file.md). Built from the
            engine's arrays, equal bit for bit to the CSV's values.
        """
        if self._time_history is None:
            self._time_history = _flexrock.time_history_arrays(self.raw, self.body)
        return self._time_history

    def to_dataframe(self):
        """The time history as a pandas DataFrame (needs pandas: Debian's python3-pandas).

        Returns
        -------
        pandas.DataFrame
            One row per output time, the columns of :meth:`time_history` with their unit
            suffixes (``time_s``, ``theta_rad``, ...), as ``pandas.read_csv`` reads the CSV.
        """
        try:
            import pandas as pd
        except ImportError as e:
            raise ImportError(
                f"Result.to_dataframe needs pandas ({e}): install python3-pandas "
                "(scripts/install-deps.sh)"
            ) from None
        return pd.DataFrame(self.time_history(), copy=False)

    def events_table(self) -> dict:
        """The event log as columns (docs/case-file.md): ``time_s`` [s], ``event`` (the
        kind's name), ``edge``, ``theta_rad`` [rad], ``theta_dot_before_rad_per_s``,
        ``theta_dot_after_rad_per_s`` [rad/s], ``energy_loss_J`` [J], ``impulse_x_N_s``,
        ``impulse_y_N_s`` [N s], ``friction_demand`` [-]; numbers as float arrays, names as an
        object array. The columns are those of the library's table (``event_columns()``)."""
        out = {}
        for name, values in zip(event_columns(), _flexrock.event_values(self.raw)):
            out[name] = values if isinstance(values, np.ndarray) else np.array(values, dtype=object)
        return out

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
        # an enum-valued option (its type's table of members: OverturnCriterion, ImpactLaw, ...)
        # takes a member or its name; anything else is refused naming the allowed names
        enum = type(getattr(options, key))
        if hasattr(enum, "__members__"):
            if isinstance(value, str):
                if value not in enum.__members__:
                    raise InputError(f"simulate: {key} {value!r}: expected one of "
                                     f"{', '.join(repr(n) for n in enum.__members__)}")
                value = enum.__members__[value]
            elif not isinstance(value, enum):
                raise InputError(f"simulate: {key} {value!r}: expected one of "
                                 f"{', '.join(repr(n) for n in enum.__members__)} (or "
                                 f"{enum.__name__}.<name>)")
        try:
            setattr(options, key, value)
        except TypeError:
            # pybind11's "incompatible function arguments" names no key: say which and what
            kind = type(getattr(options, key)).__name__
            raise InputError(f"simulate: {key}: expected a {kind}, got {value!r}") from None
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
    """Simulates a body on a base moving with a ground motion.

    Parameters
    ----------
    body : Body or BodyParameters
    motion : GroundMotion
        Base accelerations [m/s^2].
    initial : InitialState, optional
        theta [rad], theta_dot [rad/s], q [-], q_dot [1/s]; default at rest, statically deformed.
    options : SimulationOptions, optional
        Solver options; or give them as keywords.
    name, description, body_type : str
        Only fill the summary.
    **option_values
        ``rtol=1e-10``, ``output_dt=0.005`` [s], ``overturn="half_pi"``, ``t_end=...`` [s], ...
        Without options or keywords the time history is kept every 0.01 s, as in a case file.

    Returns
    -------
    Result
        Overturning, loss of contact and a stopped run are its ``status``. The GIL is released
        while the engine runs.
    """
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
    r = Result(raw, body, c)
    r._motion = motion  # with the recipe of a synthetic motion, which c.motion's copy lacks
    return r


def simulate_case(case: Case) -> Union[Result, "BodyOfRevolutionResult"]:
    """Runs a loaded case without writing anything, with the engine ``flexrock run`` uses.

    Parameters
    ----------
    case : Case
        From :func:`load_case`.

    Returns
    -------
    Result or BodyOfRevolutionResult
        A body of revolution (``cylinder``, ``body_of_revolution``) under a record pair
        (``[excitation.horizontal2]``) runs in 3D (docs/theory.md §27) and returns a
        :class:`BodyOfRevolutionResult`; with one horizontal component it is its planar section.
        ``write`` writes what the case's [output] table asks for.
    """
    if case.body3d is not None and case.has_pair:
        # the 3D engine, as `flexrock run`: never the planar section of a 3D case
        try:
            raw = _flexrock._simulate_case_3d(case)
        except InputError as e:
            raise InputError(f"{case.source}: {e}") from None
        return BodyOfRevolutionResult(raw, case.body3d, case)
    body = Body(case.body)
    if case.support is not None:
        # the support's engine returns the support's results too, which Result does not carry
        raise InputError(f"{case.source}: [support]: run it with flexrock.simulate_on_support("
                         "Body(case.body), case.support, case.motion, case.initial, case.options) "
                         "or 'flexrock run'")
    if len(case.restraints):
        # the restrained engine returns the ties' results too, which Result does not carry: a
        # run without them would be the free body's
        raise InputError(f"{case.source}: [[restraint]]: run it with flexrock.simulate_restrained("
                         "Body(case.body), case.restraints, case.motion, case.initial, "
                         "case.options) or 'flexrock run'")
    try:
        # a rocking frame runs as its equivalent body within the frame's model (docs/theory.md §25)
        raw = _flexrock._simulate_case(case)
    except InputError as e:
        raise InputError(f"{case.source}: {e}") from None
    return Result(raw, body, case)


def run_case(path: str, output_dir: Optional[str] = "") -> Union[Result, "BodyOfRevolutionResult"]:
    """``flexrock run PATH -o OUTPUT_DIR`` from Python.

    Parameters
    ----------
    path : str
        A case file (TOML).
    output_dir : str or None
        Where the outputs go, the same files byte for byte as the command line's; None writes
        nothing.

    Returns
    -------
    Result or BodyOfRevolutionResult
        As :func:`simulate_case`. Errors raise InputError or RuntimeError with the command line's
        messages.
    """
    r = simulate_case(load_case(str(path)))
    if output_dir is not None:
        r.write(str(output_dir))
    return r


class BodyOfRevolutionResult:
    """A 3D run of a rigid body of revolution (docs/theory.md §27): the engine's
    :class:`RimResult` (``raw``), the body and, for a loaded case, the case.

    Attributes are the engine's: ``status`` (:class:`RimStatus`), ``message`` (why it ended early,
    with the magnitude), ``max_tilt`` [rad], ``max_tilt_azimuth`` [rad] (of the contact at the
    largest tilt, from H1 toward H2), ``uplifts``, ``landings``, ``closest_pass`` [rad] (None:
    never rolled round upright without landing), ``max_offset`` [m], ``max_friction_demand``,
    ``min_normal_force`` [N], ``energy`` (:class:`EnergyBalance`, J), ``events`` and ``history``
    (:class:`RimHistory`: numpy arrays at the output times)."""

    def __init__(self, raw: RimResult, body: AxisymmetricBody, case: Optional[Case] = None):
        self.raw = raw
        self.body = body
        self.case = case

    def __getattr__(self, name):
        if name == "raw":  # not yet set (copy): no recursion
            raise AttributeError(name)
        return getattr(self.raw, name)

    def __repr__(self):
        return repr(self.raw)

    @property
    def alpha(self) -> float:
        """[rad] the body's slenderness atan(R / h)."""
        return self.body.alpha

    def time_history(self) -> dict:
        """The time-history CSV's columns (name with unit to numpy array)."""
        return self.raw.history.columns()

    def _need_case(self, what: str) -> Case:
        if self.case is None:
            raise InputError(f"{what}: this run has no case (simulate_body_of_revolution); load one "
                             "with load_case and run it with simulate_case")
        return self.case

    def summary(self, output_dir: str = "") -> dict:
        """The summary JSON ``flexrock run`` writes for the case, as a dict."""
        c = self._need_case("summary")
        return json.loads(_flexrock._rim_summary_json(c, self.raw, str(output_dir)))

    def write(self, output_dir: str = "") -> None:
        """Writes what the case's [output] table asks for, the same files byte for byte as
        ``flexrock run`` (atomically, summary last; nothing when a value is not finite)."""
        c = self._need_case("write")
        try:
            _flexrock._write_rim_outputs(c, self.raw, str(output_dir))
        except InputError:
            raise
        except RuntimeError as e:
            raise RuntimeError(f"could not write the outputs: {e}") from None


def axisymmetric_body(type: str, **keys: float) -> AxisymmetricBody:
    """A body of revolution in 3D from a body type of the table, with the keys and defaults a case
    file's [body] takes (docs/case-file.md). ``flexrock.cylinder(...)`` and
    ``flexrock.body_of_revolution(...)`` give the same bodies' planar sections.

    Parameters
    ----------
    type : str
        ``"cylinder"`` (keys radius [m], height [m], mass [kg], inner_radius [m], default 0) or
        ``"body_of_revolution"`` (mass [kg], cg_height [m], base_radius [m], inertia_diameter
        [kg m^2], inertia_axis [kg m^2]).
    **keys : float
        The type's keys, in SI units.

    Returns
    -------
    AxisymmetricBody

    Raises
    ------
    InputError
        Another type, an unknown or missing key, or a body no rigid body can be.
    """
    return _flexrock._axisymmetric_body(type, {k: float(v) for k, v in keys.items()})


def simulate_body_of_revolution(
    body: AxisymmetricBody,
    h1: GroundMotion,
    h2: Optional[GroundMotion] = None,
    initial: Optional[RimInitialState] = None,
    options: Optional[SimulationOptions] = None,
    **option_values,
) -> BodyOfRevolutionResult:
    """Simulates a rigid body of revolution on a floor shaken in three components
    (docs/theory.md §27): full contact, rocking-rolling on the rim without slip, landing,
    overturning. Flight, rim slip and full sliding are not modelled: they end the run, named in
    ``status`` and ``message`` with their magnitude.

    Parameters
    ----------
    body : AxisymmetricBody
        From :class:`AxisymmetricBody`, :func:`uniform_cylinder` or :func:`axisymmetric_body`.
    h1 : GroundMotion
        [m/s^2] H1, along x, and the vertical (its vertical component).
    h2 : GroundMotion, optional
        [m/s^2] H2, along y (90 degrees from H1 toward which azimuths are measured); its
        horizontal only (a vertical component is refused). None: no H2.
    initial : RimInitialState, optional
        Upright at rest by default.
    options : SimulationOptions, optional
        The planar run's options (t_end [s], rtol, atol, max_step [s], event_samples, output_dt
        [s], overturn, chatter_ratio, friction_coefficient, max_steps) as a case's [options]
        gives them; default output_dt 0.01 s.
    **option_values
        Any of those options by name.

    Returns
    -------
    BodyOfRevolutionResult
        Overturning, an unmodelled mode and a stopped run are its ``status``. The GIL is released
        while the engine runs.

    Raises
    ------
    InputError
        A bad body, option or motion.
    """
    if not isinstance(body, AxisymmetricBody):
        raise InputError(f"simulate_body_of_revolution: body: expected an AxisymmetricBody "
                         f"(axisymmetric_body, uniform_cylinder), got {type(body).__name__}")
    if h2 is not None and h2.has_vertical:
        raise InputError("simulate_body_of_revolution: h2 has a vertical component, which would be "
                         "ignored: give the vertical with h1")
    initial = initial if initial is not None else RimInitialState()
    options = _options(options, option_values)
    raw = _flexrock._simulate_axisymmetric(body, h1, h2, initial, options)
    return BodyOfRevolutionResult(raw, body)


from .response_spectra import response_spectrum  # noqa: E402

__all__ += ["response_spectrum"]

# the studies (spectrum, sweep, fragility): built in when the library provides them
if hasattr(_flexrock, "compute_spectrum"):
    from .studies import *  # noqa: F401,F403,E402
    from .studies import __all__ as _study_all  # noqa: E402

    __all__ += _study_all
