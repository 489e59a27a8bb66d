"""One point of a vectorized formula: its domain checked, a NaN answer refused.

The closed forms of sections 3 and 4 take arrays (the maps of Figures 4-8) and mark the
points outside their domain with NaN, so that a map shows a hole there.  Called at a single
point (every numeric argument a scalar or a 0-d array) the same NaN would be a silent
wrong answer, so there the domain is checked first -- ``0 <= h <= H_MAX`` (the
:class:`~rollingdisk.Disk`), ``|theta0| < pi/2`` (the disk stands on a rim edge, eq. 4),
every other argument finite -- and a NaN the formula still gives (a singular point of the
equation, named by the function) is a :class:`~rollingdisk.ParameterError` naming it.
"""

from __future__ import annotations

import functools
import inspect
import math

import numpy as np

from rollingdisk.model.disk import check_h, h_of
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["at_a_point", "why_overflow"]


def at_a_point(names: tuple, why_nan=None):
    """Decorate a vectorized formula whose numeric arguments are ``names``.

    ``why_nan(values) -> str`` says why the formula has no value at an in-domain point
    where it gives NaN (the message of the :class:`ParameterError`); ``None`` keeps a NaN
    answer at a point (where NaN is a documented answer, e.g. "no root").
    """

    def wrap(func):
        sig = inspect.signature(func)

        @functools.wraps(func)
        def inner(*args, **kwargs):
            values = sig.bind(*args, **kwargs).arguments
            if not all(np.ndim(h_of(values[n])) == 0 for n in names if n in values):
                return func(*args, **kwargs)
            checked = {}
            for n in names:
                if n not in values:
                    continue
                if n == "h":
                    checked[n] = check_h(values[n])
                elif n == "theta0":
                    checked[n] = check_real(n, values[n], low=-math.pi / 2, high=math.pi / 2,
                                            low_open=True, high_open=True)
                else:
                    checked[n] = check_real(n, values[n])
            out = func(*args, **kwargs)
            if why_nan is not None and _has_nan(out):
                at = ", ".join(f"{n}={v!r}" for n, v in checked.items())
                raise ParameterError(f"{func.__name__}({at}): {why_nan(checked)}")
            return out

        inner.__wrapped__ = func
        return inner

    return wrap


def _has_nan(out) -> bool:
    parts = out if isinstance(out, tuple) else (out,)
    return any(bool(np.any(np.isnan(np.asarray(p, dtype=float)))) for p in parts)


def why_overflow(eq: str):
    """The ``why_nan`` of a formula whose only NaN in its domain is an overflow (a huge
    argument, e.g. ``omega30 = 1e308``): the message names the equation."""
    return lambda values: (f"the terms of eq. ({eq}) overflow floating-point range at "
                           f"these values")
