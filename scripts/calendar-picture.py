#!/usr/bin/python3
"""The picture of a blinding calendar (conescan-sim --calendar DIR; docs/SUN_MOON.md).

    scripts/calendar-picture.py OUT.png DIR[=LABEL] [DIR[=LABEL] ...] [--title TEXT]
                                [--width-px W] [--height-px H]

One panel per calendar directory (a row) and head (a column): the day of the calendar against
where in the orbit the event starts (the argument of latitude, deg: 0 at the ascending node; on a
circular orbit minutes since the node times 360 / the period). Shaded: the days a body is on the
head's cone (on-cone.csv: the Sun orange, the Moon light blue; an interval narrower than a tenth
of a day is drawn a tenth of a day wide). Dots: each interval in which the body takes the head's
crossings (lost.csv: the Sun red, the Moon blue), at its start. Each panel's legend, below it,
lists only what occurs in it, with the number of events and the time they take (seconds of lost
crossings are not visible as dots). Reads only the CSV files: matplotlib (Debian's
python3-matplotlib).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

COLOURS = {  # body: (on the cone, lost)
    "sun": ("#f5c26b", "#d62728"),
    "moon": ("#b9d7ee", "#1f4e99"),
}
NARROWEST_DAYS = 0.1


def read_csv(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"calendar-picture: cannot read {path}: {e.strerror}")


def duration_text(seconds):
    if seconds >= 3600:
        return f"{seconds / 3600:.2f} h"
    if seconds >= 60:
        return f"{seconds / 60:.1f} min"
    return f"{seconds:.1f} s"


def calendar_of(directory):
    """The four tables of one calendar directory, and its heads and days."""
    tables = {name: read_csv(os.path.join(directory, name + ".csv"))
              for name in ("lost", "on-cone", "days", "seasons")}
    heads = sorted({row["head"] for row in tables["seasons"]}, key=lambda h: int(h[1:]))
    days = max((int(row["day"]) for row in tables["days"]), default=1)
    first_date = next((row["date"] for row in tables["days"] if row["day"] == "1"), "")
    return tables, heads, days, first_date


def draw_panel(ax, tables, head, days):
    """One head's panel; returns the legend's handles."""
    handles = []
    for body in ("sun", "moon"):
        cone, lost = COLOURS[body]
        spans = [r for r in tables["on-cone"] if r["head"] == head and r["body"] == body]
        for r in spans:
            start = float(r["start_s"]) / 86400 + 1
            end = max(float(r["end_s"]) / 86400 + 1, start + NARROWEST_DAYS)
            ax.axvspan(start, end, color=cone, alpha=0.8 if body == "sun" else 0.6, lw=0)
        if spans:
            on_days = next(int(r["on_cone_days"]) for r in tables["seasons"]
                           if r["head"] == head and r["body"] == body)
            handles.append(Patch(color=cone, label=f"{body.capitalize()} on the cone: "
                                                   f"{on_days} days"))
        events = [r for r in tables["lost"] if r["head"] == head and r["body"] == body]
        if events:
            x = [float(r["start_s"]) / 86400 + 1 for r in events]
            y = [float(r["start_orbit_deg"]) for r in events]
            ax.plot(x, y, "o", ms=2.2 if body == "sun" else 3.5, color=lost, lw=0)
            total = sum(float(r["duration_s"]) for r in events)
            handles.append(Line2D([], [], marker="o", lw=0, color=lost,
                                  label=f"crossings lost to the {body.capitalize()}: "
                                        f"{len(events)} events, {duration_text(total)}"))
    ax.set_xlim(1, days + 1)
    ax.set_ylim(0, 360)
    ax.set_yticks(range(0, 361, 90))
    ax.grid(color="#eeeeee", lw=0.6)
    ax.set_axisbelow(True)
    if not handles:
        handles.append(Patch(color="white", label="neither body on the cone"))
    return handles


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output")
    parser.add_argument("calendars", nargs="+", metavar="DIR[=LABEL]")
    parser.add_argument("--title", default="")
    parser.add_argument("--width-px", type=int, default=0)
    parser.add_argument("--height-px", type=int, default=0)
    args = parser.parse_args()
    calendars = []
    for spec in args.calendars:
        directory, _, label = spec.partition("=")
        calendars.append((calendar_of(directory), label))
    columns = max(len(heads) for (_, heads, _, _), _ in calendars)
    rows = len(calendars)
    dpi = 100
    width = args.width_px or 600 * columns
    height = args.height_px or 420 * rows
    fig, axes = plt.subplots(rows, columns, figsize=(width / dpi, height / dpi), dpi=dpi,
                             squeeze=False)
    for row, ((tables, heads, days, first_date), label) in enumerate(calendars):
        for column in range(columns):
            ax = axes[row][column]
            if column >= len(heads):
                ax.axis("off")
                continue
            head = heads[column]
            handles = draw_panel(ax, tables, head, days)
            ax.set_title(f"{label}{', ' if label else ''}head {head}", fontsize=10)
            ax.set_xlabel(f"day of the calendar (day 1: {first_date})", fontsize=9)
            ax.set_ylabel("argument of latitude (deg)", fontsize=9)
            ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.16),
                      ncol=1, fontsize=8, frameon=False)
    if args.title:
        fig.suptitle(args.title, fontsize=11)
    fig.tight_layout()
    fig.savefig(args.output, dpi=dpi)
    print(f"calendar-picture: wrote {args.output}", file=sys.stderr)


if __name__ == "__main__":
    main()
