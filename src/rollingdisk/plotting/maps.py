"""Maps of the steady motions (sections 3-4): where they exist, where they are stable,
where they are stable for every ``omega30`` (Figures 4-7), ``varpi^2`` as a surface and
along lines; what each map drew comes back as a :class:`MapPlot`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.model.disk import check_ground, check_h, h_of
from rollingdisk.plotting.style import (
    LABELS,
    LEGEND_FONTSIZE,
    _axes,
    _class_cmap,
    _class_handles,
    _legend_below,
    _show_degrees,
    _show_scaled,
    _theta_grid,
    axis_label,
    disk_of,
    si_factor,
)
from rollingdisk.theory.regions import (
    NO_MOTION,
    STABLE,
    UNSTABLE,
    existence_codes,
    varpi2_zero_surface,
)
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["MapPlot", "plot_existence_map", "plot_stability_map", "plot_all_omega30_stable",
           "plot_varpi2_surface", "plot_varpi2_curves"]


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
