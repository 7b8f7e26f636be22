"""Simulation.plot: a run's rotations (and the top's rise and the energy, where the run has them) against time, on
matplotlib axes. matplotlib is imported only when a plot is asked for: `import vssw` does not load it."""

import numpy as np

from . import _core
from ._errors import InputError


# What plot() can draw: name -> (axis label with its unit, the values from a Simulation). Rotations in units of the
# reference angle alpha1 (a parapet's alpha; 1 is the corner over the pivot at rest), the rise in mm, energies in J.
QUANTITIES = {
    "theta1": ("θ1 / α1  [-]", lambda s: s.theta1 / s.alpha1),
    "theta2": ("θ2 / α1  [-]", lambda s: s.theta2 / s.alpha1),
    "top_dy": ("top's rise  [mm]", lambda s: 1e3 * s.top_dy),
    "energy": ("energy  [J]", lambda s: s.kinetic + s.potential),
}
_SYMBOLS = {"theta1": "θ1", "theta2": "θ2", "top_dy": "top's rise", "energy": "energy"}
_DEFAULT = ("theta1", "theta2", "top_dy", "energy")


def require_matplotlib():
    """matplotlib.pyplot, or an InputError saying how to get it (Debian: python3-matplotlib)."""
    try:
        import matplotlib.pyplot as plt  # type: ignore[import]  # Debian's matplotlib 3.6 ships no types
    except ImportError as e:
        raise InputError(f"plotting needs matplotlib, which this Python cannot import ({e}); install it "
                         "(Debian: apt install python3-matplotlib)", _core.EXIT_BAD_INPUT) from None
    return plt


def _present(sim, name):
    """The run has this quantity: a parapet's theta2 is theta1 (not drawn twice), and a sample without theta2, rise or
    energies (NaN: a motion-only run) has none."""
    if name == "theta2" and sim.geometry is not None and sim.geometry["model"] == "parapet":
        return False
    values = QUANTITIES[name][1](sim)
    return len(values) > 0 and not np.all(np.isnan(values))


def _label(sim, name):
    """The quantity's axis label; a parapet's reference angle is its alpha (no alpha1)."""
    label = QUANTITIES[name][0]
    return label.replace("θ1 / α1", "θ / α") if sim.geometry and sim.geometry["model"] == "parapet" else label


def _chosen(sim, quantities):
    if quantities is None:
        return [q for q in _DEFAULT if _present(sim, q)]
    names = [quantities] if isinstance(quantities, str) else list(quantities)
    if not names:
        raise InputError("quantities: an empty list; name at least one of " + ", ".join(QUANTITIES),
                         _core.EXIT_BAD_INPUT)
    for name in names:
        if name not in QUANTITIES:
            raise InputError(f"quantities: {name!r} is not one plot() draws; it draws " + ", ".join(QUANTITIES),
                             _core.EXIT_BAD_INPUT)
    return names


def plot_simulation(sim, ax=None, quantities=None):
    """Draw the run's quantities against t [s] and return the Figure.

    quantities: a name or a list of "theta1", "theta2" (each / alpha1), "top_dy" (the top face centre's rise, mm),
        "energy" (kinetic + potential, J); default every one the run has. theta1 and theta2 share one axes (both are
        rotations over alpha1); each other quantity gets its own, stacked below with the time axis shared.
    ax: matplotlib Axes to draw on (then every quantity goes on it), or a sequence of Axes (one per panel), or None
        (a new Figure). InputError when matplotlib is missing or a quantity is unknown."""
    plt = require_matplotlib()
    names = _chosen(sim, quantities)
    panels = [[n for n in names if n in ("theta1", "theta2")]] if {"theta1", "theta2"} & set(names) else []
    panels += [[n] for n in names if n not in ("theta1", "theta2")]
    if ax is None:
        fig, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False,
                                 figsize=(7.0, 1.0 + 2.0 * len(panels)), layout="constrained")
        axes = list(axes[:, 0])
    elif hasattr(ax, "plot"):
        axes, panels = [ax], [names]
        fig = ax.figure
    else:
        axes = list(ax)
        if len(axes) != len(panels):
            raise InputError(f"ax: {len(axes)} Axes given for {len(panels)} panels ({panels})", _core.EXIT_BAD_INPUT)
        fig = axes[0].figure
    for panel_ax, panel in zip(axes, panels):
        for name in panel:
            panel_ax.plot(sim.t, QUANTITIES[name][1](sim), label=f"{sim.engine}: {_SYMBOLS[name]}", linewidth=1.0)
        if len(panel) > 1:
            panel_ax.set_ylabel("rotation / α1  [-]")
            panel_ax.legend(loc="upper right", fontsize="small")
        else:
            panel_ax.set_ylabel(_label(sim, panel[0]))
        panel_ax.grid(True, linewidth=0.3)
    axes[-1].set_xlabel("t  [s]")
    # The run's start in the title; its engine too on a figure of its own (on given axes the legend names the runs).
    start = sim.ground_motion if sim.ground_motion else f"released at θ0 = {sim.theta0 / sim.alpha1:.3g} α1"
    title = start if ax is not None else f"{sim.engine}, {start}" + (", overturned" if sim.overturned else "")
    axes[0].set_title(title, fontsize="medium")
    return fig
