#!/usr/bin/python3
"""Wall-clock time of a command, for bench/campaign_speed.sh (threads: CPU time would add the
threads' times up; what a user waits for is the wall clock).

Usage: bench/wall_time.py RUNS CMD [ARGS...]
Runs CMD RUNS times, standard output to /dev/null, and prints the median wall time (s). On a
shared machine the wall clock also counts the time other processes hold the cores: compare
ratios measured in one run of the bench, not times of different runs.
"""
import os
import statistics
import subprocess
import sys
import time


def run_once(command):
    start = time.perf_counter()
    with open(os.devnull, "wb") as null:
        status = subprocess.run(command, stdout=null).returncode
    seconds = time.perf_counter() - start
    if status != 0:
        sys.exit(f"wall_time: {' '.join(command)} failed with status {status}")
    return seconds


def main():
    runs = int(sys.argv[1])
    command = sys.argv[2:]
    print(f"{statistics.median(run_once(command) for _ in range(runs)):.6f}")


if __name__ == "__main__":
    main()
