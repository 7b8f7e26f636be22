"""The wall drawn from the model's own geometry: where the blocks' corners, the pivot, the hinge, the roller corner and
N's point are at (theta1, theta2), and matplotlib artists that draw them (Simulation.animate and
scripts/draw_wall_sketch.py).

The kinematics are those of analytic/two_block.hpp, written in one physical frame: x horizontal along the side the
wall tips to when theta1 > 0, y up, the origin at the base's centre at rest, both rotations clockwise positive. The
lower block turns about its base corner on the side it tips to, P = (side b, 0); the upper block about the hinge, the
lower block's top corner on the other face, H = (-side b, 2 h1) at rest. A point X of the lower block is at
P + Rot(theta1)(X - P); a point of the upper block at P + Rot(theta1)(H - P) + Rot(theta2)(X - H), with
Rot(t)(x, y) = (x cos t + y sin t, -x sin t + y cos t). The roller holds the upper block's top corner on the pivot's
side on the line x = side b. A parapet is one block turned about its base corner. Nothing here imports matplotlib:
the artists are made through the axes given."""

import dataclasses
import math
from typing import Optional

import numpy as np

from . import _core
from ._errors import InputError


def _rot(t, v):
    """Rot(t) applied to the rows of v: clockwise by t (two_block.hpp's Rot)."""
    c, s = math.cos(t), math.sin(t)
    v = np.asarray(v, dtype=float)
    return np.stack([v[..., 0] * c + v[..., 1] * s, -v[..., 0] * s + v[..., 1] * c], axis=-1)


@dataclasses.dataclass(frozen=True)
class WallPose:
    """Where the wall is at one (theta1, theta2), in metres: lower and upper (each block's four nominal corners,
    counter-clockwise from the base corner at -x at rest; upper None for a parapet), lower_outline and upper_outline
    (the blocks' outlines as drawn: the corners, or with rounded corners their arcs), pivot (where the lower block
    touches the ground), hinge (where the blocks touch; None for a parapet), roller_corner (the nominal top corner
    the roller holds: the pivot's side), load_point (where N acts on the top face), side (+1 while theta1 >= 0, else
    -1)."""

    lower: np.ndarray
    upper: Optional[np.ndarray]
    lower_outline: np.ndarray
    upper_outline: Optional[np.ndarray]
    pivot: np.ndarray
    hinge: Optional[np.ndarray]
    roller_corner: np.ndarray
    load_point: np.ndarray
    side: int


_ARC_POINTS = 8  # points per rounded corner's quarter circle in a drawn outline


def require_drawable(geometry):
    """InputError unless the Simulation carries the wall's geometry."""
    if geometry is None:
        raise InputError("this Simulation has no geometry to draw (made by an older vssw)", _core.EXIT_BAD_INPUT)


def _rectangle(b, y0, y1):
    return np.array([[-b, y0], [b, y0], [b, y1], [-b, y1]])


def _outline(b, y0, y1, r):
    """A block's outline at rest, counter-clockwise from its lower -x corner: the four corners, or each corner's arc
    of radius r."""
    if r == 0.0:
        return _rectangle(b, y0, y1)
    centres = [(-b + r, y0 + r), (b - r, y0 + r), (b - r, y1 - r), (-b + r, y1 - r)]
    arcs = []
    for k, centre in enumerate(centres):  # a quarter turn each, from 180 degrees at the lower -x corner
        a = np.linspace(np.pi * (1 + k / 2), np.pi * (1.5 + k / 2), _ARC_POINTS)
        arcs.append(np.array(centre) + r * np.stack([np.cos(a), np.sin(a)], axis=-1))
    return np.vstack(arcs)


def pose(geometry, theta1, theta2):
    """The wall at (theta1, theta2) [rad] (a parapet's theta2 is ignored): a WallPose.

    With rounded corners (r = corner_radius b > 0, docs/model/analytic-core.md "Rounded corners") the lower block
    rolls without slip on its base arc (the arc's centre, (side (b - r), r) at rest, moves r theta1 along the ground)
    and the upper block's bottom arc rolls on the lower block's top arc (equal circles: their line of centres turns by
    the mean of the two rotations), as the engines place them (multibody/kit/rounded_corners.hpp). With r = 0 the arcs
    are the corners and this is the pivoting of the header comment."""
    b, h1, h2 = geometry["b"], geometry["h1"], geometry["h2"]
    r = geometry["corner_radius"] * b
    e = geometry["overburden_eccentricity"] * b
    side = 1 if theta1 >= 0 else -1
    inner = b - r
    base_rest = np.array([side * inner, r])  # the base arc's centre (the pivot itself when r = 0)
    base = base_rest + [r * theta1, 0.0]

    def on_lower(x):
        return base + _rot(theta1, np.asarray(x) - base_rest)

    top = 2 * h1 if geometry["model"] == "parapet" else 2 * (h1 + h2)
    load_rest = np.array([e, top])
    if geometry["model"] == "parapet":
        lower = on_lower(_rectangle(b, 0.0, 2 * h1))
        return WallPose(lower=lower, upper=None, lower_outline=on_lower(_outline(b, 0.0, 2 * h1, r)),
                        upper_outline=None, pivot=np.array([base[0], 0.0]), hinge=None,
                        roller_corner=lower[2 if side > 0 else 3], load_point=on_lower(load_rest), side=side)
    hinge_lower_rest = np.array([-side * inner, 2 * h1 - r])  # the lower block's top arc's centre
    hinge_upper_rest = np.array([-side * inner, 2 * h1 + r])  # the upper block's bottom arc's centre
    hinge_lower = on_lower(hinge_lower_rest)
    hinge_upper = hinge_lower + _rot(0.5 * (theta1 + theta2), np.array([0.0, 2 * r]))

    def on_upper(x):
        return hinge_upper + _rot(theta2, np.asarray(x) - hinge_upper_rest)

    upper = on_upper(_rectangle(b, 2 * h1, top))
    return WallPose(lower=on_lower(_rectangle(b, 0.0, 2 * h1)), upper=upper,
                    lower_outline=on_lower(_outline(b, 0.0, 2 * h1, r)),
                    upper_outline=on_upper(_outline(b, 2 * h1, top, r)),
                    pivot=np.array([base[0], 0.0]), hinge=0.5 * (hinge_lower + hinge_upper),
                    roller_corner=upper[2 if side > 0 else 3], load_point=on_upper(load_rest), side=side)


class WallArtists:
    """The wall on matplotlib axes, redrawn at each (theta1, theta2): both blocks, the ground, the pivot, the hinge,
    the roller on each side of the top (a VSSW's) and N's arrow (when xi > 0). style: "solid" (filled blocks) or
    "outline" (dashed outlines, e.g. the wall at rest under a displaced one)."""

    def __init__(self, ax, geometry, style="solid"):
        require_drawable(geometry)
        self.ax = ax
        self.geometry = geometry
        b = geometry["b"]
        height = 2 * (geometry["h1"] + (geometry["h2"] or 0.0))
        self.roller_radius = 0.35 * b
        filled = style == "solid"
        line = dict(closed=True, linewidth=1.2, edgecolor="black" if filled else "grey",
                    linestyle="-" if filled else "--", fill=filled)
        from matplotlib.patches import Circle, Polygon  # type: ignore[import]  # the caller has matplotlib

        self.blocks = [Polygon(np.zeros((4, 2)), facecolor="#d9c3a5", **line)]
        if geometry["model"] == "vssw":
            self.blocks.append(Polygon(np.zeros((4, 2)), facecolor="#c9a882", **line))
        for block in self.blocks:
            ax.add_patch(block)
        self.rollers = []
        if filled and geometry["model"] == "vssw":
            for _ in (1, -1):
                roller = Circle((0.0, 0.0), self.roller_radius, facecolor="white", edgecolor="black", linewidth=1.0)
                ax.add_patch(roller)
                self.rollers.append(roller)
            for s in (1, -1):  # the rollers' fixed guides, a roller's diameter outside each face
                x = s * (b + 2 * self.roller_radius)
                ax.plot([x, x], [height - 3 * self.roller_radius, height + 3 * self.roller_radius], color="black",
                        linewidth=2.0)
        (self.hinge_dot,) = ax.plot([], [], "o", color="black", markersize=4 if filled else 0)
        (self.pivot_dot,) = ax.plot([], [], "^", color="black", markersize=6 if filled else 0)
        self.load = None
        if filled and geometry["xi"] > 0:
            self.load = ax.annotate("", xy=(0, 0), xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color="#b03030"))
        if filled:
            ax.axhline(0.0, color="black", linewidth=1.5)
        ax.set_aspect("equal")

    def update(self, theta1, theta2):
        """Move every artist to (theta1, theta2); returns the WallPose drawn and the artists (for blitting)."""
        p = pose(self.geometry, theta1, theta2)
        self.blocks[0].set_xy(p.lower_outline)
        if p.upper is not None:
            self.blocks[1].set_xy(p.upper_outline)
            self.hinge_dot.set_data([p.hinge[0]], [p.hinge[1]])
        self.pivot_dot.set_data([p.pivot[0]], [p.pivot[1]])
        if self.rollers:
            corner_y = p.roller_corner[1]
            for s, roller in zip((1, -1), self.rollers):
                roller.center = (s * (self.geometry["b"] + self.roller_radius), corner_y)
        if self.load is not None:
            arrow = 0.25 * (self.geometry["h1"] + (self.geometry["h2"] or 0.0))
            self.load.xy = tuple(p.load_point)
            self.load.set_position((p.load_point[0], p.load_point[1] + arrow))
        artists = [*self.blocks, *self.rollers, self.hinge_dot, self.pivot_dot]
        return p, artists + ([self.load] if self.load is not None else [])
