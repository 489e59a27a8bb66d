"""Maps of a sweep's nonlinear runs: where the simulated motion stayed bounded, and the
size of the basin of each steady motion.
"""

from __future__ import annotations

import numpy as np

from rollingdisk.plotting.style import _axes, axis_label
from rollingdisk.util.errors import ParameterError

__all__ = ["plot_nonlinear_map", "plot_basin_map"]


def _sweep_plane(ds, name):
    """The plane of a sweep variable drawn by the maps: ``(theta0, second axis)`` at the
    first h (circles) or ``(h, omega0)`` (straight lines); first amplitude."""
    da = ds[name]
    drop = ("amplitude",) if "omega0" in da.dims else ("h", "amplitude")
    for dim in drop:
        if dim in da.dims:
            da = da.isel({dim: 0})
    if da.ndim != 2 or da.dims[0] not in ("theta0", "h"):
        raise ParameterError(f"ds: expected a sweep over theta0 (or h for straight lines) "
                             f"and one more axis, got dims {ds[name].dims}")
    return da


def _plane_axes(da):
    """``(x, y, ylabel)`` of a sweep plane: theta0 in degrees, or h."""
    x = da[da.dims[1]].values
    if da.dims[0] == "theta0":
        return x, np.degrees(da["theta0"].values), r"$\theta_0$ [deg]"
    return x, da["h"].values, r"$h$"


#: Sweep axes other than theta0 and h: (symbol, kind of quantity) for their labels.
_SWEEP_AXES = {"omega30": (r"$\omega_{30}$", "angular_speed"),
               "Omega0": (r"$\Omega_0$", "angular_speed"),
               "omega0": (r"$\omega_0$", "angular_speed"),
               "r_C": ("$r_C$", "length")}


def _sweep_xlabel(dim: str) -> str:
    """The label of a sweep's second axis, with the paper's unit (sweeps run in them)."""
    symbol, kind = _SWEEP_AXES.get(dim, (dim, None))
    return axis_label(symbol, kind) if kind else dim


def plot_nonlinear_map(ds, ax=None) -> dict:
    """Simulated stability of a sweep (:func:`rollingdisk.sweep.runner.run_sweep`) over
    ``(theta0, omega30 | r_C | Omega0)`` or, for straight lines, ``(h, omega0)``: bounded /
    unbounded / guard event, with the closed-form boundary ``varpi^2 = 0`` (eq. 45
    corrected / 55) drawn on top.

    Returns ``{"ax", "mesh", "boundary"}``.
    """
    from matplotlib.colors import ListedColormap

    ax = _axes(ax)
    ss = _sweep_plane(ds, "stable_simulated")
    st = _sweep_plane(ds, "status")
    v = _sweep_plane(ds, "varpi2")
    y, th, ylabel = _plane_axes(ss)
    code = np.where(ss.values < 0, np.nan,
                    np.where(ss.values == 1, 2.0, np.where(st.values == 1, 1.0, 0.0)))
    cmap = ListedColormap(["tab:red", "tab:orange", "tab:green"])
    mesh = ax.pcolormesh(y, th, code, cmap=cmap, vmin=-0.5, vmax=2.5, shading="nearest")
    boundary = None
    if np.isfinite(v.values).sum() > 3 and len(th) > 1 and len(y) > 1:
        boundary = ax.contour(y, th, v.values, levels=[0.0], colors="k", linewidths=1.0)
    ax.set_xlabel(_sweep_xlabel(ss.dims[1]))
    ax.set_ylabel(ylabel)
    ax.set_title(f"{ds.attrs.get('ground', '')}: bounded (green), grew (orange), "
                 "guard (red); black: $\\varpi^2 = 0$", fontsize="small")
    return {"ax": ax, "mesh": mesh, "boundary": boundary}


def plot_basin_map(ds, ax=None) -> dict:
    """Largest bounded kick (:func:`rollingdisk.sweep.runner.basin_sweep`) over ``(theta0, omega30
    | r_C | Omega0)`` or ``(h, omega0)``, with the closed-form boundary ``varpi^2 = 0``.

    Returns ``{"ax", "mesh", "colorbar", "boundary"}``.
    """
    ax = _axes(ax)
    kb = _sweep_plane(ds, "kick_basin")
    v = _sweep_plane(ds, "varpi2")
    y, th, ylabel = _plane_axes(kb)
    mesh = ax.pcolormesh(y, th, kb.values, cmap="viridis", shading="nearest")
    cb = ax.figure.colorbar(mesh, ax=ax, label=r"largest bounded kick in $\omega_1$")
    boundary = None
    if np.isfinite(v.values).sum() > 3 and len(th) > 1 and len(y) > 1:
        boundary = ax.contour(y, th, v.values, levels=[0.0], colors="w", linewidths=1.0)
    ax.set_xlabel(_sweep_xlabel(kb.dims[1]))
    ax.set_ylabel(ylabel)
    ax.set_title(f"{ds.attrs.get('ground', '')}: basin size", fontsize="small")
    return {"ax": ax, "mesh": mesh, "colorbar": cb, "boundary": boundary}
