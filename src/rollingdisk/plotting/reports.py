"""Files of one run, written whole or not at all: the figure of an exact motion
(``rollingdisk exact --out``) and the folder of Euler's disk (``rollingdisk euler-disk
--out``: PNG, CSV, JSON).  matplotlib is used without pyplot (the user's backend is left
alone)."""

from __future__ import annotations

import json

import numpy as np

from rollingdisk.plotting.plots import check_dpi, plot_euler_disk, plot_exact, save_figure
from rollingdisk.results.stream import write_columns
from rollingdisk.util.checks import check_int
from rollingdisk.util.errors import ParameterError
from rollingdisk.util.files import atomic_dir, check_replaceable

__all__ = ["EULER_DISK_FILES", "write_euler_disk", "save_exact_figure"]

#: Files :func:`write_euler_disk` writes into its folder (replaced as a whole).
EULER_DISK_FILES = ("euler_disk.png", "euler_disk.csv", "euler_disk.json")


def write_euler_disk(result, out, *, dpi: int = 90):
    """Write Euler's disk run to its end into the folder ``out``, whole or not at all.

    Parameters
    ----------
    result : EulerDiskResult
        From :func:`rollingdisk.scenarios.euler_disk.run_euler_disk`.
    out : path-like
        The folder: new, empty, or one written here before (it is replaced as a whole;
        :func:`~rollingdisk.util.files.check_replaceable` refuses any other).
    dpi : int
        Resolution of the PNG.

    Returns
    -------
    pathlib.Path
        The folder, holding :data:`EULER_DISK_FILES`: the figure
        (:func:`~rollingdisk.plotting.plots.plot_euler_disk`), the time series
        (``result.as_columns()``) and the summary (``result.summary()``, strict JSON).
    """
    from matplotlib.figure import Figure

    dpi = check_dpi(dpi)
    target = check_replaceable(out, EULER_DISK_FILES, name="out")
    summary = result.summary()
    with atomic_dir(target) as tmp:
        fig = Figure(figsize=(10.0, 4.2))
        plot_euler_disk(result, fig)  # title: euler_disk_title(result)
        fig.savefig(tmp / EULER_DISK_FILES[0], dpi=dpi)
        with open(tmp / EULER_DISK_FILES[1], "w", newline="") as fh:
            write_columns(fh, result.as_columns(), fmt="%.12g")
        with open(tmp / EULER_DISK_FILES[2], "w") as fh:
            json.dump(summary, fh, indent=2, allow_nan=False)
    return target


def save_exact_figure(ex, path, *, motion=None, kick: float = 0.0, n_periods: int = 20,
                      dpi: int = 110) -> None:
    """Write the figure of an exact motion: ``theta(t)`` over a period, the contact point's
    rosette and, about a stable steady motion, the backbone curve (frequency against
    amplitude, tending to ``varpi``, eq. 39).

    Parameters
    ----------
    ex : ExactMotion
        From :func:`rollingdisk.theory.exact.exact_motion` or ``exact_steady``; bounded.
    path : path-like
        The image file (written whole or not at all).
    motion : SteadyMotion, optional
        The steady motion ``ex`` was kicked from: with ``varpi^2 > 0`` the backbone is
        drawn for 24 kicks up to ``1.5 max(|kick|, 1e-3)``.
    kick : float
        The kick of ``ex`` (sets the backbone's range).
    n_periods : int
        Periods of the rosette.
    dpi : int
        Resolution.
    """
    from matplotlib.figure import Figure

    from rollingdisk.theory import exact
    from rollingdisk.theory.oscillations import stability

    n_periods = check_int("n_periods", n_periods, low=1, high=1000)
    if ex.status != "bounded":
        raise ParameterError(f"--out: the motion is {ex.status}; the figure (theta over a "
                             "period, rosette) needs a bounded motion")
    bb = None
    if motion is not None and stability(motion).varpi2 > 0:
        top = max(abs(kick), 1e-3) * 1.5
        bb = exact.backbone(motion, np.linspace(top / 40, top, 24))
    fig = Figure(figsize=(12.6 if bb is not None else 8.4, 4.0))
    plot_exact(ex, fig, backbone=bb, n_periods=n_periods,
               title=f"exact motion, {ex.ground} ground, h = {ex.disk.h:.4g}")
    save_figure(fig, path, dpi=dpi)
