"""A Taylor-series integrator for the equations of motion (``simulate(method="taylor")``).

The step of order p follows the jet of the state (:mod:`rollingdisk.engine.taylor_jets`:
the recurrences of eqs. 1, 2, 37, 38 and 49), with p = ceil(-ln(tol)/2) + 1 (16 at 1e-14),
which makes the steps long.  Step size and order follow Jorba & Zou, "A software package
for the numerical integration of ODEs by means of high-order Taylor methods", Exp. Math.
14 (2005) 99, as heyoka does: ``rho = min((s/|x^[p-1]|)^(1/(p-1)), (s/|x^[p]|)^(1/p))``,
``dt = rho / e^2 exp(-0.7/(p-1))``, ``s`` = 1 under absolute and ``|x|`` under relative
control.  ``tests/test_simulate_taylor.py`` holds whole runs to DOP853.

The polynomial of each step is its dense output: guards (lift-off, edge contact, falling
flat) are sampled inside every step and located on it by regula falsi, output times
``t_eval`` are evaluated on it.  Functions here are compiled by
:mod:`rollingdisk.engine.numba_core` (names start with ``_tay``); the module itself needs only
numpy.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.engine.roots import (
    ILLINOIS_MAXITER,
    _illinois_converged,
    _illinois_trial,
    _illinois_update,
)
from rollingdisk.engine.taylor_jets import _tay_eval, _tay_eval_reduced, _tay_jet, _tay_step_size
from rollingdisk.model.outcomes import (
    COMPLETED,
    EDGE_CONTACT,
    FAILED,
    FELL_FLAT,
    LIFT_OFF,
    RUNNING,
    STEP_BUDGET,
)

#: Interior fractions of a step at which the guards are sampled.
_TAY_SAMPLES = 4


def taylor_order(tol: float) -> int:
    """The order of the method for tolerance ``tol``: ``ceil(-ln(tol)/2) + 1`` in [4, 40]."""
    return int(min(40, max(4, math.ceil(-math.log(tol) / 2.0) + 1)))


def _tay_locate(rough, h, J, P, side, kg, xa, xb, ga, gb, ytmp, g):
    """Illinois regula falsi (:mod:`.roots`) on the step polynomial for the root of guard
    ``kg`` in (xa, xb] (times from the step start), positive at xa, not positive at xb;
    returns the last admissible time (within round-off of the root)."""
    flag = 0
    for _ in range(ILLINOIS_MAXITER):
        if _illinois_converged(xa, xb):
            break
        xc = _illinois_trial(xa, xb, ga, gb)
        _tay_eval(J, P, xc, ytmp)
        _side_guards(rough, h, ytmp, side, g)  # noqa: F821 - bound by numba_core
        xa, xb, ga, gb, flag = _illinois_update(xa, xb, ga, gb, xc, g[kg], flag)
    return xa


# Why one long function (issue 17: compiled kernels are exempt from the ~80-line rule): the
# step loop of simulate(method="taylor"), compiled by numba in nopython mode (numba_core):
# no closures, no solver object, no exceptions for control flow.  The loop's state (the
# jet J, the scratch A, output buffers, guard values, counters) lives in this one frame,
# allocated once; the jet, step size, evaluation and guard location are the small _tay_*
# helpers, and what remains is control flow (break on a guard, a budget or the chunk pause)
# that would otherwise be returned through flags at every step.
def _tay_integrate(rough, h, t0, y0, t_end, rtol, atolv, max_step, use_guards, side, t_eval,
                   has_t_eval, max_steps, chunk_steps, P):
    """Integrate from (t0, y0) towards t_end with the Taylor method of order P.

    Pauses (status RUNNING) after ``chunk_steps`` steps; a continued run takes the same
    steps (the step size depends on the state only).  ``atolv``: the absolute tolerance
    per component (``inf``: left out of the error control).  Returns ``(ts, ys, n_steps,
    status, event, t_last, y_last)``: the step ends (or the values at ``t_eval``) and the
    event point if a guard fired, the status, the guard that fired or -1, the end of the
    last step and the state there.
    """
    n = y0.shape[0]
    J = np.zeros((n, P + 1))
    A = np.zeros((19, P + 1))
    y = y0.copy()
    y_new = np.empty(n)
    ytmp = np.empty(n)
    r4 = np.empty(4)
    g_a = np.empty(3)
    g_b = np.empty(3)
    g_m = np.empty(3)
    any_guard = use_guards[0] or use_guards[1] or use_guards[2]
    cap = 1024
    ts = np.empty(cap)
    ys = np.empty((cap, n))
    m = 0
    ie = 0
    t = t0
    if not has_t_eval:
        ts[0] = t0
        ys[0] = y
        m = 1
    else:
        while ie < t_eval.shape[0] and t_eval[ie] <= t0:
            if m == cap:
                ts, ys, cap = _grow(ts, ys, m)  # noqa: F821 - bound by _numba_core
            ts[m] = t0
            ys[m] = y
            m += 1
            ie += 1
    status = RUNNING
    event = -1
    n_steps = 0
    taken = 0
    _side_guards(rough, h, y, side, g_a)  # noqa: F821
    if any_guard:  # a guard already violated at the start
        k0 = _first_fired(g_a, use_guards)  # noqa: F821
        if k0 == 0 or k0 == 2:
            if m == 0:
                ts[0] = t
                ys[0] = y
                m = 1
            return ts[:m], ys[:m], 0, LIFT_OFF if k0 == 0 else FELL_FLAT, k0, t, y
    while True:
        if t >= t_end:
            status = COMPLETED
            break
        if n_steps >= max_steps:
            status = STEP_BUDGET
            break
        if taken >= chunk_steps:
            break
        _tay_jet(rough, h, y, J, A, P)
        dt = _tay_step_size(J, P, atolv, rtol)
        dt = min(dt, max_step)
        last = False
        if t + dt >= t_end:
            dt = t_end - t
            last = True
        if not (dt > 1e-15 * max(1.0, abs(t))) or not math.isfinite(dt):
            status = FAILED
            break
        _tay_eval(J, P, dt, y_new)
        finite = True  # a series beyond float range (omega3 = 1e150) fails, never completes
        for q in range(y_new.shape[0]):
            finite = finite and math.isfinite(y_new[q])
        if not finite:
            status = FAILED
            break
        fired = -1
        x_hit = dt
        if any_guard:
            # the guards at the step's start (kept from the last step), middle and end; the
            # step is sampled only where one may reach 0 (the rule of _needs_sampling)
            _tay_eval_reduced(rough, J, P, 0.5 * dt, r4)
            _side_guards(rough, h, r4, side, g_m)  # noqa: F821 - bound by _numba_core
            _side_guards(rough, h, y_new, side, g_b)  # noqa: F821
            if _needs_sampling(g_a, g_m, g_b, use_guards):  # noqa: F821
                xa = 0.0
                for js in range(1, _TAY_SAMPLES + 2):
                    xb = dt * js / (_TAY_SAMPLES + 1)
                    if js == _TAY_SAMPLES + 1:
                        xb = dt
                    _tay_eval(J, P, xb, ytmp)
                    _side_guards(rough, h, ytmp, side, g_b)  # noqa: F821
                    fired = _first_fired(g_b, use_guards)  # noqa: F821
                    if fired >= 0:
                        x_hit = _tay_locate(rough, h, J, P, side, fired, xa, xb, g_a[fired],
                                            g_b[fired], ytmp, g_m)
                        _tay_eval(J, P, x_hit, y_new)
                        break
                    xa = xb
                    for q in range(3):
                        g_a[q] = g_b[q]
            for q in range(3):
                g_a[q] = g_b[q]
        t_new = t + x_hit if fired >= 0 else (t_end if last else t + dt)
        if has_t_eval:
            while ie < t_eval.shape[0] and t_eval[ie] <= t_new:
                if m == cap:
                    ts, ys, cap = _grow(ts, ys, m)  # noqa: F821
                _tay_eval(J, P, t_eval[ie] - t, ytmp)
                ts[m] = t_eval[ie]
                ys[m] = ytmp
                m += 1
                ie += 1
        if not has_t_eval or fired >= 0:
            if m == cap:
                ts, ys, cap = _grow(ts, ys, m)  # noqa: F821
            ts[m] = t_new
            ys[m] = y_new
            m += 1
        n_steps += 1
        taken += 1
        t = t_new
        for i in range(n):
            y[i] = y_new[i]
        if fired >= 0:
            status = LIFT_OFF if fired == 0 else (EDGE_CONTACT if fired == 1 else FELL_FLAT)
            event = fired
            break
        if last:
            status = COMPLETED
            break
    return ts[:m], ys[:m], n_steps, status, event, t, y
