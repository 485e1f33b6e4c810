#!/usr/bin/python3
"""Wall-clock times of commands, for bench/campaign_speed.sh (threads: CPU time would add the
threads' times up; what a user waits for is the wall clock).

Usage: bench/wall_time.py RUNS CMD1 [ARGS...] [--- CMD2 [ARGS...] ...]
Runs the commands in turn, RUNS rounds (CMD1, CMD2, ..., CMD1, CMD2, ...), standard output to
/dev/null, and prints each command's median wall time (s), one line each. Interleaved, so that
the load of other processes on a shared machine, which comes and goes, weighs on every command
alike; compare the ratios of one call, not times of different calls.
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
    commands = [[]]
    for word in sys.argv[2:]:
        if word == "---":
            commands.append([])
        else:
            commands[-1].append(word)
    times = [[] for _ in commands]
    for _ in range(runs):
        for command, measured in zip(commands, times):
            measured.append(run_once(command))
    for measured in times:
        print(f"{statistics.median(measured):.6f}")


if __name__ == "__main__":
    main()
