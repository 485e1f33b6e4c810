#!/usr/bin/python3
"""The committed data files the docs quote, regenerated and compared (ctest docs.data_files).

Usage: tests/data_files.py SOURCE_DIR BUILD_DIR [--update]

docs/data/regenerated.txt lists each file with the command that writes its content on standard
output; each command runs from SOURCE_DIR with BUILD_DIR in the environment, and its output must
be the file: the same lines and fields, text exactly, numbers to 1e-12 relative (their last
digits move with the compiler and its options; a stale figure, -0.17 where the command now
writes 0.00, does not). A difference is a failure naming the file, its first line that differs
and the command. With --update the files that differ are rewritten.
"""
import math
import os
import pathlib
import re
import subprocess
import sys

RELATIVE = 1e-12
FIELD = re.compile(r"[^,\s]+|[,\s]+")


def same_field(a, b):
    if a == b:
        return True
    try:
        x, y = float(a), float(b)
    except ValueError:
        return False
    if math.isnan(x) or math.isnan(y):
        return math.isnan(x) and math.isnan(y)
    return abs(x - y) <= RELATIVE * max(abs(x), abs(y))


def same_line(a, b):
    fa, fb = FIELD.findall(a), FIELD.findall(b)
    return len(fa) == len(fb) and all(same_field(x, y) for x, y in zip(fa, fb))


def entries(manifest):
    for number, line in enumerate(manifest.read_text().split("\n"), 1):
        if not line.strip() or line.startswith("#"):
            continue
        name, separator, command = line.partition(": ")
        if not separator:
            raise SystemExit(f"{manifest}:{number}: expected FILE: COMMAND")
        yield name, command


def self_check():
    """The comparison itself: a stale figure is found, the last digits of a number are not."""
    assert same_line("09:00,-46.87,-34.15", "09:00,-46.87,-34.15")
    assert not same_line("09:00,-0.17,1", "09:00,0.00,1")  # blinding-beta.csv's stale figure
    assert same_line("1,86400,-5.0695315440616335", "1,86400,-5.0695315440616344")
    assert not same_line("a,b", "a,b,c") and not same_line("x,1", "y,1")


def main(argv):
    self_check()
    root, build = pathlib.Path(argv[0]).resolve(), pathlib.Path(argv[1]).resolve()
    update = "--update" in argv[2:]
    env = dict(os.environ, BUILD_DIR=str(build), LC_ALL="C")
    problems = []
    for name, command in entries(root / "docs/data/regenerated.txt"):
        done = subprocess.run(command, shell=True, cwd=root, env=env, capture_output=True,
                              text=True, timeout=600)
        if done.returncode != 0:
            problems.append(f"{name}: exit {done.returncode}: {command}\n{done.stderr[-2000:]}")
            continue
        path = root / name
        committed = path.read_text() if path.exists() else ""
        old, new = committed.split("\n"), done.stdout.split("\n")
        if len(old) == len(new) and all(same_line(a, b) for a, b in zip(old, new)):
            continue
        if update:
            path.write_text(done.stdout)
            print(f"data_files: rewrote {name}")
            continue
        line = next((k for k in range(min(len(old), len(new))) if not same_line(old[k], new[k])),
                    min(len(old), len(new)))
        shown = lambda lines: lines[line] if line < len(lines) else "(no line)"
        problems.append(f"{name}:{line + 1}: not what `{command}` writes now:\n"
                        f"  committed: {shown(old)}\n  written:   {shown(new)}\n"
                        f"  (regenerate: tests/data_files.py . build --update)")
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
