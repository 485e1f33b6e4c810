#!/usr/bin/python3
"""The pictures of docs/SENSOR_PHYSICS.md (MODEL §12), from the program's own numbers.

Runs `conescan-sensor-physics-speed --csv` (bench/sensor_physics_speed.cpp: the paper's head at
perigee of the paper's orbit, a 1.5 deg square field, 1 ms of lag at 1 rev/s, the normalised
locator at 1/2, H = 7 km, delta50 = 40 km), which prints, every 0.005 deg of scan azimuth over
the Earth-in crossing's window, the central line of sight's tangent height and radiance (the
pencil's signal), the field's mean s, the detector's output y, the locator's level and the
chain's crossing; and draws
  docs/sensor-physics-profile.png   the limb's radiance against the tangent height;
  docs/sensor-physics-crossing.png  the pencil's signal, the field's mean, the detector's output
                                    and the level across the crossing, with the crossings each
                                    would give.
Usage: scripts/sensor-physics-figures.py [BUILD_DIR]   (default build; Debian's python3-matplotlib)
"""
import csv
import io
import pathlib
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]


def window(build):
    program = pathlib.Path(build) / "bench" / "conescan-sensor-physics-speed"
    text = subprocess.run([str(program), "--csv"], check=True, capture_output=True,
                          text=True).stdout
    rows = list(csv.DictReader(io.StringIO(text)))
    return {name: [float(r[name]) for r in rows] for name in rows[0]}


def first_passage(phi, values, level):
    """The azimuth where `values` first rises through `level` (linear between samples)."""
    for k in range(1, len(values)):
        if values[k - 1] < level <= values[k]:
            t = (level - values[k - 1]) / (values[k] - values[k - 1])
            return phi[k - 1] + t * (phi[k] - phi[k - 1])
    return float("nan")


def profile_figure(w, out):
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    ax.plot(w["radiance"], w["height_km"], color="tab:blue")
    ax.axhline(40, color="grey", lw=0.8, ls="--")
    ax.text(0.02, 41, "delta50 = 40 km (l = 1/2)", color="grey", fontsize=8)
    ax.axhline(40 - 0.36651 * 7, color="grey", lw=0.8, ls=":")
    ax.text(0.02, 40 - 0.36651 * 7 - 3.5, "steepest: delta50 - 0.3665 H", color="grey",
            fontsize=8)
    ax.set_xlabel("radiance L / L0")
    ax.set_ylabel("tangent height delta (km)")
    ax.set_ylim(0, 100)
    ax.set_title("The limb profile, H = 7 km (MODEL §12)", fontsize=10)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def crossing_figure(w, out):
    phi = w["phi_deg"]
    crossing = w["crossing_deg"][0]
    keep = [k for k, p in enumerate(phi) if crossing - 3 <= p <= crossing + 2]
    x = [phi[k] - crossing for k in keep]

    def cut(name):
        return [w[name][k] for k in keep]

    level = w["level"][0]
    fig, ax = plt.subplots(figsize=(7, 4.4))
    ax.plot(x, cut("radiance"), label="pencil's signal l(delta(phi))", color="tab:blue")
    ax.plot(x, cut("field_mean"), label="field's mean s (1.5 deg square)", color="tab:orange")
    ax.plot(x, cut("output"), label="detector's output y (1 ms at 1 rev/s)", color="tab:green")
    ax.axhline(level, color="black", lw=0.8, ls="--", label="level: 1/2 of the peak")
    for name, color in (("radiance", "tab:blue"), ("field_mean", "tab:orange")):
        at = first_passage(phi, w[name], level) - crossing
        ax.axvline(at, color=color, lw=0.7, ls=":")
    ax.axvline(0, color="tab:green", lw=0.7, ls=":")
    ax.set_xlabel(f"scan azimuth - the chain's Earth-in crossing ({crossing:.6f} deg), deg")
    ax.set_ylabel("L / L0")
    ax.set_title("One Earth-in crossing: profile, field, lag, locator", fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build")
    w = window(build)
    profile_figure(w, ROOT / "docs" / "sensor-physics-profile.png")
    crossing_figure(w, ROOT / "docs" / "sensor-physics-crossing.png")
    level = w["level"][0]
    crossing = w["crossing_deg"][0]
    for name in ("radiance", "field_mean"):
        print(f"{name}: passes the level {first_passage(w['phi_deg'], w[name], level) - crossing:+.4f}"
              " deg from the chain's crossing")


if __name__ == "__main__":
    main()
