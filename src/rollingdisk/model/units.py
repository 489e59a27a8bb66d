"""Quantities with units at the edge: parsing ``23.25mm``, named disks, and SI views of results.

The numeric core computes in the paper's units (``m = a = g = 1``, :mod:`rollingdisk.model.disk`);
this module is where physical input comes in and physical output goes out:

* :func:`parse_length`, :func:`parse_mass`, :func:`parse_acceleration` (written in
  :mod:`rollingdisk.model.quantity`, which imports no disk): a string with a unit
  (``"23.25mm"``, ``"7.5g"``, ``"9.81m/s^2"``, ``"0.9in"``), a pint quantity or a plain
  number (taken as SI) -> a float in SI units.  Parsed by pint (imported only when a unit
  is written, so ``import rollingdisk`` stays light); wrong dimensions, non-positive
  values, overflow and unknown units raise
  :class:`~rollingdisk.util.errors.ParameterError` naming the option and what it expects;
* :data:`DISKS`: named everyday disks with their sources; :func:`disk_from_options`, the one
  function a command line calls to turn its options into a :class:`Disk`;
* :data:`KINDS` and :func:`si_view`: what each kind of quantity (time, length, speed, ...)
  is measured in, in the paper's units and in SI, and the conversion through a disk's
  physical scale; :func:`si_fields` gives the SI view of any result that has one;
* the way in, a dimensional input (a time, a speed, ...) in the paper's units, is
  :mod:`rollingdisk.model.inputs`.
"""

from __future__ import annotations

from dataclasses import dataclass

from rollingdisk.model.disk import DEFAULT_H, STANDARD_GRAVITY, Disk, check_h
from rollingdisk.model.quantity import parse_acceleration, parse_length, parse_mass
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["parse_length", "parse_mass", "parse_acceleration", "NamedDisk", "DISKS",
           "disk_from_options", "KINDS", "unit_of", "can_convert", "to_si", "si_view",
           "si_fields", "result_html"]


# ---------------------------------------------------------------------------- named disks
@dataclass(frozen=True)
class NamedDisk:
    """An everyday disk with its dimensions and where they come from.

    Attributes
    ----------
    name : str
        The name :func:`disk_from_options` accepts.
    radius : float
        ``a`` [m].
    thickness : float
        Full thickness ``2 h a`` [m].
    mass : float
        ``m`` [kg].
    source : str
        Where the numbers come from (and how approximate they are).
    """

    name: str
    radius: float
    thickness: float
    mass: float
    source: str

    @property
    def h(self) -> float:
        """Half-thickness in units of the radius, ``thickness / (2 radius)``."""
        return self.thickness / (2.0 * self.radius)

    def disk(self, *, mass: float | None = None, gravity: float = STANDARD_GRAVITY) -> Disk:
        """The :class:`Disk` with this physical scale (``mass`` overrides the listed one)."""
        return Disk.from_dimensions(self.radius, self.thickness,
                                    self.mass if mass is None else mass, gravity)


#: Named disks, name -> :class:`NamedDisk` (SI units).
DISKS: dict[str, NamedDisk] = {d.name: d for d in (
    NamedDisk("euler-disk", 0.0375, 0.0127, 0.45,
              "the commercial Euler's Disk (Tangent Toy Co.): 75 mm across, 12.7 mm (1/2 in) "
              "thick; sold at about 0.4-0.45 kg (Moffatt, Nature 404 (2000) 833, quotes "
              "a ~ 3.8 cm and uses m = 0.4 kg); as rollingdisk.scenarios.euler_disk.EulerDisk"),
    NamedDisk("euro-1", 0.02325 / 2, 0.00233, 0.0075,
              "1-euro coin: 23.25 mm diameter, 2.33 mm thick, 7.5 g (European Central Bank, "
              "common sides of the euro coins)"),
    NamedDisk("us-quarter", 0.02426 / 2, 0.00175, 0.00567,
              "US quarter dollar: 24.26 mm diameter, 1.75 mm thick, 5.670 g (United States "
              "Mint, coin specifications)"),
    NamedDisk("cd", 0.120 / 2, 0.0012, 0.016,
              "compact disc: 120 mm diameter, 1.2 mm thick, about 16 g (IEC 60908 / "
              "ECMA-130); treated as a full disk, the 15 mm centre hole ignored"),
    NamedDisk("can", 0.066 / 2, 0.115, 0.35,
              "a full 330 ml drink can as a homogeneous cylinder: about 66 mm diameter, "
              "115 mm tall, about 0.35 kg (approximate: a can is a thin shell full of "
              "liquid, not a rigid homogeneous body)"),
)}


def disk_from_options(disk: str | None = None, radius=None, diameter=None, thickness=None,
                      mass=None, gravity=None, h=None, *, option_prefix: str = "") -> Disk:
    """The :class:`Disk` a command line's options describe: the one place they are combined.

    The size is given exactly one way:

    * ``disk``: a name from :data:`DISKS` (``"euro-1"``, ``"euler-disk"``, ...);
    * ``radius`` or ``diameter``, with ``thickness`` (the full thickness ``2 h a``) or with
      ``h`` (half-thickness in units of the radius);
    * ``h`` alone: a dimensionless disk (no physical scale);
    * nothing: ``h = DEFAULT_H`` (0.17, close to Euler's disk), no physical scale.

    ``mass`` and ``gravity`` may be added to any of these (with ``disk``, ``mass`` replaces
    the listed mass).

    Parameters
    ----------
    disk : str, optional
        A key of :data:`DISKS`.
    radius, diameter, thickness : str or float, optional
        Lengths, parsed by :func:`parse_length` (plain numbers are metres).
    mass : str or float, optional
        Parsed by :func:`parse_mass` (plain numbers are kilograms).
    gravity : str or float, optional
        Parsed by :func:`parse_acceleration`; standard gravity (9.80665 m/s^2) by default.
    h : str or float, optional
        Half-thickness in units of the radius, ``0 <= h <= 1e8``.
    option_prefix : str
        Put before each name in messages (``"--"`` for a command line: ``--radius``).

    Returns
    -------
    Disk

    Raises
    ------
    ParameterError
        An unknown name, two ways of giving the size (``disk`` and ``radius``, ``radius``
        and ``diameter``, ``thickness`` and ``h`` with a radius), a thickness without a
        radius, a radius without thickness or ``h``, or a bad value (see
        :func:`parse_length`).

    Examples
    --------
    >>> d = disk_from_options(disk="euro-1")
    >>> round(d.h, 4), d.radius
    (0.1002, 0.011625)
    >>> disk_from_options(radius="37.5mm", thickness="12.7mm").h == 12.7 / 75
    True
    """
    p = option_prefix
    if gravity is None:
        g = STANDARD_GRAVITY
    else:
        g = parse_acceleration(gravity, f"{p}gravity")
    m = None if mass is None else parse_mass(mass, f"{p}mass")
    size = [n for n, v in (("radius", radius), ("diameter", diameter),
                           ("thickness", thickness), ("h", h)) if v is not None]
    if disk is not None:
        if not isinstance(disk, str):
            raise ParameterTypeError(f"{p}disk must be a name, one of {sorted(DISKS)}, got "
                                     f"{type(disk).__name__} {disk!r}")
        if disk not in DISKS:
            raise ParameterError(f"{p}disk must be one of {', '.join(sorted(DISKS))}, got "
                                 f"{disk!r}")
        if size:
            raise ParameterError(
                f"{p}disk {disk} fixes the size: give either {p}disk or "
                f"{' and '.join(p + n for n in size)}, not both")
        return DISKS[disk].disk(mass=m, gravity=g)
    if radius is not None and diameter is not None:
        raise ParameterError(f"give {p}radius or {p}diameter, not both")
    a = None
    if radius is not None:
        a = parse_length(radius, f"{p}radius")
    elif diameter is not None:
        a = 0.5 * parse_length(diameter, f"{p}diameter")
        if a == 0.0:  # a subnormal diameter halved to nothing
            raise ParameterError(f"{p}diameter must be > 1e-323 m, got {diameter!r}")
    hh = None if h is None else _parse_h(h, f"{p}h")
    if a is None:
        if thickness is not None:
            raise ParameterError(f"{p}thickness needs {p}radius or {p}diameter (or give "
                                 f"{p}h, the half-thickness in units of the radius, alone)")
        return Disk(h=DEFAULT_H if hh is None else hh, mass=m, gravity=g)
    given = "radius" if radius is not None else "diameter"
    if thickness is not None and hh is not None:
        raise ParameterError(f"give {p}thickness or {p}h with {p}{given}, not both "
                             "(each fixes the thickness)")
    if thickness is None and hh is None:
        raise ParameterError(f"{p}{given} needs {p}thickness (the full thickness, e.g. "
                             f"2.33mm) or {p}h (half-thickness in units of the radius)")
    if hh is not None:
        return Disk(h=hh, radius=a, mass=m, gravity=g)
    t = parse_length(thickness, f"{p}thickness")
    if t / (2.0 * a) > 1e8:
        raise ParameterError(f"{p}thickness / {p}{given} is beyond the range of the theory "
                             f"(h = thickness / (2 radius) must be <= 1e8)")
    return Disk.from_dimensions(a, t, m, g)


def _parse_h(value, name) -> float:
    if isinstance(value, str):
        try:
            value = float(value)
        except ValueError:
            raise ParameterError(f"{name} must be a plain number in [0, 1e8] (half-thickness "
                                 f"in units of the radius), got {value!r}") from None
    try:
        return check_h(value)
    except ParameterError as exc:
        raise ParameterError(str(exc).replace("h must", f"{name} must", 1)) from None


# ---------------------------------------------------------------------- kinds of quantity
#: Kinds of quantity: kind -> (unit in the paper's units, SI unit).  The paper's units are
#: named with ``a`` the radius, ``g`` gravity, ``m`` the mass.
KINDS: dict[str, tuple[str, str]] = {
    "time": ("sqrt(a/g)", "s"),
    "length": ("a", "m"),
    "speed": ("sqrt(a g)", "m/s"),
    "angular_speed": ("sqrt(g/a)", "rad/s"),
    "rate": ("sqrt(g/a)", "1/s"),
    "rate_sq": ("g/a", "1/s^2"),
    "force": ("m g", "N"),
    "energy": ("m g a", "J"),
    "angle": ("rad", "rad"),
    "dimensionless": ("1", "1"),
}

_NEEDS = {"time": ("radius",), "length": ("radius",), "speed": ("radius",),
          "angular_speed": ("radius",), "rate": ("radius",), "rate_sq": ("radius",),
          "force": ("mass",), "energy": ("mass", "radius"), "angle": (),
          "dimensionless": ()}


def can_convert(disk: Disk | None, kind: str) -> bool:
    """Whether ``disk``'s physical scale converts ``kind`` to SI (angles and pure numbers
    always; times, lengths, speeds need the radius; forces the mass; energies both)."""
    if kind not in KINDS:
        raise ParameterError(f"kind must be one of {sorted(KINDS)}, got {kind!r}")
    needs = _NEEDS[kind]
    if not needs:
        return True
    return disk is not None and all(getattr(disk, n) is not None for n in needs)


def unit_of(disk: Disk | None, kind: str) -> str:
    """The unit of ``kind`` as :func:`to_si` gives it: SI when :func:`can_convert`, else
    the paper's unit (``"sqrt(a/g)"``, ``"a"``, ...)."""
    paper, si = KINDS[kind] if kind in KINDS else (None, None)
    return si if can_convert(disk, kind) else paper


def to_si(disk: Disk, kind: str, value):
    """``value`` (paper's units, a number or an array) of ``kind`` in SI units.

    Raises :class:`ParameterError` when ``disk`` lacks the scale (see :func:`can_convert`).
    """
    if not can_convert(disk, kind):
        if isinstance(disk, Disk):
            disk._need(*_NEEDS[kind])  # raises, naming what is missing
        raise ParameterError(f"converting a {kind} to SI needs a Disk with a physical scale "
                             f"(radius, mass), got {disk!r}")
    if value is None:
        return None
    if kind in ("angle", "dimensionless"):
        return value
    if kind == "length":
        return disk.length_to_si(value)
    if kind == "time":
        return disk.time_to_si(value)
    if kind == "speed":
        return disk.speed_to_si(value)
    if kind in ("angular_speed", "rate"):
        return disk.angular_speed_to_si(value)
    if kind == "rate_sq":
        return disk.angular_speed_to_si(disk.angular_speed_to_si(value))
    if kind == "force":
        return disk.force_to_si(value)
    return disk.energy_to_si(value)


def si_view(disk: Disk | None, values: dict, kinds: dict) -> dict:
    """``values`` with, beside each field of ``kinds`` the disk's scale converts, its SI
    value as ``<name>_si``, and a ``"units"`` map naming every field's unit.

    Parameters
    ----------
    disk : Disk or None
        The disk whose physical scale converts (``None``: nothing is converted).
    values : dict
        Dimensionless values (numbers, arrays or None), by field name.
    kinds : dict
        Field name -> a key of :data:`KINDS`; fields without a kind are passed through.

    Returns
    -------
    dict
        ``values``, the ``<name>_si`` entries, and ``"units"``: ``{name: paper unit,
        name_si: SI unit}``.
    """
    out = dict(values)
    units = {}
    for name, kind in kinds.items():
        if name not in values:
            continue
        units[name] = KINDS[kind][0]
        if kind in ("angle", "dimensionless"):
            continue
        if can_convert(disk, kind):
            out[f"{name}_si"] = to_si(disk, kind, values[name])
            units[f"{name}_si"] = KINDS[kind][1]
    out["units"] = units
    return out


def si_fields(result, disk: Disk | None = None) -> dict:
    """The SI view of a result: its fields, ``<name>_si`` SI values beside them, and a
    ``"units"`` map (:func:`si_view`).

    Parameters
    ----------
    result : SteadyMotion, Stability, Thresholds, ExactMotion, or any object with ``to_si()``
        A result of the library.
    disk : Disk, optional
        The disk for results that do not carry one (:class:`~rollingdisk.Stability`).

    Raises
    ------
    ParameterError
        When the disk has no physical scale.
    ParameterTypeError
        When ``result`` has no SI view.

    Examples
    --------
    >>> import rollingdisk as rd
    >>> t = rd.thresholds(disk_from_options(disk="euro-1"))
    >>> round(si_fields(t)["rough_straight_line_speed_si"], 3)   # m/s
    0.197
    """
    if disk is not None and not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk or None, got "
                                 f"{type(disk).__name__}")
    to = getattr(result, "to_si", None)
    if to is None or not callable(to):
        raise ParameterTypeError(f"result must be a result of rollingdisk with an SI view "
                                 f"(to_si), got {type(result).__name__}")
    return to() if disk is None else to(disk)


def result_html(title: str, disk: Disk | None, values: dict, kinds: dict,
                note: str | None = None) -> str:
    """A result as a small HTML table for a notebook: one row per field, its value and unit
    in the paper's units, and its SI value and unit where ``disk``'s scale converts it.

    Parameters
    ----------
    title : str
        The caption.
    disk : Disk or None
        The disk whose scale gives the SI column (none when it has no scale).
    values : dict
        Field name -> value (numbers, strings, None).
    kinds : dict
        Field name -> a key of :data:`KINDS`; fields without a kind get no unit.
    note : str, optional
        A line under the table.
    """
    from rollingdisk.util.display import html_table

    si = disk is not None and getattr(disk, "radius", None) is not None
    rows = []
    for name, v in values.items():
        kind = kinds.get(name)
        unit = KINDS[kind][0] if kind else ""
        row = [name, v, unit]
        if si:
            if kind and kind not in ("angle", "dimensionless") and can_convert(disk, kind) \
                    and isinstance(v, (int, float)) and not isinstance(v, bool):
                row += [to_si(disk, kind, v), KINDS[kind][1]]
            else:
                row += ["", ""]
        rows.append(tuple(row))
    header = ("field", "value", "unit") + (("SI value", "SI unit") if si else ())
    return html_table(title, header, rows, note)

