"""The sweeps behind the simulated stability maps (``rollingdisk map --kind nonlinear``,
``--kind basin``): kicked steady circles over the (theta0, omega30) plane."""

from __future__ import annotations

import numpy as np

from rollingdisk.sweep.runner import Perturbation, SweepGrid, basin_sweep, run_sweep
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["MAP_THETA0", "MAP_OMEGA30", "map_sweep"]

#: theta0 range of the maps (rad): the steady circles from nearly upright to nearly flat.
MAP_THETA0 = (0.05, 1.5)
#: omega30 range of the maps (spin rate in units sqrt(g/a)).
MAP_OMEGA30 = (0.1, 3.0)


def map_sweep(ground: str, h: float, kind: str, *, n: int = 40, t_end: float = 100.0,
              kick: float = 1e-3, kick_max: float = 0.5, rounds: int = 8, progress=None):
    """Sweep an ``n x n`` grid of steady circles for a simulated stability map.

    Parameters
    ----------
    ground : {"rough", "smooth"}
        The ground.
    h : float
        Half-thickness / radius.
    kind : {"nonlinear", "basin"}
        ``"nonlinear"``: each circle kicked by ``kick`` in omega1 and integrated to
        ``t_end`` (:func:`run_sweep`); ``"basin"``: the largest kick up to ``kick_max``
        that stays bounded, by ``rounds`` bisection rounds (:func:`basin_sweep`).
    n : int
        Points per axis, theta0 over :data:`MAP_THETA0` and omega30 over
        :data:`MAP_OMEGA30` (default 40).
    t_end : float
        Simulated time of each run (default 100, time unit sqrt(a/g)).
    kick, kick_max : float
        The kick of the nonlinear map, the largest kick of the basin map.
    rounds : int
        Bisection rounds of the basin map.
    progress : callable, optional
        Passed to the sweep.

    Returns
    -------
    xarray.Dataset
        The sweep (for :func:`~rollingdisk.plotting.plots.plot_nonlinear_map` or
        :func:`~rollingdisk.plotting.plots.plot_basin_map`).
    """
    if kind not in ("nonlinear", "basin"):
        raise ParameterError(f"kind must be 'nonlinear' or 'basin', got {kind!r}")
    n = check_int("n", n, low=2, high=400)
    t_end = check_real("t_end", t_end, low=0.0, low_open=True)
    grid = SweepGrid(ground, h=h, theta0=np.linspace(*MAP_THETA0, n),
                     omega30=np.linspace(*MAP_OMEGA30, n))
    if kind == "nonlinear":
        return run_sweep(grid, t_end, perturbation=Perturbation(kick=kick), progress=progress)
    return basin_sweep(grid, t_end, kick_max=kick_max, rounds=rounds, progress=progress)
