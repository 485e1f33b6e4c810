#!/usr/bin/python3
"""The Python module's vectorised half chord against a plain C++ loop over the same arrays
(bench/half_chord_loop.cpp), in one run so that the ratio holds whatever the machine's load
(docs/PERFORMANCE.md; target: within 1.5x). Both are pinned to one CPU and timed in alternating
rounds (each the median of RUNS single passes); the ratio is the median of the rounds' ratios.
Checks on the way that both give the same bits.

Usage: /usr/bin/python3 bench/python_half_chord.py [N [BUILD_DIR]]   (default 10^6, build)
Needs the build's module and bench programs: cmake --build BUILD_DIR --target conescan_python
conescan-half-chord-loop.
"""
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

ROUNDS, RUNS = 5, 7
n = int(float(sys.argv[1])) if len(sys.argv) > 1 else 10**6
build = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else "build").resolve()
sys.path.insert(0, str(build / "python"))
import conescan  # noqa: E402  (from the build tree)

os.sched_setaffinity(0, {0})  # the C++ program inherits it
rng = np.random.default_rng(18)
deg = np.pi / 180
# The paper's head and orbit, its attitude swept widely: mostly ok, some miss and engulfed.
psi = rng.uniform(44.9, 45.1, n) * deg
eta = rng.uniform(60, 120, n) * deg
rho = rng.uniform(60, 78, n) * deg


def python_ns_per_element():
    conescan.half_chord(psi, eta, rho)  # warm
    times = []
    for _ in range(RUNS):
        start = time.perf_counter_ns()
        conescan.half_chord(psi, eta, rho)
        times.append((time.perf_counter_ns() - start) / n)
    return statistics.median(times)


with tempfile.TemporaryDirectory() as work:
    inputs, outputs = pathlib.Path(work, "in"), pathlib.Path(work, "out")
    np.concatenate([psi, eta, rho]).tofile(inputs)
    loop = [str(build / "bench" / "conescan-half-chord-loop"), str(inputs), str(outputs), str(RUNS)]
    rounds = []
    for _ in range(ROUNDS):
        cpp = float(subprocess.run(loop, capture_output=True, text=True, check=True).stdout.split()[0])
        rounds.append((python_ns_per_element(), cpp))
    raw = outputs.read_bytes()
    cpp_value = np.frombuffer(raw[:8 * n], dtype=np.float64)
    cpp_status = np.frombuffer(raw[8 * n:], dtype=np.uint8)

r = conescan.half_chord(psi, eta, rho)
same = np.array_equal(r.status, cpp_status) and np.array_equal(
    r.value.view(np.int64)[r.status == 0], cpp_value.view(np.int64)[cpp_status == 0])
counts = {name: int((r.status == code).sum()) for code, name in enumerate(conescan.status_names)
          if (r.status == code).any()}
ratio = statistics.median(p / c for p, c in rounds)
print(f"half chord of {n} elements ({counts}), ns per element, median of {RUNS} passes:")
for p, c in rounds:
    print(f"  conescan.half_chord {p:7.2f}   C++ loop {c:7.2f}   ratio {p / c:.3f}")
print(f"Python / C++: {ratio:.3f} (median of {ROUNDS} rounds; target <= 1.5); "
      f"same bits: {'yes' if same else 'NO'}")
sys.exit(0 if same else 1)
