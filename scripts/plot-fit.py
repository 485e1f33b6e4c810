#!/usr/bin/python3
"""Pictures of a conescan-fit result (docs/CALIBRATION.md, "Pictures").

    conescan-fit ... --json --residuals residuals.csv > fit.json
    scripts/plot-fit.py fit.json OUTDIR [--residuals residuals.csv]
                        [--truth NAME=FILE:COLUMN] [--title TEXT]

writes into OUTDIR:
  residuals-hK.png   per head: chord and phase residuals against time and against the
                     satellite's latitude: every measurement as a faint dot (at most 8 000,
                     evenly thinned), the median and the 16-84 % band of each bin (100 bins of
                     time, 2 deg of latitude), the outliers (normalised residual above the fit's
                     threshold) in red; needs --residuals
  correlation.png    the correlation matrix of the estimated values (parameter_order), withheld
                     ones grey
  drift-NAME.png     per drifting parameter (--free NAME@SECONDS): each segment's estimate with
                     its 1 sigma band against time; with --truth NAME=FILE:COLUMN (a CSV with
                     start_s and COLUMN, one row per segment) the truth over it and, below, each
                     segment's estimate - truth with the 1 sigma band

Reads only the JSON and the CSV: matplotlib and numpy (Debian's python3-matplotlib, hence
Debian's interpreter in the first line: a virtual environment's python3 first in PATH may have neither).
Writes as conescan's programs do (docs/RELIABILITY.md): a picture is never a file read here, nor
a read-only file; each is written to a temporary file beside it and renamed over it when whole;
bad input exits 2 and a write error 1, each with one line naming the file, never a traceback.
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DOT_LIMIT = 8000
INPUTS = []  # the files read, which no picture may replace


def fail(status, message):
    print("plot-fit.py: " + message, file=sys.stderr)
    sys.exit(status)


def save(fig, path):
    """fig as PNG at path: a temporary file beside it, renamed over it once written whole."""
    if os.path.lexists(path):
        for read in INPUTS:
            if os.path.exists(read) and os.path.samefile(path, read):
                fail(2, f"{path!r} is a file this run reads: give OUTDIR of its own")
        mode = os.stat(path).st_mode
        if not os.path.isfile(path) or not (mode & 0o222) or not os.access(path, os.W_OK):
            fail(1, f"cannot write {path!r}: not a regular file we may write")
    temporary = f"{path}.tmp-{os.getpid()}"
    try:
        fig.savefig(temporary, dpi=110, format="png")
        os.replace(temporary, path)
    except OSError as error:
        if os.path.lexists(temporary):
            os.remove(temporary)
        fail(1, f"cannot write {path!r}: {error.strerror or error}")
    finally:
        plt.close(fig)
TIME_BINS = 100
LATITUDE_BIN_DEG = 2.0


def time_axis(t_s):
    """Times in hours, or in days beyond three days, with the label."""
    span = float(np.nanmax(t_s) - np.nanmin(t_s)) if len(t_s) else 0.0
    if span > 3 * 86400:
        return t_s / 86400.0, "t (days)"
    return t_s / 3600.0, "t (h)"


def binned(x, y, edges):
    """Per bin of x: centre, median, 16 % and 84 % quantiles of y (bins with data only)."""
    index = np.digitize(x, edges) - 1
    rows = []
    for b in range(len(edges) - 1):
        values = y[index == b]
        values = values[np.isfinite(values)]
        if len(values) == 0:
            continue
        rows.append(((edges[b] + edges[b + 1]) / 2, *np.percentile(values, [50, 16, 84])))
    return np.array(rows).reshape(-1, 4)


def residual_panel(ax, x, y, outlier, edges, xlabel, ylabel):
    finite = np.isfinite(y)
    step = max(1, int(np.count_nonzero(finite) / DOT_LIMIT))
    ax.plot(x[finite][::step], y[finite][::step], ".", ms=1.5, alpha=0.25, color="tab:blue",
            rasterized=True, label="measurements" if step == 1 else f"every {step}th measurement")
    b = binned(x, y, edges)
    if len(b):
        ax.fill_between(b[:, 0], b[:, 2], b[:, 3], color="tab:orange", alpha=0.35,
                        label="16-84 % of each bin")
        ax.plot(b[:, 0], b[:, 1], "-", color="tab:orange", lw=1.5, label="median of each bin")
    if np.any(outlier):
        ax.plot(x[outlier], y[outlier], "x", color="tab:red", ms=4, label="outliers")
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)


def plot_residuals(fit, path, outdir, title):
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if data.size == 0:
        return []
    t, head, lat = data[:, 0], data[:, 2], data[:, 3]
    chord, phase, normalised, fitted = data[:, 4], data[:, 5], data[:, 6], data[:, 7]
    threshold = fit["outliers"]["threshold"]
    noise = fit.get("noise", {})
    written = []
    for k in sorted(set(head.astype(int))):
        on = head == k
        x_t, t_label = time_axis(t[on])
        time_edges = np.linspace(np.min(x_t), np.max(x_t) + 1e-9, TIME_BINS + 1)
        lat_edges = np.arange(-90.0, 90.0 + LATITUDE_BIN_DEG, LATITUDE_BIN_DEG)
        outlier = (normalised[on] > threshold) & (fitted[on] == 1)
        fig, axes = plt.subplots(2, 2, figsize=(12, 7.5), sharey="row")
        name = f"h{k}"
        for row, (values, what) in enumerate(((chord[on], "chord"), (phase[on], "phase"))):
            residual_panel(axes[row][0], x_t, values, outlier, time_edges, t_label,
                           f"{what} residual (deg)")
            residual_panel(axes[row][1], lat[on], values, outlier, lat_edges,
                           "geocentric latitude (deg)", "")
        rms = fit["residual_rms_deg"].get(name)
        n = noise.get(name, {})
        subtitle = f"{name}: {int(np.count_nonzero(on))} measurements, residual RMS {rms:.4g} deg"
        if n.get("estimated_deg") is not None:
            subtitle += f", estimated crossing noise {n['estimated_deg']:.4g} deg"
        if n.get("declared_deg"):
            subtitle += f" (declared {n['declared_deg']:.4g})"
        fig.suptitle((title + "\n" if title else "") + subtitle)
        axes[0][0].legend(loc="upper right", fontsize=7, markerscale=4)
        fig.tight_layout()
        out = os.path.join(outdir, f"residuals-{name}.png")
        save(fig, out)
        plt.close(fig)
        written.append(out)
    return written


def plot_correlation(fit, outdir, title):
    names = fit["parameter_order"]
    if len(names) < 2:
        return []
    c = np.array([[np.nan if v is None else v for v in row] for row in fit["correlation"]])
    size = min(11, 4 + 0.25 * len(names))
    fig, ax = plt.subplots(figsize=(size + 1.5, size))
    cmap = plt.get_cmap("RdBu_r").copy()
    cmap.set_bad("0.8")
    image = ax.imshow(np.ma.masked_invalid(c), cmap=cmap, vmin=-1, vmax=1)
    ax.set_xticks(range(len(names)))
    ax.set_yticks(range(len(names)))
    font = 8 if len(names) <= 20 else 5
    ax.set_xticklabels(names, rotation=90, fontsize=font)
    ax.set_yticklabels(names, fontsize=font)
    if len(names) <= 12:
        for i in range(len(names)):
            for j in range(len(names)):
                if np.isfinite(c[i, j]):
                    ax.text(j, i, f"{c[i, j]:.2f}", ha="center", va="center", fontsize=7,
                            color="w" if abs(c[i, j]) > 0.6 else "k")
    fig.colorbar(image, ax=ax, shrink=0.8, label="correlation")
    ax.set_title((title + "\n" if title else "") +
                 f"correlation of the estimated values (condition number {fit['condition']:.3g})")
    fig.tight_layout()
    out = os.path.join(outdir, "correlation.png")
    save(fig, out)
    plt.close(fig)
    return [out]


def read_truth(spec):
    """NAME=FILE:COLUMN -> (NAME, start_s array, value array)."""
    name, rest = spec.split("=", 1)
    path, column = rest.rsplit(":", 1)
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return name, np.array([float(r["start_s"]) for r in rows]), np.array(
        [float(r[column]) for r in rows])


def plot_drift(fit, truths, outdir, title):
    written = []
    for name, history in fit.get("drift", {}).items():
        segments = history["segments"]
        start = np.array([s["start_s"] for s in segments])
        end = np.array([s["end_s"] for s in segments])
        estimate = np.array([np.nan if s["estimate"] is None else s["estimate"] for s in segments])
        sigma = np.array([np.nan if s["sigma"] is None else s["sigma"] for s in segments])
        middle, t_label = time_axis((start + end) / 2)
        truth = truths.get(name)
        rows = 2 if truth is not None else 1
        fig, axes = plt.subplots(rows, 1, figsize=(10, 4.5 * rows), sharex=True, squeeze=False)
        ax = axes[0][0]
        # A band thinner than a few pixels of this axis would be drawn and not seen (30 days of
        # the season: 1 sigma 0.0008 km on a 2 km axis): the legend says where it is shown.
        spread = float(np.nanmax(estimate) - np.nanmin(estimate)) if np.any(np.isfinite(estimate)) else 0.0
        visible = not spread > 0 or np.nanmedian(sigma) > 0.01 * spread
        if visible:
            ax.fill_between(middle, estimate - sigma, estimate + sigma, color="tab:blue",
                            alpha=0.3, step=None, label="estimate ± 1σ")
        ax.errorbar(middle, estimate, yerr=sigma, fmt="o", ms=3, color="tab:blue", capsize=2,
                    label=None if visible else
                    "estimate (its ± 1σ is too small to see at this scale" +
                    ("; below, against the truth)" if truth is not None else ")"))
        if truth is not None:
            t_start, t_value = truth[1], truth[2]
            on_segments = np.interp(start, t_start, t_value)
            ax.plot(middle, on_segments, "-", color="k", lw=1, label="truth (segment mean)")
            z = (estimate - on_segments) / sigma
            low = axes[1][0]
            low.fill_between(middle, -sigma, sigma, color="tab:blue", alpha=0.3, label="± 1σ")
            low.errorbar(middle, estimate - on_segments, yerr=sigma, fmt="o", ms=3,
                         color="tab:blue", capsize=2, label="estimate − truth")
            low.axhline(0, color="k", lw=0.5)
            low.set_ylabel(f"estimate − truth ({history['unit']})")
            low.set_xlabel(t_label)
            low.grid(alpha=0.3)
            low.legend(fontsize=8)
            inside = np.count_nonzero(np.abs(z) <= 1)
            low.set_title(f"{inside} of {len(z)} segments within 1σ of the truth; (estimate − truth)"
                          f" / 1σ: mean {np.mean(z):.2f}, rms {np.sqrt(np.mean(z * z)):.2f}, "
                          f"largest {np.max(np.abs(z)):.2f}")
        else:
            ax.set_xlabel(t_label)
        ax.set_ylabel(f"{name} ({history['unit']})")
        ax.set_title((title + "\n" if title else "") +
                     f"{name}: one value per {history['segment_s']:g} s, 1σ "
                     f"{np.nanmedian(sigma):.3g} {history['unit']} (median)")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        out = os.path.join(outdir, f"drift-{name}.png")
        save(fig, out)
        plt.close(fig)
        written.append(out)
    return written


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("fit", help="conescan-fit --json's output")
    parser.add_argument("outdir")
    parser.add_argument("--residuals", help="conescan-fit --residuals FILE")
    parser.add_argument("--truth", action="append", default=[], metavar="NAME=FILE:COLUMN")
    parser.add_argument("--title", default="")
    args = parser.parse_args(argv)
    INPUTS.extend([args.fit] + ([args.residuals] if args.residuals else []) +
                  [spec.partition("=")[2].rpartition(":")[0] for spec in args.truth])
    try:
        with open(args.fit) as f:
            fit = json.load(f)
    except OSError as error:
        fail(2, f"cannot read {args.fit!r}: {error.strerror}")
    except ValueError as error:
        fail(2, f"{args.fit!r} is not JSON: {error}")
    if not isinstance(fit, dict) or fit.get("kind") != "fit" or not fit.get("converged"):
        fail(2, f"{args.fit!r} is not a converged fit's JSON")
    if os.path.lexists(args.outdir) and not os.path.isdir(args.outdir):
        fail(2, f"OUTDIR {args.outdir!r} is not a directory")
    try:
        os.makedirs(args.outdir, exist_ok=True)
    except OSError as error:
        fail(1, f"cannot make OUTDIR {args.outdir!r}: {error.strerror}")
    truths = {}
    for spec in args.truth:
        name, start, value = read_truth(spec)
        truths[name] = (name, start, value)
    written = plot_correlation(fit, args.outdir, args.title)
    written += plot_drift(fit, truths, args.outdir, args.title)
    if args.residuals:
        written += plot_residuals(fit, args.residuals, args.outdir, args.title)
    for path in written:
        print(path)


if __name__ == "__main__":
    main(sys.argv[1:])
