"""The step loop of :mod:`rollingdisk.engine.steploop`, compiled once for every model.

How a model's functions reach compiled code -- the choice and why (numba 0.68, tried with a
toy loop, ``NUMBA_CACHE_DIR`` in a fresh folder, two processes each):

* **numba dispatchers passed as arguments** (the loop typed on each function's
  ``Dispatcher`` type): one specialization of the loop per model, and ``cache=True`` never
  hits -- the type is the dispatcher object, which differs in every process, so each
  process compiled the loop again and added entries to the cache.  Rejected.
* **closures from a factory** (``make_loop(rhs)`` returning an ``njit`` function that
  calls ``rhs``): the cache key holds the pickled closure cells, which differ in every
  process: a miss every time.  Rejected.
* **first-class function types** (``numba.types.FunctionType``): the loop is compiled with
  an explicit signature in which ``rhs``, ``events`` and ``impact`` are typed by their
  signatures alone; the model's functions are compiled with those signatures, each in its
  own cache, and called through a function pointer.  One compiled loop serves every model
  and it loads from the cache in the next process.  The indirect call costs a few
  nanoseconds and numba cannot inline the model's function into the loop; a DOP853 step
  makes 12-16 calls into a right-hand side that costs far more than that.
  Chosen.  numba documents first-class functions as experimental; the tests of
  ``tests/test_engine_contract.py`` run every model both ways and compare.

On the disk on rough ground the loop takes the steps of
:func:`rollingdisk.engine.numba_core.integrate` to the last bit, compiled and uncompiled
(``tests/test_engine_contract.py``); its compile, load and step times are measured in
``benchmarks/`` (docs/performance.md).

The loop and its helpers are the plain functions of :mod:`rollingdisk.engine.steploop`,
:mod:`rollingdisk.engine.dop853` and :mod:`rollingdisk.engine.roots`, made callable from
compiled code by ``numba.extending.register_jitable`` (which leaves the Python functions
as they are): nothing is copied into a merged namespace and no source is written twice.
numba keys a cached function by its own file alone; the loop is named after the hash of
every source of ``engine/`` and ``model/`` (:func:`rollingdisk.engine.compile.source_key`),
and a model's function after the hash of its own module and its helpers' modules, so that
an edited callee never meets a stale cache entry.

Everything is compiled with numpy's error model: a float divided by 0 gives inf or nan
(the uncompiled loop, which computes on numpy's float64 scalars, does the same) instead of
raising; the Illinois step then falls back to bisection (:func:`.roots.illinois_trial`)
and a non-finite step is rejected.
"""

from __future__ import annotations

import sys
import types as _pytypes

import numba
from numba import types
from numba.extending import register_jitable

import rollingdisk.engine as _engine_pkg
import rollingdisk.model as _model_pkg
from rollingdisk.engine import dop853 as _dop
from rollingdisk.engine import roots as _roots
from rollingdisk.engine import steploop as _loopsrc
from rollingdisk.engine.compile import source_key
from rollingdisk.util.errors import ParameterError

__all__ = ["RHS_SIGNATURE", "EVENTS_SIGNATURE", "IMPACT_SIGNATURE", "loop",
           "model_functions", "compile_function"]

_VEC = types.float64[::1]
#: ``rhs(t, y, p, out) -> None``
RHS_SIGNATURE = types.void(types.float64, _VEC, _VEC, _VEC)
#: ``events(t, y, p, g) -> None``
EVENTS_SIGNATURE = types.void(types.float64, _VEC, _VEC, _VEC)
#: ``impact(k, t, y, p, out) -> int``
IMPACT_SIGNATURE = types.int64(types.int64, types.float64, _VEC, _VEC, _VEC)
_LOOP_ARGS = (types.FunctionType(RHS_SIGNATURE), types.FunctionType(EVENTS_SIGNATURE),
              types.FunctionType(IMPACT_SIGNATURE), _VEC, types.float64, _VEC, types.float64,
              types.float64, _VEC, types.float64, types.float64, types.int64,
              types.int64[::1], types.int64[::1])

#: The plain functions the loop calls, compiled into it where it calls them.
_HELPERS = (_dop._combine, _dop._dense_tail, _dop._dense_value, _dop._error_norm_v,
            _dop._step_factor, _dop._rms, _roots._illinois_converged, _roots._illinois_trial,
            _roots._illinois_update, _loopsrc._stages, _loopsrc._dense, _loopsrc._first_step,
            _loopsrc._crosses, _loopsrc._event_root, _dop._grow, _loopsrc._grow_events)
_registered: set = set()
_loop = None
_functions: dict = {}


def _register(fns) -> None:
    for f in fns:
        if id(f) not in _registered:
            register_jitable(f)
            _registered.add(id(f))


def _renamed(f, key):
    """``f`` with ``_key`` appended to its qualified name (numba's cache key); its globals
    are its own module's."""
    g = _pytypes.FunctionType(f.__code__, f.__globals__, f.__name__, f.__defaults__,
                              f.__closure__)
    g.__qualname__ = f"{f.__qualname__}_{key}"
    g.__module__ = f.__module__
    g.__doc__ = f.__doc__
    return g


def loop():
    """The compiled :func:`rollingdisk.engine.steploop.integrate` (compiled, or loaded from
    numba's on-disk cache, on the first call of a process)."""
    global _loop
    if _loop is None:
        _register(_HELPERS)
        key = source_key(_model_pkg, _engine_pkg)
        _loop = numba.njit(_LOOP_ARGS, cache=True, error_model="numpy")(
            _renamed(_loopsrc.integrate, key))
    return _loop


def compile_function(f, signature, helpers=()):
    """``f`` compiled with ``signature`` (cached on disk), its ``helpers`` compiled into it.

    A numba dispatcher is compiled for ``signature`` (if it is not already) and returned
    as it is; one whose signatures are fixed to others raises :class:`ParameterError`.
    """
    memo = (id(f), str(signature))
    if memo in _functions:
        return _functions[memo][1]
    if isinstance(f, numba.core.dispatcher.Dispatcher):
        if tuple(signature.args) not in [tuple(a) for a in f.signatures]:
            try:
                f.compile(signature)
            except RuntimeError:  # numba: "compilation disabled" (its signatures fixed)
                raise ParameterError(f"{f.__name__}: compiled for {f.signatures}, the "
                                     f"engine calls it as {signature}") from None
        d = f
    else:
        _register(helpers)
        mods = {sys.modules[g.__module__] for g in (f, *helpers)
                if getattr(sys.modules.get(g.__module__), "__file__", None)}
        key = source_key(*sorted(mods, key=lambda m: m.__name__)) if mods else ""
        d = numba.njit(signature, cache=True, error_model="numpy")(_renamed(f, key) if key else f)
    _functions[memo] = (f, d)  # f kept alive: its id is the memo's key
    return d


def model_functions(model):
    """``(rhs, events, impact)`` of ``model`` compiled for the loop's signatures."""
    return (compile_function(model.rhs, RHS_SIGNATURE, model.helpers),
            compile_function(model.events, EVENTS_SIGNATURE, model.helpers),
            compile_function(model.impact, IMPACT_SIGNATURE, model.helpers))
