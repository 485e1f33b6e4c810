#!/usr/bin/python3
"""conescan.simulate against conescan-sim --summary on 10^6 rows of the paper's scene, in one run
so that the ratio holds whatever the machine's load (docs/PERFORMANCE.md; target: within 1.2x).

--summary computes the same rows as the CSV without formatting them: the yardstick of an array
of the rows. Both run on one CPU (CPU 0; the CLI as a child), timed in CPU time (user + system:
the wall clock would also count the time other processes hold the core), in alternating rounds;
each ratio is the median of the rounds' ratios. conescan.summary (the same summary from Python)
is timed alongside. Checks on the way that the rows are the same rows: simulate's row count and
extreme roll and pitch errors equal the CLI's summary exactly.

simulate's array is fresh memory (120 MB for 10^6 rows), and what fresh memory costs depends on
the machine as much as on the program. On a virtual machine with free page reporting (Linux
page_reporting: a freed block is handed back to the host ~2 s after it is freed), memory that
has been free for a while costs a fault in the host on first touch. So simulate is timed twice a
round: on warm memory (a same-sized array touched and freed just before: pages the kernel still
holds, zeroed again on the fault as on any machine) and on cold memory (after 3 s idle). The
memory alone (np.ones of the same bytes, warm and cold) is timed beside it, so that the cold
round's extra time can be told apart from the program's.

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
COLD_PAUSE_S = 3.0  # > page_reporting's 2 s delay
REPORTING = pathlib.Path("/sys/module/page_reporting/parameters/page_reporting_order")
rows = int(float(sys.argv[1])) if len(sys.argv) > 1 else 10**6
build = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else "build").resolve()
sys.path.insert(0, str(build / "python"))
import conescan  # noqa: E402  (from the build tree)

os.sched_setaffinity(0, {0})  # the CLI inherits it
# The paper's scene, `rows` rows at its 10 s step.
options = {"duration_s": 10 * (rows - 1), "max_rows": max(rows, 10**7)}
cli = [str(build / "conescan-sim"), "--summary"] + [
    a for name, value in options.items() for a in (f"--{name.replace('_', '-')}", str(value))]


def cpu_seconds(who=resource.RUSAGE_SELF):
    usage = resource.getrusage(who)
    return usage.ru_utime + usage.ru_stime


def cli_seconds():
    """CPU time of conescan-sim --summary (getrusage: to the microsecond), and its output."""
    before = cpu_seconds(resource.RUSAGE_CHILDREN)
    done = subprocess.run(cli, capture_output=True, text=True, check=True)
    return cpu_seconds(resource.RUSAGE_CHILDREN) - before, done.stdout


def seconds_of(function, **keywords):
    """CPU time of one call; the result is freed before returning."""
    start = cpu_seconds()
    result = function(**keywords)
    seconds = cpu_seconds() - start
    del result
    return seconds


def memory_alone(count):
    return np.ones(count)  # what fresh memory of the array's bytes costs, touched once


conescan.simulate(duration_s=100)  # warm: the module's first call
doubles = rows * conescan.simulate(duration_s=0).dtype.itemsize // 8
times = {k: [] for k in ("cli", "warm", "summary", "memory warm", "memory cold", "cold")}
for _ in range(ROUNDS):
    seconds, text = cli_seconds()
    times["cli"].append(seconds)
    seconds_of(memory_alone, count=doubles)  # leaves warm pages behind
    times["warm"].append(seconds_of(conescan.simulate, **options))
    times["memory warm"].append(seconds_of(memory_alone, count=doubles))
    times["summary"].append(seconds_of(conescan.summary, **options))
    time.sleep(COLD_PAUSE_S)
    times["memory cold"].append(seconds_of(memory_alone, count=doubles))
    time.sleep(COLD_PAUSE_S)
    times["cold"].append(seconds_of(conescan.simulate, **options))

# The same rows: simulate's count and extremes are the CLI's summary's, exactly.
table = conescan.simulate(**options)
lines = text.splitlines()
line = dict(zip(lines[0].split(","), lines[-1].split(",")))  # the header, the system's line
same = (len(table) == rows == int(line["rows"])
        and np.nanmax(table["roll_err_deg"]) == float(line["roll_max_deg"])
        and np.nanmin(table["pitch_err_deg"]) == float(line["pitch_min_deg"]))


def ratio(name):
    return statistics.median(p / c for p, c in zip(times[name], times["cli"]))


def cold_extra(cold, warm):
    return statistics.median(times[cold]) - statistics.median(times[warm])


reporting = REPORTING.read_text().strip() if REPORTING.exists() else "none"
print(f"the paper's scene, {rows} rows ({table.dtype.itemsize} bytes a row), CPU seconds "
      f"(free page reporting order: {reporting}):")
print("  " + "  ".join(f"{name:>11}" for name in times))
for k in range(ROUNDS):
    print("  " + "  ".join(f"{times[name][k]:11.3f}" for name in times))
print(f"conescan.simulate / conescan-sim --summary, warm memory: {ratio('warm'):.3f} "
      f"(median of {ROUNDS} rounds; target <= 1.2); "
      f"{rows / statistics.median(times['warm']):.3g} rows/s")
print(f"conescan.simulate / conescan-sim --summary, cold memory: {ratio('cold'):.3f}")
print(f"  cold - warm: simulate {cold_extra('cold', 'warm'):.3f} s, the memory alone "
      f"{cold_extra('memory cold', 'memory warm'):.3f} s (medians)")
print(f"conescan.summary / conescan-sim --summary: {ratio('summary'):.3f}")
print(f"same rows: {'yes' if same else 'NO'}")
sys.exit(0 if same else 1)
