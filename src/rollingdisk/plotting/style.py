"""What every plot shares: the colours and labels of the classes of steady motion, axis
labels in the paper's symbols with units (SI when the disk has a physical scale), ticks
shown scaled or in degrees, new axes, legends under the axes, pyplot imported on first use.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.theory.regions import NO_MOTION, STABLE, UNSTABLE

__all__ = ["CLASS_COLORS", "disk_of", "si_factor", "axis_label"]

#: Colours of the classes, as in the paper's Figure 4: dark, gray, white.
CLASS_COLORS = ("#3a3a3a", "#b4b4b4", "#ffffff")
CLASS_LABELS = ("no steady motion ($\\Omega_0^2<0$)", "possible, unstable ($\\varpi^2<0$)",
                "stable ($\\varpi^2>0$)")

#: Axis labels in the paper's symbols (matplotlib mathtext), with the paper's units
#: (``m = a = g = 1``).  Angles are shown in degrees on every axis (the data stay in radians
#: where the library computes in radians, :func:`_show_degrees`); the plot functions switch
#: lengths, times and rates to SI units when their disk has a physical scale
#: (:func:`axis_label`).
LABELS = {
    "theta0": r"$\theta_0$ [deg]",
    "theta0_deg": r"$\theta_0$ [deg]",
    "r_C": r"$r_C$ [$a$]",
    "h": r"$h$ (half-thickness / radius)",
    "omega30": r"$\omega_{30}$ [$\sqrt{g/a}$]",
    "varpi2": r"$\varpi^2$ [$g/a$]",
}

#: Units of each kind of quantity on an axis (mathtext): (the paper's units, SI).  Kinds as
#: in :data:`rollingdisk.model.units.KINDS`.
AXIS_UNITS = {
    "time": (r"$\sqrt{a/g}$", "s"),
    "length": (r"$a$", "m"),
    "speed": (r"$\sqrt{ag}$", "m/s"),
    "angular_speed": (r"$\sqrt{g/a}$", "rad/s"),
    "rate_sq": (r"$g/a$", r"rad$^2$/s$^2$"),
    "force": (r"$mg$", "N"),
    "energy": (r"$mga$", "J"),
}


def disk_of(obj):
    """The :class:`~rollingdisk.Disk` of ``obj`` (a disk, or a result with a ``disk``
    attribute: trajectory, steady or exact motion), or ``None`` (a plain ``h``)."""
    from rollingdisk.model.disk import Disk

    if isinstance(obj, Disk):
        return obj
    d = getattr(obj, "disk", None)
    return d if isinstance(d, Disk) else None


def si_factor(disk, kind: str) -> float:
    """What a quantity of ``kind`` in the paper's units is multiplied by to show it on an
    axis: its SI conversion when ``disk`` has the physical scale it needs (times, lengths,
    speeds and rates the radius, forces the mass, energies both), else 1."""
    from rollingdisk.model.units import can_convert, to_si

    if disk is None or not can_convert(disk, kind):
        return 1.0
    return float(to_si(disk, kind, 1.0))


def axis_label(symbol: str, kind: str, disk=None) -> str:
    """``"<symbol> [<unit>]"``: SI units when ``disk`` converts ``kind``
    (:func:`si_factor`), else the paper's units (``[\\sqrt{a/g}]``, ``[a]``, ...)."""
    paper, si = AXIS_UNITS[kind]
    return f"{symbol} [{si if si_factor(disk, kind) != 1.0 else paper}]"


def _tick(v: float) -> str:
    """A tick label without floating-point noise (``0.30000000000000004`` -> ``0.3``)."""
    return f"{float(f'{v:.6g}'):g}"


def _path_axes(ax, disk, x_name: str, y_name: str) -> None:
    """Axes of a path on the plane: equal aspect, lengths shown in the disk's units (SI
    for a disk with a physical size), labelled ``x_name``, ``y_name``."""
    ax.set_aspect("equal", adjustable="datalim")
    f = si_factor(disk, "length")
    _show_scaled(ax.xaxis, f)
    _show_scaled(ax.yaxis, f)
    ax.set_xlabel(axis_label(x_name, "length", disk))
    ax.set_ylabel(axis_label(y_name, "length", disk))


def _show_scaled(axis, factor: float, ticks=None) -> None:
    """Show the data of ``axis`` (a matplotlib Axis, in the paper's units or radians)
    multiplied by ``factor``: round tick values in the shown units, labelled in them.
    The data, and so every artist and :class:`MapPlot` grid, stay as computed.
    ``ticks``: explicit tick positions in data units (for symlog axes)."""
    if factor == 1.0 and ticks is None:
        return
    from matplotlib.ticker import FixedLocator, FuncFormatter, Locator, MaxNLocator

    class _ScaledLocator(Locator):
        def __init__(self):
            self._inner = MaxNLocator(nbins=6, steps=[1, 1.5, 2, 2.5, 3, 5, 10])

        def __call__(self):
            return self.tick_values(*self.axis.get_view_interval())

        def tick_values(self, vmin, vmax):
            return np.asarray(self._inner.tick_values(vmin * factor, vmax * factor)) / factor

    axis.set_major_locator(FixedLocator(ticks) if ticks is not None else _ScaledLocator())
    axis.set_major_formatter(FuncFormatter(lambda v, _: _tick(v * factor)))


def _show_degrees(axis) -> None:
    """Label an axis whose data are angles in radians in degrees (ticks every 15 deg on
    a quarter turn)."""
    _show_scaled(axis, 180.0 / math.pi)


def _time_axis(ax, disk) -> None:
    """The time axis of a trajectory plot: data in units of ``sqrt(a/g)``, shown in seconds
    when ``disk`` has a physical radius."""
    _show_scaled(ax.xaxis, si_factor(disk, "time"))
    ax.set_xlabel(axis_label("$t$", "time", disk))



def _pyplot():
    import matplotlib.pyplot as plt

    return plt


def _axes(ax, projection=None, figsize=(5.0, 4.0)):
    if ax is not None:
        return ax
    plt = _pyplot()
    fig = plt.figure(figsize=figsize)
    return fig.add_subplot(1, 1, 1, projection=projection)


def _class_cmap():
    from matplotlib.colors import BoundaryNorm, ListedColormap

    return ListedColormap(CLASS_COLORS), BoundaryNorm([-0.5, 0.5, 1.5, 2.5], 3)


def _class_handles(codes_present=(NO_MOTION, UNSTABLE, STABLE), labels=None) -> list:
    from matplotlib.patches import Patch

    labels = labels or {}
    return [Patch(facecolor=CLASS_COLORS[c], edgecolor="k", linewidth=0.5,
                  label=labels.get(c, CLASS_LABELS[c])) for c in codes_present]


#: Font size of legends [points]: 8 pt is 11 px at 100 dpi.
LEGEND_FONTSIZE = 8


def _legend_below(ax, handles, ncol: int = 2):
    """One legend under the axes (never over the regions it explains)."""
    return ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.16),
                     ncol=ncol, fontsize=LEGEND_FONTSIZE, frameon=False,
                     handlelength=1.6, columnspacing=1.2)


def _theta_grid(n, theta_max=None):
    hi = (0.5 * math.pi) if theta_max is None else theta_max
    # open at both ends: theta0 = 0 and pi/2 are excluded from the circle theory
    return np.linspace(0.0, hi, n + 2)[1:-1]
