# SPDX-License-Identifier: BSD-3-Clause
"""CSV text written by flexrock (time histories, event logs, study tables) as numpy columns."""

import numpy as np


def columns(rows, source: str) -> dict:
    """CSV rows (header first) as columns: numbers as float arrays (an empty field, a value that
    does not apply, is nan), text as object arrays. Numbers are the shortest text that reads back
    exactly, so the arrays equal the engine's doubles."""
    if not rows:
        raise ValueError(f"{source}: empty file, expected a CSV with a header row")
    header, body = rows[0], [r for r in rows[1:] if r]
    out = {}
    for j, name in enumerate(header):
        col = [r[j] if j < len(r) else "" for r in body]
        try:
            if col and all(v == "" for v in col):
                raise ValueError("no numbers")
            out[name] = np.array([float(v) if v != "" else np.nan for v in col], dtype=float)
        except ValueError:
            out[name] = np.array(col, dtype=object)
    return out
