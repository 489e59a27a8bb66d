"""The library's own errors: bad input of the right kind, never a bug in disguise.

Every check of a public argument raises one of these (they subclass the built-in errors
numpy and scipy raise, so ``except ValueError`` still works).  The command line turns
exactly these into a one-line message and exit status 2; any other exception is a bug and
is reported as one (exit status 1, with its traceback).

* :class:`ParameterError` (a ``ValueError``): a value out of its allowed range, or a
  request that is impossible (the message says what would work);
* :class:`ParameterTypeError` (a ``TypeError``): an argument of the wrong type.
"""

from __future__ import annotations

__all__ = ["ParameterError", "ParameterTypeError", "INPUT_ERRORS"]


class ParameterError(ValueError):
    """A parameter out of its allowed range, or an impossible request (message says why)."""


class ParameterTypeError(TypeError):
    """A parameter of the wrong type (e.g. a string where a number is needed)."""


#: The exceptions that mean "bad input" (CLI exit status 2); anything else is a bug.
INPUT_ERRORS = (ParameterError, ParameterTypeError)
