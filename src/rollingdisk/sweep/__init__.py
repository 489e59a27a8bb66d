"""Many runs at once: grids of steady motions, their kicked simulations on every core or a
Dask cluster, and the resumable stores they stream to.

Modules: :mod:`~rollingdisk.sweep.grid` (grids, perturbations, set-up),
:mod:`~rollingdisk.sweep.executors` (serial, threads, Dask), :mod:`~rollingdisk.sweep.store`
(the locked partial folder, the described dataset, the final store),
:mod:`~rollingdisk.sweep.options` (the one validator of the arguments),
:mod:`~rollingdisk.sweep.runner` (:func:`run_sweep`) and :mod:`~rollingdisk.sweep.basin`
(:func:`basin_sweep`).
"""

from rollingdisk.sweep.basin import basin_sweep as basin_sweep
from rollingdisk.sweep.grid import BOUND_FACTOR as BOUND_FACTOR
from rollingdisk.sweep.grid import GROW_HI as GROW_HI
from rollingdisk.sweep.grid import GROW_LO as GROW_LO
from rollingdisk.sweep.grid import Perturbation as Perturbation
from rollingdisk.sweep.grid import SweepGrid as SweepGrid
from rollingdisk.sweep.runner import run_sweep as run_sweep
from rollingdisk.sweep.store import open_sweep as open_sweep

__all__ = [
    "SweepGrid",
    "Perturbation",
    "run_sweep",
    "basin_sweep",
    "open_sweep",
    "BOUND_FACTOR",
    "GROW_LO",
    "GROW_HI",
]
