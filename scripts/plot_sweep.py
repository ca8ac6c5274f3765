#!/usr/bin/python3
"""Plots a sweep's results.csv (`cerebellum sweep`, docs/sweeps.md) into PNG files.

usage: scripts/plot_sweep.py DIR [--out PLOTS_DIR]
writes into PLOTS_DIR (default DIR/plots): outcomes_by_<axis>.png (the runs' outcomes per value of
each axis, stacked), falls.png (when each run first fell, in robot seconds, against its cell) and
max_tilt.png (the distribution of the runs' largest tilt). Needs Debian's python3-matplotlib (run
with /usr/bin/python3).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

OUTCOMES = ("ok", "moving", "stopped", "fell", "unsafe", "crashed")
COLOURS = {"ok": "tab:green", "moving": "tab:olive", "stopped": "tab:orange", "fell": "tab:red",
           "unsafe": "tab:purple", "crashed": "black"}
# the columns after the axes: everything from seed on is a measure, not an axis
FIRST_MEASURE = "seed"


def read_rows(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        header = reader.fieldnames or []
        if "cell" not in header or "outcome" not in header or FIRST_MEASURE not in header:
            raise ValueError(f"{path}: not a sweep's results.csv (no cell, seed or outcome column)")
        return header, list(reader)


def axes_of(header, rows):
    axes = header[1:header.index(FIRST_MEASURE)]
    # a seed axis is the seed column itself: plot it when the seeds vary
    if len({r["seed"] for r in rows}) > 1:
        axes.append("seed")
    return axes


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def plot_outcomes(rows, axis, out_dir):
    # numbers in their order; a terrain axis's specs (text) as the file listed them
    values = list(dict.fromkeys(r[axis] for r in rows))
    if all(is_number(v) for v in values):
        values.sort(key=float)
    fig, ax = plt.subplots(figsize=(max(4, 0.6 * len(values) + 2), 3.5))
    bottom = [0] * len(values)
    for outcome in OUTCOMES:
        counts = [sum(1 for r in rows if r[axis] == v and r["outcome"] == outcome) for v in values]
        if any(counts):
            ax.bar(values, counts, bottom=bottom, label=outcome, color=COLOURS[outcome])
            bottom = [b + c for b, c in zip(bottom, counts)]
    ax.set_xlabel(axis)
    ax.set_ylabel("runs")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, f"outcomes_by_{axis}.png"), dpi=100)
    plt.close(fig)


def plot_falls(rows, out_dir):
    fell = [(int(r["cell"]), float(r["first_fall_s"])) for r in rows if float(r["first_fall_s"]) >= 0]
    fig, ax = plt.subplots(figsize=(6, 3.5))
    if fell:
        ax.scatter([c for c, _ in fell], [t for _, t in fell], s=10, color=COLOURS["fell"])
    ax.set_xlabel("cell")
    ax.set_ylabel("first fall (robot s)")
    ax.set_title(f"{len(fell)} of {len(rows)} runs fell")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "falls.png"), dpi=100)
    plt.close(fig)


def plot_tilt(rows, out_dir):
    tilts = [float(r["max_tilt_deg"]) for r in rows if r["outcome"] != "crashed"]
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.hist(tilts, bins=30, color="tab:blue")
    ax.axvline(34.4, color=COLOURS["fell"], linestyle="--", label="fall (0.6 rad)")
    ax.set_xlabel("largest tilt of a run (deg)")
    ax.set_ylabel("runs")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "max_tilt.png"), dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="the sweep's output folder (holding results.csv)")
    parser.add_argument("--out", help="where the PNG files go (default DIR/plots)")
    args = parser.parse_args()
    try:
        header, rows = read_rows(os.path.join(args.dir, "results.csv"))
    except (OSError, ValueError) as e:
        sys.exit(f"plot_sweep: {e}")
    if not rows:
        sys.exit(f"plot_sweep: {args.dir}/results.csv has no runs yet")
    out_dir = args.out or os.path.join(args.dir, "plots")
    os.makedirs(out_dir, exist_ok=True)
    for axis in axes_of(header, rows):
        plot_outcomes(rows, axis, out_dir)
    plot_falls(rows, out_dir)
    plot_tilt(rows, out_dir)
    print(f"plot_sweep: {len(rows)} runs plotted into {out_dir}")


if __name__ == "__main__":
    main()
