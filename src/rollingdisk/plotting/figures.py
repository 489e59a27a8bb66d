"""The paper's Figures 4-8, recomputed from the library (sections 3.2.1, 4.1, 4.2).

Each ``figureN`` returns a matplotlib Figure; :func:`paper_figures` writes them all as
``fig4.png`` ... ``fig8.png``.  Where the library's (derived and checked) result differs
from the paper's description, the figure shows the library's result; see
``docs/figures.md``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

from rollingdisk.plotting import plots as plotting
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["FIGURE_HS", "SCALE_MAX", "figure4", "figure5", "figure6", "figure7", "figure8",
           "paper_figures", "FIGURES"]

#: Largest grid resolution factor of :func:`paper_figures` (4: about 1000 x 800 cells per
#: map, 360 x 360 on the surfaces; beyond it the work and memory grow without a visible
#: gain).
SCALE_MAX = 4.0

#: The four thicknesses of Figure 4.
FIGURE_HS = (0.0, 0.17, math.sqrt(3.0) / 2.0, 5.0)


def _figure(figsize):
    from matplotlib.figure import Figure

    return Figure(figsize=figsize)


def _check_scale(scale) -> float:
    return check_real("scale", scale, low=0.0, high=SCALE_MAX, low_open=True)


#: The Parameters and Returns of every ``figureN``, written once.
_FIGURE_SECTIONS = """

    Parameters
    ----------
    scale : float
        Grid resolution factor in ``(0, 4]`` (:data:`SCALE_MAX`).

    Returns
    -------
    matplotlib Figure
        With ``fig.maps``, the :class:`~rollingdisk.plotting.plots.MapPlot` of each panel.
    """


def _figure_doc(f):
    """``f`` with :data:`_FIGURE_SECTIONS` after its summary."""
    f.__doc__ = f.__doc__.rstrip() + _FIGURE_SECTIONS
    return f


@_figure_doc
def figure4(scale: float = 1.0):
    """Figure 4: ``Omega0^2 > 0`` and ``varpi^2 > 0`` in ``(theta0, r_C)``, rough ground,
    for ``h = 0, 0.17, sqrt(3)/2, 5``."""
    scale = _check_scale(scale)
    fig = _figure((10.0, 8.0))
    axs = fig.subplots(2, 2)
    n = (max(20, int(240 * scale)), max(20, int(200 * scale)))
    names = ("0", "0.17", r"\sqrt{3}/2", "5")
    maps = []
    for ax, h, name, letter in zip(axs.flat, FIGURE_HS, names, "abcd", strict=True):
        maps.append(plotting.plot_existence_map(
            h, "rough", ax, n=n, legend=(letter == "a"),
            title=f"({letter}) $h = {name}$"))
    fig.suptitle(r"Rough ground: steady circles in the $(\theta_0, r_C)$ plane")
    fig.tight_layout()
    fig.maps = maps
    return fig


def _all_omega30_figure(ground: str, scale: float, zoom: tuple[tuple, tuple]):
    scale = _check_scale(scale)
    fig = _figure((11.0, 4.6))
    axs = fig.subplots(1, 2)
    n = (max(20, int(240 * scale)), max(20, int(200 * scale)))
    m1 = plotting.plot_all_omega30_stable(ground, axs[0], n=n, title=f"{ground} ground")
    (t0, t1), (h0, h1) = zoom
    m2 = plotting.plot_all_omega30_stable(ground, axs[1], n=n, theta0_deg_range=(t0, t1),
                                          h_range=(h0, h1), asymptote=False,
                                          title="magnified near $\\theta_0 = 0$")
    from matplotlib.patches import Rectangle

    axs[0].add_patch(Rectangle((t0, h0), t1 - t0, h1 - h0, fill=False, ec="tab:green", lw=1.2))
    fig.suptitle(f"{ground.capitalize()} ground: white = stable for every "
                 r"$\omega_{30}$ (gray: unstable for some $\omega_{30}$)")
    fig.tight_layout()
    fig.maps = [m1, m2]
    return fig


@_figure_doc
def figure5(scale: float = 1.0):
    """Figure 5: rough ground, region stable for every ``omega30`` in ``(theta0 [deg], h)``
    (condition 46), with the small region near ``theta0 = 0`` magnified."""
    return _all_omega30_figure("rough", scale, ((0.0, 1.0), (0.6, 1.05)))


@_figure_doc
def figure7(scale: float = 1.0):
    """Figure 7: as Figure 5 on smooth ground (condition 59)."""
    return _all_omega30_figure("smooth", scale, ((0.0, 15.0), (0.3, 1.0)))


def _surface_figure(ground: str, scale: float):
    scale = _check_scale(scale)
    fig = _figure((7.0, 5.8))
    ax = fig.add_subplot(1, 1, 1, projection="3d")
    n = (max(16, int(90 * scale)), max(16, int(90 * scale)))
    m = plotting.plot_varpi2_surface(ground, ax, n=n)
    fig.maps = [m]
    return fig


@_figure_doc
def figure6(scale: float = 1.0):
    """Figure 6: rough ground, the surface ``varpi^2 = 0`` (eq. 45) in
    ``(theta0, h, omega30)``; theta0 in radians."""
    return _surface_figure("rough", scale)


@_figure_doc
def figure8(scale: float = 1.0):
    """Figure 8: smooth ground, the surface ``varpi^2 = 0`` (eq. 55)."""
    return _surface_figure("smooth", scale)


FIGURES: dict[str, Callable] = {"fig4": figure4, "fig5": figure5, "fig6": figure6,
                                "fig7": figure7, "fig8": figure8}


def paper_figures(out_dir, *, scale: float = 1.0, dpi: int = 110,
                  only=None, progress: Callable[[str], None] | None = None) -> list[Path]:
    """Write ``fig4.png`` ... ``fig8.png`` into the folder ``out_dir``; return their paths.

    The folder is built under a temporary name and swapped in at the end
    (:func:`rollingdisk.util.files.atomic_dir`), so it appears whole or not at all; the figures
    of an earlier run that ``only`` leaves out are carried over.  An existing ``out_dir``
    is replaced only if it holds nothing but ``figN.png`` files.

    Parameters
    ----------
    out_dir : path-like
        The folder to write; its parent folder must exist.
    scale : float
        Grid resolution factor in ``(0, 4]`` (:data:`SCALE_MAX`; ``0.2`` for a quick
        low-resolution check).
    dpi : int
        Resolution of the PNG files, in :data:`rollingdisk.plotting.plots.DPI_RANGE`.
    only : iterable of str, optional
        A subset of ``"fig4" ... "fig8"``.
    progress : callable, optional
        Called with a short message before each figure.

    Returns
    -------
    list of Path
        The files written, in ``out_dir``.

    Raises
    ------
    ParameterError
        For an argument out of range or a folder that cannot be written (before any work).
    """
    import shutil

    from rollingdisk.util.files import atomic_dir, check_replaceable

    scale = _check_scale(scale)
    dpi = plotting.check_dpi(dpi)
    if isinstance(only, str):
        only = [only]
    try:
        names = list(FIGURES) if only is None else list(dict.fromkeys(only))
    except TypeError:
        raise ParameterTypeError(f"only must be a list of figure names, got {only!r}") from None
    for name in names:
        if name not in FIGURES:
            raise ParameterError(f"figure must be one of {tuple(FIGURES)}, got {name!r}")
    if progress is not None and not callable(progress):
        raise ParameterTypeError(f"progress must be callable, got {progress!r}")
    files = [f"{name}.png" for name in FIGURES]
    target = check_replaceable(out_dir, files, name="out_dir")
    with atomic_dir(target) as tmp:
        for name in names:
            if progress:
                progress(f"{name} ...")
            fig = FIGURES[name](scale)
            fig.savefig(tmp / f"{name}.png", dpi=dpi, format="png")
        for file in files:  # the figures of an earlier run that this one leaves alone
            if file[:-4] not in names and (target / file).is_file():
                shutil.copy2(target / file, tmp / file)
    return [target / f"{name}.png" for name in names]
