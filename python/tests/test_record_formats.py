# SPDX-License-Identifier: BSD-3-Clause
"""Records as agencies publish them, from Python: the one table of formats, numpy values, the
shipped SMC pair, and two-column files with a units row."""

import numpy as np
import pytest

import flexrock as fr
from conftest import DATA


def test_the_table_of_formats_is_the_libraries():
    names = [f.name for f in fr.record_formats()]
    assert names == ["at2", "smc", "knet", "esm", "cosmos", "single_column", "time_series"]
    smc = fr.record_formats()[1]
    assert smc.suffixes == [".smc"] and not smc.needs_dt and not smc.needs_units
    assert [f.name for f in fr.record_formats() if f.needs_dt] == ["single_column"]


def test_smc_pair_by_file_name_with_numpy_values():
    r = fr.read_record(DATA / "A-CAT090.AT2.smc")
    assert isinstance(r.values, np.ndarray) and isinstance(r.time, np.ndarray)
    assert r.values.dtype == np.float64 and r.values.shape == (1646,)
    assert r.npts == 1646 and r.dt == pytest.approx(0.02, rel=1e-15)
    assert r.units == fr.AccelUnit.cm_per_s2
    assert r.values[0] == 9.5746585e-04 and r.values[-1] == 4.1989844e-02
    assert r.time[-1] == pytest.approx(32.9, abs=1e-12)
    other = fr.read_record(DATA / "A-CAT180.AT2.smc", "smc")
    assert other.values[0] == 4.1843182e-03 and other.values[-1] == 1.9560158e-02
    # to_motion in m/s^2
    m = fr.motion_from_file(DATA / "A-CAT090.AT2.smc")
    assert m.at(11.42)[0] == pytest.approx(0.41355427, abs=1e-12)


def test_given_units_must_agree_with_the_file():
    with pytest.raises(fr.InputError, match="states its values in cm/s\\^2"):
        fr.read_record(DATA / "A-CAT090.AT2.smc", units="g")


def test_time_series_with_a_units_row_needs_no_units(tmp_path):
    p = tmp_path / "r.csv"
    p.write_text("time;acceleration\ns;cm/s^2\n0,00;1,5\n0,01;-2,5\n0,02;0\n")
    r = fr.read_record(p, "time_series")
    assert r.units == fr.AccelUnit.cm_per_s2
    np.testing.assert_array_equal(r.values, [1.5, -2.5, 0.0])
    with pytest.raises(fr.InputError, match=r"q\.csv:1: .*does not state the units"):
        q = tmp_path / "q.csv"
        q.write_text("t,a\n0,1\n1,2\n")
        fr.read_record(q, "time_series")


def test_a_file_name_that_says_no_format_is_refused_listing_them(tmp_path):
    p = tmp_path / "r.txt"
    p.write_text("0.1\n0.2\n")
    with pytest.raises(fr.InputError, match="at2, smc, knet, esm, cosmos, single_column, time_series"):
        fr.read_record(p)
    assert fr.read_record(p, "single_column", dt=0.01, units="g").npts == 2
