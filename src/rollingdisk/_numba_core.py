"""Compiled integration core for :mod:`rollingdisk.simulate` (numba; imported lazily).

The right-hand sides are the very kernels of :mod:`rollingdisk.equations` (eqs. 1, 2, 37,
38 on rough, 2, 8, 49 on smooth ground), compiled from their own source: each kernel's code
object is re-bound to a namespace in which the kernels it calls are the compiled versions,
then handed to ``numba.njit``.  No formula is restated here: the lift-off guard uses the
normal force kernel of eq. (11) from :mod:`rollingdisk.equations` too.

The integrator is the explicit Runge-Kutta method of Dormand and Prince of order 8 with
the 5th/3rd order error estimator (DOP853, Hairer, Norsett & Wanner, *Solving ODE I*,
sec. II.10), with the same coefficients (taken from scipy) and the same step-size control
as ``scipy.integrate.solve_ivp(method="DOP853")``, so both take the same steps.  Guard
events are checked at the end of every accepted step and located by the Illinois variant of
regula falsi on the step length, re-integrating one DOP853 step from the start of the
step for each trial (a shorter step of the same method is at least as accurate as the
accepted one).  Output at requested times ``t_eval`` comes from the 7th-degree dense
output of DOP853 (the interpolant of scipy's ``DOP853.dense_output``, 3 extra right-hand
side evaluations per step that holds requested times).
"""

from __future__ import annotations

import types

import numba
import numpy as np

try:  # a private scipy module: the coefficients of scipy's own DOP853 (scipy >= 1.4)
    from scipy.integrate._ivp import dop853_coefficients as _dop

    for _name in ("N_STAGES", "N_STAGES_EXTENDED", "INTERPOLATOR_POWER", "A", "B", "C", "E3",
                  "E5", "D"):
        getattr(_dop, _name)
except (ImportError, AttributeError) as _exc:  # pragma: no cover - depends on scipy
    import scipy

    raise ImportError(
        "rollingdisk's compiled integrator takes the DOP853 coefficients from scipy's "
        "private module scipy.integrate._ivp.dop853_coefficients (present in scipy 1.4 to "
        f"at least 1.17), which scipy {scipy.__version__} does not provide as expected "
        f"({_exc}); install a scipy version that has it, or use simulate(method='scipy')"
    ) from _exc

from . import equations as _eq

# ------------------------------------------------------------------ compiled kernels
_ns = dict(_eq.__dict__)


def _compile(name):
    f = _eq.__dict__[name]
    g = types.FunctionType(f.__code__, _ns, f.__name__, f.__defaults__, f.__closure__)
    g.__qualname__ = f.__qualname__
    g.__module__ = f.__module__
    d = numba.njit(cache=True)(g)
    _ns[name] = d  # later kernels call the compiled version
    return d


_geometry = _compile("_geometry")
_rough_omega_dot = _compile("_rough_omega_dot")
_smooth_omega_dot = _compile("_smooth_omega_dot")
_rough_rhs = _compile("_rough_rhs")
_smooth_rhs = _compile("_smooth_rhs")
_reduced_state = _compile("_reduced_state")
_reduced_rhs = _compile("_reduced_rhs")
_normal_force = _compile("_normal_force")  # eq. (11), for the lift-off guard

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

# status codes shared with simulate.py
RUNNING, COMPLETED, LIFT_OFF, EDGE_CONTACT, FELL_FLAT, FAILED = 0, 1, 2, 3, 4, 5


@numba.njit(cache=True)
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


@numba.njit(cache=True)
def _guards(rough, h, y, g):
    """Guard values, each positive while the motion is admissible.

    g[0] = F_z (lift-off when it reaches 0, eq. 11); g[1] = theta (for h > 0 the disk
    lands on its other rim edge when theta reaches 0); g[2] = pi/2 - |theta| (falls flat).
    """
    theta = _reduced_state(rough, y)[0]
    g[0] = _normal_force(rough, h, y)
    g[1] = theta
    g[2] = 0.5 * np.pi - abs(theta)


@numba.njit(cache=True)
def _step(rough, h, t, y, f, dt, K, ytmp, y_new, f_new):
    """One DOP853 step of length dt from (t, y) with f = f(t, y); fills y_new, f_new, K."""
    n = y.shape[0]
    for i in range(n):
        K[0, i] = f[i]
    for s in range(1, _NS):
        for i in range(n):
            acc = 0.0
            for j in range(s):
                acc += _A[s, j] * K[j, i]
            ytmp[i] = y[i] + dt * acc
        _rhs(rough, h, ytmp, K[s])
    for i in range(n):
        acc = 0.0
        for j in range(_NS):
            acc += _B[j] * K[j, i]
        y_new[i] = y[i] + dt * acc
    _rhs(rough, h, y_new, f_new)
    for i in range(n):
        K[_NS, i] = f_new[i]


@numba.njit(cache=True)
def _dense_coefficients(rough, h, y, y_new, f_new, dt, K, ytmp, F):
    """Coefficients F of the DOP853 interpolant on an accepted step (t, y) -> (t + dt, y_new).

    ``K`` holds the stages of the step (rows 0 ... N_STAGES, as left by :func:`_step`); the
    3 extra stages go to its rows N_STAGES + 1 ... (3 right-hand-side evaluations).  The
    same formulas as scipy's ``DOP853._dense_output_impl`` (the right-hand side does not
    depend on t, so the extra nodes ``C_EXTRA`` do not enter).
    """
    n = y.shape[0]
    for s in range(_NS + 1, _NSX):
        for i in range(n):
            acc = 0.0
            for j in range(s):
                acc += _AX[s - _NS - 1, j] * K[j, i]
            ytmp[i] = y[i] + dt * acc
        _rhs(rough, h, ytmp, K[s])
    for i in range(n):
        dy = y_new[i] - y[i]
        F[0, i] = dy
        F[1, i] = dt * K[0, i] - dy
        F[2, i] = 2.0 * dy - dt * (f_new[i] + K[0, i])
        for r in range(_NF - 3):
            acc = 0.0
            for j in range(_NSX):
                acc += _D[r, j] * K[j, i]
            F[3 + r, i] = dt * acc


@numba.njit(cache=True)
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


@numba.njit(cache=True)
def _error_norm(y, y_new, K, dt, rtol, atol):
    n = y.shape[0]
    e5 = 0.0
    e3 = 0.0
    for i in range(n):
        a5 = 0.0
        a3 = 0.0
        for j in range(_NS + 1):
            a5 += _E5[j] * K[j, i]
            a3 += _E3[j] * K[j, i]
        sc = atol + rtol * max(abs(y[i]), abs(y_new[i]))
        e5 += (a5 / sc) ** 2
        e3 += (a3 / sc) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(dt) * e5 / np.sqrt((e5 + 0.01 * e3) * n)


@numba.njit(cache=True)
def _rms(v, scale):
    acc = 0.0
    for i in range(v.shape[0]):
        acc += (v[i] / scale[i]) ** 2
    return np.sqrt(acc / v.shape[0])


@numba.njit(cache=True)
def initial_step(rough, h, t0, y0, f0, t_bound, max_step, rtol, atol):
    """scipy's ``select_initial_step`` (Hairer, Norsett & Wanner, sec. II.4)."""
    n = y0.shape[0]
    interval = abs(t_bound - t0)
    if interval == 0.0:
        return 0.0
    scale = np.empty(n)
    for i in range(n):
        scale[i] = atol + abs(y0[i]) * rtol
    d0 = _rms(y0, scale)
    d1 = _rms(f0, scale)
    if d0 < 1e-5 or d1 < 1e-5:
        h0 = 1e-6
    else:
        h0 = 0.01 * d0 / d1
    h0 = min(h0, interval)
    y1 = y0 + h0 * f0
    f1 = np.empty(n)
    _rhs(rough, h, y1, f1)
    d2 = _rms(f1 - f0, scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 8.0)
    return min(100.0 * h0, h1, interval, max_step)


@numba.njit(cache=True)
def _fired(k, g_old, g_new):
    """True if guard k fired in the step from guard values g_old to g_new.

    theta (k = 1) fires when it reaches 0 or changes sign; the others when they reach 0.
    """
    if k == 1:
        return g_new[1] == 0.0 or (g_old[1] > 0.0) != (g_new[1] > 0.0)
    return g_new[k] <= 0.0


@numba.njit(cache=True)
def _triggered(g_old, g_new, use):
    """Index of a guard that fired in the step (first in order), or -1."""
    for k in range(3):
        if use[k] and _fired(k, g_old, g_new):
            return k
    return -1


@numba.njit(cache=True)
def _guard_value(k, g, sign1):
    # For the theta guard, measure in the direction of the sign theta had at the start.
    if k == 1:
        return g[1] * sign1
    return g[k]


@numba.njit(cache=True)
def _locate(rough, h, t, y, f, dt_hi, k, sign1, K, ytmp, y_try, f_try, g, xtol):
    """Illinois regula falsi for the root of guard k within (t, t + dt_hi].

    Returns (dt_root, n_rhs); y_try holds the state at dt_root, the admissible end of the
    final bracket (within xtol of the root), or the start state if the guard is not
    positive there.
    """
    n_rhs = 0
    a = 0.0
    _guards(rough, h, y, g)
    ga = _guard_value(k, g, sign1)
    b = dt_hi
    _step(rough, h, t, y, f, b, K, ytmp, y_try, f_try)
    n_rhs += _NS
    _guards(rough, h, y_try, g)
    gb = _guard_value(k, g, sign1)
    if ga > 0.0 and not (gb <= 0.0):
        return b, n_rhs  # nothing to bracket: the guard is positive at the end
    side = 0
    # (no bracket either when the guard is non-positive at the start: a = 0 below)
    for _ in range(200 if ga > 0.0 else 0):
        if abs(b - a) <= xtol:
            break
        c = (a * gb - b * ga) / (gb - ga)
        if not (a < c < b):
            c = 0.5 * (a + b)
        _step(rough, h, t, y, f, c, K, ytmp, y_try, f_try)
        n_rhs += _NS
        _guards(rough, h, y_try, g)
        gc = _guard_value(k, g, sign1)
        if gc > 0.0:
            a, ga = c, gc
            if side == -1:
                gb *= 0.5
            side = -1
        else:
            b, gb = c, gc
            if side == 1:
                ga *= 0.5
            side = 1
    # report the last admissible point, the bracket's lower end a (guard > 0 there, within
    # xtol of the root): the state before the event, where the model still holds
    if a == 0.0:
        for i in range(y.shape[0]):
            y_try[i] = y[i]
    else:
        _step(rough, h, t, y, f, a, K, ytmp, y_try, f_try)
        n_rhs += _NS
    return a, n_rhs


@numba.njit(cache=True)
def integrate(rough, h, t0, y0, t_end, t_pause, rtol, atol, max_step, first_step, use_guards,
              t_eval, has_t_eval, max_steps):
    """Integrate from (t0, y0) to t_end, stopping at the first guard event.

    Pauses (status RUNNING) after the first accepted step that reaches ``t_pause < t_end``;
    steps are never shortened to land on ``t_pause``, so a run continued from the returned
    ``(t_last, y_last)`` with ``first_step = h_next`` takes the very steps of an
    uninterrupted run.

    Returns ``(ts, ys, n_steps, n_rhs, status, event, h_next, t_last, y_last)`` where
    ``ts, ys`` are the accepted steps (or the values at ``t_eval``) followed by the event
    point if one fired, ``status`` one of the codes above, ``event`` the index of the
    guard that fired or -1, ``h_next`` the step size to try next and ``(t_last, y_last)``
    the end of the last accepted step.
    """
    n = y0.shape[0]
    K = np.empty((_NSX, n))
    F = np.empty((_NF, n))
    ytmp = np.empty(n)
    y = y0.copy()
    f = np.empty(n)
    y_new = np.empty(n)
    f_new = np.empty(n)
    y_try = np.empty(n)
    f_try = np.empty(n)
    g_old = np.empty(3)
    g_new = np.empty(3)
    g_tmp = np.empty(3)

    cap = 1024 if not has_t_eval else t_eval.shape[0] + 2
    ts = np.empty(cap)
    ys = np.empty((cap, n))
    m = 0
    ie = 0  # next t_eval index
    if not has_t_eval:
        ts[0] = t0
        ys[0] = y
        m = 1
    else:
        while ie < t_eval.shape[0] and t_eval[ie] <= t0:
            ts[m] = t0
            ys[m] = y
            m += 1
            ie += 1

    n_rhs = 0
    n_steps = 0
    t = t0
    _guards(rough, h, y, g_old)
    # a guard already violated at the start
    for k in range(3):
        if use_guards[k] and k != 1 and g_old[k] <= 0.0:
            if has_t_eval:
                ts[m] = t
                ys[m] = y
                m += 1
            return (ts[:m], ys[:m], n_steps, n_rhs, LIFT_OFF if k == 0 else FELL_FLAT, k,
                    0.0, t, y)
    sign1 = 1.0 if g_old[1] > 0.0 else -1.0
    _rhs(rough, h, y, f)
    n_rhs += 1

    if first_step > 0.0:
        h_abs = first_step
    else:
        h_abs = initial_step(rough, h, t0, y, f, t_end, max_step, rtol, atol)
        n_rhs += 1
    status = RUNNING
    event = -1
    while status == RUNNING:
        if t >= t_end:
            status = COMPLETED
            break
        if n_steps >= max_steps:
            status = FAILED
            break
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        if h_abs > max_step:
            h_abs = max_step
        if h_abs < min_step:
            h_abs = min_step
        rejected = False
        accepted = False
        while not accepted:
            if h_abs < min_step:
                status = FAILED
                break
            dt = h_abs
            t_new = t + dt
            if t_new > t_end:
                t_new = t_end
            dt = t_new - t
            h_abs = abs(dt)
            _step(rough, h, t, y, f, dt, K, ytmp, y_new, f_new)
            n_rhs += _NS
            finite = True
            for i in range(n):
                if not np.isfinite(y_new[i]):
                    finite = False
            err = _error_norm(y, y_new, K, dt, rtol, atol) if finite else np.inf
            if err < 1.0:
                if err == 0.0:
                    factor = _MAX_FACTOR
                else:
                    factor = min(_MAX_FACTOR, _SAFETY * err ** _ERR_EXP)
                if rejected:
                    factor = min(1.0, factor)
                h_next = h_abs * factor
                accepted = True
            else:
                if finite:
                    h_abs *= max(_MIN_FACTOR, _SAFETY * err ** _ERR_EXP)
                else:
                    h_abs *= _MIN_FACTOR
                rejected = True
        if status == FAILED:
            break
        n_steps += 1
        # dense output of the whole step (needed unless the next requested time is its
        # end), computed before event location reuses K and y_new
        dense = has_t_eval and ie < t_eval.shape[0] and t_eval[ie] < t_new
        if dense:
            _dense_coefficients(rough, h, y, y_new, f_new, dt, K, ytmp, F)
            n_rhs += _NSX - _NS - 1
        _guards(rough, h, y_new, g_new)
        k = _triggered(g_old, g_new, use_guards)
        t_stop = t_new
        if k >= 0:
            # locate the earliest guard root in this step
            best = dt
            kbest = -1
            for kk in range(3):
                if not (use_guards[kk] and _fired(kk, g_old, g_new)):
                    continue
                xtol = 4.0 * abs(np.nextafter(t + dt, np.inf) - (t + dt))
                dtk, nr = _locate(rough, h, t, y, f, dt, kk, sign1, K, ytmp, y_try, f_try,
                                  g_tmp, xtol)
                n_rhs += nr
                if kbest == -1 or dtk < best:
                    best = dtk
                    kbest = kk
                    for i in range(n):
                        y_new[i] = y_try[i]
            event = kbest
            t_stop = t + best
            if event == 0:
                status = LIFT_OFF
            elif event == 1:
                status = EDGE_CONTACT
            else:
                status = FELL_FLAT
        # output
        if has_t_eval:
            while ie < t_eval.shape[0] and t_eval[ie] <= t_stop:
                if t_eval[ie] == t_stop:
                    ys[m] = y_new
                else:
                    _dense_value(y, F, (t_eval[ie] - t) / dt, y_try)
                    ys[m] = y_try
                ts[m] = t_eval[ie]
                m += 1
                ie += 1
            if status != RUNNING and (m == 0 or ts[m - 1] != t_stop):
                ts[m] = t_stop
                ys[m] = y_new
                m += 1
        else:
            if m == cap:
                cap *= 2
                ts2 = np.empty(cap)
                ys2 = np.empty((cap, n))
                ts2[:m] = ts[:m]
                ys2[:m] = ys[:m]
                ts = ts2
                ys = ys2
            ts[m] = t_stop
            ys[m] = y_new
            m += 1
        if status != RUNNING:
            break
        t = t_new
        for i in range(n):
            y[i] = y_new[i]
            f[i] = f_new[i]
        for i in range(3):
            g_old[i] = g_new[i]
        h_abs = h_next
        if t_pause <= t < t_end:
            break  # paused, status RUNNING
    return ts[:m], ys[:m], n_steps, n_rhs, status, event, h_abs, t, y


# ------------------------------------------------------------------ stale-cache guard
_DISPATCHERS = ("_geometry", "_rough_omega_dot", "_smooth_omega_dot", "_rough_rhs",
                "_smooth_rhs", "_reduced_state", "_reduced_rhs", "_rhs", "_normal_force",
                "_guards", "_step",
                "_dense_coefficients", "_dense_value", "_error_norm", "_rms", "initial_step",
                "_fired", "_triggered", "_guard_value", "_locate", "integrate")


def rhs_matches_kernels() -> bool:
    """True if the compiled right-hand side and normal force agree with equations.py.

    numba's on-disk cache of a function does not notice a change in the functions it calls
    (here: a kernel edited in equations.py would leave ``_rhs`` and ``integrate`` running
    the old formula).  This probe catches that.
    """
    rng = np.random.default_rng(12345)
    for rough, n, kernel in ((True, 8, _eq._rough_rhs), (False, 10, _eq._smooth_rhs)):
        for h in (0.0, 0.37):
            for _ in range(3):
                y = rng.uniform(-1.0, 1.0, n)
                out = np.empty(n)
                _rhs(rough, h, y, out)
                ref = np.array(kernel(h, y), dtype=float)
                if not np.allclose(out, ref, rtol=1e-12, atol=1e-12):
                    return False
                if not np.isclose(_normal_force(rough, h, y), _eq._normal_force(rough, h, y),
                                  rtol=1e-12, atol=1e-12):
                    return False
                x = y[:4].copy()
                out4 = np.empty(4)
                _rhs(rough, h, x, out4)
                if not np.allclose(out4, np.array(_eq._reduced_rhs(rough, h, x)), rtol=1e-12,
                                   atol=1e-12):
                    return False
    return True


def recompile_all() -> None:
    """Recompile every compiled function from the current sources (refreshing the cache)."""
    g = globals()
    for name in _DISPATCHERS:
        d = g[name]
        if d.signatures:
            d.recompile()
