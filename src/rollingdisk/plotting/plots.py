"""Plots: existence and stability maps of steady motions (sections 3-4) and trajectories.

This module sits outside the numeric core: it calls :mod:`rollingdisk.theory.steady`,
:mod:`rollingdisk.theory.oscillations` and :mod:`rollingdisk.model.equations` and draws what they
return.
It never re-implements a formula of the paper, and what a map shows (which steady
motions exist, which are stable) is computed in :mod:`rollingdisk.theory.regions`.  matplotlib is
imported only when a plot function is called; every function takes ``ax=None`` (a new
figure is made when it is ``None``), returns what it drew and never calls ``plt.show()``.

One import path for every plot function, each kind of plot in a module of its own:
the maps of steady motions (:mod:`.maps`), one trajectory or exact motion
(:mod:`.trajectory_plots`), a sweep's nonlinear runs (:mod:`.sweep_plots`), Euler's disk
(:mod:`.euler_plot`); what they share (class colours, labels and units of axes) is
:mod:`.style`, image files :mod:`.images`.

Map functions return a :class:`MapPlot`: the axes, the grid, the values on the grid (a
class code of :mod:`rollingdisk.theory.regions` or ``varpi2``) and the artists.  Class codes are

* ``NO_MOTION = 0``: no steady motion (``Omega0^2 <= 0``),
* ``UNSTABLE = 1``: a steady motion exists but ``varpi^2 < 0``,
* ``STABLE = 2``: ``varpi^2 > 0``.
"""

from __future__ import annotations

from rollingdisk.plotting.euler_plot import euler_disk_title, plot_euler_disk
from rollingdisk.plotting.images import (
    DPI_RANGE,
    IMAGE_FORMATS,
    check_dpi,
    image_format,
    save_figure,
)
from rollingdisk.plotting.maps import (
    MapPlot,
    plot_all_omega30_stable,
    plot_existence_map,
    plot_stability_map,
    plot_varpi2_curves,
    plot_varpi2_surface,
)
from rollingdisk.plotting.style import AXIS_UNITS as AXIS_UNITS
from rollingdisk.plotting.style import CLASS_COLORS, axis_label, disk_of, si_factor
from rollingdisk.plotting.style import CLASS_LABELS as CLASS_LABELS
from rollingdisk.plotting.style import LABELS as LABELS
from rollingdisk.plotting.style import LEGEND_FONTSIZE as LEGEND_FONTSIZE
from rollingdisk.plotting.sweep_plots import plot_basin_map, plot_nonlinear_map
from rollingdisk.plotting.trajectory_plots import (
    plot_backbone,
    plot_contact_forces,
    plot_energy_error,
    plot_exact,
    plot_exact_theta,
    plot_paths,
    plot_rosette,
    plot_theta,
    plot_trajectory,
    trajectory_series,
)

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
