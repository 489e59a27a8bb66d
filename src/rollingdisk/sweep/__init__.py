"""Many runs at once: grids of steady motions, their kicked simulations on every core or a
Dask cluster, and the resumable stores they stream to.

Modules: :mod:`~rollingdisk.sweep.grid` (grids, perturbations, set-up),
:mod:`~rollingdisk.sweep.executors` (serial, threads, Dask), :mod:`~rollingdisk.sweep.store`
(the locked partial folder, the described dataset, the final store),
:mod:`~rollingdisk.sweep.options` (the one validator of the arguments),
:mod:`~rollingdisk.sweep.runner` (:func:`run_sweep`) and :mod:`~rollingdisk.sweep.basin`
(:func:`basin_sweep`).
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "SweepGrid": "rollingdisk.sweep.grid",
    "Perturbation": "rollingdisk.sweep.grid",
    "run_sweep": "rollingdisk.sweep.runner",
    "basin_sweep": "rollingdisk.sweep.basin",
    "open_sweep": "rollingdisk.sweep.store",
    "BOUND_FACTOR": "rollingdisk.sweep.grid",
    "GROW_LO": "rollingdisk.sweep.grid",
    "GROW_HI": "rollingdisk.sweep.grid",
})
