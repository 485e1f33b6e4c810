#!/usr/bin/python3
"""conescan.simulate against conescan-sim --summary on 10^6 rows of the paper's scene, in one run
so that the ratio holds whatever the machine's load (docs/PERFORMANCE.md; target: within 1.2x).

--summary computes the same rows as the CSV without formatting them: the yardstick of an array
of the rows. Both run on one CPU (CPU 0; the CLI as a child), timed in CPU time (user + system:
the wall clock would also count the time other processes hold the core), in alternating rounds;
the ratio is the median of the rounds' ratios. conescan.summary (the same summary from Python)
is timed alongside. Checks on the way that the rows are the same rows: simulate's row count and
extreme roll and pitch errors equal the CLI's summary exactly.

Usage: /usr/bin/python3 bench/python_simulate.py [ROWS [BUILD_DIR]]   (default 10^6, build)
Needs: cmake --build BUILD_DIR --target conescan_python conescan-sim
"""
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import time

import numpy as np

ROUNDS = 7
rows = int(float(sys.argv[1])) if len(sys.argv) > 1 else 10**6
build = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else "build").resolve()
sys.path.insert(0, str(build / "python"))
import conescan  # noqa: E402  (from the build tree)

os.sched_setaffinity(0, {0})  # the CLI inherits it
# The paper's scene, `rows` rows at its 10 s step.
options = {"duration_s": 10 * (rows - 1), "max_rows": max(rows, 10**7)}
cli = [str(build / "conescan-sim"), "--summary"] + [
    a for name, value in options.items() for a in (f"--{name.replace('_', '-')}", str(value))]


def cli_seconds():
    """CPU time of conescan-sim --summary (getrusage: to the microsecond), and its output."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run(cli, capture_output=True, text=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, done.stdout


def python_seconds(function):
    start = time.process_time()
    result = function(**options)
    return time.process_time() - start, result


conescan.simulate(duration_s=100)  # warm: the module's first call
simulate_times, summary_times, cli_times = [], [], []
for _ in range(ROUNDS):
    seconds, text = cli_seconds()
    cli_times.append(seconds)
    seconds, table = python_seconds(conescan.simulate)
    simulate_times.append(seconds)
    del table
    summary_times.append(python_seconds(conescan.summary)[0])

# The same rows: simulate's count and extremes are the CLI's summary's, exactly.
table = conescan.simulate(**options)
lines = text.splitlines()
line = dict(zip(lines[0].split(","), lines[-1].split(",")))  # the header, the system's line
same = (len(table) == rows == int(line["rows"])
        and np.nanmax(table["roll_err_deg"]) == float(line["roll_max_deg"])
        and np.nanmin(table["pitch_err_deg"]) == float(line["pitch_min_deg"]))

ratios = [p / c for p, c in zip(simulate_times, cli_times)]
summary_ratios = [p / c for p, c in zip(summary_times, cli_times)]
print(f"the paper's scene, {rows} rows ({table.dtype.itemsize} bytes a row), CPU seconds:")
for c, p, s in zip(cli_times, simulate_times, summary_times):
    print(f"  conescan-sim --summary {c:6.3f}   conescan.simulate {p:6.3f} ({p / c:.3f})   "
          f"conescan.summary {s:6.3f} ({s / c:.3f})")
print(f"conescan.simulate / conescan-sim --summary: {statistics.median(ratios):.3f} "
      f"(median of {ROUNDS} rounds; target <= 1.2); {rows / statistics.median(simulate_times):.3g}"
      f" rows/s")
print(f"conescan.summary / conescan-sim --summary: {statistics.median(summary_ratios):.3f}")
print(f"same rows: {'yes' if same else 'NO'}")
sys.exit(0 if same else 1)
