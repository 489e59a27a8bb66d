"""When the compiled integrator is worth loading, and filling a cold compile cache.

Loading the numba integrator costs about 0.5 s (``import numba`` and the cached machine
code), compiling it with an empty cache 10-20 s; the same integrator run uncompiled
(:mod:`rollingdisk._pycore`) takes about 30 times as long per step as compiled.  So
:func:`rollingdisk.simulate` starts every run uncompiled and

* if the compiled code is already loaded in this process, uses it from the start;
* if the run is not done after :data:`PY_BUDGET` seconds and the on-disk cache is ready,
  loads the compiled code (0.5 s) and continues with it (the very same steps: the run
  pauses and resumes);
* if the cache is cold, starts :func:`start_background_compile`: a detached process that
  compiles and fills the on-disk cache, then marks it ready; the run goes on
  uncompiled and switches once the mark appears.  The user never waits for a compiler.

The mark is a file named after the sources (path, size and modification time of
``_dop853.py``, ``equations.py``, ``_numba_core.py`` and numba's own ``__init__.py``) and
the Python version, in the folder of numba's cache (``NUMBA_CACHE_DIR`` or the package's
``__pycache__``, else a user cache folder).  Two processes may start a compiler at once:
the compiler takes an exclusive lock (``fcntl.flock``) and a second one leaves at once;
numba itself writes its cache files atomically.

Run as ``python -m rollingdisk._jit`` it is that background compiler.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
from pathlib import Path

#: Seconds of uncompiled integration after which a run switches to the compiled code
#: (about what loading it costs, so a run never pays more than twice the best choice).
PY_BUDGET = 0.4

_PKG = Path(__file__).resolve().parent
_started = False


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
    parts = [sys.version]
    spec = importlib.util.find_spec("numba")
    files = [_PKG / "_dop853.py", _PKG / "equations.py", _PKG / "_numba_core.py"]
    if spec is not None and spec.origin:
        files.append(Path(spec.origin))
    for f in files:
        try:
            st = f.stat()
            parts.append(f"{f}:{st.st_size}:{st.st_mtime_ns}")
        except OSError:
            parts.append(f"{f}:missing")
    return hashlib.sha1("|".join(parts).encode()).hexdigest()[:16]


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
    m = marker()
    try:
        m.parent.mkdir(parents=True, exist_ok=True)
        tmp = m.with_name(f"{m.name}.{os.getpid()}.tmp")
        tmp.write_text("numba cache of rollingdisk's integrator is filled\n")
        os.replace(tmp, m)
    except OSError:
        pass


def start_background_compile() -> bool:
    """Start, once per process, a detached process that fills the compile cache; True if
    one was started.  Never waits for it."""
    global _started
    if _started or ready() or importlib.util.find_spec("numba") is None:
        return False
    _started = True
    import subprocess

    env = dict(os.environ)
    src = str(_PKG.parent)
    env["PYTHONPATH"] = src + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    try:
        subprocess.Popen([sys.executable, "-m", "rollingdisk._jit"], env=env,
                         stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, start_new_session=True, close_fds=True)
    except OSError:
        return False
    return True


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
    from ._simulate import jit_compile

    jit_compile()  # compiles, fills the cache and marks it ready
    return 0


if __name__ == "__main__":
    sys.exit(_compile_here())
