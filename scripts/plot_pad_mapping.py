#!/usr/bin/env python3
"""Draws the gamepad mapping of `cerebellum drive` (docs/images/pad_mapping.png) from the mapping
the program prints, so the picture has the same one home as the help and docs/driving.md
(kButtonBindings, src/cli/pad_mapping.hpp).

    scripts/plot_pad_mapping.py build/src/cli/cerebellum docs/images/pad_mapping.png
"""
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle, FancyBboxPatch  # noqa: E402

# where each control sits on the drawn pad (x, y), and where its label goes (x, y, alignment)
PLACES = {
    "left stick": ((3.0, 3.0), (-0.2, 1.2, "right")),
    "right stick": ((7.0, 1.8), (10.2, 0.4, "left")),
    "RT / LT": ((5.0, 6.1), (5.0, 7.4, "center")),
    "LB": ((2.0, 5.6), (-0.2, 5.9, "right")),
    "RB": ((8.0, 5.6), (10.2, 6.4, "left")),
    "Y": ((8.0, 4.0), (10.2, 5.2, "left")),
    "X": ((7.3, 3.3), (10.2, 4.4, "left")),
    "B": ((8.7, 3.3), (10.2, 3.6, "left")),
    "A": ((8.0, 2.6), (10.2, 2.8, "left")),
}


def mapping_lines(exe):
    text = subprocess.run([exe, "drive", "--help"], check=True, capture_output=True, text=True).stdout
    lines = text[text.index("mapping ("):].splitlines()[1:]
    # a control's line: two spaces, the control in 12 columns, a space, what it does; a longer
    # first column (the walking gaits) is a note as it stands
    return [(line[2:14].strip(), line[15:].strip()) if line[14:15] == " " else ("", line.strip()) for line in lines]


def main():
    exe, out = sys.argv[1], sys.argv[2]
    fig, ax = plt.subplots(figsize=(13, 6.5))
    ax.add_patch(FancyBboxPatch((1.0, 1.0), 8.0, 4.6, boxstyle="round,pad=0.4", fc="#eeeeee", ec="#555555"))
    for name, ((x, y), _) in PLACES.items():
        if name.endswith("stick"):
            ax.add_patch(Circle((x, y), 0.55, fc="#bbbbbb", ec="#333333"))
        elif name in ("LB", "RB"):
            ax.add_patch(FancyBboxPatch((x - 0.6, y - 0.15), 1.2, 0.3, boxstyle="round,pad=0.05", fc="#cccccc"))
        elif name != "RT / LT":
            ax.add_patch(Circle((x, y), 0.3, fc="#ffffff", ec="#333333"))
        ax.text(x, y, name.replace(" stick", "").replace("RT / LT", "triggers LT, RT"), ha="center",
                va="center", fontsize=9)
    footnotes = []
    for name, what in mapping_lines(exe):
        if name in PLACES:
            (x, y), (lx, ly, align) = PLACES[name]
            ax.annotate("%s: %s" % (name, what), (x, y), (lx, ly), ha=align, va="center", fontsize=9,
                        arrowprops={"arrowstyle": "-", "color": "#888888"})
        else:
            footnotes.append(("%s: %s" % (name, what)) if name else what)
    ax.text(5.0, -0.6, "\n".join(footnotes), ha="center", va="top", fontsize=9)
    ax.set_xlim(-6.5, 16.5)
    ax.set_ylim(-2.0, 8.0)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("cerebellum drive: the gamepad mapping (SDL's Xbox layout)")
    fig.savefig(out, dpi=80, bbox_inches="tight")


if __name__ == "__main__":
    main()
