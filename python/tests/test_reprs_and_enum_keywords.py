# SPDX-License-Identifier: BSD-3-Clause
"""No raw binding errors from the keywords of simulate(): every enum-valued option (found from
the bound options' own table of fields) takes a member or its name, and anything else raises
InputError (a ValueError) naming the allowed names; a value of the wrong type names its key.
The value types print their fields."""

import subprocess

import pytest

import flexrock as fr


def _enum_options():
    o = fr.SimulationOptions()
    return {n: type(getattr(o, n)) for n in dir(o)
            if not n.startswith("_") and hasattr(type(getattr(o, n)), "__members__")}


@pytest.fixture(scope="module")
def case():
    return (fr.rigid_block(width=0.4, height=2.0, mass=100.0),
            fr.one_sine_pulse(amplitude_g=0.3, frequency_hz=2.0, duration=1.0))


def test_every_enum_option_refuses_an_unknown_name_with_the_allowed_ones(case):
    body, motion = case
    enums = _enum_options()
    assert {"overturn", "impact_law", "contact_model", "contact_force_law"} <= set(enums)
    for key, enum in enums.items():
        with pytest.raises(ValueError, match=rf"simulate: {key} .*: expected one of") as e:
            fr.simulate(body, motion, **{key: "pi"})
        for name in enum.__members__:
            assert repr(name) in str(e.value)
        with pytest.raises(ValueError, match=rf"simulate: {key} .*: expected one of"):
            fr.simulate(body, motion, **{key: 3})
    # the names and the members themselves are taken
    a = fr.simulate(body, motion, overturn="static_instability")
    b = fr.simulate(body, motion, overturn=fr.OverturnCriterion.static_instability)
    assert a.status == b.status and a.t_end == b.t_end


def test_a_value_of_the_wrong_type_names_its_key(case):
    body, motion = case
    with pytest.raises(ValueError, match=r"simulate: max_step: expected a float, got 'x'"):
        fr.simulate(body, motion, max_step="x")


def test_value_types_print_their_fields(case, cli, source_dir, tmp_path):
    body, motion = case
    assert repr(fr.SimulationOptions()) == "SimulationOptions()"
    o = fr.SimulationOptions()
    o.max_step = 0.001
    o.overturn = fr.OverturnCriterion.static_instability
    o.methods.series_rocking = not o.methods.series_rocking
    text = repr(o)
    assert text.startswith("SimulationOptions(max_step=0.001, methods=SimulationMethods(series_rocking=")
    assert "overturn=OverturnCriterion.static_instability" in text
    r = fr.simulate(body, motion)
    assert repr(r.extremes).startswith("Extremes(") and f"impacts={r.extremes.impacts}" in repr(r.extremes)
    assert f"input_work={r.energy.input_work!r}" in repr(r.energy)
    sweep = tmp_path / "sweep.csv"
    subprocess.run([str(cli), "sweep", str(source_dir / "examples/studies/sweep.toml"), "-o",
                    str(sweep), "-q"], check=True, capture_output=True)
    s = fr.fragility_session(str(sweep), body="statue")
    d = s.data(0, 0)
    assert repr(d).startswith("FragilityData(body='statue', ")
    assert "im_name='pga_g'" in repr(d) and "im_unit='g'" in repr(d)


def test_a_pulse_component_is_a_member_or_its_name():
    with pytest.raises(ValueError, match=r"one_sine: component 'up': expected one of 'horizontal', "
                                         r"'vertical'"):
        fr.one_sine_pulse(amplitude_g=0.3, frequency_hz=2.0, duration=3.0, component="up")
    a = fr.one_sine_pulse(amplitude_g=0.3, frequency_hz=2.0, duration=3.0, component="vertical")
    b = fr.one_sine_pulse(amplitude_g=0.3, frequency_hz=2.0, duration=3.0,
                          component=fr.Component.vertical)
    assert a.at(0.1) == b.at(0.1) and a.at(0.1)[0] == 0.0
