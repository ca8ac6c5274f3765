#!/usr/bin/python3
"""Plots commanded vs estimated vs true velocity of the locomotion benchmark's scenarios.

usage: bench/plot_locomotion.py [CSV] [PNG]
  CSV defaults to build/bench/results/locomotion_velocity.csv (written by locomotion_bench),
  PNG to docs/images/locomotion_velocity.png.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCENARIOS = [  # (scenario label in the CSV, channel plotted, axis label)
    ("forward 0.3 m/s", "vx", "vx (m/s)"),
    ("forward 0.8 m/s", "vx", "vx (m/s)"),
    ("forward 1.2 m/s", "vx", "vx (m/s)"),
    ("forward 1.6 m/s", "vx", "vx (m/s)"),
    ("lateral 0.4 m/s", "vy", "vy (m/s)"),
    ("yaw 2.0 rad/s", "wz", "yaw rate (rad/s)"),
]


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else "build/bench/results/locomotion_velocity.csv"
    target = sys.argv[2] if len(sys.argv) > 2 else "docs/images/locomotion_velocity.png"
    series = defaultdict(lambda: defaultdict(list))
    with open(source, newline="") as f:
        for row in csv.DictReader(f):
            data = series[row["scenario"]]
            for key, value in row.items():
                if key != "scenario":
                    data[key].append(float(value))
    figure, axes = plt.subplots(3, 2, figsize=(11, 9), sharex=True)
    for axis, (label, channel, unit) in zip(axes.flat, SCENARIOS):
        data = series.get(label)
        if data is None:
            axis.set_title(f"{label}: no data")
            continue
        t = data["t"]
        axis.plot(t, data[f"{channel}_cmd"], "k--", label="commanded")
        axis.plot(t, data[f"{channel}_true"], color="tab:blue", linewidth=0.8, label="true (simulator)")
        axis.plot(t, data[f"{channel}_est"], color="tab:orange", linewidth=0.8, label="estimated")
        axis.set_title(label)
        axis.set_ylabel(unit)
        axis.grid(alpha=0.3)
    for axis in axes[-1]:
        axis.set_xlabel("time since the command (s)")
    axes[0][0].legend(loc="lower right", fontsize=8)
    figure.suptitle("cerebellum locomotion: commanded vs estimated vs true velocity")
    figure.tight_layout()
    figure.savefig(target, dpi=90)
    print(target)


if __name__ == "__main__":
    main()
