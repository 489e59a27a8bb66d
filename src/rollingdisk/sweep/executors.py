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

from rollingdisk.model.geometry import inertia
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


def _kernel_args(spec: _Spec, setup, a0=None):
    """``(ok, args)`` from ``setup = _setup(spec, i0, i1)``: which points have a steady
    motion, and for those the arguments of the batch kernels
    (:mod:`rollingdisk.sweep.batch`, before the order): ``(rough, h, k1, k2, x0,
    theta_ref, a0, GROW_LO, GROW_HI, t_end, rtol, atol, max_steps)``, k1 and k2 by eq. (10),
    a0 (``setup``'s unless given) = 1 where it is not finite."""
    x0, h, theta_ref, _, _, a0_ = setup
    a0 = a0_ if a0 is None else a0
    ok = np.all(np.isfinite(x0), axis=1)
    h = h[ok]
    k1 = inertia(h)[0]  # eq. (10)
    a0o = np.where(np.isfinite(a0[ok]), a0[ok], 1.0)
    return ok, (spec.grid.ground == "rough", h, k1, np.full(k1.shape, 0.5),
                np.ascontiguousarray(x0[ok]), theta_ref[ok], a0o, GROW_LO, GROW_HI,
                spec.t_end, spec.rtol, spec.atol, spec.max_steps)


def kernel_args(spec: _Spec, i0: int = 0, i1: int | None = None):
    """``(ok, args)`` of :func:`_kernel_args` for the points i0 ... i1 - 1 of ``spec`` (all
    by default): benchmarks and tests call the batch kernels with exactly what a sweep
    passes them."""
    return _kernel_args(spec, _setup(spec, i0, spec.n if i1 is None else i1))


def _kernel(method, args):
    """Summaries (n, NCOL) of the trajectories of :func:`_kernel_args` by ``method``: the
    batch Taylor kernel (order from min(rtol, atol),
    :func:`rollingdisk.engine.taylor.taylor_order`; in vector lanes up to
    :data:`rollingdisk.engine.lanes.MAX_ORDER`, tolerance 1e-17) or the batch DOP853
    kernel of :mod:`rollingdisk.sweep.batch`."""
    from rollingdisk.engine.lanes import MAX_ORDER
    from rollingdisk.engine.taylor import taylor_order
    from rollingdisk.sweep import batch as core

    if method == "taylor":
        rtol, atol = args[10], args[11]
        P = taylor_order(min(rtol, atol))
        if P <= MAX_ORDER:
            return core.run_batch_lanes(*args, P)
        return core.run_batch_taylor(*args, P)
    return core.run_batch(*args)


def _compute_chunk(spec: _Spec, k: int, n_threads: int | None = None) -> dict:
    """Summaries of chunk k (a dict of 1-d arrays); deterministic."""
    from rollingdisk.sweep import batch as core

    if n_threads is not None:
        core.set_threads(n_threads)
    i0 = k * spec.chunk
    i1 = min(spec.n, i0 + spec.chunk)
    setup = _setup(spec, i0, i1)
    x0, h, theta_ref, varpi2, stable, a0 = setup
    ok, args = _kernel_args(spec, setup)
    out = np.full((i1 - i0, core.NCOL), np.nan)
    if ok.any():
        out[ok] = _kernel(spec.method, args)
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
        from rollingdisk.sweep import batch as core

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
