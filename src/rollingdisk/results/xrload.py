"""xarray, imported without importing dask, pint, sparse or cupy until something uses them.

xarray asks, for every plain numpy array put into a ``Variable``, whether it is a dask
array (``isinstance(data, array_type("dask"))``, and ``is_dask_collection``), and, for every
index, whether it is a pint, sparse or cupy array; the first such question imports that
package when it is installed (``dask.array`` alone about 1 s on a 2-core machine, measured
by ``benchmarks/startup.py``).  No object can be an instance of a class of a package that
has not been imported, so the answer "no" is exact until then: this module registers, in
xarray's cache of duck-array modules, an entry per package that answers so and hands every
other question (version, module, availability) to xarray's own ``DuckArrayModule``, built on
first need; and it answers ``is_dask_collection`` with False while dask is not imported.
Once the package is imported (a Dask sweep, ``open_zarr`` with chunks) the answers are
xarray's own.

The entries are installed only where xarray keeps its cache where this module expects it
(``xarray.namedarray.pycompat._cached_duck_array_modules``); elsewhere xarray is returned
as it is.
"""

from __future__ import annotations

import sys

import xarray as xr

__all__ = ["xr", "dask_deferred"]

#: xarray's duck-array packages, and the module whose import makes their array type exist.
_DEFERRED = {"dask": "dask.array", "pint": "pint", "sparse": "sparse", "cupy": "cupy",
             "cubed": "cubed"}


class _DeferredDask:
    """xarray's duck-array entry for one package, exact without importing it."""

    def __init__(self, real_entry, module: str = "dask.array"):
        self._real_entry = real_entry  # callable: xarray's own DuckArrayModule(name)
        self._module = module
        self._real = None

    def _resolve(self):
        if self._real is None:
            self._real = self._real_entry()
        return self._real

    @property
    def type(self):
        if self._real is None and self._module not in sys.modules:
            return ()  # nothing is an instance of a class not yet defined
        return self._resolve().type

    def __getattr__(self, name):  # module, version, available: xarray's own answer
        if name.startswith("_"):
            raise AttributeError(name)
        return getattr(self._resolve(), name)


def dask_deferred() -> bool:
    """Install the deferred entries in xarray's cache (once); whether dask's is in place."""
    try:
        from xarray.namedarray import pycompat
    except ImportError:  # pragma: no cover - another xarray layout: left as it is
        return False
    cache = getattr(pycompat, "_cached_duck_array_modules", None)
    make = getattr(pycompat, "DuckArrayModule", None)
    if not isinstance(cache, dict) or make is None:  # pragma: no cover - another layout
        return False
    for name, module in _DEFERRED.items():
        if name not in cache:
            cache[name] = _DeferredDask(lambda name=name: make(name), module)
    _defer_dask_collections()
    return isinstance(cache["dask"], _DeferredDask)


def _defer_dask_collections() -> None:
    """``is_dask_collection(x)`` is False while dask is not imported (no dask collection
    exists then); xarray's own answer once it is."""
    from xarray.namedarray import utils

    real = getattr(utils, "is_dask_collection", None)
    if real is None or getattr(real, "_rollingdisk_deferred", False):
        return

    def is_dask_collection(x):
        return "dask" in sys.modules and real(x)

    is_dask_collection._rollingdisk_deferred = True
    is_dask_collection.__doc__ = real.__doc__
    utils.is_dask_collection = is_dask_collection


dask_deferred()
