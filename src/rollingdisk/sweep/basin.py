"""Finite-amplitude stability: per steady motion the largest kick that stays bounded,
found by bisection, one batch over the whole grid per round (resumable by rounds)."""

from __future__ import annotations

import json
import time
from dataclasses import asdict

import numpy as np

from rollingdisk.sweep.executors import _kernel, _kernel_args
from rollingdisk.sweep.grid import BOUND_FACTOR, Perturbation, SweepGrid, _setup, _Spec
from rollingdisk.sweep.options import check_run_options
from rollingdisk.sweep.store import describe, partial_store, save
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["basin_sweep"]


def basin_sweep(grid: SweepGrid, t_end: float, *, kick_max: float = 1.0, rounds: int = 10,
                out=None, executor: str = "serial", workers: int | None = None,
                chunk: int = 2048, rtol: float = 1e-9, atol: float = 1e-9,
                max_steps: int = 1_000_000, method: str = "taylor", progress=None):
    """Finite-amplitude stability: per steady motion the largest kick in omega1 (bisection
    over ``[0, kick_max]``, ``rounds`` rounds, each round one batch over the whole grid)
    that still gives bounded motion (``stable_simulated``) over ``t_end``.

    Parameters
    ----------
    grid : SweepGrid
        A grid of steady motions (not ``states``).
    t_end : float
        Duration of each run (units sqrt(a/g)), in (0, 1e9].
    kick_max : float
        The largest kick tried (rad per sqrt(a/g)), in (0, 100].
    rounds : int
        Bisection rounds after the first trial of ``kick_max``, in [1, 60].
    out, workers, chunk, rtol, atol, max_steps, method, progress
        As in :func:`rollingdisk.sweep.run_sweep` (each finished round is kept in
        ``out + ".partial"``; a rerun resumes after the last one).  ``progress`` gets
        ``(rounds done, rounds in all, trajectories computed per second, seconds left)``.
    executor : {"serial", "threads"}
        Each round is one batch on numba threads; ``"dask"`` is refused.

    Returns
    -------
    xarray.Dataset
        ``kick_basin`` (lower end of the final bracket; 0 where even the first trial
        failed, ``kick_max`` where it never failed, NaN where there is no steady motion)
        and the closed-form ``varpi2``, ``stable``, with CF attributes; attribute
        ``n_computed``: the trajectories this call integrated.
    """
    if isinstance(executor, str) and executor == "dask":
        raise ParameterError("executor: basin_sweep runs its rounds on 'serial' or "
                             "'threads'; 'dask' is not supported (use run_sweep for Dask)")
    opts = check_run_options(grid, t_end, out=out, executor=executor, workers=workers,
                             chunk=chunk, rtol=rtol, atol=atol, max_steps=max_steps,
                             method=method, progress=progress,
                             executors=("serial", "threads"))
    kick_max = check_real("kick_max", kick_max, low=0.0, low_open=True, high=100.0)
    rounds = check_int("rounds", rounds, low=1, high=60)
    if grid.states is not None:
        raise ParameterError("grid: basin_sweep needs a grid of steady motions, not states")
    state = _Bisection(grid, opts, kick_max, rounds, progress)
    if opts.out is None:
        state.run(None)
        return state.dataset()
    key = json.dumps({"grid": asdict(grid), "t_end": opts.t_end, "kick_max": kick_max,
                      "rtol": opts.rtol, "atol": opts.atol, "max_steps": opts.max_steps,
                      "method": opts.method}, sort_keys=True, allow_nan=False)
    with partial_store(opts.out, key, "basin.json") as store:
        state.run(store)
        res = state.dataset()
        save(res, opts.out)
    return res


class _Bisection:
    """The brackets ``[lo, hi]`` of every grid point and the next trial kick."""

    def __init__(self, grid, opts, kick_max, rounds, progress):
        self.grid, self.opts, self.kick_max, self.rounds = grid, opts, kick_max, rounds
        self.progress = progress
        self.lo = np.zeros(grid.shape)
        self.hi = np.full(grid.shape, kick_max)
        self.trial = self.hi.copy()  # round 0 tests kick_max itself; then bisection
        self.first = None
        self.computed = 0

    def run(self, store) -> None:
        start = 0
        done = store.done("round") if store is not None else []
        if done:
            z = store.load("round", done[-1])
            self.lo, self.hi, self.trial = z["lo"], z["hi"], z["trial"]
            self.first = {"stable": z["stable"], "varpi2": z["varpi2"]}
            start = done[-1] + 1
        t0 = time.perf_counter()
        for r in range(start, self.rounds + 1):
            self.step()
            if store is not None:
                store.write("round", r, dict(lo=self.lo, hi=self.hi, trial=self.trial,
                                             **self.first))
            if self.progress is not None:
                dt = time.perf_counter() - t0
                rate = self.computed / dt if dt > 0 else float("nan")
                left = (self.rounds - r) * self.lo.size
                self.progress(r + 1, self.rounds + 1, rate,
                              left / rate if rate > 0 else float("nan"))

    def step(self) -> None:
        """One round: every point with its own trial kick; the brackets narrowed."""
        ok, stable, varpi2, n_run = _basin_round(self.grid, self.trial, self.opts)
        self.computed += n_run
        ok = ok.reshape(self.grid.shape)
        if self.first is None:
            self.first = {"stable": stable.reshape(self.grid.shape),
                          "varpi2": varpi2.reshape(self.grid.shape)}
            self.lo = np.where(ok, self.kick_max, 0.0)
            self.hi = np.full(self.grid.shape, self.kick_max)
        else:
            self.lo = np.where(ok, self.trial, self.lo)
            self.hi = np.where(ok, self.hi, self.trial)
        self.trial = 0.5 * (self.lo + self.hi)

    def dataset(self):
        from rollingdisk.results.xrload import xr

        st = self.first["stable"]
        dims = self.grid.dims
        res = xr.Dataset(
            {"kick_basin": (dims, np.where(st >= 0, self.lo, np.nan)),
             "varpi2": (dims, self.first["varpi2"]), "stable": (dims, st)},
            coords=self.grid.coords())
        o = self.opts
        res.attrs.update({"ground": self.grid.ground, "t_end": o.t_end,
                          "kick_max": self.kick_max, "rounds": self.rounds, "rtol": o.rtol,
                          "atol": o.atol, "method": o.method, "n_computed": self.computed,
                          "time_unit": "sqrt(a/g) (a: radius, g: gravity)",
                          "rule": f"bounded: completed and max_dtheta <= {BOUND_FACTOR} * kick"})
        return describe(res)


def _basin_round(grid, kicks, opts):
    """One batch: the steady state of every grid point with its own kick; ``(bounded,
    stable, varpi2)`` flat and the number of trajectories integrated."""
    from rollingdisk.sweep import batch as core

    spec = _Spec(grid, Perturbation(kick=1.0), opts.t_end, opts.rtol, opts.atol,
                 opts.max_steps, opts.chunk, int(np.prod(grid.shape)), opts.method)
    setup = _setup(spec, 0, spec.n)
    x0, h, theta_ref, varpi2, stable, _ = setup
    k = np.ravel(kicks)
    x0[:, 1] = k
    ok, args = _kernel_args(spec, setup, a0=k)
    with core.threads(1 if opts.executor == "serial" else opts.workers):
        out = np.full((spec.n, core.NCOL), np.nan)
        if ok.any():
            out[ok] = _kernel(opts.method, args)
    bounded = (out[:, 0] == core.COMPLETED) & (out[:, 2] <= BOUND_FACTOR * k)
    return np.where(ok, bounded, False), stable, varpi2, int(ok.sum())
