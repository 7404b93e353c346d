# SPDX-License-Identifier: BSD-3-Clause
"""Errors: bad input is flexrock.InputError (a ValueError) with the command line's message."""

import subprocess

import pytest

import flexrock as fr


def cli_error(cli, *args, cwd=None):
    p = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, cwd=cwd)
    assert p.returncode == 2, p.stderr
    prefix = "flexrock: error: "
    line = p.stderr.splitlines()[0]
    assert line.startswith(prefix)
    return line[len(prefix):]


def test_input_error_is_a_value_error():
    assert issubclass(fr.InputError, ValueError)
    with pytest.raises(ValueError, match="mass"):
        fr.Body(fr.rigid_block(0.4, 1.8, -1.0))


def test_bad_case_file_message_equals_the_cli(cli, tmp_path):
    case = tmp_path / "bad.toml"
    case.write_text('[body]\ntype = "rigid_block"\nwidth = 0.4\nheigth = 1.8\nmass = 10\n'
                    '[excitation.horizontal]\ntype = "none"\nduration = 1\n')
    expected = cli_error(cli, "run", "-o", tmp_path / "out", case)
    with pytest.raises(fr.InputError) as e:
        fr.run_case(str(case), str(tmp_path / "out2"))
    assert str(e.value) == expected
    assert "did you mean" in expected  # the case loader's hint survives the trip
    assert not (tmp_path / "out2").exists()


def test_input_error_carries_file_line_and_key(tmp_path):
    case = tmp_path / "bad.toml"
    case.write_text('[body]\ntype = "rigid_block"\nwidth = -0.4\nheight = 1.8\nmass = 10\n'
                    '[excitation.horizontal]\ntype = "none"\nduration = 1\n')
    with pytest.raises(fr.InputError) as e:
        fr.run_case(str(case), str(tmp_path / "out"))
    assert (e.value.file, e.value.line, e.value.key) == (str(case), 3, "body.width")
    assert str(e.value).startswith(f"{case}:3: key 'body.width': expected a number > 0")


def test_missing_record_message_equals_the_cli(cli, tmp_path):
    case = tmp_path / "rec.toml"
    case.write_text('[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 1.8\nmass = 10\n'
                    '[excitation.horizontal]\ntype = "record"\nfile = "nowhere.AT2"\n')
    expected = cli_error(cli, "run", "-o", tmp_path, case)
    with pytest.raises(fr.InputError) as e:
        fr.load_case(str(case))
    assert str(e.value) == expected


def test_bad_initial_state_message_equals_the_cli(cli, tmp_path):
    # an error found by the engine (not the loader): the CLI prefixes the case file's path
    case = tmp_path / "init.toml"
    case.write_text('[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 1.8\nmass = 10\n'
                    '[excitation.horizontal]\ntype = "none"\nduration = 1\n'
                    '[initial]\ntheta = 1.6\n')
    expected = cli_error(cli, "run", "-o", tmp_path, case)
    with pytest.raises(fr.InputError) as e:
        fr.run_case(str(case), str(tmp_path))
    assert str(e.value) == expected


def test_record_parse_error_names_file_and_line(tmp_path):
    f = tmp_path / "r.AT2"
    f.write_text("a\nb\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 3, DT= .01 SEC\n0.1 0.2\n")
    with pytest.raises(fr.InputError, match=r"r\.AT2:\d+: "):
        fr.read_at2(str(f))


def test_unwritable_output_is_a_runtime_error(tmp_path):
    r = fr.simulate(fr.rigid_block(0.4, 1.8, 800.0), fr.one_sine_pulse(a_p=5.0, omega_p=12.0, duration=1.0))
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(RuntimeError, match="could not write the outputs"):
        r.write(blocker / "sub", time_history="a.csv")


def test_bad_solver_option_is_an_input_error():
    with pytest.raises(fr.InputError, match="rtol"):
        fr.simulate(fr.rigid_block(0.4, 1.8, 800.0), fr.free_rocking(1.0), rtol=-1.0)
