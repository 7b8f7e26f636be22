#!/usr/bin/env python3
"""The wall and its symbols (docs/img/wall-sketch.svg): a VSSW at rest with its dimensions 2b, 2h1, 2h2, the angles
alpha1 and alpha2, the hinge, the roller and N; beside it the same wall rocking, with theta1 and theta2. Both drawn by
the animation's own code (python/vssw/_wall_drawing.py) from the geometry and the rotations the analytic model gives
(vssw.simulate: its first sample is the release, theta2 from Eq. 2). The wall is stockier than Table 1's (2b/2h = 1/4)
so that the angles can be read.

    PYTHONPATH=build/python /usr/bin/python3 scripts/draw_wall_sketch.py [--out docs/img/wall-sketch.svg]

The SVG is written byte for byte the same at each run (no date, fixed ids): python/tests/test_wall_sketch.py holds
the committed file to what this script writes."""

import argparse
import math
import sys

import numpy as np

WALL = dict(height=2.0, thickness=0.5, hinge=0.6, xi=0.3)  # half dimensions b = 0.25, h1 = 0.6, h2 = 0.4 m
RELEASE = 0.6  # theta0 / alpha1 of the rocking wall drawn on the right
INK, ACCENT = "#222222", "#1f5fa8"


def _arc(ax, centre, radius, start_deg, end_deg, label, label_radius=1.35):
    """An angle's arc about centre from start to end (degrees, counter-clockwise from +x) and its label."""
    from matplotlib.patches import Arc

    lo, hi = sorted((start_deg, end_deg))
    ax.add_patch(Arc(centre, 2 * radius, 2 * radius, theta1=lo, theta2=hi, color=ACCENT, linewidth=1.0))
    mid = math.radians((lo + hi) / 2)
    ax.text(centre[0] + label_radius * radius * math.cos(mid), centre[1] + label_radius * radius * math.sin(mid),
            label, color=ACCENT, ha="center", va="center", fontsize=12)


def _dimension(ax, a, b, label, offset):
    """A dimension line from a to b (with arrows), its label beside it at offset."""
    ax.annotate("", xy=a, xytext=b, arrowprops=dict(arrowstyle="<->", color=INK, linewidth=0.8, shrinkA=0, shrinkB=0))
    ax.text((a[0] + b[0]) / 2 + offset[0], (a[1] + b[1]) / 2 + offset[1], label, ha="center", va="center",
            fontsize=12, color=INK)


def _at_rest(ax, g, wall_artists):
    """The left panel: dimensions, alpha1 at the base pivot, alpha2 at the hinge, N, the roller, the hinge."""
    from vssw._wall_drawing import pose

    b, h1, h2 = g["b"], g["h1"], g["h2"]
    wall_artists(ax, g).update(0.0, 0.0)
    p = pose(g, 0.0, 0.0)
    _dimension(ax, (-b - 0.18, 0.0), (-b - 0.18, 2 * h1), r"$2h_1$", (-0.14, 0.0))
    _dimension(ax, (-b - 0.18, 2 * h1), (-b - 0.18, 2 * (h1 + h2)), r"$2h_2$", (-0.14, 0.0))
    _dimension(ax, (-b, -0.12), (b, -0.12), r"$2b$", (0.0, -0.09))
    # alpha1: at the base pivot, between the vertical and the line to the lower block's centre (tan alpha1 = b/h1).
    pivot, g1 = p.pivot, np.array([0.0, h1])
    ax.plot(*zip(pivot, g1), color=ACCENT, linewidth=0.8, linestyle="--")
    ax.plot(*zip(pivot, pivot + [0.0, 0.75 * h1]), color=ACCENT, linewidth=0.8, linestyle=":")
    _arc(ax, pivot, 0.45 * h1, 90.0, 90.0 + math.degrees(g["alpha1"]), r"$\alpha_1$")
    # alpha2: at the hinge, between the vertical and the line to the upper block's centre (tan alpha2 = b/h2).
    hinge, g2 = p.hinge, np.array([0.0, 2 * h1 + h2])
    ax.plot(*zip(hinge, g2), color=ACCENT, linewidth=0.8, linestyle="--")
    ax.plot(*zip(hinge, hinge + [0.0, 0.75 * h2 * 2]), color=ACCENT, linewidth=0.8, linestyle=":")
    _arc(ax, hinge, 0.5 * h2, 90.0, 90.0 - math.degrees(g["alpha2"]), r"$\alpha_2$")
    ax.text(hinge[0] + 0.04, hinge[1] - 0.04, "hinge", ha="left", va="top", fontsize=10, color=INK)
    ax.text(pivot[0] + 0.05, -0.05, "pivot", ha="left", va="top", fontsize=10, color=INK)
    ax.text(p.load_point[0] + 0.05, p.load_point[1] + 0.3, r"$N$", ha="left", va="center", fontsize=12,
            color="#b03030")
    ax.text(b + 0.2, 2 * (h1 + h2) + 0.2, "roller", ha="left", va="bottom", fontsize=10, color=INK)


def _rocking(ax, g, theta1, theta2, wall_artists):
    """The right panel: the wall at (theta1, theta2) over its rest outline, theta1 at the pivot, theta2 at the hinge."""
    from vssw._wall_drawing import pose

    wall_artists(ax, g, style="outline").update(0.0, 0.0)
    wall_artists(ax, g).update(theta1, theta2)
    p = pose(g, theta1, theta2)
    h1, h2 = g["h1"], g["h2"]
    ax.plot(*zip(p.pivot, p.pivot + [0.0, 1.2 * h1]), color=ACCENT, linewidth=0.8, linestyle=":")
    _arc(ax, p.pivot, 0.9 * h1, 90.0, 90.0 - math.degrees(theta1), r"$\theta_1$", label_radius=1.2)
    ax.plot(*zip(p.hinge, p.hinge + [0.0, 1.6 * h2]), color=ACCENT, linewidth=0.8, linestyle=":")
    _arc(ax, p.hinge, 1.2 * h2, 90.0, 90.0 - math.degrees(theta2), r"$\theta_2$", label_radius=1.25)


def draw(out):
    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "vssw-wall-sketch"  # fixed ids: the same file at every run
    import matplotlib.pyplot as plt

    import vssw
    from vssw._wall_drawing import WallArtists

    release = vssw.simulate("analytic", **WALL, theta0=RELEASE, t_end=0.01)
    g = release.geometry
    theta1, theta2 = float(release.theta1[0]), float(release.theta2[0])
    fig, (left, right) = plt.subplots(1, 2, figsize=(7.0, 4.6), layout="constrained")
    _at_rest(left, g, WallArtists)
    _rocking(right, g, theta1, theta2, WallArtists)
    left.set_title("at rest", fontsize=11)
    right.set_title(rf"rocking: $\theta_1 = {RELEASE:g}\,\alpha_1$", fontsize=11)
    height = 2 * (g["h1"] + g["h2"])
    for ax in (left, right):
        ax.set_xlim(-0.8, 0.95)
        ax.set_ylim(-0.3, height + 0.45)
        ax.set_axis_off()
    fig.savefig(out, format="svg", metadata={"Date": None})
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="docs/img/wall-sketch.svg", help="the SVG to write")
    args = parser.parse_args()
    draw(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
