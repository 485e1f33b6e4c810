"""The GIL is released while a vectorised call runs: another Python thread runs meanwhile.

Deterministic, with no time threshold: the switch interval is raised so far that a thread holding
the GIL is never made to give it up, so the only way the waiting thread can run before the call
returns is the call releasing the GIL itself."""
import numpy as np
from conftest import another_thread_runs_during

import conescan

ROWS = 2_000_000  # ~0.1 s of half chords: time enough for the waiting thread to be scheduled


def test_another_thread_runs_during_a_long_call():
    rng = np.random.default_rng(1)
    psi, eta, rho = rng.uniform(0.7, 0.9, ROWS), rng.uniform(1.0, 2.0, ROWS), rng.uniform(1, 1.2,
                                                                                          ROWS)
    assert another_thread_runs_during(lambda: conescan.half_chord(psi, eta, rho), tries=20), \
        "the worker ran only after the calls returned: the GIL was held"
