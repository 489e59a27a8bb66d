"""Many runs at once: grids of steady motions, their kicked simulations on every core or a
Dask cluster, and the resumable stores they stream to.
"""

from rollingdisk.sweep.runner import (
    BOUND_FACTOR as BOUND_FACTOR,
)
from rollingdisk.sweep.runner import (
    GROW_HI as GROW_HI,
)
from rollingdisk.sweep.runner import (
    GROW_LO as GROW_LO,
)
from rollingdisk.sweep.runner import (
    Perturbation as Perturbation,
)
from rollingdisk.sweep.runner import (
    SweepGrid as SweepGrid,
)
from rollingdisk.sweep.runner import (
    basin_sweep as basin_sweep,
)
from rollingdisk.sweep.runner import (
    open_sweep as open_sweep,
)
from rollingdisk.sweep.runner import (
    run_sweep as run_sweep,
)

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
