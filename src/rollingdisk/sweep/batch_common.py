"""What every batch kernel of the sweeps shares (numba; imported lazily): the compile
decorator, the summary columns and how a trajectory's running summaries become one row of
them (:mod:`rollingdisk.sweep.batch` runs the kernels).
"""

from __future__ import annotations

import numba
import numpy as np

from rollingdisk.engine.numba_core import (
    SOURCE_KEY,
    energy_sc,
    geometry,
)


def _jit(**kw):
    """``numba.njit(cache=True, **kw)`` under a name that carries the hash of the sources the
    function may call (:func:`rollingdisk.engine.compile.source_key`): numba's cache is
    keyed by this file alone, and a kernel cached before an edit of taylor.py or lanes.py
    (which it inlines or traces) would otherwise be loaded stale."""

    def deco(f):
        f.__qualname__ = f"{f.__qualname__}_{SOURCE_KEY}"
        return numba.njit(cache=True, **kw)(f)

    return deco


#: The summary columns of every batch kernel (float64 array of shape (n, NCOL)).
COLUMNS = ("status", "t_end", "max_dtheta", "n_crossings", "period", "t_grow_lo",
           "t_grow_hi", "energy_drift", "n_steps")
NCOL = len(COLUMNS)


@_jit()
def _reduced_energy(rough, h, k1, k2, y):
    """E of the reduced state (:func:`energy_sc`)."""
    ht, s, c, p, y_P, z_P = geometry(h, y[0])
    return energy_sc(rough, ht, k1, k2, s, c, y)


@_jit()
def _add_crossing(cr, tc):
    """Add the crossing time ``tc`` to the least-squares sums ``cr = (count, sum k, sum t_k,
    sum k^2, sum k t_k)`` of the crossing times t_k against their index k."""
    k = cr[0]
    cr[1] += k
    cr[2] += tc
    cr[3] += k * k
    cr[4] += k * tc
    cr[0] = k + 1.0


@_jit()
def _summaries(out, status, t, max_d, cr, t_lo, t_hi, e_drift, n_steps):
    """Fill one row of :data:`COLUMNS`; the period is the least-squares slope of the
    crossing times against their index (sums ``cr`` of :func:`_add_crossing`), NaN below
    two crossings."""
    nc, sk, st, skk, skt = cr[0], cr[1], cr[2], cr[3], cr[4]
    period = np.nan
    if nc >= 2:
        den = nc * skk - sk * sk
        period = (nc * skt - sk * st) / den
    out[0] = status
    out[1] = t
    out[2] = max_d
    out[3] = nc
    out[4] = period
    out[5] = t_lo
    out[6] = t_hi
    out[7] = e_drift
    out[8] = n_steps


@_jit()
def _spread(n):
    """A permutation of 0..n-1 that spreads neighbours apart (the golden-ratio sequence
    ``frac(i phi)``, sorted): the threads of a ``prange`` take contiguous ranges of it, so
    each gets a fair share of every part of the grid (in grid order one thread would take
    the low tilts, with fewer steps, and another the high ones).  Each trajectory is
    computed alone, so the order changes no result."""
    key = np.empty(n)
    for i in range(n):
        x = i * 0.6180339887498949
        key[i] = x - np.floor(x)
    return np.argsort(key, kind="mergesort")
