"""The sweeps' batch Taylor kernels, one trajectory at a time and in vector lanes (numba;
imported lazily; run by :func:`rollingdisk.sweep.batch.run_batch_taylor` and
:func:`rollingdisk.sweep.batch.run_batch_lanes`).

The Taylor method of :mod:`rollingdisk.engine.taylor` on the reduced jets
``tay_jet4_rough``/``_smooth`` of :mod:`rollingdisk.engine.taylor_jets`, in vector lanes
(:mod:`rollingdisk.engine.lanes`, eight trajectories per instruction) or scalar; summaries
and guards sampled on the step polynomial and located on it, by the same per-step code
(:func:`_tay_plain` for the common step, traced into the lanes; :func:`_tay_advance` for
the others).
"""

from __future__ import annotations

import numpy as np

from rollingdisk.engine.lanes import (
    LANES,
    lane_jet_rough,
    lane_jet_smooth,
    lane_plain,
    lane_samples,
)
from rollingdisk.engine.numba_core import (
    energy_sc,
    tay_jet4_rough,
    tay_jet4_smooth,
    tay_normal,
    tay_poly_root,
    tay_sample,
    tay_step_size,
    where,
)
from rollingdisk.model.outcomes import (
    COMPLETED,
    EDGE_CONTACT,
    FAILED,
    FELL_FLAT,
    LIFT_OFF,
)
from rollingdisk.sweep.batch_common import (
    _add_crossing,
    _jit,
    _reduced_energy,
    _summaries,
)

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
    """:func:`rollingdisk.engine.taylor_jets._tay_poly_root` on theta's polynomial in lane
    ``ln``.  This and the other ``_lane_*`` helpers take the lane's slices (views with a
    reference count) out of line, on the rare branches: the inlined step only indexes."""
    return tay_poly_root(J[0, :, ln], P, sg, off, xa, xb, fa, fb)


@_jit()
def _lane_sample(h, J, A, ln, P, x, v):
    """:func:`rollingdisk.engine.taylor_jets._tay_sample` in lane ``ln``."""
    tay_sample(h, J[:, :, ln], A[:, :, ln], P, x, v)


@_jit()
def _lane_lift_off(h, J, A, ln, P, N, xa, xb, fa, fb):
    """The root of F_z in lane ``ln`` (:func:`rollingdisk.engine.taylor_jets._tay_normal`)."""
    tay_normal(h, J[:, :, ln], A[:, :, ln], P, N)
    return tay_poly_root(N, P - 1, 1.0, 0.0, xa, xb, fa, fb)


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
    ``Y[:]`` the state, ``rec[:]`` the record.  Written with :func:`where` alone, it is
    traced into the vector lanes as it stands
    (:func:`rollingdisk.engine.lanes.lane_plain`: every lane at once); the lanes
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
    ok = where(n > 0.0, 1.0, 0.0)
    ok = where(n < max_steps, ok, 0.0)
    ok = where(t + dt < t_end, ok, 0.0)  # not the last step (nor a NaN or infinite one)
    ok = where(dt > 1e-15 * max(1.0, t), ok, 0.0)
    max_d = rec[_R_MAXD]
    da = Y[0] - theta_ref
    for m in range(_SAMPLES):
        th = V[m, 0]
        ok = where(th * side <= 0.0, where(h > 0.0, 0.0, ok), ok)  # edge contact
        ok = where(V[m, 4] <= 0.0, 0.0, ok)  # lift-off
        ok = where(half_pi - abs(th) <= 0.0, 0.0, ok)  # fell flat
        db = th - theta_ref
        ok = where(da < 0.0, where(db >= 0.0, 0.0, ok), ok)  # a crossing
        ad = abs(db)
        max_d = max(max_d, ad)
        # a threshold not yet passed (its time NaN, not equal to itself) is passed now
        ok = where(ad > lev_lo, where(t_lo == t_lo, ok, 0.0), ok)
        ok = where(ad > lev_hi, where(t_hi == t_hi, ok, 0.0), ok)
        da = db
    E0 = rec[_R_E0]
    de = abs(E - E0) / max(abs(E0), 1e-300)
    go = ok > 0.0
    rec[_R_EDRIFT] = where(go, max(rec[_R_EDRIFT], de), rec[_R_EDRIFT])
    rec[_R_MAXD] = where(go, max_d, rec[_R_MAXD])
    rec[_R_NSTEPS] = where(go, n + 1.0, n)
    rec[_R_T] = where(go, t + dt, t)
    rec[_R_NA] = where(go, V[_SAMPLES - 1, 4], rec[_R_NA])
    for i in range(4):
        Y[i] = where(go, V[_SAMPLES - 1, i], Y[i])
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
    (:func:`rollingdisk.engine.taylor_jets._tay_jet4_rough` / ``_smooth``); ``E``: the energy
    there; ``dt``: the step size before clipping to ``t_end``; ``V[m - 1, :, ln]`` =
    ``(theta, omega1, omega2, omega3, F_z)`` at ``dt' m / _SAMPLES`` (``dt'`` clipped,
    :func:`_tay_clip`; :func:`rollingdisk.engine.taylor_jets._tay_sample`): theta (crossings,
    thresholds, max |theta - theta0|, edge contact, falling flat) and F_z (lift-off) at
    each sample.  Crossings, threshold times and guard events are located on the
    polynomial (:func:`rollingdisk.engine.taylor_jets._tay_poly_root`; for F_z on its series,
    :func:`rollingdisk.engine.taylor_jets._tay_normal`), so a guard ends the run where it
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
            tay_jet4_rough(h, y, J2, A2, P)
        else:
            tay_jet4_smooth(h, y, J2, A2, P)
        E = energy_sc(rough, ht, k1, k2, A2[0, 0], A2[1, 0], y)
        dt = tay_step_size(J2, P, atolv, rtol)
        dtc = _tay_clip(rec[_R_T, 0], dt, t_end)
        for m in range(1, _SAMPLES + 1):
            tay_sample(h, J2, A2, P, dtc * m / _SAMPLES if m < _SAMPLES else dtc, v)
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
    # speed varied from process to process with where the allocator put them)
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
            lane_jet_rough(P, hv, k1v, k2v, atol, rtol, Y, J, A, EO)
        else:
            lane_jet_smooth(P, hv, k1v, k2v, atol, rtol, Y, J, A, EO)
        for ln in range(W):
            dtc[ln] = _tay_clip(rec[_R_T, ln], EO[1, ln], t_end)
        lane_samples(P, _SAMPLES, hv, J, A, dtc, V)
        lane_plain(_tay_plain, t_end, mx, grow_lo, grow_hi, side, c, EO, V, Y, rec, plain)
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
