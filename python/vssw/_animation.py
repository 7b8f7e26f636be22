"""Simulation.animate: the two blocks and the roller moving as the run did (the drawing of _wall_drawing.py at the
run's samples), as a matplotlib Animation, written to a GIF (Pillow) or an MP4 (ffmpeg, where installed)."""

import math
import numbers
import os
import pathlib
import tempfile

import numpy as np

from . import _core
from ._errors import InputError
from ._plot import require_matplotlib
from ._wall_drawing import WallArtists, pose, require_drawable

_MAX_FPS = 100.0  # frames per second: a GIF's frame delay is counted in 10 ms, so 100 is the most a viewer shows
_MARGIN = 0.15  # of the wall's height around the drawing, so the roller and N's arrow stay inside the frame


def _positive(name, value, largest=math.inf):
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0 < float(value) <= largest:
        raise InputError(f"{name} {value!r}: a number above 0" + (f" and at most {largest:g}" if largest < math.inf
                                                                  else "") + " is expected", _core.EXIT_BAD_INPUT)
    return float(value)


def frame_samples(sim, fps, speed, t_start, t_stop):
    """The sample shown at each frame: frame k shows t_start + k speed / fps of the run, drawn at the last sample at
    or before that time (a sample, not an interpolation: every frame is a configuration the run reached)."""
    t = sim.t
    start = t[0] if t_start is None else t_start
    stop = t[-1] if t_stop is None else t_stop
    for name, value in (("t_start", start), ("t_stop", stop)):
        if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
            raise InputError(f"{name} {value!r}: a time in seconds is expected", _core.EXIT_BAD_INPUT)
    if not t[0] <= start < stop <= t[-1]:
        raise InputError(f"t_start {start:g} s, t_stop {stop:g} s: the run's samples span {t[0]:g} to {t[-1]:g} s "
                         "(t_start < t_stop, both within it)", _core.EXIT_BAD_INPUT)
    times = start + np.arange(int(math.floor((stop - start) * fps / speed)) + 1) * speed / fps
    return np.searchsorted(t, times, side="right") - 1


def _limits(sim, indices):
    """Axes limits holding every frame's wall, the rollers and the arrow of N."""
    g = sim.geometry
    height = 2 * (g["h1"] + (g["h2"] or 0.0))
    points = [np.array([[-g["b"], 0.0], [g["b"], height]])]
    for i in indices:
        p = pose(g, sim.theta1[i], sim.theta2[i])
        points += [p.lower] + ([p.upper] if p.upper is not None else [])
    xy = np.vstack(points)
    pad = _MARGIN * height
    return (xy[:, 0].min() - pad, xy[:, 0].max() + pad), (-0.05 * height, xy[:, 1].max() + 1.5 * pad)


def _writer(path, fps):
    """The matplotlib writer for path's suffix; InputError for another suffix, a missing encoder or a folder that does
    not exist."""
    from matplotlib import animation  # type: ignore[import]  # no types in matplotlib 3.6

    suffix = path.suffix.lower()
    if not path.parent.is_dir():
        raise InputError(f"path {str(path)!r}: its folder {str(path.parent)!r} does not exist", _core.EXIT_BAD_INPUT)
    if suffix == ".gif":
        return animation.PillowWriter(fps=fps)
    if suffix == ".mp4":
        if not animation.writers.is_available("ffmpeg"):
            raise InputError(f"path {str(path)!r}: an MP4 needs ffmpeg, which is not installed here (Debian: apt "
                             "install ffmpeg); write a .gif instead", _core.EXIT_BAD_INPUT)
        return animation.FFMpegWriter(fps=fps)
    raise InputError(f"path {str(path)!r}: the animation is written as .gif or .mp4, not {suffix or 'no suffix'!r}",
                     _core.EXIT_BAD_INPUT)


def _save(anim, path, writer):
    """Write beside the target and rename over it: a failed write leaves no half file and keeps an existing one."""
    handle, temporary = tempfile.mkstemp(suffix=path.suffix, prefix=f".{path.stem}.", dir=path.parent)
    os.close(handle)
    try:
        anim.save(temporary, writer=writer)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def animate_simulation(sim, path=None, fps=25, speed=1.0, t_start=None, t_stop=None):
    """The run as a matplotlib FuncAnimation of the wall: both blocks turned by the run's theta1 and theta2 about the
    base pivot and the hinge, the roller at the top (a VSSW's), N's arrow when xi > 0.

    path: where to write it, .gif (Pillow) or .mp4 (ffmpeg, where installed); None: only returned (e.g. shown in a
        notebook). fps: frames per second of the file (0 < fps <= 100). speed: run seconds per second of film (0.25:
        four times slower). t_start, t_stop [s]: the part of the run shown (default all of it).
    The returned Animation has sample_indices (the sample each frame shows) and draw_frame(k) (draws frame k and
    returns its WallPose). InputError for a bad value, a Simulation without geometry, a missing matplotlib or
    encoder."""
    plt = require_matplotlib()
    from matplotlib import animation  # type: ignore[import]

    require_drawable(sim.geometry)
    fps = _positive("fps", fps, _MAX_FPS)
    speed = _positive("speed", speed)
    target = None if path is None else pathlib.Path(os.fspath(path))
    writer = None if target is None else _writer(target, fps)
    indices = frame_samples(sim, fps, speed, t_start, t_stop)
    if sim.geometry["model"] == "vssw" and np.isnan(sim.theta2[indices]).any():
        raise InputError("theta2 is NaN in this run's samples (a run that sampled theta1 alone): the upper block "
                         "cannot be drawn", _core.EXIT_BAD_INPUT)
    fig, ax = plt.subplots(figsize=(4.0, 6.0), layout="constrained")
    xlim, ylim = _limits(sim, indices)
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_xlabel("x  [m]")
    ax.set_ylabel("y  [m]")
    wall = WallArtists(ax, sim.geometry)
    clock = ax.set_title("")

    def draw_frame(k):
        i = indices[k]
        drawn, _ = wall.update(sim.theta1[i], sim.theta2[i])
        clock.set_text(f"{sim.engine}  t = {sim.t[i]:.3f} s  θ1/α1 = {sim.theta1[i] / sim.alpha1:+.3f}")
        return drawn

    # init_func keeps what is drawn: without one, the figure's first rendering (a notebook showing it) draws frame 0
    # over the frame draw_frame chose.
    anim = animation.FuncAnimation(fig, lambda k: (draw_frame(k), ax.patches)[1], frames=len(indices),
                                   init_func=lambda: ax.patches, interval=1000.0 / fps, blit=False)
    anim.sample_indices = indices
    anim.draw_frame = draw_frame
    anim.wall = wall
    draw_frame(0)
    if target is not None:
        _save(anim, target, writer)
    return anim
