"""The linear system of line contact and its right-hand side as plain functions on floats,
compiled with numba where the process runs compiled code.

:func:`line_system` builds and solves, for one sub-phase, the 11 x 11 system of
:func:`rollingdisk.phases.line_contact.line_forces` (the balances of
:func:`rollingdisk.symbolic.line_contact.newton_euler` with the corner laws of the mode);
:func:`line_rhs_kernel` adds the kinematics and the dissipated power of
:func:`~rollingdisk.phases.line_contact.line_rhs`.  The compiled functions give the plain
ones' numbers bit for bit: the same operations in the same order (numba's
``np.linalg.solve`` is LAPACK's ``gesv``, as numpy's is), and the length of a slip,
``math.hypot`` in the plain functions, is :func:`python_hypot` in the compiled ones:
CPython's own algorithm, which libm's ``hypot`` (numba's ``math.hypot``) does not share
to the last bit.  :func:`load_compiled` checks both before it hands the compiled ones
out.  Compiled, because a toss that stands on its tread evaluates the line phase's
right-hand side thousands of times, and uncompiled that was most of such a toss's time.

Parameters ``p``: the float array of :func:`~rollingdisk.phases.line_contact.line_params`.
Units m = a = g = 1.
"""

from __future__ import annotations

import math
import types

import numpy as np

__all__ = ["line_system", "line_rhs_kernel", "corner_directions", "python_hypot", "kernels",
           "load_compiled", "loaded", "NAMES"]

#: The functions of the namespace, callees first.
NAMES = ("_hypot", "_direction", "corner_directions", "line_system", "line_rhs_kernel")

_SPLIT = 134217729.0  # 2**27 + 1: Veltkamp's split of a double into two 26-bit halves
_START = 2.0  # line_contact._START: a seeded slip keeps its seed up to _START * floor
_hypot = math.hypot  # the plain functions' slip length; python_hypot where compiled


def python_hypot(x, y):
    """``math.hypot(x, y)`` as CPython 3.11 computes it (``vector_norm`` of
    ``Modules/mathmodule.c``): the squares summed exactly in double-double arithmetic
    (Veltkamp splitting, compensated sums), one square root, one Newton correction.
    numba-compilable; :func:`load_compiled` checks it against ``math.hypot`` of the
    running Python and uses it only where they agree."""
    ax = abs(x)
    ay = abs(y)
    mx = 0.0
    if ax > mx:
        mx = ax
    if ay > mx:
        mx = ay
    if math.isinf(mx):
        return mx
    if math.isnan(ax) or math.isnan(ay):
        return math.nan
    if mx == 0.0:
        return mx
    max_e = math.frexp(mx)[1]
    csum = 1.0
    frac1 = 0.0
    frac2 = 0.0
    frac3 = 0.0
    if max_e < -1023:  # subnormal: divide by the largest instead of scaling
        for v in (ax, ay):
            q = v / mx
            q = q * q
            old = csum
            csum += q
            frac1 += (old - csum) + q
        return mx * math.sqrt(csum - 1.0 + frac1)
    scale = math.ldexp(1.0, -max_e)
    for v in (ax, ay):
        q = v * scale
        t = q * _SPLIT
        hi = t - (t - q)
        lo = q - hi
        q = hi * hi
        old = csum
        csum += q
        frac1 += (old - csum) + q
        q = 2.0 * hi * lo
        old = csum
        csum += q
        frac2 += (old - csum) + q
        frac3 += lo * lo
    hh = math.sqrt(csum - 1.0 + (frac1 + frac2 + frac3))
    t = hh * _SPLIT
    hi = t - (t - hh)
    lo = hh - hi
    q = -hi * hi
    old = csum
    csum += q
    frac1 += (old - csum) + q
    q = -2.0 * hi * lo
    old = csum
    csum += q
    frac2 += (old - csum) + q
    q = -lo * lo
    old = csum
    csum += q
    frac3 += (old - csum) + q
    q = csum - 1.0 + (frac1 + frac2 + frac3)
    return (hh + q / (2.0 * hh)) / scale


def _direction(ux, uy, sx, sy, floor):
    """Unit slip direction of a sliding corner (:func:`rollingdisk.phases.line_contact
    ._direction`): a seeded corner (``(sx, sy) != 0``: it has just started to slip from
    rest) keeps its seed until its slip passes ``_START * floor``."""
    n = _hypot(ux, uy)
    if (sx != 0.0 or sy != 0.0) and n <= _START * floor:
        return sx, sy
    if n > 0.0:
        return ux / n, uy / n
    return 0.0, 0.0


def corner_directions(y, p):
    """Unit slip directions ``(d_+x, d_+y, d_-x, d_-y)`` of the sliding corners of the mode
    of ``p`` at ``y`` (0 for a sticking corner); slips ``u_s = (v_x - omega2 + s h omega3,
    v_y)``."""
    h = p[0]
    base = int(p[8]) & 3
    dpx = dpy = dmx = dmy = 0.0
    if base != 3 and base != 1:
        dpx, dpy = _direction(y[4] - y[6] + h * y[7], y[5], p[9], p[10], p[14])
    if base != 3 and base != 2:
        dmx, dmy = _direction(y[4] - y[6] - h * y[7], y[5], p[11], p[12], p[14])
    return dpx, dpy, dmx, dmy


def line_system(y, p):
    """Solve the mode ``p[8]``'s linear system at the line state ``y``.

    Parameters
    ----------
    y : ndarray, shape (9,)
        Line state (:data:`~rollingdisk.phases.line_contact.LINE_STATE`).
    p : ndarray
        :func:`~rollingdisk.phases.line_contact.line_params`.

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
    dpx, dpy, dmx, dmy = corner_directions(y, p)
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


def line_rhs_kernel(y, p):
    """``dy/dt`` of the line state ``y`` (:func:`~rollingdisk.phases.line_contact.line_rhs`):
    the centre's velocity in OXYZ, ``dpsi/dt = omega3``, ``dphi/dt = omega2``, the
    accelerations of :func:`line_system` and the dissipated power ``-(sum F_s . u_s +
    omega . M)``."""
    f = line_system(y, p)
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
        ns["_hypot"] = python_hypot
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
    """Whether the functions of ``ns`` give the plain functions' numbers bit for bit: the
    slip length on pairs over 600 binades (and zeros, subnormals, infinities), the kernels
    on states of every mode, seeded or not (this also compiles them, or loads them from
    numba's cache)."""
    rng = np.random.default_rng(7)
    xs = rng.standard_normal((20000, 2)) * 10.0 ** rng.uniform(-300.0, 300.0, (20000, 1))
    xs[:, 1] *= 10.0 ** rng.uniform(-20.0, 0.0, 20000)
    xs = np.concatenate([xs, [[0.0, 0.0], [5e-324, 0.0], [3e-310, -4e-310], [np.inf, 1.0],
                              [1e308, 1e308], [-0.0, 2.0]]])
    hyp = ns["_hypot"]
    if any(hyp(a, b) != math.hypot(a, b) for a, b in xs):
        return False
    for mode in range(8):
        for seeded in (False, True):
            y = rng.uniform(-1.0, 1.0, 9)
            if seeded:  # slips at the floor, where the seed decides
                y[4] = y[6] - 0.1 * y[7] + 1e-9
                y[5] = 1e-9
            d = rng.uniform(-1.0, 1.0, 4) if seeded else np.zeros(4)
            p = np.array([0.1, 0.25 + 0.01 / 3.0, 0.5, 0.6, 0.5, 0.01, 0.002, 0.001,
                          float(mode), d[0], d[1], d[2], d[3], 1.0, 1e-9])
            for name in ("corner_directions", "line_system", "line_rhs_kernel"):
                a = np.array(ns[name](y, p))
                b = np.array(_PYTHON[name](y, p))
                if not np.array_equal(a, b):
                    return False
    return True
