# SPDX-License-Identifier: BSD-3-Clause
"""Elastic response spectra of records: the pseudo-spectral acceleration of a damped single-degree
oscillator over a range of periods, for one horizontal component or, for a pair, each component
and the orientation-independent RotD50 and RotD100 (Boore 2010). Each value is the library's
``intensity_measure("sa", ...)`` (and ``rotd``): the oscillator integrated exactly between the
record's samples, peak over the record and one free period after it."""

from __future__ import annotations

from typing import Optional

import numpy as np

from . import _flexrock

__all__ = ["response_spectrum"]

STANDARD_GRAVITY = 9.80665  # [m/s^2]

# the default periods: 0.01 s to 10 s, 20 a decade (61 periods), as design spectra are read
DEFAULT_PERIODS = np.geomspace(0.01, 10.0, 61)


def _samples(source, name: str):
    # (t, a [m/s^2]) of a Record, a sampled GroundMotion or a (t, a) pair of arrays in m/s^2
    if hasattr(source, "to_si") and hasattr(source, "time"):  # a Record, in its own units
        return np.asarray(source.time, dtype=float), np.asarray(source.to_si(), dtype=float)
    if hasattr(source, "is_sampled") and hasattr(source, "times"):  # a GroundMotion
        if not source.is_sampled():
            raise ValueError(f"{name}: a response spectrum needs a sampled motion (a record), not an analytic one")
        return np.asarray(source.times(), dtype=float), np.asarray(source.horizontal(), dtype=float)
    if isinstance(source, tuple) and len(source) == 2:
        return np.asarray(source[0], dtype=float), np.asarray(source[1], dtype=float)
    raise TypeError(f"{name}: expected a Record, a sampled GroundMotion or a (t, a) pair of arrays [s, m/s^2], got {type(source).__name__}")


def response_spectrum(
    record,
    periods=None,
    *,
    second=None,
    zeta: float = 0.05,
    units: str = "m/s^2",
) -> dict:
    """The elastic response spectrum of a record, or of a pair of horizontal components.

    Parameters
    ----------
    record : Record, GroundMotion or (array, array)
        The (first) horizontal component: a record read with ``read_record``, a sampled
        ``GroundMotion`` (its horizontal acceleration) or times [s] and accelerations [m/s^2].
    periods : array of float, optional
        [s] natural periods, each at least the library's smallest spectral period (default: 61
        periods from 0.01 s to 10 s, 20 a decade).
    second : same kinds as ``record``, optional
        The orthogonal horizontal component, on the same samples: then RotD50 and RotD100 too.
    zeta : float
        [-] the oscillator's damping ratio (default 0.05).
    units : {"m/s^2", "g"}
        The unit of the spectral accelerations returned.

    Returns
    -------
    dict
        ``period_s`` and ``sa`` (the first component), with ``second`` also ``sa_h2``,
        ``rotd50`` and ``rotd100`` (numpy arrays, in ``units``), and ``units``, ``zeta``.
    """
    if units not in ("m/s^2", "g"):
        raise ValueError(f"units={units!r}: expected 'm/s^2' or 'g'")
    if not (0.0 <= zeta < 1.0):
        raise ValueError(f"zeta={zeta!r}: expected a damping ratio in [0, 1)")
    t, a = _samples(record, "record")
    periods = DEFAULT_PERIODS if periods is None else np.asarray(periods, dtype=float).ravel()
    if periods.size == 0 or not np.all(np.isfinite(periods)) or np.any(periods <= 0.0):
        raise ValueError("periods: expected positive finite periods [s]")
    scale = 1.0 / STANDARD_GRAVITY if units == "g" else 1.0
    tl, al = t.tolist(), a.tolist()
    out = {
        "period_s": periods.copy(),
        "sa": np.array([_flexrock.intensity_measure("sa", tl, al, float(p), zeta) for p in periods]) * scale,
        "units": units,
        "zeta": zeta,
    }
    if second is not None:
        t2, a2 = _samples(second, "second")
        if t2.shape != t.shape or not np.array_equal(t2, t):
            raise ValueError("second: the two components must have the same samples (times)")
        a2l = a2.tolist()
        out["sa_h2"] = np.array([_flexrock.intensity_measure("sa", tl, a2l, float(p), zeta) for p in periods]) * scale
        rot = [_flexrock.rotd(tl, al, a2l, float(p), zeta) for p in periods]
        out["rotd50"] = np.array([r["rotd50"] for r in rot]) * scale
        out["rotd100"] = np.array([r["rotd100"] for r in rot]) * scale
    return out
