"""Parameter sweeps: many perturbed steady motions, integrated in batches.

A sweep integrates the reduced system ``(theta, omega1, omega2, omega3)`` (eq. 2 with
eq. 38 on rough / eq. 49 on smooth ground) from a perturbed steady circle at every point of
a grid and keeps a few summaries per trajectory (no per-step storage), next to the
closed-form ``varpi^2`` (eq. 45 corrected / 55) and its sign.

Rules (stated once, used everywhere):

* Perturbation: ``theta(0) = theta0 + tilt``, ``omega1(0) = kick``; omega2, omega3 keep
  their steady values.  The *initial amplitude* is ``a0 = |tilt| + |kick|`` (kick in
  rad per unit time sqrt(a/g); for a linear oscillation of frequency varpi the amplitude is
  ``sqrt(tilt^2 + kick^2/varpi^2)``, at most ``a0 * max(1, 1/varpi)``).
* ``stable_simulated``: the run completed (no guard fired: lift-off F_z <= 0 eq. 11, edge
  contact theta crossing 0, falling flat |theta| >= pi/2) and
  ``max|theta - theta0| <= BOUND_FACTOR * a0`` with ``BOUND_FACTOR = 20``.
* ``frequency``: ``2 pi / period``, the period being the least-squares slope of the times
  of the upward crossings of ``theta - theta0`` against their index; NaN with fewer than 2
  crossings.  The crossings are located on the step polynomial (``method="taylor"``, the
  default) or by cubic Hermite interpolation with omega1 as derivative (``"dop853"``).
* ``growth_rate``: ``ln(GROW_HI / GROW_LO) / (t_hi - t_lo)`` with ``t_lo`` (``t_hi``) the
  time at which ``|theta - theta0|`` first exceeds ``GROW_LO * a0`` (``GROW_HI * a0``),
  ``GROW_LO = 2``, ``GROW_HI = 10``: the log-slope of the envelope in the linear window;
  NaN when the departure never reaches ``GROW_HI * a0``.  ``taylor`` samples every step
  at its middle and end, ``dop853`` at its end, and both locate the time inside.
* Guards: ``taylor`` locates a guard inside the step where it fires (``t_end`` is the
  event time); ``dop853`` stops at the end of that step.
* ``energy_drift``: ``max_t |E(t) - E(0)| / |E(0)|`` over accepted steps, E of the reduced
  state (eq. 13 with eqs. 37 and 7 on rough ground; on smooth ground the part without the
  constant horizontal velocity of C).
* ``status``: the outcome's code (:mod:`rollingdisk.model.outcomes`), ``no-steady-motion``
  where the grid point has no steady motion (nothing integrated).

The results are the same bit for bit whichever executor computes them (each trajectory's
computation depends on its own inputs only).  Results are stored chunk by chunk in
``OUT.partial/`` (locked: one writer at a time) and the final Zarr store (or NetCDF file)
appears under its name only once complete; a run interrupted for any reason resumes from
the finished chunks.  The parts: :mod:`~rollingdisk.sweep.grid` (grids, perturbations,
set-up), :mod:`~rollingdisk.sweep.executors`, :mod:`~rollingdisk.sweep.store` (partial
folder, lock, dataset), :mod:`~rollingdisk.sweep.options` (the one validator) and
:mod:`~rollingdisk.sweep.basin` (finite-amplitude stability); this module runs a sweep
and re-exports the public names.
"""

from __future__ import annotations

import time

import numpy as np

from rollingdisk.sweep.basin import basin_sweep
from rollingdisk.sweep.executors import open_executor
from rollingdisk.sweep.grid import (
    BOUND_FACTOR,
    GROW_HI,
    GROW_LO,
    Perturbation,
    SweepGrid,
    _Spec,
)
from rollingdisk.sweep.options import check_perturbation, check_run_options
from rollingdisk.sweep.store import build_dataset, open_sweep, partial_store, save

__all__ = ["SweepGrid", "Perturbation", "run_sweep", "basin_sweep", "open_sweep",
           "BOUND_FACTOR", "GROW_LO", "GROW_HI"]


def run_sweep(grid: SweepGrid, t_end: float, *, perturbation: Perturbation | None = None,
              out=None, executor: str = "serial", workers: int | None = None,
              dask_address: str | None = None, chunk: int = 2048, rtol: float = 1e-9,
              atol: float = 1e-9, max_steps: int = 1_000_000, method: str = "taylor",
              progress=None):
    """Integrate a perturbed steady motion from every grid point; an ``xarray.Dataset``.

    Parameters
    ----------
    grid : SweepGrid
    t_end : float
        Duration of each run (units sqrt(a/g)), in (0, 1e9].
    perturbation : Perturbation, optional
        Default: kick 1e-3 in omega1.
    out : path, optional
        ``*.zarr`` or ``*.nc``.  Finished chunks are kept in ``out + ".partial"``; the store
        appears only once complete.  A rerun with the same arguments resumes; a run while
        another process writes the same ``out`` is refused (``ParameterError``).
    executor : {"serial", "threads", "dask"}
        ``serial``: one thread; ``threads``: numba threads over ``workers`` (default all)
        cores; ``dask``: ``dask.distributed`` tasks of ``chunk`` trajectories on a
        LocalCluster with ``workers`` processes, or on the scheduler ``dask_address``
        (refused if it does not answer within 5 s).
    rtol, atol : float
        Tolerances, in [1e-15, 1] and [1e-300, 1] (for ``taylor`` the order is
        ``ceil(-ln min(rtol, atol) / 2) + 1``).
    max_steps : int
        Step budget per trajectory, in [1, 1e12]; a trajectory that exhausts it has status
        "failed".
    method : {"taylor", "dop853"}
        ``taylor`` (default): the batch Taylor kernel (:mod:`rollingdisk.engine.taylor`;
        guards, crossings and thresholds located on the step polynomials, 2.0-2.1 times the
        trajectories per second of ``dop853``, docs/sweeps.md); ``dop853``: the batch
        DOP853 kernel (guards checked at step ends).
    progress : callable, optional
        ``progress(done, total, rate, eta)`` after each chunk: trajectories done (resumed
        ones included), in all, computed per second by this call, seconds left.  An
        exception it raises interrupts the sweep (finished chunks are kept).

    Returns
    -------
    xarray.Dataset
        Dims ``(h, theta0, omega30|r_C|Omega0, amplitude)``, ``(h, omega0, amplitude)``
        for straight lines, or ``(point, amplitude)``; variables varpi2, stable (closed
        form, -1 where no steady motion), status, t_end, max_dtheta, frequency,
        growth_rate, energy_drift, stable_simulated, ... (module docstring for the rules),
        each with CF ``long_name`` and ``units`` (flags for the integer ones); attribute
        ``n_computed``: the trajectories this call integrated (the rest were resumed).
    """
    opts = check_run_options(grid, t_end, out=out, executor=executor, workers=workers,
                             dask_address=dask_address, chunk=chunk, rtol=rtol, atol=atol,
                             max_steps=max_steps, method=method, progress=progress)
    perturbation = check_perturbation(perturbation)
    n = int(np.prod(grid.shape)) * len(perturbation.kick)
    spec = _Spec(grid, perturbation, opts.t_end, opts.rtol, opts.atol, opts.max_steps,
                 opts.chunk, n, opts.method)
    if opts.out is None:
        results: dict = {}
        with open_executor(opts.executor, opts.workers, opts.dask_address) as run:
            computed = _run_chunks(run, spec, [], results.__setitem__, progress)
        parts = [results[k] for k in sorted(results)]
        return build_dataset(spec, _concat(parts), opts.executor, computed)
    with partial_store(opts.out, spec.to_json(), "spec.json") as store:
        with open_executor(opts.executor, opts.workers, opts.dask_address) as run:
            computed = _run_chunks(run, spec, store.done("chunk"),
                                   lambda k, res: store.write("chunk", k, res), progress)
        parts = [store.load("chunk", k) for k in range(-(-n // opts.chunk))]
        ds = build_dataset(spec, _concat(parts), opts.executor, computed)
        save(ds, opts.out)
    return ds


def _concat(parts: list) -> dict:
    return {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}


def _run_chunks(run, spec: _Spec, done: list, keep, progress) -> int:
    """Compute the chunks of ``spec`` not in ``done`` with ``run``, handing each to
    ``keep(k, summaries)``; report to ``progress``.  Returns the trajectories computed."""
    n, chunk = spec.n, spec.chunk
    size = [min(n, (k + 1) * chunk) - k * chunk for k in range(-(-n // chunk))]
    todo = [k for k in range(len(size)) if k not in set(done)]
    count = {"done": sum(size[k] for k in done), "computed": 0}
    t0 = time.perf_counter()

    def finished(k, res):
        keep(k, res)
        count["done"] += size[k]
        count["computed"] += size[k]  # the rate counts what this call computed, only
        if progress is not None:
            dt = time.perf_counter() - t0
            rate = count["computed"] / dt if dt > 0 else float("nan")
            left = n - count["done"]
            progress(count["done"], n, rate, left / rate if rate > 0 else float("nan"))

    run(spec, todo, finished)
    return count["computed"]
