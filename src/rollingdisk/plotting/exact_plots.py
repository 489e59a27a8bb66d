"""Plots of an exact motion (:mod:`rollingdisk.theory.exact`): ``theta(t)`` over a period,
the rosette of the contact point, the backbone curve, and the three side by side.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.plotting.style import (
    LEGEND_FONTSIZE,
    _axes,
    _path_axes,
    _pyplot,
    _show_degrees,
    _show_scaled,
    _time_axis,
    axis_label,
    disk_of,
    si_factor,
)
from rollingdisk.util.errors import ParameterError

__all__ = ["plot_exact_theta", "plot_rosette", "plot_backbone", "plot_exact"]


def plot_exact_theta(ex, ax=None, *, title: str | None = None) -> dict:
    """``theta(t)`` of an exact motion (:mod:`rollingdisk.theory.exact`) over one period, with
    its turning points."""
    ax = _axes(ax)
    if ex.period is None:
        raise ParameterError(f"ex: the motion ends ({ex.status}); theta(t) over a period "
                             "needs a bounded motion")
    t = np.linspace(0.0, ex.period, 400)
    (line,) = ax.plot(t, ex.theta(t), color="k", lw=1.2, label=r"$\theta(t)$ (quadrature)")
    for v, name in ((ex.theta_min, r"$\theta_{min}$"), (ex.theta_max, r"$\theta_{max}$")):
        ax.axhline(v, color="tab:blue", ls=":", lw=0.8)
        ax.annotate(name, (t[-1], v), fontsize=LEGEND_FONTSIZE, ha="right", va="bottom")
    disk = disk_of(ex)
    _time_axis(ax, disk)
    _show_degrees(ax.yaxis)
    ax.set_ylabel(r"$\theta$ [deg]")
    if title is None:
        ft = si_factor(disk, "time")
        title = (f"one period, $T$ = {ex.period * ft:.4g} s" if ft != 1.0 else
                 rf"one period, $T$ = {ex.period:.6g} $\sqrt{{a/g}}$")
    ax.set_title(title)
    return {"ax": ax, "theta": line}


def plot_rosette(ex, ax=None, *, n_periods: int = 20, title: str | None = None) -> dict:
    """The contact point's path (eq. 5) over ``n_periods`` nutation periods: a rosette."""
    ax = _axes(ax)
    if ex.period is None:
        raise ParameterError(f"ex: the motion ends ({ex.status}); the rosette needs a "
                             "bounded motion")
    t = np.linspace(0.0, n_periods * ex.period, 200 * n_periods + 1)
    X, Y = ex.contact_path(t)
    (line,) = ax.plot(X, Y, color="tab:red", lw=0.7)
    ax.plot(X[:1], Y[:1], "o", color="tab:red", ms=3)
    _path_axes(ax, disk_of(ex), "$X_P$", "$Y_P$")
    ax.set_title(title if title is not None else
                 rf"contact point, {n_periods} periods, $\Delta\psi$ = "
                 f"{math.degrees(ex.delta_psi):.4g}°")
    return {"ax": ax, "path": line}


def plot_backbone(bb, ax=None, *, title: str | None = None, disk=None) -> dict:
    """Backbone curve (:func:`rollingdisk.theory.exact.backbone`): nutation frequency against
    amplitude, tending to the linear ``varpi`` (eq. 39) at zero amplitude.  Amplitude
    labelled in degrees (data in radians); frequency in ``sqrt(g/a)``, or rad/s with
    ``disk`` (or ``bb.disk``) of physical radius."""
    ax = _axes(ax)
    ok = np.isfinite(bb.frequency)
    (line,) = ax.plot(bb.amplitude[ok], bb.frequency[ok], "o-", color="k", ms=3, lw=1.0,
                      label="exact frequency")
    out = {"ax": ax, "frequency": line}
    if np.isfinite(bb.varpi):
        out["varpi"] = ax.axhline(bb.varpi, color="tab:blue", ls="--", lw=0.8,
                                  label=r"$\varpi$ (eq. 39)")
    disk = disk_of(bb) if disk is None else disk
    _show_degrees(ax.xaxis)
    _show_scaled(ax.yaxis, si_factor(disk, "angular_speed"))
    ax.set_xlabel(r"amplitude $(\theta_{max}-\theta_{min})/2$ [deg]")
    ax.set_ylabel(axis_label(r"$2\pi/T$", "angular_speed", disk))
    ax.legend(loc="best", fontsize=LEGEND_FONTSIZE)
    ax.set_title(title if title is not None else "backbone")
    return {**out}


def plot_exact(ex, fig=None, *, backbone=None, n_periods: int = 20,
               title: str | None = None) -> dict:
    """One figure of an exact motion: ``theta(t)`` over a period, the rosette, and the
    backbone curve when ``backbone`` (a :class:`rollingdisk.theory.exact.Backbone`) is given."""
    plt = _pyplot()
    n = 3 if backbone is not None else 2
    if fig is None:
        fig = plt.figure(figsize=(4.2 * n, 4.0))
    axs = fig.subplots(1, n)
    out = {"fig": fig, "axes": axs, "theta": plot_exact_theta(ex, axs[0]),
           "rosette": plot_rosette(ex, axs[1], n_periods=n_periods)}
    if backbone is not None:
        out["backbone"] = plot_backbone(backbone, axs[2], disk=disk_of(ex))
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    return out
