"""Compiled batch integrators for :mod:`rollingdisk.sweep.runner` (numba; imported lazily).

Integrate many trajectories of the reduced system ``x = (theta, omega1, omega2, omega3)``
(eq. 2 with eq. 38 on rough / eq. 49 on smooth ground) in one call, a ``numba.prange`` loop
over trajectories, by one of two methods:

* :func:`run_batch_taylor` (the default of the sweeps): the Taylor method of
  :mod:`rollingdisk.integrate.taylor` on the reduced jets ``_tay_jet4_rough``/``_tay_jet4_smooth``;
  summaries and guards sampled on the step polynomial and located on it.
* :func:`run_batch`: DOP853 with the building blocks of :mod:`rollingdisk.integrate.numba_core`
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

from rollingdisk.integrate.numba_core import (
    _A,
    _B,
    _NS,
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


@numba.njit(cache=True)
def _energy_sc(rough, ht, k1, k2, s, c, y):
    """E of the reduced state ``y`` with ``sin theta = s``, ``cos theta = c`` given (eqs. 13,
    37, 7; a = 1); on smooth ground the part of E that does not contain the constant
    V_X, V_Y (conserved by itself)."""
    w1, w2, w3 = y[1], y[2], y[3]
    y_P = s - ht * c  # eq. (4)
    z_P = -(c + ht * s)
    v_Cz = -w1 * y_P  # eq. (7)
    if rough:
        v_Cx = w2 - ht * w3  # eq. (37)
        v_Cy = w1 * z_P
        kin = 0.5 * (v_Cx * v_Cx + v_Cy * v_Cy + v_Cz * v_Cz)
    else:
        kin = 0.5 * v_Cz * v_Cz
    return kin + 0.5 * k1 * (w1 * w1 + w3 * w3) + 0.5 * k2 * w2 * w2 - z_P


@numba.njit(cache=True)
def _reduced_energy(rough, h, k1, k2, y):
    """E of the reduced state (:func:`_energy_sc`)."""
    ht, s, c, p, y_P, z_P = _geometry(h, y[0])
    return _energy_sc(rough, ht, k1, k2, s, c, y)


@numba.njit(cache=True)
def _step4(rough, h, y, dt, K, ytmp, y_new):
    """One DOP853 step of the reduced system (4 components), stages in the columns of
    ``K`` (shape (4, 13); column 0 holds f(y) on entry, column 12 f(y_new) on exit).

    The arithmetic of :func:`rollingdisk.integrate.dop853._step` (same coefficients, same order of
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


@numba.njit(cache=True)
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


@numba.njit(cache=True)
def _add_crossing(cr, tc):
    """Add the crossing time ``tc`` to the least-squares sums ``cr = (count, sum k, sum t_k,
    sum k^2, sum k t_k)`` of the crossing times t_k against their index k."""
    k = cr[0]
    cr[1] += k
    cr[2] += tc
    cr[3] += k * k
    cr[4] += k * tc
    cr[0] = k + 1.0


@numba.njit(cache=True)
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
@numba.njit(cache=True)
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


@numba.njit(cache=True)
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


@numba.njit(parallel=True, cache=True)
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


# Why one long function (issue 17: compiled kernels are exempt from the ~80-line rule): the
# Taylor twin of _one, compiled by numba (nopython, inside a prange loop).  The running
# summaries are taken on each step's polynomial at a few sample points, and with no
# closures or objects in nopython they stay local scalars of the one frame that owns the
# jet arrays (J, A) and the step loop; splitting would pass and return them as tuples at
# every step.  The jet, the step size and the polynomial evaluation are the taylor module's
# small _tay_* helpers.
@numba.njit(cache=True)
def _one_taylor(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atolv,
                max_steps, P, out):
    """One trajectory by the Taylor method of :mod:`rollingdisk.integrate.taylor` (order P, step
    size of Jorba & Zou); the summaries of :func:`_one`, taken on the step polynomials.

    Every step is sampled at ``_SAMPLES`` points (:func:`rollingdisk.integrate.taylor._tay_sample`):
    theta (crossings, thresholds, max |theta - theta0|, edge contact, falling flat) and F_z
    (lift-off).  Crossings, threshold times and guard events are located on the
    polynomial (regula falsi; for F_z on its series,
    :func:`rollingdisk.integrate.taylor._tay_normal`),
    so a guard ends the run where it fires, not at the end of a step.  The energy is taken
    at every step's start (sin and cos theta come with the jet) and at the end.
    """
    J = np.zeros((4, P + 1))
    A = np.zeros((14, P + 1))
    N = np.zeros(P + 1)
    y = x0.copy()
    v = np.empty(5)
    t = 0.0
    side = 1.0 if y[0] >= 0.0 else -1.0
    ht = h * side
    max_d = abs(y[0] - theta_ref)
    t_lo = np.nan
    t_hi = np.nan
    cr = np.zeros(5)  # least squares of crossing times t_k against k (_add_crossing)
    e_drift = 0.0
    status = 0
    n_steps = 0
    E0 = 0.0
    half_pi = 0.5 * np.pi
    edge = h > 0.0
    n_a = 0.0
    while status == 0:
        if rough:
            _tay_jet4_rough(h, y, J, A, P)
        else:
            _tay_jet4_smooth(h, y, J, A, P)
        E = _energy_sc(rough, ht, k1, k2, A[0, 0], A[1, 0], y)
        if n_steps == 0:
            E0 = E
            _tay_sample(h, J, A, P, 0.0, v)
            n_a = v[4]
            if n_a <= 0.0:
                status = LIFT_OFF
                break
            if half_pi - abs(y[0]) <= 0.0:
                status = FELL_FLAT
                break
        de = abs(E - E0) / max(abs(E0), 1e-300)
        if de > e_drift:
            e_drift = de
        if t >= t_end:
            status = COMPLETED
            break
        if n_steps >= max_steps:
            status = FAILED
            break
        dt = _tay_step_size(J, P, atolv, rtol)
        last = False
        if t + dt >= t_end:
            dt = t_end - t
            last = True
        if not (dt > 1e-15 * max(1.0, t)) or not np.isfinite(dt):
            status = FAILED
            break
        xa = 0.0
        th_a = y[0]
        da = th_a - theta_ref
        for m in range(1, _SAMPLES + 1):
            xb = dt * m / _SAMPLES if m < _SAMPLES else dt
            _tay_sample(h, J, A, P, xb, v)
            th_b = v[0]
            n_b = v[4]
            # guards (an edge contact first, as rollingdisk.integrate.dop853._first_fired)
            fired = 0
            if edge and th_b * side <= 0.0:
                xb = _tay_poly_root(J[0], P, side, 0.0, xa, xb, th_a * side, th_b * side)
                fired = EDGE_CONTACT
            elif n_b <= 0.0:
                _tay_normal(h, J, A, P, N)
                xb = _tay_poly_root(N, P - 1, 1.0, 0.0, xa, xb, n_a, n_b)
                fired = LIFT_OFF
            elif half_pi - abs(th_b) <= 0.0:
                sg = 1.0 if th_b >= 0.0 else -1.0
                xb = _tay_poly_root(J[0], P, -sg, -half_pi, xa, xb, half_pi - abs(th_a),
                                    half_pi - abs(th_b))
                fired = FELL_FLAT
            if fired != 0:
                _tay_sample(h, J, A, P, xb, v)
                th_b = v[0]
            db = th_b - theta_ref
            # summaries on (xa, xb]
            if da < 0.0 <= db:
                _add_crossing(cr, t + _tay_poly_root(J[0], P, 1.0, theta_ref, xa, xb, da, db))
            ad = abs(db)
            if ad > max_d:
                max_d = ad
            sg = 1.0 if db >= 0.0 else -1.0
            if np.isnan(t_lo) and ad > grow_lo * a0:
                lev = grow_lo * a0
                t_lo = t + _tay_poly_root(J[0], P, sg, sg * theta_ref + lev, xa, xb,
                                          sg * da - lev, ad - lev)
            if np.isnan(t_hi) and ad > grow_hi * a0:
                lev = grow_hi * a0
                t_hi = t + _tay_poly_root(J[0], P, sg, sg * theta_ref + lev, xa, xb,
                                          sg * da - lev, ad - lev)
            xa = xb
            da = db
            th_a = th_b
            n_a = n_b
            if fired != 0:
                status = fired
                break
        n_steps += 1
        t = t_end if (last and status == 0) else t + xa
        for i in range(4):
            y[i] = v[i]
        if status != 0:
            E = _reduced_energy(rough, h, k1, k2, y)
            de = abs(E - E0) / max(abs(E0), 1e-300)
            if de > e_drift:
                e_drift = de
    _summaries(out, status, t, max_d, cr, t_lo, t_hi, e_drift, n_steps)


@numba.njit(parallel=True, cache=True)
def run_batch_taylor(rough, h, k1, k2, x0, theta_ref, a0, grow_lo, grow_hi, t_end, rtol, atol,
                     max_steps, P):
    """:func:`run_batch` by the Taylor method of order P (:func:`_one_taylor`); guards are
    located inside the step where they fire."""
    n = x0.shape[0]
    out = np.empty((n, NCOL))
    atolv = np.full(4, atol)
    order = _spread(n)
    for k in numba.prange(n):
        i = order[k]
        _one_taylor(rough, h[i], k1[i], k2[i], x0[i], theta_ref[i], a0[i], grow_lo, grow_hi,
                    t_end, rtol, atolv, max_steps, P, out[i])
    return out
