"""Parsing quantities with units: ``"23.25mm"``, ``"7.5g"``, pint quantities -> SI floats.

Parsed by pint (imported only when a unit is written, so ``import rollingdisk`` stays light).
This module imports nothing of the disk, so that :class:`rollingdisk.Disk` can take quantities
(:mod:`rollingdisk.model.units` re-exports the parsers).
"""

from __future__ import annotations

import math
import re
from functools import lru_cache

import numpy as np

from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["parse_length", "parse_mass", "parse_acceleration"]


# ------------------------------------------------------------------------------ parsing
#: What each parser expects: pint's dimensionality, the SI unit, and examples for messages.
_EXPECT = {
    "length": ("[length]", "m", "a length such as 23.25mm, 0.9in or a plain number in metres"),
    "mass": ("[mass]", "kg", "a mass such as 7.5g, 0.45kg or a plain number in kilograms"),
    "acceleration": ("[length] / [time] ** 2", "m/s^2",
                     "an acceleration such as 9.81m/s^2, 1g0 or a plain number in m/s^2"),
}

_DIMENSION_WORDS = {
    "[length]": "a length", "[mass]": "a mass", "[time]": "a time",
    "[length] / [time] ** 2": "an acceleration", "[length] / [time]": "a speed",
    "dimensionless": "a plain number", "[length] ** 2": "an area",
    "[length] ** 3": "a volume", "[temperature]": "a temperature",
    "1 / [time]": "an angular speed (or a rate)", "[time] / [length]": "an inverse speed",
    "[mass] * [length] ** 2 / [time]": "an angular momentum (a moment per angular speed)",
}


@lru_cache(maxsize=1)
def _registry():
    """pint's unit registry, built once (about half a second) and only when a unit is used."""
    import pint

    return pint.UnitRegistry()


def _is_quantity(value) -> bool:
    """Whether ``value`` is a pint quantity (of any registry)."""
    return hasattr(value, "dimensionality") and hasattr(value, "to") and \
        hasattr(value, "magnitude")


def _from_quantity(q, dim: str, si_unit: str, expect: str, name: str) -> float:
    """A pint quantity of dimension ``dim`` as a float in ``si_unit``."""
    got = str(q.dimensionality)
    if got != dim:
        words = _DIMENSION_WORDS.get(got, f"of dimension {got}")
        raise ParameterError(f"{name} must be {expect}; got {q!r}, which is {words}")
    try:
        return float(q.to(si_unit).magnitude)
    except OverflowError:
        return math.inf
    except TypeError:
        raise ParameterTypeError(f"{name} must be {expect}, got {q!r} (not one number)") \
            from None


def _float_or_inf(value) -> float:
    """``float(value)``, an int beyond floating-point range (``10**400``) as ``inf``: the
    callers refuse it as not finite, with their message."""
    try:
        return float(value)
    except OverflowError:
        return math.inf


def _parse(value, kind: str, name: str) -> float:
    dim, si_unit, expect = _EXPECT[kind]
    if _is_quantity(value):
        value = _from_quantity(value, dim, si_unit, expect, name)
    if isinstance(value, bool) or not isinstance(value, (str, int, float, np.integer,
                                                         np.floating)):
        raise ParameterTypeError(f"{name} must be {expect}, got {type(value).__name__} "
                                 f"{value!r}")
    shown = repr(value) if isinstance(value, str) else f"{value!r}"
    if isinstance(value, str):
        text = value.strip()
        try:
            x = float(text)  # a plain number: SI, no pint needed
        except ValueError:
            x = _parse_with_unit(text, dim, si_unit, expect, name, shown)
    else:
        x = _float_or_inf(value)
    if not math.isfinite(x):
        what = "not a number" if math.isnan(x) else "beyond floating-point range"
        raise ParameterError(f"{name} must be {expect}, finite and positive; got {shown}, "
                             f"which is {what}")
    if x <= 0.0:
        raise ParameterError(f"{name} must be positive ({expect}), got {shown}")
    return x


#: A power whose exponent is itself raised to a power (``10**10**10``): pint would compute
#: it exactly, for ever; such input is refused before it reaches pint.
_NESTED_POWER = re.compile(r"(\*\*|\^)\s*[-+(\s]*[\d.]+([eE][-+]?\d+)?\s*\)?\s*(\*\*|\^)")
_EXPONENT = re.compile(r"(?:\*\*|\^)\s*[-+(\s]*([\d.]+(?:[eE][-+]?\d+)?)")
#: Longest text handed to pint.
_MAX_TEXT = 200


def _parse_with_unit(text, dim, si_unit, expect, name, shown) -> float:
    return _quantity_of(text, dim, si_unit, expect, name, shown)[0]


def _quantity_of(text, dim, si_unit, expect, name, shown) -> tuple[float, str]:
    """``text`` read by pint, in ``si_unit``; ``dim`` and ``si_unit`` may be tuples of
    alternatives (the one that matched is returned beside the value)."""
    dims = (dim,) if isinstance(dim, str) else tuple(dim)
    units = (si_unit,) if isinstance(si_unit, str) else tuple(si_unit)
    if not any(ch.isdigit() for ch in text):
        raise ParameterError(f"{name} must be {expect}: a number with a unit, got {shown}")
    if len(text) > _MAX_TEXT or _NESTED_POWER.search(text) or any(
            float(e) > 1000.0 for e in _EXPONENT.findall(text)):
        raise ParameterError(f"{name} must be {expect}; got {shown}, too long or with "
                             "powers beyond floating-point range")
    ureg = _registry()
    try:
        q = ureg.Quantity(text)
    except Exception as exc:  # pint raises many kinds (undefined unit, syntax, ...)
        import pint

        if isinstance(exc, pint.errors.UndefinedUnitError):
            why = f"unknown unit ({exc})"
        else:
            why = f"not a quantity pint can read ({type(exc).__name__}: {exc})"
        raise ParameterError(f"{name} must be {expect}; got {shown}: {why}") from None
    if not isinstance(q, ureg.Quantity):  # e.g. "2*3" is a plain number
        q = ureg.Quantity(float(q), "")
    got = str(q.dimensionality)
    if got not in dims:
        words = _DIMENSION_WORDS.get(got, f"of dimension {got}")
        raise ParameterError(f"{name} must be {expect}; got {shown}, which is {words}")
    unit = units[dims.index(got)]
    try:
        return float(q.to(unit).magnitude), unit
    except OverflowError:
        return math.inf, unit


def parse_length(value, name: str = "length") -> float:
    """A length in metres from ``"23.25mm"``, ``"0.9 in"``, ``"2.5cm"`` or a plain number (m).

    Parameters
    ----------
    value : str or float
        A number with a unit pint knows, or a plain number taken as metres.
    name : str
        The option's name, for messages (e.g. ``"--radius"``).

    Returns
    -------
    float
        The length [m], finite and ``> 0``.

    Raises
    ------
    ParameterError
        Another dimension (``"3kg"``), an unknown unit, a value that is not positive or
        beyond floating-point range (``"1e400mm"``); the message names ``name`` and what it
        expects.
    ParameterTypeError
        Neither a string nor a real number.

    Examples
    --------
    >>> parse_length("23.25mm")
    0.02325
    >>> parse_length(0.5)
    0.5
    """
    return _parse(value, "length", name)


def parse_mass(value, name: str = "mass") -> float:
    """A mass in kilograms from ``"7.5g"``, ``"0.45 kg"``, ``"1 lb"`` or a plain number (kg).

    As :func:`parse_length`, for masses.

    Examples
    --------
    >>> parse_mass("7.5g")
    0.0075
    """
    return _parse(value, "mass", name)


def parse_acceleration(value, name: str = "gravity") -> float:
    """An acceleration in m/s^2 from ``"9.81m/s^2"``, ``"1.62 m/s**2"``, ``"1g0"`` (standard
    gravity) or a plain number (m/s^2).

    As :func:`parse_length`, for accelerations.  (``"1g"`` is a gram, a mass; standard
    gravity is ``g0``.)

    Examples
    --------
    >>> parse_acceleration("9.81m/s^2")
    9.81
    """
    return _parse(value, "acceleration", name)
