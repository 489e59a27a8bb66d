"""The linear system of line contact and its right-hand side as plain functions on floats,
compiled with numba where the process runs compiled code.

:func:`line_system` builds and solves, for one sub-phase, the 11 x 11 system of
:func:`rollingdisk.phases.line_contact.line_forces` (the balances of
:func:`rollingdisk.symbolic.line_contact.newton_euler` with the corner laws of the mode);
:func:`line_rhs_kernel` adds the kinematics and the dissipated power of
:func:`~rollingdisk.phases.line_contact.line_rhs`.  The unit slip directions of the sliding
corners are arguments: they are computed by the caller with Python's ``math.hypot``
(whose rounding numba's libm ``hypot`` need not share), so the compiled and the
uncompiled functions give the same numbers bit for bit (the same operations in the same
order; numba's ``np.linalg.solve`` is LAPACK's ``gesv`` as numpy's is).  The line phase
was 60-80 % of the CPU time of a toss that ends on its edge: about 10,000 right-hand
sides a toss, 75 microseconds each uncompiled.

Parameters ``p``: the float array of :func:`~rollingdisk.phases.line_contact.line_params`.
Units m = a = g = 1.
"""

from __future__ import annotations

import math
import types

import numpy as np

__all__ = ["line_system", "line_rhs_kernel", "kernels", "load_compiled", "loaded", "NAMES"]

#: The functions of the namespace, callees first.
NAMES = ("line_system", "line_rhs_kernel")


def line_system(y, p, dpx, dpy, dmx, dmy):
    """Solve the mode ``p[8]``'s linear system at the line state ``y``.

    Parameters
    ----------
    y : ndarray, shape (9,)
        Line state (:data:`~rollingdisk.phases.line_contact.LINE_STATE`).
    p : ndarray
        :func:`~rollingdisk.phases.line_contact.line_params`.
    dpx, dpy, dmx, dmy : float
        Unit slip directions of corners + and - (used where the corner slides).

    Returns
    -------
    ndarray, shape (12,)
        ``(d v_x/dt, d v_y/dt, d omega2/dt, d omega3/dt, lambda_+, lambda_-, F_+x, F_+y,
        F_-x, F_-y, M_y, M_z)`` [``m g``, ``m g a``]: accelerations, normal forces, corner
        friction in Cxyz and the contact moments (``M_y`` the holding moment while the
        rolling resistance is stuck).
    """
    h = p[0]
    k1 = p[1]
    k2 = p[2]
    mode = int(p[8])
    base = mode & 3
    stuck = (mode & 4) != 0
    vx = y[4]
    vy = y[5]
    w2 = y[6]
    w3 = y[7]
    # unknowns: 0 dvx, 1 dvy, 2 dw2, 3 dw3, 4 lam_p, 5 lam_m, 6 Fpx, 7 Fpy, 8 Fmx, 9 Fmy,
    # 10 M_y (the holding moment while stuck)
    A = np.zeros((11, 11))
    b = np.zeros(11)
    sg3 = 1.0 if w3 > 0.0 else (-1.0 if w3 < 0.0 else 0.0)
    Mz = -p[6] * sg3 - p[7] * w3  # pivot and air moments
    My = 0.0
    if not stuck:  # rolling resistance opposes omega2 (p[13] its sign at omega2 = 0)
        sg2 = 1.0 if w2 > 0.0 else (-1.0 if w2 < 0.0 else p[13])
        My = -p[5] * sg2
    # balances (symbolic.line_contact.newton_euler), M_x = 0 (omega_h = (0, omega2))
    A[0, 0] = 1.0
    A[0, 6] = -1.0
    A[0, 8] = -1.0
    b[0] = w3 * vy
    A[1, 1] = 1.0
    A[1, 7] = -1.0
    A[1, 9] = -1.0
    b[1] = -w3 * vx
    A[2, 2] = k2
    A[2, 6] = 1.0
    A[2, 8] = 1.0
    b[2] = My
    if stuck:
        A[2, 10] = -1.0
    A[3, 3] = k1
    A[3, 6] = -h
    A[3, 8] = h
    b[3] = Mz
    A[4, 4] = 2.0 * h
    A[4, 7] = -1.0
    A[4, 9] = -1.0
    b[4] = h + k2 * w2 * w3
    A[5, 4] = 1.0
    A[5, 5] = 1.0
    b[5] = 1.0
    row = 6
    # corner + (friction unknowns 6, 7; normal 4), then corner - (8, 9; 5)
    if base == 3 or base == 1:  # sticks: d u_+/dt = 0: dvx - dw2 + h dw3 = 0
        A[row, 0] = 1.0
        A[row, 2] = -1.0
        A[row, 3] = h
        row += 1
    else:  # F_+ = -mu_k lam_+ d_+
        A[row, 6] = 1.0
        A[row, 4] = p[4] * dpx
        A[row + 1, 7] = 1.0
        A[row + 1, 4] = p[4] * dpy
        row += 2
    if base == 3 or base == 2:  # sticks: dvx - dw2 - h dw3 = 0
        A[row, 0] = 1.0
        A[row, 2] = -1.0
        A[row, 3] = -h
        row += 1
    else:
        A[row, 8] = 1.0
        A[row, 5] = p[4] * dmx
        A[row + 1, 9] = 1.0
        A[row + 1, 5] = p[4] * dmy
        row += 2
    if base != 0:
        A[row, 1] = 1.0  # dvy = 0
        row += 1
    if base == 3:  # the sideways split is free; equal halves
        A[row, 7] = 1.0
        A[row, 9] = -1.0
        row += 1
    if stuck:
        A[row, 2] = 1.0
    else:
        A[row, 10] = 1.0
    x = np.linalg.solve(A, b)
    out = np.empty(12)
    out[:10] = x[:10]
    out[10] = x[10] if stuck else My
    out[11] = Mz
    return out


def line_rhs_kernel(y, p, dpx, dpy, dmx, dmy):
    """``dy/dt`` of the line state ``y`` (:func:`~rollingdisk.phases.line_contact.line_rhs`):
    the centre's velocity in OXYZ, ``dpsi/dt = omega3``, ``dphi/dt = omega2``, the
    accelerations of :func:`line_system` and the dissipated power ``-(sum F_s . u_s +
    omega . M)``."""
    f = line_system(y, p, dpx, dpy, dmx, dmy)
    h = p[0]
    c = math.cos(y[2])
    s = math.sin(y[2])
    upx = y[4] - y[6] + h * y[7]  # slip of corner +: (v_x - omega2 + h omega3, v_y)
    umx = y[4] - y[6] - h * y[7]
    power = (f[6] * upx + f[7] * y[5] + f[8] * umx + f[9] * y[5]
             + y[6] * f[10] + y[7] * f[11])
    out = np.empty(9)
    out[0] = y[4] * c - y[5] * s
    out[1] = y[4] * s + y[5] * c
    out[2] = y[7]
    out[3] = y[6]
    out[4] = f[0]
    out[5] = f[1]
    out[6] = f[2]
    out[7] = f[3]
    out[8] = -power
    return out


_PYTHON = {name: globals()[name] for name in NAMES}
_compiled = None


def kernels() -> dict:
    """``{name: function}`` of :data:`NAMES`: the compiled ones once :func:`load_compiled`
    has run in this process, else these plain functions (the same numbers)."""
    return _PYTHON if _compiled is None else _compiled


def loaded() -> bool:
    """Whether the compiled kernels are in use in this process."""
    return _compiled is not None


def load_compiled() -> bool:
    """Compile (or load from numba's on-disk cache) :data:`NAMES` and use them from now
    on; False (and the plain functions stay) where numba is missing or fails."""
    global _compiled
    if _compiled is not None:
        return True
    try:
        from rollingdisk.engine.compile import compile_namespace, numba_available, source_key

        if not numba_available():
            return False
        import sys

        ns = dict(globals())
        for name in NAMES:
            f = ns[name]
            ns[name] = types.FunctionType(f.__code__, ns, f.__name__, f.__defaults__,
                                          f.__closure__)
        key = source_key(sys.modules[__name__])
        done = {n: f for n, f in compile_namespace(ns, NAMES, key=key).items()
                if n in NAMES}
        if not _same_numbers(done):  # pragma: no cover - a libm or LAPACK that rounds
            return False             # otherwise: the plain functions keep the numbers
        _compiled = done
    except Exception:  # noqa: BLE001 - numba broken: the plain functions still work
        return False
    return True


def _same_numbers(ns) -> bool:
    """Whether the functions of ``ns`` give the plain functions' numbers bit for bit on
    states of every mode (this also compiles them, or loads them from the cache)."""
    rng = np.random.default_rng(7)
    for mode in range(8):
        y = rng.uniform(-1.0, 1.0, 9)
        p = np.array([0.1, 0.25 + 0.01 / 3.0, 0.5, 0.6, 0.5, 0.01, 0.002, 0.001,
                      float(mode), 0.0, 0.0, 0.0, 0.0, 1.0, 1e-9])
        d = rng.uniform(-1.0, 1.0, 4)
        for name in NAMES:
            a = ns[name](y, p, d[0], d[1], d[2], d[3])
            b = _PYTHON[name](y, p, d[0], d[1], d[2], d[3])
            if not np.array_equal(a, b):
                return False
    return True
