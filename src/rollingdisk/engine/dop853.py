"""The DOP853 integrator of :func:`rollingdisk.simulate`: one source, run two ways.

Plain Python functions on numpy arrays and floats, importing neither numba nor
``scipy.integrate``.  :mod:`rollingdisk.engine.numba_core` compiles them with numba (as
it compiles the kernels of :mod:`rollingdisk.model.equations`, from their own source);
:mod:`rollingdisk.engine.pycore` runs the very same functions uncompiled, re-bound to a
namespace whose ``np`` does scalar maths with :mod:`math` and whose few array loops (``_combine``,
``_error_norm_v``, ``_dense_tail``, ``_dense_value``, ``_rms``, ``_rhs``) are numpy
one-liners.  The step-size control, the guards, the pauses and the output are written once.

The method is the explicit Runge-Kutta method of Dormand and Prince of order 8 with the
5th/3rd order error estimator (DOP853, Hairer, Norsett & Wanner, *Solving ODE I*, sec.
II.10), with Hairer's coefficients and scipy's step-size control, so it takes the steps of
``scipy.integrate.solve_ivp(method="DOP853")``.  Guard events
(:mod:`rollingdisk.model.events`) are located on the 7th-degree dense output (3 extra
right-hand sides) by the Illinois variant of regula falsi.  The error can be controlled on
part of the state only: a per-component ``atol`` of ``inf`` leaves a component out of the
error norm (it is still integrated through the same stages), which is how the quadratures
``X_C, Y_C, psi, phi`` ride along the reduced system ``(theta, omega1, omega2, omega3)``
(``error_control="reduced"``).

The coefficients are data of the library's own (:mod:`.dop853_coefficients`, Hairer's
table, checked against the order conditions by the tests), so an upgrade of scipy cannot
change them.

Why one module: every function here is compiled by numba into one
namespace (and run uncompiled in another), so the integrator, its dense output and its
guard location stay in one source file that both can re-bind.
"""

from __future__ import annotations

import numpy as np

from rollingdisk.engine import dop853_coefficients as _dop  # Hairer's DOP853 table
from rollingdisk.engine.roots import (
    ILLINOIS_MAXITER,
    _illinois_converged,
    _illinois_trial,
    _illinois_update,
)
from rollingdisk.model import events as _ev

# the model's kernels, under the names by which this module's functions call them and the
# compiled namespaces (numba_core, pycore) bind their compiled versions
from rollingdisk.model.equations import normal_force as _normal_force
from rollingdisk.model.equations import reduced_rhs as _reduced_rhs
from rollingdisk.model.equations import rough_rhs as _rough_rhs
from rollingdisk.model.equations import side_normal_force as _side_normal_force
from rollingdisk.model.equations import smooth_rhs as _smooth_rhs
from rollingdisk.model.state import reduced_state as _reduced_state

# ------------------------------------------------------------------ DOP853 coefficients
_NS = _dop.N_STAGES  # 12
_A = np.ascontiguousarray(_dop.A[:_NS, :_NS])
_B = np.ascontiguousarray(_dop.B)
_C = np.ascontiguousarray(_dop.C[:_NS])
_E3 = np.ascontiguousarray(_dop.E3)
_E5 = np.ascontiguousarray(_dop.E5)
# dense output: 3 extra stages (rows N_STAGES + 1 ... of A and C) and the matrix D
_NSX = _dop.N_STAGES_EXTENDED  # 16
_NF = _dop.INTERPOLATOR_POWER  # 7
_AX = np.ascontiguousarray(_dop.A[_NS + 1:_NSX, :_NSX])
_D = np.ascontiguousarray(_dop.D)
_SAFETY = 0.9
_MIN_FACTOR = 0.2
_MAX_FACTOR = 10.0
_ERR_EXP = -1.0 / 8.0  # error estimator of order 7
_NSUB = 8  # guards sampled on the dense output at 7 inner points of a step
#: Dense sampling of a guard is skipped in a step where it stays above this many times its
#: spread over the step (start, a stage, end) and above _GUARD_FLOOR: see _needs_sampling.
_GUARD_SPAN = 16.0
_GUARD_FLOOR = 0.05
_MID_STAGE = 9  # node C[9] = 0.6 of the step

# status codes shared with rollingdisk.model.events
RUNNING, COMPLETED, LIFT_OFF, EDGE_CONTACT, FELL_FLAT, FAILED, STEP_BUDGET = (
    _ev.RUNNING, _ev.COMPLETED, _ev.LIFT_OFF, _ev.EDGE_CONTACT, _ev.FELL_FLAT, _ev.FAILED,
    _ev.STEP_BUDGET)


def _rhs(rough, h, y, out):
    """dy/dt into ``out``: full state of either ground (8 or 10 components) or the reduced
    state ``(theta, omega1, omega2, omega3)`` (4 components)."""
    if y.shape[0] == 4:
        r4 = _reduced_rhs(rough, h, y)
        for i in range(4):
            out[i] = r4[i]
    elif rough:
        r = _rough_rhs(h, y)
        for i in range(8):
            out[i] = r[i]
    else:
        r2 = _smooth_rhs(h, y)
        for i in range(10):
            out[i] = r2[i]


def _rhs_col(rough, h, y, K, s):
    """dy/dt into column ``s`` of the stage array ``K`` (shape (n, stages)): as
    :func:`_rhs`, without a view of ``K`` per stage."""
    if y.shape[0] == 4:
        r4 = _reduced_rhs(rough, h, y)
        for i in range(4):
            K[i, s] = r4[i]
    elif rough:
        r = _rough_rhs(h, y)
        for i in range(8):
            K[i, s] = r[i]
    else:
        r2 = _smooth_rhs(h, y)
        for i in range(10):
            K[i, s] = r2[i]


def _guards(rough, h, y, g):
    """Guard values, each positive while the motion is admissible.

    g[0] = F_z (lift-off when it reaches 0, eq. 11); g[1] = theta (for h > 0 the disk
    lands on its other rim edge when theta reaches 0); g[2] = pi/2 - |theta| (falls flat).
    """
    theta = _reduced_state(rough, y)[0]
    g[0] = _normal_force(rough, h, y)
    g[1] = theta
    g[2] = 0.5 * np.pi - abs(theta)


def _combine(y, dt, coef, K, m, out):
    """out = y + dt * sum_{j < m} coef[j] K[:, j] (a Runge-Kutta stage or the new state).

    ``K`` holds the stages in its columns, so that the sum over stages runs along
    contiguous memory."""
    for i in range(y.shape[0]):
        acc = 0.0
        for j in range(m):
            acc += coef[j] * K[i, j]
        out[i] = y[i] + dt * acc


def _step(rough, h, t, y, f, dt, K, ytmp, y_new, f_new):
    """One DOP853 step of length dt from (t, y) with f = f(t, y); fills y_new, f_new and the
    stages K (shape (n, stages), one column per stage)."""
    n = y.shape[0]
    for i in range(n):
        K[i, 0] = f[i]
    for s in range(1, _NS):
        _combine(y, dt, _A[s], K, s, ytmp)
        _rhs_col(rough, h, ytmp, K, s)
    _combine(y, dt, _B, K, _NS, y_new)
    _rhs(rough, h, y_new, f_new)
    for i in range(n):
        K[i, _NS] = f_new[i]


def _dense_tail(y, y_new, f_new, dt, K, F):
    """The interpolant's coefficients F from the 16 stages in K (scipy's formulas)."""
    for i in range(y.shape[0]):
        dy = y_new[i] - y[i]
        F[0, i] = dy
        F[1, i] = dt * K[i, 0] - dy
        F[2, i] = 2.0 * dy - dt * (f_new[i] + K[i, 0])
        for r in range(_NF - 3):
            acc = 0.0
            for j in range(_NSX):
                acc += _D[r, j] * K[i, j]
            F[3 + r, i] = dt * acc


def _dense_coefficients(rough, h, y, y_new, f_new, dt, K, ytmp, F):
    """Coefficients F of the DOP853 interpolant on an accepted step (t, y) -> (t + dt, y_new).

    ``K`` holds the stages of the step (rows 0 ... N_STAGES, as left by :func:`_step`); the
    3 extra stages go to its rows N_STAGES + 1 ... (3 right-hand-side evaluations).  The
    same formulas as scipy's ``DOP853._dense_output_impl`` (the right-hand side does not
    depend on t, so the extra nodes ``C_EXTRA`` do not enter).
    """
    for s in range(_NS + 1, _NSX):
        _combine(y, dt, _AX[s - _NS - 1], K, s, ytmp)
        _rhs_col(rough, h, ytmp, K, s)
    _dense_tail(y, y_new, f_new, dt, K, F)


def _dense_value(y, F, x, out):
    """The interpolant at the fraction x of the step (scipy's ``Dop853DenseOutput``)."""
    for i in range(y.shape[0]):
        acc = 0.0
        for r in range(_NF - 1, -1, -1):
            acc += F[r, i]
            if (_NF - 1 - r) % 2 == 0:
                acc *= x
            else:
                acc *= 1.0 - x
        out[i] = y[i] + acc


def _error_norm(y, y_new, K, dt, rtol, atol):
    n = y.shape[0]
    e5 = 0.0
    e3 = 0.0
    for i in range(n):
        a5 = 0.0
        a3 = 0.0
        for j in range(_NS + 1):
            a5 += _E5[j] * K[i, j]
            a3 += _E3[j] * K[i, j]
        sc = atol + rtol * max(abs(y[i]), abs(y_new[i]))
        e5 += (a5 / sc) ** 2
        e3 += (a3 / sc) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(dt) * e5 / np.sqrt((e5 + 0.01 * e3) * n)


def _error_norm_v(y, y_new, K, dt, rtol, atolv):
    """:func:`_error_norm` with a tolerance per component; ``atolv[i] = inf`` leaves
    component i out of the error (it still counts in the mean, as in scipy with such an
    ``atol``)."""
    n = y.shape[0]
    e5 = 0.0
    e3 = 0.0
    for i in range(n):
        if atolv[i] == np.inf:
            continue
        a5 = 0.0
        a3 = 0.0
        for j in range(_NS + 1):
            a5 += _E5[j] * K[i, j]
            a3 += _E3[j] * K[i, j]
        sc = atolv[i] + rtol * max(abs(y[i]), abs(y_new[i]))
        e5 += (a5 / sc) ** 2
        e3 += (a3 / sc) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(dt) * e5 / np.sqrt((e5 + 0.01 * e3) * n)


def _step_factor(err, rejected):
    """The factor for the next step size after a step with error norm ``err``: scipy's
    DOP853 control.  Accepted (``err < 1``): ``min(10, 0.9 err^(-1/8))``, at most 1 right
    after a rejection; rejected: ``max(0.2, 0.9 err^(-1/8))``, 0.2 if ``err`` is not finite.
    """
    if err < 1.0:
        factor = _MAX_FACTOR if err == 0.0 else min(_MAX_FACTOR, _SAFETY * err ** _ERR_EXP)
        return min(1.0, factor) if rejected else factor
    if err == err and err < np.inf:
        return max(_MIN_FACTOR, _SAFETY * err ** _ERR_EXP)
    return _MIN_FACTOR


def _rms(v, scale):
    acc = 0.0
    for i in range(v.shape[0]):
        acc += (v[i] / scale[i]) ** 2
    return np.sqrt(acc / v.shape[0])


def initial_step(rough, h, t0, y0, f0, t_bound, max_step, rtol, atol):
    """scipy's ``select_initial_step`` (Hairer, Norsett & Wanner, sec. II.4)."""
    n = y0.shape[0]
    scale = np.empty(n)
    for i in range(n):
        scale[i] = atol + abs(y0[i]) * rtol
    return _initial_step_scaled(rough, h, t0, y0, f0, t_bound, max_step, scale)


def initial_step_v(rough, h, t0, y0, f0, t_bound, max_step, rtol, atolv):
    """:func:`initial_step` with a tolerance per component (``inf``: not controlled)."""
    n = y0.shape[0]
    scale = np.empty(n)
    for i in range(n):
        scale[i] = atolv[i] + abs(y0[i]) * rtol
    return _initial_step_scaled(rough, h, t0, y0, f0, t_bound, max_step, scale)


def _initial_step_scaled(rough, h, t0, y0, f0, t_bound, max_step, scale):
    n = y0.shape[0]
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
    if not h0 > 0.0:  # d1 overflowed (or interval is subnormal): no usable first step
        return 0.0
    y1 = y0 + h0 * f0
    f1 = np.empty(n)
    _rhs(rough, h, y1, f1)
    d2 = _rms(f1 - f0, scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 8.0)
    return min(100.0 * h0, h1, interval, max_step)


def _side_guards(rough, h, y, side, g):
    """Guard values on the side ``side = sgn(theta(0))``, each positive while admissible
    (:mod:`rollingdisk.model.events`): g[0] = F_z with ``h~ = h side`` (eq. 11), g[1] =
    ``theta side``, g[2] = ``pi/2 - |theta|``."""
    theta = _reduced_state(rough, y)[0]
    g[0] = _side_normal_force(rough, h, y, side)
    g[1] = theta * side
    g[2] = 0.5 * np.pi - abs(theta)


def _first_fired(g, use):
    """The guard that is not positive in g (edge contact first, then lift-off, then
    falling flat: at one instant an edge contact wins), or -1."""
    for k in (1, 0, 2):
        if use[k] and g[k] <= 0.0:
            return k
    return -1


def _guard_root(rough, h, y, F, side, k, xa, xb, ga, gb, ytmp, g):
    """Illinois regula falsi (:mod:`.roots`) on the interpolant for the root of guard k in
    (xa, xb], with guard k positive (ga) at xa and not positive (gb) at xb.  Returns the last
    admissible fraction of the step (within round-off of the root)."""
    flag = 0
    for _ in range(ILLINOIS_MAXITER):
        if _illinois_converged(xa, xb):
            break
        xc = _illinois_trial(xa, xb, ga, gb)
        _dense_value(y, F, xc, ytmp)
        _side_guards(rough, h, ytmp, side, g)
        xa, xb, ga, gb, flag = _illinois_update(xa, xb, ga, gb, xc, g[k], flag)
    return xa


def _locate_on_dense(rough, h, y, y_new, F, side, use, g_old, g_new, ytmp, g, g2):
    """First guard root inside the step, located on its dense output.

    The guards are sampled at the fractions ``j / _NSUB`` of the step; in the first
    sub-interval where one is no longer positive each guard that fired there is refined on
    the interpolant and the earliest root wins (ties: :func:`_first_fired`'s order).
    Returns ``(k, x)``: the guard and the admissible fraction of the step just before its
    root, or ``(-1, 1.0)``.
    """
    for i in range(3):
        g2[i] = g_old[i]
    x_prev = 0.0
    for j in range(1, _NSUB + 1):
        x = j / _NSUB
        if j == _NSUB:
            for i in range(3):
                g[i] = g_new[i]
        else:
            _dense_value(y, F, x, ytmp)
            _side_guards(rough, h, ytmp, side, g)
        if _first_fired(g, use) >= 0:
            best_k = -1
            best_x = x
            gb = np.empty(3)
            for i in range(3):
                gb[i] = g[i]
            for k in (1, 0, 2):
                if use[k] and gb[k] <= 0.0:
                    if not (g2[k] > 0.0):  # not positive at the start: stop there
                        xk = x_prev
                    else:
                        xk = _guard_root(rough, h, y, F, side, k, x_prev, x, g2[k], gb[k],
                                         ytmp, g)
                    if best_k == -1 or xk < best_x:
                        best_k = k
                        best_x = xk
            return best_k, best_x
        for i in range(3):
            g2[i] = g[i]
        x_prev = x
    return -1, 1.0


def _needs_sampling(g_old, g_mid, g_new, use):
    """Whether a guard may reach 0 inside a step: its values at the start, at the stage
    ``_MID_STAGE`` of the step and at the end come within ``_GUARD_SPAN`` times their
    spread, or within ``_GUARD_FLOOR``, of 0.

    A guard far from 0 compared with how much it moves in a step (the three values see a
    turning point inside it too) cannot dip below 0 there; elsewhere it is sampled on the
    dense output at ``j / _NSUB`` of the step and located there.  Cheap: the guards at the
    step's ends are needed anyway, the stage state is one short sum away."""
    for k in range(3):
        if use[k]:
            lo = min(g_old[k], g_mid[k], g_new[k])
            hi = max(g_old[k], g_mid[k], g_new[k])
            if lo <= max(_GUARD_SPAN * (hi - lo), _GUARD_FLOOR):
                return True
    return False


def _mid_guards(rough, h, y, dt, K, side, ytmp, g):
    """The guards at the stage state ``_MID_STAGE`` of a step (node ``_C[_MID_STAGE]``)."""
    _combine(y, dt, _A[_MID_STAGE], K, _MID_STAGE, ytmp)
    _side_guards(rough, h, ytmp, side, g)


def _grow(ts, ys, m):
    """Output arrays of twice the size, holding the first m rows."""
    cap = 2 * ts.shape[0]
    ts2 = np.empty(cap)
    ys2 = np.empty((cap, ys.shape[1]))
    ts2[:m] = ts[:m]
    ys2[:m] = ys[:m]
    return ts2, ys2, cap


# Why one long function (issue 17: compiled kernels are exempt from the ~80-line rule): this
# is the hot loop of every compiled run, compiled by numba in nopython mode
# (rollingdisk.engine.numba_core).  There it can use no closures, no objects holding the
# solver's state and no exceptions for control flow, so the step loop - step, error norm,
# accept or reject, guards sampled and located on the dense output, t_eval output, budgets
# and the chunk pause - keeps its work arrays (K, y, y_new, F, the guard vectors) as locals
# of one frame, allocated once per call; the per-step pieces are already small helpers
# above (_step, _error_norm_v, _dense_coefficients, _locate_on_dense, ...).  Moving the
# remaining control flow (break on a guard or a budget, continue on a rejected step) into
# functions would need flag tuples returned through every call and would put status
# bookkeeping into the per-step path.
def integrate(rough, h, t0, y0, t_end, t_pause, rtol, atolv, max_step, first_step, use_guards,
              side, t_eval, has_t_eval, max_steps, chunk_steps, keep_dense):
    """Integrate from (t0, y0) to t_end, stopping at the first guard event.

    Pauses (status RUNNING) after the first accepted step that reaches ``t_pause < t_end``
    or after ``chunk_steps`` steps; steps are never shortened for a pause, so a run
    continued from the returned ``(t_last, y_last)`` with ``first_step = h_next`` takes the
    very steps of an uninterrupted run.  ``atolv``: the absolute tolerance per component
    (``inf``: left out of the error control).  Guards are located on the dense output inside
    every step where they may reach 0 (:func:`_needs_sampling`, :func:`_locate_on_dense`),
    on the side ``side = sgn(theta(0))``.  Status
    STEP_BUDGET once ``max_steps`` steps are taken, FAILED if the step size falls below
    round-off (or the first step comes out 0).

    Returns ``(ts, ys, n_steps, n_rhs, status, event, h_next, t_last, y_last, seg_t,
    seg_dt, seg_y, seg_F)``: the accepted steps (or the values at ``t_eval``) followed by
    the event point if one fired, the status, the index of the guard that fired or -1,
    the step size to try next, the end of the last accepted step and, with
    ``keep_dense``, each step's start, length, start state and interpolant coefficients.
    """
    n = y0.shape[0]
    K = np.empty((n, _NSX))
    F = np.empty((_NF, n))
    ytmp = np.empty(n)
    y = y0.copy()
    f = np.empty(n)
    y_new = np.empty(n)
    f_new = np.empty(n)
    y_ev = np.empty(n)
    g_old = np.empty(3)
    g_new = np.empty(3)
    g_tmp = np.empty(3)
    g_tmp2 = np.empty(3)
    any_guard = use_guards[0] or use_guards[1] or use_guards[2]

    cap = 1024
    ts = np.empty(cap)
    ys = np.empty((cap, n))
    dcap = 64 if keep_dense else 1
    seg_t = np.empty(dcap)
    seg_dt = np.empty(dcap)
    seg_y = np.empty((dcap, n))
    seg_F = np.empty((dcap, _NF, n))
    nseg = 0
    m = 0
    ie = 0  # next t_eval index
    if not has_t_eval:
        ts[0] = t0
        ys[0] = y
        m = 1
    else:
        while ie < t_eval.shape[0] and t_eval[ie] <= t0:
            if m == cap:
                ts, ys, cap = _grow(ts, ys, m)
            ts[m] = t0
            ys[m] = y
            m += 1
            ie += 1

    n_rhs = 0
    n_steps = 0
    t = t0
    _side_guards(rough, h, y, side, g_old)
    # a guard already violated at the start
    k0 = _first_fired(g_old, use_guards)
    if k0 == 0 or k0 == 2:
        if m == 0:
            ts[m] = t
            ys[m] = y
            m += 1
        return (ts[:m], ys[:m], n_steps, n_rhs, LIFT_OFF if k0 == 0 else FELL_FLAT, k0,
                0.0, t, y, seg_t[:0], seg_dt[:0], seg_y[:0], seg_F[:0])
    _rhs(rough, h, y, f)
    n_rhs += 1

    if first_step > 0.0:
        dt_abs = first_step
    else:
        dt_abs = initial_step_v(rough, h, t0, y, f, t_end, max_step, rtol, atolv)
        n_rhs += 1
    status = RUNNING
    event = -1
    if not (dt_abs > 0.0) or not np.isfinite(dt_abs):
        status = FAILED  # the first step came out 0 (or not finite): nothing to integrate
    n_here = 0
    h_next = dt_abs
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
        while not accepted:
            if dt_abs < min_step:
                status = FAILED
                break
            dt = dt_abs
            t_new = t + dt
            if t_new > t_end:
                t_new = t_end
            dt = t_new - t
            dt_abs = abs(dt)
            if not dt > 0.0:
                status = FAILED
                break
            _step(rough, h, t, y, f, dt, K, ytmp, y_new, f_new)
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
        if status == FAILED:
            break
        n_steps += 1
        n_here += 1
        # dense output of the whole step (3 more right-hand sides): for the guards inside it
        # where one may reach 0 (its ends and one stage say so), for t_eval and keep_dense
        _side_guards(rough, h, y_new, side, g_new)
        sample = False
        if any_guard:
            _mid_guards(rough, h, y, dt, K, side, ytmp, g_tmp)
            sample = _needs_sampling(g_old, g_tmp, g_new, use_guards)
        dense = sample or keep_dense or (
            has_t_eval and ie < t_eval.shape[0] and t_eval[ie] < t_new)
        if dense:
            _dense_coefficients(rough, h, y, y_new, f_new, dt, K, ytmp, F)
            n_rhs += _NSX - _NS - 1
        t_stop = t_new
        if sample:
            k, x = _locate_on_dense(rough, h, y, y_new, F, side, use_guards, g_old, g_new,
                                    ytmp, g_tmp, g_tmp2)
            if k >= 0:
                event = k
                t_stop = t + x * dt
                if x <= 0.0:
                    t_stop = t
                    for i in range(n):
                        y_ev[i] = y[i]
                else:
                    _dense_value(y, F, x, y_ev)
                if k == 0:
                    status = LIFT_OFF
                elif k == 1:
                    status = EDGE_CONTACT
                else:
                    status = FELL_FLAT
        if keep_dense:
            if nseg == dcap:
                dcap *= 2
                a1 = np.empty(dcap)
                a2 = np.empty(dcap)
                a3 = np.empty((dcap, n))
                a4 = np.empty((dcap, _NF, n))
                a1[:nseg] = seg_t[:nseg]
                a2[:nseg] = seg_dt[:nseg]
                a3[:nseg] = seg_y[:nseg]
                a4[:nseg] = seg_F[:nseg]
                seg_t, seg_dt, seg_y, seg_F = a1, a2, a3, a4
            seg_t[nseg] = t
            seg_dt[nseg] = dt
            seg_y[nseg] = y
            seg_F[nseg] = F
            nseg += 1
        y_out = y_ev if status != RUNNING else y_new
        # output
        if has_t_eval:
            while ie < t_eval.shape[0] and t_eval[ie] <= t_stop:
                if m + 1 >= cap:
                    ts, ys, cap = _grow(ts, ys, m)
                if t_eval[ie] == t_stop:
                    ys[m] = y_out
                else:
                    _dense_value(y, F, (t_eval[ie] - t) / dt, ytmp)
                    ys[m] = ytmp
                ts[m] = t_eval[ie]
                m += 1
                ie += 1
            if status != RUNNING and (m == 0 or ts[m - 1] != t_stop):
                if m == cap:
                    ts, ys, cap = _grow(ts, ys, m)
                ts[m] = t_stop
                ys[m] = y_out
                m += 1
        else:
            if m == cap:
                ts, ys, cap = _grow(ts, ys, m)
            if not (status != RUNNING and ts[m - 1] == t_stop):
                ts[m] = t_stop
                ys[m] = y_out
                m += 1
        if status != RUNNING:
            break
        t = t_new
        for i in range(n):
            y[i] = y_new[i]
            f[i] = f_new[i]
        for i in range(3):
            g_old[i] = g_new[i]
        dt_abs = h_next
        if t_pause <= t < t_end or n_here >= chunk_steps:
            break  # paused, status RUNNING
    return (ts[:m], ys[:m], n_steps, n_rhs, status, event, dt_abs, t, y, seg_t[:nseg],
            seg_dt[:nseg], seg_y[:nseg], seg_F[:nseg])


# What the scipy-path driver (rollingdisk.ivp.drivers) applies to scipy's steps, under public
# names: the guard-sampling rule of this loop, its stage and the stage matrix it reads.
needs_sampling = _needs_sampling
MID_STAGE = _MID_STAGE
STAGE_MATRIX = _A
