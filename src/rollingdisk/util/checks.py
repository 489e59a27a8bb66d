"""Validators of the public boundary: a real number or an integer in a range, named in the error.

What counts as a real number here: ``int`` (not ``bool``), ``float``, numpy integers and
floats, and 0-d numpy arrays of them.  A value that is none of these (``None``, a string,
bytes, a complex number, a boolean, a ``decimal.Decimal`` or ``fractions.Fraction`` --
convert those with ``float()`` first --, an object) is a :class:`ParameterTypeError`; NaN,
infinities, an integer beyond floating-point range (``10**400``) and a masked (missing)
entry of a ``numpy.ma`` array are a :class:`ParameterError` naming the parameter and its
range -- never the ``OverflowError``, ``decimal.InvalidOperation`` or ``MaskError`` that
converting them with ``float`` or comparing them would raise.
"""

from __future__ import annotations

import math

from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["check_real", "check_int", "check_span", "real_array", "check_instance",
           "check_sign"]


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
    if not _is_real(value):
        raise ParameterTypeError(f"{name} must be a real number in {allowed}, got "
                                 f"{type(value).__name__} {_short(value)}")
    x = _as_float(name, value)
    if not math.isfinite(x):
        raise ParameterError(f"{name} must be a finite real number in {allowed}, got "
                             f"{_short(value)}")
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
    if not _is_real(value):
        raise ParameterTypeError(f"{name} must be an integer in {allowed}, got "
                                 f"{type(value).__name__} {_short(value)}")
    x = _as_float(name, value)
    if not math.isfinite(x) or x != math.floor(x):
        raise ParameterError(f"{name} must be an integer in {allowed}, got {_short(value)}")
    n = int(value)
    if (low is not None and n < low) or (high is not None and n > high):
        raise ParameterError(f"{name} must be an integer in {allowed}, got {n!r}")
    return n


def real_array(name: str, value):
    """``value`` as a float ndarray (any shape), or raise naming ``name``.

    For the vectorized formulas, which take arrays and may mark points outside their
    domain with NaN: NaN and infinities pass through, but a string, bytes, a boolean, a
    complex number, a ``Decimal`` or another non-number raises :class:`ParameterTypeError`,
    and an integer beyond floating-point range (``10**400``, which numpy would turn into an
    ``OverflowError``) and a masked entry of a ``numpy.ma`` array (a missing value, which
    ``numpy`` would silently read as its fill value) raise :class:`ParameterError`.  A
    masked array with nothing masked is its data.

    Examples
    --------
    >>> real_array("theta0", [0.1, 0.2]).tolist()
    [0.1, 0.2]
    """
    import numpy as np

    def wrong_type():
        return ParameterTypeError(f"{name} must be a real number or an array of them, got "
                                  f"{type(value).__name__} {_short(value)}")

    if isinstance(value, (str, bytes, bool, complex)) or value is None:
        raise wrong_type()
    if np.ma.isMaskedArray(value):
        if np.ma.count_masked(value):
            raise ParameterError(f"{name} has masked (missing) entries: fill them or pass a "
                                 f"plain array")
        value = np.ma.getdata(value)
    try:
        raw = np.asarray(value)
        if raw.dtype.kind not in "iuf":
            if raw.dtype.kind != "O" or any(not _is_real(v) for v in raw.flat):
                raise wrong_type()
        return raw.astype(float) if raw.dtype != float else raw
    except OverflowError:
        raise ParameterError(f"{name} must lie within floating-point range (|x| <= 1.8e308), "
                             f"got a value beyond it") from None
    except (TypeError, ValueError) as exc:
        if isinstance(exc, (ParameterTypeError, ParameterError)):
            raise
        raise wrong_type() from None


def check_instance(name: str, value, kind: type, what: str):
    """Return ``value`` if it is a ``kind``, else :class:`ParameterTypeError` naming
    ``name`` and ``what`` it must be (e.g. ``"a Trajectory (the result of simulate)"``)."""
    if not isinstance(value, kind):
        raise ParameterTypeError(f"{name} must be {what}, got {type(value).__name__} "
                                 f"{_short(value)}")
    return value


def _short(value) -> str:
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 - a repr that fails is no reason to hide the error
        text = f"<{type(value).__name__}>"
    text = " ".join(text.split())
    return text if len(text) <= 80 else text[:77] + "..."


def _is_real(value) -> bool:
    """A real number: int (not bool), float, a numpy integer or float, or a 0-d array of
    one (a masked one included: :func:`_as_float` refuses its mask)."""
    if isinstance(value, bool):
        return False
    return isinstance(value, (int, float)) or _is_numpy_real(value)


def _as_float(name: str, value) -> float:
    """``float(value)`` for a real :func:`_is_real` accepted; beyond floating-point range an
    infinity of its sign; a masked entry or a signalling NaN a :class:`ParameterError`."""
    import numpy as np

    if np.ma.isMaskedArray(value):
        if np.ma.count_masked(value):
            raise ParameterError(f"{name} is masked (a missing value): pass a number")
        value = np.ma.getdata(value)
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
    bad = ParameterError(f"t_span must be a pair (t0, t1) of real numbers, got "
                         f"{_short(t_span)}")
    try:
        pair = list(t_span)
    except TypeError:
        raise bad from None
    if len(pair) != 2 or not all(_is_real(v) for v in pair):
        raise bad
    t0, t1 = (_as_float("t_span", v) for v in pair)
    if not (math.isfinite(t0) and math.isfinite(t1) and t1 > t0):
        raise ParameterError(f"t_span must be a pair (t0, t1) of finite numbers with t1 > t0,"
                             f" got {_short(t_span)}")
    return t0, t1


def check_sign(name: str, value) -> int:
    """``value`` as the int ``+1`` or ``-1`` (a side, a sign), or raise naming ``name``.

    Any real number equal to +-1 is accepted (``1.0``, ``numpy.int64(-1)``).  A boolean is
    a :class:`ParameterError` (``True == 1`` would otherwise slip through); a ``Decimal``
    (whose NaN raises ``decimal.InvalidOperation`` when compared) a
    :class:`ParameterTypeError`, like any other non-number.
    """
    if isinstance(value, bool):
        raise ParameterError(f"{name} must be +1 or -1 (a number, not a boolean), got {value!r}")
    if not _is_real(value):
        raise ParameterTypeError(f"{name} must be +1 or -1, got {type(value).__name__} "
                                 f"{_short(value)}")
    x = _as_float(name, value)
    if x not in (1.0, -1.0):
        raise ParameterError(f"{name} must be +1 or -1, got {_short(value)}")
    return int(x)
