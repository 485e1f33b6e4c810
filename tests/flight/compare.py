#!/usr/bin/env python3
"""The flight target's tests (ctest flight.*): a probe run on the Cortex-M7 under QEMU against the
same probe on the host, its budgets, the symbols of its programs, and the measured table of
docs/FLIGHT_SOFTWARE.md.

  compare.py probe --name N --scalar S --elf E --size-elf E --baseline E --host H --qemu Q
                   --size-tool T --nm-tool T --results DIR
      Runs E under QEMU and H on the host; their cases must match line for line: statuses,
      counts and texts equal, values within the probe's tolerance (0 unless stated) in ulps of
      the larger of the value and 1 (ulps_apart). The
      target's budget line against the probe's limits (instructions, stack) and the code size
      (text of the size-only program minus the baseline's) against its code limit. No program
      may hold a heap, stdio or C++-runtime symbol. Writes DIR/N_S.json for the table.
  compare.py program --elf E --qemu Q --nm-tool T [--expect-fault]
      Runs E (a program that checks itself: exit 0) and shows what it wrote; the same symbols
      refused. --expect-fault: E must fault instead (the harness's report, exit status 3).
  compare.py table --results DIR --page PAGE [--update]
      The table between <!-- flight-table --> and <!-- /flight-table --> in PAGE must be the one
      the results make (--update: rewrite it).
"""
import argparse
import json
import math
import pathlib
import re
import struct
import subprocess
import sys

QEMU_OPTIONS = ["-M", "mps2-an500", "-display", "none", "-monitor", "none", "-serial", "none",
                "-chardev", "stdio,id=out", "-semihosting-config",
                "enable=on,target=native,chardev=out", "-icount", "shift=0", "-kernel"]
# What a flight program must not hold: the heap, stdio, the C++ runtime (function-local statics'
# guards, exceptions, RTTI, operator new), process control (newlib's system calls).
FORBIDDEN = re.compile(r"^(malloc|calloc|realloc|free|_?sbrk|_malloc_r|_free_r|__cxa_\w+|"
                       r"_Zn[wa]\w*|_Zd[la]\w*|__gxx_personality\w*|_Unwind_\w+|abort|_?exit|"
                       r"_kill|_getpid|__dso_handle|printf|puts|fputs|_write|_read|_impure_ptr|"
                       r"impure_data|__sinit)$")
STATUSES = ["ok", "miss", "engulfed", "grazing", "multiple", "fold", "ambiguous", "gimbal", "sun",
            "moon", "invalid", "none"]


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def run(command, what, timeout=120):
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        fail(f"{what} did not finish within {timeout} s")
    if done.returncode != 0:
        fail(f"{what} exited {done.returncode}\n{done.stdout}{done.stderr}")
    return done.stdout


def run_target(qemu, elf):
    return run([qemu] + QEMU_OPTIONS + [elf], f"{elf} under QEMU")


def check_symbols(nm_tool, elf):
    out = subprocess.run([nm_tool, elf], capture_output=True, text=True, check=True).stdout
    names = [line.split()[-1] for line in out.splitlines() if line.strip()]
    bad = sorted(n for n in names if FORBIDDEN.match(n))
    if bad:
        fail(f"{elf} holds {', '.join(bad)}: heap, stdio or the C++ runtime")
    return len(names)


def text_size(size_tool, elf):
    out = subprocess.run([size_tool, elf], capture_output=True, text=True, check=True).stdout
    return int(out.splitlines()[1].split()[0])


def parse(output):
    """The compared items in order, and the target-only items by kind."""
    items, extra = [], {"tolerance": {}, "limit": {}, "budget": {}, "calibration": None}
    for line in output.splitlines():
        words = line.split()
        if not words:
            continue
        kind = words[0]
        if kind in ("value", "status", "count"):
            items.append((kind, words[1], words[2], words[3:]))
        elif kind == "text":
            items.append((kind, "", "", [line[5:]]))
        elif kind == "tolerance":
            extra["tolerance"][words[1]] = int(words[2])
        elif kind == "limit":
            extra["limit"].setdefault(words[1], {})[words[2]] = int(words[3])
        elif kind == "budget":
            extra["budget"][words[1]] = {"instructions": int(words[3]), "stack": int(words[5])}
        elif kind == "calibration":
            extra["calibration"] = (int(words[1]), int(words[2]))
    return items, extra


def ordered(kind, hex_bits):
    """The bits as an integer that orders like the value (ulp distances by subtraction)."""
    bits = int(hex_bits, 16)
    width = 32 if kind == "f" else 64
    sign = 1 << (width - 1)
    return -(bits - sign) if bits & sign else bits


def is_nan(kind, hex_bits):
    bits = int(hex_bits, 16)
    if kind == "f":
        return (bits & 0x7F800000) == 0x7F800000 and bits & 0x7FFFFF
    return (bits & 0x7FF0000000000000) == 0x7FF0000000000000 and bits & 0xFFFFFFFFFFFFF


def as_number(kind, hex_bits):
    raw = bytes.fromhex(hex_bits)
    return struct.unpack(">f" if kind == "f" else ">d", raw)[0]


def ulps_apart(kind, a_hex, b_hex):
    """|a - b| in ulps of max(|a|, |b|, 1): angles in rad and unit-vector components are of
    order 1, and a small angle computed from them (a roll of 0.01 rad from a nadir's
    components) carries their absolute rounding, not one relative to itself. Also the
    distance in ulps of the value itself, for the record."""
    a, b = as_number(kind, a_hex), as_number(kind, b_hex)
    relative = abs(ordered(kind, a_hex) - ordered(kind, b_hex))
    if a == b:
        return 0.0, relative
    scale = max(abs(a), abs(b), 1.0)
    epsilon = 2.0 ** -23 if kind == "f" else 2.0 ** -52
    ulp = 2.0 ** math.floor(math.log2(scale)) * epsilon
    return abs(a - b) / ulp, relative


def compare_items(target, host, tolerance):
    if len(target) != len(host):
        fail(f"the target wrote {len(target)} items, the host {len(host)}")
    worst, worst_relative, values, statuses, mismatches = 0.0, 0, 0, 0, []
    for t, h in zip(target, host):
        where = f"{t[1]} {t[2]}" if t[0] != "text" else f"text line '{t[3][0]}'"
        if t[:3] != h[:3]:
            fail(f"the target's item '{t[0]} {where}' stands where the host has '{h[0]} {h[1]} {h[2]}'")
        if t[0] == "value":
            values += 1
            (tk, tb), (hk, hb) = t[3], h[3]
            if is_nan(tk, tb) or is_nan(hk, hb):
                if not (is_nan(tk, tb) and is_nan(hk, hb)):
                    mismatches.append(f"{where}: target {as_number(tk, tb)!r}, host {as_number(hk, hb)!r}")
                continue
            ulps, relative = ulps_apart(tk, tb, hb)
            worst, worst_relative = max(worst, ulps), max(worst_relative, relative)
            if ulps > tolerance.get(t[2], 0):
                mismatches.append(f"{where}: target {as_number(tk, tb)!r}, host {as_number(hk, hb)!r}: "
                                  f"{ulps:.2f} ulps (tolerance {tolerance.get(t[2], 0)})")
        else:
            statuses += t[0] == "status"
            if t[3] != h[3]:
                show = (lambda w: STATUSES[int(w[0])] if t[0] == "status" else w[0])
                mismatches.append(f"{where}: target {show(t[3])}, host {show(h[3])}")
    if mismatches:
        fail("target and host disagree:\n  " + "\n  ".join(mismatches[:40]))
    return values, statuses, worst, worst_relative


def probe(args):
    target_out = run_target(args.qemu, args.elf)
    host_out = run([args.host], args.host)
    for what, out in (("the target", target_out), ("the host", host_out)):
        if out.splitlines()[-1:] != ["end"]:
            fail(f"{what}'s probe did not run to its end:\n{out[-2000:]}")
    target, extra = parse(target_out)
    host, _ = parse(host_out)
    values, statuses, worst, worst_relative = compare_items(target, host, extra["tolerance"])
    for elf in (args.elf, args.size_elf):
        check_symbols(args.nm_tool, elf)
    code = text_size(args.size_tool, args.size_elf) - text_size(args.size_tool, args.baseline)
    label = f"{args.name} {args.scalar}"
    stated = max(extra["tolerance"].values(), default=0)
    print(f"{label}: {values} values within {worst:.2f} ulp of the host's (ulps of the larger of "
          f"the value and 1; {worst_relative} ulps of the value itself), tolerance {stated} ulp; "
          f"{statuses} statuses equal")
    result = {"probe": args.name, "scalar": args.scalar, "values": values, "statuses": statuses,
              "max_ulps": round(worst, 2), "max_relative_ulps": worst_relative,
              "tolerance": stated,
              "code": code, "entries": {}}
    problems = []
    for entry, budget in extra["budget"].items():
        measured = dict(budget, code=code)
        result["entries"][entry] = measured
        limits = extra["limit"].get(entry, {})
        print(f"{label}: {entry}: " + ", ".join(
            f"{measured[w]} {w}" + (f" (limit {limits[w]})" if w in limits else "")
            for w in ("instructions", "stack", "code")))
        problems += [f"{entry}: {measured[w]} {w} over the limit {n}" for w, n in limits.items()
                     if measured[w] > n]
    if not extra["budget"]:
        print(f"{label}: no entry point measured (cases only)")
    print(f"{label}: nm: no heap, stdio or C++-runtime symbol in {pathlib.Path(args.elf).name} "
          f"and {pathlib.Path(args.size_elf).name}")
    if problems:
        fail("; ".join(problems))
    pathlib.Path(args.results).mkdir(parents=True, exist_ok=True)
    (pathlib.Path(args.results) / f"{args.name}_{args.scalar}.json").write_text(
        json.dumps(result, indent=1) + "\n")


def program(args):
    if args.expect_fault:
        done = subprocess.run([args.qemu] + QEMU_OPTIONS + [args.elf], capture_output=True,
                              text=True, timeout=120)
        if done.returncode != 3 or "harness: fault" not in done.stdout:
            fail(f"{args.elf} should have faulted (exit 3), exited {done.returncode}:\n"
                 f"{done.stdout[-2000:]}")
        print(done.stdout.splitlines()[-1])
        print(f"{pathlib.Path(args.elf).name}: the overflow faulted, reported, exit status 3")
        return
    out = run_target(args.qemu, args.elf)
    for line in out.splitlines():
        print(line[5:] if line.startswith("text ") else line)
    check_symbols(args.nm_tool, args.elf)
    print(f"nm: no heap, stdio or C++-runtime symbol in {pathlib.Path(args.elf).name}")


# The table's order: the flight loop's entry points first, then the model's, the C interface's,
# the statuses; a probe not listed comes after them, by name.
TABLE_ORDER = ["two_head_sample", "one_head", "head_build", "correction", "scan_sphere",
               "scan_ellipsoid", "core_rest", "c_interface", "statuses"]


def table_key(r):
    order = TABLE_ORDER.index(r["probe"]) if r["probe"] in TABLE_ORDER else len(TABLE_ORDER)
    return (order, r["probe"], r["scalar"] != "float")


def table_text(results):
    rows = ["| entry point | scalar | instructions | stack (bytes) | code (bytes) | target vs host |",
            "|---|---|---:|---:|---:|---|"]
    for r in sorted((json.loads(p.read_text()) for p in pathlib.Path(results).glob("*.json")),
                    key=table_key):
        agreement = ("bit for bit" if r["max_ulps"] == 0 else
                     f"{r['max_ulps']:.2f} ulp ({r['max_relative_ulps']} of the value)") + \
            f"; {r['values']} values, {r['statuses']} statuses"
        for entry, m in sorted(r["entries"].items()):
            rows.append(f"| `{entry}` | {r['scalar']} | {m['instructions']} | {m['stack']} | "
                        f"{m['code']} | {agreement} |")
        if not r["entries"]:
            rows.append(f"| {r['probe']} (cases only) | {r['scalar']} | – | – | – | {agreement} |")
    return "\n".join(rows) + "\n"


def table(args):
    page = pathlib.Path(args.page)
    text = page.read_text()
    mark = re.compile(r"(<!-- flight-table -->\n)(.*?)(<!-- /flight-table -->)", re.S)
    found = mark.search(text)
    if not found:
        fail(f"{page} has no <!-- flight-table --> ... <!-- /flight-table --> block")
    measured = table_text(args.results)
    if found.group(2) == measured:
        print(f"{page.name}: the table is the one measured")
        return
    if args.update:
        page.write_text(text[:found.start(2)] + measured + text[found.end(2):])
        print(f"{page.name}: table updated")
        return
    fail(f"{page} shows another table than the one measured (rewrite it with --update):\n"
         f"{measured}")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("probe")
    for option in ("name", "scalar", "elf", "size-elf", "baseline", "host", "qemu", "size-tool",
                   "nm-tool", "results"):
        p.add_argument("--" + option, required=True)
    p = sub.add_parser("program")
    for option in ("elf", "qemu", "nm-tool"):
        p.add_argument("--" + option, required=True)
    p.add_argument("--expect-fault", action="store_true")
    p = sub.add_parser("table")
    p.add_argument("--results", required=True)
    p.add_argument("--page", required=True)
    p.add_argument("--update", action="store_true")
    args = parser.parse_args()
    {"probe": probe, "program": program, "table": table}[args.command](args)


if __name__ == "__main__":
    main()
