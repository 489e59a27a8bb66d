"""The contact phase of :func:`rollingdisk.simulate_coulomb` in one compiled loop.

:func:`advance` takes accepted DOP853 steps in one Coulomb mode (rolling or sliding, pivot
free or stuck, rolling resistance free or stuck, :mod:`rollingdisk.model.coulomb`) with
the step-size control of :func:`rollingdisk.engine.dop853.integrate` (scipy's), and
after each step evaluates the six event functions of
:meth:`rollingdisk.ivp.coulomb_modes._Run.events` -- mode end, pivot, lift-off ``F_z``
(eq. 11), edge contact ``theta side``, fell flat ``pi/2 - |theta| - alpha_min``, roll --
on the step's dense output at the 9 points the hybrid driver samples
(:func:`rollingdisk.ivp.coulomb_modes._first_event`).  Steps where none crosses from ``> 0``
to ``<= 0`` are stored and the loop goes on (in sliding the slip reference is updated as
:meth:`rollingdisk.ivp.coulomb_driver._Hybrid._accept` does); at a step where one does, the
loop returns that step (start, length, dense coefficients) and the Python driver locates
the event on it (``brentq``) and handles the transition as before.

Everything here is plain Python on numpy arrays and floats.  :func:`namespace` re-binds
these functions, the Coulomb kernels (eqs. 6, 8, 9, 11, 37, the stuck sub-modes) and the
DOP853 building blocks of :mod:`rollingdisk.engine.dop853` to one namespace, in which
DOP853's ``_rhs(rough, h, y, out)`` is this module's :func:`_rhs` with ``rough`` the
parameter array ``p`` below; :func:`compiled` hands that namespace to
:func:`rollingdisk.engine.compile.compile_namespace` (numba, cached on disk), and
:func:`namespace` ``(compiled=False)`` runs the very same functions uncompiled (slow; for
checks).

State: 14 components, the 10 Coulomb state components and the 4 dissipated energies
(slip, rolling resistance, pivot, air; eq. 12).  Parameters ``p`` (float64 array, see
:data:`P_FIELDS`): the mode code, ``mu_k, mu_s``, the moment coefficients, the inertial slip
reference ``ref`` (updated in place by :func:`advance` in sliding), ``u_eps``, the pivot
sign ``sz``, the side ``sgn(theta)`` of the segment, ``alpha_min``, and the inertial
reference ``rref`` of the rolling resistance (updated in place by :func:`advance` to
``omega_h/|omega_h|`` while it is free) with its ``w_eps``.
"""

from __future__ import annotations

import math
import time
import types

import numpy as np

from rollingdisk.engine import dop853 as _dop
from rollingdisk.engine.roots import (
    illinois_converged as _illinois_converged,
)
from rollingdisk.engine.roots import (
    illinois_trial as _illinois_trial,
)
from rollingdisk.engine.roots import (
    illinois_update as _illinois_update,
)
from rollingdisk.model import coulomb as _cl

#: Fields of the parameter array ``p`` of :func:`_rhs` and :func:`advance`, in order.
P_FIELDS = ("mode", "mu_k", "mu_s", "c_roll", "c_pivot", "c_air", "ref_X", "ref_Y", "u_eps",
            "sz", "side", "alpha_min", "rref_X", "rref_Y", "w_eps", "u_qs", "arm_floor",
            "arm_u_eps")
_NP = len(P_FIELDS)
_NP_BASE = 16  # a shorter p (the first 16 fields) never arms: see advance
N_STATE = 14
N_EVENTS = 6
_N_SUB = 8  # the dense output sampled at j/8 of a step, j = 1..8 (9 points with the start)
#: Status codes of :func:`advance` (``RUNNING``: paused, call again).
RUNNING, COMPLETED, EVENT, FAILED, SINGULAR = 0, 1, 2, 3, 4


# ------------------------------------------------------------------ right-hand side, events
def _cc_solve(p, h, y):
    """The mode ``p[0]``'s kernel at ``y``: ``(dy[0:10], P_slip, P_roll, P_pivot, P_air,
    F_x, F_y, F_z, M_piv, M_hx, M_hy)`` (as :meth:`rollingdisk.ivp.coulomb_modes._Run.solve`)."""
    mode = int(p[0])
    sz = p[9]
    if mode & 2:
        sz = 0.0
    rs = (mode & 4) != 0
    if mode & 1 == 0:
        d, F_x, F_y, F_z, P1, P2, P3, L, Lx, Ly = _coulomb_rolling_full(  # noqa: F821
            h, p[3], p[4], p[5], y, sz, p[12], p[13], p[14], rs)
        P0 = 0.0
    else:
        ref_X, ref_Y, u_eps = p[6], p[7], p[8]
        if p[15] > 0.0:
            ref_X, ref_Y, u_eps = _quasi_static_ref(p, h, y, sz)
        d, F_x, F_y, F_z, P0, P1, P2, P3, L, Lx, Ly = _coulomb_sliding_full(  # noqa: F821
            h, p[1], p[3], p[4], p[5], y, ref_X, ref_Y, u_eps, sz, p[12], p[13], p[14], rs)
    return d, P0, P1, P2, P3, F_x, F_y, F_z, L, Lx, Ly


def _quasi_static_ref(p, h, y, sz):
    """``(ref_X, ref_Y, u_eps)`` for the sliding kernel with the quasi-static slip
    direction (``p[15] = u_qs > 0``): below ``|u| = u_qs`` the friction direction is that of
    ``sgn(u . e*) u + (u_qs - |u|) e*`` (:func:`rollingdisk.model.coulomb.
    _friction_direction` with ``ref = e*``, ``u_eps = u_qs``), ``e*`` the direction in which
    the slip accelerates along itself, ``e* x du/dt(e*) = 0`` (the fixed point the slip's
    direction relaxes to at the rate ``mu g/|u|``; :func:`slip_scan`), found by Newton's
    method on its angle from the slip's (or ``ref``'s) direction.  Above ``u_qs``: ``p``'s
    own ``ref``, ``u_eps``."""
    u_x, u_y = _slip_velocity(h, y)  # noqa: F821 - namespace
    n = math.sqrt(u_x * u_x + u_y * u_y)
    if n >= p[15]:
        return p[6], p[7], p[8]
    cp = math.cos(y[4])
    sp = math.sin(y[4])
    r_x = p[6] * cp + p[7] * sp  # ref in Cxyz
    r_y = -p[6] * sp + p[7] * cp
    if n > 0.0 and u_x * r_x + u_y * r_y >= 0.0:  # Newton from the slip's direction
        a = math.atan2(u_y, u_x)
    else:
        a = math.atan2(r_y, r_x)
    for _ in range(8):
        f0 = _slip_parts(h, p[1], p[3], p[4], p[5], y, sz, False, a)[0]
        f1 = _slip_parts(h, p[1], p[3], p[4], p[5], y, sz, False, a + 1e-7)[0]
        if f1 == f0:
            break
        da = -f0 * 1e-7 / (f1 - f0)
        a += da
        if abs(da) < 1e-13:
            break
    e_x = math.cos(a)
    e_y = math.sin(a)
    return e_x * cp - e_y * sp, e_x * sp + e_y * cp, p[15]


def _rhs(p, h, y, out):
    """``dz/dt`` (14 components: eqs. 1, 2, 8, 9 and ``-P`` of each dissipation term) into
    ``out``, in the mode and with the parameters ``p``."""
    d, P0, P1, P2, P3, F_x, F_y, F_z, L, Lx, Ly = _cc_solve(p, h, y)
    for i in range(10):
        out[i] = d[i]
    out[10] = -P0
    out[11] = -P1
    out[12] = -P2
    out[13] = -P3


def _rhs_col(p, h, y, K, s):
    """:func:`_rhs` into column ``s`` of the stage array ``K``."""
    d, P0, P1, P2, P3, F_x, F_y, F_z, L, Lx, Ly = _cc_solve(p, h, y)
    for i in range(10):
        K[i, s] = d[i]
    K[10, s] = -P0
    K[11, s] = -P1
    K[12, s] = -P2
    K[13, s] = -P3


def _cc_events(p, h, y, g):
    """The event functions of :meth:`rollingdisk.ivp.coulomb_modes._Run.events` into ``g``
    (6), each crossing from ``> 0`` to ``<= 0``: mode end (rolling: ``mu_s F_z - |F_t|``;
    sliding: ``U . ref``), pivot (``sz omega_z``, or ``c F_z - |M_piv|`` while stuck),
    ``F_z``, ``theta side`` (1 for ``h = 0``), ``pi/2 - |theta| - alpha_min``, roll
    (``omega_h . rref``, inertial, or ``c F_z - |M_h|`` while stuck)."""
    d, P0, P1, P2, P3, F_x, F_y, F_z, L, Lx, Ly = _cc_solve(p, h, y)
    mode = int(p[0])
    if mode & 1 == 0:
        g[0] = p[2] * F_z - math.hypot(F_x, F_y)
    else:
        u_x, u_y = _slip_velocity(h, y)  # noqa: F821 - namespace
        U_X, U_Y = _to_inertial(y[4], u_x, u_y)  # noqa: F821
        g[0] = U_X * p[6] + U_Y * p[7]
    theta = y[5]
    if mode & 2:
        g[1] = p[4] * F_z - abs(L)
    else:
        g[1] = p[9] * _omega_z(theta, y[8], y[9])  # noqa: F821
    g[2] = F_z
    g[3] = theta * p[10] if h > 0 else 1.0
    g[4] = 0.5 * math.pi - abs(theta) - p[11]
    if mode & 4:
        g[5] = p[3] * F_z - math.hypot(Lx, Ly)
    else:
        W_X, W_Y = _to_inertial(y[4], y[7], y[8] * math.cos(theta)  # noqa: F821
                                - y[9] * math.sin(theta))
        g[5] = W_X * p[12] + W_Y * p[13]


def _all_finite(a, n, c0, c1):
    """Whether the columns ``c0 <= j < c1`` of ``a[:n]`` are all finite."""
    for i in range(n):
        for j in range(c0, c1):
            if not np.isfinite(a[i, j]):
                return False
    return True


def _vec_finite(v):
    for i in range(v.shape[0]):
        if not np.isfinite(v[i]):
            return False
    return True


# ------------------------------------------------------------------ the loop
# Why one long function: the hot loop, compiled by numba in nopython mode (no closures, no
# objects, no exceptions for control flow), as rollingdisk.engine.dop853.integrate.
def advance(p, h, t, y0, t_end, dt_try, rtol, atolv, max_step, max_steps, active, ts, zs):
    """Accepted DOP853 steps in one mode from ``(t, y0)`` until an event may fire in a step.

    Parameters
    ----------
    p : ndarray, shape (18,) or (16,)
        Parameters (:data:`P_FIELDS`); in sliding ``ref`` (``p[6:8]``) is set to ``U/|U|``
        after every stored step where ``|U| > u_eps``, with rolling resistance on and free
        ``rref`` (``p[12:14]``) to ``omega_h/|omega_h|`` where ``|omega_h| > w_eps`` (as the
        Python driver does).  While event 0 is inactive and ``arm_floor`` (``p[16]``) is
        ``> 0`` (a slip started from rest, not yet armed), a stored step with ``|U| >
        arm_floor`` arms it: ``active[0]`` becomes True, ``u_eps`` becomes ``arm_u_eps``
        and ``arm_floor`` 0, and the loop goes on as a new call from that step would
        (the Python driver once took one step a call to make that check).
    h : float
        Half-thickness of the disk (units of the radius ``a``).
    t, y0 : float, ndarray (14,)
        Start.
    t_end : float
        End of the run.
    dt_try : float
        Step size to try first; ``<= 0``: scipy's initial step (a new segment).
    rtol : float
    atolv : ndarray (14,)
        Tolerances.
    max_step : float
    max_steps : int
        Most steps taken in this call (the run's remaining step budget).
    active : ndarray of bool, shape (6,)
        Which event functions count.
    ts, zs : ndarray, shapes (cap,), (cap, 14)
        Output: the stored steps; the call pauses when they are full.

    Returns
    -------
    tuple
        ``(status, m, n_steps, n_rhs, t, y, dt_next, t_new, dt, y_new, F)``: status
        (``RUNNING``: paused, full output or ``max_steps``; ``COMPLETED``: ``t_end``
        reached; ``EVENT``: an event function changed sign in the step ``(t, t_new)``,
        of length ``dt``, end ``y_new``, dense coefficients ``F``, not stored; ``FAILED``:
        the step size fell below round-off; ``SINGULAR``: a non-finite right-hand side in
        the step from ``(t, y)``), ``m`` steps stored, the steps and right-hand sides
        taken, the last accepted ``(t, y)``, the step size to try next.
    """
    n = y0.shape[0]
    K = np.empty((n, _NSX))  # noqa: F821 - namespace (dop853 constants)
    F = np.zeros((_NF, n))  # noqa: F821
    ytmp = np.empty(n)
    ys = np.empty(n)
    y = y0.copy()
    f = np.empty(n)
    y_new = y0.copy()
    f_new = np.empty(n)
    g_old = np.empty(N_EVENTS)
    g_prev = np.empty(N_EVENTS)
    g = np.empty(N_EVENTS)
    cap = ts.shape[0]
    m = 0
    n_steps = 0
    if t >= t_end:
        return COMPLETED, m, n_steps, 0, t, y, dt_try, t, 0.0, y_new, F
    n_rhs = 1
    _rhs(p, h, y, f)
    status = RUNNING
    if not _vec_finite(f):
        return SINGULAR, m, n_steps, n_rhs, t, y, 0.0, t, 0.0, y_new, F
    dt_abs = dt_try
    if not dt_abs > 0.0:
        dt_abs = initial_step_v(p, h, t, y, f, t_end, max_step, rtol, atolv)  # noqa: F821
        n_rhs += 1
    if not (dt_abs > 0.0) or not np.isfinite(dt_abs):
        return FAILED, m, n_steps, n_rhs, t, y, 0.0, t, 0.0, y_new, F
    _cc_events(p, h, y, g_old)
    t_new = t
    dt = 0.0
    h_next = dt_abs
    sliding = int(p[0]) & 1 == 1
    roll_free = p[3] > 0.0 and (int(p[0]) & 4) == 0
    while status == RUNNING:
        if t >= t_end:
            status = COMPLETED
            break
        if n_steps >= max_steps or m >= cap:
            break  # paused
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
            t_new = t + dt_abs
            if t_new > t_end:
                t_new = t_end
            dt = t_new - t
            dt_abs = abs(dt)
            if not dt > 0.0:
                status = FAILED
                break
            _step(p, h, t, y, f, dt, K, ytmp, y_new, f_new)  # noqa: F821
            n_rhs += _NS  # noqa: F821
            if not (_all_finite(K, n, 0, _NS + 1) and _vec_finite(y_new)):  # noqa: F821
                status = SINGULAR
                break
            err = _error_norm_v(y, y_new, K, dt, rtol, atolv)  # noqa: F821
            if err < 1.0:
                h_next = dt_abs * _step_factor(err, rejected)  # noqa: F821
                accepted = True
            else:
                dt_abs *= _step_factor(err, rejected)  # noqa: F821
                rejected = True
        if status != RUNNING:
            break
        n_steps += 1
        _dense_coefficients(p, h, y, y_new, f_new, dt, K, ytmp, F)  # noqa: F821
        n_rhs += _NSX - _NS - 1  # noqa: F821
        if not _all_finite(K, n, _NS + 1, _NSX):  # noqa: F821
            status = SINGULAR
            break
        for k in range(N_EVENTS):
            g_prev[k] = g_old[k]
        hit = False
        for j in range(1, _N_SUB + 1):
            _dense_value(y, F, j / _N_SUB, ys)  # noqa: F821
            _cc_events(p, h, ys, g)
            for k in range(N_EVENTS):
                if active[k] and g_prev[k] > 0.0 and g[k] <= 0.0:
                    hit = True
                g_prev[k] = g[k]
            if hit:
                break
        if hit:
            status = EVENT
            dt_abs = h_next
            break
        t = t_new
        for i in range(n):
            y[i] = y_new[i]
            f[i] = f_new[i]
        ts[m] = t
        zs[m] = y
        m += 1
        if sliding:
            u_x, u_y = _slip_velocity(h, y)  # noqa: F821
            U_X, U_Y = _to_inertial(y[4], u_x, u_y)  # noqa: F821
            nu = math.hypot(U_X, U_Y)
            if nu > p[8]:
                p[6] = U_X / nu
                p[7] = U_Y / nu
        if roll_free:
            W_X, W_Y = _to_inertial(y[4], y[7], y[8] * math.cos(y[5])  # noqa: F821
                                    - y[9] * math.sin(y[5]))
            nw = math.hypot(W_X, W_Y)
            if nw > p[14]:
                p[12] = W_X / nw
                p[13] = W_Y / nw
        if not active[0] and p.shape[0] > _NP_BASE and p[16] > 0.0:
            # a slip started from u = 0 passes its floor (coulomb_driver._Hybrid._arms):
            # its end counts from here on, the friction follows u/|u| above arm_u_eps;
            # the step goes on as a new call would, from f and events at the new p
            u_x, u_y = _slip_velocity(h, y)  # noqa: F821
            U_X, U_Y = _to_inertial(y[4], u_x, u_y)  # noqa: F821
            if math.hypot(U_X, U_Y) > p[16]:
                active[0] = True
                p[16] = 0.0
                p[8] = p[17]
                _rhs(p, h, y, f)
                n_rhs += 1
        _cc_events(p, h, y, g_old)
        dt_abs = h_next
    return status, m, n_steps, n_rhs, t, y, dt_abs, t_new, dt, y_new, F


# ------------------------------------------------------------------ slip direction
def _slip_accel_c(h, mu_k, c_roll, c_pivot, c_air, y, e_x, e_y, sz, sz_free):
    """:func:`rollingdisk.ivp.hybrid._slip_accel` in compilable form (``sz_free``:
    the pivot moment of :func:`_coulomb_moments` with ``sgn omega_z``, else the pivot
    state ``sz``, 0 stuck): the slip acceleration ``du/dt`` (Cxyz) at ``u = 0`` sliding
    with friction ``-mu_k F_z e``."""
    theta, w1, w2, w3 = y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)  # noqa: F821 - namespace
    if sz_free:
        M0x, M0y, M0z, M1x, M1y, M1z = _coulomb_moments(  # noqa: F821
            c_roll, c_pivot, c_air, theta, w1, w2, w3)
        d1, d2, d3, F_x, F_y, F_z = _sliding_solve(  # noqa: F821
            h, mu_k, e_x, e_y, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z)
    else:
        M0x, M0y, M0z, M1x, M1y, M1z = _pivot_moments(  # noqa: F821
            c_roll, c_pivot, c_air, theta, w1, w2, w3, sz)
        if sz == 0.0:
            d1, d2, d3, F_x, F_y, F_z, _L = _sliding_stuck_solve(  # noqa: F821
                h, mu_k, e_x, e_y, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z)
        else:
            d1, d2, d3, F_x, F_y, F_z = _sliding_solve(  # noqa: F821
                h, mu_k, e_x, e_y, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z)
    Om = w3 / c
    v_Cx = w2 - ht * w3  # u = 0
    v_Cy = w1 * z_P
    dv_Cx = F_x + v_Cy * Om  # eq. (8)_1
    dv_Cy = F_y - v_Cx * Om  # eq. (8)_2
    return dv_Cx - d2 + ht * d3, dv_Cy - d1 * z_P - w1 * w1 * y_P


def _slip_parts(h, mu_k, c_roll, c_pivot, c_air, y, sz, sz_free, a):
    """``(d x du/dt, d . du/dt)`` for the slip direction ``d = (cos a, sin a)``."""
    ex = np.cos(a)
    ey = np.sin(a)
    ax, ay = _slip_accel_c(h, mu_k, c_roll, c_pivot, c_air, y, ex, ey, sz, sz_free)
    return ex * ay - ey * ax, ex * ax + ey * ay


def slip_scan(h, mu_k, c_roll, c_pivot, c_air, y, sz, sz_free, n_grid):
    """The angle of the slip direction of
    :func:`rollingdisk.ivp.hybrid.slip_direction`: the grid of ``n_grid`` angles on
    ``[0, 2 pi]`` scanned for sign changes of ``d x du/dt``, each root refined to round-off
    (bisection), and among the roots with ``d . du/dt > 0`` the one of largest slip
    acceleration; ``nan`` if there is none."""
    best_a = np.nan
    best_along = 0.0
    two_pi = 2.0 * np.pi
    a0 = 0.0
    f0 = _slip_parts(h, mu_k, c_roll, c_pivot, c_air, y, sz, sz_free, a0)[0]
    for i in range(n_grid - 1):
        a1 = two_pi * (i + 1) / (n_grid - 1)
        f1 = _slip_parts(h, mu_k, c_roll, c_pivot, c_air, y, sz, sz_free, a1)[0]
        root = np.nan
        if f0 == 0.0:
            root = a0
        elif f0 * f1 < 0.0:
            lo, hi, flo = a0, a1, f0
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if not (lo < mid < hi):
                    break
                fm = _slip_parts(h, mu_k, c_roll, c_pivot, c_air, y, sz, sz_free, mid)[0]
                if fm == 0.0:
                    lo = mid
                    hi = mid
                    break
                if (fm > 0.0) == (flo > 0.0):
                    lo, flo = mid, fm
                else:
                    hi = mid
            root = 0.5 * (lo + hi)
        if root == root:
            along = _slip_parts(h, mu_k, c_roll, c_pivot, c_air, y, sz, sz_free, root)[1]
            if along > 0.0 and (best_a != best_a or along > best_along):
                best_a = root
                best_along = along
        a0 = a1
        f0 = f1
    return best_a


# ------------------------------------------------------------------ touchdown
def _flight_height(Z0, VZ0, par, per, crs, Om_p, h, t):
    """Height of the lowest point of the freely flying disk at ``t``
    (:func:`rollingdisk.phases.flight.touchdown_time`: the axis precesses uniformly)."""
    ez = par + per * math.cos(Om_p * t) + crs * math.sin(Om_p * t)
    ez = min(1.0, max(-1.0, ez))
    return Z0 + VZ0 * t - 0.5 * t * t - math.sqrt(1.0 - ez * ez) - h * abs(ez)


def touchdown_scan(Z0, VZ0, par, per, crs, Om_p, h, t, Ht):
    """The conservative advancement of :func:`rollingdisk.phases.flight.touchdown_time`
    from ``t`` (height ``Ht > 0``), compiled; a bracketed root is refined by the Illinois
    rule (:mod:`rollingdisk.engine.roots`) to round-off.  ``-1`` if no bracket is found
    in 100000 advances (a grazing flight: the caller scans a grid).  Plain Python too: the
    one advancement of :func:`~rollingdisk.phases.flight.touchdown_time`, compiled or not."""
    spin = Om_p * (1.0 + h)
    for _ in range(100000):
        B = max(0.0, -(VZ0 - t)) + spin
        tau = -B + np.sqrt(B * B + 2.0 * Ht)
        if tau <= 4e-16 * max(t, 1.0):
            return t
        probe = t + 2.0 * tau
        Hp = _flight_height(Z0, VZ0, par, per, crs, Om_p, h, probe)
        if Hp <= 0.0:
            xa = t + tau
            fa = _flight_height(Z0, VZ0, par, per, crs, Om_p, h, xa)
            if fa <= 0.0:
                return xa
            xb = probe
            fb = Hp
            flag = 0
            for _k in range(200):
                if _illinois_converged(xa, xb):
                    break
                xc = _illinois_trial(xa, xb, fa, fb)
                fc = _flight_height(Z0, VZ0, par, per, crs, Om_p, h, xc)
                xa, xb, fa, fb, flag = _illinois_update(xa, xb, fa, fb, xc, fc,
                                                        flag)
            return xb if fb == 0.0 else 0.5 * (xa + xb)
        t += tau
        Ht = _flight_height(Z0, VZ0, par, per, crs, Om_p, h, t)
        if Ht <= 0.0:
            return t
    return -1.0


# ------------------------------------------------------------------ namespaces
#: The functions of the namespace, callees before callers: the Coulomb kernels, this
#: module's right-hand side and events, DOP853's building blocks, the loop.
_KERNELS = ("_inertia", "_geometry", "_coulomb_moments", "_coulomb_powers", "_omega_z",
            "_rolling_solve", "_sliding_solve", "_stuck_correction", "_rolling_stuck_solve",
            "_sliding_stuck_solve", "_pivot_moments", "_slip_velocity", "_to_inertial",
            "_friction_direction", "_roll_direction", "_mode_moments", "_hold_h",
            "_rolling_response", "_rolling_roll_stuck_solve", "_sliding_roll_stuck_solve",
            "_coulomb_rolling_full", "_coulomb_sliding_full")
_OWN = ("_slip_accel_c", "_slip_parts", "_quasi_static_ref", "_cc_solve", "_rhs", "_rhs_col",
        "_cc_events", "_all_finite", "_vec_finite")
_DOP = ("_combine", "_step", "_dense_tail", "_dense_coefficients", "_dense_value",
        "_error_norm_v", "_step_factor", "_rms", "_initial_step_scaled", "initial_step_v")
_ROOTS = ("_illinois_converged", "_illinois_trial", "_illinois_update")
NAMES = (_KERNELS + _OWN + _DOP + _ROOTS
         + ("advance", "slip_scan", "_flight_height",
            "touchdown_scan"))

_compiled = None
_compile_time = None


def namespace(compiled: bool = False) -> dict:
    """A namespace holding :data:`NAMES` re-bound to it (DOP853's ``_rhs`` is this
    module's): uncompiled, or compiled with numba (:func:`compiled`)."""
    ns = {**_dop.__dict__, **_cl.__dict__, **globals()}
    if compiled:
        import rollingdisk.engine
        import rollingdisk.ivp
        import rollingdisk.model
        from rollingdisk.engine.compile import compile_namespace, source_key

        key = source_key(rollingdisk.model, rollingdisk.engine, rollingdisk.ivp)
        return compile_namespace(ns, NAMES, key=key)
    for name in NAMES:
        f = ns[name]
        ns[name] = types.FunctionType(f.__code__, ns, f.__name__, f.__defaults__,
                                      f.__closure__)
    return ns


def available() -> bool:
    """Whether the compiled loop can be had (numba importable)."""
    from rollingdisk.engine.compile import numba_available

    return numba_available()


def loaded() -> bool:
    """Whether the compiled loop is loaded in this process."""
    return _compiled is not None


def _probe_states():
    """A few states, parameters and step sizes exercising every mode (for the stale-cache
    probe): ``(p, h, y)``."""
    rng = np.random.default_rng(2024)
    out = []
    for mode in range(8):
        h = 0.0 if mode == 0 else 0.2
        y = np.zeros(N_STATE)
        y[2:4] = rng.uniform(-0.3, 0.3, 2)
        y[4] = rng.uniform(-1.0, 1.0)
        y[5] = 0.4 + 0.2 * rng.uniform()
        y[7:10] = rng.uniform(-1.0, 1.0, 3)
        p = np.array([float(mode), 0.4, 0.5, 0.01, 0.02, 0.003, 0.6, 0.8, 1e-8, -1.0, 1.0,
                      1e-8, -0.8, 0.6, 1e-8, 0.0, 1e-6, 1e-8])  # sliding modes arm
        out.append((p, h, y))
    return out


def matches_python(ns) -> bool:
    """True if the compiled loop takes the steps the uncompiled one takes (to 1e-10).

    numba's on-disk cache of a function does not notice an edit of a function it calls in
    another file (a Coulomb kernel, a DOP853 building block): this probe catches that, by
    running 3 steps in each mode both ways."""
    py = namespace(compiled=False)
    atolv = np.full(N_STATE, 1e-12)
    active = np.zeros(N_EVENTS, dtype=np.bool_)
    for p, h, y in _probe_states():
        res = []
        for space in (ns, py):
            ts = np.empty(3)
            zs = np.empty((3, N_STATE))
            r = space["advance"](p.copy(), h, 0.0, y, 1.0, 0.0, 1e-9, atolv, np.inf, 3,
                                 active.copy(), ts, zs)
            res.append((r[2], ts.copy(), zs.copy()))
        (n1, t1, z1), (n2, t2, z2) = res
        if n1 != n2 or not np.allclose(t1, t2, rtol=1e-10, atol=1e-14) or not np.allclose(
                z1, z2, rtol=1e-10, atol=1e-12):
            return False
    return True


def _marker():
    """The file whose presence says numba's cache holds this loop for these sources (named
    as the compiled functions are: :func:`rollingdisk.engine.compile.marker_key`)."""
    import rollingdisk.engine
    import rollingdisk.ivp
    import rollingdisk.model
    from rollingdisk.engine import jit as _jit
    from rollingdisk.engine.compile import marker_key

    key = marker_key(rollingdisk.model, rollingdisk.engine, rollingdisk.ivp)
    return _jit.cache_folder() / f"rollingdisk-coulomb-{key}.ready"


def cache_ready() -> bool:
    """Whether the compiled loop loads from numba's on-disk cache (no compiling)."""
    try:
        return _marker().exists()
    except OSError:
        return False


def _mark_ready():
    from rollingdisk.engine.compile import write_marker

    try:
        write_marker(_marker(), "numba cache of rollingdisk's Coulomb loop is filled\n")
    except OSError:  # no cache folder to be had
        pass


def compiled() -> dict:
    """The compiled namespace (compiled, or loaded from numba's on-disk cache, on the first
    call of a process; a stale cache is detected and recompiled).

    Raises
    ------
    ImportError
        If numba is missing.
    """
    global _compiled, _compile_time
    if _compiled is None:
        t0 = time.perf_counter()
        ns = namespace(compiled=True)
        if not matches_python(ns):
            from rollingdisk.engine.compile import recompile

            recompile(ns, NAMES)
            if not matches_python(ns):  # pragma: no cover - would be a numba bug
                raise RuntimeError("the compiled Coulomb loop disagrees with its Python source")
        _compile_time = time.perf_counter() - t0
        _compiled = ns
        _mark_ready()
    return _compiled


def compile_time() -> float | None:
    """Seconds the first :func:`compiled` call of this process took (None before it)."""
    return _compile_time
