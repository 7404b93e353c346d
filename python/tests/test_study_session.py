# SPDX-License-Identifier: BSD-3-Clause
"""A sweep as a session: Python runs, resumes and reads sweeps through the library's session and
column table, the same code as ``flexrock sweep``, so either finishes a sweep the other started
with the same bytes."""

import math
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import flexrock as fr


def _manifest(tmp_path):
    # a 20 s two-sine record in g and 40 slow runs (a small max_step), so that a kill lands
    # mid-way
    dt = 0.01
    vals = [0.3 * math.sin(2 * math.pi * 1.1 * i * dt) + 0.2 * math.sin(2 * math.pi * 2.7 * i * dt)
            for i in range(2000)]
    (tmp_path / "rec.dat").write_text("".join(f"{v:.8e}\n" for v in vals))
    (tmp_path / "block.toml").write_text(
        '[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 2.0\nmass = 1000.0\n')
    m = tmp_path / "m.toml"
    m.write_text('free_periods = 1\n[[body]]\nfile = "block.toml"\n'
                 '[[record]]\nname = "two_sines"\nfile = "rec.dat"\nformat = "single_column"\n'
                 'dt = 0.01\nunits = "g"\n'
                 '[scales]\nfactors = { start = 0.1, stop = 4.0, step = 0.1 }\n'
                 '[intensity]\nmeasures = ["arias"]\n'
                 '[solver]\nmax_step = 0.0002\nfriction_coefficient = 0.7\n')
    return m


def _journal_rows(path):
    try:
        with open(path, "rb") as f:
            return f.read().count(b"\n") - 1
    except FileNotFoundError:
        return 0


def test_python_resumes_a_sweep_the_cli_started_with_the_same_bytes(cli, tmp_path):
    m = _manifest(tmp_path)
    ref = tmp_path / "ref.csv"
    p = subprocess.run([str(cli), "sweep", str(m), "-o", str(ref), "-q", "-j", "2"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    runs = len(ref.read_text().splitlines()) - 1
    assert runs == 40

    # the command line starts the sweep and is killed mid-way (SIGKILL: no clean-up at all)
    out = tmp_path / "out.csv"
    journal = tmp_path / "out.csv.partial"
    proc = subprocess.Popen([str(cli), "sweep", str(m), "-o", str(out), "-q", "-j", "1"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while _journal_rows(journal) < 5 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    assert proc.poll() is None, "the sweep ended before the kill (too fast to test)"
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    assert not out.exists()
    done = _journal_rows(journal)
    assert 5 <= done < runs
    # a torn last line, as a kill in the middle of a write leaves it
    with open(journal, "ab") as f:
        f.write(b"39 0123456789abcdef 39,two_si")

    # Python opens the same journal through the same session and goes on from there
    session = fr.SweepSession(fr.load_sweep_manifest(str(m)), str(out))
    assert session.resumed == done and session.remaining == runs - done
    assert session.journal_path == str(journal)
    session.run(2)
    rows = session.finish()
    assert [r.index for r in rows] == list(range(runs))
    assert out.read_bytes() == ref.read_bytes()
    assert not journal.exists()

    # the rows as typed arrays, by the sweep's column table; the CSV read back gives the same
    arrays = fr.sweep_arrays(session.manifest.spec, rows)
    info = fr.sweep_column_info(session.manifest.spec)
    assert list(arrays) == [c["name"] for c in info] == ref.read_text().splitlines()[0].split(",")
    dtypes = {"integer": np.int64, "real": np.float64, "text": object}
    for c in info:
        assert arrays[c["name"]].dtype == dtypes[c["type"]], c
    assert "arias_m_per_s" in arrays and "regime" in arrays
    back = fr.read_sweep(m, ref)
    for name, a in arrays.items():
        if a.dtype == np.float64:
            np.testing.assert_array_equal(back[name], a)  # bit for bit, nan where empty
        else:
            assert list(back[name]) == list(a), name
    assert list(arrays["index"]) == list(range(runs))
    assert arrays["overturned"].sum() == sum(o.startswith("overturned_") for o in arrays["outcome"])


def test_a_sweep_python_started_and_the_cli_finished_has_the_same_bytes(cli, tmp_path):
    m = _manifest(tmp_path)
    ref = tmp_path / "ref.csv"
    whole = fr.sweep_manifest(m, ref, threads=2)
    assert len(whole["index"]) == 40
    # Python starts the sweep (in a process of its own, killed mid-way); the command line goes on
    out = tmp_path / "out.csv"
    journal = tmp_path / "out.csv.partial"
    code = f"import flexrock as fr; fr.sweep_manifest({str(m)!r}, {str(out)!r}, threads=1)"
    proc = subprocess.Popen([sys.executable, "-c", code], env=os.environ.copy())
    deadline = time.monotonic() + 120
    while _journal_rows(journal) < 5 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    assert proc.poll() is None, "the Python sweep ended before the kill (too fast to test)"
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    done = _journal_rows(journal)
    assert 5 <= done < 40 and not out.exists()
    p = subprocess.run([str(cli), "sweep", str(m), "-o", str(out), "-j", "2"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert f"resuming: {done} of 40 runs already in" in p.stdout
    assert out.read_bytes() == ref.read_bytes()


def test_a_sweep_csv_that_is_not_its_runs_is_refused_naming_line_and_field(tmp_path):
    m = _manifest(tmp_path)
    m.write_text(m.read_text().replace("stop = 4.0", "stop = 0.3").replace("max_step = 0.0002", "max_step = 0.01"))
    out = tmp_path / "s.csv"
    fr.sweep_manifest(m, out, threads=1)
    lines = out.read_text().splitlines()
    bad = lines[:2] + [lines[2].replace(",two_sines,", ",two_sine,")] + lines[3:]
    (tmp_path / "bad.csv").write_text("\n".join(bad) + "\n")
    with pytest.raises(fr.InputError, match=r"bad.csv:3: field 3 \(record\)"):
        fr.read_sweep(m, tmp_path / "bad.csv")
    (tmp_path / "short.csv").write_text("\n".join(lines[:-1]) + "\n")
    with pytest.raises(fr.InputError, match="2 rows, expected one per run"):
        fr.read_sweep(m, tmp_path / "short.csv")


def test_python_finishes_a_spectrum_the_cli_left_with_the_same_bytes(cli, source_dir, tmp_path):
    spec = source_dir / "examples" / "studies" / "one_sine_block.toml"
    p = subprocess.run([str(cli), "spectrum", str(spec), "-o", str(tmp_path / "ref.csv"), "-q",
                        "-j", "2"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    # a complete journal, kept because the boundary could not be written (its directory does not
    # exist), cut to its header and half its cells: what a kill leaves
    out = tmp_path / "out.csv"
    p = subprocess.run([str(cli), "spectrum", str(spec), "-o", str(out), "--boundary",
                        str(tmp_path / "no_such_dir" / "b.csv"), "-q", "-j", "2"],
                       capture_output=True, text=True)
    assert p.returncode == 1 and "the finished cells are kept in" in p.stderr
    out.unlink()
    journal = tmp_path / "out.csv.partial"
    lines = journal.read_text().splitlines(keepends=True)
    journal.write_text("".join(lines[: len(lines) // 2]))
    session = fr.SpectrumSession(fr.load_spectrum_file(str(spec)), str(out),
                                 str(tmp_path / "out.boundary.csv"))
    assert session.resumed == len(lines) // 2 - 1 and session.bisect
    session.run(2)
    res = session.finish()
    assert out.read_bytes() == (tmp_path / "ref.csv").read_bytes()
    assert (tmp_path / "out.boundary.csv").read_bytes() == (tmp_path / "ref.boundary.csv").read_bytes()
    assert not journal.exists()
    # the result as data: every cell and boundary, read back through the column tables
    assert len(res.cells) == session.cells and all(c.computed for c in res.cells)
    assert len(res.boundary) == session.runs - session.cells
    rows = (tmp_path / "ref.csv").read_text().splitlines()
    col = rows[0].split(",").index("outcome")
    assert [c.run.outcome.name for c in res.cells] == [r.split(",")[col] for r in rows[1:]]
    # the cells as typed arrays, by the spectrum's column table: the CSV's columns and numbers
    arrays = fr.spectrum_arrays(res, fr.Body(fr.load_spectrum_file(str(spec)).body).g)
    assert list(arrays) == rows[0].split(",")
    assert arrays["row"].dtype == np.int64 and arrays["outcome"].dtype == object
    assert arrays["a_p_m_per_s2"].dtype == np.float64
    text = fr.read_csv_table(str(tmp_path / "ref.csv"))
    for j, name in enumerate(text.columns):
        if arrays[name].dtype == np.float64:
            expected = [float(r[j]) if r[j] else math.nan for r in text.rows]
            np.testing.assert_array_equal(arrays[name], expected)
        else:
            assert [str(x) for x in arrays[name]] == [r[j] for r in text.rows], name
    # the same file again from the convenience function (no journal: every run afresh)
    again = fr.spectrum_file(spec, tmp_path / "again.csv", threads=2)
    assert (tmp_path / "again.csv").read_bytes() == (tmp_path / "ref.csv").read_bytes()
    assert (tmp_path / "again.boundary.csv").read_bytes() == (tmp_path / "ref.boundary.csv").read_bytes()
    # (a column with no overturning has no value: nan)
    np.testing.assert_array_equal([b.overturning for b in again.boundary],
                                  [b.overturning for b in res.boundary])
    assert [b.kind for b in again.boundary] == [b.kind for b in res.boundary]
