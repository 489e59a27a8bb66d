"""The way in: a dimensional input (a time, a length, a speed, ...) in the paper's units.

The rule, the same in Python and on the command line:

* a number (``2.0``) is in the paper's units (m = a = g = 1: time ``sqrt(a/g)``, length
  ``a``, speed ``sqrt(a g)``, angular speed ``sqrt(g/a)``), the units the whole library
  computes in;
* a pint quantity (``Quantity(2, "s")``) or text with a unit (``"2 s"``, ``"5cm"``,
  ``"30rad/s"``, ``"0.3m/s"``) is SI, converted with the disk's physical scale (it needs
  one: :meth:`rollingdisk.Disk.time_from_si` and the like);
* text with the suffix ``a`` (``"20a"``) is in the paper's units;
* text without a unit (``"20"``, as every command-line value is typed) is refused for a disk
  with a physical size, since it could mean either; the one-line message names both
  spellings.  For a disk without a physical size it is in the paper's units.

:func:`to_paper` applies the rule; :func:`read_input` reads without a disk (the command line
checks a value when it is read, before the disk is known); :func:`from_si` is the inverse of
:func:`rollingdisk.model.units.to_si`.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.model.quantity import (
    _DIMENSION_WORDS,
    _float_or_inf,
    _from_quantity,
    _is_quantity,
    _quantity_of,
)
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["INPUT_KINDS", "PAPER_SUFFIX", "read_input", "from_si", "to_paper"]

#: Kinds of dimensional input: kind -> (pint dimensions accepted, their SI units, the SI unit
#: in words, the unit in the paper's units, what it is).  ``rolling_rate`` is a rolling rate
#: ``d phi/dt`` given as an angular speed or as the speed of C rolling without slip
#: (``v_C = a d phi/dt``, eq. 18: in the paper's units the same number).
INPUT_KINDS: dict[str, tuple[tuple[str, ...], tuple[str, ...], str, str, str]] = {
    "time": (("[time]",), ("s",), "seconds", "sqrt(a/g)", "a time"),
    "length": (("[length]",), ("m",), "metres", "a", "a length"),
    "speed": (("[length] / [time]",), ("m/s",), "metres per second", "sqrt(a g)", "a speed"),
    "angular_speed": (("1 / [time]",), ("rad/s",), "radians per second", "sqrt(g/a)",
                      "an angular speed"),
    "rolling_rate": (("1 / [time]", "[length] / [time]"), ("rad/s", "m/s"),
                     "radians per second; or 0.3m/s, the speed of C", "sqrt(g/a)",
                     "an angular speed or a speed"),
    "inverse_speed": (("[time] / [length]",), ("s/m",), "s/m", "1/sqrt(a g)",
                      "an inverse speed"),
    "moment_per_rate": (("[mass] * [length] ** 2 / [time]",), ("kg*m^2/s",), "kg m^2/s",
                        "m a^(3/2) g^(1/2)", "a moment per angular speed"),
}

#: The SI unit's kind of :data:`KINDS` for each input kind's SI unit (``from_si``).
_SI_KIND = {"s": "time", "m": "length", "m/s": "speed", "rad/s": "angular_speed",
            "s/m": "inverse_speed", "kg*m^2/s": "moment_per_rate"}

#: The paper-units suffix of text (``"20a"``): m = a = g = 1.
PAPER_SUFFIX = "a"


def _input_kind(kind: str):
    if kind not in INPUT_KINDS:
        raise ParameterError(f"kind must be one of {sorted(INPUT_KINDS)}, got {kind!r}")
    return INPUT_KINDS[kind]


def read_input(kind: str, value, name: str = "value") -> tuple[str, float, str | None]:
    """Read a dimensional input without a disk: how it was given, its number, its SI unit.

    Parameters
    ----------
    kind : str
        A key of :data:`INPUT_KINDS`.
    value : float, str or pint.Quantity
        ``2.0`` (the paper's units), ``"20a"`` (the paper's units), ``"20"`` (text without
        a unit), ``"2 s"`` or ``Quantity(2, "s")`` (SI).
    name : str
        For messages (``"--t-end"``, ``"t_end"``).

    Returns
    -------
    (how, x, unit) : tuple
        ``how`` is ``"paper"``, ``"bare"`` (text without a unit) or ``"si"``; ``x`` the
        number (finite); ``unit`` the SI unit of ``"si"`` (``"m/s"``, ...), else None.

    Raises
    ------
    ParameterError
        Another dimension, an unknown unit, a value that is not finite.
    ParameterTypeError
        Neither a number, a string nor a pint quantity.
    """
    dims, units, words, paper, what = _input_kind(kind)
    expect = (f"{what} (a number in the paper's units {paper}, or with a unit: "
              f"{' or '.join(units)})")
    how, unit = "paper", None
    if _is_quantity(value):
        got = str(value.dimensionality)
        if got not in dims:
            words_got = _DIMENSION_WORDS.get(got, f"of dimension {got}")
            raise ParameterError(f"{name} must be {expect}; got {value!r}, which is "
                                 f"{words_got}")
        unit = units[dims.index(got)]
        x, how = _from_quantity(value, got, unit, expect, name), "si"
    elif isinstance(value, str):
        text = value.strip()
        body = text[:-len(PAPER_SUFFIX)].strip() if text.endswith(PAPER_SUFFIX) else None
        try:
            x, how = float(text), "bare"
        except ValueError:
            try:
                x = float(body) if body is not None else None
            except ValueError:
                x = None
            if x is None:
                x, unit = _quantity_of(text, dims, units, expect, name, repr(value))
                how = "si"
    elif isinstance(value, bool) or not isinstance(value, (int, float, np.integer,
                                                           np.floating)):
        raise ParameterTypeError(f"{name} must be {expect}, got {type(value).__name__} "
                                 f"{value!r}")
    else:
        x = _float_or_inf(value)
    if not math.isfinite(x):
        raise ParameterError(f"{name} must be {expect}, finite; got {value!r}")
    return how, x, unit


def from_si(disk, kind: str, value):
    """``value`` (SI, a number or an array) of ``kind`` (a key of :data:`KINDS` or of
    :data:`INPUT_KINDS`) in the paper's units: the inverse of :func:`to_si`.

    Raises :class:`ParameterError` when ``disk`` lacks the scale.
    """
    if kind in ("angle", "dimensionless"):
        return value
    if kind == "length":
        return disk.length_from_si(value)
    if kind == "time":
        return disk.time_from_si(value)
    if kind == "speed":
        return disk.speed_from_si(value)
    if kind in ("angular_speed", "rate"):
        return disk.angular_speed_from_si(value)
    if kind == "rate_sq":
        return disk.angular_speed_from_si(disk.angular_speed_from_si(value))
    if kind == "force":
        return disk.force_from_si(value)
    if kind == "energy":
        return disk.energy_from_si(value)
    if kind == "inverse_speed":  # units 1/sqrt(a g): the inverse of a speed's
        return value / disk.speed_from_si(1.0)
    if kind == "moment_per_rate":  # units m a^(3/2) g^(1/2) = (m g a) / sqrt(g/a)
        return disk.energy_from_si(disk.angular_speed_to_si(value))
    raise ParameterError(f"kind must be a kind of quantity of rollingdisk.model.units.KINDS "
                         f"or {sorted(INPUT_KINDS)}, got {kind!r}")


def to_paper(disk, kind: str, value, name: str = "value") -> float:
    """A dimensional input in the paper's units, by the rule of this module (top).

    Parameters
    ----------
    disk : Disk or None
        The disk whose physical scale converts SI input (None: a disk without one).  (This
        module imports no Disk: :class:`rollingdisk.Disk` calls it.)
    kind : str
        A key of :data:`INPUT_KINDS` (``"time"``, ``"length"``, ``"speed"``,
        ``"angular_speed"``, ``"rolling_rate"``, ...).
    value : float, str or pint.Quantity
        See :func:`read_input`.
    name : str
        The parameter's name, for messages.

    Returns
    -------
    float
        The value in the paper's units (time ``sqrt(a/g)``, length ``a``, ...).

    Raises
    ------
    ParameterError
        Text without a unit for a disk with a physical size (the message names both
        spellings), SI input for a disk without one, or what :func:`read_input` refuses.

    Examples
    --------
    >>> from rollingdisk.model.units import disk_from_options
    >>> coin = disk_from_options(disk="euro-1")
    >>> round(to_paper(coin, "rolling_rate", "0.3 m/s"), 6)    # v_C / sqrt(a g)
    0.888514
    >>> to_paper(coin, "time", "20a"), to_paper(coin, "time", 20.0)
    (20.0, 20.0)
    """
    how, x, unit = read_input(kind, value, name)
    scaled = disk is not None and getattr(disk, "radius", None) is not None
    if how == "paper":
        return x
    dims, units, words, paper, _ = INPUT_KINDS[kind]
    if how == "bare":
        if not scaled:
            return x
        text = str(value).strip()
        sep = "" if name.endswith("=") else " "  # "--state omega3=2"
        raise ParameterError(
            f"{name}{sep}{text} is ambiguous with a physical disk: write {name}{sep}{text}"
            f"{units[0].replace('*', '')} ({words}) or {name}{sep}{text}{PAPER_SUFFIX} "
            f"(paper units, {paper})")
    if not scaled:
        sep = "" if name.endswith("=") else " "
        raise ParameterError(
            f"{name}{sep}{value} has a unit: it needs a disk with a physical size (--disk, "
            f"--radius or --diameter; Disk(radius=...)); without one give it in the paper's "
            f"units ({paper}) as a plain number")
    return float(from_si(disk, _SI_KIND[unit], x))
