"""The examples in the docstrings under src/rollingdisk run and print what they show.

Every module of the package is imported and its docstring examples run with doctest (the
README's test command collects this file, so CI runs them).  The symbolic package is
left out: its examples would rebuild the sympy derivation (tested in test_derivation.py).
"""

import doctest
import importlib
import pkgutil

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402

import rollingdisk  # noqa: E402

SKIP = ("rollingdisk.symbolic", "rollingdisk.__main__")
MODULES = sorted(m.name for m in pkgutil.walk_packages(rollingdisk.__path__, "rollingdisk.")
                 if not m.name.startswith(SKIP))


@pytest.mark.parametrize("name", ["rollingdisk", *MODULES])
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {name}"
