# SPDX-License-Identifier: BSD-3-Clause
"""The GIL is released while simulating: threads run at once and give the serial results."""

import math
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import flexrock as fr


def _run(amplitude):
    body = fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0)
    return fr.simulate(body, fr.harmonic(a_p=amplitude, omega_p=2 * math.pi * 1.2, duration=4.0), output_dt=0.01)


def test_threads_give_the_serial_results():
    amplitudes = [1.5, 2.0, 2.5, 3.0, 3.5, 4.0]
    serial = [_run(a) for a in amplitudes]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(_run, amplitudes))
    for s, t in zip(serial, threaded):
        assert s.status == t.status
        assert s.time_history_csv() == t.time_history_csv()
        assert s.summary() == t.summary()


def test_python_runs_while_a_simulation_runs():
    # with the GIL held for the whole simulation, the main thread could not run a single
    # iteration between the worker's start and end marks
    # a flexible body below its uplift threshold under an analytic motion is propagated step by
    # step (a rigid one in full contact is not, nor is any body under a sampled record: the record
    # walk takes one update per sample, 3,000 here, about 3 ms, too short for the main thread to
    # be scheduled on a loaded machine): 30 s at max_step 1e-4 is 300,000 steps, about 0.2 s
    marks = {}
    body = fr.uniform_cantilever(10.0, 3.0, 2000.0, 5e9, modes=2, base_mass=1000.0)
    motion = fr.harmonic(a_p=0.3, omega_p=2 * math.pi * 1.3, duration=30.0)

    def work():
        marks["start"] = time.perf_counter()
        marks["result"] = fr.simulate(body, motion, max_step=1e-4)
        marks["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    worker.start()
    ticks = []
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    assert marks["result"].extremes.first_uplift_time < 0  # it stayed in full contact
    during = [x for x in ticks if marks["start"] < x < marks["end"]]
    assert len(during) > 10, (len(ticks), marks["end"] - marks["start"])
