"""xarray, imported without importing ``dask.array`` until something uses dask.

xarray asks, for every plain numpy array put into a ``Variable``, whether it is a dask
array: ``isinstance(data, array_type("dask"))``, and the first such question imports
``dask.array`` (about 1 s on a 2-core machine, measured by ``benchmarks/startup.py``) when
dask is installed.  No object can be an instance of ``dask.array.Array`` while
``dask.array`` has not been imported, so the answer ``()`` is exact until then; this module
registers, in xarray's cache of duck-array modules, an entry for dask that answers so and
hands every other question (version, module, availability) to xarray's own
``DuckArrayModule("dask")``, built on first need.  Once ``dask.array`` is imported (a Dask
sweep, ``open_zarr`` with chunks) the entry answers with the real type.

The entry is installed only where xarray keeps that cache where this module expects it
(``xarray.namedarray.pycompat._cached_duck_array_modules``); elsewhere xarray is returned
as it is.
"""

from __future__ import annotations

import sys

import xarray as xr

__all__ = ["xr", "dask_deferred"]


class _DeferredDask:
    """xarray's duck-array entry for dask, exact without importing ``dask.array``."""

    def __init__(self, real_entry):
        self._real_entry = real_entry  # callable: xarray's own DuckArrayModule("dask")
        self._real = None

    def _resolve(self):
        if self._real is None:
            self._real = self._real_entry()
        return self._real

    @property
    def type(self):
        if self._real is None and "dask.array" not in sys.modules:
            return ()  # nothing is a dask array before dask.array exists
        return self._resolve().type

    def __getattr__(self, name):  # module, version, available: xarray's own answer
        if name.startswith("_"):
            raise AttributeError(name)
        return getattr(self._resolve(), name)


def dask_deferred() -> bool:
    """Install the deferred dask entry in xarray's cache (once); whether it is in place."""
    try:
        from xarray.namedarray import pycompat
    except ImportError:  # pragma: no cover - another xarray layout: left as it is
        return False
    cache = getattr(pycompat, "_cached_duck_array_modules", None)
    make = getattr(pycompat, "DuckArrayModule", None)
    if not isinstance(cache, dict) or make is None:  # pragma: no cover - another layout
        return False
    if "dask" not in cache:
        cache["dask"] = _DeferredDask(lambda: make("dask"))
    return isinstance(cache["dask"], _DeferredDask)


dask_deferred()
