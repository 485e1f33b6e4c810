#!/usr/bin/python3
"""A mission study in one step: a scene turned into a folder with a self-contained HTML report
(docs/STUDY.md).

    scripts/study-report.py [--calendar-days N] [--map-points N] [--screenshot] [--title TEXT]
                            OUTDIR SCENE-OPTIONS...

SCENE-OPTIONS are conescan-sim's (a scene file with --config, --tle, --sensor-preset, heads...).
OUTDIR (new, empty, or a report written before, which is replaced whole) receives:

  index.html      the page, every picture embedded (data: URIs), nothing fetched
  scene.toml      the scene as conescan-sim --print-config writes it
  budget.csv      conescan-sim --budget --summary: each error source alone, all, their sum
  budget.png      each source's RMS of roll and pitch
  worst-day.csv   the rows of the day (86 400 s from the epoch) whose largest |system error| is
                  the largest, every head's errors and statuses
  worst-day.png   its error time series
  calendar/       conescan-sim --calendar over N days from the epoch (default 365) at 1 s:
                  lost.csv, on-cone.csv, days.csv, seasons.csv, calendar.png
  stability.csv   each head's status at the epoch over roll x pitch offsets of twice the scene's
  stability.png   attitude envelope (N x N points, default 41), the envelope drawn on it
  provenance.csv  conescan's version, the command line, every conescan-sim run, each input
                  file's SHA-256, the source tree's commit, the time
  screenshot.png  with --screenshot: the page as headless Chromium draws it (1280 px wide)

A section the scene cannot have (a calendar needs --model scan, the map constant attitude
angles) says why on the page; a scene conescan-sim refuses stops the report (exit 2, its
message), and nothing of OUTDIR changes until the report is whole. CONESCAN_SIM: the program
(default build/conescan-sim, built when missing). Needs matplotlib (Debian's python3-matplotlib)
and, for --screenshot, chromium.
"""
import argparse
import base64
import csv
import datetime
import hashlib
import html
import math
import os
import shlex
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DPI = 100
# The statuses in include/conescan/status.hpp's order, with the stability map's colours
# (bench/charts/stability_map.gp's).
STATUSES = ["ok", "miss", "engulfed", "grazing", "multiple", "fold", "ambiguous", "gimbal",
            "sun", "moon", "invalid", "none"]
STATUS_COLOURS = ["#b7e4b0", "#f2f2f2", "#9e9e9e", "#ff9f1c", "#17becf", "#d62728", "#e377c2",
                  "#7b3294", "#ffd700", "#1f4e99", "black", "#ffffff"]
# Scene options the report's own runs set: dropped from the scene's for those runs.
SPAN_OPTIONS = {"--duration-s", "--orbits", "--step-s"}
ATTITUDE_OPTIONS = {"--roll-deg", "--pitch-deg"}
RUN_MODES = {"--budget", "--summary", "--sweep", "--calendar", "--summary-state", "--shard",
             "--write-oem", "--write-aem", "--runs", "--print-config", "--merge"}


class Refused(Exception):
    """conescan-sim refused the scene: the report stops (exit 2)."""


def say(text):
    print(f"study-report: {text}", file=sys.stderr, flush=True)


class Runner:
    """Runs conescan-sim and keeps every command line for the provenance."""

    def __init__(self, sim, work, out):
        self.sim = sim
        self.commands = []
        self.work, self.out = work, out  # the report's folder while written, and its name

    def record(self, args):
        """The command as the provenance keeps it (the folder by its final name)."""
        self.commands.append(shlex.join(["conescan-sim"] + args).replace(self.work, self.out))

    def run(self, args, what, stdout=None, quiet=False):
        command = [self.sim] + args
        if not quiet:
            self.record(args)
        start = time.monotonic()
        result = subprocess.run(command, stdout=stdout or subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True)
        if not quiet:
            say(f"{what}: {time.monotonic() - start:.1f} s")
        if result.returncode == 2:
            raise Refused(result.stderr.strip())
        if result.returncode != 0:
            raise RuntimeError(f"conescan-sim failed ({what}, exit {result.returncode}): "
                               f"{result.stderr.strip()}")
        return result


def without(tokens, names):
    """The scene's tokens without the options `names` (each with its value; --x=v too)."""
    out, skip = [], False
    for token in tokens:
        if skip:
            skip = False
            continue
        name = token.split("=", 1)[0]
        if name in names:
            skip = "=" not in token
            continue
        out.append(token)
    return out


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        raise RuntimeError(f"{path}: not a PNG")
    return struct.unpack(">II", head[16:24])


def save(fig, path, width, height):
    fig.set_size_inches(width / DPI, height / DPI)
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def scene_value(scene_text, key):
    """A top-level key's value in --print-config's scene file ("" when absent)."""
    for line in scene_text.splitlines():
        if line.startswith("[["):
            break
        name, _, value = line.partition(" = ")
        if name.strip() == key:
            return value.strip().strip('"')
    return ""


# --- Sections ---------------------------------------------------------------------------------

def budget_section(runner, scene, out):
    with open(os.path.join(out, "budget.csv"), "w") as f:
        runner.run(scene + ["--budget", "--summary"], "the budget", stdout=f)
    rows = read_csv(os.path.join(out, "budget.csv"))
    sources = [r["source"] for r in rows]
    fig, ax = plt.subplots()
    y = range(len(rows))
    ax.barh([i - 0.2 for i in y], [float(r["roll_rms_deg"]) for r in rows], 0.4,
            label="roll RMS", color="#1f77b4")
    ax.barh([i + 0.2 for i in y], [float(r["pitch_rms_deg"]) for r in rows], 0.4,
            label="pitch RMS", color="#ff7f0e")
    ax.set_yticks(list(y), sources)
    ax.invert_yaxis()
    ax.set_xlabel("deg (RMS over the rows, the mean included; system solution)")
    ax.set_title("The error budget: each source alone, all together, their sum and the "
                 "interaction (all - sum)", fontsize=10)
    ax.grid(axis="x", color="#eeeeee")
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(out, "budget.png"), 900, 120 + 34 * len(rows))
    return rows


def worst_day_section(runner, scene, out):
    """Streams the rows; keeps the day with the largest |system error|."""
    command = [runner.sim] + scene
    runner.record(scene)
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    reader = csv.reader(process.stdout)
    header = next(reader, None)
    best_day, best_error, day, day_rows, day_error, best_rows = None, -1.0, None, [], -1.0, []
    rows = 0
    if header:
        t, roll, pitch = (header.index(c) for c in ("t_s", "roll_err_deg", "pitch_err_deg"))
        for fields in reader:
            rows += 1
            d = int(float(fields[t]) // 86400) + 1
            if d != day:
                if day is not None and day_error > best_error:
                    best_day, best_error, best_rows = day, day_error, day_rows
                day, day_rows, day_error = d, [], -1.0
            day_rows.append(fields)
            for column in (roll, pitch):
                value = float(fields[column])
                if not math.isnan(value):
                    day_error = max(day_error, abs(value))
        if day is not None and day_error > best_error:
            best_day, best_error, best_rows = day, day_error, day_rows
    error = process.stderr.read()
    if process.wait() != 0:
        raise Refused(error.strip()) if process.returncode == 2 else RuntimeError(error)
    say(f"the rows ({rows}): {time.monotonic() - start:.1f} s")
    with open(os.path.join(out, "worst-day.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(best_rows)
    fig, axes = plt.subplots(2, 1, sharex=True)
    t0 = (best_day - 1) * 86400
    hours = [(float(r[header.index("t_s")]) - t0) / 3600 for r in best_rows]
    heads = sorted({c.split("_")[0] for c in header if c.startswith("h") and c.endswith("_roll_err_deg")},
                   key=lambda h: int(h[1:]))
    for ax, angle in zip(axes, ("roll", "pitch")):
        for h in heads:
            column = header.index(f"{h}_{angle}_err_deg")
            ax.plot(hours, [float(r[column]) for r in best_rows], lw=0.6, alpha=0.7, label=h)
        column = header.index(f"{angle}_err_deg")
        ax.plot(hours, [float(r[column]) for r in best_rows], lw=1.2, color="black", label="system")
        ax.set_ylabel(f"{angle} error (deg)")
        ax.grid(color="#eeeeee")
    axes[0].legend(loc="upper right", fontsize=8, ncol=len(heads) + 1)
    axes[1].set_xlabel(f"hours into day {best_day} from the epoch")
    axes[0].set_title(f"The worst day: day {best_day}, largest |system error| "
                      f"{best_error:.4g} deg", fontsize=10)
    fig.tight_layout()
    save(fig, os.path.join(out, "worst-day.png"), 1000, 520)
    return {"day": best_day, "largest_deg": best_error, "rows": len(best_rows), "all_rows": rows}


def calendar_section(runner, scene, out, days):
    directory = os.path.join(out, "calendar")
    runner.run(without(scene, SPAN_OPTIONS) + ["--duration-s", str(days * 86400), "--step-s", "1",
                                                "--calendar", directory], "the calendar")
    picture = os.path.join(directory, "calendar.png")
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "calendar-picture.py"), picture,
                    directory, "--title", f"Sun and Moon in the scan over {days} days"],
                   check=True, stderr=subprocess.DEVNULL)
    return read_csv(os.path.join(directory, "seasons.csv"))


def stability_section(runner, scene, out, scene_text, points):
    envelope = float(scene_value(scene_text, "attitude-envelope-deg") or 10)
    half = 2 * envelope if envelope > 0 else 10.0
    step = 2 * half / (points - 1)
    base = without(without(scene, SPAN_OPTIONS | ATTITUDE_OPTIONS), {"--attitude-envelope-deg"})
    grid, heads = [], None
    for j in range(points):
        pitch = -half + j * step
        result = runner.run(base + ["--attitude-envelope-deg", repr(envelope),
                                    "--pitch-deg", repr(pitch), "--duration-s", "0",
                                    "--sweep", f"roll-deg={-half!r}:{half!r}:{step!r}"],
                            f"the stability map, pitch {pitch:+.2f} deg", quiet=True)
        rows = list(csv.DictReader(result.stdout.splitlines()))
        heads = heads or sorted({k[:-7] for k in rows[0] if k.startswith("h") and
                                 k.endswith("_status")}, key=lambda h: int(h[1:]))
        grid.append([[r[f"{h}_status"] for h in heads] + [r["status"]] for r in rows[:points]])
    names = heads + ["system"]
    say(f"the stability map ({points} x {points} points)")
    runner.record(base + ["--attitude-envelope-deg", repr(envelope), "--pitch-deg", "P",
                          "--duration-s", "0", "--sweep", f"roll-deg={-half!r}:{half!r}:{step!r}"])
    runner.commands[-1] += f"  # for P from {-half!r} to {half!r} by {step!r}"
    with open(os.path.join(out, "stability.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["pitch_deg", "roll_deg"] + [f"{n}_status" for n in names])
        for j, line in enumerate(grid):
            for i, statuses in enumerate(line):
                writer.writerow([repr(-half + j * step), repr(-half + i * step)] + statuses)
    fig, axes = plt.subplots(1, len(names), squeeze=False)
    colours = ListedColormap(STATUS_COLOURS)
    seen = set()
    for k, (ax, name) in enumerate(zip(axes[0], names)):
        image = [[STATUSES.index(line[i][k]) for i in range(points)] for line in grid]
        seen.update(line[i][k] for line in grid for i in range(points))
        ax.imshow(image, origin="lower", cmap=colours, vmin=-0.5, vmax=len(STATUSES) - 0.5,
                  extent=(-half - step / 2, half + step / 2, -half - step / 2, half + step / 2),
                  interpolation="nearest")
        ax.add_patch(Rectangle((-envelope, -envelope), 2 * envelope, 2 * envelope, fill=False,
                               lw=1.2, ls="--", color="black"))
        ax.set_title(name, fontsize=10)
        ax.set_xlabel("roll offset (deg)")
        if k == 0:
            ax.set_ylabel("pitch offset (deg)")
    fig.legend(handles=[Patch(color=STATUS_COLOURS[STATUSES.index(s)], label=s)
                        for s in STATUSES if s in seen] +
               [Patch(fill=False, ls="--", label=f"attitude envelope +-{envelope:g} deg")],
               loc="lower center", ncol=8, fontsize=8, frameon=False)
    fig.suptitle("Each head's status at the epoch over the attitude offsets", fontsize=10)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    save(fig, os.path.join(out, "stability.png"), 330 * len(names), 400)
    return {"envelope": envelope, "half": half, "points": points, "seen": sorted(seen)}


# --- The page ---------------------------------------------------------------------------------

def image(out, name, alt):
    path = os.path.join(out, name)
    width, height = png_size(path)
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode("ascii")
    return (f'<figure><img src="data:image/png;base64,{data}" width="{width}" height="{height}" '
            f'alt="{html.escape(alt)}" data-file="{html.escape(name)}">'
            f'<figcaption>{html.escape(alt)} (<a href="{html.escape(name)}">{html.escape(name)}'
            f"</a>, {width} x {height})</figcaption></figure>")


def number_cell(text, digits=3):
    """A CSV number shown to `digits` significant digits, its exact text in data-value."""
    try:
        value = float(text)
        shown = f"{value:.{digits}g}" if math.isfinite(value) else text
    except ValueError:
        shown = text
    return f'<td data-value="{html.escape(text)}">{html.escape(shown)}</td>'


def table(rows, columns, caption, table_id):
    head = "".join(f"<th>{html.escape(label)}</th>" for _, label, _ in columns)
    body = []
    for r in rows:
        cells = "".join(number_cell(r[key]) if numeric else f"<td>{html.escape(r[key])}</td>"
                        for key, _, numeric in columns)
        body.append(f"<tr>{cells}</tr>")
    return (f'<table id="{table_id}"><caption>{html.escape(caption)}</caption><thead><tr>{head}'
            f"</tr></thead><tbody>{''.join(body)}</tbody></table>")


STYLE = """
body { font-family: "DejaVu Sans", sans-serif; max-width: 1100px; margin: 1.5em auto;
       padding: 0 1em; color: #222; line-height: 1.4; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; border-bottom: 1px solid #ddd; margin-top: 1.8em; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.6em; text-align: right; }
th { background: #f4f4f4; } td:first-child, th:first-child { text-align: left; }
caption { text-align: left; font-size: 0.9em; color: #555; padding-bottom: 0.3em; }
pre { background: #f7f7f7; padding: 0.6em; font-size: 0.8em; overflow-x: auto; }
img { max-width: 100%; height: auto; } figure { margin: 0.8em 0; }
figcaption { font-size: 0.8em; color: #555; } .note { color: #8a4b00; }
#provenance-table td { text-align: left; font-size: 0.85em; }
"""


def page(title, sections):
    body = "\n".join(f'<section id="{sid}"><h2>{html.escape(heading)}</h2>\n{content}</section>'
                     for sid, heading, content in sections)
    return (f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
            f"<title>{html.escape(title)}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n"
            f"<h1>{html.escape(title)}</h1>\n{body}\n</body>\n</html>\n")


def sha256(path):
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 16), b""):
            digest.update(block)
    return digest.hexdigest()


def provenance(runner, argv, scene, scene_text, started):
    version = subprocess.run([runner.sim, "--version"], capture_output=True, text=True).stdout
    rows = [("conescan", version.strip()),
            ("command", shlex.join(["scripts/study-report.py"] + argv)),
            ("started", started), ("host", socket.gethostname())]
    commit = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty", "--abbrev=40"],
                            capture_output=True, text=True)
    rows.append(("source tree", commit.stdout.strip() if commit.returncode == 0 else "not a git tree"))
    inputs = []
    for key in ("tle", "omm", "oem", "aem", "attitude-csv", "eop", "apply"):
        value = scene_value(scene_text, key)
        if value:
            inputs.append((f"--{key}", value))
    for k, token in enumerate(scene):
        if token == "--config" and k + 1 < len(scene):
            inputs.append(("--config", scene[k + 1]))
        elif token.startswith("--config="):
            inputs.append(("--config", token.split("=", 1)[1]))
    for option, path in inputs:
        rows.append((f"input {option}", f"{path} sha256 {sha256(path)}"))
    rows += [(f"run {k + 1}", command) for k, command in enumerate(runner.commands)]
    return rows


def screenshot(out):
    """The page as headless Chromium draws it, 1280 px wide (at most 60 s)."""
    chromium = shutil.which("chromium")
    if not chromium:
        raise RuntimeError("no chromium on PATH (scripts/setup.sh installs it)")
    with tempfile.TemporaryDirectory() as profile:
        target = os.path.join(out, "screenshot.png")
        command = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                   "--no-first-run", "--disable-background-networking",
                   "--disable-component-update", "--disable-sync", f"--user-data-dir={profile}",
                   "--hide-scrollbars", "--window-size=1280,2400", f"--screenshot={target}",
                   "file://" + os.path.abspath(os.path.join(out, "index.html"))]
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                   start_new_session=True)
        try:
            _, error = process.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            raise RuntimeError("chromium did not finish within 60 s")
        if process.returncode != 0 or not os.path.exists(target):
            raise RuntimeError(f"chromium failed: {error.decode(errors='replace')[-500:]}")


def build(args, argv, out, final):
    started = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    runner = Runner(args.sim, out, final)
    scene = args.scene
    config = runner.run(scene + ["--print-config"], "the scene").stdout
    with open(os.path.join(out, "scene.toml"), "w") as f:
        f.write(config)
    heads = config.count("[[head]]")
    source = next((f"--{k} {scene_value(config, k)}" for k in ("tle", "omm", "oem")
                   if scene_value(config, k)), "classical elements")
    summary = (f"orbit from {source}; {heads} head(s); earth {scene_value(config, 'earth')}, "
               f"model {scene_value(config, 'model')}, sensor preset "
               f"{scene_value(config, 'sensor-preset') or 'none'}, step "
               f"{scene_value(config, 'step-s')} s over "
               f"{scene_value(config, 'duration-s') or scene_value(config, 'orbits') + ' orbit(s)'}")
    sections = [("scene", "The scene",
                 f"<p>{html.escape(summary)}. The whole scene as <code>conescan-sim "
                 '--print-config</code> writes it (<a href="scene.toml">scene.toml</a>; it reads '
                 "back to the same rows):</p>"
                 f"<details><summary>scene.toml</summary><pre>{html.escape(config)}</pre>"
                 "</details>")]
    budget = budget_section(runner, scene, out)
    columns = [("source", "source", False), ("rows", "rows", True), ("ok", "ok", True),
               ("roll_rms_deg", "roll RMS (deg)", True), ("roll_3sigma_deg", "roll 3σ (deg)", True),
               ("pitch_rms_deg", "pitch RMS (deg)", True),
               ("pitch_3sigma_deg", "pitch 3σ (deg)", True)]
    sections.append(("budget", "The error budget",
                     "<p>Each error source alone, all of them, and the sum of their errors, row by "
                     "row (<code>--budget --summary</code>, the system solution; RMS includes "
                     "the mean, 3σ is three standard deviations about it; "
                     '<a href="budget.csv">budget.csv</a> holds every statistic).</p>' +
                     table(budget, columns, "RMS and 3σ of each source", "budget-table") +
                     image(out, "budget.png", "Each source's RMS of roll and pitch")))
    worst = worst_day_section(runner, scene, out)
    sections.append(("worst-day", "The worst day",
                     f"<p>Of the scene's {worst['all_rows']} rows, day {worst['day']} from the "
                     f"epoch holds the largest |system error|, "
                     f"<span id=\"worst-error\" data-value=\"{worst['largest_deg']!r}\">"
                     f"{worst['largest_deg']:.4g}</span> deg; its {worst['rows']} rows are "
                     '<a href="worst-day.csv">worst-day.csv</a>.</p>' +
                     image(out, "worst-day.png", "Roll and pitch errors over the worst day")))
    try:
        seasons = calendar_section(runner, scene, out, args.calendar_days)
        columns = [("head", "head", False), ("body", "body", False),
                   ("on_cone_days", "days on the cone", True), ("lost_days", "days lost", True),
                   ("first_lost_day", "first", True), ("last_lost_day", "last", True),
                   ("lost_events", "events", True), ("lost_s", "time lost (s)", True),
                   ("longest_event_s", "longest event (s)", True)]
        content = (f"<p>The Sun and the Moon over {args.calendar_days} days from the epoch "
                   "(<code>--calendar</code>, at 1 s, edges to 1 ms; "
                   '<a href="calendar/lost.csv">every event</a>, '
                   '<a href="calendar/days.csv">every day</a>).</p>' +
                   table(seasons, columns, "The seasons of each head and body", "calendar-table") +
                   image(out, "calendar/calendar.png", "The blinding calendar"))
    except Refused as refusal:
        content = f'<p class="note">No calendar: {html.escape(str(refusal))}</p>'
    sections.append(("calendar", "The blinding calendar", content))
    attitude_file = scene_value(config, "aem") or scene_value(config, "attitude-csv")
    if attitude_file:
        content = (f'<p class="note">No map: the attitude comes from {html.escape(attitude_file)}'
                   ", not from constant angles the map could offset.</p>")
    else:
        stability = stability_section(runner, scene, out, config, args.map_points)
        content = (f"<p>Each head's status, and the system's, at the epoch with the attitude "
                   f"offset in roll and pitch by up to ±{stability['half']:g}° "
                   f"({stability['points']} × {stability['points']} points; the dashed square "
                   f"is the attitude envelope, ±{stability['envelope']:g}°); statuses seen: "
                   f"{', '.join(stability['seen'])} "
                   '(<a href="stability.csv">stability.csv</a>).</p>' +
                   image(out, "stability.png", "The heads' statuses over the attitude offsets"))
    sections.append(("stability", "The stability map", content))
    rows = provenance(runner, argv, scene, config, started)
    with open(os.path.join(out, "provenance.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["what", "value"])
        writer.writerows(rows)
    sections.append(("provenance", "Provenance",
                     "<table id=\"provenance-table\"><tbody>" +
                     "".join(f"<tr><th>{html.escape(k)}</th><td><code>{html.escape(v)}</code>"
                             f"</td></tr>" for k, v in rows) + "</tbody></table>"))
    with open(os.path.join(out, "index.html"), "w") as f:
        f.write(page(args.title or "conescan mission study", sections))
    if args.screenshot:
        screenshot(out)


def sim_path():
    sim = os.environ.get("CONESCAN_SIM") or os.path.join(ROOT, "build", "conescan-sim")
    if os.path.exists(sim):
        return sim
    say("building conescan-sim (minutes when nothing is built yet)")
    subprocess.run([os.path.join(ROOT, "scripts", "build.sh"), "--target", "conescan-sim"],
                   check=True, stdout=subprocess.DEVNULL)
    return sim


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--calendar-days", type=int, default=365)
    parser.add_argument("--map-points", type=int, default=41)
    parser.add_argument("--screenshot", action="store_true")
    parser.add_argument("--title", default="")
    parser.add_argument("out", metavar="OUTDIR")
    parser.add_argument("scene", nargs=argparse.REMAINDER, metavar="SCENE-OPTIONS")
    argv = sys.argv[1:]
    args = parser.parse_args()
    if not 1 <= args.calendar_days <= 3660 or not 3 <= args.map_points <= 201:
        parser.error("--calendar-days takes 1 to 3660, --map-points 3 to 201")
    for token in args.scene:
        if token.split("=", 1)[0] in RUN_MODES:
            parser.error(f"{token}: the report runs the scene its own ways; give the scene only")
    out = args.out.rstrip("/") or args.out
    if os.path.exists(out) and os.listdir(out) and not os.path.exists(os.path.join(out, "index.html")):
        parser.error(f"{out} holds files and no report: give a new or empty folder")
    args.sim = sim_path()
    work = tempfile.mkdtemp(prefix=os.path.basename(out) + ".tmp-",
                            dir=os.path.dirname(os.path.abspath(out)))
    start = time.monotonic()
    try:
        build(args, argv, work, out)
    except Refused as refusal:
        shutil.rmtree(work)
        print(refusal, file=sys.stderr)
        sys.exit(2)
    except BaseException:
        shutil.rmtree(work)
        raise
    os.chmod(work, 0o755)
    if os.path.exists(out):
        shutil.rmtree(out)
    os.rename(work, out)
    say(f"wrote {out}/index.html in {time.monotonic() - start:.1f} s")


if __name__ == "__main__":
    main()
