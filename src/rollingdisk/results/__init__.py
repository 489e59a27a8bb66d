"""What a run returns and what is measured on it: :class:`Trajectory` and :class:`Transition`,
the measurements compared with the theory, streamed summaries, and data out (xarray,
pandas, CSV with units).
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "Trajectory": "rollingdisk.results.trajectory",
    "Transition": "rollingdisk.results.trajectory",
    "energy_drift": "rollingdisk.results.measure",
    "oscillation_frequency": "rollingdisk.results.measure",
    "growth_rate": "rollingdisk.results.measure",
    "fit_circle": "rollingdisk.results.measure",
    "TheoryComparison": "rollingdisk.results.measure",
    "compare_with_theory": "rollingdisk.results.measure",
    "LINEAR_RANGE": "rollingdisk.results.measure",
})
