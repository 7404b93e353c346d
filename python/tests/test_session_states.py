# SPDX-License-Identifier: BSD-3-Clause
"""Every state the sessions' public API reaches raises an exception that says what to do (never
an abort), and Ctrl-C stops a sweep or a spectrum between runs, as the command line's SIGINT
does: KeyboardInterrupt at once, the journal kept, and a rerun that ends with the same bytes as
an uninterrupted one."""

import math
import os
import signal
import subprocess
import sys
import time

import pytest

import flexrock as fr


def _manifest(tmp_path, factors="{ start = 0.02, stop = 4.0, step = 0.02 }", max_step=0.0002):
    # a 20 s two-sine record in g and 200 slow runs (a small max_step), so that a signal lands
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
                 f'[scales]\nfactors = {factors}\n'
                 f'[solver]\nmax_step = {max_step}\nfriction_coefficient = 0.7\n')
    return m


def _spectrum(tmp_path, count, max_step=0.0005):
    s = tmp_path / "s.toml"
    s.write_text('[body]\ntype = "rigid_block"\nwidth = 0.4\nheight = 2.0\nmass = 100.0\n'
                 '[spectrum]\nfree_periods = 4\n'
                 f'amplitudes = {{ start = 0.5, stop = 8.0, count = {count} }}\n'
                 f'frequencies = {{ start = 1.5, stop = 8.0, count = {count} }}\n'
                 f'[solver]\nmax_step = {max_step}\n')
    return s


def _journal_rows(path):
    try:
        with open(path, "rb") as f:
            return f.read().count(b"\n") - 1
    except FileNotFoundError:
        return 0


def test_finish_before_the_runs_raises_and_says_to_run_first(tmp_path):
    m = _manifest(tmp_path, factors="[0.5, 1.0]", max_step=0.01)
    out = tmp_path / "s.csv"
    s = fr.SweepSession(fr.load_sweep_manifest(str(m)), str(out))
    with pytest.raises(RuntimeError, match=r"0 of 2 runs are finished .*call run\(\) first"):
        s.finish()
    assert not out.exists() and os.path.exists(s.journal_path)
    s.run(1)
    s.run(1)  # nothing left: each run is journaled once
    assert len(s.finish()) == 2 and out.exists() and not os.path.exists(s.journal_path)
    # the session is over: it says so instead of journaling into a deleted journal
    for call in (lambda: s.run(1), s.finish):
        with pytest.raises(RuntimeError, match=r"after finish\(\): the session is over"):
            call()

    spec = _spectrum(tmp_path, 2)
    cells, boundary = tmp_path / "c.csv", tmp_path / "b.csv"
    sp = fr.SpectrumSession(fr.load_spectrum_file(str(spec)), str(cells), str(boundary))
    with pytest.raises(RuntimeError, match=r"0 of 4 cells are finished .*call run\(\) first"):
        sp.finish()
    assert not cells.exists()
    sp.run(1)
    assert len(sp.finish().cells) == 4 and cells.exists() and boundary.exists()
    for call in (lambda: sp.run(1), sp.finish):
        with pytest.raises(RuntimeError, match=r"after finish\(\): the session is over"):
            call()


def _interrupt(code, journal, out, min_rows):
    """Starts `code` in a Python of its own, sends SIGINT once `min_rows` runs are journaled, and
    returns (seconds from the signal to the exit, stderr, exit status, rows journaled at the
    signal)."""
    proc = subprocess.Popen([sys.executable, "-c", code], env=os.environ.copy(),
                            stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while _journal_rows(journal) < min_rows and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    assert proc.poll() is None, "the study ended before the signal (too fast to test)"
    sent = time.monotonic()
    at_signal = _journal_rows(journal)
    proc.send_signal(signal.SIGINT)
    try:
        _, err = proc.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        pytest.fail("SIGINT did not stop the study within 60 s")
    return time.monotonic() - sent, err, proc.returncode, at_signal


def test_ctrl_c_stops_a_python_sweep_and_the_rerun_has_the_same_bytes(tmp_path):
    m = _manifest(tmp_path)
    ref = tmp_path / "ref.csv"
    fr.sweep_manifest(m, ref, threads=2)
    out = tmp_path / "out.csv"
    journal = tmp_path / "out.csv.partial"
    code = f"import flexrock as fr; fr.sweep_manifest({str(m)!r}, {str(out)!r}, threads=1)"
    seconds, err, rc, at_signal = _interrupt(code, journal, out, 3)
    assert rc != 0 and "KeyboardInterrupt" in err, err
    # between runs: what is added after the signal is the run in progress and those that end
    # before the pool looks for signals again (every 20 ms) and the process exits, a few of the
    # 200, not the rest of them. How many depends on the machine's speed (runs of 5 to 25 ms),
    # so the bound is a quarter of the runs left, far below the rest that a sweep running on
    # journals (all 200 before Ctrl-C was heeded)
    done = _journal_rows(journal)
    assert 3 <= at_signal <= done <= at_signal + max(10, (200 - at_signal) // 4) < 200, (
        at_signal, done, seconds)
    assert not out.exists()
    # a new session goes on from the journal
    s = fr.SweepSession(fr.load_sweep_manifest(str(m)), str(out))
    assert s.resumed == done
    s.run(2)
    s.finish()
    assert out.read_bytes() == ref.read_bytes()


def test_ctrl_c_stops_a_python_spectrum_and_the_rerun_has_the_same_bytes(tmp_path):
    spec = _spectrum(tmp_path, 10, max_step=0.00002)
    ref, ref_b = tmp_path / "ref.csv", tmp_path / "ref_b.csv"
    fr.spectrum_file(spec, ref, ref_b, threads=2)
    out, out_b = tmp_path / "out.csv", tmp_path / "out_b.csv"
    journal = tmp_path / "out.csv.partial"
    code = (f"import flexrock as fr; fr.spectrum_file({str(spec)!r}, {str(out)!r}, "
            f"{str(out_b)!r}, threads=1)")
    seconds, err, rc, at_signal = _interrupt(code, journal, out, 3)
    assert rc != 0 and "KeyboardInterrupt" in err, err
    done = _journal_rows(journal)
    # as for the sweep: a quarter of the 100 cells left at most, not the rest of them
    assert 3 <= at_signal <= done <= at_signal + max(10, (100 - at_signal) // 4) < 100, (
        at_signal, done, seconds)
    assert not out.exists() and not out_b.exists()
    fr.spectrum_file(spec, out, out_b, threads=2)
    assert out.read_bytes() == ref.read_bytes() and out_b.read_bytes() == ref_b.read_bytes()


def test_ctrl_c_stops_an_in_memory_sweep(tmp_path):
    # no journal: the arrays are dropped, KeyboardInterrupt comes at once; 20,000 runs would
    # take minutes (the timeout below guards against a sweep that runs on)
    m = _manifest(tmp_path, factors="{ start = 0.0002, stop = 4.0, step = 0.0002 }")
    code = (f"import flexrock as fr, threading, os, signal\n"
            f"threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()\n"
            f"import time; t = time.monotonic()\n"
            f"try:\n"
            f"    fr.run_sweep(fr.load_sweep_manifest({str(m)!r}).spec, [], 1)\n"
            f"except KeyboardInterrupt:\n"
            f"    print('stopped after', time.monotonic() - t)\n")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0 and "stopped after" in p.stdout, (p.stdout, p.stderr)
