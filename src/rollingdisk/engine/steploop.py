"""The DOP853 step loop of every model of :mod:`rollingdisk.engine.contract`.

:func:`integrate` takes a model's right-hand side, event functions and impact map as
explicit arguments (nothing is re-bound, no module global stands for the model) and runs
uncompiled as written or compiled by :mod:`rollingdisk.engine.steploop_numba` from this
very source.  Callers use the driver :func:`rollingdisk.engine.driver.solve`, which checks
the arguments, picks the path and returns a frozen
:class:`~rollingdisk.engine.contract.Solution`.

The method is DOP853 with the arithmetic of :mod:`rollingdisk.engine.dop853`: the stage
sums, the error norm, the step-size factor, the dense output and its evaluation and the
output buffers are that module's functions (``_combine``, ``_error_norm_v``,
``_step_factor``, ``_dense_tail``, ``_dense_value``, ``_rms``, ``_grow``) and its copy of
Hairer's table (:mod:`rollingdisk.engine.dop853_coefficients`); only the three places that call the
right-hand side (the stages, the extra stages of the dense output, the initial step) are
written here, with the model's ``rhs`` as an argument.  Stage ``s`` is evaluated at time
``t + C[s] dt``, so a right-hand side may depend on ``t``.

Events are located inside every accepted step: the event functions are sampled on the
dense output (order 7) at ``j / 8`` of the step, and in each sub-interval where one
changes sign in its direction its root is refined by the Illinois rule
(:mod:`rollingdisk.engine.roots`) to round-off; the roots of one sub-interval are handled
in time order.  An event's state is the dense output at the last point before its root
(the root to within 4e-16 of the step).  A recorded event lets the step go on; a terminal
one ends the run (``completed``); an impact applies the model's map and the run restarts
from the state it returns, with a fresh right-hand side and scipy's initial step (the
steps after an impact do not remember the steps before it).  The run ends with an outcome
of :mod:`rollingdisk.model.outcomes`: ``completed``, ``step-budget`` after ``max_steps``
accepted steps, ``failed`` when the step size falls below round-off, or the outcome an
impact map returns.
"""

from __future__ import annotations

import numpy as np

from rollingdisk.engine.contract import CONTINUE, IMPACT, RECORD
from rollingdisk.engine.dop853 import (
    _A,
    _AX,
    _B,
    _NF,
    _NS,
    _NSUB,
    _NSX,
    _combine,
    _dense_tail,
    _dense_value,
    _error_norm_v,
    _grow,
    _rms,
    _step_factor,
)
from rollingdisk.engine.dop853_coefficients import C as _C_ALL
from rollingdisk.engine.roots import (
    ILLINOIS_MAXITER,
    _illinois_converged,
    _illinois_trial,
    _illinois_update,
)
from rollingdisk.model.outcomes import COMPLETED, FAILED, RUNNING, STEP_BUDGET

__all__ = ["integrate"]

#: The nodes of all 16 stages (the method's 12, the end, the dense output's 3).
_CS = np.ascontiguousarray(_C_ALL)


# ------------------------------------------------------------------ the stages
def _stages(rhs, p, t, y, f, dt, K, ytmp, kout, y_new, f_new):
    """One DOP853 step of length ``dt`` from ``(t, y)`` with ``f = rhs(t, y)``: the stages
    into the columns of ``K`` (shape ``(n, 16)``), the new state and its slope into
    ``y_new``, ``f_new`` (:func:`rollingdisk.engine.dop853._step` with ``rhs`` given)."""
    n = y.shape[0]
    for i in range(n):
        K[i, 0] = f[i]
    for s in range(1, _NS):
        _combine(y, dt, _A[s], K, s, ytmp)
        rhs(t + _CS[s] * dt, ytmp, p, kout)
        for i in range(n):
            K[i, s] = kout[i]
    _combine(y, dt, _B, K, _NS, y_new)
    rhs(t + dt, y_new, p, f_new)
    for i in range(n):
        K[i, _NS] = f_new[i]


def _dense(rhs, p, t, y, y_new, f_new, dt, K, ytmp, kout, F):
    """The interpolant's coefficients ``F`` (shape ``(7, n)``) of an accepted step: the 3
    extra stages, then :func:`rollingdisk.engine.dop853._dense_tail`."""
    n = y.shape[0]
    for s in range(_NS + 1, _NSX):
        _combine(y, dt, _AX[s - _NS - 1], K, s, ytmp)
        rhs(t + _CS[s] * dt, ytmp, p, kout)
        for i in range(n):
            K[i, s] = kout[i]
    _dense_tail(y, y_new, f_new, dt, K, F)


def _first_step(rhs, p, t0, y0, f0, t_bound, max_step, rtol, atolv):
    """scipy's ``select_initial_step`` (Hairer, Norsett & Wanner, sec. II.4) with a
    tolerance per component: :func:`rollingdisk.engine.dop853.initial_step_v`."""
    n = y0.shape[0]
    scale = np.empty(n)
    for i in range(n):
        scale[i] = atolv[i] + abs(y0[i]) * rtol
    interval = abs(t_bound - t0)
    if interval == 0.0:
        return 0.0
    d0 = _rms(y0, scale)
    d1 = _rms(f0, scale)
    if d0 < 1e-5 or d1 < 1e-5:
        h0 = 1e-6
    else:
        h0 = 0.01 * d0 / d1
    h0 = min(h0, interval)
    if not h0 > 0.0:
        return 0.0
    y1 = y0 + h0 * f0
    f1 = np.empty(n)
    rhs(t0 + h0, y1, p, f1)
    d2 = _rms(f1 - f0, scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 8.0)
    return min(100.0 * h0, h1, interval, max_step)


# ------------------------------------------------------------------ events
def _crosses(ga, gb, d):
    """Whether an event of direction ``d`` occurs between values ``ga`` and ``gb``."""
    if d <= 0 and ga > 0.0 and gb <= 0.0:
        return True
    return d >= 0 and ga < 0.0 and gb >= 0.0


def _event_root(events, p, t, dt, y, F, k, xa, xb, ga, gb, ytmp, g):
    """The last fraction of the step before the root of event ``k`` in ``(xa, xb]``
    (``ga`` nonzero at ``xa``, ``gb`` of the other sign or 0 at ``xb``): Illinois on the
    dense output (:mod:`rollingdisk.engine.roots`)."""
    flag = 0
    for _ in range(ILLINOIS_MAXITER):
        if _illinois_converged(xa, xb):
            break
        xc = _illinois_trial(xa, xb, ga, gb)
        _dense_value(y, F, xc, ytmp)
        events(t + xc * dt, ytmp, p, g)
        xa, xb, ga, gb, flag = _illinois_update(xa, xb, ga, gb, xc, g[k], flag)
    return xa


def _grow_events(ev_t, ev_k, ev_y, ev_yp, m):
    """Event arrays of twice the size, holding the first ``m`` rows."""
    cap = 2 * ev_t.shape[0]
    a = np.empty(cap)
    b = np.empty(cap, dtype=np.int64)
    c = np.empty((cap, ev_y.shape[1]))
    d = np.empty((cap, ev_y.shape[1]))
    a[:m] = ev_t[:m]
    b[:m] = ev_k[:m]
    c[:m] = ev_y[:m]
    d[:m] = ev_yp[:m]
    return a, b, c, d


# ------------------------------------------------------------------ the loop
# Why one long function: it is the hot loop, compiled by numba in nopython mode
# (steploop_numba), where the work arrays live as locals of one frame and control flow
# (a rejected step, an event, a budget) cannot leave through exceptions or objects.
def integrate(rhs, events, impact, p, t0, y0, t_end, rtol, atolv, max_step, first_step,
              max_steps, direction, action):
    """Integrate a model from ``(t0, y0)`` to ``t_end`` with DOP853 and its events.

    Parameters
    ----------
    rhs, events, impact : functions
        The model's (signatures in :mod:`rollingdisk.engine.contract`).
    p : ndarray, shape (n_p,)
        The model's parameters (an impact map may update them).
    t0, t_end : float
        Start and end time (``t_end > t0``).
    y0 : ndarray, shape (n,)
        Initial state.
    rtol : float
        Relative tolerance.
    atolv : ndarray, shape (n,)
        Absolute tolerance per component (``inf``: not controlled).
    max_step : float
        Largest step.
    first_step : float
        First step to try; ``<= 0``: scipy's initial step.
    max_steps : int
        Accepted steps at most.
    direction, action : ndarray of int64, shape (n_events,)
        Per event: its direction (-1, 0, +1) and action (``RECORD``, ``TERMINAL``,
        ``IMPACT`` of :mod:`rollingdisk.engine.contract`).

    Returns
    -------
    tuple
        ``(ts, ys, ev_t, ev_k, ev_y, ev_yp, status, end_event, n_steps, n_rhs)``: the
        output points, the events (time, index, state before, state after), the outcome
        code, the event that ended the run or -1, the accepted steps and right-hand sides.
    """
    n = y0.shape[0]
    ne = direction.shape[0]
    K = np.empty((n, _NSX))
    F = np.empty((_NF, n))
    ytmp = np.empty(n)
    kout = np.empty(n)
    y = y0.copy()
    f = np.empty(n)
    y_new = np.empty(n)
    f_new = np.empty(n)
    y_e = np.empty(n)
    y_after = np.empty(n)
    g_old = np.empty(ne)
    g_new = np.empty(ne)
    g_a = np.empty(ne)
    g_b = np.empty(ne)
    g_w = np.empty(ne)
    x_root = np.empty(ne)
    pending = np.zeros(ne, dtype=np.bool_)
    ts = np.empty(256)
    ys = np.empty((256, n))
    ev_t = np.empty(16)
    ev_k = np.empty(16, dtype=np.int64)
    ev_y = np.empty((16, n))
    ev_yp = np.empty((16, n))
    m = 1
    m_ev = 0
    ts[0] = t0
    ys[0] = y
    t = t0
    n_steps = 0
    n_rhs = 1
    rhs(t, y, p, f)
    events(t, y, p, g_old)
    dt_abs = first_step
    if not dt_abs > 0.0:
        dt_abs = _first_step(rhs, p, t, y, f, t_end, max_step, rtol, atolv)
        n_rhs += 1
    status = RUNNING
    end_event = -1
    if not (dt_abs > 0.0) or not np.isfinite(dt_abs):
        status = FAILED
    while status == RUNNING:
        if t >= t_end:
            status = COMPLETED
            break
        if n_steps >= max_steps:
            status = STEP_BUDGET
            break
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        if dt_abs > max_step:
            dt_abs = max_step
        if dt_abs < min_step:
            dt_abs = min_step
        rejected = False
        accepted = False
        dt = 0.0
        t_new = t
        h_next = dt_abs
        while not accepted:
            if dt_abs < min_step:
                status = FAILED
                break
            t_new = t + dt_abs
            if t_new > t_end:
                t_new = t_end
            dt = t_new - t
            dt_abs = abs(dt)
            if not dt > 0.0:
                status = FAILED
                break
            _stages(rhs, p, t, y, f, dt, K, ytmp, kout, y_new, f_new)
            n_rhs += _NS
            finite = True
            for i in range(n):
                if not np.isfinite(y_new[i]):
                    finite = False
            err = _error_norm_v(y, y_new, K, dt, rtol, atolv) if finite else np.inf
            if err < 1.0:
                h_next = dt_abs * _step_factor(err, rejected)
                accepted = True
            else:
                dt_abs *= _step_factor(err, rejected)
                rejected = True
        if status != RUNNING:
            break
        n_steps += 1
        # events: sampled on the dense output, each sub-interval's roots in time order
        restart = False
        if ne > 0:
            events(t_new, y_new, p, g_new)
            _dense(rhs, p, t, y, y_new, f_new, dt, K, ytmp, kout, F)
            n_rhs += _NSX - _NS - 1
            for k in range(ne):
                g_a[k] = g_old[k]
            x_prev = 0.0
            for j in range(1, _NSUB + 1):
                x = j / _NSUB
                if j == _NSUB:
                    for k in range(ne):
                        g_b[k] = g_new[k]
                else:
                    _dense_value(y, F, x, ytmp)
                    events(t + x * dt, ytmp, p, g_b)
                for k in range(ne):
                    pending[k] = _crosses(g_a[k], g_b[k], direction[k])
                    if pending[k]:
                        x_root[k] = _event_root(events, p, t, dt, y, F, k, x_prev, x,
                                                g_a[k], g_b[k], ytmp, g_w)
                while True:
                    best = -1
                    for k in range(ne):
                        if pending[k] and (best == -1 or x_root[k] < x_root[best]):
                            best = k
                    if best == -1:
                        break
                    pending[best] = False
                    x_e = x_root[best]
                    t_e = t + x_e * dt
                    _dense_value(y, F, x_e, y_e)
                    for i in range(n):
                        y_after[i] = y_e[i]
                    code = CONTINUE
                    if action[best] == IMPACT:
                        code = impact(best, t_e, y_e, p, y_after)
                    if m_ev == ev_t.shape[0]:
                        ev_t, ev_k, ev_y, ev_yp = _grow_events(ev_t, ev_k, ev_y, ev_yp, m_ev)
                    ev_t[m_ev] = t_e
                    ev_k[m_ev] = best
                    ev_y[m_ev] = y_e
                    ev_yp[m_ev] = y_after
                    m_ev += 1
                    if action[best] == RECORD:
                        continue
                    if m + 2 > ts.shape[0]:
                        ts, ys, _cap = _grow(ts, ys, m)
                    ts[m] = t_e
                    ys[m] = y_e
                    m += 1
                    end_event = best
                    if action[best] == IMPACT:
                        ts[m] = t_e
                        ys[m] = y_after
                        m += 1
                        if code != CONTINUE:
                            status = code
                        else:
                            restart = True
                    else:
                        status = COMPLETED
                    break
                if restart or status != RUNNING:
                    break
                for k in range(ne):
                    g_a[k] = g_b[k]
                x_prev = x
        if status != RUNNING:
            break
        if restart:  # from the impact map's state, as a new initial-value problem
            end_event = -1
            t = ts[m - 1]
            for i in range(n):
                y[i] = y_after[i]
            rhs(t, y, p, f)
            events(t, y, p, g_old)
            dt_abs = _first_step(rhs, p, t, y, f, t_end, max_step, rtol, atolv)
            n_rhs += 2
            if not (dt_abs > 0.0) or not np.isfinite(dt_abs):
                status = FAILED
            continue
        if m == ts.shape[0]:
            ts, ys, _cap = _grow(ts, ys, m)
        ts[m] = t_new
        ys[m] = y_new
        m += 1
        t = t_new
        for i in range(n):
            y[i] = y_new[i]
            f[i] = f_new[i]
        for k in range(ne):
            g_old[k] = g_new[k]
        dt_abs = h_next
    return (ts[:m], ys[:m], ev_t[:m_ev], ev_k[:m_ev], ev_y[:m_ev], ev_yp[:m_ev], status,
            end_event, n_steps, n_rhs)
