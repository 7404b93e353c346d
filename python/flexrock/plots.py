# SPDX-License-Identifier: BSD-3-Clause
"""Figures of flexrock results (matplotlib), as PNG or SVG.

Every function returns a :class:`matplotlib.figure.Figure` built without pyplot, so it needs no
display and is safe in threads; :func:`save` writes it by extension. In Jupyter a returned figure
shows inline. Inputs are a :class:`flexrock.Result`, a time-history CSV written by
``flexrock run`` (its summary JSON and event log are found next to it) or, for
:func:`spectrum_map`, the CSV ``flexrock spectrum`` writes.
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
    "spectrum_map",
    "read_spectrum",
    "save",
]

# rocking on edge 1 / edge 2: the same colours in every figure
_EDGE_COLOURS = {1: "tab:orange", 2: "tab:purple"}


# --- inputs ------------------------------------------------------------------------------------


def _read_columns(path: str) -> dict:
    with open(path, newline="") as f:
        return _columns(list(csv.reader(f)), path)


def load_run(path: str):
    """A run's outputs from its time-history CSV: (columns, events, summary). The summary JSON
    "<stem>.summary.json" and the event log (the summary's outputs.events, or
    "<stem>.events.csv") are read when they lie next to the CSV; otherwise they are None."""
    cols = _read_columns(path)
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


def _event_times(events, kind: str) -> np.ndarray:
    if events is None or "event" not in events:
        return np.array([])
    mask = np.array([e == kind for e in events["event"]], dtype=bool)
    return np.asarray(events["time_s"], dtype=float)[mask]


# --- the response figure -----------------------------------------------------------------------


def response_figure(
    source, events=None, summary=None, *, title: Optional[str] = None, xlim=None, figsize=(9, 11)
) -> Figure:
    """Six panels against time: base accelerations; theta with the rocking phases shaded (edge 1
    and edge 2 in two colours), impacts marked and the overturning angles dashed (theta/alpha on
    the right axis); deformation q; floor reactions; friction demand; energy budget
    (input work = stored + dissipated + residual). ``xlim=(t0, t1)`` shows a time window."""
    cols, events, summary = _run_data(source, events, summary)
    t = np.asarray(cols["time_s"], dtype=float)
    fig = Figure(figsize=figsize, layout="constrained")
    axes = fig.subplots(6, 1, sharex=True)
    ax_acc, ax_th, ax_q, ax_r, ax_f, ax_e = axes

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
    if impacts.size == 0 and events is None:
        # no event log: impacts where the pivot changes between the edges
        switch = (phase[1:] != phase[:-1]) & (phase[1:] > 0) & (phase[:-1] > 0)
        impacts = t[1:][switch]
    if impacts.size:
        ax_th.plot(impacts, np.zeros_like(impacts), "x", color="tab:red", ms=5, label="impact", gid="impacts")
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
    qs = sorted((k for k in cols if k.startswith("q") and k[1:].isdigit()), key=lambda k: int(k[1:]))
    for k in qs:
        ax_q.plot(t, cols[k], lw=0.8, label=k)
    if qs:
        ax_q.legend(loc="upper right", fontsize="small")
    else:
        ax_q.text(0.5, 0.5, "rigid body: no deformation modes", transform=ax_q.transAxes, ha="center", va="center", color="0.4")
    ax_q.set_ylabel("q [-]")

    # reactions and friction demand
    ax_r.plot(t, cols["reaction_x_N"], lw=0.8, label="$F_I$ (shear)")
    ax_r.plot(t, cols["reaction_y_N"], lw=0.8, label="$F_J$ (normal)")
    ax_r.set_ylabel("reaction [N]")
    ax_r.legend(loc="upper right", fontsize="small")
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
    ax_e.plot(t, w - stored - lost, lw=0.8, color="0.5", ls=":", label="residual")
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


def moment_rotation_loop(source, events=None, summary=None, *, figsize=(6, 5)) -> Figure:
    """The base moment (moment of the floor reaction about the c.g. projection,
    reaction_y x resultant [N m]) against theta [rad]: the rocking hysteresis loop. With a
    summary, the static uplift moments M g b1 and -M g b2 are dashed."""
    cols, events, summary = _run_data(source, events, summary)
    theta = np.asarray(cols["theta_rad"], dtype=float)
    moment = np.asarray(cols["reaction_y_N"], dtype=float) * np.asarray(cols["resultant_m"], dtype=float)
    fig = Figure(figsize=figsize, layout="constrained")
    ax = fig.subplots()
    ax.plot(theta, moment, lw=0.7, color="k", label="base moment")
    if summary:
        b = summary.get("body", {})
        g = b.get("uplift_acceleration_edge1_m_per_s2", 0.0) / max(b.get("alpha1") or 1.0, 1e-300)
        m_kg = b.get("mass_kg")
        if m_kg and b.get("b1_m") is not None:
            ax.axhline(m_kg * g * b["b1_m"], color="tab:red", ls="--", lw=0.7, label="$M g b_1$")
            ax.axhline(-m_kg * g * b["b2_m"], color="tab:red", ls="-.", lw=0.7, label="$-M g b_2$")
    ax.axhline(0.0, color="0.7", lw=0.5)
    ax.axvline(0.0, color="0.7", lw=0.5)
    ax.set_xlabel("θ [rad]")
    ax.set_ylabel("base moment [N m]")
    ax.legend(loc="best", fontsize="small")
    name = ((summary or {}).get("case") or {}).get("name")
    ax.set_title(f"{name}: moment-rotation loop" if name else "moment-rotation loop")
    return fig


# --- the overturning spectrum ------------------------------------------------------------------

# outcome classes of a spectrum CSV (docs/studies.md) -> colour; the two overturning modes differ
_OUTCOME_COLOURS = {
    "no_uplift": "#e8e8e8",
    "rocking": "#9ecae1",
    "overturned_without_impact": "#d62728",  # mode 2: on the first uplift
    "overturned_after_impacts": "#ff9f4a",  # mode 1: after one or more impacts
    "contact_lost": "#8c564b",
    "stopped": "#7f7f7f",
}


def read_spectrum(path: str) -> dict:
    """The columns of a spectrum CSV as numpy arrays (text columns as object arrays)."""
    cols = _read_columns(path)
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
    # (cells, boundary) from a CSV path, a dict of columns or a flexrock.SpectrumResult
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        cols = read_spectrum(path)
        if boundary is None:
            boundary = _boundary_next_to(path)
        elif isinstance(boundary, (str, os.PathLike)):
            boundary = _read_columns(os.fspath(boundary))
        return cols, boundary
    if hasattr(source, "cells") and hasattr(source, "boundary"):
        from . import _flexrock  # the CSV text the command line writes, as columns

        def parse(text):
            return _columns(list(csv.reader(text.splitlines())), "spectrum")

        cols = parse(_flexrock.spectrum_csv(source, g))
        b = parse(_flexrock.boundary_csv(source, True, g)) if len(source.boundary) else None
        return cols, b
    return source, boundary


def spectrum_map(
    source, boundary=None, *, g: float = 9.80665, figsize=(7, 5), title: Optional[str] = None
) -> Figure:
    """The overturning-spectrum map: one cell per (omega_p/p, a_p/(g tan alpha)) point of the
    spectrum, coloured by its outcome (no uplift, rocking, overturning without impact = mode 2,
    overturning after impacts = mode 1), and the minimum overturning curve: the bisection's
    boundary CSV when given or found next to the spectrum ("<stem>.boundary.csv"), otherwise the
    lowest overturning cell of each column. A record spectrum (one record x scales) is drawn as
    one column against the scale factor. ``source`` may also be a :class:`flexrock.SpectrumResult`
    (then ``g`` is the body's gravity, for the normalised columns)."""
    cols, bnd = _spectrum_data(source, boundary, g)
    record = "omega_p_over_p" not in cols or np.all(np.asarray(cols["omega_p_over_p"], dtype=float) == 0.0)
    if record:
        xk, yk = None, "scale"
        x = np.zeros(len(cols[yk]))
    else:
        xk, yk = "omega_p_over_p", "a_p_over_g_tan_alpha"
        x = np.asarray(cols[xk], dtype=float)
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
    fig = Figure(figsize=figsize, layout="constrained")
    ax = fig.subplots()

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
    # minimum overturning curve
    cx, cy = [], []
    if bnd is not None and "kind" in bnd and not record:
        for xv, kind, v in zip(bnd["omega_p_over_p"], bnd["kind"], bnd["min_overturning_over_g_tan_alpha"]):
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
        handles.append(Line2D([], [], color="k", lw=1.6, label="minimum overturning"))
    ax.legend(handles=handles, loc="upper left", fontsize="small", framealpha=0.9)
    if record:
        ax.set_xticks([])
        ax.set_xlabel("record")
        ax.set_ylabel("scale factor [-]")
    else:
        ax.set_xlabel("$\\omega_p / p$")
        ax.set_ylabel("$a_p / (g \\tan\\alpha)$")
    ax.set_title(title or "overturning spectrum")
    return fig


# --- files -------------------------------------------------------------------------------------


def save(fig: Figure, path: str, *, dpi: int = 110) -> str:
    """Writes ``fig`` as PNG or SVG, chosen by the extension of ``path``."""
    ext = os.path.splitext(os.fspath(path))[1].lower()
    if ext not in (".png", ".svg"):
        raise ValueError(f"{path}: expected a .png or .svg file name, got {ext or 'no extension'!r}")
    fig.savefig(os.fspath(path), dpi=dpi, format=ext[1:])
    return os.fspath(path)
