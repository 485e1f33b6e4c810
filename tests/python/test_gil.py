"""The GIL is released while a vectorised call runs: another Python thread runs meanwhile.

Deterministic, with no time threshold: the switch interval is raised so far that a thread holding
the GIL is never made to give it up, so the only way the waiting thread can run before the call
returns is the call releasing the GIL itself."""
import sys
import threading

import numpy as np

import conescan

ROWS = 2_000_000  # ~0.1 s of half chords: time enough for the waiting thread to be scheduled


def test_another_thread_runs_during_a_long_call():
    rng = np.random.default_rng(1)
    psi, eta, rho = rng.uniform(0.7, 0.9, ROWS), rng.uniform(1.0, 2.0, ROWS), rng.uniform(1, 1.2,
                                                                                          ROWS)
    in_call = [False]
    seen = []
    go = threading.Event()

    def worker():
        go.wait()  # blocks without the GIL; wakes wanting it
        seen.append(in_call[0])

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e6)
    try:
        thread = threading.Thread(target=worker)
        thread.start()
        go.set()  # from here the worker waits for the GIL, which this thread keeps...
        for _ in range(20):  # ...unless the call releases it (a few tries: a busy machine)
            in_call[0] = True
            conescan.half_chord(psi, eta, rho)
            in_call[0] = False
            if seen:
                break
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    assert seen == [True], "the worker ran only after the calls returned: the GIL was held"
