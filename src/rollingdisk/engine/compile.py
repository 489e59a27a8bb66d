"""Compile a namespace of plain-Python numeric functions with numba (the one service the
layers above ``integrate`` use to get compiled code; only ``integrate`` imports numba).

The trick of :mod:`rollingdisk.engine.numba_core`, made generic: every named function's
code object is re-bound to the namespace ``ns`` (so that the functions it calls by global
name are the compiled versions found there), then handed to ``numba.njit(cache=True)``; the
compiled dispatcher replaces the function in ``ns``.  Building blocks of
:mod:`rollingdisk.engine.dop853` (``_step``, ``_combine``, ``_dense_coefficients``, ...)
can thus be compiled around a right-hand side ``_rhs(p, h, y, out)`` of another layer (a
Coulomb mode, :mod:`rollingdisk.ivp.fastsegment`): numba is duck-typed, so the
argument that DOP853 calls ``rough`` may be any value the caller's ``_rhs`` understands.

numba's on-disk cache is keyed by each function's source file, qualified name and argument
types; a function compiled in two namespaces with the same argument types would share one
cache entry, so a caller must give its own right-hand side a different argument type (a
parameter array instead of ``rough: bool``) or its own names.  The cache does not notice an
edit of a called function in another file: a caller checks the compiled result against its
Python kernels (and calls :func:`recompile`) as :func:`rollingdisk.engine.jit.jit_compile`
does.
"""

from __future__ import annotations

import types
from collections.abc import Iterable, Sequence

__all__ = ["compile_namespace", "recompile", "numba_available", "source_key", "marker_key",
           "write_marker", "announce"]

#: source_key by module names: the sources do not change under a running process, and the
#: hash is asked for on every compiled-or-not decision.
_KEYS: dict = {}


def numba_available() -> bool:
    """Whether numba can be imported (without importing it)."""
    import importlib.util

    return importlib.util.find_spec("numba") is not None


def source_key(*modules) -> str:
    """A short hash of the source files of ``modules`` (a package stands for every ``.py``
    file of its folder), for :func:`compile_namespace`'s ``key``.

    numba keys its on-disk cache of a function by that function's own file alone: a
    compiled caller from the cache keeps the machine code of its callees as they were
    when it was compiled.  After an edit of a callee in another file (a parameter array or
    an event vector grown by one) such a caller indexed past its arrays and the process
    died with a segmentation fault before any check could run (seen on the Coulomb loop).
    Naming the compiled functions after the hash of every file they may call gives each
    version of the sources its own cache entries."""
    import hashlib
    from pathlib import Path

    names = tuple(m.__name__ for m in modules)
    if names not in _KEYS:
        digest = hashlib.sha1()
        for m in modules:
            path = Path(m.__file__)
            files = sorted(path.parent.glob("*.py")) if path.name == "__init__.py" else [path]
            for f in files:
                digest.update(f.name.encode())
                digest.update(f.read_bytes())
        _KEYS[names] = digest.hexdigest()[:12]
    return _KEYS[names]


def marker_key(*modules) -> str:
    """The name of a filled cache's mark for code compiled from ``modules``: their
    :func:`source_key` (the key in the compiled functions' names) with the Python version
    and numba's (its ``__init__.py``'s size and time), so that a mark never says "ready"
    for a cache the compiled names do not find."""
    import hashlib
    import importlib.util
    import sys
    from pathlib import Path

    parts = [sys.version, source_key(*modules)]
    spec = importlib.util.find_spec("numba")
    if spec is not None and spec.origin:
        try:
            st = Path(spec.origin).stat()
            parts.append(f"{spec.origin}:{st.st_size}:{st.st_mtime_ns}")
        except OSError:
            parts.append("numba:missing")
    return hashlib.sha1("|".join(parts).encode()).hexdigest()[:16]


def write_marker(path, text: str) -> None:
    """Create the mark ``path`` whole or not at all (a temporary file renamed over it); a
    folder that cannot be written leaves no mark (the next run compiles again)."""
    import os

    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(f"{path.name}.{os.getpid()}.tmp")
        tmp.write_text(text)
        os.replace(tmp, path)
    except OSError:
        pass


def compile_namespace(ns: dict, names: Sequence[str], *, cache: bool = True,
                      key: str = "") -> dict:
    """Compile the functions ``names`` of the namespace ``ns`` in place, in that order.

    Parameters
    ----------
    ns : dict
        Global namespace of the functions: every global name they use (helpers, constants,
        ``np``) must resolve there.  Modified in place: each name becomes its compiled
        dispatcher (lazily compiled on first call, from the on-disk cache when it is there).
    names : sequence of str
        The functions to compile; functions called by them must be compiled too (listed)
        or be numba-compilable globals already.
    cache : bool
        ``numba.njit(cache=True)`` (default).
    key : str
        Appended to each function's qualified name, which numba's cache is keyed by: pass
        :func:`source_key` of every module the functions may call, so that a stale cache
        entry is never loaded.

    Returns
    -------
    dict
        ``ns`` itself.

    Raises
    ------
    ImportError
        If numba is missing.
    KeyError
        If a name is not in ``ns``.
    """
    import numba

    for name in names:
        f = ns[name]
        g = types.FunctionType(f.__code__, ns, f.__name__, f.__defaults__, f.__closure__)
        g.__qualname__ = f"{f.__qualname__}_{key}" if key else f.__qualname__
        g.__module__ = f.__module__
        ns[name] = numba.njit(cache=cache)(g)
    return ns


def recompile(ns: dict, names: Iterable[str]) -> None:
    """Recompile the compiled functions ``names`` of ``ns`` from their current sources
    (refreshing a stale on-disk cache)."""
    for name in names:
        d = ns[name]
        if getattr(d, "signatures", None):
            d.recompile()


def announce(line: str) -> None:
    """Say on a terminal, in one line on stderr, that a compile is starting (it can take a
    minute and would otherwise look like a hang); silent when stderr is not a terminal."""
    import sys

    stream = sys.stderr
    try:
        if stream is not None and stream.isatty():
            stream.write(f"rollingdisk: {line}\n")
            stream.flush()
    except (OSError, ValueError):  # a closed or broken stderr: nothing to say it on
        pass
