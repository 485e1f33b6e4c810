#!/usr/bin/python3
"""CPU time of a command, for bench/cli_speed.sh.

Usage: bench/cpu_time.py RUNS CMD [ARGS...]
Runs CMD RUNS times on one core (CPU 0), standard output to /dev/null, and prints the median
CPU time (user + system, in seconds, to the microsecond of getrusage). CPU time rather than wall
time: on a shared machine the wall clock also counts the time other processes hold the core.
Microseconds rather than /usr/bin/time's hundredths: at ~0.3 s per run those would make a ratio
uncertain by 3 %. (Peak memory is left to /usr/bin/time: a child forked from Python counts
Python's own pages until it execs.)
"""
import os
import statistics
import sys


def run_once(command):
    pid = os.fork()
    if pid == 0:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, 1)
        os.sched_setaffinity(0, {0})
        try:
            os.execvp(command[0], command)
        finally:
            os._exit(127)
    _, status, usage = os.wait4(pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"cpu_time: {' '.join(command)} failed with status {status}")
    return usage.ru_utime + usage.ru_stime


def main():
    if len(sys.argv) < 3 or not sys.argv[1].isdigit() or int(sys.argv[1]) < 1:
        sys.exit("usage: cpu_time.py RUNS CMD [ARGS...]")
    results = [run_once(sys.argv[2:]) for _ in range(int(sys.argv[1]))]
    print(f"{statistics.median(results):.6f}")


if __name__ == "__main__":
    main()
