# SPDX-License-Identifier: BSD-3-Clause
"""A spectrum's cells and boundaries as numpy arrays typed by their column tables (int64, float64,
str), read from the result itself, holding the values of the CSVs flexrock spectrum writes."""

import csv
import io

import numpy as np
import pytest

import flexrock as fr
from flexrock import _csv


@pytest.fixture(scope="module")
def result():
    block = fr.Body(fr.rigid_block(0.5, 3.0, 1000.0))
    return block, fr.spectrum(block, [1.5, 4.0, 8.0], [1.5, 4.0], threads=2,
                              bisection_tolerance=0.05)


def _same(typed: dict, text: str):
    parsed = _csv.columns(list(csv.reader(io.StringIO(text))), "csv")
    assert list(typed) == list(parsed)
    for name, v in typed.items():
        if v.dtype == object:
            assert list(v) == list(parsed[name]), name
        else:
            # a column the CSV leaves empty throughout reads back as text
            p = parsed[name]
            p = np.full(len(v), np.nan) if p.dtype == object else p
            np.testing.assert_array_equal(v.astype(float), p, err_msg=name)


def test_spectrum_table_is_typed_and_holds_the_csv_values(result):
    block, r = result
    t = fr.spectrum_table(r, block.g)
    assert t["row"].dtype == np.int64 and t["overturned"].dtype == np.int64
    assert t["a_p_m_per_s2"].dtype == np.float64 and t["outcome"].dtype == object
    # a pulse spectrum has no scale factor: nan, not an empty text
    assert t["scale"].dtype == np.float64 and np.isnan(t["scale"]).all()
    _same(t, fr.spectrum_csv(r, block.g))


def test_boundary_table_is_typed_and_holds_the_csv_values(result):
    block, r = result
    b = fr.boundary_table(r, block.g)
    assert b["column"].dtype == np.int64 and b["bisection_runs"].dtype == np.int64
    assert b["kind"].dtype == object and b["min_overturning"].dtype == np.float64
    _same(b, fr._flexrock.boundary_csv(r, True, block.g))
