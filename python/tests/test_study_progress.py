# SPDX-License-Identifier: BSD-3-Clause
"""Progress of Python studies: a callback sees every study's count grow to its total, from the
calling thread; an exception it raises stops the runs between two, as Ctrl-C does, the journal
kept and a rerun ending with the uninterrupted bytes; a bar (a plain line where tqdm is not
installed) on stderr, none with progress=False; wrong keywords are refused."""

import os
import subprocess
import sys
import threading

import pytest

import flexrock as fr

from test_session_states import _manifest, _spectrum


def _check_counts(calls, total):
    assert calls, "the callback was never called"
    dones = [d for d, _ in calls]
    assert all(t == total for _, t in calls), calls
    assert dones == sorted(dones), dones  # monotone
    assert dones[-1] == total  # ends at the total


def test_callback_sees_a_monotone_count_to_the_total(tmp_path):
    calls, threads = [], set()

    def cb(done, total):
        calls.append((done, total))
        threads.add(threading.get_ident())

    m = _manifest(tmp_path, factors="{ start = 0.05, stop = 2.0, step = 0.05 }", max_step=0.002)
    rows = fr.sweep_manifest(m, tmp_path / "s.csv", threads=2, progress=False, callback=cb)
    _check_counts(calls, len(rows["index"]))
    assert threads == {threading.get_ident()}  # on the calling thread, never a worker

    calls.clear()
    spec = _spectrum(tmp_path, 4)
    res = fr.spectrum_file(spec, tmp_path / "c.csv", threads=2, progress=False, callback=cb)
    _check_counts(calls, len(res.cells))

    calls.clear()
    body = fr.rigid_block(width=0.4, height=2.0, mass=100.0)
    res = fr.spectrum(body, amplitudes=[1.0, 2.0, 3.0], frequencies=[2.0, 4.0], bisect=False,
                      progress=False, callback=cb)
    _check_counts(calls, 6)


def test_an_exception_in_the_callback_stops_the_runs_and_a_rerun_resumes(tmp_path):
    m = _manifest(tmp_path, factors="{ start = 0.05, stop = 2.0, step = 0.05 }", max_step=0.002)
    ref = fr.sweep_manifest(m, tmp_path / "ref.csv", threads=2, progress=False)
    total = len(ref["index"])

    class Stop(Exception):
        pass

    def cb(done, _total):
        if done >= 3:
            raise Stop

    out = tmp_path / "s.csv"
    with pytest.raises(Stop):
        fr.sweep_manifest(m, out, threads=1, progress=False, callback=cb)
    assert not out.exists()
    journaled = open(str(out) + ".partial").read().count("\n") - 1
    assert 3 <= journaled < total, journaled  # stopped between runs, the finished ones kept
    fr.sweep_manifest(m, out, threads=2, progress=False)
    assert out.read_bytes() == (tmp_path / "ref.csv").read_bytes()


def _stderr_of(tmp_path, progress):
    m = _manifest(tmp_path, factors="{ start = 0.05, stop = 1.0, step = 0.05 }", max_step=0.002)
    code = ("import sys, flexrock as fr, flexrock._progress as p\n"
            "p._BAR_DELAY = 0.0\n"  # a bar from the first count, for a short study
            f"fr.sweep_manifest(sys.argv[1], sys.argv[2], threads=1, progress={progress})\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    p = subprocess.run([sys.executable, "-c", code, str(m), str(tmp_path / f"{progress}.csv")],
                       capture_output=True, text=True, env=env, timeout=120)
    assert p.returncode == 0, p.stderr
    return p.stderr


def test_a_progress_line_on_stderr_and_none_when_asked(tmp_path):
    err = _stderr_of(tmp_path, True)
    try:
        import tqdm  # noqa: F401
    except ImportError:
        # stderr is no terminal here: plain lines, the last at the total
        lines = [ln for ln in err.splitlines() if ln.startswith("sweep: ")]
        assert lines and lines[-1].startswith("sweep: 20 of 20 runs (100%)"), err
    else:
        assert "20/20" in err, err
    assert _stderr_of(tmp_path, False) == ""


def test_wrong_progress_keywords_are_refused(tmp_path):
    body = fr.rigid_block(width=0.4, height=2.0, mass=100.0)
    with pytest.raises(TypeError, match="progress: expected True or False"):
        fr.spectrum(body, amplitudes=[1.0], frequencies=[2.0], progress="yes")
    with pytest.raises(TypeError, match="callback: expected a function"):
        fr.spectrum(body, amplitudes=[1.0], frequencies=[2.0], callback=3)
