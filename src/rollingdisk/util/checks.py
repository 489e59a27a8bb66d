"""Validators of the public boundary: a real number or an integer in a range, named in the error."""

from __future__ import annotations

import math

from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["check_real", "check_int", "check_span", "real_array"]


def check_real(name: str, value, *, low: float | None = None, high: float | None = None,
               low_open: bool = False, high_open: bool = False) -> float:
    """Return ``value`` as a float, or raise naming ``name`` and the allowed range.

    Booleans, strings and other non-numbers raise :class:`ParameterTypeError`; NaN,
    infinities and values out of range raise :class:`ParameterError`.
    """
    lo = "-inf" if low is None else f"{low:g}"
    hi = "inf" if high is None else f"{high:g}"
    left = "(" if low is None or low_open else "["
    right = ")" if high is None or high_open else "]"
    allowed = f"{left}{lo}, {hi}{right}"
    if isinstance(value, bool) or not isinstance(value, (int, float)) and not _is_numpy_real(value):
        raise ParameterTypeError(f"{name} must be a real number in {allowed}, got "
                                 f"{type(value).__name__} {value!r}")
    x = _as_float(value)
    if not math.isfinite(x):
        raise ParameterError(f"{name} must be a finite real number in {allowed}, got {x!r}")
    if low is not None and (x < low or (low_open and x == low)):
        raise ParameterError(f"{name} must lie in {allowed}, got {x!r}")
    if high is not None and (x > high or (high_open and x == high)):
        raise ParameterError(f"{name} must lie in {allowed}, got {x!r}")
    return x


def check_int(name: str, value, *, low: int | None = None, high: int | None = None) -> int:
    """Return ``value`` as an int, or raise naming ``name`` and the allowed range.

    Parameters
    ----------
    name : str
        The parameter's name, for the message.
    value : int
        An integer (``numpy`` integers and integral floats such as ``60.0`` are accepted).
    low, high : int, optional
        Inclusive bounds.

    Returns
    -------
    int

    Raises
    ------
    ParameterTypeError
        For a non-number (booleans and strings included).
    ParameterError
        For a fractional, non-finite or out-of-range value.

    Examples
    --------
    >>> check_int("frames", 60.0, low=2, high=2000)
    60
    """
    lo = "(-inf" if low is None else f"[{low:d}"
    hi = "inf)" if high is None else f"{high:d}]"
    allowed = f"{lo}, {hi}"
    if isinstance(value, bool) or not isinstance(value, (int, float)) and not _is_numpy_real(value):
        raise ParameterTypeError(f"{name} must be an integer in {allowed}, got "
                                 f"{type(value).__name__} {value!r}")
    x = _as_float(value)
    if not math.isfinite(x) or x != math.floor(x):
        raise ParameterError(f"{name} must be an integer in {allowed}, got {value!r}")
    n = int(value)
    if (low is not None and n < low) or (high is not None and n > high):
        raise ParameterError(f"{name} must be an integer in {allowed}, got {n!r}")
    return n


def real_array(name: str, value):
    """``value`` as a float ndarray (any shape), or raise naming ``name``.

    For the vectorized formulas, which take arrays and may return NaN outside their domain:
    NaN and infinities pass through, but a string, bytes or another non-number raises
    :class:`ParameterTypeError` and an integer beyond floating-point range (``10**400``,
    which numpy would turn into an ``OverflowError``) raises :class:`ParameterError`.

    Examples
    --------
    >>> real_array("theta0", [0.1, 0.2]).tolist()
    [0.1, 0.2]
    """
    import numpy as np

    if isinstance(value, (str, bytes)):
        raise ParameterTypeError(f"{name} must be a real number or an array of them, got "
                                 f"{type(value).__name__} {value!r}")
    try:
        return np.asarray(value, dtype=float)
    except OverflowError:
        raise ParameterError(f"{name} must lie within floating-point range (|x| <= 1.8e308), "
                             f"got an integer beyond it") from None
    except (TypeError, ValueError):
        raise ParameterTypeError(f"{name} must be a real number or an array of them, got "
                                 f"{type(value).__name__} {_short(value)}") from None


def _short(value) -> str:
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def _as_float(value) -> float:
    try:
        return float(value)
    except OverflowError:  # an int beyond floating-point range
        return math.inf if value > 0 else -math.inf


def _is_numpy_real(value) -> bool:
    try:
        import numpy as np
    except ImportError:  # pragma: no cover - numpy is a hard dependency
        return False
    return isinstance(value, (np.integer, np.floating)) or (
        isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf"
    )


def check_span(t_span) -> tuple[float, float]:
    """``t_span`` as ``(t0, t1)`` floats, finite with ``t1 > t0``, or ParameterError (a
    TypeError-free message for anything that is not a pair of real numbers)."""
    try:
        t0, t1 = (float(v) for v in t_span)
    except (TypeError, ValueError, OverflowError):
        raise ParameterError(f"t_span must be a pair (t0, t1) of real numbers, got "
                             f"{t_span!r}") from None
    if not (math.isfinite(t0) and math.isfinite(t1) and t1 > t0):
        raise ParameterError(f"t_span must be a pair (t0, t1) of finite numbers with t1 > t0,"
                             f" got {t_span!r}")
    return t0, t1
