#!/usr/bin/python3
"""conescan-table-scan: random scenes whose rows conescan-sim takes from the physics table
(docs/SENSOR_PHYSICS.md, "The table"), each against the same rows by the chain.

Each scene draws, from its seed: an orbit (an 800 km sun-synchronous circle, or an ellipse 6900
to 7600 km in semi-major axis, perigee at least 370 km up, any inclination, with J2 in one scene
in four), a date, the Earth (WGS84 in two scenes in three, else the sphere), one or two heads
(misaligned within 0.5 deg, on the pitch or roll axis, each a pencil or a 0.3-2 deg square or
circle, 0.5-3 rev/s, no lag or 0.1-2 ms, each locator), the limb (50 % point 20-45 km up, scale
height 2-10 km) and the season term (|A| <= 0.3, on either Earth). The orbit is written once as an OEM (--write-oem), which every run then
reads, so that the day and its windows see one geometry. The day runs at 2 s over 43 000 rows (a
field's head is tabulated from 512 rows, a pencil's from 256); each window runs 11 of its rows
from their own epoch, too few for a table: the chain. It prints each scene with the worst
difference of its heads' chords and phases in degrees, and exits 1 where one passes the tolerance
or a status differs. A head whose build fails runs the chain on the day as well: the comparison
then holds trivially (the scene's CPU time, printed, tells: a field's day by the chain takes
minutes).

Usage: /usr/bin/python3 bench/table_scan.py [SEED [SCENES [TOLERANCE_DEG [BUILD_DIR]]]]
Defaults: seed 1, 10 scenes, 5e-7 deg (the build checks its pieces to 1e-7 deg per crossing;
between the checks a chain that is not smooth leaves a row up to some 2e-7 deg off, docs/
SENSOR_PHYSICS.md "The table"), build. Needs: cmake --build BUILD_DIR --target conescan-sim.
"""
import csv
import datetime
import pathlib
import random
import resource
import subprocess
import sys
import tempfile

seed = int(sys.argv[1]) if len(sys.argv) > 1 else 1
scenes = int(sys.argv[2]) if len(sys.argv) > 2 else 10
tolerance_deg = float(sys.argv[3]) if len(sys.argv) > 3 else 5e-7
sim = str(pathlib.Path(sys.argv[4] if len(sys.argv) > 4 else "build").resolve() / "conescan-sim")

STEP_S = 2
DAY_ROWS = 43000
WINDOWS = 6
WINDOW_ROWS = 11


def run(args, out_path):
    """conescan-sim's rows as dicts; exits on any error (a drawn scene must be valid)."""
    with open(out_path, "w") as out:
        done = subprocess.run([sim] + args, stdout=out, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"table_scan: conescan-sim {' '.join(args)}: {done.stderr.strip()}")
    with open(out_path) as f:
        return list(csv.DictReader(f))


def draw_head(rng):
    spec = (f"sigma={rng.uniform(0, 0.5):.3f},phase={rng.uniform(0, 360):.1f},"
            f"beta={rng.choice(['90', '-90', '0'])},spin-hz={rng.uniform(0.5, 3):.2f}")
    if rng.random() < 0.6:
        spec += f",fov={rng.uniform(0.3, 2.0):.3f},fov-shape={rng.choice(['square', 'circle'])}"
    if rng.random() < 0.7:
        spec += f",tau-ms={rng.uniform(0.1, 2.0):.3f}"
    locator = rng.choice(["normalised", "fixed", "slope"])
    spec += f",locator={locator}"
    if locator == "normalised":
        spec += f",threshold={rng.uniform(0.3, 0.7):.3f}"
    elif locator == "fixed":
        spec += f",threshold={rng.uniform(0.2, 0.6):.3f}"
    return spec


def draw_scene(rng):
    if rng.random() < 0.4:
        orbit = ["--a-km", "7178", "--e", "0.001", "--i-deg", "98.6"]
    else:
        a_km = rng.uniform(6900, 7600)
        orbit = ["--a-km", f"{a_km:.1f}", "--e", f"{rng.uniform(0, 1 - 6750 / a_km):.4f}",
                 "--i-deg", f"{rng.uniform(0, 100):.1f}", "--argp-deg", f"{rng.uniform(0, 360):.1f}",
                 "--m0-deg", f"{rng.uniform(0, 360):.1f}"]
    if rng.random() < 0.25:
        orbit.append("--j2")
    date = f"2026-{rng.randint(1, 12):02d}-{rng.randint(1, 28):02d}"
    ellipsoid = rng.random() < 2 / 3
    season = rng.uniform(-0.3, 0.3)
    physics = ["--earth", "wgs84" if ellipsoid else "sphere", "--model", "scan",
               "--radiance-offset-km", f"{rng.uniform(20, 45):.1f}",
               "--radiance-scale-km", f"{rng.uniform(2, 10):.2f}",
               "--processing-horizon-km", "40", "--radiance-season", f"{season:.3f}"]
    heads = [draw_head(rng) for _ in range(rng.choice([1, 2]))]
    for h in heads:
        physics += ["--head", h]
    return orbit, date, physics


def child_cpu_s():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def compare_window(day, window, first, heads):
    """The worst |difference| (deg) of the heads' chords and phases, and the statuses that differ."""
    worst, differ, compared = 0.0, 0, 0
    for j, by_chain in enumerate(window):
        by_day = day[first + j]
        for k in range(1, heads + 1):
            status = f"h{k}_status"
            if by_day[status] != by_chain[status]:
                differ += 1
                print(f"  t = {by_chain['t_s']} s, head {k}: day {by_day[status]}, "
                      f"chain {by_chain[status]}")
                continue
            if by_chain[status] != "ok":
                continue
            compared += 1
            for column in (f"h{k}_chord_deg", f"h{k}_phase_deg"):
                worst = max(worst, abs(float(by_day[column]) - float(by_chain[column])))
    return worst, differ, compared


def scan_scene(index, rng, work):
    orbit, date, physics = draw_scene(rng)
    heads = physics.count("--head")
    oem = str(work / "orbit.oem")
    epoch = datetime.datetime.fromisoformat(date + "T00:00:00")
    duration_s = STEP_S * (DAY_ROWS - 1)
    run(orbit + ["--epoch", epoch.isoformat(), "--step-s", str(STEP_S), "--duration-s",
                 str(duration_s + STEP_S * WINDOW_ROWS), "--write-oem", oem], "/dev/null")
    common = ["--oem", oem, "--threads", "1"] + physics
    cpu_before = child_cpu_s()
    day = run(common + ["--epoch", epoch.isoformat(), "--step-s", str(STEP_S),
                        "--duration-s", str(duration_s)], work / "day.csv")
    day_cpu_s = child_cpu_s() - cpu_before
    worst, differ, compared = 0.0, 0, 0
    for _ in range(WINDOWS):
        first = rng.randrange(0, DAY_ROWS - WINDOW_ROWS)
        start = epoch + datetime.timedelta(seconds=first * STEP_S)
        window = run(common + ["--epoch", start.isoformat(), "--step-s", str(STEP_S),
                               "--duration-s", str(STEP_S * (WINDOW_ROWS - 1))],
                     work / "window.csv")
        w, d, c = compare_window(day, window, first, heads)
        worst, differ, compared = max(worst, w), differ + d, compared + c
    print(f"scene {index}: {' '.join(orbit)} --epoch {date} {' '.join(physics)}")
    print(f"  day {day_cpu_s:.1f} s of CPU; {compared} ok head rows compared, worst "
          f"{worst:.2e} deg, {differ} statuses differ", flush=True)
    return worst, differ


def main():
    rng = random.Random(seed)
    worst_all, failed = 0.0, 0
    with tempfile.TemporaryDirectory() as directory:
        for index in range(scenes):
            worst, differ = scan_scene(index, rng, pathlib.Path(directory))
            worst_all = max(worst_all, worst)
            failed += worst > tolerance_deg or differ > 0
    print(f"table_scan: seed {seed}, {scenes} scenes, worst {worst_all:.2e} deg, "
          f"{failed} beyond {tolerance_deg:g} deg or with a status that differs")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
