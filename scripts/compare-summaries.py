#!/usr/bin/python3
"""Compares two conescan-sim summaries (--summary, --merge): every count and name equal, every
statistic (columns *_deg) within RELATIVE of the larger of its own magnitude and its line's RMS
(the scale a mean near zero is known to). Exit 0 when they agree, 1 with the differences.

Usage: scripts/compare-summaries.py EXPECTED.csv ACTUAL.csv [RELATIVE]   (default 1e-12)
"""
import csv
import math
import sys


def main():
    expected_path, actual_path = sys.argv[1], sys.argv[2]
    relative = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-12
    with open(expected_path, newline="") as f:
        expected = list(csv.reader(f))
    with open(actual_path, newline="") as f:
        actual = list(csv.reader(f))
    problems = []
    if not expected or expected[0] != actual[0] or len(expected) != len(actual):
        problems.append("different headers or line counts")
    else:
        header = expected[0]
        worst = 0.0
        for line, (a, b) in enumerate(zip(expected[1:], actual[1:]), start=2):
            for name, x, y in zip(header, a, b):
                if not name.endswith("_deg"):
                    if x != y:
                        problems.append(f"line {line} {name}: {x} != {y}")
                    continue
                x, y = float(x), float(y)
                if math.isnan(x) or math.isnan(y):
                    if not (math.isnan(x) and math.isnan(y)):
                        problems.append(f"line {line} {name}: {x} != {y}")
                    continue
                rms = abs(float(a[header.index(name.split("_")[0] + "_rms_deg")]))
                difference = abs(x - y) / max(abs(x), rms, 1e-300)
                worst = max(worst, difference)
                if difference > relative:
                    problems.append(f"line {line} {name}: {x!r} and {y!r} differ by {difference:.3g}")
        print(f"{len(expected) - 1} summary lines; largest relative difference {worst:.3g}")
    for p in problems:
        print(p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
