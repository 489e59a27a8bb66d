"""The order of the gallery: from one disk's numbers (and the notebook view that shows them)
to whole maps and Euler's disk."""

from __future__ import annotations

import os

ORDER = (
    "plot_coin_thresholds.py",
    "plot_steady_circle.py",
    "plot_notebook_widget.py",
    "plot_friction_sliding.py",
    "plot_exact_orbit.py",
    "plot_sweep_basin.py",
    "plot_euler_disk.py",
)


def example_order(filename: str) -> tuple[int, str]:
    """Sort key of sphinx-gallery's ``within_subsection_order``: listed examples first, in
    :data:`ORDER`, then any other by name."""
    name = os.path.basename(filename)
    return (ORDER.index(name) if name in ORDER else len(ORDER), name)
