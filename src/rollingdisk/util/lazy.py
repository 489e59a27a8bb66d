"""Lazy re-exports for package ``__init__`` modules (PEP 562).

A package lists its public names and the module that defines each; a name is imported on
first use, so ``import rollingdisk`` (and the console script's first instant, before its
signal handlers are in) imports no numeric module at all, and a command imports only what
it uses.  The same table serves ``__all__``, ``dir()`` and the API reference.

Old import paths, kept working for one release, are a second table: a module path that moved
maps to its new home, and importing the old path warns (``DeprecationWarning``) and hands
back the new module itself (:class:`MovedModules`).
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
import types
import warnings
from collections.abc import Callable, Mapping

__all__ = ["attach", "MovedModules"]


def attach(package: str, exports: Mapping[str, str]) -> tuple[Callable, Callable, list[str]]:
    """``(__getattr__, __dir__, __all__)`` for the package ``package``.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    exports : mapping of str to str
        Public name -> the module that defines it (absolute, e.g.
        ``"rollingdisk.theory.steady"``), in the order of ``__all__``.

    Returns
    -------
    tuple
        The module-level ``__getattr__`` (imports the defining module on first use and
        caches the value in the package's namespace), ``__dir__`` and ``__all__``.
    """
    table = dict(exports)
    names = list(table)

    def __getattr__(name: str):
        try:
            where = table[name]
        except KeyError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
        value = getattr(importlib.import_module(where), name)
        setattr(sys.modules[package], name, value)
        return value

    def __dir__():
        return sorted(set(names) | set(vars(sys.modules[package])))

    return __getattr__, __dir__, names


class _Alias(importlib.abc.Loader):
    """Loads an old module path as the module that now holds its code (with a warning)."""

    def __init__(self, new: str):
        self.new = new

    def create_module(self, spec):
        return None  # a placeholder; exec_module puts the real module in its place

    def exec_module(self, module):
        old = module.__name__
        warnings.warn(f"{old} moved to {self.new}; the old path will be removed in the "
                      f"next release", DeprecationWarning, stacklevel=2)
        target = importlib.import_module(self.new)
        # the import system returns what sys.modules holds under the old name: the real
        # module, whose own __spec__ and __name__ stay untouched
        sys.modules[old] = target


class MovedModules(importlib.abc.MetaPathFinder):
    """A finder for module paths that moved: ``{old dotted path: new dotted path}``.

    An old path that was a package with re-exports (``rollingdisk.integrate``) maps to
    ``None`` and gets a package of its own whose attributes resolve through ``names``
    (old attribute -> new module) with a warning.
    """

    def __init__(self, moved: Mapping[str, str | None], names: Mapping[str, Mapping[str, str]]):
        self.moved = dict(moved)
        self.names = {k: dict(v) for k, v in names.items()}

    def find_spec(self, fullname, path=None, target=None):
        if fullname not in self.moved:
            return None
        new = self.moved[fullname]
        if new is None:
            return importlib.machinery.ModuleSpec(fullname, _OldPackage(self.names[fullname]),
                                                  is_package=True)
        return importlib.machinery.ModuleSpec(fullname, _Alias(new))


class _OldPackage(importlib.abc.Loader):
    """An old package: empty, its former re-exports resolved on first use, with a warning."""

    def __init__(self, names: Mapping[str, str]):
        self.names = names

    def create_module(self, spec):
        return None

    def exec_module(self, module: types.ModuleType):
        module.__path__ = []
        names = self.names
        package = module.__name__

        def __getattr__(name):
            if name not in names:
                raise AttributeError(f"module {package!r} has no attribute {name!r}")
            warnings.warn(f"{package}.{name} moved to {names[name]}.{name}; the old path "
                          f"will be removed in the next release", DeprecationWarning,
                          stacklevel=2)
            value = getattr(importlib.import_module(names[name]), name)
            setattr(module, name, value)  # warned once
            return value

        module.__getattr__ = __getattr__
        module.__all__ = list(names)
