"""The one ``method`` vocabulary of every front door that integrates.

Each word names who takes the steps, the same at every front door (``simulate``,
``simulate_coulomb``, ``run_sweep``, ``basin_sweep``, the command line); a front door
accepts the subset it has.  The same words come back in a result's ``method`` (a run in which
two methods took steps reports both, joined by ``+``, in the order they ran).

========== ==================================================================================
method     who takes the steps
========== ==================================================================================
``auto``   the library chooses (:func:`rollingdisk.engine.jit.auto_method` for
           ``simulate``; scipy's DOP853 then the compiled loop for ``simulate_coulomb``)
``dop853`` rollingdisk's Dormand-Prince 8(5,3) (:mod:`rollingdisk.engine.dop853`), compiled
           or not as the compile policy decides (:mod:`rollingdisk.engine.jit`)
``taylor`` the Taylor-series method (:mod:`rollingdisk.engine.taylor`, compiled)
``scipy``  scipy's ``DOP853`` stepped one step at a time from Python
``lsoda``  scipy's ``LSODA`` (switches to BDF where the problem is stiff), stepped from
           Python: for long micro-slip at the edge of the friction cone
========== ==================================================================================

Older spellings are accepted with a :class:`DeprecationWarning`: ``"compiled"`` (now
``"dop853"``) and ``"stiff"`` (now ``"lsoda"``) of ``simulate_coulomb``.
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence

from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["METHODS", "ALIASES", "check_method"]

#: Every method word and what it means (the table above).
METHODS = {
    "auto": "the library chooses",
    "dop853": "rollingdisk's DOP853, compiled or not as the compile policy decides",
    "taylor": "the Taylor-series method (compiled)",
    "scipy": "scipy's DOP853 stepped from Python",
    "lsoda": "scipy's LSODA (stiff-switching) stepped from Python",
}
#: Older spellings -> the word that means the same now.
ALIASES = {"compiled": "dop853", "stiff": "lsoda"}


def check_method(method, allowed: Sequence[str], *, name: str = "method") -> str:
    """The method word of ``method`` if the front door has it (an old spelling is mapped to
    its word with a :class:`DeprecationWarning`).

    Raises
    ------
    ParameterTypeError
        If ``method`` is not a string.
    ParameterError
        If it is no word of ``allowed``.
    """
    if not isinstance(method, str):
        raise ParameterTypeError(f"{name} must be a string, one of {tuple(allowed)}, got "
                                 f"{type(method).__name__}")
    if method in ALIASES and ALIASES[method] in allowed:
        warnings.warn(f"{name}={method!r} is now spelled {ALIASES[method]!r}",
                      DeprecationWarning, stacklevel=3)
        method = ALIASES[method]
    if method not in allowed:
        raise ParameterError(f"{name} must be one of {tuple(allowed)}, got {method!r}")
    return method
