"""Plots: existence and stability maps of steady motions (sections 3-4) and trajectories.

This module sits outside the numeric core: it calls :mod:`rollingdisk.theory.steady`,
:mod:`rollingdisk.theory.oscillations` and :mod:`rollingdisk.model.equations` and draws what they
return.
It never re-implements a formula of the paper, and what a map shows (which steady
motions exist, which are stable) is computed in :mod:`rollingdisk.theory.regions`.  matplotlib is
imported only when a plot function is called; every function takes ``ax=None`` (a new
figure is made when it is ``None``), returns what it drew and never calls ``plt.show()``.

One module on purpose: one function per kind of map or trajectory plot, sharing the
class colours, labels and file helpers at the top (split by plot kind, they would be
scattered over several modules).

Map functions return a :class:`MapPlot`: the axes, the grid, the values on the grid (a
class code of :mod:`rollingdisk.theory.regions` or ``varpi2``) and the artists.  Class codes are

* ``NO_MOTION = 0``: no steady motion (``Omega0^2 <= 0``),
* ``UNSTABLE = 1``: a steady motion exists but ``varpi^2 < 0``,
* ``STABLE = 2``: ``varpi^2 > 0``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.model.disk import check_ground, check_h, h_of
from rollingdisk.theory.regions import (
    NO_MOTION,
    STABLE,
    UNSTABLE,
    existence_codes,
    varpi2_zero_surface,
)
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = [
    "DPI_RANGE",
    "IMAGE_FORMATS",
    "check_dpi",
    "image_format",
    "save_figure",
    "CLASS_COLORS",
    "MapPlot",
    "plot_existence_map",
    "plot_stability_map",
    "plot_all_omega30_stable",
    "plot_varpi2_surface",
    "plot_varpi2_curves",
    "plot_paths",
    "plot_theta",
    "plot_energy_error",
    "plot_contact_forces",
    "plot_trajectory",
    "trajectory_series",
    "plot_euler_disk",
    "euler_disk_title",
    "disk_of",
    "si_factor",
    "axis_label",
    "plot_nonlinear_map",
    "plot_basin_map",
    "plot_exact_theta",
    "plot_rosette",
    "plot_backbone",
    "plot_exact",
]

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


@dataclass(frozen=True)
class MapPlot:
    """What a map function drew.

    Attributes
    ----------
    ax : matplotlib Axes
    x, y : ndarray
        The grid (1-D coordinates of the cell centres along each axis).
    values : ndarray, shape (len(y), len(x))
        Class codes (:data:`NO_MOTION`, :data:`UNSTABLE`, :data:`STABLE`), a boolean, or
        the plotted quantity.
    artists : dict
        The artists drawn, by role (``"mesh"``, ``"r_C_star"``, ...).
    """

    ax: object
    x: np.ndarray
    y: np.ndarray
    values: np.ndarray
    artists: dict = field(default_factory=dict)

    def share(self, code, mask=None) -> float:
        """Fraction of the cells (inside ``mask`` if given) whose value equals ``code``."""
        v = np.asarray(self.values)
        sel = np.ones(v.shape, bool) if mask is None else np.asarray(mask, bool)
        return float(np.mean(v[sel] == code)) if sel.any() else float("nan")


# ------------------------------------------------------------------------------ files
#: Resolutions accepted for images and animations, in dots per inch: below 20 the text is
#: unreadable, above 600 a figure of the library runs to hundreds of megabytes.
DPI_RANGE = (20, 600)

#: Image formats :func:`save_figure` writes (matplotlib's own backends, no LaTeX needed).
IMAGE_FORMATS = ("png", "pdf", "svg")


def check_dpi(dpi, name: str = "dpi") -> int:
    """``dpi`` as an int in :data:`DPI_RANGE`, or :class:`~rollingdisk.ParameterError`.

    Parameters
    ----------
    dpi : int
        Dots per inch.
    name : str
        The parameter's name for the message.

    Returns
    -------
    int
    """
    return check_int(name, dpi, low=DPI_RANGE[0], high=DPI_RANGE[1])


def image_format(path, name: str = "out") -> str:
    """The image format of ``path`` by its suffix, one of :data:`IMAGE_FORMATS`.

    Parameters
    ----------
    path : path-like
        The image file.
    name : str
        The parameter's name for the message.

    Returns
    -------
    str
        ``"png"``, ``"pdf"`` or ``"svg"``.

    Raises
    ------
    ParameterError
        For any other suffix (or none).
    """
    import os

    try:
        suffix = os.path.splitext(os.fspath(path))[1].lower().lstrip(".")
    except TypeError:
        raise ParameterTypeError(f"{name} must be a file name, got {type(path).__name__} "
                                 f"{path!r}") from None
    if suffix not in IMAGE_FORMATS:
        raise ParameterError(f"{name} must end in one of "
                             f"{', '.join('.' + f for f in IMAGE_FORMATS)}, got {str(path)!r}")
    return suffix


def save_figure(fig, path, *, dpi: int = 110):
    """Write ``fig`` to ``path`` whole or not at all (a temporary file, renamed at the end).

    Parameters
    ----------
    fig : matplotlib Figure
    path : path-like
        ``.png``, ``.pdf`` or ``.svg`` (:data:`IMAGE_FORMATS`); its folder must exist.
    dpi : int
        Resolution, in :data:`DPI_RANGE`.

    Returns
    -------
    Path
        ``path``.
    """
    from pathlib import Path

    from rollingdisk.util.files import atomic_file, check_writable

    fmt = image_format(path)
    dpi = check_dpi(dpi)
    target = check_writable(path, name="out")
    with atomic_file(target, mode=None) as tmp:
        fig.savefig(tmp, dpi=dpi, format=fmt)
    return Path(path)


# ------------------------------------------------------------------------------ helpers
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


# ------------------------------------------------------------------- existence / stability
def _default_r_C_range(h: float, scale: str) -> tuple[float, float]:
    R = max(1.0, 0.5 * h) if scale == "linear" else 20.0
    return -R, R


def _r_C_grid(lo: float, hi: float, n: int, scale: str, linthresh: float) -> np.ndarray:
    """``n`` values of ``r_C`` in ``[lo, hi]``, uniform on the axis's scale."""
    if scale == "linear":
        return np.linspace(lo, hi, n)
    from matplotlib.scale import SymmetricalLogTransform

    fwd = SymmetricalLogTransform(10.0, linthresh, 1.0)
    u = np.linspace(*fwd.transform(np.array([lo, hi])), n)
    return fwd.inverted().transform(u)


def plot_existence_map(h: float, ground: str = "rough", ax=None, *, n=(240, 200),
                       r_C_range: tuple[float, float] | None = None,
                       r_C_scale: str = "symlog", linthresh: float = 0.5,
                       legend: bool = True, title: str | None = None) -> MapPlot:
    """Existence and stability of steady circles in the ``(theta0, r_C)`` plane (Figure 4).

    Rough ground: dark where no steady motion exists (``Omega0^2 <= 0``, eq. 31), gray
    where it exists but is unstable (``varpi^2 < 0``), white where it is stable; the
    boundary curve ``r_C*`` (eq. 32) and the static-equilibrium tilt ``tan theta0 = h`` are
    drawn.

    Smooth ground: the centre C is at rest (``r_C = 0``, section 3.1.2), so a steady motion
    exists only on the line ``r_C = 0`` (for every ``theta0`` and every ``Omega0``); the
    map shows the rest of the plane as "no steady motion" and the line itself.

    The ``theta0`` axis is labelled in degrees (the grid ``x`` stays in radians); with a
    :class:`~rollingdisk.Disk` of physical radius ``a`` the ``r_C`` axis is labelled in
    metres (the grid ``y`` stays in units of ``a``).  The legend sits under the axes.

    Parameters
    ----------
    h : float or Disk
        Half-thickness, ``h >= 0``, or a disk (its ``radius``, if set, gives SI labels).
    ground : {"rough", "smooth"}
    ax : matplotlib Axes, optional
    n : (int, int)
        Grid size along ``theta0`` and ``r_C``.
    r_C_range : (float, float), optional
        Range of ``r_C``; by default ``+-20`` on the symlog scale, ``+-max(1, h/2)`` on the
        linear one.
    r_C_scale : {"symlog", "linear"}
        ``"symlog"`` (default) is linear for ``|r_C| < linthresh`` and logarithmic beyond,
        so that both the small radii near ``r_C*`` and the narrowing of the unstable bands
        at large radii (section 4.1, text after eq. 47) are visible; the grid is uniform on
        the chosen scale.
    """
    from rollingdisk.theory.steady import r_C_star

    disk = disk_of(h)
    h = check_h(h)
    check_ground(ground)
    ax = _axes(ax)
    if r_C_scale not in ("symlog", "linear"):
        raise ParameterError(f"r_C_scale must be 'symlog' or 'linear', got {r_C_scale!r}")
    lo, hi = r_C_range or _default_r_C_range(h, r_C_scale)
    th = _theta_grid(n[0])
    rc = _r_C_grid(lo, hi, n[1], r_C_scale, linthresh)
    TH, RC = np.meshgrid(th, rc)
    cmap, norm = _class_cmap()
    artists = {}
    if ground == "rough":
        codes = existence_codes(h, TH, RC)
    else:
        codes = np.full(TH.shape, NO_MOTION, dtype=np.int8)
    artists["mesh"] = ax.pcolormesh(th, rc, codes, cmap=cmap, norm=norm, shading="nearest",
                                    rasterized=True)
    if ground == "rough":
        with np.errstate(all="ignore"):
            star = np.asarray(r_C_star(h, th), float)
        (artists["r_C_star"],) = ax.plot(th, star, color="tab:red", lw=1.4,
                                         label=r"$r_C^*$ (eq. 32)")
        present = (NO_MOTION, UNSTABLE, STABLE)
    else:
        (artists["line"],) = ax.plot(th, 0.0 * th, color="tab:green", lw=2.5,
                                     label=r"C at rest, $r_C=0$ (any $\Omega_0$)")
        present = (NO_MOTION,)
    if h > 0:
        artists["se"] = ax.axvline(math.atan(h), color="tab:blue", ls="--", lw=1.0,
                                   label=r"SE: $\tan\theta_0=h$")
    f = si_factor(disk, "length")
    if r_C_scale == "symlog":
        ax.set_yscale("symlog", linthresh=linthresh)
        if f == 1.0:
            shown = [-100, -10, -1, 0, 1, 10, 100]  # (+-linthresh crowded +-1)
        else:  # decades of metres
            shown = [0.0] + [s * 10.0 ** k / f for k in range(-6, 4) for s in (-1, 1)
                             if 10.0 ** k / f > 1.5 * linthresh]
        _show_scaled(ax.yaxis, f, sorted(t for t in shown if lo <= t <= hi))
    else:
        _show_scaled(ax.yaxis, f)
    _show_degrees(ax.xaxis)
    ax.set_xlim(0.0, 0.5 * math.pi)
    ax.set_ylim(lo, hi)
    ax.set_xlabel(LABELS["theta0"])
    ax.set_ylabel(axis_label("$r_C$", "length", disk)
                  + (f" (linear for $|r_C|<{linthresh * f:.3g}$)"
                     if r_C_scale == "symlog" else ""))
    ax.set_title(title if title is not None else f"{ground} ground, $h = {h:.4g}$")
    if legend:
        labels = ({} if ground == "rough"
                  else {NO_MOTION: "no steady motion (no friction: C cannot circle)"})
        lines = [a for k, a in artists.items() if k != "mesh"]
        _legend_below(ax, _class_handles(present, labels) + lines)
    return MapPlot(ax, th, rc, codes, artists)


def plot_stability_map(h: float, ground: str, ax=None, *, n=(240, 200),
                       omega30_max: float = 3.0, legend: bool = True,
                       title: str | None = None) -> MapPlot:
    """Sign of ``varpi^2`` of steady circles in the ``(theta0, omega30)`` plane.

    For every ``theta0`` and ``omega30 != 0`` a steady circle exists on either ground
    (``omega20`` follows from eq. 44 rough / eq. 54 smooth), so the map has two classes:
    gray unstable, white stable.  ``values`` holds the class codes; the dotted horizontal
    line is the uniform bound above which every steady circle is stable whatever ``h`` and
    ``theta0``: ``omega30^2 = 1`` on rough ground (as the paper concludes) and
    ``omega30^2 = 4`` on smooth ground (the paper's conclusion prints ``2``, but its own
    section 4.2 puts the top of the surface ``varpi^2 = 0`` at ``omega30 = 2``, h = 0;
    see ``docs/figures.md``).

    ``h`` may be a :class:`~rollingdisk.Disk`: with a physical radius the ``omega30`` axis
    is labelled in rad/s (the grid ``y`` stays in units of ``sqrt(g/a)``); ``theta0`` is
    labelled in degrees (the grid ``x`` stays in radians).
    """
    from rollingdisk.theory.oscillations import varpi2_circle

    disk = disk_of(h)
    h = check_h(h)
    check_ground(ground)
    omega30_max = check_real("omega30_max", omega30_max, low=0.0, low_open=True)
    ax = _axes(ax)
    th = _theta_grid(n[0])
    w = np.linspace(0.0, omega30_max, n[1] + 1)[1:]
    TH, W = np.meshgrid(th, w)
    with np.errstate(all="ignore"):
        v2 = np.asarray(varpi2_circle(h, ground, TH, W), float)
    codes = np.where(np.isfinite(v2) & (v2 > 0), STABLE, UNSTABLE).astype(np.int8)
    cmap, norm = _class_cmap()
    artists = {"mesh": ax.pcolormesh(th, w, codes, cmap=cmap, norm=norm, shading="nearest",
                                     rasterized=True)}
    with np.errstate(all="ignore"):
        if np.nanmin(v2) < 0 < np.nanmax(v2):
            artists["contour"] = ax.contour(th, w, v2, levels=[0.0], colors="k",
                                            linewidths=0.8)
    # uniform bound: the supremum of the surface varpi^2 = 0 over (theta0, h)
    bound = 1.0 if ground == "rough" else 2.0
    if bound <= omega30_max:
        artists["uniform_bound"] = ax.axhline(
            bound, color="tab:purple", ls=":", lw=1.2,
            label=(r"$\omega_{30}^2=" + ("1" if ground == "rough" else "4")
                   + r"\,g/a$: stable above for all $h,\theta_0$"))
    if h > 0:
        artists["se"] = ax.axvline(math.atan(h), color="tab:blue", ls="--", lw=1.0,
                                   label=r"SE: $\tan\theta_0=h$")
    _show_degrees(ax.xaxis)
    _show_scaled(ax.yaxis, si_factor(disk, "angular_speed"))
    ax.set_xlim(0.0, 0.5 * math.pi)
    ax.set_ylim(0.0, omega30_max)
    ax.set_xlabel(LABELS["theta0"])
    ax.set_ylabel(axis_label(r"$\omega_{30}$", "angular_speed", disk))
    ax.set_title(title if title is not None else f"{ground} ground, $h = {h:.4g}$")
    if legend:
        lines = [a for k, a in artists.items() if k in ("uniform_bound", "se")]
        _legend_below(ax, _class_handles((UNSTABLE, STABLE)) + lines)
    return MapPlot(ax, th, w, codes, artists)


def plot_all_omega30_stable(ground: str, ax=None, *, n=(240, 200),
                            theta0_deg_range: tuple[float, float] = (0.0, 90.0),
                            h_range: tuple[float, float] = (0.0, 3.0),
                            mark_h: float | None = None, asymptote: bool = True,
                            title: str | None = None) -> MapPlot:
    """Region of ``(theta0 [deg], h)`` where the steady circle is stable for every
    ``omega30`` (Figure 5 rough, condition (46); Figure 7 smooth, condition (59)).

    White (``values`` True) is stable for every ``omega30``; gray is unstable for some.
    The dashed line is the paper's large-``h`` asymptote of the right boundary
    (``theta0 = arctan(3h/2)`` rough, ``arctan(4h/3)`` smooth); ``mark_h`` draws a
    horizontal line at one disk's ``h``.
    """
    from rollingdisk.theory.oscillations import stable_for_all_omega30

    check_ground(ground)
    if mark_h is not None:
        mark_h = check_real("mark_h", h_of(mark_h), low=0.0)
        h_range = (h_range[0], max(h_range[1], 1.2 * mark_h))  # keep the marked disk in view
    ax = _axes(ax)
    t_lo, t_hi = theta0_deg_range
    deg = np.linspace(t_lo, t_hi, n[0] + 2)[1:-1]
    hh = np.linspace(h_range[0], h_range[1], n[1])
    D, H = np.meshgrid(deg, hh)
    ok = np.asarray(stable_for_all_omega30(H, ground, np.radians(D)), bool)
    cmap, norm = _class_cmap()
    codes = np.where(ok, STABLE, UNSTABLE).astype(np.int8)
    artists = {"mesh": ax.pcolormesh(deg, hh, codes, cmap=cmap, norm=norm, shading="nearest",
                                     rasterized=True)}
    if asymptote:
        k = 1.5 if ground == "rough" else 4.0 / 3.0
        (artists["asymptote"],) = ax.plot(
            np.degrees(np.arctan(k * hh)), hh, color="tab:red", ls="--", lw=1.0,
            label=(r"paper: $\theta_0=\arctan(3h/2)$" if ground == "rough"
                   else r"paper: $\theta_0=\arctan(4h/3)$"))
    if mark_h is not None:
        artists["mark_h"] = ax.axhline(mark_h, color="tab:blue", lw=1.0,
                                       label=f"this disk, $h={mark_h:.4g}$")
    ax.set_xlim(t_lo, t_hi)
    ax.set_ylim(*h_range)
    ax.set_xlabel(LABELS["theta0_deg"])
    ax.set_ylabel(LABELS["h"])
    ax.set_title(title if title is not None
                 else f"{ground} ground: stable for every $\\omega_{{30}}$ (white)")
    if asymptote or mark_h is not None:
        _legend_below(ax, _class_handles((UNSTABLE, STABLE), {UNSTABLE: "unstable for some "
                                          r"$\omega_{30}$", STABLE: r"stable for every "
                                          r"$\omega_{30}$"})
                      + [a for k, a in artists.items() if k != "mesh"])
    return MapPlot(ax, deg, hh, ok, artists)


def _close_fold(ground, H, TH, lo, hi):
    """Grid cells next to the fold of the surface (where the two sheets meet, ``Delta = 0``)
    get the double root, so that the drawn sheets meet instead of leaving a ragged gap.
    This moves the drawn fold by at most one grid cell."""
    from scipy.ndimage import binary_dilation

    from rollingdisk.theory.oscillations import circle_coefficients

    _, P1, P2, _ = circle_coefficients(H, ground, TH)
    valid = np.isfinite(lo) & np.isfinite(hi)
    with np.errstate(all="ignore"):
        double = -P1 / (2.0 * P2)  # the double root in omega30^2
    edge = binary_dilation(valid) & ~valid & np.isfinite(double) & (double > 0)
    lo, hi = lo.copy(), hi.copy()
    lo[edge] = hi[edge] = np.sqrt(double[edge])
    return lo, hi


def plot_varpi2_surface(ground: str, ax=None, *, n=(80, 80),
                        theta0_range: tuple[float, float] = (0.0, 0.5 * math.pi),
                        h_range: tuple[float, float] = (0.0, 2.0),
                        title: str | None = None) -> MapPlot:
    """The surface ``varpi^2 = 0`` in ``(theta0, h, omega30)`` (Figure 6 rough, 8 smooth).

    Both sheets (lower and upper positive root ``omega30`` of the numerator of eq. 45 / 55,
    quadratic in ``omega30^2``) are drawn; where there is no positive root the surface is
    masked.  Outside the closed surface the steady motions are stable.  ``values`` holds
    the upper sheet (NaN where none); ``artists["lower"], artists["upper"]`` are the
    surfaces.
    """
    check_ground(ground)
    ax = _axes(ax, projection="3d", figsize=(6.0, 5.0))
    th = np.linspace(theta0_range[0], theta0_range[1], n[0] + 2)[1:-1]
    hh = np.linspace(h_range[0], h_range[1], n[1])
    TH, H = np.meshgrid(th, hh)
    lo, hi = _close_fold(ground, H, TH, *varpi2_zero_surface(H, ground, TH))
    artists = {}
    for name, Z, color in (("lower", lo, "tab:orange"), ("upper", hi, "tab:blue")):
        if np.isfinite(Z).any():
            artists[name] = ax.plot_surface(TH, H, np.ma.masked_invalid(Z), color=color,
                                            alpha=0.75, linewidth=0, antialiased=False,
                                            rcount=n[1], ccount=n[0])
    _show_degrees(ax.xaxis)
    ax.set_xlabel(LABELS["theta0"])
    ax.set_ylabel(LABELS["h"])
    ax.set_zlabel(LABELS["omega30"])
    ax.set_xlim(*theta0_range)
    ax.set_ylim(*h_range)
    zmax = np.nanmax(hi) if np.isfinite(hi).any() else 1.0
    ax.set_zlim(0.0, 1.05 * zmax)
    ax.view_init(elev=25, azim=-60)
    ax.set_title(title if title is not None
                 else f"{ground} ground: surface $\\varpi^2=0$")
    return MapPlot(ax, th, hh, hi, artists)


def plot_varpi2_curves(h: float, ground: str, ax=None, *, theta0s=None,
                       omega30_max: float = 3.0, n: int = 400,
                       title: str | None = None) -> dict:
    """``varpi^2`` of steady circles against ``omega30`` for a few tilts ``theta0``.

    ``varpi^2 > 0`` (above the zero line) is stable; ``varpi`` is then the angular
    frequency of the small oscillation of the tilt, ``sqrt(-varpi^2)`` otherwise the rate
    at which a disturbance grows (eqs. 45 / 55 as corrected in the library).  By default
    the tilts are 0.1, the static-equilibrium tilt ``arctan h`` (if ``h > 0``), 0.5 and 1.0
    rad.  Returns ``{"ax": ax, "lines": {theta0: Line2D}}`` (the lines' data in the paper's
    units; the axes are labelled in rad/s and rad^2/s^2 when ``h`` is a
    :class:`~rollingdisk.Disk` with a physical radius).
    """
    from rollingdisk.theory.oscillations import varpi2_circle

    disk = disk_of(h)
    h = check_h(h)
    check_ground(ground)
    ax = _axes(ax)
    if theta0s is None:
        theta0s = [0.1, 0.5, 1.0] + ([math.atan(h)] if h > 0 else [])
    w = np.linspace(0.0, omega30_max, n + 1)[1:]
    lines = {}
    for th in sorted(theta0s):
        with np.errstate(all="ignore"):
            v2 = np.asarray(varpi2_circle(h, ground, th, w), float)
        label = (f"$\\theta_0 = {math.degrees(th):.3g}°$"
                 + (" (SE)" if h > 0 and th == math.atan(h) else ""))
        (lines[th],) = ax.plot(w, v2, lw=1.2, label=label)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_ylim(-3.0, 6.0)
    ax.set_xlim(0.0, omega30_max)
    _show_scaled(ax.xaxis, si_factor(disk, "angular_speed"))
    _show_scaled(ax.yaxis, si_factor(disk, "rate_sq"))
    ax.set_xlabel(axis_label(r"$\omega_{30}$", "angular_speed", disk))
    ax.set_ylabel(axis_label(r"$\varpi^2$", "rate_sq", disk))
    ax.legend(loc="lower right", fontsize=LEGEND_FONTSIZE)
    ax.set_title(title if title is not None else f"{ground} ground, $h = {h:.4g}$")
    return {"ax": ax, "lines": lines}


# ------------------------------------------------------------------------------ trajectories
def trajectory_series(traj, name: str) -> np.ndarray:
    """A time series of ``traj``: its attribute ``name`` if it has one, else computed from
    ``traj.y`` with :mod:`rollingdisk.model.equations` (needs ``traj.disk``, ``traj.ground``).

    Works with :class:`rollingdisk.Trajectory` and any object with ``disk``,
    ``ground``, ``t`` and ``y`` of shape ``(n_state, n)``.
    """
    value = getattr(traj, name, None)
    if value is not None:
        return np.asarray(value, float)
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


def _time_axis(ax, disk) -> None:
    """The time axis of a trajectory plot: data in units of ``sqrt(a/g)``, shown in seconds
    when ``disk`` has a physical radius."""
    _show_scaled(ax.xaxis, si_factor(disk, "time"))
    ax.set_xlabel(axis_label("$t$", "time", disk))


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


# ---------------------------------------------------------------------------- sweeps
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


# ---------------------------------------------------------------------------- exact motions
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


def _thin(n: int, k: int = 3000) -> np.ndarray:
    """At most about ``k`` indices of ``n`` points (evenly, plus the last)."""
    if n <= k:
        return np.arange(n)
    return np.unique(np.append(np.linspace(0, n - 1, k).astype(int), n - 1))


def euler_disk_title(result) -> str:
    """A figure title for Euler's disk run to its end, in one style: symbols with units,
    SI first, the paper's time unit after (``"Euler's disk: fell flat, α = 0.001 rad at
    t = 100.3 s (1623 √(a/g))"``)."""
    r = result
    words = {"fell-flat": "fell flat", "lift-off": "lifted off",
             "edge-contact": "the other rim edge touched", "at-rest": "came to rest"}
    what = words.get(r.end, r.end) if r.end is not None else f"stopped ({r.status})"
    alpha = float(r.alpha[-1]) if np.size(r.alpha) else float("nan")
    return (f"Euler's disk: {what}, α = {alpha:.3g} rad ({math.degrees(alpha):.3g}°) at "
            f"t = {r.t_end_s:.4g} s ({r.t_end:.4g} √(a/g))")


def plot_euler_disk(result, fig=None, *, title: str | None = None) -> dict:
    """Euler's disk run to its end (:func:`rollingdisk.scenarios.euler_disk.run_euler_disk`).

    ``title``: by default :func:`euler_disk_title`; ``""`` for none.

    Left: the tilt ``alpha``, the precession rate ``Omega`` and the contact-point speed
    against time (seconds), the end marked.  Right: the same against ``t0 - t`` on log-log
    axes (``t0`` the fitted singular time), with the fitted power laws over the fit window
    (solid) and the slopes predicted by the steady family (dashed), exponents in the legend.

    Returns
    -------
    dict
        ``fig``, ``axes`` (the two axes) and ``lines`` (name -> Line2D).
    """
    plt = _pyplot()
    if fig is None:
        fig = plt.figure(figsize=(10.0, 4.2))
    ax1, ax2 = fig.subplots(1, 2)
    r = result
    unit = r.toy.time_unit
    i = _thin(r.t.size)
    t = r.t[i] * unit
    series = (("alpha", r"$\alpha$ [deg]", np.degrees(r.alpha), "C0"),
              ("Omega", r"$\Omega$ [rad/s]", r.Omega / unit, "C1"),
              ("contact_speed", r"$v_P$ [m/s]", r.contact_speed
               * math.sqrt(r.toy.radius * r.toy.gravity), "C2"))
    lines = {}
    for name, label, y, color in series:
        (lines[name],) = ax1.semilogy(t, y[i], color=color, lw=1.2, label=label)
    if r.end is not None:
        ax1.axvline(r.t_end_s, color="0.4", ls=":", lw=1)
        ax1.annotate(f"{r.end}\n{r.t_end_s:.1f} s", (r.t_end_s, 0.5),
                     xycoords=("data", "axes fraction"), ha="right", va="center",
                     fontsize=8, color="0.3")
    ax1.set_xlabel("t [s]")
    ax1.legend(loc="upper left", fontsize=8)
    ax1.set_title("tilt, precession rate, contact-point speed", fontsize=9)
    if math.isfinite(r.t0):
        tau = (r.t0 - r.t) * unit
        ok = tau > 0
        j = np.flatnonzero(ok)[_thin(np.count_nonzero(ok))]
        lo, hi = r.fit_window
        w = (r.alpha > lo) & (r.alpha < hi) & ok
        for name, label, y, color in series:
            ax2.loglog(tau[j], y[j], color=color, lw=1.0, alpha=0.6)
            if np.count_nonzero(w) >= 2:
                tw, yw = tau[w], y[w]
                p, q = r.exponents[name], r.predicted[name]
                ref = np.exp(np.mean(np.log(yw) - p * np.log(tw)))
                tt = np.geomspace(tw.min(), tw.max(), 20)
                (lines[f"{name}_fit"],) = ax2.loglog(
                    tt, ref * tt ** p, color=color, lw=2.4,
                    label=f"{label.split(' ')[0]}: fit {p:.4g}, predicted {q:.4g}")
                if math.isfinite(q):
                    qref = np.exp(np.mean(np.log(yw) - q * np.log(tw)))
                    (lines[f"{name}_predicted"],) = ax2.loglog(
                        tt, qref * tt ** q * 1.6, color=color, lw=1.2, ls="--")
        ax2.set_xlabel(r"$t_0 - t$ [s]  ($t_0$ fitted: " + f"{r.t0_s:.2f} s)")
        ax2.legend(loc="best", fontsize=8, title="exponents (dashed: predicted, offset)",
                   title_fontsize=8)
    else:
        ax2.text(0.5, 0.5, "the fit window was not reached", ha="center",
                 transform=ax2.transAxes)
    ax2.set_title(r"log-log against $t_0 - t$", fontsize=9)
    title = euler_disk_title(r) if title is None else title
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return {"fig": fig, "axes": (ax1, ax2), "lines": lines}
