"""Compiled batch integrators for :mod:`rollingdisk.sweep.runner` (numba; imported lazily).

Integrate many trajectories of the reduced system ``x = (theta, omega1, omega2, omega3)``
(eq. 2 with eq. 38 on rough / eq. 49 on smooth ground) in one call, a ``numba.prange`` loop
over trajectories, by one of two methods:

* :func:`run_batch_lanes` (the default of the sweeps, orders up to
  :data:`rollingdisk.engine.lanes.MAX_ORDER`) and :func:`run_batch_taylor` (one
  trajectory at a time, any order): the Taylor method of
  :mod:`rollingdisk.engine.taylor` on the reduced jets ``_tay_jet4_rough``/``_smooth``,
  in vector lanes (:mod:`rollingdisk.engine.lanes`, eight trajectories per
  instruction) or scalar; summaries and guards sampled on the step polynomial and located
  on it, by the same per-step code (:func:`_tay_plain` for the common step, traced into
  the lanes; :func:`_tay_advance` for the others).
* :func:`run_batch`: DOP853 with the building blocks of :mod:`rollingdisk.engine.numba_core`
  (``_error_norm``'s rule, ``initial_step``, ``_guards``; the step-size control of scipy's
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

from rollingdisk.engine.lanes import (
    LANES,
    MAX_ORDER,
    _lane_jet_rough,
    _lane_jet_smooth,
    _lane_plain,
    _lane_samples,
)
from rollingdisk.engine.numba_core import (
    _A,
    _B,
    _KEY,
    _NS,
    _energy_sc,
    _error_norm,
    _geometry,
    _guards,
    _reduced_rhs,
    _rhs,
    _step_factor,
    _tay_jet4_rough,
    _tay_jet4_smooth,
    _tay_normal,
    _tay_poly_root,
    _tay_sample,
    _tay_step_size,
    _where,
    initial_step,
)
from rollingdisk.model.outcomes import (
    COMPLETED,
    EDGE_CONTACT,
    FAILED,
    FELL_FLAT,
    LIFT_OFF,
    outcome,
)


def _jit(**kw):
    """``numba.njit(cache=True, **kw)`` under a name that carries the hash of the sources the
    function may call (:func:`rollingdisk.engine.compile.source_key`): numba's cache is
    keyed by this file alone, and a kernel cached before an edit of taylor.py or lanes.py
    (which it inlines or traces) would otherwise be loaded stale."""

    def deco(f):
        f.__qualname__ = f"{f.__qualname__}_{_KEY}"
        return numba.njit(cache=True, **kw)(f)

    return deco


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

# summary columns returned by run_batch (float64 array of shape (n, NCOL))
COLUMNS = ("status", "t_end", "max_dtheta", "n_crossings", "period", "t_grow_lo",
           "t_grow_hi", "energy_drift", "n_steps")
NCOL = len(COLUMNS)


@_jit()
def _reduced_energy(rough, h, k1, k2, y):
    """E of the reduced state (:func:`_energy_sc`)."""
    ht, s, c, p, y_P, z_P = _geometry(h, y[0])
    return _energy_sc(rough, ht, k1, k2, s, c, y)


@_jit()
def _step4(rough, h, y, dt, K, ytmp, y_new):
    """One DOP853 step of the reduced system (4 components), stages in the columns of
    ``K`` (shape (4, 13); column 0 holds f(y) on entry, column 12 f(y_new) on exit).

    The arithmetic of :func:`rollingdisk.engine.dop853._step` (same coefficients, same order of
    the sums, so the same numbers), laid out for the batch: the stages of one component
    are contiguous and the right-hand side is the compiled kernel ``_reduced_rhs`` returning
    a tuple, which makes a step about 2.2 times cheaper than the general 4-to-10-component
    step (measured in benchmarks/sweep.py)."""
    for s in range(1, _NS):
        for i in range(4):
            acc = 0.0
            for j in range(s):
                acc += _A[s, j] * K[i, j]
            ytmp[i] = y[i] + dt * acc
        r = _reduced_rhs(rough, h, ytmp)
        K[0, s] = r[0]
        K[1, s] = r[1]
        K[2, s] = r[2]
        K[3, s] = r[3]
    for i in range(4):
        acc = 0.0
        for j in range(_NS):
            acc += _B[j] * K[i, j]
        y_new[i] = y[i] + dt * acc
    r = _reduced_rhs(rough, h, y_new)
    K[0, _NS] = r[0]
    K[1, _NS] = r[1]
    K[2, _NS] = r[2]
    K[3, _NS] = r[3]


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
    K = np.empty((n, _NS + 1))
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
    _guards(rough, h, y, g)
    sign1 = 1.0 if g[1] > 0.0 else -1.0
    if g[0] <= 0.0:
        status = LIFT_OFF
    elif g[2] <= 0.0:
        status = FELL_FLAT
    _rhs(rough, h, y, f)
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
            err = _error_norm(y, y_new, K, dt, rtol, atol)
            dt_abs = dt * _step_factor(err, rejected)
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
            K[i, 0] = K[i, _NS]
        _guards(rough, h, y, g)
        if g[0] <= 0.0:
            status = LIFT_OFF
        elif (g[1] > 0.0) != (sign1 > 0.0) or g[1] == 0.0:
            if h > 0.0:
                status = EDGE_CONTACT
        elif g[2] <= 0.0:
            status = FELL_FLAT
    _summaries(out, status, t, max_d, cr, t_lo, t_hi, e_drift, n_steps)


@_jit()
def _spread(n):
    """A permutation of 0..n-1 that spreads neighbours apart (the golden-ratio sequence
    ``frac(i phi)``, sorted): the threads of a ``prange`` take contiguous ranges of it, so
    each gets a fair share of every part of the grid.  In grid order one thread took the
    low tilts and the other the high ones (fewer and more steps): 2 threads gave 1.70x;
    spread, 2.0x.  Each trajectory is computed alone, so the order changes no result."""
    key = np.empty(n)
    for i in range(n):
        x = i * 0.6180339887498949
        key[i] = x - np.floor(x)
    return np.argsort(key, kind="mergesort")


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


# ------------------------------------------------------------------ the Taylor method
#: Points per step (fractions m / _SAMPLES, m = 1.._SAMPLES) at which the state and F_z are
#: evaluated on the step polynomial: summaries and guards see inside every step.  A step
#: of order P ~ 12 spans about a tenth of an oscillation (the radius of convergence of
#: sin(varpi t) over e^2), so the midpoint and the end suffice.
_SAMPLES = 2


# The running records of the trajectories of the Taylor kernels (float64, shape (_NREC,
# lanes): a field's row holds one value per lane, a vector in the lanes): the summaries as
# they stand and what a step needs from the steps before it.
_R_T, _R_MAXD, _R_TLO, _R_THI, _R_EDRIFT, _R_STATUS, _R_NSTEPS, _R_E0, _R_NA = range(9)
_R_CR = 9  # five entries: the least-squares sums of _add_crossing
_NREC = _R_CR + 5


@_jit()
def _tay_begin(x0, theta_ref, rec, ln):
    """Record ``ln`` of ``rec`` for a trajectory starting at ``x0``: t = 0, no step, no
    crossing."""
    for i in range(_NREC):
        rec[i, ln] = 0.0
    rec[_R_MAXD, ln] = abs(x0[0] - theta_ref)
    rec[_R_TLO, ln] = np.nan
    rec[_R_THI, ln] = np.nan


@_jit()
def _tay_end(rec, ln, out):
    """One row of :data:`COLUMNS` from the finished record ``ln`` (:func:`_summaries`)."""
    r = rec[:, ln]
    _summaries(out, r[_R_STATUS], r[_R_T], r[_R_MAXD], r[_R_CR:_R_CR + 5], r[_R_TLO],
               r[_R_THI], r[_R_EDRIFT], r[_R_NSTEPS])


@_jit()
def _tay_clip(t, dt, t_end):
    """The step actually taken: ``dt``, or what is left to ``t_end``."""
    return t_end - t if t + dt >= t_end else dt


@_jit()
def _lane_root(J, ln, P, sg, off, xa, xb, fa, fb):
    """:func:`rollingdisk.engine.taylor._tay_poly_root` on theta's polynomial in lane
    ``ln``.  This and the other ``_lane_*`` helpers take the lane's slices (views with a
    reference count) out of line, on the rare branches: the inlined step only indexes."""
    return _tay_poly_root(J[0, :, ln], P, sg, off, xa, xb, fa, fb)


@_jit()
def _lane_sample(h, J, A, ln, P, x, v):
    """:func:`rollingdisk.engine.taylor._tay_sample` in lane ``ln``."""
    _tay_sample(h, J[:, :, ln], A[:, :, ln], P, x, v)


@_jit()
def _lane_lift_off(h, J, A, ln, P, N, xa, xb, fa, fb):
    """The root of F_z in lane ``ln`` (:func:`rollingdisk.engine.taylor._tay_normal`)."""
    _tay_normal(h, J[:, :, ln], A[:, :, ln], P, N)
    return _tay_poly_root(N, P - 1, 1.0, 0.0, xa, xb, fa, fb)


@_jit()
def _lane_crossing(rec, ln, tc):
    """:func:`_add_crossing` to the sums of record ``ln``."""
    _add_crossing(rec[_R_CR:_R_CR + 5, ln], tc)


@_jit()
def _lane_energy(rough, h, k1, k2, Y, ln):
    """:func:`_reduced_energy` of lane ``ln``'s state."""
    return _reduced_energy(rough, h, k1, k2, Y[:, ln].copy())


@_jit(inline="always")
def _tay_plain(t_end, max_steps, grow_lo, grow_hi, side, c, E, dt, V, Y, rec):
    """The common step of :func:`_tay_advance`, without a branch: one whose samples show no
    guard, no crossing and no threshold, which is neither the first nor the last step of
    its run, nor a failing one.  If the step is such, the record ``rec`` and the state
    ``Y`` are advanced as :func:`_tay_advance` would (the same operations, in the same
    order) and 1.0 is returned; otherwise 0.0, and nothing is changed.

    The arguments are one lane's: ``c`` = (h, theta_ref, a0), ``side`` = sgn theta, ``E``
    and ``dt`` the energy and the unclipped step size, ``V[m - 1, :]`` the samples,
    ``Y[:]`` the state, ``rec[:]`` the record.  Written with :func:`_where` alone, it is
    traced into the vector lanes as it stands
    (:func:`rollingdisk.engine.lanes._lane_plain`: every lane at once); the lanes
    whose step is not common go through :func:`_tay_advance`."""
    t = rec[_R_T]
    n = rec[_R_NSTEPS]
    h = c[0]
    theta_ref = c[1]
    half_pi = 0.5 * np.pi
    lev_lo = grow_lo * c[2]
    lev_hi = grow_hi * c[2]
    t_lo = rec[_R_TLO]
    t_hi = rec[_R_THI]
    ok = _where(n > 0.0, 1.0, 0.0)
    ok = _where(n < max_steps, ok, 0.0)
    ok = _where(t + dt < t_end, ok, 0.0)  # not the last step (nor a NaN or infinite one)
    ok = _where(dt > 1e-15 * max(1.0, t), ok, 0.0)
    max_d = rec[_R_MAXD]
    da = Y[0] - theta_ref
    for m in range(_SAMPLES):
        th = V[m, 0]
        ok = _where(th * side <= 0.0, _where(h > 0.0, 0.0, ok), ok)  # edge contact
        ok = _where(V[m, 4] <= 0.0, 0.0, ok)  # lift-off
        ok = _where(half_pi - abs(th) <= 0.0, 0.0, ok)  # fell flat
        db = th - theta_ref
        ok = _where(da < 0.0, _where(db >= 0.0, 0.0, ok), ok)  # a crossing
        ad = abs(db)
        max_d = max(max_d, ad)
        # a threshold not yet passed (its time NaN, not equal to itself) is passed now
        ok = _where(ad > lev_lo, _where(t_lo == t_lo, ok, 0.0), ok)
        ok = _where(ad > lev_hi, _where(t_hi == t_hi, ok, 0.0), ok)
        da = db
    E0 = rec[_R_E0]
    de = abs(E - E0) / max(abs(E0), 1e-300)
    go = ok > 0.0
    rec[_R_EDRIFT] = _where(go, max(rec[_R_EDRIFT], de), rec[_R_EDRIFT])
    rec[_R_MAXD] = _where(go, max_d, rec[_R_MAXD])
    rec[_R_NSTEPS] = _where(go, n + 1.0, n)
    rec[_R_T] = _where(go, t + dt, t)
    rec[_R_NA] = _where(go, V[_SAMPLES - 1, 4], rec[_R_NA])
    for i in range(4):
        Y[i] = _where(go, V[_SAMPLES - 1, i], Y[i])
    return ok


# Why one long function (issue 17: compiled kernels are exempt from the ~80-line rule): one
# step of one trajectory of the batch Taylor kernels, compiled by numba (nopython, inlined
# into the step loops of _one_taylor and of the vector lanes).  The summaries are taken on
# the step polynomial at its sample points, and the guards and crossings found there are
# located on it; with no closures or objects in nopython, the running summaries are read
# from the record into local scalars once and written back once.  The arrays are indexed
# by lane rather than sliced (a slice is a view with a reference count).
@_jit(inline="always")
def _tay_advance(rough, h, k1, k2, side, theta_ref, a0, grow_lo, grow_hi, t_end, max_steps,
                 P, J, A, N, E, dt, V, v, Y, rec, ln):
    """One step of the trajectory in lane ``ln`` by the Taylor method of
    :mod:`rollingdisk.engine.taylor` (order P, step size of Jorba & Zou); the summaries
    of :func:`_one`, taken on the step polynomials.  Returns the status (0 while running);
    updates ``Y[:, ln]`` and ``rec[:, ln]``.

    ``J[:, :, ln]``, ``A[:, :, ln]``: the jet at ``Y[:, ln]``
    (:func:`rollingdisk.engine.taylor._tay_jet4_rough` / ``_smooth``); ``E``: the energy
    there; ``dt``: the step size before clipping to ``t_end``; ``V[m - 1, :, ln]`` =
    ``(theta, omega1, omega2, omega3, F_z)`` at ``dt' m / _SAMPLES`` (``dt'`` clipped,
    :func:`_tay_clip`; :func:`rollingdisk.engine.taylor._tay_sample`): theta (crossings,
    thresholds, max |theta - theta0|, edge contact, falling flat) and F_z (lift-off) at
    each sample.  Crossings, threshold times and guard events are located on the
    polynomial (:func:`rollingdisk.engine.taylor._tay_poly_root`; for F_z on its series,
    :func:`rollingdisk.engine.taylor._tay_normal`), so a guard ends the run where it
    fires, not at the end of a step.  The energy is taken at every step's start and at the
    end.
    """
    t = rec[_R_T, ln]
    n_steps = rec[_R_NSTEPS, ln]
    half_pi = 0.5 * np.pi
    if n_steps == 0:
        rec[_R_E0, ln] = E
        _lane_sample(h, J, A, ln, P, 0.0, v)
        rec[_R_NA, ln] = v[4]
        if v[4] <= 0.0:
            rec[_R_STATUS, ln] = LIFT_OFF
            return LIFT_OFF
        if half_pi - abs(Y[0, ln]) <= 0.0:
            rec[_R_STATUS, ln] = FELL_FLAT
            return FELL_FLAT
    E0 = rec[_R_E0, ln]
    de = abs(E - E0) / max(abs(E0), 1e-300)
    if de > rec[_R_EDRIFT, ln]:
        rec[_R_EDRIFT, ln] = de
    status = 0
    if t >= t_end:
        status = COMPLETED
    elif n_steps >= max_steps:
        status = FAILED
    last = t + dt >= t_end
    dt = _tay_clip(t, dt, t_end)
    if status == 0 and (not (dt > 1e-15 * max(1.0, t)) or not np.isfinite(dt)):
        status = FAILED
    if status != 0:
        rec[_R_STATUS, ln] = status
        return status
    edge = h > 0.0
    max_d = rec[_R_MAXD, ln]
    t_lo = rec[_R_TLO, ln]
    t_hi = rec[_R_THI, ln]
    n_a = rec[_R_NA, ln]
    xa = 0.0
    th_a = Y[0, ln]
    da = th_a - theta_ref
    fired = 0
    mb = 0
    for m in range(1, _SAMPLES + 1):
        mb = m
        xb = dt * m / _SAMPLES if m < _SAMPLES else dt
        th_b = V[m - 1, 0, ln]
        n_b = V[m - 1, 4, ln]
        # guards (an edge contact first, as rollingdisk.engine.dop853._first_fired)
        if edge and th_b * side <= 0.0:
            xb = _lane_root(J, ln, P, side, 0.0, xa, xb, th_a * side, th_b * side)
            fired = EDGE_CONTACT
        elif n_b <= 0.0:
            xb = _lane_lift_off(h, J, A, ln, P, N, xa, xb, n_a, n_b)
            fired = LIFT_OFF
        elif half_pi - abs(th_b) <= 0.0:
            sg = 1.0 if th_b >= 0.0 else -1.0
            xb = _lane_root(J, ln, P, -sg, -half_pi, xa, xb, half_pi - abs(th_a),
                            half_pi - abs(th_b))
            fired = FELL_FLAT
        if fired != 0:
            _lane_sample(h, J, A, ln, P, xb, v)
            th_b = v[0]
        db = th_b - theta_ref
        # summaries on (xa, xb]
        if da < 0.0 <= db:
            _lane_crossing(rec, ln, t + _lane_root(J, ln, P, 1.0, theta_ref, xa, xb, da, db))
        ad = abs(db)
        if ad > max_d:
            max_d = ad
        sg = 1.0 if db >= 0.0 else -1.0
        if np.isnan(t_lo) and ad > grow_lo * a0:
            lev = grow_lo * a0
            t_lo = t + _lane_root(J, ln, P, sg, sg * theta_ref + lev, xa, xb, sg * da - lev,
                                  ad - lev)
        if np.isnan(t_hi) and ad > grow_hi * a0:
            lev = grow_hi * a0
            t_hi = t + _lane_root(J, ln, P, sg, sg * theta_ref + lev, xa, xb, sg * da - lev,
                                  ad - lev)
        xa = xb
        da = db
        th_a = th_b
        n_a = n_b
        if fired != 0:
            break
    rec[_R_NSTEPS, ln] = n_steps + 1
    rec[_R_T, ln] = t_end if (last and fired == 0) else t + xa
    rec[_R_MAXD, ln] = max_d
    rec[_R_TLO, ln] = t_lo
    rec[_R_THI, ln] = t_hi
    rec[_R_NA, ln] = n_a
    if fired == 0:
        for i in range(4):
            Y[i, ln] = V[mb - 1, i, ln]
        return 0
    for i in range(4):
        Y[i, ln] = v[i]
    rec[_R_STATUS, ln] = fired
    E = _lane_energy(rough, h, k1, k2, Y, ln)
    de = abs(E - E0) / max(abs(E0), 1e-300)
    if de > rec[_R_EDRIFT, ln]:
        rec[_R_EDRIFT, ln] = de
    return fired


@_jit()
def _one_taylor(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atolv,
                max_steps, P, out):
    """One trajectory by the Taylor method (:func:`_tay_advance` step by step), the jet,
    step size and samples computed here one trajectory at a time (one lane): the kernel for
    orders above :data:`rollingdisk.engine.lanes.MAX_ORDER`, and the reference the
    vector lanes are held to."""
    J2 = np.zeros((4, P + 1))
    A2 = np.zeros((14, P + 1))
    N = np.zeros(P + 1)
    V = np.zeros((_SAMPLES, 5, 1))
    y = x0.copy()
    Y = y.reshape((4, 1))  # the lane views share memory with y, J2, A2
    J = J2.reshape((4, P + 1, 1))
    A = A2.reshape((14, P + 1, 1))
    v = np.empty(5)
    side = 1.0 if y[0] >= 0.0 else -1.0
    ht = h * side
    rec = np.empty((_NREC, 1))
    c = np.array([h, theta_ref, a0])
    _tay_begin(x0, theta_ref, rec, 0)
    while True:
        if rough:
            _tay_jet4_rough(h, y, J2, A2, P)
        else:
            _tay_jet4_smooth(h, y, J2, A2, P)
        E = _energy_sc(rough, ht, k1, k2, A2[0, 0], A2[1, 0], y)
        dt = _tay_step_size(J2, P, atolv, rtol)
        dtc = _tay_clip(rec[_R_T, 0], dt, t_end)
        for m in range(1, _SAMPLES + 1):
            _tay_sample(h, J2, A2, P, dtc * m / _SAMPLES if m < _SAMPLES else dtc, v)
            for i in range(5):
                V[m - 1, i, 0] = v[i]
        if _tay_plain(t_end, max_steps, grow_lo, grow_hi, side, c, E, dt, V[:, :, 0], y,
                      rec[:, 0]) > 0.0:
            continue
        if _tay_advance(rough, h, k1, k2, side, theta_ref, a0, grow_lo, grow_hi, t_end,
                        max_steps, P, J, A, N, E, dt, V, v, Y, rec, 0) != 0:
            break
    _tay_end(rec, 0, out)


@_jit()
def _lane_rows(n):
    """Zeros of shape (n, LANES) whose rows start on a 64-byte boundary: a row is one vector
    of the lanes, and a vector load that straddles two cache lines costs two."""
    buf = np.zeros((n + 1) * LANES)
    k = (-(buf.ctypes.data // 8)) % LANES
    return buf[k:k + n * LANES].reshape((n, LANES))


# Why one long function (issue 17: compiled kernels are exempt from the ~80-line rule): the
# step loop of LANES trajectories at once, compiled by numba (nopython, one call per
# block of a prange).  The lanes' arrays (jets, samples, records) are allocated once in
# this frame; each step is one traced vector call for the jets, energies and step sizes,
# one for the samples, one for the common step (_tay_plain), then the scalar bookkeeping
# (_tay_advance) of the lanes whose step was not common, and a lane whose trajectory
# ended takes the next one of the block.
@_jit()
def _lanes(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atol,
           max_steps, P, order, lo, hi, out):
    """The trajectories ``order[lo:hi]`` through :data:`rollingdisk.engine.lanes.LANES`
    vector lanes (:mod:`rollingdisk.engine.lanes`; ``P`` a compile-time literal); rows
    of ``out`` as :func:`_one_taylor` fills them, bit for bit."""
    W = LANES
    # every array of the lanes in one block, each row one vector on a cache line: their
    # relative places are then fixed, not the allocator's (with separate arrays the kernel's
    # speed varied from process to process by up to 25 %; in one block, by 11 %)
    rows = _lane_rows(18 * (P + 1) + 5 * _SAMPLES + _NREC + 15)
    J, r = rows[:4 * (P + 1)].reshape((4, P + 1, W)), 4 * (P + 1)
    A, r = rows[r:r + 14 * (P + 1)].reshape((14, P + 1, W)), r + 14 * (P + 1)
    V, r = rows[r:r + 5 * _SAMPLES].reshape((_SAMPLES, 5, W)), r + 5 * _SAMPLES
    rec, r = rows[r:r + _NREC], r + _NREC
    Y, EO, c = rows[r:r + 4], rows[r + 4:r + 6], rows[r + 6:r + 9]  # c: h, theta_ref, a0
    hv, k1v, k2v, dtc, side = rows[r + 9], rows[r + 10], rows[r + 11], rows[r + 12], rows[r + 13]
    plain = rows[r + 14]  # 1.0 where the lane's step was the common one (_tay_plain)
    Y[0, :] = 0.3  # an idle lane's state: any value that keeps its arithmetic finite
    Y[3, :] = 1.0
    k1v[:] = 0.25
    k2v[:] = 0.5
    side[:] = 1.0
    N = np.zeros(P + 1)
    v = np.empty(5)
    mx = float(max_steps)
    lane = np.full(W, -1)  # the trajectory in each lane, -1 for none
    fresh = np.zeros(W, np.bool_)  # a trajectory just put in the lane, not started
    nxt = lo
    for ln in range(W):
        if nxt < hi:
            lane[ln] = order[nxt]
            fresh[ln] = True
            nxt += 1
    live = W - np.sum(lane < 0)
    while live > 0:
        for ln in range(W):
            if fresh[ln]:
                i = lane[ln]
                fresh[ln] = False
                side[ln] = 1.0 if x0[i, 0] >= 0.0 else -1.0
                hv[ln] = h[i] * side[ln]
                k1v[ln] = k1[i]
                k2v[ln] = k2[i]
                c[0, ln] = h[i]
                c[1, ln] = theta_ref[i]
                c[2, ln] = a0[i]
                for q in range(4):
                    Y[q, ln] = x0[i, q]
                _tay_begin(x0[i], theta_ref[i], rec, ln)
        if rough:
            _lane_jet_rough(P, hv, k1v, k2v, atol, rtol, Y, J, A, EO)
        else:
            _lane_jet_smooth(P, hv, k1v, k2v, atol, rtol, Y, J, A, EO)
        for ln in range(W):
            dtc[ln] = _tay_clip(rec[_R_T, ln], EO[1, ln], t_end)
        _lane_samples(P, _SAMPLES, hv, J, A, dtc, V)
        _lane_plain(_tay_plain, t_end, mx, grow_lo, grow_hi, side, c, EO, V, Y, rec, plain)
        for ln in range(W):
            i = lane[ln]
            if i < 0 or plain[ln] > 0.0:
                continue
            st = _tay_advance(rough, c[0, ln], k1v[ln], k2v[ln], side[ln], c[1, ln], c[2, ln],
                              grow_lo, grow_hi, t_end, max_steps, P, J, A, N, EO[0, ln],
                              EO[1, ln], V, v, Y, rec, ln)
            if st != 0:
                _tay_end(rec, ln, out[i])
                if nxt < hi:
                    lane[ln] = order[nxt]
                    fresh[ln] = True
                    nxt += 1
                else:
                    lane[ln] = -1
                    live -= 1


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
