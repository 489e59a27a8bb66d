"""Compiled batch integrators for :mod:`rollingdisk.sweep.runner` (numba; imported lazily).

Integrate many trajectories of the reduced system ``x = (theta, omega1, omega2, omega3)``
(eq. 2 with eq. 38 on rough / eq. 49 on smooth ground) in one call, a ``numba.prange`` loop
over trajectories, by one of two methods:

* :func:`run_batch_lanes` (the default of the sweeps, orders up to
  :data:`rollingdisk.engine.lanes.MAX_ORDER`) and :func:`run_batch_taylor` (one
  trajectory at a time, any order): the Taylor method, in vector lanes or scalar, of
  :mod:`rollingdisk.sweep.batch_taylor`; summaries and guards sampled on the step
  polynomial and located on it.
* :func:`run_batch`: DOP853 with the building blocks of :mod:`rollingdisk.engine.numba_core`
  (``error_norm``'s rule, ``initial_step``, ``guards``; the step-size control of scipy's
  DOP853); guards checked at step ends.

No step is stored: each trajectory keeps running summaries only.  Each trajectory's
computation depends on its own inputs alone (no reduction across trajectories, no
thread-dependent state), so the results are bitwise the same whichever thread, chunk or
process computes it.
"""

from __future__ import annotations

import contextlib

import numba
import numpy as np

from rollingdisk.engine.lanes import LANES, MAX_ORDER
from rollingdisk.engine.numba_core import (
    NS,
    A,
    B,
    error_norm,
    guards,
    initial_step,
    reduced_rhs,
    rhs,
    step_factor,
)
from rollingdisk.model.outcomes import (
    COMPLETED,
    EDGE_CONTACT,
    FAILED,
    FELL_FLAT,
    LIFT_OFF,
    outcome,
)
from rollingdisk.sweep.batch_common import (
    COLUMNS,
    NCOL,
    _add_crossing,
    _jit,
    _reduced_energy,
    _spread,
    _summaries,
)
from rollingdisk.sweep.batch_taylor import _lanes, _one_taylor

__all__ = ["COLUMNS", "NCOL", "STATUS_NAMES", "run_batch", "run_batch_lanes",
           "run_batch_taylor", "set_threads", "threads"]


def set_threads(n: int) -> int:
    """Run the batch kernels on ``n`` numba threads (clipped to ``[1, NUMBA_NUM_THREADS]``);
    return the number set."""
    numba.set_num_threads(max(1, min(int(n), numba.config.NUMBA_NUM_THREADS)))
    return numba.get_num_threads()


@contextlib.contextmanager
def threads(n: int | None = None):
    """The batch kernels in the block run on ``n`` numba threads (as they are for ``None``);
    the previous number is restored after.  Yields the number in force."""
    old = numba.get_num_threads()
    try:
        yield old if n is None else set_threads(n)
    finally:
        numba.set_num_threads(old)


#: Status code -> name of the outcomes a batch kernel can end with (rollingdisk.model.outcomes).
STATUS_NAMES = {c: outcome(c).name for c in (COMPLETED, LIFT_OFF, EDGE_CONTACT, FELL_FLAT, FAILED)}


@_jit()
def _step4(rough, h, y, dt, K, ytmp, y_new):
    """One DOP853 step of the reduced system (4 components), stages in the columns of
    ``K`` (shape (4, 13); column 0 holds f(y) on entry, column 12 f(y_new) on exit).

    The arithmetic of :func:`rollingdisk.engine.dop853._step` (same coefficients, same order of
    the sums, so the same numbers), laid out for the batch: the stages of one component
    are contiguous and the right-hand side is the compiled kernel ``reduced_rhs`` returning
    a tuple, which makes a step cheaper than the general 4-to-10-component step
    (benchmarks/sweep.py, docs/performance.md)."""
    for s in range(1, NS):
        for i in range(4):
            acc = 0.0
            for j in range(s):
                acc += A[s, j] * K[i, j]
            ytmp[i] = y[i] + dt * acc
        r = reduced_rhs(rough, h, ytmp)
        K[0, s] = r[0]
        K[1, s] = r[1]
        K[2, s] = r[2]
        K[3, s] = r[3]
    for i in range(4):
        acc = 0.0
        for j in range(NS):
            acc += B[j] * K[i, j]
        y_new[i] = y[i] + dt * acc
    r = reduced_rhs(rough, h, y_new)
    K[0, NS] = r[0]
    K[1, NS] = r[1]
    K[2, NS] = r[2]
    K[3, NS] = r[3]


@_jit()
def _hermite_root(dt, d0, v0, d1, v1):
    """Root in [0, dt] of the cubic Hermite interpolant of d with d(0) = d0 < 0 <= d(dt) = d1
    and slopes v0, v1 (bisection on the bracket then Newton polish)."""
    a, b = 0.0, 1.0
    for _ in range(60):
        m = 0.5 * (a + b)
        s = m
        h00 = (1 + 2 * s) * (1 - s) ** 2
        h10 = s * (1 - s) ** 2
        h01 = s * s * (3 - 2 * s)
        h11 = s * s * (s - 1)
        val = h00 * d0 + h10 * dt * v0 + h01 * d1 + h11 * dt * v1
        if val < 0.0:
            a = m
        else:
            b = m
        if b - a < 1e-14:
            break
    return 0.5 * (a + b) * dt


# Why one long function (issue 17: compiled kernels are exempt from the ~80-line rule): one
# trajectory of a sweep, compiled by numba (nopython, called from a prange loop over
# millions of points).  Nopython allows no closures and no objects carrying the running
# summaries, so the step loop and the summaries it updates at every step (the largest
# departure, the theta crossings for the frequency, the growth window, the energy drift)
# stay local scalars of one frame: split into functions they would be passed in and
# returned as tuples at every step of every point.  The step itself (_step4), the crossing
# interpolation (_hermite_root, _add_crossing) and the final record (_summaries) are
# already separate.
@_jit()
def _one(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atol,
         max_steps, out):
    n = 4
    K = np.empty((n, NS + 1))
    ytmp = np.empty(n)
    y = x0.copy()
    f = np.empty(n)
    y_new = np.empty(n)
    g = np.empty(3)
    E0 = _reduced_energy(rough, h, k1, k2, y)
    t = 0.0
    max_d = abs(y[0] - theta_ref)
    t_lo = np.nan
    t_hi = np.nan
    cr = np.zeros(5)  # least squares of crossing times t_k against k (_add_crossing)
    e_drift = 0.0
    status = 0
    n_steps = 0
    guards(rough, h, y, g)
    sign1 = 1.0 if g[1] > 0.0 else -1.0
    if g[0] <= 0.0:
        status = LIFT_OFF
    elif g[2] <= 0.0:
        status = FELL_FLAT
    rhs(rough, h, y, f)
    for i in range(n):
        K[i, 0] = f[i]
    dt_abs = initial_step(rough, h, 0.0, y, f, t_end, np.inf, rtol, atol)
    while status == 0:
        if t >= t_end:
            status = COMPLETED
            break
        if n_steps >= max_steps:
            status = FAILED
            break
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        if dt_abs < min_step:
            dt_abs = min_step
        accepted = False
        rejected = False
        while not accepted:
            if dt_abs < min_step:
                break
            dt = dt_abs
            if t + dt > t_end:
                dt = t_end - t
            _step4(rough, h, y, dt, K, ytmp, y_new)
            err = error_norm(y, y_new, K, dt, rtol, atol)
            dt_abs = dt * step_factor(err, rejected)
            if err < 1.0:
                accepted = True
            else:
                rejected = True
        if not accepted:
            status = FAILED
            break
        n_steps += 1
        # summaries on the accepted step (t, y) -> (t + dt, y_new)
        d0 = y[0] - theta_ref
        d1 = y_new[0] - theta_ref
        if d0 < 0.0 <= d1:
            _add_crossing(cr, t + _hermite_root(dt, d0, y[1], d1, y_new[1]))
        ad = abs(d1)
        if ad > max_d:
            max_d = ad
        sg = 1.0 if d1 >= 0.0 else -1.0
        if np.isnan(t_lo) and ad > grow_lo * a0:
            lev = grow_lo * a0  # |d| <= lev at t (first step beyond): crossing in the step
            t_lo = t + _hermite_root(dt, sg * d0 - lev, sg * y[1], ad - lev, sg * y_new[1])
        if np.isnan(t_hi) and ad > grow_hi * a0:
            lev = grow_hi * a0
            t_hi = t + _hermite_root(dt, sg * d0 - lev, sg * y[1], ad - lev, sg * y_new[1])
        E = _reduced_energy(rough, h, k1, k2, y_new)
        de = abs(E - E0) / max(abs(E0), 1e-300)
        if de > e_drift:
            e_drift = de
        t = t + dt
        for i in range(n):
            y[i] = y_new[i]
            K[i, 0] = K[i, NS]
        guards(rough, h, y, g)
        if g[0] <= 0.0:
            status = LIFT_OFF
        elif (g[1] > 0.0) != (sign1 > 0.0) or g[1] == 0.0:
            if h > 0.0:
                status = EDGE_CONTACT
        elif g[2] <= 0.0:
            status = FELL_FLAT
    _summaries(out, status, t, max_d, cr, t_lo, t_hi, e_drift, n_steps)


@_jit(parallel=True)
def run_batch(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atol,
              max_steps):
    """Integrate every row of ``x0`` (shape (n, 4)) to ``t_end``; summaries (n, NCOL).

    ``h, k1, k2, theta_ref, a0`` are arrays of length n (per-trajectory disk, reference
    tilt and initial amplitude).  Guards end a trajectory at the end of the step on which
    they fire (not located: the sweep only needs which one fired and about when).
    """
    n = x0.shape[0]
    out = np.empty((n, NCOL))
    order = _spread(n)
    for k in numba.prange(n):
        i = order[k]
        _one(rough, h[i], k1[i], k2[i], x0[i], theta_ref[i], a0[i], grow_lo, grow_hi, t_end,
             rtol, atol, max_steps, out[i])
    return out


@_jit(parallel=True)
def run_batch_taylor(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atol,
                     max_steps, P):
    """:func:`run_batch` by the Taylor method of order P (:func:`_one_taylor`, one trajectory
    at a time); guards are located inside the step where they fire."""
    n = x0.shape[0]
    out = np.empty((n, NCOL))
    atolv = np.full(4, atol)
    order = _spread(n)
    for k in numba.prange(n):
        i = order[k]
        _one_taylor(rough, h[i], k1[i], k2[i], x0[i], theta_ref[i], a0[i], grow_lo, grow_hi,
                    t_end, rtol, atolv, max_steps, P, out[i])
    return out


@_jit(parallel=True)
def _run_lanes(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atol,
               max_steps, P, nb):
    n = x0.shape[0]
    out = np.empty((n, NCOL))
    order = _spread(n)
    for b in numba.prange(nb):
        _lanes(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atol,
               max_steps, numba.literally(P), order, b * n // nb, (b + 1) * n // nb, out)
    return out


def run_batch_lanes(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atol,
                    max_steps, P):
    """:func:`run_batch_taylor` in vector lanes (:func:`_lanes`),
    :data:`rollingdisk.engine.lanes.LANES` trajectories per instruction; the same
    verdicts, summaries within round-off (the lanes' sin, cos, log and exp are fdlibm's
    polynomials, not libm's calls).  The order ``P`` (at most
    :data:`rollingdisk.engine.lanes.MAX_ORDER`) is compiled in: each order compiles
    once.  Blocks of the spread order (:func:`_spread`) are shared among the threads,
    four per thread (one on one thread: the lanes are refilled from it until it runs
    dry)."""
    if not 4 <= P <= MAX_ORDER:
        raise ValueError(f"P = {P}: the lanes are compiled for orders 4..{MAX_ORDER}")
    n = x0.shape[0]
    nt = numba.get_num_threads()
    nb = 1 if nt == 1 else max(1, min(4 * nt, n // (16 * LANES)))
    return _run_lanes(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol,
                      atol, max_steps, int(P), nb)
