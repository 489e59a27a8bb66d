"""Plots of one motion in time.  A trajectory: its time series (state, contact point,
contact force, energy), the paths of C and P on the plane, the tilt, the energy error and
the contact force.  An exact motion (:mod:`rollingdisk.theory.exact`): ``theta(t)`` over a
period, the rosette of the contact point, the backbone curve, and the three side by side.
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
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["trajectory_series", "plot_paths", "plot_theta", "plot_energy_error",
           "plot_contact_forces", "plot_trajectory", "plot_exact_theta", "plot_rosette",
           "plot_backbone", "plot_exact"]


def trajectory_series(traj, name: str) -> np.ndarray:
    """A time series of ``traj``: its attribute ``name`` if it has one, else computed from
    ``traj.y`` with :mod:`rollingdisk.model.equations` (needs ``traj.disk``, ``traj.ground``).

    Works with :class:`rollingdisk.Trajectory` and any object with ``disk``,
    ``ground``, ``t`` and ``y`` of shape ``(n_state, n)``.
    """
    if not isinstance(name, str):
        raise ParameterTypeError(f"name must be a string, got {type(name).__name__}")
    value = getattr(traj, name, None)
    if value is not None:
        return np.asarray(value, float)
    if not all(hasattr(traj, a) for a in ("y", "disk", "ground")):
        raise ParameterTypeError(f"traj must be a trajectory (with t, y, disk, ground), got "
                                 f"{type(traj).__name__}")
    from rollingdisk.model import equations as eq
    from rollingdisk.model.state import state_names

    y = np.asarray(traj.y, float)
    names = state_names(traj.ground)
    if name in names:
        return y[names.index(name)]
    if name in ("X_P", "Y_P"):
        return np.asarray(eq.contact_point(traj.disk, traj.ground, y)[name == "Y_P"], float)
    if name in ("F_x", "F_y", "F_z"):
        F = eq.contact_force(traj.disk, traj.ground, y)["xyz".index(name[-1])]
        return np.broadcast_to(np.asarray(F, float), y.shape[1:]).copy()
    if name == "E":
        return np.asarray(eq.energy(traj.disk, traj.ground, y), float)
    raise ParameterError(f"unknown series {name!r}")



def plot_paths(traj, ax=None, *, title: str | None = None) -> dict:
    """Paths of the centre C (projected on the plane) and of the contact point P (eq. 5).

    Every trajectory plot labels its axes with units: the paper's (``t`` in ``sqrt(a/g)``,
    lengths in ``a``, forces in ``m g``) or, when ``traj.disk`` has a physical scale, SI
    (s, m, N; forces need the mass too).  The drawn data stay in the paper's units.
    """
    ax = _axes(ax)
    XC, YC = trajectory_series(traj, "X_C"), trajectory_series(traj, "Y_C")
    XP, YP = trajectory_series(traj, "X_P"), trajectory_series(traj, "Y_P")
    (lc,) = ax.plot(XC, YC, color="tab:blue", lw=1.0, label="C (centre)")
    (lp,) = ax.plot(XP, YP, color="tab:red", lw=1.0, label="P (contact)")
    start = ax.scatter([XC[0], XP[0]], [YC[0], YP[0]], color=["tab:blue", "tab:red"],
                       marker="o", s=16, zorder=3)
    _path_axes(ax, disk_of(traj), "$X$", "$Y$")
    ax.legend(loc="best", fontsize=LEGEND_FONTSIZE)
    ax.set_title(title if title is not None else "paths on the plane")
    return {"ax": ax, "C": lc, "P": lp, "start": start}


def plot_theta(traj, ax=None, *, theta0: float | None = None, title: str | None = None) -> dict:
    """Inclination ``theta(t)``; ``theta0`` [rad] draws the steady value.  The line holds
    radians; the axis is labelled in degrees."""
    ax = _axes(ax)
    t = np.asarray(traj.t, float)
    (line,) = ax.plot(t, trajectory_series(traj, "theta"), color="k", lw=1.0,
                      label=r"$\theta(t)$")
    out = {"ax": ax, "theta": line}
    if theta0 is not None:
        out["theta0"] = ax.axhline(theta0, color="tab:blue", ls="--", lw=0.8,
                                   label=r"$\theta_0$")
        ax.legend(loc="best", fontsize=LEGEND_FONTSIZE)
    _time_axis(ax, disk_of(traj))
    _show_degrees(ax.yaxis)
    ax.set_ylabel(r"$\theta$ [deg]")
    ax.set_title(title if title is not None else "inclination")
    return out


def plot_energy_error(traj, ax=None, *, title: str | None = None) -> dict:
    """Energy error ``E(t) - E(0)`` (eq. 13), in units of ``m g a``."""
    ax = _axes(ax)
    t = np.asarray(traj.t, float)
    E = trajectory_series(traj, "E")
    (line,) = ax.plot(t, E - E[0], color="tab:green", lw=1.0)
    disk = disk_of(traj)
    _time_axis(ax, disk)
    fE = si_factor(disk, "energy")
    if fE != 1.0:  # joules: tick labels such as 1e-15
        _show_scaled(ax.yaxis, fE)
    else:
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 2))
    ax.set_ylabel(axis_label("$E(t)-E(0)$", "energy", disk))
    ax.set_title(title if title is not None else "energy error")
    return {"ax": ax, "dE": line}


def plot_contact_forces(traj, ax=None, *, title: str | None = None) -> dict:
    """Contact force components ``F_x, F_y, F_z`` in Cxyz (eqs. 8, 11), units of ``m g``."""
    ax = _axes(ax)
    t = np.asarray(traj.t, float)
    out = {"ax": ax}
    for name, color in (("F_x", "tab:blue"), ("F_y", "tab:orange"), ("F_z", "k")):
        (out[name],) = ax.plot(t, trajectory_series(traj, name), color=color, lw=1.0,
                               label=f"${name}$")
    ax.axhline(0.0, color="0.6", lw=0.6)
    disk = disk_of(traj)
    _time_axis(ax, disk)
    _show_scaled(ax.yaxis, si_factor(disk, "force"))
    ax.set_ylabel(axis_label("force", "force", disk))
    ax.legend(loc="best", fontsize=LEGEND_FONTSIZE)
    ax.set_title(title if title is not None else "contact force")
    return out


def plot_trajectory(traj, fig=None, *, theta0: float | None = None,
                    title: str | None = None) -> dict:
    """A 2x2 summary of a trajectory: paths, ``theta(t)``, energy error, contact force."""
    plt = _pyplot()
    if fig is None:
        fig = plt.figure(figsize=(9.0, 6.5))
    axs = fig.subplots(2, 2)
    out = {"fig": fig, "axes": axs,
           "paths": plot_paths(traj, axs[0, 0]),
           "theta": plot_theta(traj, axs[0, 1], theta0=theta0),
           "energy": plot_energy_error(traj, axs[1, 0]),
           "forces": plot_contact_forces(traj, axs[1, 1])}
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    return out


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
