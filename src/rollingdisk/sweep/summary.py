"""What a finished sweep says in one number: simulated against closed-form stability."""

from __future__ import annotations

import numpy as np

from rollingdisk.util.checks import check_real

__all__ = ["stability_agreement"]


def stability_agreement(ds, *, margin: float = 0.05) -> float | None:
    """Fraction of the grid where the simulation agrees with the sign of ``varpi^2``.

    Near ``varpi^2 = 0`` (eqs. 40, 51) a finite run cannot tell a slow growth from a slow
    oscillation, so points with ``|varpi^2| <= margin`` are left out.

    Parameters
    ----------
    ds : xarray.Dataset
        The result of :func:`~rollingdisk.sweep.runner.run_sweep` (variables ``varpi2``,
        ``stable`` and ``stable_simulated``).
    margin : float
        Points with ``|varpi^2| <= margin`` are not counted (default 0.05).

    Returns
    -------
    float or None
        The fraction in [0, 1], or None when no point is beyond the margin (or the
        dataset holds no simulated verdict, e.g. a basin sweep).

    Examples
    --------
    >>> import xarray as xr
    >>> ds = xr.Dataset({"varpi2": ("i", [1.0, -1.0, 0.01]),
    ...                  "stable": ("i", [True, False, True]),
    ...                  "stable_simulated": ("i", [True, True, False])})
    >>> stability_agreement(ds)
    0.5
    """
    margin = check_real("margin", margin, low=0.0)
    if "stable_simulated" not in ds or "varpi2" not in ds or "stable" not in ds:
        return None
    far = np.abs(np.asarray(ds.varpi2.values, dtype=float)) > margin
    if not far.any():
        return None
    same = np.asarray(ds.stable_simulated.values)[far] == np.asarray(ds.stable.values)[far]
    return float(np.mean(same))
