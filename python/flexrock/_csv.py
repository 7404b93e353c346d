# SPDX-License-Identifier: BSD-3-Clause
"""CSV text written by flexrock (time histories, event logs, study tables) as numpy columns."""

import warnings

import numpy as np


class CsvWarning(UserWarning):
    """A CSV file read for a figure or a table has rows that are not whole or not numbers."""


def columns(rows, source: str, *, require_rows: bool = False) -> dict:
    """CSV rows (header first) as columns: numbers as float arrays (an empty field, a value that
    does not apply, is nan), text as object arrays. Numbers are the shortest text that reads back
    exactly, so the arrays equal the engine's doubles.

    A row with another number of fields than the header (a truncated file) is left out with a
    :class:`CsvWarning` naming its line; ``require_rows=True`` makes a header without rows a
    ``ValueError``."""
    if not rows:
        raise ValueError(f"{source}: empty file, expected a CSV with a header row")
    header = rows[0]
    body, short = [], []
    for line, r in enumerate(rows[1:], start=2):
        if not r:
            continue
        if len(r) != len(header):
            short.append((line, len(r)))
        else:
            body.append(r)
    if short:
        line, n = short[0]
        warnings.warn(
            f"{source}:{line}: {n} fields, expected {len(header)} (as the header): "
            f"{len(short)} such row(s) left out (a truncated file?)",
            CsvWarning,
            stacklevel=3,
        )
    if require_rows and not body:
        raise ValueError(f"{source}: no data rows, only the header ({', '.join(header)})")
    out = {}
    for j, name in enumerate(header):
        col = [r[j] for r in body]
        try:
            if col and all(v == "" for v in col):
                raise ValueError("no numbers")
            out[name] = np.array([float(v) if v != "" else np.nan for v in col], dtype=float)
        except ValueError:
            out[name] = np.array(col, dtype=object)
    return out


def warn_nan(cols: dict, names, source: str) -> None:
    """A :class:`CsvWarning` for rows whose ``names`` columns hold nan (drawn as gaps)."""
    for name in names:
        v = cols.get(name)
        if v is None or v.dtype == object:
            continue
        bad = np.flatnonzero(np.isnan(v))
        if bad.size:
            warnings.warn(
                f"{source}: column {name}: {bad.size} row(s) are nan (the first is data row "
                f"{bad[0] + 1}): drawn as gaps",
                CsvWarning,
                stacklevel=3,
            )
