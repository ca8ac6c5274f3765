#!/usr/bin/python3
"""Plots a telemetry CSV of `cerebellum sim --telemetry FILE.csv` into PNG files.

usage: scripts/plot_telemetry.py FILE.csv --out DIR
writes DIR/body_height.png, velocity_tracking.png, joint_torques.png, temperatures.png, battery.png.
Needs Debian's python3-matplotlib (run with /usr/bin/python3). Columns named truth_* are
simulator truth (tools only); est_* are the MC's estimator; cmd_* are drawn when present.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LEGS = ("fr", "fl", "rr", "rl")
JOINTS = ("abad", "hip", "knee")


def read_columns(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if not header or "time_s" not in header:
            raise ValueError(f"{path}: not a cerebellum telemetry file (no time_s column)")
        columns = {name: [] for name in header}
        for line, row in enumerate(reader, start=2):
            if len(row) != len(header):
                raise ValueError(f"{path}:{line}: {len(row)} fields, the header has {len(header)}")
            for name, value in zip(header, row):
                columns[name].append(float(value))
    if not columns["time_s"]:
        raise ValueError(f"{path}: no rows")
    return columns


def mode_changes(columns):
    """(time, mode) at the start and wherever the mode changes."""
    t, mode = columns["time_s"], columns["mode"]
    return [(t[i], int(mode[i])) for i in range(len(t)) if i == 0 or mode[i] != mode[i - 1]]


def mark_modes(axis, columns):
    for time_s, mode in mode_changes(columns):
        axis.axvline(time_s, color="0.6", linewidth=0.8, linestyle=":")
        axis.annotate(f"mode {mode}", (time_s, 1.0), xycoords=("data", "axes fraction"),
                      fontsize=7, color="0.4", rotation=90, va="top", ha="right")


def save(figure, out_dir, name):
    path = os.path.join(out_dir, name)
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)
    return path


def plot_height(columns, out_dir):
    figure, axis = plt.subplots(figsize=(9, 4))
    t = columns["time_s"]
    axis.plot(t, columns["est_height_m"], label="estimated (above the stance feet)")
    axis.plot(t, columns["truth_z_m"], label="truth (simulator)", linestyle="--")
    axis.set_xlabel("time (s)")
    axis.set_ylabel("trunk height (m)")
    axis.set_title("body height")
    mark_modes(axis, columns)
    axis.legend(loc="lower right")
    axis.grid(alpha=0.3)
    return save(figure, out_dir, "body_height.png")


def plot_velocity(columns, out_dir):
    figure, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    t = columns["time_s"]
    rows = (("vx", "m/s", "forward velocity vx"), ("vy", "m/s", "lateral velocity vy"),
            ("wz", "rad/s", "yaw rate wz"))
    for axis, (name, unit, title) in zip(axes, rows):
        suffix = f"_{name}_{'rad_s' if unit == 'rad/s' else 'm_s'}"
        if "cmd" + suffix in columns:
            axis.plot(t, columns["cmd" + suffix], label="commanded", color="k", linewidth=1.2)
        axis.plot(t, columns["est" + suffix], label="estimated")
        axis.plot(t, columns["truth" + suffix], label="truth (simulator)", linestyle="--")
        axis.set_ylabel(unit)
        axis.set_title(title, fontsize=10)
        axis.grid(alpha=0.3)
        mark_modes(axis, columns)
    axes[0].legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("time (s)")
    figure.suptitle("velocity tracking (body frame)")
    return save(figure, out_dir, "velocity_tracking.png")


def plot_per_joint(columns, out_dir, quantity, unit_suffix, ylabel, title, name):
    figure, axes = plt.subplots(2, 2, figsize=(10, 6), sharex=True, sharey=True)
    t = columns["time_s"]
    for axis, leg in zip(axes.flat, LEGS):
        for joint in JOINTS:
            axis.plot(t, columns[f"{quantity}_{leg}_{joint}_{unit_suffix}"], label=joint)
        axis.set_title(leg.upper(), fontsize=10)
        axis.set_ylabel(ylabel)
        axis.grid(alpha=0.3)
    axes[0][0].legend(fontsize=8)
    for axis in axes[-1]:
        axis.set_xlabel("time (s)")
    figure.suptitle(title)
    return save(figure, out_dir, name)


def plot_battery(columns, out_dir):
    """State of charge and terminal voltage, with the times the health protection was on."""
    figure, axes = plt.subplots(2, 1, figsize=(10, 5), sharex=True)
    t = columns["time_s"]
    axes[0].plot(t, columns["battery_soc_percent"])
    axes[0].set_ylabel("state of charge (%)")
    axes[1].plot(t, columns["battery_v"])
    axes[1].set_ylabel("voltage (V)")
    protected = [c != 0 for c in columns["health_causes"]]
    for axis in axes:
        axis.grid(alpha=0.3)
        axis.fill_between(t, 0, 1, where=protected, transform=axis.get_xaxis_transform(), color="red", alpha=0.15,
                          label="health protection")
    axes[0].legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("time (s)")
    figure.suptitle("battery")
    return save(figure, out_dir, "battery.png")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="telemetry CSV from cerebellum sim --telemetry")
    parser.add_argument("--out", required=True, help="directory for the PNG files (created)")
    args = parser.parse_args(argv)
    try:
        columns = read_columns(args.csv)
    except (OSError, ValueError) as error:
        print(f"plot_telemetry: {error}", file=sys.stderr)
        return 1
    os.makedirs(args.out, exist_ok=True)
    written = [
        plot_height(columns, args.out),
        plot_velocity(columns, args.out),
        plot_per_joint(columns, args.out, "tau", "nm", "torque (N m)", "joint torques", "joint_torques.png"),
        plot_per_joint(columns, args.out, "temp", "c", "temperature (deg C)", "motor temperatures",
                       "temperatures.png"),
    ]
    if "battery_soc_percent" in columns:
        written.append(plot_battery(columns, args.out))
    for path in written:
        print(f"plot_telemetry: wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
