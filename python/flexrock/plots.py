# SPDX-License-Identifier: BSD-3-Clause
"""Figures of flexrock results (matplotlib): PNG, SVG or PDF.

Every function draws into the ``ax=`` (an :class:`~matplotlib.axes.Axes`) or ``fig=`` (a
:class:`~matplotlib.figure.Figure`) it is given and returns what it drew: the Axes, or the Figure
for the six-panel :func:`response_figure`. Given neither, it makes a new figure with pyplot, so
``plt.show()`` shows it and Jupyter shows it inline; pass ``fig=matplotlib.figure.Figure()`` to
draw without pyplot (no display, safe in threads). :func:`save` writes a figure by extension.

Inputs are a :class:`flexrock.Result`, a time-history CSV written by ``flexrock run`` (its summary
JSON and event log are found next to it), the spectrum CSV of ``flexrock spectrum`` or a
:class:`flexrock.SpectrumResult`, and for :func:`fragility_curve` a sweep CSV, the output of
``flexrock fragility`` or a fit. Units are those of the column names (SI unless the name says
``_g`` or ``_hz``).
"""

from __future__ import annotations

import csv
import json
import math
import os
from typing import Optional

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from ._csv import columns as _columns  # shared with the results API

__all__ = [
    "load_run",
    "response_figure",
    "moment_rotation_loop",
    "rim_figure",
    "load_rim",
    "is_rim_history",
    "spectrum_map",
    "read_spectrum",
    "fragility_curve",
    "ida_curves",
    "response_spectrum",
    "save",
]

STANDARD_GRAVITY = 9.80665  # [m/s^2]


def _axes(ax, fig, figsize):
    # the Axes to draw into: the caller's, one on the caller's figure, or a new pyplot figure
    if ax is not None:
        return ax
    if fig is None:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=figsize, layout="constrained")
    elif figsize is not None and not fig.axes:
        fig.set_size_inches(*figsize)
    return fig.add_subplot()


# rocking on edge 1 / edge 2: the same colours in every figure
_EDGE_COLOURS = {1: "tab:orange", 2: "tab:purple"}


# --- inputs ------------------------------------------------------------------------------------


def _read_columns(path: str, require_rows: bool = False) -> dict:
    with open(path, newline="") as f:
        return _columns(list(csv.reader(f)), path, require_rows=require_rows)


def load_run(path: str):
    """A run's outputs from its time-history CSV.

    Parameters
    ----------
    path : str
        A time-history CSV of ``flexrock run``.

    Returns
    -------
    (dict, dict or None, dict or None)
        Its columns (numpy arrays, SI units as the names say), the event log's columns and the
        summary: the summary JSON "<stem>.summary.json" and the event log (the summary's
        outputs.events, or "<stem>.events.csv") when they lie next to the CSV, else None. A
        header without rows is a ValueError.
    """
    cols = _read_columns(path, require_rows=True)
    if "time_s" not in cols or "theta_rad" not in cols:
        raise ValueError(
            f"{path}: not a flexrock time history: expected the columns time_s, theta_rad, ..."
        )
    folder = os.path.dirname(path)
    stem = os.path.basename(path)
    stem = stem[:-4] if stem.endswith(".csv") else stem
    summary = None
    summary_path = os.path.join(folder, stem + ".summary.json")
    if os.path.exists(summary_path):
        with open(summary_path) as f:
            summary = json.load(f)
    candidates = []
    if summary and summary.get("outputs", {}).get("events"):
        candidates.append(os.path.join(folder, os.path.basename(summary["outputs"]["events"])))
    candidates.append(os.path.join(folder, stem + ".events.csv"))
    events = next((_read_columns(p) for p in candidates if os.path.exists(p)), None)
    return cols, events, summary


def _run_data(source, events=None, summary=None):
    # (columns, events, summary) from a Result, a CSV path or a dict of columns
    if hasattr(source, "time_history") and hasattr(source, "events_table"):
        return source.time_history(), source.events_table(), source.summary()
    if isinstance(source, (str, os.PathLike)):
        cols, ev, su = load_run(os.fspath(source))
        return cols, events if events is not None else ev, summary if summary is not None else su
    if isinstance(source, dict):
        return source, events, summary
    raise TypeError(f"expected a flexrock.Result, a time-history CSV path or a dict, got {type(source)}")


def _spans(t: np.ndarray, phase: np.ndarray, value: int):
    # [start, end] time spans where phase == value
    on = phase == value
    spans = []
    i, n = 0, len(t)
    while i < n:
        if on[i]:
            j = i
            while j + 1 < n and on[j + 1]:
                j += 1
            # the phase changed between samples j and j + 1: shade up to j + 1
            spans.append((t[i], t[j + 1] if j + 1 < n else t[j]))
            i = j + 1
        else:
            i += 1
    return spans


def _impacts_from_history(t: np.ndarray, phase: np.ndarray, impact_loss) -> np.ndarray:
    # a history without its event log: an impact lies between two rows where the impact loss
    # rises (a landing that dissipates: onto the other pivot, or a flexible body's onto its base)
    # or the pivot changes from one edge to the other (a lossless law); marked at the later row
    hit = (phase[1:] != phase[:-1]) & (phase[1:] > 0) & (phase[:-1] > 0)
    if impact_loss is not None:
        loss = np.asarray(impact_loss, dtype=float)
        hit |= loss[1:] > loss[:-1]
    return t[1:][hit]


def _event_times(events, kind: str) -> np.ndarray:
    if events is None or "event" not in events:
        return np.array([])
    mask = np.array([e == kind for e in events["event"]], dtype=bool)
    return np.asarray(events["time_s"], dtype=float)[mask]


# --- a support's and restraints' panels --------------------------------------------------------


def _restraint_numbers(cols) -> list:
    # the ties of a case with [[restraint]] tables, by their 1-based number in the history's
    # restraint_force_N_<i> columns
    prefix = "restraint_force_N_"
    return sorted(int(k[len(prefix):]) for k in cols if k.startswith(prefix) and k[len(prefix):].isdigit())


def _restraint_events(source, summary):
    # the ties' events: "<events stem>.restraints.csv" beside a CSV's event log, else the summary's
    # copy of them; None when neither is there
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        folder = os.path.dirname(path)
        stem = os.path.basename(path)
        stem = stem[:-4] if stem.endswith(".csv") else stem
        logs = []
        if summary and summary.get("outputs", {}).get("events"):
            logs.append(os.path.basename(summary["outputs"]["events"]))
        logs.append(stem + ".events.csv")
        for log in logs:
            candidate = os.path.join(folder, (log[:-4] if log.endswith(".csv") else log) + ".restraints.csv")
            if os.path.exists(candidate):
                return _read_columns(candidate)
    rows = ((summary or {}).get("restraints") or {}).get("events")
    if rows:
        names = ("time_s", "restraint", "event", "force_N")
        return {n: [r.get(n) for r in rows] for n in names}
    return None


def _support_panel(ax, t, cols):
    # the support's displacement from the ground (left axis) and its spring and dashpot force
    # k u + c u_dot (right axis, a twin: the last of fig.axes)
    line_u = ax.plot(t, cols["support_u_m"], lw=0.8, color="tab:blue", label="displacement u", gid="support_u")
    ax.set_ylabel("support u [m]")
    ax_force = ax.twinx()
    line_f = ax_force.plot(
        t, cols["support_force_N"], lw=0.8, color="tab:brown", label="force k u + c u̇", gid="support_force"
    )
    ax_force.set_ylabel("support force [N]")
    ax.set_title("support displacement / force", fontsize="small", loc="left")
    ax.legend(line_u + line_f, [ln.get_label() for ln in line_u + line_f], loc="upper right", fontsize="small")


def _restraint_panel(ax, t, cols, ties, events):
    # one line per tie; its yields (triangles) and fracture (a cross) where its event log says
    for i in ties:
        (line,) = ax.plot(t, cols[f"restraint_force_N_{i}"], lw=0.8, label=f"restraint {i}", gid=f"restraint_{i}")
        if events is None or "event" not in events:
            continue
        who = np.asarray(events["restraint"], dtype=float)
        when = np.asarray(events["time_s"], dtype=float)
        force = np.asarray(events["force_N"], dtype=float)
        for kind, style, size in (("yield", "^", 5), ("fracture", "X", 8)):
            mask = (who == i) & np.array([e == kind for e in events["event"]], dtype=bool)
            if mask.any():
                ax.plot(
                    when[mask], force[mask], style, color=line.get_color(), mfc="none", ms=size,
                    gid=f"restraint_{i}_{kind}",
                )
    handles, labels = ax.get_legend_handles_labels()
    for kind, style, size, label in (("yield", "^", 5, "yield"), ("fracture", "X", 8, "fracture")):
        if any(ln.get_gid() and ln.get_gid().endswith("_" + kind) for ln in ax.lines):
            handles.append(Line2D([], [], ls="none", marker=style, color="0.3", mfc="none", ms=size))
            labels.append(label)
    ax.set_ylabel("restraint force [N]")
    ax.set_title("restraint forces", fontsize="small", loc="left")
    ax.legend(handles, labels, loc="upper right", fontsize="small", ncol=2)


# --- the response figure -----------------------------------------------------------------------


def response_figure(
    source,
    events=None,
    summary=None,
    *,
    title: Optional[str] = None,
    xlim=None,
    figsize=(9, 11),
    fig: Optional[Figure] = None,
    restraint_events=None,
) -> Figure:
    """The response of one run against time, in six panels (five for a rigid body).

    Base accelerations [m/s^2]; theta [rad] with the rocking phases shaded (edge 1 and edge 2 in
    two colours), the landings marked (``impact`` events as red crosses; ``rocking_ended``, a
    landing that ends rocking, as green circles; ``chatter_cutoff`` as blue diamonds) and the
    overturning angles dashed (theta/alpha on the right axis); deformation q [-] (a flexible
    body only); floor reactions [N]; friction demand [-]; energy budget [J] (input work = stored
    + dissipated + residual). Without an event log the impacts are read from the history: at the
    first row after each rise of the impact loss or change of pivot, so within one output
    interval of the impact (legend "impact (from the history)").

    A history with a support's columns (a case with ``[support]``) gains a panel after the
    reactions, "support displacement / force": ``support_u_m`` [m] on the left axis,
    ``support_force_N`` [N] on a twin axis (the last of ``fig.axes``). One with restraints'
    columns (``[[restraint]]``) gains "restraint forces": one line per ``restraint_force_N_i``,
    each tie's yields (triangles) and fracture (a cross) at their times and forces, from
    ``<events stem>.restraints.csv`` next to the event log (else the summary's copy); the energy
    residual then holds the ties' plastic and fracture work, which no column gives. A 3D body of
    revolution's history is drawn by :func:`rim_figure`.

    Parameters
    ----------
    source : flexrock.Result, str or dict
        A result, a time-history CSV path (its ``.summary.json`` and event log are read from
        next to it) or a dict of the CSV's columns.
    events, summary : dict, optional
        The event log's columns and the summary, overriding what ``source`` brings.
    title : str, optional
        Default: the case name and outcome.
    xlim : (float, float), optional
        A time window [s].
    figsize : (float, float)
        [in], for a new figure.
    fig : matplotlib.figure.Figure, optional
        An empty figure to draw into; default a new pyplot figure.
    restraint_events : dict, optional
        The restraints' event log's columns (``time_s``, ``restraint``, ``event``, ``force_N``),
        overriding the file next to ``source``.

    Returns
    -------
    matplotlib.figure.Figure
        The figure; its Axes are ``fig.axes``: accelerations, theta, q (a flexible body only),
        reactions, support (with ``[support]``), restraint forces (with restraints), friction
        demand, energies, then the support force's twin axis.
    """
    cols, events, summary = _run_data(source, events, summary)
    t = np.asarray(cols["time_s"], dtype=float)
    if fig is None:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=figsize, layout="constrained")
    qs = sorted((k for k in cols if k.startswith("q") and k[1:].isdigit()), key=lambda k: int(k[1:]))
    ties = _restraint_numbers(cols)
    has_support = "support_u_m" in cols
    # a panel each for what the history has: a rigid body has no deformation to show, a body on
    # the floor no support, a free one no restraints
    names = ["acc", "theta"] + ["q"] * bool(qs) + ["reaction"]
    names += ["support"] * has_support + ["restraints"] * bool(ties) + ["friction", "energy"]
    panels = dict(zip(names, fig.subplots(len(names), 1, sharex=True)))
    ax_acc, ax_th, ax_r, ax_f, ax_e = (panels[k] for k in ("acc", "theta", "reaction", "friction", "energy"))
    ax_q = panels.get("q")

    # base accelerations
    ax_acc.plot(t, cols["base_acc_x_m_per_s2"], lw=0.8, label="horizontal $\\ddot X$")
    if np.any(cols["base_acc_y_m_per_s2"] != 0.0):
        ax_acc.plot(t, cols["base_acc_y_m_per_s2"], lw=0.8, label="vertical $\\ddot Y$")
    ax_acc.set_ylabel("base acc. [m/s²]")
    ax_acc.legend(loc="upper right", fontsize="small")

    # theta, phases, impacts, overturning angles
    theta = np.asarray(cols["theta_rad"], dtype=float)
    phase = np.asarray(cols["phase"], dtype=float)
    for edge in (1, 2):
        for a, b in _spans(t, phase, edge):
            ax_th.axvspan(a, b, color=_EDGE_COLOURS[edge], alpha=0.18, lw=0, gid=f"phase_edge{edge}")
    ax_th.plot(t, theta, color="k", lw=0.9, label="θ")
    impacts = _event_times(events, "impact")
    impact_label = "impact"
    if events is None:
        impacts = _impacts_from_history(t, phase, cols.get("impact_loss_J"))
        impact_label = "impact (from the history)"
    if impacts.size:
        ax_th.plot(impacts, np.zeros_like(impacts), "x", color="tab:red", ms=5, label=impact_label, gid="impacts")
    # landings that end rocking (a flexible body settles rather than bounces): marked apart
    for kind, style, colour, label in (
        ("rocking_ended", "o", "tab:green", "rocking ended"),
        ("chatter_cutoff", "D", "tab:blue", "chatter cut off"),
    ):
        times = _event_times(events, kind)
        if times.size:
            ax_th.plot(times, np.zeros_like(times), style, mfc="none", color=colour, ms=5, label=label, gid=kind)
    overturn = _event_times(events, "overturn")
    if overturn.size:
        ax_th.plot(overturn, np.interp(overturn, t, theta), "*", color="tab:red", ms=10, label="overturn")
    if summary:
        b = summary.get("body", {})
        for key, sign in (("tipping_angle_edge1_rad", 1.0), ("tipping_angle_edge2_rad", -1.0)):
            if b.get(key) is not None and np.max(np.abs(theta)) > 0.25 * b[key]:
                ax_th.axhline(sign * b[key], color="tab:red", ls="--", lw=0.7)
        alpha = b.get("alpha1")
        if alpha and b.get("alpha2") == alpha:
            a = math.atan(alpha)  # slenderness angle
            sec = ax_th.secondary_yaxis("right", functions=(lambda x: x / a, lambda x: x * a))
            sec.set_ylabel("θ/α")
    ax_th.set_ylabel("θ [rad]")
    handles, labels = ax_th.get_legend_handles_labels()
    handles += [Patch(color=_EDGE_COLOURS[1], alpha=0.3), Patch(color=_EDGE_COLOURS[2], alpha=0.3)]
    labels += ["rocking on edge 1", "rocking on edge 2"]
    ax_th.legend(handles, labels, loc="upper right", fontsize="small", ncol=2)

    # deformation
    if qs:
        for k in qs:
            ax_q.plot(t, cols[k], lw=0.8, label=k)
        ax_q.legend(loc="upper right", fontsize="small")
        ax_q.set_ylabel("q [-]")

    # reactions and friction demand
    ax_r.plot(t, cols["reaction_x_N"], lw=0.8, label="$F_I$ (shear)")
    ax_r.plot(t, cols["reaction_y_N"], lw=0.8, label="$F_J$ (normal)")
    ax_r.set_ylabel("reaction [N]")
    ax_r.legend(loc="upper right", fontsize="small")
    if has_support:
        _support_panel(panels["support"], t, cols)
    if ties:
        if restraint_events is None:
            restraint_events = _restraint_events(source, summary)
        _restraint_panel(panels["restraints"], t, cols, ties, restraint_events)
    fd = np.asarray(cols["friction_demand"], dtype=float)
    ax_f.plot(t, np.where(np.isfinite(fd), fd, np.nan), lw=0.8, color="tab:green", label="|F_I|/F_J")
    mu = (summary or {}).get("solver", {}).get("friction_coefficient")
    if mu is not None:
        ax_f.axhline(mu, color="tab:red", ls="--", lw=0.7, label="friction coefficient")
    ax_f.set_ylabel("friction demand [-]")
    ax_f.legend(loc="upper right", fontsize="small")

    # energy budget
    w = cols["input_work_J"]
    stored = cols["kinetic_J"] + cols["potential_J"] - cols["potential_J"][0]
    lost = cols["damping_loss_J"] + cols["impact_loss_J"]
    ax_e.plot(t, w, lw=1.0, label="input work")
    ax_e.plot(t, cols["kinetic_J"], lw=0.8, label="kinetic")
    ax_e.plot(t, cols["potential_J"] - cols["potential_J"][0], lw=0.8, label="potential change")
    ax_e.plot(t, cols["damping_loss_J"], lw=0.8, label="damping loss")
    ax_e.plot(t, cols["impact_loss_J"], lw=0.8, label="impact loss")
    # a tie's plastic and fracture work is not a column of the history (the summary's restraints
    # give its total): the residual drawn holds it
    residual_label = "residual (incl. ties' plastic work)" if ties else "residual"
    ax_e.plot(t, w - stored - lost, lw=0.8, color="0.5", ls=":", label=residual_label)
    ax_e.set_ylabel("energy [J]")
    ax_e.set_xlabel("time [s]")
    ax_e.legend(loc="center right", fontsize="small", ncol=2)

    if xlim is not None:
        ax_e.set_xlim(*xlim)
    if title is None and summary:
        case = summary.get("case", {})
        outcome = summary.get("outcome", {}).get("status", "")
        title = f"{case.get('name') or 'flexrock'}: {outcome}"
    if title:
        fig.suptitle(title)
    return fig


# --- a body of revolution in 3D ----------------------------------------------------------------

# the columns that tell a 3D body of revolution's time history (docs/case-file.md)
RIM_COLUMNS = ("time_s", "mode", "tilt_rad", "tilt_azimuth_deg", "contact_angle_deg")

# rolling on the rim / pivoting near upright: the shading of the tilt panel
_RIM_MODES = {1: ("tab:orange", "rolling on the rim"), 2: ("tab:purple", "pivoting near upright")}


def is_rim_history(cols_or_header) -> bool:
    """Whether a time history (its columns or its header) is a 3D body of revolution's."""
    return set(RIM_COLUMNS) <= set(cols_or_header)


def load_rim(path: str):
    """A 3D body of revolution's outputs from its time-history CSV (``flexrock run`` of a
    ``cylinder`` or ``body_of_revolution`` under a record pair).

    Returns
    -------
    (dict, dict or None, dict or None)
        Its columns, the event log's columns (``time_s, kind, tilt_rad, azimuth_deg, value,
        energy_loss_J``) and the summary, as :func:`load_run`: the summary "<stem>.summary.json"
        and the event log it names (``files.events``) when they lie next to the CSV, else None.
    """
    cols = _read_columns(path, require_rows=True)
    if not is_rim_history(cols):
        raise ValueError(
            f"{path}: not the time history of a body of revolution in 3D: expected the columns "
            + ", ".join(RIM_COLUMNS)
        )
    folder = os.path.dirname(path)
    stem = os.path.basename(path)
    stem = stem[:-4] if stem.endswith(".csv") else stem
    summary = None
    summary_path = os.path.join(folder, stem + ".summary.json")
    if os.path.exists(summary_path):
        with open(summary_path) as f:
            summary = json.load(f)
    events = None
    named = ((summary or {}).get("files") or {}).get("events")
    if named:
        candidate = os.path.join(folder, os.path.basename(named))
        if os.path.exists(candidate):
            events = _read_columns(candidate)
    return cols, events, summary


def rim_figure(
    source,
    events=None,
    summary=None,
    *,
    title: Optional[str] = None,
    xlim=None,
    figsize=(11, 8),
    fig: Optional[Figure] = None,
) -> Figure:
    """A 3D body of revolution's response (docs/theory.md §27): where it leans and where it stands.

    Left, against time: the tilt [rad] with the modes shaded (rolling on the rim orange, pivoting
    near upright purple) and the events marked (uplift, landing, rest, overturn, and a mode not
    modelled: lift_off, rim_slip, full_sliding), the tilt azimuth [deg] (toward which the axis
    leans, from H1 toward H2) and the contact angle [deg] (the contact's angle on the base circle
    in the body, unwrapped: how far it rolled). Right: the tilt's orbit (polar: tilt magnitude
    against tilt azimuth, with the overturning angle dashed when the tilt comes within 4 times of
    it) and the contact point's path on the base circle (radius R from the summary, else 1): a
    dot a row coloured by time (the rows in full contact, which have no contact point, left
    out; a colour bar beside it).

    Parameters
    ----------
    source : str or dict
        The time-history CSV of ``flexrock run`` (its summary and event log are read from next
        to it) or a dict of its columns.
    events, summary : dict, optional
        The event log's columns and the summary, overriding what ``source`` brings.
    title : str, optional
        Default: the case name and status.
    xlim : (float, float), optional
        A time window [s] of the time panels (the orbit and the path show every row).
    fig : matplotlib.figure.Figure, optional
        An empty figure to draw into; default a new pyplot figure.

    Returns
    -------
    matplotlib.figure.Figure
        Its Axes, in ``fig.axes`` order and by their labels (``Axes.get_label()``): "tilt", "tilt
        azimuth", "contact angle", "tilt orbit" (polar), "contact path", and the colour bar of
        the path's time when the body left full contact.
    """
    if isinstance(source, (str, os.PathLike)):
        cols, ev, su = load_rim(os.fspath(source))
        events = events if events is not None else ev
        summary = summary if summary is not None else su
    elif isinstance(source, dict):
        cols = source
        if not is_rim_history(cols):
            raise ValueError("not the time history of a body of revolution in 3D: expected the columns " + ", ".join(RIM_COLUMNS))
    else:
        raise TypeError(f"expected a time-history CSV path or a dict, got {type(source)}")
    if fig is None:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=figsize, layout="constrained")
    t = np.asarray(cols["time_s"], dtype=float)
    mode = np.asarray(cols["mode"], dtype=float)
    tilt = np.asarray(cols["tilt_rad"], dtype=float)
    azimuth = np.asarray(cols["tilt_azimuth_deg"], dtype=float)
    contact = np.asarray(cols["contact_angle_deg"], dtype=float)
    body = (summary or {}).get("body", {})

    grid = fig.add_gridspec(2, 2, width_ratios=(1.6, 1))
    left = grid[:, 0].subgridspec(3, 1)
    ax_tilt = fig.add_subplot(left[0], label="tilt")
    ax_az = fig.add_subplot(left[1], sharex=ax_tilt, label="tilt azimuth")
    ax_c = fig.add_subplot(left[2], sharex=ax_tilt, label="contact angle")
    ax_orbit = fig.add_subplot(grid[0, 1], projection="polar", label="tilt orbit")
    ax_path = fig.add_subplot(grid[1, 1], label="contact path")

    # tilt against time, the modes shaded, the events marked
    for value, (colour, _) in _RIM_MODES.items():
        for a, b in _spans(t, mode, value):
            ax_tilt.axvspan(a, b, color=colour, alpha=0.18, lw=0, gid=f"mode{value}")
    ax_tilt.plot(t, tilt, color="k", lw=0.9, label="tilt θ", gid="tilt")
    if events is not None and "kind" in events and len(events["kind"]):
        when = np.asarray(events["time_s"], dtype=float)
        at = np.asarray(events["tilt_rad"], dtype=float)
        kinds = np.asarray(events["kind"], dtype=object)
        styles = {"uplift": ("^", "tab:green"), "landing": ("x", "tab:red"), "rest": ("o", "tab:blue"),
                  "overturn": ("*", "tab:red")}
        for kind in dict.fromkeys(kinds):
            marker, colour = styles.get(kind, ("D", "tab:red"))  # a mode not modelled
            mask = kinds == kind
            ax_tilt.plot(when[mask], at[mask], marker, color=colour, mfc="none", ms=6, ls="none",
                         label=kind.replace("_", " "), gid=f"event_{kind}")
    ax_tilt.set_ylabel("tilt [rad]")
    handles, labels = ax_tilt.get_legend_handles_labels()
    for value, (colour, label) in _RIM_MODES.items():
        handles.append(Patch(color=colour, alpha=0.3))
        labels.append(label)
    ax_tilt.legend(handles, labels, loc="upper right", fontsize="small", ncol=2)
    ax_tilt.tick_params(labelbottom=False)

    ax_az.plot(t, azimuth, lw=0.8, color="tab:blue", gid="tilt_azimuth")
    ax_az.set_ylabel("tilt azimuth [deg]")
    ax_az.tick_params(labelbottom=False)
    ax_c.plot(t, contact, lw=0.8, color="tab:brown", gid="contact_angle")
    ax_c.set_ylabel("contact angle [deg]")
    ax_c.set_xlabel("time [s]")
    if xlim is not None:
        ax_c.set_xlim(*xlim)

    # the tilt's orbit: where the axis leans, how far
    ax_orbit.plot(np.radians(azimuth), tilt, lw=0.7, color="k", gid="orbit")
    alpha = body.get("alpha_rad")
    if alpha and np.nanmax(tilt, initial=0.0) > 0.25 * alpha:
        ring = np.linspace(0.0, 2.0 * np.pi, 361)
        ax_orbit.plot(ring, np.full_like(ring, alpha), "--", color="tab:red", lw=0.7, gid="alpha")
    ax_orbit.set_rlabel_position(112.5)
    ax_orbit.set_title("tilt orbit: θ [rad] against its azimuth (H1 at 0°, H2 at 90°)", fontsize="small")

    # the contact point on the base circle, in the body; none in full contact
    radius = body.get("base_radius_m") or 1.0
    ring = np.linspace(0.0, 2.0 * np.pi, 361)
    ax_path.plot(radius * np.cos(ring), radius * np.sin(ring), color="0.7", lw=0.8, gid="base_circle")
    # one dot a row, coloured by time: between rows the contact may travel far round the rim, so
    # joining the rows by chords would draw a path it never took
    on_rim = mode != 0
    c = np.radians(contact[on_rim])
    dots = ax_path.scatter(radius * np.cos(c), radius * np.sin(c), c=t[on_rim], s=4, cmap="viridis",
                           gid="contact_path")
    if on_rim.any():
        dots.set_clim(t[on_rim][0], t[on_rim][-1])
        fig.colorbar(dots, ax=ax_path, label="time [s]", shrink=0.8)
        ax_path.plot(radius * np.cos(c[0]), radius * np.sin(c[0]), "^", color="tab:red", mfc="none", ms=8,
                     label="first contact on the rim", gid="contact_first")
        ax_path.legend(loc="upper right", fontsize="small")
    ax_path.set_aspect("equal")
    unit = "m" if body.get("base_radius_m") else "R"
    ax_path.set_xlabel(f"base x [{unit}]")
    ax_path.set_ylabel(f"base y [{unit}]")
    ax_path.set_title("contact point's path on the base circle (in the body)", fontsize="small")

    if title is None and summary:
        title = f"{summary.get('case') or 'flexrock'}: {summary.get('status', '')}"
    if title:
        fig.suptitle(title)
    return fig


def moment_rotation_loop(
    source, events=None, summary=None, *, tlim=None, figsize=(6, 5), ax=None, fig: Optional[Figure] = None
):
    """The base moment against theta: the rocking hysteresis loop.

    The base moment [N m] is the moment of the floor reaction about the c.g. projection,
    ``reaction_y_N * resultant_m``. While the body rocks on edge 1 (theta > 0) the reaction acts
    at the pivot x = -b1, so the moment is about -M g b1; on edge 2 about +M g b2. With a summary
    both are dashed (``gid`` "uplift_moment_edge1" and "uplift_moment_edge2").

    Parameters
    ----------
    source, events, summary
        As for :func:`response_figure`.
    tlim : (float, float), optional
        Only the rows in this time window [s].
    figsize : (float, float)
        [in], for a new figure.
    ax : matplotlib.axes.Axes, optional
        Where to draw; otherwise a new Axes on ``fig`` or on a new pyplot figure.
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.axes.Axes
    """
    cols, events, summary = _run_data(source, events, summary)
    theta = np.asarray(cols["theta_rad"], dtype=float)
    moment = np.asarray(cols["reaction_y_N"], dtype=float) * np.asarray(cols["resultant_m"], dtype=float)
    if tlim is not None:
        t = np.asarray(cols["time_s"], dtype=float)
        keep = (t >= tlim[0]) & (t <= tlim[1])
        if not np.any(keep):
            raise ValueError(f"no rows between {tlim[0]:g} s and {tlim[1]:g} s")
        theta, moment = theta[keep], moment[keep]
    ax = _axes(ax, fig, figsize)
    ax.plot(theta, moment, lw=0.7, color="k", label="base moment", gid="loop")
    if summary:
        b = summary.get("body", {})
        g = b.get("uplift_acceleration_edge1_m_per_s2", 0.0) / max(b.get("alpha1") or 1.0, 1e-300)
        m_kg = b.get("mass_kg")
        if m_kg and b.get("b1_m") is not None:
            # the pivot of edge 1 is left of the c.g.: a negative moment, and edge 2 positive
            ax.axhline(-m_kg * g * b["b1_m"], color="tab:orange", ls="--", lw=0.7,
                       label="$-M g b_1$ (edge 1)", gid="uplift_moment_edge1")
            ax.axhline(m_kg * g * b["b2_m"], color="tab:purple", ls="-.", lw=0.7,
                       label="$M g b_2$ (edge 2)", gid="uplift_moment_edge2")
    ax.axhline(0.0, color="0.7", lw=0.5)
    ax.axvline(0.0, color="0.7", lw=0.5)
    ax.set_xlabel("θ [rad]")
    ax.set_ylabel("base moment [N m]")
    ax.legend(loc="best", fontsize="small")
    name = ((summary or {}).get("case") or {}).get("name")
    ax.set_title(f"{name}: moment-rotation loop" if name else "moment-rotation loop")
    return ax


# --- the overturning spectrum ------------------------------------------------------------------

# outcome classes of a spectrum CSV (docs/studies.md) -> colour; the two overturning modes differ
_OUTCOME_COLOURS = {
    "no_uplift": "#e8e8e8",
    "rocking": "#9ecae1",
    "overturned_without_impact": "#d62728",  # mode 2: on the first uplift
    "overturned_after_impacts": "#ff9f4a",  # mode 1: after one or more impacts
    "stopped": "#7f7f7f",
}


def read_spectrum(path: str) -> dict:
    """The columns of a spectrum CSV.

    Parameters
    ----------
    path : str
        A cells CSV of ``flexrock spectrum``.

    Returns
    -------
    dict of str to numpy.ndarray
        Numbers as float arrays, text as object arrays; a file that is not a spectrum, or a
        header without rows, is a ValueError.
    """
    cols = _read_columns(path, require_rows=True)
    if "outcome" not in cols or "a_p_over_g_tan_alpha" not in cols:
        raise ValueError(
            f"{path}: not a spectrum CSV: expected the columns of `flexrock spectrum` "
            "(row, column, a_p_m_per_s2, a_p_over_g_tan_alpha, ..., outcome), got "
            + ", ".join(cols)
        )
    return cols


def _boundary_next_to(path: str):
    # `flexrock spectrum` writes "x.spectrum.csv" (or "x.csv") and "x.boundary.csv"
    stem = path[:-4] if path.endswith(".csv") else path
    stem = stem[: -len(".spectrum")] if stem.endswith(".spectrum") else stem
    for candidate in (stem + ".boundary.csv",):
        if os.path.exists(candidate):
            return _read_columns(candidate)
    return None


def _spectrum_data(source, boundary, g):
    # (cells, boundary, units) from a CSV path, a dict of columns or a flexrock.SpectrumResult;
    # units: (amplitude, frequency) the spectrum was asked for in, None for the normalised axes
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        cols = read_spectrum(path)
        if boundary is None:
            boundary = _boundary_next_to(path)
        elif isinstance(boundary, (str, os.PathLike)):
            boundary = _read_columns(os.fspath(boundary))
        return cols, boundary, _csv_units(cols)
    if hasattr(source, "cells") and hasattr(source, "boundary"):
        from .studies import boundary_table, spectrum_table

        b = boundary_table(source, g=g) if len(source.boundary) else None
        return spectrum_table(source, g=g), b, getattr(source, "_flexrock_units", None)
    return source, boundary, None


def _csv_units(cols):
    # the units a spectrum CSV's grid was given in, from its columns in them (a_p_g, f_p_hz after
    # the SI ones); None when it has none: normalised axes
    suffixes = {"g": "g", "cm_per_s2": "cm/s^2"}
    a = next((suffixes[k[4:]] for k in cols if k.startswith("a_p_") and k[4:] in suffixes), None)
    w = "Hz" if "f_p_hz" in cols else None
    if a is None and w is None:
        return None
    return (a or "m/s^2", w or "rad/s")


def _unit_column(prefix: str, unit: str) -> str:
    from .studies import unit_suffix

    return f"{prefix}_{unit_suffix(unit)}"


def spectrum_map(
    source,
    boundary=None,
    *,
    g: float = STANDARD_GRAVITY,
    figsize=(7, 5),
    title: Optional[str] = None,
    ax=None,
    fig: Optional[Figure] = None,
):
    """The overturning-spectrum map.

    One cell per grid point of the spectrum, coloured by its outcome (no uplift, rocking,
    overturning without impact = mode 2, overturning after impacts = mode 1), and the minimum
    overturning curve: the bisection's boundary (its CSV when given or found next to the
    spectrum, "<stem>.boundary.csv"), otherwise the lowest overturning cell of each column. A
    record spectrum (one record x scales) is one column against the scale factor, with the
    bisected minimum overturning scale as a line.

    Parameters
    ----------
    source : str, dict or flexrock.SpectrumResult
        A spectrum CSV, its columns, or a result of :func:`flexrock.spectrum` (axes then as the
        spectrum was asked for: a_p/(g tan alpha) and omega_p/p when normalised, otherwise the
        amplitude and frequency units given, e.g. [g] and [Hz]).
    boundary : str or dict, optional
        The minimum-overturning CSV or its columns.
    g : float
        [m/s^2] gravity of the body, for the normalised columns of a result.
    figsize : (float, float)
        [in], for a new figure.
    title : str, optional
    ax : matplotlib.axes.Axes, optional
        Where to draw; otherwise a new Axes on ``fig`` or on a new pyplot figure.
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.axes.Axes
    """
    cols, bnd, units = _spectrum_data(source, boundary, g)
    record = "omega_p_over_p" not in cols or np.all(np.asarray(cols["omega_p_over_p"], dtype=float) == 0.0)
    if record:
        xk, yk = None, "scale"
        x = np.zeros(len(cols[yk]))
        xlabel, ylabel = "record", "scale factor [-]"
    elif units is not None:
        xk, yk = _unit_column("f_p" if units[1] == "Hz" else "omega_p", units[1]), _unit_column("a_p", units[0])
        x = np.asarray(cols[xk], dtype=float)
        xlabel = f"pulse frequency [{units[1]}]"
        ylabel = f"pulse amplitude [{units[0]}]"
    else:
        xk, yk = "omega_p_over_p", "a_p_over_g_tan_alpha"
        x = np.asarray(cols[xk], dtype=float)
        xlabel, ylabel = "$\\omega_p / p$", "$a_p / (g \\tan\\alpha)$"
    y = np.asarray(cols[yk], dtype=float)
    outcome = np.array([str(o) for o in cols["outcome"]], dtype=object)
    xs, ys = np.unique(x), np.unique(y)
    present = set(outcome)
    kinds = [k for k in _OUTCOME_COLOURS if k in present] + sorted(present - set(_OUTCOME_COLOURS))
    index = {k: i for i, k in enumerate(kinds)}
    grid = np.full((len(ys), len(xs)), np.nan)
    grid[np.searchsorted(ys, y), np.searchsorted(xs, x)] = [index[o] for o in outcome]

    from matplotlib.colors import BoundaryNorm, ListedColormap

    colours = [_OUTCOME_COLOURS.get(k, "C%d" % i) for i, k in enumerate(kinds)]
    ax = _axes(ax, fig, figsize)

    def edges(v):
        if len(v) == 1:
            return np.array([v[0] - 0.5, v[0] + 0.5]) if v[0] == 0 else np.array([0.9 * v[0], 1.1 * v[0]])
        mid = 0.5 * (v[1:] + v[:-1])
        return np.concatenate([[2 * v[0] - mid[0]], mid, [2 * v[-1] - mid[-1]]])

    ax.pcolormesh(
        edges(xs),
        edges(ys),
        np.ma.masked_invalid(grid),
        cmap=ListedColormap(colours),
        norm=BoundaryNorm(np.arange(len(kinds) + 1) - 0.5, len(kinds)),
        shading="flat",
        gid="outcome_cells",
    )
    # minimum overturning curve: the bisected values where there are some
    cx, cy = [], []
    if bnd is not None and "kind" in bnd:
        if record:
            bx, by = np.zeros(len(bnd["kind"])), bnd["min_overturning"]
        elif units is not None:
            bx = bnd[_unit_column("f_p" if units[1] == "Hz" else "omega_p", units[1])]
            by = bnd[_unit_column("min_overturning", units[0])]
        else:
            bx, by = bnd["omega_p_over_p"], bnd["min_overturning_over_g_tan_alpha"]
        for xv, kind, v in zip(bx, bnd["kind"], by):
            if str(kind) != "none" and np.isfinite(float(v)):
                cx.append(float(xv))
                cy.append(float(v))
    else:
        for j, xv in enumerate(xs):
            over = [ys[i] for i in range(len(ys)) if not np.isnan(grid[i, j]) and kinds[int(grid[i, j])].startswith("overturned")]
            if over:
                cx.append(xv)
                cy.append(min(over))
    handles = [Patch(color=c, label=k.replace("_", " ")) for k, c in zip(kinds, colours)]
    if cx and not record:
        ax.plot(cx, cy, color="k", lw=1.6, marker=".", label="minimum overturning", gid="min_overturning")
        handles.append(Line2D([], [], color="k", lw=1.6, marker=".", label="minimum overturning"))
    elif cy:
        ax.axhline(cy[0], color="k", lw=1.6, label="minimum overturning", gid="min_overturning")
        handles.append(Line2D([], [], color="k", lw=1.6, label=f"minimum overturning ({cy[0]:.4g})"))
    ax.legend(handles=handles, loc="upper left", fontsize="small", framealpha=0.9)
    if record:
        ax.set_xticks([])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title or "overturning spectrum")
    return ax


# --- fragility ---------------------------------------------------------------------------------

_IM_TITLES = {
    "pga": ("PGA", "m/s^2"),
    "pga_g": ("PGA", "g"),
    "pgv": ("PGV", "m/s"),
    "scale": ("scale factor", "-"),
    "requested_level": ("requested level", ""),
}


def _pretty_unit(unit: str) -> str:
    return unit.replace("^2", "²")


def _im_title(im: str):
    # the measure's title ("PGA", "Sa(1 s, 5 %)") and own unit: the fixed names, sa:T[:zeta], then
    # the library's table of intensity measures
    if im in _IM_TITLES:
        return _IM_TITLES[im]
    if im.startswith("rotd50:"):  # a worst-azimuth fit: the measure's median over azimuths
        title, unit = _im_title(im[len("rotd50:"):])
        return f"RotD50 {title}", unit
    if im.startswith("sa:"):
        parts = im.split(":")
        zeta = float(parts[2]) if len(parts) > 2 else 0.05
        return f"Sa({parts[1]} s, {100 * zeta:g} %)", "m/s^2"
    from . import _flexrock

    for m in _flexrock.intensity_measures():
        if m["name"] == im:
            return im, m["unit"]
    return im, ""


def _im_label(im: Optional[str], unit: Optional[str] = None) -> str:
    # the axis label: the measure's title and the unit a file records (else the measure's own)
    if im is None:
        return "intensity measure (not recorded in the file)"
    title, own = _im_title(im)
    unit = own if unit is None else unit
    return f"{title} [{_pretty_unit(unit)}]" if unit else title


def _recorded_im(path, cols, im):
    # the measure a fit or curve CSV records (im_name, im_unit); an --im that disagrees is refused
    if "im_name" not in cols:
        return (im, None) if im is not None else (None, None)
    names = list(dict.fromkeys(str(v) for v in cols["im_name"]))
    units = list(dict.fromkeys(str(v) for v in cols["im_unit"])) if "im_unit" in cols else [None]
    if len(names) != 1 or len(units) != 1:
        raise ValueError(f"{path}: more than one intensity measure in the file: {', '.join(names)}")
    if im is not None and im != names[0]:
        raise ValueError(
            f"{path}: the file holds a fit against {names[0]} [{units[0]}], not {im}: "
            "leave --im out (a fit or curve CSV records its intensity measure)"
        )
    return names[0], units[0]


def _observed(im, failed, groups=None):
    # (level, fraction, count): the observed failure fraction at each level; rows of one level
    # share a group key (the sweep's requested level) or, without one, an IM value to 12 digits
    im = np.asarray(im, dtype=float)
    failed = np.asarray(failed, dtype=float)
    keys = np.asarray(groups if groups is not None else [float(f"{v:.12g}") for v in im])
    out = []
    for k in np.unique(keys):
        sel = keys == k
        out.append((float(np.mean(im[sel])), float(np.mean(failed[sel])), int(np.count_nonzero(sel))))
    out.sort()
    return np.array([o[0] for o in out]), np.array([o[1] for o in out]), np.array([o[2] for o in out])


def _fragility_sources(source, im, body, state=None):
    # ([(label, fit or None, im values, failed flags, group keys, curve or None, theta, beta)],
    #  (measure name, unit)): the unit None when the measure's own
    items, measure = _fragility_items(source, im, body, state)
    if not items and (body or state):
        what = " and ".join(f"{k} {v!r}" for k, v in (("body", body), ("state", state)) if v)
        where = f"{os.fspath(source)}: " if isinstance(source, (str, os.PathLike)) else ""
        raise ValueError(f"{where}no fragility of {what} to draw")
    return items, measure


def _fragility_items(source, im, body, state):
    from . import studies

    items = []
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        cols = _read_columns(path, require_rows=True)
        # a family of damage states (flexrock fragility --state): one curve per body and state
        keys = [str(v) for v in cols["body"]] if "body" in cols else []
        states = [str(v) for v in cols["state"]] if "state" in cols else []
        if states:
            keys = [f"{bv}: {sv}" for bv, sv in zip(keys, states)]
        bodies = [str(v) for v in cols["body"]] if "body" in cols else []
        fitted = {"probability", "lower", "upper", "im"} <= set(cols) or {"theta", "beta", "samples"} <= set(cols)
        if fitted and state and not states:
            raise ValueError(f"{path}: a fit of one damage state (no state column): leave --state out")

        def wanted(k):
            return (not body or bodies[k] == body) and (not state or states[k] == state)

        if {"probability", "lower", "upper", "im"} <= set(cols):  # flexrock fragility --curve
            for key in dict.fromkeys(keys):
                sel = np.array([k == key for k in keys])
                if not wanted(int(np.argmax(sel))):
                    continue
                curve = (cols["im"][sel], cols["probability"][sel], cols["lower"][sel], cols["upper"][sel])
                items.append((key, None, None, None, None, curve, None, None))
            return items, _recorded_im(path, cols, im)
        if {"theta", "beta", "samples"} <= set(cols):  # flexrock fragility -o
            for k, key in enumerate(keys):
                if wanted(k):
                    items.append((key, None, None, None, None, None, float(cols["theta"][k]), float(cols["beta"][k])))
            return items, _recorded_im(path, cols, im)
        if "overturned" not in cols:
            raise ValueError(
                f"{path}: not a sweep CSV nor a fragility output: expected the columns of "
                "`flexrock sweep` or `flexrock fragility` (-o or --curve), got " + ", ".join(cols)
            )
        measure = (im or "pga_g", None)
        if state:
            # one damage state, as flexrock fragility --state names it ("theta:0.5")
            st = studies.damage_state(state)
            pairs = studies.fragility_from_sweep(path, im=im or "pga_g", outcome=st.outcome.name, level=st.level,
                                                 body=body or "")
        else:
            pairs = studies.fragility_from_sweep(path, im=im or "pga_g", body=body or "")
        for data, fit in pairs:
            measure = (data.im_name, data.im_unit)
            groups = None
            if "requested_level" in cols:
                sel = np.array([str(v) == data.body for v in cols["body"]])
                keep = np.array([str(o) not in ("stopped", "contact_lost") for o in cols["outcome"]])
                groups = np.asarray(cols["requested_level"])[sel & keep]
                if len(groups) != len(data.im):
                    groups = None
            items.append((data.body, fit, np.asarray(data.im), np.asarray(data.failed), groups, None, fit.theta, fit.beta))
        return items, measure
    if hasattr(source, "theta") and hasattr(source, "beta"):  # a FragilityFit
        return [("", source, None, None, None, None, source.theta, source.beta)], (im or "pga_g", None)
    if isinstance(source, tuple) and len(source) == 2 and hasattr(source[1], "theta"):
        source = [source]
    measure = (im or "pga_g", None)
    for data, fit in source:  # what fragility_from_sweep returns
        items.append((data.body, fit, np.asarray(data.im), np.asarray(data.failed), None, None, fit.theta, fit.beta))
        if getattr(data, "im_name", ""):
            measure = _recorded_im("the fragility data", {"im_name": [data.im_name], "im_unit": [data.im_unit]}, im)
    return items, measure


def fragility_curve(
    source,
    im_values=None,
    failed=None,
    *,
    im: Optional[str] = None,
    body: str = "",
    state: Optional[str] = None,
    band: bool = True,
    xlabel: Optional[str] = None,
    figsize=(6, 4.5),
    ax=None,
    fig: Optional[Figure] = None,
):
    """A lognormal fragility curve with its confidence band and the observed fractions.

    Draws, for each body, the fitted P(failure | IM = x) = Phi(ln(x/theta)/beta) (``gid``
    "fit"), its pointwise confidence band (``gid`` "band", the delta method of
    :func:`flexrock.fragility_band`) and the observed fraction of failures at each level of the
    sweep (``gid`` "observed", marker area growing with the number of runs).

    Parameters
    ----------
    source : str, FragilityFit or list of (FragilityData, FragilityFit)
        A sweep CSV (fitted as ``flexrock fragility`` fits it; levels grouped by its
        ``requested_level`` column), the fit CSV (``flexrock fragility -o``: the curve only) or
        the curve CSV (``--curve``: curve and band) of ``flexrock fragility``, what
        :func:`flexrock.fragility_from_sweep` returns, or one fit.
    im_values, failed : array_like, optional
        With a bare fit: the observations to draw (IM in the fit's units, 0/1 failures).
    im : str, optional
        The intensity measure of a sweep CSV (default "pga_g"): "pga" [m/s^2], "pga_g" [g],
        "pgv" [m/s], "scale" [-], "requested_level" (the manifest's levels), "sa:T", ... A fit
        or curve CSV, and what :func:`flexrock.fragility_from_sweep` returns, record their
        measure and unit, which label the axis; an `im` that disagrees with them is refused.
    body : str
        Only this body of a sweep or fragility CSV.
    state : str, optional
        Only this damage state ("overturned", "theta:0.5", ...): of a fit or curve CSV of
        ``flexrock fragility --state``, or the state a sweep CSV is fitted for (default:
        overturning). Bodies that cannot be fitted are left out with a FragilityWarning.
    band : bool
        Draw the confidence band.
    xlabel : str, optional
        Default: the IM and its unit, as the source records them.
    figsize : (float, float)
        [in], for a new figure.
    ax : matplotlib.axes.Axes, optional
        Where to draw; otherwise a new Axes on ``fig`` or on a new pyplot figure.
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.axes.Axes
    """
    from . import studies

    items, (im_name, im_unit) = _fragility_sources(source, im, body, state)
    if not items:
        raise ValueError(f"no fragility to draw{' for body ' + repr(body) if body else ''}")
    ax = _axes(ax, fig, figsize)
    for k, (label, fit, xs, ys, groups, curve, theta, beta) in enumerate(items):
        colour = f"C{k}"
        if xs is None and im_values is not None:
            xs, ys = np.asarray(im_values, dtype=float), np.asarray(failed, dtype=float)
        if curve is not None:
            x, p, lo, hi = (np.asarray(c, dtype=float) for c in curve)
        else:
            top = max(theta * math.exp(3.0 * beta), float(np.max(xs)) if xs is not None and len(xs) else 0.0)
            x = np.linspace(0.0, top, 200)[1:]
            if fit is not None:
                p = studies.fragility_probability(fit, x)
            else:  # a fit CSV: theta and beta only
                from statistics import NormalDist

                nd = NormalDist()
                p = np.array([nd.cdf(math.log(v / theta) / beta) for v in x])
            lo = hi = None
            if fit is not None and band:
                lo, hi = studies.fragility_band(fit, x)
        name = f"{label}: " if label and len(items) > 1 else ""
        unit = "" if im_name is None else im_unit if im_unit is not None else _im_title(im_name)[1]
        theta_unit = f" {_pretty_unit(unit)}" if unit and unit != "-" else ""
        ax.plot(x, p, color=colour, lw=1.5, gid="fit",
                label=f"{name}fit, θ = {theta:.3g}{theta_unit}, β = {beta:.3g}" if theta is not None else f"{name}fit")
        if band and lo is not None:
            conf = getattr(fit, "confidence", None)
            ax.fill_between(x, lo, hi, color=colour, alpha=0.2, lw=0, gid="band",
                            label=f"{name}{100 * conf:.0f}% band" if conf else f"{name}band")
        if xs is not None and len(xs):
            lx, frac, n = _observed(xs, ys, groups)
            ax.scatter(lx, frac, s=12 + 60 * n / max(n.max(), 1), color=colour, edgecolor="k", lw=0.5,
                       zorder=3, gid="observed", label=f"{name}observed fraction")
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlim(left=0.0)
    ax.set_xlabel(xlabel or _im_label(im_name, im_unit))
    ax.set_ylabel("probability of failure [-]")
    ax.legend(loc="lower right", fontsize="small")
    ax.set_title("fragility")
    return ax


# --- files -------------------------------------------------------------------------------------

_FORMATS = (".png", ".svg", ".pdf")


# --- incremental dynamic analysis ---------------------------------------------------------------

# response measures of a sweep CSV an IDA curve can show: column -> axis label
_IDA_MEASURES = {
    "max_theta_over_alpha": "largest tilt θ/α [-]",
    "max_theta_rad": "largest tilt θ [rad]",
    "max_uplift_m": "largest uplift [m]",
    "max_impulse_N_s": "largest impulse [N s]",
    "max_friction_demand": "largest friction demand [-]",
    "energy_lost_J": "energy lost [J]",
}


def _ida_im_values(path, cols, rows, body, im):
    # the intensity measure of the given rows: a column of the sweep, else as flexrock fragility
    # --im computes it (sa:T, the library's measures), in the rows' order
    if im in cols:
        return np.asarray(cols[im], dtype=float)[rows], (im, None)
    from . import studies

    data = studies.fragility_session(path, im, "overturned", 0.0, body).data(0, 0)
    kept = [r for r in rows if str(cols["outcome"][r]) not in ("stopped", "contact_lost")]
    values = np.full(len(rows), np.nan)
    if len(kept) != len(data.im):
        raise ValueError(f"{path}: cannot align the intensity measure {im} with the rows of {body}")
    where = {r: k for k, r in enumerate(kept)}
    for j, r in enumerate(rows):
        if r in where:
            values[j] = data.im[where[r]]
    return values, (data.im_name or im, data.im_unit or None)


def ida_curves(
    source,
    *,
    im: str = "pga_g",
    measure: str = "max_theta_over_alpha",
    body: str = "",
    figsize=(6, 4.5),
    ax=None,
    fig: Optional[Figure] = None,
):
    """Incremental dynamic analysis: one curve per record of a sweep, the response measure
    against the intensity measure, with where each record overturns the body.

    Each record's runs are joined in the order of the intensity measure (``gid`` "ida:RECORD");
    runs that overturn are red crosses (``gid`` "overturned:RECORD") in a column at the right
    edge, 10 % beyond the largest response of a run that stands (or theta/alpha = 1, the static
    tipping tilt, if larger): an overturned body's response is its fall, which would crush the
    scale of the others. The lowest intensity that overturns the body under that record is a dotted level
    (``gid`` "margin:RECORD"): the record's overturning margin. The title gives the median of
    those levels over the records that overturn it, and how many do not within the sweep. Runs
    whose outcome is ``stopped`` or ``contact_lost`` are left out.

    Parameters
    ----------
    source : str or os.PathLike
        A sweep CSV of ``flexrock sweep``.
    im : str
        A column of the sweep (``pga_g``, ``pga_m_per_s2``, ``pgv_m_per_s``, ``scale``,
        ``requested_level``) or any measure ``flexrock fragility --im`` takes (``sa:1.0``, ...).
    measure : str
        The response: one of ``max_theta_over_alpha``, ``max_theta_rad``, ``max_uplift_m``,
        ``max_impulse_N_s``, ``max_friction_demand``, ``energy_lost_J``.
    body : str
        The sweep's body to draw (default: the only one; a sweep of several needs it).
    figsize, ax, fig
        As for :func:`moment_rotation_loop`.

    Returns
    -------
    matplotlib.axes.Axes
    """
    path = os.fspath(source)
    cols = _read_columns(path, require_rows=True)
    for need in ("body", "record", "overturned", "outcome"):
        if need not in cols:
            raise ValueError(f"{path}: not a sweep CSV (no column {need})")
    if measure not in _IDA_MEASURES:
        raise ValueError(f"unknown response measure {measure!r}: expected one of {', '.join(_IDA_MEASURES)}")
    bodies = list(dict.fromkeys(str(b) for b in cols["body"]))
    if not body:
        if len(bodies) > 1:
            raise ValueError(f"{path}: a sweep of {len(bodies)} bodies ({', '.join(bodies)}): choose one (body=, or --body of flexrock plot)")
        body = bodies[0]
    elif body not in bodies:
        raise ValueError(f"{path}: no body {body!r} in the sweep (it has {', '.join(bodies)})")
    rows = [k for k, b in enumerate(cols["body"]) if str(b) == body]
    ims, (im_name, im_unit) = _ida_im_values(path, cols, rows, body, im)
    response = np.asarray(cols[measure], dtype=float)[rows]
    over = np.asarray(cols["overturned"], dtype=float)[rows] != 0
    valid = np.array([str(cols["outcome"][r]) not in ("stopped", "contact_lost") for r in rows])
    records = [str(cols["record"][r]) for r in rows]

    ax = _axes(ax, fig, figsize)
    standing_max = response[valid & ~over & np.isfinite(response)]
    edge = max(float(np.max(standing_max)) if standing_max.size else 0.0,
               1.0 if measure == "max_theta_over_alpha" else 0.0)
    edge = 1.1 * edge if edge > 0.0 else 1.0
    margins = []
    for j, rec in enumerate(dict.fromkeys(records)):
        sel = np.array([r == rec for r in records]) & valid & np.isfinite(ims)
        order = np.argsort(ims[sel], kind="stable")
        x, y, o = response[sel][order], ims[sel][order], over[sel][order]
        colour = f"C{j % 10}"
        standing = ~o
        ax.plot(x[standing], y[standing], "o-", ms=3, lw=1.0, color=colour, label=rec, gid=f"ida:{rec}")
        if np.any(o):
            ax.plot(np.full(np.count_nonzero(o), edge), y[o], "x", ms=6, color="tab:red", gid=f"overturned:{rec}")
            level = float(np.min(y[o]))
            margins.append(level)
            ax.axhline(level, color=colour, ls=":", lw=0.8, gid=f"margin:{rec}")
    if margins:
        ax.plot([], [], "x", color="tab:red", label="overturned")
        ax.axvline(edge, color="0.8", lw=0.6)
    ax.set_xlabel(_IDA_MEASURES[measure])
    ax.set_ylabel(_im_label(im_name, im_unit))
    n_records = len(dict.fromkeys(records))
    if margins:
        unit = im_unit if im_unit is not None else _im_title(im_name)[1]
        what = f"overturns from median {np.median(margins):.3g} {_pretty_unit(unit)} ({len(margins)} of {n_records} records)"
    else:
        what = f"no overturning in the sweep ({n_records} records)"
    ax.set_title(f"{body}: IDA, {what}", fontsize="medium")
    ax.legend(loc="lower right", fontsize="small")
    return ax


# --- elastic response spectra -------------------------------------------------------------------


def response_spectrum(spectrum: dict, *, logx: bool = True, figsize=(6, 4.5), ax=None, fig: Optional[Figure] = None):
    """An elastic response spectrum: pseudo-spectral acceleration against period.

    Parameters
    ----------
    spectrum : dict
        What :func:`flexrock.response_spectrum` returns: ``period_s`` and ``sa`` (``gid`` "sa"),
        for a pair also ``sa_h2``, ``rotd50`` and ``rotd100`` (``gid`` the same names).
    logx : bool
        A logarithmic period axis (default).
    figsize, ax, fig
        As for :func:`moment_rotation_loop`.

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = _axes(ax, fig, figsize)
    t = np.asarray(spectrum["period_s"], dtype=float)
    pair = "rotd50" in spectrum
    styles = (
        ("sa", "H1" if pair else "Sa", dict(lw=0.9, color="tab:blue")),
        ("sa_h2", "H2", dict(lw=0.9, color="tab:orange")),
        ("rotd50", "RotD50", dict(lw=1.6, color="k")),
        ("rotd100", "RotD100", dict(lw=1.2, color="k", ls="--")),
    )
    for key, label, style in styles:
        if key in spectrum:
            ax.plot(t, np.asarray(spectrum[key], dtype=float), label=label, gid=key, **style)
    if logx:
        ax.set_xscale("log")
    unit = spectrum.get("units", "m/s^2")
    zeta = spectrum.get("zeta", 0.05)
    ax.set_xlabel("period [s]")
    ax.set_ylabel(f"Sa [{_pretty_unit(unit)}]")
    ax.set_title(f"elastic response spectrum, {100 * zeta:g} % damping", fontsize="medium")
    ax.grid(True, which="both", alpha=0.3)
    if pair:
        ax.legend(loc="upper right", fontsize="small")
    return ax


def save(fig, path: str, *, dpi: int = 110) -> str:
    """Writes a figure as PNG, SVG or PDF, chosen by the extension of ``path``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure or matplotlib.axes.Axes
        What a plotting function returned (an Axes is saved with its figure).
    path : str or os.PathLike
        Ends in .png, .svg or .pdf.
    dpi : int
        [dots per inch] of a PNG.

    Returns
    -------
    str
        ``path``.
    """
    ext = os.path.splitext(os.fspath(path))[1].lower()
    if ext not in _FORMATS:
        raise ValueError(f"{path}: expected a .png, .svg or .pdf file name, got {ext or 'no extension'!r}")
    figure = fig if isinstance(fig, Figure) else fig.get_figure()
    figure.savefig(os.fspath(path), dpi=dpi, format=ext[1:])
    return os.fspath(path)
