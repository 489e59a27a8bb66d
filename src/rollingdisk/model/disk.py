"""The disk model: thickness, inertia (eq. 10), the grounds, and the physical scale.

Everything in the library is computed in the paper's dimensionless units: mass ``m``,
radius ``a`` and gravity ``g`` are set to one, so lengths are in units of ``a``, times in
units of ``sqrt(a/g)``, speeds in ``sqrt(a g)``, angular speeds in ``sqrt(g/a)``, forces in
``m g`` and energies in ``m g a``.  A :class:`Disk` may carry an optional physical scale
(radius, mass, gravity); its ``*_to_si`` methods are the one place where dimensionless
numbers become SI numbers, and its ``*_from_si`` methods the way back.  Its ``radius``,
``mass`` and ``gravity`` may be given as text with a unit (``"11.625mm"``) or as pint
quantities (``Quantity(7.5, "g")``), converted to SI (:mod:`rollingdisk.model.quantity`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.geometry import _geometry, _inertia, h_tilde
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["Disk", "DEFAULT_H", "GROUNDS", "H_MAX", "STANDARD_GRAVITY", "check_ground", "check_h",
           "h_of", "sharp_h"]



#: The two kinds of ground the theory covers: no slip, or no friction.
GROUNDS = ("rough", "smooth")


#: Largest half-thickness accepted (a bar 1e8 radii long): far beyond it h^4 and the
#: like in the stability formulas leave floating-point range.
H_MAX = 1e8


#: The default disk of the command line and the atlas: close to a commercial Euler's disk
#: (radius 37.5 mm, 12.7 mm thick: h = 6.35 / 37.5 = 0.17).
DEFAULT_H = 0.17


#: Standard gravity [m/s^2], the default physical gravity of a :class:`Disk`.
STANDARD_GRAVITY = 9.80665


def check_h(h) -> float:
    """``h`` as a float, or ``ValueError``: the half-thickness must lie in ``[0, H_MAX]``.

    A :class:`Disk` stands for its half-thickness: ``check_h(disk) == disk.h``; a disk with
    a rounded rim is refused (:func:`sharp_h`).
    """
    if isinstance(h, Disk):
        return sharp_h(h)
    return check_real("h", h, low=0.0, high=H_MAX)


def sharp_h(disk) -> float:
    """``disk.h`` of a sharp-edged disk; ``ParameterError`` for one with a rounded rim, which
    the paper's formulas do not describe (:mod:`rollingdisk.theory.rounded` does)."""
    if disk.rim_radius != 0.0:
        raise ParameterError(
            f"this function models the paper's sharp-edged disk, and this disk has a rounded "
            f"rim (rim_radius = {disk.rim_radius:g}): use rollingdisk.theory.rounded "
            "(rounded_steady_motion, rounded_varpi2, rounded_thresholds), or rim_radius = 0")
    return disk.h


def h_of(h):
    """``disk.h`` for a :class:`Disk`, anything else unchanged (the functions that take an
    ``h`` or an array of them also take a disk; a rounded rim is refused, :func:`sharp_h`)."""
    return sharp_h(h) if isinstance(h, Disk) else h


def _number(x):
    """A real number as it is; a sequence or array as a float ndarray (for the converters)."""
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return x
    return np.asarray(x, dtype=float)


def _plain(value, parse, name):
    """A physical input (text with a unit, a pint quantity) in SI, by ``parse``; anything
    else unchanged (checked by the caller)."""
    if isinstance(value, str) or hasattr(value, "dimensionality"):
        return parse(value, name)
    return value


def _si_inputs(disk) -> None:
    """Text with a unit and pint quantities for ``radius``, ``mass``, ``gravity``, in SI."""
    for name in ("radius", "mass", "gravity"):
        value = getattr(disk, name)
        if isinstance(value, str) or hasattr(value, "dimensionality"):
            from rollingdisk.model import quantity

            parse = {"radius": quantity.parse_length, "mass": quantity.parse_mass,
                     "gravity": quantity.parse_acceleration}[name]
            object.__setattr__(disk, name, parse(value, name))


def _rim_radius(disk) -> float:
    """The rim radius in units of ``a``, checked: ``0 <= rho <= min(h, 1)``; a physical length
    (text with a unit, a pint quantity) divided by the disk's radius."""
    rho = disk.rim_radius
    if isinstance(rho, str) or hasattr(rho, "dimensionality"):
        from rollingdisk.model.inputs import read_input

        how, rho, _ = read_input("length", rho, "rim_radius")  # 0 allowed, unlike radius
        if how == "paper":  # "0.05a": already in units of the radius
            return _rim_in_range(disk, rho)
        if disk.radius is None:
            raise ParameterError("rim_radius given as a length needs the disk's radius "
                                 "(Disk(h, radius=..., rim_radius=...)); without one give it "
                                 "in units of the radius, 0 <= rim_radius <= h")
        rho = rho / disk.radius
    return _rim_in_range(disk, rho)


def _rim_in_range(disk, rho) -> float:
    """``rho`` checked: ``0 <= rho <= min(h, 1)`` (the arcs fit in the half-thickness and in
    the radius: their centres sit at ``h - rho >= 0`` and ``1 - rho >= 0``)."""
    high = min(disk.h, 1.0)
    rho = check_real("rim_radius", rho, low=0.0)
    if rho > high:
        raise ParameterError(f"rim_radius must lie in [0, min(h, 1)] = [0, {high:g}] (units of "
                             f"the radius: at most the half-thickness and the radius), got "
                             f"{rho!r}")
    return rho


def check_ground(ground) -> str:
    """Return ``ground`` if it is ``"rough"`` or ``"smooth"``, else raise ``ValueError``."""
    if ground not in GROUNDS:
        raise ParameterError(f"ground must be one of {GROUNDS}, got {ground!r}")
    return ground


@dataclass(frozen=True)
class Disk:
    """A homogeneous rigid disk (cylinder, bar) of radius ``a`` and thickness ``2h``.

    Parameters
    ----------
    h : float
        Half-thickness in units of the radius, ``0 <= h <= 1e8`` (the paper's ``h``;
        ``h = 0`` is the infinitely thin disk, large ``h`` a cylinder or a bar; the upper
        bound keeps every formula within floating-point range).
    radius : float, optional
        Physical radius ``a`` [m], ``> 0``. Needed only for conversions to SI units.
    mass : float, optional
        Physical mass ``m`` [kg], ``> 0``. Needed only for forces and energies in SI units.
    gravity : float, optional
        Gravitational acceleration ``g`` [m/s^2], ``> 0``; standard gravity by default.
    rim_radius : float, str or pint quantity, optional
        Radius ``rho`` of the rounded rim in units of the radius ``a``,
        ``0 <= rho <= min(h, 1)``
        (the meridian is a flat face, a quarter circle of radius ``rho``, a flat tread of
        length ``2 (h - rho)``, a quarter circle, a flat face; see
        :mod:`rollingdisk.model.rim`).  Text with a unit (``"0.3mm"``) or a pint quantity
        is a physical length (text without a unit: metres, as for ``radius``; ``"0.05a"``:
        units of ``a``), divided by ``radius`` (which it then needs).  ``0`` (the
        default) is the paper's sharp-edged disk, and everything is as without it.

    Examples
    --------
    >>> disk = Disk(h=0.17)
    >>> round(disk.k1_sq, 6)  # eq. (10): 1/4 + h^2/3
    0.259633
    >>> coin = Disk.from_dimensions(radius=0.0125, thickness=0.002, mass=0.0075)
    >>> round(coin.h, 3)
    0.08
    """

    h: float
    radius: float | None = None
    mass: float | None = None
    gravity: float = STANDARD_GRAVITY
    rim_radius: float = 0.0

    def __repr__(self) -> str:
        # the sharp disk's repr is the one it always had; the rim shows only when rounded
        rim = f", rim_radius={self.rim_radius!r}" if self.rim_radius != 0.0 else ""
        return (f"Disk(h={self.h!r}, radius={self.radius!r}, mass={self.mass!r}, "
                f"gravity={self.gravity!r}{rim})")

    def __post_init__(self) -> None:
        object.__setattr__(self, "h", check_h(self.h))
        _si_inputs(self)
        if self.radius is not None:
            object.__setattr__(self, "radius",
                               check_real("radius", self.radius, low=0.0, low_open=True))
        if self.mass is not None:
            object.__setattr__(self, "mass", check_real("mass", self.mass, low=0.0, low_open=True))
        object.__setattr__(self, "gravity",
                           check_real("gravity", self.gravity, low=0.0, low_open=True))
        object.__setattr__(self, "rim_radius", _rim_radius(self))

    @classmethod
    def from_dimensions(cls, radius: float, thickness: float, mass: float | None = None,
                        gravity: float = STANDARD_GRAVITY, rim_radius=0.0) -> Disk:
        """A disk from its physical radius and full thickness ``2h a`` (both in metres);
        a ``rim_radius`` as a number is in metres too (text with a unit, a pint quantity
        as in :class:`Disk`)."""
        from rollingdisk.model.quantity import parse_length

        radius = check_real("radius", _plain(radius, parse_length, "radius"), low=0.0,
                            low_open=True)
        thickness = check_real("thickness", _plain(thickness, parse_length, "thickness"),
                               low=0.0)
        if not (isinstance(rim_radius, str) or hasattr(rim_radius, "dimensionality")):
            rim_radius = check_real("rim_radius", rim_radius, low=0.0) / radius
        return cls(h=thickness / (2.0 * radius), radius=radius, mass=mass, gravity=gravity,
                   rim_radius=rim_radius)

    # -- inertia, eq. (10) -------------------------------------------------------------
    @property
    def k1_sq(self) -> float:
        """Squared radius of gyration about a diameter, ``1/4 + h^2/3`` (eq. 10)."""
        return _inertia(self.h)[0]

    @property
    def k2_sq(self) -> float:
        """Squared radius of gyration about the symmetry axis, ``1/2`` (eq. 10)."""
        return _inertia(self.h)[1]

    # -- contact geometry, eq. (4) -----------------------------------------------------
    def h_tilde(self, theta: float) -> float:
        """``h~ = h sgn(theta)``: the rim edge that touches the plane (eq. 4)."""
        return h_tilde(self.h, theta)

    def contact_point_xyz(self, theta: float) -> tuple[float, float]:
        """Contact point P in the disk-fixed frame Cxyz, ``(y_P, z_P)`` (eq. 4), in units of
        ``a`` (:func:`rollingdisk.contact_point` gives P on the plane, in OXYZ)."""
        g = _geometry(self.h, float(theta))
        return float(g[4]), float(g[5])

    @property
    def static_equilibrium_theta(self) -> float:
        """The static-equilibrium tilt ``theta0 = arctan h`` (Figure 3b, eq. 30)."""
        return math.atan(self.h)

    # -- units ---------------------------------------------------------------------------
    def _need(self, *names: str) -> None:
        missing = [n for n in names if getattr(self, n) is None]
        if missing:
            raise ParameterError(
                f"this Disk has no physical scale: give {' and '.join(missing)} "
                f"(e.g. Disk(h={self.h:g}, radius=0.05, mass=0.4)) to convert to SI units"
            )

    @property
    def time_unit(self) -> float:
        """The unit of time ``sqrt(a/g)`` [s]."""
        self._need("radius")
        return math.sqrt(self.radius / self.gravity)

    def length_to_si(self, x):
        """Lengths: units of ``a`` -> metres (a number, a sequence or an array)."""
        self._need("radius")
        return _number(x) * self.radius

    def time_to_si(self, t):
        """Times: units of ``sqrt(a/g)`` -> seconds (a number, a sequence or an array)."""
        return _number(t) * self.time_unit

    def speed_to_si(self, v):
        """Speeds: units of ``sqrt(a g)`` -> m/s (a number, a sequence or an array)."""
        self._need("radius")
        return _number(v) * math.sqrt(self.radius * self.gravity)

    def angular_speed_to_si(self, w):
        """Angular speeds: units of ``sqrt(g/a)`` -> rad/s (a number, a sequence or an
        array)."""
        return _number(w) / self.time_unit

    def force_to_si(self, f):
        """Forces: units of ``m g`` -> newtons (a number, a sequence or an array)."""
        self._need("mass")
        return _number(f) * self.mass * self.gravity

    def energy_to_si(self, e):
        """Energies: units of ``m g a`` -> joules (a number, a sequence or an array)."""
        self._need("mass", "radius")
        return _number(e) * self.mass * self.gravity * self.radius

    # -- units, the way back: SI -> the paper's units (the inverses of the above) ---------
    def length_from_si(self, x):
        """Lengths: metres -> units of ``a`` (a number, a sequence or an array)."""
        self._need("radius")
        return _number(x) / self.radius

    def time_from_si(self, t):
        """Times: seconds -> units of ``sqrt(a/g)`` (a number, a sequence or an array)."""
        return _number(t) / self.time_unit

    def speed_from_si(self, v):
        """Speeds: m/s -> units of ``sqrt(a g)`` (a number, a sequence or an array)."""
        self._need("radius")
        return _number(v) / math.sqrt(self.radius * self.gravity)

    def angular_speed_from_si(self, w):
        """Angular speeds: rad/s -> units of ``sqrt(g/a)`` (a number, a sequence or an
        array)."""
        return _number(w) * self.time_unit

    def force_from_si(self, f):
        """Forces: newtons -> units of ``m g`` (a number, a sequence or an array)."""
        self._need("mass")
        return _number(f) / (self.mass * self.gravity)

    def energy_from_si(self, e):
        """Energies: joules -> units of ``m g a`` (a number, a sequence or an array)."""
        self._need("mass", "radius")
        return _number(e) / (self.mass * self.gravity * self.radius)

    def to_paper(self, kind: str, value, name: str = "value") -> float:
        """A dimensional input in the paper's units: a number as it is (the library's units),
        text with a unit (``"2 s"``) or a pint quantity converted from SI with this disk's
        scale; text without a unit is refused (ambiguous for a disk with a physical size),
        ``"20a"`` is 20 in the paper's units.  See :func:`rollingdisk.model.inputs.to_paper`.

        Examples
        --------
        >>> coin = Disk.from_dimensions(0.011625, 0.00233, 0.0075)
        >>> round(coin.to_paper("time", "2 s"), 6)
        58.088994
        """
        from rollingdisk.model.inputs import to_paper

        return to_paper(self, kind, value, name)
