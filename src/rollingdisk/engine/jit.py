"""When the compiled integrator is worth loading, and which method ``"auto"`` runs.

Loading the numba integrator costs about 1 s on a 2-core machine (``import numba`` 0.3 s,
numba's own set-up and the cached machine code 0.8-1.0 s), compiling it with an empty
cache 10-60 s once per machine; the same integrator run
uncompiled (:mod:`rollingdisk.engine.pycore`) takes 30-65 times as long per step as
compiled.  The rule (the one place it is written; docs/simulation.md quotes it):

* Work is counted in steps, never in seconds: the process counts the DOP853 steps it has
  taken uncompiled over all its runs (:func:`py_steps`), and a run projects the steps still
  ahead of it from the part of its span its first chunks covered.  Every decision is thus
  a function of the run (and of the runs before it in the process), never of the machine's
  speed or load: the same command takes the same steps and prints the same numbers.
* A run starts uncompiled, in chunks of :data:`PY_CHUNK` steps.  At a chunk boundary it
  goes on compiled (the very same steps: the run pauses and resumes) once the process has
  taken :data:`PY_BUDGET` steps uncompiled in total, or once the run is projected to need
  more than :data:`LOAD_WORTH` steps more (:func:`worth_loading`); both are about a second
  of uncompiled stepping, so a short script never imports numba and a long run pays one
  load.  Once loaded, every later run of the process is compiled from its first step.
* With a cold cache the compile happens then and there, in the foreground, announced by
  one line on a terminal (:func:`rollingdisk.engine.compile.announce`); no process is
  started that outlives the command.  Whether the cache is cold changes how long the run
  takes, not which steps it takes.

``simulate(method="auto")`` (the default) asks :func:`auto_method` which method the process
has that is fastest for the tolerance, at equal accuracy (energy drift): user events need
scipy's solver, ``dense_output`` and ``first_step`` DOP853; otherwise, on rough ground
(:data:`TAYLOR_RANGE`), the compiled Taylor method at 1e-3 times the tolerance, where its
drift is no larger than DOP853's at the one asked for, and DOP853 on smooth ground.  While
the process has no compiled code, the Taylor part starts as uncompiled DOP853 (the Taylor
method exists only compiled) and goes on with the Taylor method from the chunk at which the
compiled code is loaded.

The mark of a filled cache is a file named after the sources (the hash of ``engine/`` and
``model/`` that also names the compiled functions,
:func:`rollingdisk.engine.compile.source_key`), numba's own ``__init__.py`` and the Python
version, in the folder of numba's cache (``NUMBA_CACHE_DIR`` or the package's
``__pycache__``, else a user cache folder).

Run as ``python -m rollingdisk.engine.jit`` it fills the cache up front (one compiler at a
time: an exclusive lock; numba itself writes its cache files atomically).
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import numpy as np

#: Uncompiled DOP853 steps, in total over the runs of the process, after which the
#: compiled code is loaded (one to two seconds of uncompiled stepping, about a warm load).
PY_BUDGET = 8_000

#: Uncompiled steps still ahead of a run (projected from the part of its span done) beyond
#: which it loads the compiled code at once instead of waiting for :data:`PY_BUDGET`.
LOAD_WORTH = 8_000

#: Steps of one uncompiled chunk (a fixed number, so that the chunk boundaries at which the
#: rule is applied do not depend on the machine's speed; about 0.05 s).
PY_CHUNK = 256

#: Where ``method="auto"`` uses the Taylor method, per ground: ``(lowest, highest, factor)``
#: -- for tolerances ``min(rtol, atol)`` in ``[lowest, highest]`` it runs the Taylor method
#: at ``rtol`` and ``atol`` times ``factor`` (floored at 100 eps), where its energy drift is
#: no larger than DOP853's at the tolerance asked for, so that ``"auto"`` keeps the accuracy
#: the tolerance gives.  Measured (benchmarks/simulate.py and 12 random perturbed circles
#: per ground; docs/simulation.md): on rough ground the Taylor method at 1e-3 times the
#: tolerance matches DOP853's drift from 1e-2 down to round-off.  On smooth ground the
#: factor it needs varies from job to job and its drift stops falling at about 1e-12
#: (round-off in the quotient of eq. 49) where DOP853's goes on to 1e-14: DOP853 there.
TAYLOR_RANGE = {"rough": (0.0, 1.0, 1e-3)}
_TOL_FLOOR = 100 * float(np.finfo(float).eps)

_py_steps = 0

_PKG = Path(__file__).resolve().parent


def cache_folder() -> Path:
    env = os.environ.get("NUMBA_CACHE_DIR")
    if env:
        return Path(env)
    here = _PKG / "__pycache__"
    try:
        here.mkdir(exist_ok=True)
        if os.access(here, os.W_OK):
            return here
    except OSError:
        pass
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "rollingdisk"


def _key() -> str:
    import rollingdisk.engine
    import rollingdisk.model
    from rollingdisk.engine.compile import marker_key

    return marker_key(rollingdisk.model, rollingdisk.engine)


def marker() -> Path:
    """The file whose presence says the on-disk compile cache is ready for these sources."""
    return cache_folder() / f"rollingdisk-jit-{_key()}.ready"


def ready() -> bool:
    """Whether the compiled integrator loads from the on-disk cache (no compiling)."""
    try:
        return marker().exists()
    except OSError:
        return False


def mark_ready() -> None:
    """Record that the cache is ready (called after a successful compile or load)."""
    from rollingdisk.engine.compile import write_marker

    write_marker(marker(), "numba cache of rollingdisk's integrator is filled\n")


def py_steps() -> int:
    """DOP853 steps this process has taken uncompiled, over all its runs."""
    return _py_steps


def spend(steps: int) -> None:
    """Count ``steps`` more uncompiled steps against :data:`PY_BUDGET`."""
    global _py_steps
    _py_steps += max(0, int(steps))


def budget_spent() -> bool:
    """Whether the process has taken :data:`PY_BUDGET` uncompiled steps in total."""
    return _py_steps >= PY_BUDGET


def pick_core(steps_here: int, fraction: float):
    """The integrator for the next chunk of a run, by the rule of this module's docstring:
    ``(module, compiled)``.  ``steps_here``: the steps the run has taken uncompiled so far;
    ``fraction``: the part of its span done (for :func:`worth_loading`)."""
    global _compile_failed
    if _core is None and (budget_spent() or worth_loading(steps_here, fraction)) \
            and _can_compile():
        try:
            jit_compile()  # loads from the on-disk cache, or compiles (announced)
        except Exception:  # noqa: BLE001 - numba broken here: the run goes on uncompiled
            _compile_failed = True
    if _core is not None:
        return _core, True
    from rollingdisk.engine import pycore

    return pycore, False


def worth_loading(steps_here: int, fraction: float) -> bool:
    """Whether a run that has taken ``steps_here`` steps uncompiled on ``fraction`` of its
    span is projected to need more than :data:`LOAD_WORTH` steps more."""
    if not 0.0 < fraction < 1.0 or not steps_here > 0:
        return False
    return steps_here * (1.0 - fraction) / fraction > LOAD_WORTH


_compile_failed = False


def _can_compile() -> bool:
    """numba is importable and has not failed in this process."""
    import importlib.util

    return not _compile_failed and importlib.util.find_spec("numba") is not None


def auto_method(ground: str, rtol: float, atol: float, *, events: bool, dense_output: bool,
                first_step: bool) -> tuple[str, float, float]:
    """What ``simulate(method="auto")`` runs: ``(method, rtol, atol)``.

    ``"scipy"`` with user events, ``"dop853"`` with ``dense_output`` or ``first_step``
    (options of those methods only) or for a tolerance ``min(rtol, atol)`` outside the
    ground's :data:`TAYLOR_RANGE`; otherwise ``"auto-taylor"``: the Taylor method at
    ``rtol`` and ``atol`` times the range's factor (``rtol`` floored at 100 eps, ``atol``
    never above what was asked) once the compiled code is loaded, uncompiled DOP853 at the
    tolerances asked for until then (see the module docstring).
    """
    if events:
        return "scipy", rtol, atol
    lowest, highest, factor = TAYLOR_RANGE.get(ground, (0.0, -1.0, 1.0))
    if dense_output or first_step or not lowest <= min(rtol, atol) <= highest:
        return "dop853", rtol, atol
    return ("auto-taylor", max(rtol * factor, _TOL_FLOOR),
            max(atol * factor, min(atol, _TOL_FLOOR)))


def _compile_here() -> int:
    """``python -m rollingdisk.engine.jit``: fill the cache up front, one compiler at a
    time (a second one leaves at once)."""
    folder = cache_folder()
    folder.mkdir(parents=True, exist_ok=True)
    lock = open(folder / "rollingdisk-jit.lock", "a")  # noqa: SIM115 - held until exit
    try:
        import fcntl

        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except ImportError:  # pragma: no cover - no fcntl (Windows): numba's atomic writes
        pass
    except OSError:
        return 0  # another process is compiling
    if ready():
        return 0
    jit_compile()  # compiles, fills the cache and marks it ready
    return 0


# ---------------------------------------------------------------------------- numba core
_core = None
_compile_time = None


def jit_compile() -> float:
    """Import (and on first use compile) the numba integrator; return the seconds it took.

    The compiled code is cached on disk (``numba`` ``cache=True``), so after the first
    run this is the time to load it.  A cache left stale by an edit of the kernels in
    :mod:`rollingdisk.model.equations` (eqs. 11, 38, 49) is detected and recompiled.
    :func:`simulate` does not need it: it starts uncompiled and loads the compiled code
    once the work ahead is worth it (the rule of :mod:`rollingdisk.engine.jit`).
    Call it to compile (or load) up front, e.g. before timing runs: every later run is
    compiled from its first step (and ``method="auto"`` is the Taylor method on rough
    ground).

    Returns
    -------
    float
        Seconds spent importing, compiling or loading, and checking the compiled code on
        the first call; the same figure again on later calls (nothing is redone).

    Raises
    ------
    ImportError
        If numba is missing, or scipy lacks the DOP853 coefficients the core takes from it.
    """
    global _core, _compile_time
    if _core is None:
        t0 = time.perf_counter()
        if not ready():
            from rollingdisk.engine.compile import announce

            announce("compiling rollingdisk's integrator (once per machine; usually 10-60 s)")
        from rollingdisk.engine import numba_core as core

        y = np.array([0.0, 0.0, 0.0, 0.3, 0.0, 0.0, 1.0, 0.5])
        ys = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.3, 0.0, 0.0, 1.0, 0.5])
        guards = np.ones(3, dtype=np.bool_)
        for rough, y0 in ((True, y), (False, ys)):
            atolv = np.full(y0.shape[0], 1e-8)
            for keep in (False, True):
                core.integrate(rough, 0.1, 0.0, y0, 1e-3, 1e-3, 1e-8, atolv, np.inf, 0.0,
                               guards, 1.0, np.zeros(1), False, 10, 10, keep)
                core.integrate(rough, 0.1, 0.0, y0, 1e-3, 1e-3, 1e-8, atolv, np.inf, 0.0,
                               guards, 1.0, np.array([5e-4]), True, 10, 10, keep)
            P = 6  # the Taylor integrator (method="taylor"); the order is a run-time value
            for te, has in ((np.zeros(1), False), (np.array([5e-4]), True)):
                core._tay_integrate(rough, 0.1, 0.0, y0, 1e-3, 1e-8, atolv, np.inf, guards,
                                    1.0, te, has, 10, 10, P)
        if not core.rhs_matches_kernels():  # a stale on-disk cache (see _numba_core)
            core.recompile_all()
            if not core.rhs_matches_kernels():  # pragma: no cover - would be a numba bug
                raise RuntimeError("the compiled right-hand side disagrees with "
                                   "rollingdisk.model.equations")
        _compile_time = time.perf_counter() - t0
        _core = core
        mark_ready()
    return _compile_time



if __name__ == "__main__":
    sys.exit(_compile_here())
