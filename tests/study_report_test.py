#!/usr/bin/env python3
"""ctest report.page and report.screenshot: scripts/study-report.py on a small scene (half an
hour of rows at 60 s, a day's calendar, a 5 x 5 map), and scripts/calendar.sh.

  page        the page parses as HTML5 (html5lib, strict: any parse error fails); every image it
              shows is embedded, is a PNG of the width and height its <img> states, and equals
              the file beside the page it names; the budget's and the calendar's tables equal
              budget.csv and calendar/seasons.csv (each cell's data-value the CSV's text, its
              text that number to 3 significant digits), the worst error equals worst-day.csv's;
              the provenance names the version and the input's SHA-256; refusals (a scene
              conescan-sim refuses, a folder that is no report, a run mode in the scene) exit 2
              and leave the folder as it was; a report replaces the one before it whole;
              scripts/calendar.sh writes the tables and a picture of 600 px a head
  screenshot  --screenshot: headless Chromium draws the page (within 60 s, or the report
              fails): a 1280 x 2400 PNG, far from blank (skipped, 77, without chromium)

Usage: study_report_test.py page|screenshot CONESCAN_SIM SOURCE_DIR
"""
import base64
import csv
import hashlib
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile

import html5lib

MODE, SIM, ROOT = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
REPORT = os.path.join(ROOT, "scripts", "study-report.py")
TLE = os.path.join(ROOT, "tests", "data", "tle", "delta-1-deb.tle")
# docs/SUN_MOON.md's example day with the preset's physics: the +y head loses crossings to the Sun.
SCENE = ["--sensor-preset", "conical-15um", "--epoch", "2026-05-01T00:00:00", "--a-km", "7178.137",
         "--e", "0", "--sun-sync", "--j2", "--raan-deg", "353.93852694944263",
         "--head", "beta=90,sigma=0", "--head", "beta=-90,sigma=0",
         "--duration-s", "1800", "--step-s", "60"]
SMALL = ["--calendar-days", "1", "--map-points", "5"]
NS = "{http://www.w3.org/1999/xhtml}"
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print(f"FAILED: {what}", file=sys.stderr)


def report(args, env_extra=None):
    env = dict(os.environ, CONESCAN_SIM=SIM, **(env_extra or {}))
    return subprocess.run([sys.executable, REPORT] + args, capture_output=True, text=True, env=env,
                          timeout=240)


def png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    return struct.unpack(">II", data[16:24])


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def text_of(element):
    return "".join(element.itertext())


def check_table(doc, table_id, rows, keys):
    table = next((t for t in doc.iter(NS + "table") if t.get("id") == table_id), None)
    check(table is not None, f"table {table_id} is on the page")
    if table is None:
        return
    body = [tr for tr in table.iter(NS + "tr") if tr.find(NS + "td") is not None]
    check(len(body) == len(rows), f"table {table_id}: {len(body)} rows, the CSV {len(rows)}")
    for tr, row in zip(body, rows):
        cells = tr.findall(NS + "td")
        for cell, (key, numeric) in zip(cells, keys):
            if not numeric:
                check(text_of(cell) == row[key], f"{table_id} {key}: {text_of(cell)} != {row[key]}")
                continue
            check(cell.get("data-value") == row[key],
                  f"{table_id} {key}: data-value {cell.get('data-value')} != {row[key]}")
            if row[key]:
                check(text_of(cell) == f"{float(row[key]):.3g}",
                      f"{table_id} {key}: shows {text_of(cell)} for {row[key]}")


def page_test(work):
    out = os.path.join(work, "study")
    result = report(SMALL + [out] + SCENE)
    check(result.returncode == 0, f"the report runs (exit {result.returncode}): {result.stderr}")
    if result.returncode != 0:
        return
    page = os.path.join(out, "index.html")
    with open(page, "rb") as f:
        source = f.read()
    parser = html5lib.HTMLParser(strict=True, namespaceHTMLElements=True)
    try:
        doc = parser.parse(source)
    except html5lib.html5parser.ParseError as e:
        check(False, f"index.html parses as HTML5: {e}")
        return
    images = list(doc.iter(NS + "img"))
    check(len(images) == 4, f"4 pictures on the page, not {len(images)}")
    for img in images:
        src, name = img.get("src"), img.get("data-file")
        check(src.startswith("data:image/png;base64,"), f"{name}: embedded as a PNG")
        data = base64.b64decode(src.split(",", 1)[1])
        width, height = png_size(data)
        check((str(width), str(height)) == (img.get("width"), img.get("height")),
              f"{name}: {width} x {height}, the page says {img.get('width')} x {img.get('height')}")
        path = os.path.join(out, name)
        check(os.path.isfile(path), f"{name} is beside the page")
        if os.path.isfile(path):
            with open(path, "rb") as f:
                check(f.read() == data, f"{name}: the file is the embedded picture")
        check(bool(img.get("alt")), f"{name}: has a text")
    budget = read_csv(os.path.join(out, "budget.csv"))
    check([r["source"] for r in budget][-3:] == ["all", "sum", "interaction"],
          "the budget ends with all, sum and interaction")
    check_table(doc, "budget-table", budget,
                [("source", False), ("rows", True), ("ok", True), ("roll_rms_deg", True),
                 ("roll_3sigma_deg", True), ("pitch_rms_deg", True), ("pitch_3sigma_deg", True)])
    seasons = read_csv(os.path.join(out, "calendar", "seasons.csv"))
    check(any(r["head"] == "h1" and r["body"] == "sun" and int(r["lost_events"]) > 20
              for r in seasons), "the calendar: the +y head loses crossings to the Sun")
    check_table(doc, "calendar-table", seasons,
                [("head", False), ("body", False), ("on_cone_days", True), ("lost_days", True),
                 ("first_lost_day", True), ("last_lost_day", True), ("lost_events", True),
                 ("lost_s", True), ("longest_event_s", True)])
    rows = read_csv(os.path.join(out, "worst-day.csv"))
    largest = max(abs(float(r[c])) for r in rows for c in ("roll_err_deg", "pitch_err_deg")
                  if not math.isnan(float(r[c])))
    worst = next(e for e in doc.iter(NS + "span") if e.get("id") == "worst-error")
    check(float(worst.get("data-value")) == largest, "the worst error is worst-day.csv's")
    with open(os.path.join(out, "provenance.csv"), newline="") as f:
        provenance = dict(csv.reader(f))
    version = subprocess.run([SIM, "--version"], capture_output=True, text=True).stdout.strip()
    check(provenance.get("conescan") == version, "the provenance names the version")
    text = source.decode()
    check(version in text, "the page names the version")
    check("--budget --summary" in text and "--calendar" in text, "the page lists the runs")
    # An input's SHA-256: the same scene from a scene file.
    scene_file = os.path.join(work, "scene.toml")
    shutil.copy(os.path.join(out, "scene.toml"), scene_file)
    with open(scene_file, "rb") as f:
        digest = hashlib.sha256(f.read()).hexdigest()
    again = report(SMALL + [out, "--config", scene_file])
    check(again.returncode == 0, f"a report from the scene file (exit {again.returncode})")
    with open(os.path.join(out, "provenance.csv"), newline="") as f:
        check(f"{scene_file} sha256 {digest}" in f.read(), "the provenance holds the file's SHA-256")
    check(read_csv(os.path.join(out, "budget.csv")) == budget,
          "the scene file gives the same budget (and replaced the report before)")
    # Refusals: exit 2, the folder as it was.
    before = sorted(os.listdir(out))
    refused = report(SMALL + [out] + SCENE[:-4] + ["--e", "2"])
    check(refused.returncode == 2 and "--e" in refused.stderr,
          f"a scene conescan-sim refuses: exit 2 naming the option ({refused.stderr.strip()})")
    check(sorted(os.listdir(out)) == before, "a refused report leaves the folder as it was")
    mode = report(SMALL + [out] + SCENE + ["--budget"])
    check(mode.returncode == 2 and "give the scene only" in mode.stderr, "a run mode: exit 2")
    foreign = os.path.join(work, "foreign")
    os.mkdir(foreign)
    open(os.path.join(foreign, "keep.txt"), "w").close()
    refused = report(SMALL + [foreign] + SCENE)
    check(refused.returncode == 2 and "no report" in refused.stderr, "a folder that is no report")
    check(os.listdir(foreign) == ["keep.txt"], "its files are kept")
    check(not [n for n in os.listdir(work) if ".tmp-" in n], "no temporary folder left")
    # scripts/calendar.sh: the tables, a picture of 600 x 420 a head, the seasons printed.
    calendar = os.path.join(work, "calendar")
    run = subprocess.run([os.path.join(ROOT, "scripts", "calendar.sh"), calendar] + SCENE[:-4] +
                         ["--duration-s", "86400"], capture_output=True, text=True, timeout=120,
                         env=dict(os.environ, BUILD_DIR=os.path.dirname(SIM)))
    check(run.returncode == 0, f"scripts/calendar.sh runs: {run.stderr}")
    if run.returncode == 0:
        with open(os.path.join(calendar, "calendar.png"), "rb") as f:
            check(png_size(f.read(24)) == (1200, 420), "calendar.png: 1200 x 420 for two heads")
        check(run.stdout.startswith("head") and "h1    sun" in run.stdout, "the seasons printed")


def screenshot_test(work):
    if not shutil.which("chromium"):
        print("report.screenshot: skipped: no chromium (scripts/setup.sh installs it)")
        sys.exit(77)
    out = os.path.join(work, "study")
    result = report(SMALL + ["--screenshot", out] + SCENE)
    check(result.returncode == 0, f"the report with --screenshot (exit {result.returncode}): "
                                  f"{result.stderr[-800:]}")
    if result.returncode != 0:
        return
    path = os.path.join(out, "screenshot.png")
    with open(path, "rb") as f:
        check(png_size(f.read(24)) == (1280, 2400), "the screenshot is 1280 x 2400")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.image
    pixels = matplotlib.image.imread(path)[:, :, :3]
    drawn = (pixels.min(axis=2) < 0.9).mean()
    colours = len({tuple(p) for p in (pixels[::7, ::7] * 255).astype(int).reshape(-1, 3)})
    check(drawn > 0.05, f"the screenshot is drawn: {drawn:.1%} of it not white")
    check(colours > 50, f"the screenshot holds text and pictures: {colours} colours")
    # The title at the top, the budget's picture below: its orange and blue bars.
    top = pixels[:200]
    check((top.min(axis=2) < 0.5).mean() > 0.002, "the title is drawn at the top")


def main():
    work = tempfile.mkdtemp()
    try:
        {"page": page_test, "screenshot": screenshot_test}[MODE](work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        print(f"{len(failures)} check(s) failed", file=sys.stderr)
        sys.exit(1)
    print(f"report.{MODE}: every check passed")


if __name__ == "__main__":
    main()
