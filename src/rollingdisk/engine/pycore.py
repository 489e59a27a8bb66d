"""The integrator of :mod:`rollingdisk.engine.dop853`, run uncompiled in CPython.

The very functions of :mod:`rollingdisk.engine.dop853` and the kernels of
:mod:`rollingdisk.model.equations`, re-bound (as :mod:`rollingdisk.engine.numba_core` does before
compiling them) to a namespace in which

* ``np`` is :data:`_SCALAR_NP`: scalar maths from :mod:`math` (``np.sin`` of a float costs
  many times ``math.sin``), everything else numpy's;
* the loops over state components that numba compiles well and CPython runs slowly are
  numpy one-liners doing the same sums: :func:`_combine`, :func:`_dense_tail`,
  :func:`_error_norm_v`, :func:`_dense_value`, :func:`_rms`, and ``_rhs`` hands the
  kernels a list of Python floats.

Where ``math`` raises on inf or nan (IEEE arithmetic would not), :func:`integrate` runs the
chunk again in a namespace with numpy's own scalars.  The step-size control, the guards,
pauses and output are those of ``_dop853`` itself, so a
run begun here and continued compiled takes the steps of a compiled run (up to round-off in
the order of the sums).  Only this namespace sees the shim: the public element-wise API of
:mod:`rollingdisk.model.equations` keeps numpy.  No numba, no ``scipy.integrate``.
"""

from __future__ import annotations

import math
import types

import numpy as np

from rollingdisk.engine import dop853 as _src
from rollingdisk.model import equations as _eq


def _sign(x):
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else 0.0)


def _real(x):
    return x.real  # what np.real returns for a Python float, without its dispatch (~1 us)


class _ScalarNumpy:
    """numpy with the scalar functions the kernels use taken from math."""

    sin, cos, sqrt, isfinite, nextafter = math.sin, math.cos, math.sqrt, math.isfinite, \
        math.nextafter
    sign = staticmethod(_sign)
    real = staticmethod(_real)
    pi, inf = math.pi, math.inf

    def __getattr__(self, name):
        return getattr(np, name)


_SCALAR_NP = _ScalarNumpy()


# ------------------------------------------------------------------ the loops, vectorized
def _combine(y, dt, coef, K, m, out):
    out[:] = y + dt * (K[:, :m] @ coef[:m])  # K: one column per stage


def _dense_tail(y, y_new, f_new, dt, K, F):
    dy = y_new - y
    F[0] = dy
    F[1] = dt * K[:, 0] - dy
    F[2] = 2.0 * dy - dt * (f_new + K[:, 0])
    F[3:] = dt * (_src._D @ K.T)


def _dense_value(y, F, x, out):
    # scipy's Dop853DenseOutput evaluates sum_r F[r] prod_{q <= r} (x or 1 - x, alternating
    # from the top) by Horner's rule; the same sum with the products formed first
    nf = _src._NF
    w = [0.0] * nf
    p = 1.0
    for q in range(nf):
        p *= x if (nf - 1 - q) % 2 == 0 else 1.0 - x
        w[q] = p
    out[:] = y + np.dot(w, F)


def _error_norm_v(y, y_new, K, dt, rtol, atolv):
    n = y.shape[0]
    keep = atolv != np.inf
    sc = atolv[keep] + rtol * np.maximum(np.abs(y[keep]), np.abs(y_new[keep]))
    Kk = K[keep, :_src._NS + 1].T
    e5 = float(np.sum((_src._E5 @ Kk / sc) ** 2))
    e3 = float(np.sum((_src._E3 @ Kk / sc) ** 2))
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(dt) * e5 / math.sqrt((e5 + 0.01 * e3) * n)


def _rms(v, scale):
    return math.sqrt(float(np.mean((v / scale) ** 2)))


def _build(fast=True):
    ns = {**_eq.__dict__, **_src.__dict__}
    names = ("_geometry", "_rough_omega_dot", "_smooth_omega_dot", "_rough_rhs",
             "_smooth_rhs", "_reduced_state", "_reduced_rhs", "_normal_force",
             "_side_normal_force", "_guards", "_step", "_step_factor", "_dense_coefficients",
             "_error_norm",
             "initial_step", "initial_step_v", "_initial_step_scaled", "_side_guards",
             "_first_fired", "_guard_root", "_locate_on_dense", "_needs_sampling",
             "_mid_guards", "_grow", "integrate")
    for name in names:
        f = ns[name]
        ns[name] = types.FunctionType(f.__code__, ns, f.__name__, f.__defaults__,
                                      f.__closure__)
    ns.update(np=_SCALAR_NP if fast else np, _combine=_combine, _dense_tail=_dense_tail,
              _dense_value=_dense_value, _error_norm_v=_error_norm_v, _rms=_rms)
    rough_rhs, smooth_rhs, reduced_rhs = ns["_rough_rhs"], ns["_smooth_rhs"], \
        ns["_reduced_rhs"]

    def _rhs(rough, h, y, out):
        # Python floats: math-speed scalar arithmetic in the kernels; numpy's floats (IEEE
        # inf and nan, as compiled) in the fallback
        v = y.tolist() if fast else y
        if len(v) == 4:
            out[:] = reduced_rhs(rough, h, v)
        elif rough:
            out[:] = rough_rhs(h, v)
        else:
            out[:] = smooth_rhs(h, v)

    def _rhs_col(rough, h, y, K, s):
        v = y.tolist() if fast else y
        if len(v) == 4:
            K[:, s] = reduced_rhs(rough, h, v)
        elif rough:
            K[:, s] = rough_rhs(h, v)
        else:
            K[:, s] = smooth_rhs(h, v)

    ns["_rhs"] = _rhs
    ns["_rhs_col"] = _rhs_col
    return ns


_ns = _build()
_integrate_fast = _ns["integrate"]
_integrate_ieee = _build(fast=False)["integrate"]
RUNNING = _src.RUNNING


def integrate(*args):
    """``_dop853.integrate`` uncompiled.  Python's ``math`` raises where IEEE arithmetic
    (numba, numpy) gives inf or nan (``math.sin(inf)``, a float divided by 0): then the
    chunk is run again from its start with numpy scalars, which behave as compiled code
    (its inputs are not modified, so it takes the same steps).  numpy's warnings are off
    in both: an overflow is reported by the run's status, as a compiled run's is."""
    try:
        with np.errstate(all="ignore"):  # as compiled code: IEEE, no warnings (the run's
            return _integrate_fast(*args)  # status says what overflowed)
    except (ValueError, ArithmeticError):
        with np.errstate(all="ignore"):
            return _integrate_ieee(*args)
