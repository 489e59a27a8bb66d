"""The integrator of :mod:`rollingdisk.engine.dop853`, compiled with numba (imported lazily).

Nothing is written twice: every function here is compiled from its own source, the
kernels of :mod:`rollingdisk.model.equations` (eqs. 1, 2, 11, 37, 38, 49) and the DOP853 of
:mod:`rollingdisk.engine.dop853` alike.  Each function's code object is re-bound to one namespace
in which the functions it calls are the compiled versions, then handed to
``numba.njit(cache=True)``; the compiled code is cached on disk (see
:mod:`rollingdisk.engine.jit` for how a cold cache is filled without making a user wait).

The compiled functions keep the names of their sources, by which they call each other.
The sweeps' batch kernels (:mod:`rollingdisk.sweep.batch` and its parts) are compiled
against the building blocks listed under "the building blocks of the batch kernels" below,
by public names: keep their names and signatures.
"""

from __future__ import annotations

import types

import numba
import numpy as np

import rollingdisk.engine as _engine_pkg
import rollingdisk.model as _model_pkg
from rollingdisk.engine import dop853 as _src
from rollingdisk.engine import taylor as _tay
from rollingdisk.engine import taylor_jets as _jets
from rollingdisk.engine.compile import source_key as _source_key
from rollingdisk.model import equations as _eq

_ns = {**_eq.__dict__, **_src.__dict__, **_jets.__dict__, **_tay.__dict__}

#: The kernels of equations.py, then the integrator of _dop853.py, every one compiled.
_KERNELS = ("_inertia", "_geometry", "_rough_omega_dot", "_smooth_omega_dot", "_rough_rhs",
            "_smooth_rhs", "_reduced_state", "_reduced_rhs", "_normal_force", "_side_normal_force")
_INTEGRATOR = ("_illinois_converged", "_illinois_trial", "_illinois_update", "_rhs", "_rhs_col",
               "_guards", "_combine", "_step", "_dense_tail",
               "_dense_coefficients", "_dense_value", "_error_norm", "_error_norm_v",
               "_step_factor", "_rms", "initial_step",
               "initial_step_v", "_initial_step_scaled", "_side_guards", "_first_fired",
               "_guard_root", "_locate_on_dense", "_needs_sampling", "_mid_guards", "_grow",
               "integrate")
#: The jets of taylor_jets.py (the reduced jets, sampler and root finder of the sweeps' batch
#: Taylor kernels among them) and the Taylor integrator of taylor.py
#: (``simulate(method="taylor")``).
_TAYLOR = ("_signed_h", "where", "_tay_jet_rough", "_tay_rows_rough", "_tay_rows_smooth",
           "_tay_quadratures_smooth", "_tay_jet", "_tay_jet4_rough", "_tay_jet4_smooth",
           "_energy_sc", "_tay_normal", "_tay_sample", "_tay_poly", "_tay_poly_d", "_tay_poly_root",
           "_tay_eval",
           "_tay_eval_reduced", "_tay_step_size", "_tay_locate", "_tay_integrate")
_DISPATCHERS = _KERNELS + _INTEGRATOR + _TAYLOR
#: The Taylor jet and its Horner evaluation: multiply-adds fused (``contract``: one rounding
#: instead of two, the order of every sum kept, no reassociation) and numpy's error model
#: (a quotient by cos theta = 0 gives inf, which fails the step size, instead of a branch
#: raising ZeroDivisionError on every division).
_CONTRACT = ("_tay_jet_rough", "_tay_rows_rough", "_tay_rows_smooth",
             "_tay_quadratures_smooth", "_tay_jet", "_tay_jet4_rough", "_tay_jet4_smooth",
             "_tay_normal", "_tay_sample", "_tay_poly", "_tay_poly_d", "_tay_eval",
             "_tay_eval_reduced")
#: numpy's error model without ``contract``: the step size takes the logarithm of a
#: quotient by a norm that may be 0 (giving inf, which ``where`` then discards), the
#: root finder's Newton step divides by a derivative that may be 0 (a step out of the
#: bracket, which bisects instead).
_NUMPY_ERRORS = ("_tay_step_size", "_tay_poly_root")


#: Hash of the sources the compiled functions may call, in their names: numba's cache then
#: never hands back a function compiled against other callees (:func:`.compile.source_key`).
_KEY = _source_key(_model_pkg, _engine_pkg)


def _compile(name):
    f = _ns[name]
    g = types.FunctionType(f.__code__, _ns, f.__name__, f.__defaults__, f.__closure__)
    g.__qualname__ = f"{f.__qualname__}_{_KEY}"
    g.__module__ = f.__module__
    if name in _CONTRACT:
        d = numba.njit(cache=True, fastmath={"contract"}, error_model="numpy")(g)
    elif name in _NUMPY_ERRORS:
        d = numba.njit(cache=True, error_model="numpy")(g)
    else:
        d = numba.njit(cache=True)(g)
    _ns[name] = d  # the others call the compiled version
    return d


for _name in _DISPATCHERS:
    globals()[_name] = _compile(_name)
del _name

# constants and status codes, as in _dop853 (_dop: scipy's table of coefficients)
_dop = _src._dop
_NS, _NSX, _NF, _NSUB = _src._NS, _src._NSX, _src._NF, _src._NSUB
_A, _B, _C, _E3, _E5, _AX, _D = _src._A, _src._B, _src._C, _src._E3, _src._E5, _src._AX, _src._D
_SAFETY, _MIN_FACTOR, _MAX_FACTOR, _ERR_EXP = (_src._SAFETY, _src._MIN_FACTOR,
                                               _src._MAX_FACTOR, _src._ERR_EXP)
RUNNING, COMPLETED, LIFT_OFF, EDGE_CONTACT, FELL_FLAT, FAILED, STEP_BUDGET = (
    _src.RUNNING, _src.COMPLETED, _src.LIFT_OFF, _src.EDGE_CONTACT, _src.FELL_FLAT,
    _src.FAILED, _src.STEP_BUDGET)

# ---------------------------------------------- the building blocks of the batch kernels
#: Hash of the sources the compiled functions may call (:func:`.compile.source_key`): a
#: batch kernel compiled against them carries it in its name.
SOURCE_KEY = _KEY
#: DOP853's stages and their weights (:mod:`.dop853`).
NS, A, B = _NS, _A, _B
#: DOP853 on the disk: the right-hand side on a 4- to 10-component state, its reduced form
#: returning a tuple, the error norm and the step-size factor of scipy's control, the
#: guards, and eq. (4).
rhs, reduced_rhs, error_norm, step_factor, guards, geometry = (
    _ns["_rhs"], _ns["_reduced_rhs"], _ns["_error_norm"], _ns["_step_factor"],
    _ns["_guards"], _ns["_geometry"])
#: The Taylor method on the reduced disk (:mod:`.taylor_jets`): the jets, their step
#: size, the samples and the normal force along a step, a root of its polynomial, the
#: energy, and the traceable choice.
tay_jet4_rough, tay_jet4_smooth, tay_step_size, tay_sample, tay_normal, tay_poly_root = (
    _ns["_tay_jet4_rough"], _ns["_tay_jet4_smooth"], _ns["_tay_step_size"],
    _ns["_tay_sample"], _ns["_tay_normal"], _ns["_tay_poly_root"])
energy_sc, where = _ns["_energy_sc"], _ns["where"]


# ------------------------------------------------------------------ stale-cache guard
def rhs_matches_kernels() -> bool:
    """True if the compiled right-hand side and normal force agree with equations.py.

    numba's on-disk cache of a function does not notice a change in the functions it calls
    (here: a kernel edited in equations.py would leave ``_rhs`` and ``integrate`` running
    the old formula).  This probe catches that.
    """
    rng = np.random.default_rng(12345)
    for rough, n, kernel in ((True, 8, _eq.rough_rhs), (False, 10, _eq.smooth_rhs)):
        for h in (0.0, 0.37):
            for _ in range(3):
                y = rng.uniform(-1.0, 1.0, n)
                out = np.empty(n)
                _rhs(rough, h, y, out)  # noqa: F821 - compiled above
                ref = np.array(kernel(h, y), dtype=float)
                if not np.allclose(out, ref, rtol=1e-12, atol=1e-12):
                    return False
                if not np.isclose(_normal_force(rough, h, y),  # noqa: F821
                                  _eq.normal_force(rough, h, y), rtol=1e-12, atol=1e-12):
                    return False
                x = y[:4].copy()
                out4 = np.empty(4)
                _rhs(rough, h, x, out4)  # noqa: F821
                if not np.allclose(out4, np.array(_eq.reduced_rhs(rough, h, x)), rtol=1e-12,
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
