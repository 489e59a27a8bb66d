"""Where a sweep's chunks are computed: one thread, numba threads, or Dask workers.

Each chunk's summaries depend on its own inputs only (:func:`_compute_chunk`), so every
executor gives the same numbers bit for bit.  :func:`open_executor` connects to the
executor before any chunk is computed: an unreachable Dask scheduler is refused within
``CONNECT_TIMEOUT`` seconds, as a :class:`~rollingdisk.util.errors.ParameterError` naming
its address.
"""

from __future__ import annotations

import contextlib
import math
import os
from collections.abc import Callable, Iterator

import numpy as np

from rollingdisk.model.geometry import _inertia
from rollingdisk.model.outcomes import outcome
from rollingdisk.sweep.grid import BOUND_FACTOR, GROW_HI, GROW_LO, _setup, _Spec
from rollingdisk.util.errors import ParameterError

__all__ = ["EXECUTORS", "METHODS", "CONNECT_TIMEOUT", "open_executor"]

#: The executors of :func:`rollingdisk.sweep.run_sweep`.
EXECUTORS = ("serial", "threads", "dask")
#: The integrators of the batch kernels.
METHODS = ("taylor", "dop853")
#: Seconds to wait for a Dask scheduler to answer before refusing its address.
CONNECT_TIMEOUT = 5.0
#: The status of a grid point without a steady motion (nothing is integrated there).
NO_STEADY_MOTION = outcome("no-steady-motion").code


def _kernel(method, rough, h, x0, theta_ref, a0, t_end, rtol, atol, max_steps):
    """Summaries (n, NCOL) of the trajectories from the rows of ``x0`` by ``method``: the
    batch Taylor kernel (order from min(rtol, atol),
    :func:`rollingdisk.integrate.taylor.taylor_order`; in vector lanes up to
    :data:`rollingdisk.integrate.lanes.MAX_ORDER`, tolerance 1e-17) or the batch DOP853
    kernel of :mod:`rollingdisk.integrate.batch`."""
    from rollingdisk.integrate import batch as core
    from rollingdisk.integrate.lanes import MAX_ORDER
    from rollingdisk.integrate.taylor import taylor_order

    k1 = _inertia(h)[0]  # eq. (10)
    k2 = np.full(k1.shape, 0.5)
    args = (rough, h, k1, k2, np.ascontiguousarray(x0), theta_ref, a0, GROW_LO, GROW_HI,
            t_end, rtol, atol, max_steps)
    if method == "taylor":
        P = taylor_order(min(rtol, atol))
        if P <= MAX_ORDER:
            return core.run_batch_lanes(*args, P)
        return core.run_batch_taylor(*args, P)
    return core.run_batch(*args)


def _compute_chunk(spec: _Spec, k: int, n_threads: int | None = None) -> dict:
    """Summaries of chunk k (a dict of 1-d arrays); deterministic."""
    from rollingdisk.integrate import batch as core

    if n_threads is not None:
        core.set_threads(n_threads)
    i0 = k * spec.chunk
    i1 = min(spec.n, i0 + spec.chunk)
    x0, h, theta_ref, varpi2, stable, a0 = _setup(spec, i0, i1)
    ok = np.all(np.isfinite(x0), axis=1)
    out = np.full((i1 - i0, core.NCOL), np.nan)
    if ok.any():
        a0o = np.where(np.isfinite(a0[ok]), a0[ok], 1.0)
        out[ok] = _kernel(spec.method, spec.grid.ground == "rough", h[ok], x0[ok],
                          theta_ref[ok], a0o, spec.t_end, spec.rtol, spec.atol, spec.max_steps)
    cols = dict(zip(core.COLUMNS, out.T))
    status = np.where(ok, cols["status"], NO_STEADY_MOTION).astype(np.int8)
    period = cols["period"]
    with np.errstate(all="ignore"):
        freq = 2 * np.pi / period
        growth = math.log(GROW_HI / GROW_LO) / (cols["t_grow_hi"] - cols["t_grow_lo"])
        bounded = (status == core.COMPLETED) & (cols["max_dtheta"] <= BOUND_FACTOR * a0)
    stable_sim = np.where(ok, bounded.astype(np.int8), -1).astype(np.int8)
    return {"varpi2": varpi2, "stable": stable, "status": status, "t_end": cols["t_end"],
            "max_dtheta": cols["max_dtheta"], "frequency": freq, "growth_rate": growth,
            "energy_drift": cols["energy_drift"], "n_crossings": cols["n_crossings"],
            "n_steps": cols["n_steps"], "stable_simulated": stable_sim, "amplitude0": a0}


#: ``run(spec, todo, finished)``: compute the chunks ``todo`` of ``spec`` and call
#: ``finished(k, summaries)`` for each as it ends (in any order).
Runner = Callable[[_Spec, list, Callable[[int, dict], None]], None]


@contextlib.contextmanager
def open_executor(kind: str, workers: int | None = None,
                  address: str | None = None) -> Iterator[Runner]:
    """Start (or connect to) the executor ``kind`` and yield its :data:`Runner`.

    ``serial``: one numba thread; ``threads``: ``workers`` numba threads (default all);
    ``dask``: a LocalCluster of ``workers`` single-threaded processes, or the scheduler at
    ``address`` (refused with :class:`ParameterError` if it does not answer within
    :data:`CONNECT_TIMEOUT` seconds).
    """
    if kind != "dask":
        yield _thread_runner(1 if kind == "serial" else workers)
        return
    client, cluster = _dask_client(workers, address)
    try:
        yield _dask_runner(client)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _thread_runner(n_threads: int | None) -> Runner:
    def run(spec, todo, finished):
        from rollingdisk.integrate import batch as core

        with core.threads() as all_threads:
            for k in todo:
                finished(k, _compute_chunk(spec, k, n_threads or all_threads))
    return run


def _dask_client(workers, address):
    """A ``dask.distributed`` client (and the LocalCluster it owns, or None)."""
    from dask.distributed import Client, LocalCluster

    if address in (None, "local"):
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                               processes=True, dashboard_address=None)
        return Client(cluster), cluster
    try:
        return Client(address, timeout=CONNECT_TIMEOUT), None
    except (OSError, TimeoutError, ValueError) as exc:  # refused, unreachable, malformed
        raise ParameterError(
            f"dask_address: no Dask scheduler answers at {address!r} within "
            f"{CONNECT_TIMEOUT:g} s ({type(exc).__name__}); start one there, or use "
            "executor 'threads'") from None


def _dask_runner(client) -> Runner:
    def run(spec, todo, finished):
        from dask.distributed import as_completed

        futs = {client.submit(_compute_chunk, spec, k, 1, pure=False): k for k in todo}
        for fut in as_completed(futs):
            finished(futs[fut], fut.result())
    return run
