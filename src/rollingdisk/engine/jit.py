"""When the compiled integrator is worth loading, which method ``"auto"`` runs, and filling a
cold compile cache.

Loading the numba integrator costs about 0.5 s (``import numba`` and the cached machine
code), compiling it with an empty cache 10-50 s; the same integrator run uncompiled
(:mod:`rollingdisk.engine.pycore`) takes 30-65 times as long per step as compiled.  The
rule (the one place it is written; docs/simulation.md quotes it):

* The process counts the seconds it has spent integrating uncompiled, over all its runs
  (:func:`py_seconds`).  While the count is under :data:`PY_BUDGET` (0.4 s) a run goes
  uncompiled: a short script, or the first medium run of one, never pays for ``import
  numba``.
* Once the count reaches :data:`PY_BUDGET` in total (not per run) and the on-disk cache is
  ready, the process loads the compiled code (0.5 s) at the next chunk boundary of the
  run under way (the very same steps: the run pauses and resumes) and every later run is
  compiled from its first step.  With a ready cache a run loads it sooner, at the first
  chunk boundary at which it is projected (from the part of its span done) to need more
  than :data:`LOAD_WORTH` (0.1 s) more uncompiled (:func:`worth_loading`).  A loop of
  medium runs (0.15-0.4 s each uncompiled) is thus compiled from its first run's second
  chunk on, where before each run started uncompiled again and, never reaching a budget
  of its own, stayed uncompiled; a lone medium run pays at most one load more.
* If the cache is cold when the count reaches the budget, :func:`start_background_compile`
  starts (once per process) a detached process that compiles and fills the on-disk cache,
  then marks it ready; runs go on uncompiled and switch once the mark appears.  A run
  never waits for a compiler, except a run that would need more than
  :data:`COMPILE_GUESS` seconds more uncompiled on a machine with no idle core
  (:func:`worth_waiting`): it waits instead of competing with the compiler for the CPU.
* If the compiled code is loaded (an earlier run, or :func:`jit_compile`), every run uses
  it from the start.

``simulate(method="auto")`` (the default) asks :func:`auto_method` which method the process
has that is fastest for the tolerance, at equal accuracy (energy drift): user events need
scipy's solver, ``dense_output`` and ``first_step`` DOP853; otherwise, on rough ground
(:data:`TAYLOR_RANGE`), the compiled Taylor method at 1e-3 times the tolerance, where its
drift is no larger than DOP853's at the one asked for (and 1.3-9 times as fast), and
DOP853 on smooth ground.  While the process has
no compiled code, the Taylor part starts as uncompiled DOP853 (the Taylor method exists
only compiled) and goes on with the Taylor method from the chunk at which the compiled
code is loaded.

The mark is a file named after the sources (the hash of ``engine/`` and ``model/`` that
also names the compiled functions, :func:`rollingdisk.engine.compile.source_key`),
numba's own ``__init__.py`` and the Python version, in the folder of numba's cache
(``NUMBA_CACHE_DIR`` or the package's ``__pycache__``, else a user cache folder).  Two
processes may start a compiler at once: the compiler takes an exclusive lock
(``fcntl.flock``) and a second one leaves at once; numba itself writes its cache files
atomically.

Run as ``python -m rollingdisk.engine.jit`` it is that background compiler.
"""

from __future__ import annotations

import importlib.util
import os
import sys
import time
from pathlib import Path

import numpy as np

#: Seconds of uncompiled integration, in total over the runs of the process, after which
#: the compiled code is loaded (about what loading it costs, so a process never pays more
#: than about twice the better of the two paths).
PY_BUDGET = 0.4

#: Seconds of uncompiled integration still ahead of a run (projected from its first chunks)
#: beyond which, with a warm cache, the run loads the compiled code at once instead of
#: waiting for :data:`PY_BUDGET`: a quarter of a load (0.4-0.5 s), so that a loop of medium
#: runs (0.15-0.4 s each uncompiled) is compiled from its first run's second chunk, and a
#: lone such run pays at most one load more than it would uncompiled.
LOAD_WORTH = 0.1

#: Where ``method="auto"`` uses the Taylor method, per ground: ``(lowest, highest, factor)``
#: -- for tolerances ``min(rtol, atol)`` in ``[lowest, highest]`` it runs the Taylor method
#: at ``rtol`` and ``atol`` times ``factor`` (floored at 100 eps), where its energy drift is
#: no larger than DOP853's at the tolerance asked for, so that ``"auto"`` keeps the accuracy
#: the tolerance gave before it picked methods; DOP853 elsewhere.  Measured
#: (benchmarks/simulate.py and 12 random perturbed circles per ground; docs/simulation.md):
#: on rough ground the Taylor method at 1e-3 times the tolerance matches DOP853's drift from
#: 1e-2 down to round-off (within 1e-14 at 1e-12) and is 1.3-9 times as fast.  On smooth
#: ground the factor it needs varies from job to job (3e-4 on some, below 3e-5 on the
#: benchmark's circle) and its drift stops falling at about 1e-12 (round-off in the
#: quotient of eq. 49) where DOP853's goes on to 1e-14: DOP853 there.
TAYLOR_RANGE = {"rough": (0.0, 1.0, 1e-3)}
_TOL_FLOOR = 100 * float(np.finfo(float).eps)

#: The clock of the uncompiled seconds (a test replaces it).
clock = time.perf_counter
_py_seconds = 0.0

#: About how long a compile takes (seconds): a run projected to need more than this
#: uncompiled waits for the background compiler when no core is idle (see worth_waiting).
COMPILE_GUESS = 20.0
#: The longest a run waits for the background compiler before going on uncompiled.
MAX_WAIT = 300.0

_PKG = Path(__file__).resolve().parent
_started = False
_proc = None


def _folder() -> Path:
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
    return _folder() / f"rollingdisk-jit-{_key()}.ready"


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


def start_background_compile() -> bool:
    """Start, once per process, a detached process that fills the compile cache; True if
    one was started.  Never waits for it."""
    global _started, _proc
    if _started or ready() or importlib.util.find_spec("numba") is None:
        return False
    _started = True
    import subprocess

    env = dict(os.environ)
    src = str(_PKG.parent)
    env["PYTHONPATH"] = src + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    try:
        _proc = subprocess.Popen([sys.executable, "-m", "rollingdisk.engine.jit"], env=env,
                         stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, start_new_session=True, close_fds=True)
    except OSError:
        return False
    return True


def py_seconds() -> float:
    """Seconds this process has spent integrating uncompiled, over all its runs."""
    return _py_seconds


def spend(seconds: float) -> None:
    """Count ``seconds`` more of uncompiled integration against :data:`PY_BUDGET`."""
    global _py_seconds
    _py_seconds += max(0.0, float(seconds))


def budget_spent() -> bool:
    """Whether the process has integrated uncompiled for :data:`PY_BUDGET` s in total."""
    return _py_seconds >= PY_BUDGET


def pick_core(state: dict, elapsed: float, fraction: float):
    """The integrator for the next chunk of a run, by the rule of this module's docstring:
    ``(module, compiled)``.  ``state``: a dict kept by the run (what it has started or
    waited for); ``elapsed``: seconds the run has spent integrating uncompiled so far;
    ``fraction``: the part of its span done (for :func:`worth_loading` and
    :func:`worth_waiting`)."""
    if _core is not None:
        return _core, True
    if worth_loading(elapsed, fraction) and ready():
        jit_compile()  # loads from the on-disk cache
        return _core, True
    if budget_spent():
        cold = not ready()
        if cold and not state.get("spawned"):
            state["spawned"] = True
            start_background_compile()
        elif cold and not state.get("waited") and worth_waiting(elapsed, fraction):
            state["waited"] = True
            wait_ready()
        if ready():
            jit_compile()  # loads from the on-disk cache
            return _core, True
    from rollingdisk.engine import pycore

    return pycore, False


def worth_loading(elapsed: float, fraction: float) -> bool:
    """Whether a run that has spent ``elapsed`` seconds uncompiled on ``fraction`` of its
    span is projected to need more than :data:`LOAD_WORTH` seconds more uncompiled: with a
    warm cache it then loads the compiled code at once (rule 2 of the module docstring)."""
    if not 0.0 < fraction < 1.0 or not elapsed > 0.0:
        return False
    return elapsed * (1.0 - fraction) / fraction > LOAD_WORTH


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


def worth_waiting(elapsed: float, fraction: float) -> bool:
    """Whether a run that has spent ``elapsed`` seconds uncompiled on ``fraction`` of its
    span should wait for the background compiler: it would need more than
    :data:`COMPILE_GUESS` seconds more uncompiled, and no core is idle (load average of one
    minute at least the number of cores less one half), so that running on would only slow
    the compiler down.  With idle cores it runs on while the compiler works beside it."""
    if not 0.0 < fraction < 1.0:
        return False
    remaining = elapsed * (1.0 - fraction) / fraction
    try:
        busy = os.getloadavg()[0] >= (os.cpu_count() or 1) - 0.5
    except (AttributeError, OSError):  # pragma: no cover - no load average (Windows)
        busy = True
    return remaining > COMPILE_GUESS and busy


def _compiling_now() -> bool:
    """Whether some process holds the compiler's lock."""
    try:
        import fcntl
    except ImportError:  # pragma: no cover
        return _proc is not None and _proc.poll() is None
    try:
        with open(_folder() / "rollingdisk-jit.lock", "a") as lock:
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                return True
            fcntl.flock(lock, fcntl.LOCK_UN)
            return False
    except OSError:
        return False


def wait_ready(timeout: float = MAX_WAIT) -> bool:
    """Wait (polling, interruptible) until the cache is ready; False if no compiler is at
    work any more without having made it ready, or after ``timeout`` seconds."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if ready():
            return True
        ours_alive = _proc is not None and _proc.poll() is None
        if not ours_alive and not _compiling_now():
            return ready()
        time.sleep(0.2)
    return ready()


def _compile_here() -> int:
    """The background compiler: one at a time (a lock).  Not niced: a long run waits for
    it, a short one (under PY_BUDGET) never starts it."""
    folder = _folder()
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
    once the process has integrated uncompiled for ``PY_BUDGET`` seconds in total, filling
    a cold cache in a background process meanwhile (:mod:`rollingdisk.engine.jit`).
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
