"""Steady motions, section 3 of the paper: straight lines, circles and spinning in place.

A steady motion keeps the inclination ``theta = theta0`` and the angular velocity
``(0, omega20, omega30)`` constant (``omega1 = 0``).  With ``omega30 = Omega0 cos(theta0)``
(eq. 3) the reduced equations (38) / (49) leave a single condition, eq. (28) on rough and
eq. (34) on smooth ground, so a steady motion has two free parameters:

* rough ground, ``Omega0 = 0``: rolling on a straight line at the static-equilibrium (SE)
  tilt ``tan(theta0) = h``, parameter ``omega0`` (section 3.1);
* rough ground, ``Omega0 != 0``: rolling on a circle, parameters ``theta0`` and one of
  ``Omega0``, ``r_C``, ``r_P`` (eqs. 26-33, section 3.2.1).  At the SE tilt the radius is
  fixed by eq. (30) and ``Omega0`` is free; ``r_C = r_P = 0`` is spinning in place;
* smooth ground: the centre C is at rest (``r_C = 0``, ``F_y = 0``) while the contact point
  runs on a circle of radius ``|y_P0|``; parameters ``theta0`` and ``Omega0`` (eqs. 34, 35),
  or a straight line at the SE tilt with any velocity of C.

Negative ``theta0`` is handled directly through ``h~ = h sgn(theta0)``; the paper's symmetry
``theta0 -> -theta0, r_C -> -r_C`` (with ``Omega0 -> -Omega0``, ``omega30 -> -omega30`` at
the same ``omega20``) is checked in the tests.

The formulas here were re-derived with sympy from the reduced equations (see
:mod:`rollingdisk.symbolic.sections34`).  The paper's first form of eq. (31) and eq. (33)
are misprinted (a factor 2 on the ``h~`` term of the denominator); this module uses the
derived forms, see ``docs/errata.md``.

The map functions that take a half-thickness ``h`` (:func:`Omega0_sq`, :func:`r_C_star`,
:func:`mu_required_map`, :func:`se_circle_radius`) also take a :class:`Disk` (its ``h``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.disk import Disk, check_ground, check_h, h_of
from rollingdisk.model.geometry import h_tilde, inertia
from rollingdisk.theory._points import at_a_point, why_overflow
from rollingdisk.util.checks import check_real, real_array
from rollingdisk.util.errors import ParameterError

__all__ = [
    "NoSteadyMotion",
    "SteadyMotion",
    "steady_motion",
    "straight_line",
    "Omega0_sq",
    "r_C_star",
    "se_circle_radius",
    "mu_required_map",
]

#: The kind of quantity of each field of :class:`SteadyMotion` (keys of
#: :data:`rollingdisk.model.units.KINDS`): what its SI view converts, and how.
STEADY_KINDS = {"theta0": "angle", "Omega0": "angular_speed", "omega0": "angular_speed",
                "omega20": "angular_speed", "omega30": "angular_speed", "r_C": "length",
                "r_P": "length", "F_y": "force", "v_C": "speed", "v_Cx0": "speed",
                "v_Cy0": "speed", "y_P0": "length", "h": "dimensionless",
                "mu_required": "dimensionless"}

#: Tolerance on |y_P0| below which a tilt counts as the static-equilibrium (SE) tilt.
SE_TOL = 1e-12


class NoSteadyMotion(ParameterError):
    """No steady motion exists for the requested parameters (the message says which work)."""


@dataclass(frozen=True)
class SteadyMotion:
    """A steady motion of the disk (section 3).  Dimensionless units, angles in radians.

    Attributes
    ----------
    ground : {"rough", "smooth"}
    disk : Disk
        The disk (as given to :func:`steady_motion` / :func:`straight_line`, with its
        physical scale if it has one); ``h`` is its half-thickness (units of the radius).
    motion : {"straight", "circle", "spin"}
        ``"spin"``: C and P both at rest (``r_C = r_P = 0``).
    theta0 : float
        Constant inclination, ``-pi/2 < theta0 < pi/2``.
    Omega0 : float
        Spin rate of the frame Cxyz about the vertical, ``d psi/dt`` (eq. 15);
        ``> 0`` counter-clockwise about the centre A.
    omega0 : float
        Rolling rate ``d phi/dt`` (eq. 15).
    omega20, omega30 : float
        Constant angular-velocity components (eq. 3); ``omega10 = 0``.
    r_C, r_P : float
        Signed radii of the circles of C and of the contact point P about the centre A
        (eqs. 24, 26); ``r_C`` with the sign of ``theta0`` means leaning towards A.
        ``nan`` for straight lines.
    F_y : float
        Friction force, its component along the y axis of Cxyz: ``F_y = -r_C Omega0^2``
        (eq. 27), which points from C to the centre A; 0 on smooth ground and on straight
        lines.  ``F_x = 0`` and ``F_z = 1`` always (eq. 19).
    v_C : float
        Speed of the centre C.
    v_Cx0, v_Cy0 : float
        Velocity of C in the frame Cxyz (eq. 18); ``v_Cx0 = -r_C Omega0`` on circles.
    y_P0 : float
        Horizontal offset of the contact point from C in Cxyz, eq. (16).
    """

    ground: str
    disk: Disk
    motion: str
    theta0: float
    Omega0: float
    omega0: float
    omega20: float
    omega30: float
    r_C: float
    r_P: float
    F_y: float
    v_C: float
    v_Cx0: float = 0.0
    v_Cy0: float = 0.0
    y_P0: float = 0.0

    @property
    def F_centre(self) -> float:
        """Magnitude of the friction force, directed from C to the centre A: ``|r_C| Omega0^2``."""
        return abs(self.F_y)

    @property
    def h(self) -> float:
        """Half-thickness of the disk, ``disk.h`` (units of the radius ``a``)."""
        return self.disk.h

    @property
    def mu_required(self) -> float:
        """Least static friction coefficient that keeps this motion rolling, ``|F_t| / F_z``.

        With ``F_x = 0``, ``F_z = 1`` (eq. 19) and ``F_y = -r_C Omega0^2`` (eq. 27) it is
        ``|r_C| Omega0^2``; 0 on straight lines, spins and smooth ground.  On Coulomb
        ground with ``mu_s > mu_required`` the motion keeps rolling; below, it starts to
        slide at once.
        """
        return abs(self.F_y) / 1.0  # |F_t| / F_z with F_x = 0, F_z = 1 (eq. 19)

    @property
    def h_tilde(self) -> float:
        """``h~ = h sgn(theta0)`` (eq. 4)."""
        return h_tilde(self.h, self.theta0)

    def initial_state(self, psi0: float = 0.0, phi0: float = 0.0) -> np.ndarray:
        """State vector (layout of :mod:`rollingdisk.model.equations`) on this steady motion at t=0.

        Circles are centred at the origin (``X_A = Y_A = 0``), so C starts at
        ``(-r_C sin psi0, r_C cos psi0)`` (eq. 25); straight lines start with C at the
        origin.  On smooth ground the inertial velocity of C is ``(v_Cx0, v_Cy0)`` rotated
        by ``psi0`` (eq. 1).
        """
        psi0 = check_real("psi0", psi0)
        phi0 = check_real("phi0", phi0)
        if self.motion == "straight":
            X_C = Y_C = 0.0
        else:
            X_C, Y_C = -self.r_C * math.sin(psi0), self.r_C * math.cos(psi0)  # eq. (25)
        if self.ground == "rough":
            return np.array([X_C, Y_C, psi0, self.theta0, phi0, 0.0,
                             self.omega20, self.omega30])
        cp, sp = math.cos(psi0), math.sin(psi0)
        V_X = self.v_Cx0 * cp - self.v_Cy0 * sp  # eq. (1)
        V_Y = self.v_Cx0 * sp + self.v_Cy0 * cp
        return np.array([X_C, Y_C, V_X, V_Y, psi0, self.theta0, phi0, 0.0,
                         self.omega20, self.omega30])

    def as_dict(self) -> dict:
        """Fields as a plain dict (floats; ``nan`` radii of straight lines become ``None``;
        the disk as its half-thickness ``h``)."""
        out = {}
        for name in self.__dataclass_fields__:
            v = getattr(self, name)
            if name == "disk":
                name, v = "h", v.h
            if isinstance(v, float) and not math.isfinite(v):
                v = None
            out[name] = v
        out["mu_required"] = self.mu_required
        return out

    def to_si(self, disk: Disk | None = None) -> dict:
        """The fields (:meth:`as_dict`) with their SI values beside them: ``<name>_si``
        (angular speeds in rad/s, radii in m, speeds in m/s, ``F_y_si`` in N) and a
        ``"units"`` map; through the scale of ``disk`` (default: this motion's disk).

        Raises :class:`ParameterError` when the disk has no physical scale (no radius).

        Examples
        --------
        >>> from rollingdisk.model.units import disk_from_options
        >>> m = straight_line(disk_from_options(disk="euro-1"), "rough", 1.0)
        >>> round(m.to_si()["v_C_si"], 4)   # sqrt(a g), a = 11.625 mm
        0.3376
        """
        from rollingdisk.model.units import si_view

        disk = self.disk if disk is None else disk
        disk._need("radius")
        return si_view(disk, self.as_dict(), STEADY_KINDS)

    def _repr_html_(self) -> str:
        from rollingdisk.model.units import result_html

        values = {k: v for k, v in self.as_dict().items()}
        return result_html(f"SteadyMotion: {self.motion} on {self.ground} ground", self.disk,
                           values, STEADY_KINDS)


# ---------------------------------------------------------------------------------------
def _check_theta0(disk: Disk, theta0) -> float:
    theta0 = check_real("theta0", theta0, low=-math.pi / 2, high=math.pi / 2,
                        low_open=True, high_open=True)
    if theta0 == 0.0 and disk.h > 0.0:
        raise ParameterError(
            "theta0 must lie in (-pi/2, 0) or (0, pi/2) for a disk of finite thickness "
            "(h > 0): at theta0 = 0 the disk touches the plane along a line, which the theory "
            "excludes (section 2)"
        )
    return theta0


def se_circle_radius(h: float, theta0: float = 1.0) -> float:
    """Radius ``r_C = r_P`` of every rough steady circle at the SE tilt, eq. (30).

    ``h~ (3 - 4h^2) / (6 (3 + 2h^2) sqrt(1 + h^2))`` with ``h~ = h sgn(theta0)``: positive
    (leaning towards A) for ``h < sqrt(3)/2``, negative for ``h > sqrt(3)/2``.
    """
    h = check_h(h)
    ht = h_tilde(h, check_real("theta0", theta0))
    return ht * (3.0 - 4.0 * h * h) / (6.0 * (3.0 + 2.0 * h * h) * math.sqrt(1.0 + h * h))


def _rough_Omega0_sq_parts(h, ht, s, c, p):
    """Numerator and the two denominator terms of the corrected eq. (31):
    ``Omega0^2 = 12 (p - h~) / (A + B r_C)``."""
    N = 12.0 * (p - ht)
    A = c * ((3.0 + 4.0 * h * h) * p - 6.0 * ht)  # eq. (31) corrected: 6 h~, not 12 h~
    B = 6.0 * (3.0 + 2.0 * ht * p)
    return N, A, B


def _describe_r_range(name: str, lo: float | None, hi: float | None) -> str:
    if lo is None:
        return f"{name} < {hi:.6g}"
    return f"{name} > {lo:.6g}"


def steady_omega20(ground: str, h, ht, s, c, omega30):
    """``omega20`` of the steady motion with ``omega30`` at the tilt with ``sin = s``,
    ``cos = c`` (``h~ = ht``): eq. (28) on rough, eq. (34) on smooth ground, solved for
    omega20.  Element-wise on arrays (the sweeps use it for whole grids)."""
    p = s / c
    y_P = s - ht * c  # eq. (16)
    if ground == "rough":
        return (((3.0 + 16.0 * h * h) * p + 12.0 * ht) * omega30 * omega30 - 12.0 * y_P) / (
            6.0 * (3.0 + 2.0 * ht * p) * omega30)
    k1, k2 = inertia(h)  # eq. (10)
    return (k1 * p * omega30 * omega30 - y_P) / k2 / omega30  # eq. (34); k2 omega30 may underflow


def _build(disk: Disk, ground: str, theta0: float, Omega0: float) -> SteadyMotion:
    """The circle/spin of ``disk`` at ``theta0`` turning at ``Omega0 != 0``."""
    h = disk.h
    ht = h_tilde(h, theta0)
    s, c = math.sin(theta0), math.cos(theta0)
    y_P = s - ht * c  # eq. (16)
    omega30 = Omega0 * c  # eq. (3)
    if omega30 == 0.0:  # Omega0 so small that omega30 underflows: eqs. (28), (34) divide by it
        raise NoSteadyMotion(
            f"Omega0 = {Omega0:.6g} is beyond floating-point range for this steady motion "
            "(omega30 = Omega0 cos(theta0) underflows to 0): choose 1e-100 < |Omega0| < 1e100")
    omega20 = steady_omega20(ground, h, ht, s, c, omega30)
    if ground == "rough":
        v_Cx0 = omega20 - ht * omega30  # eq. (18) with v_Px0 = 0
        r_C = -v_Cx0 / Omega0  # eq. (24)
        F_y = -r_C * Omega0 * Omega0  # eq. (27)
    else:
        v_Cx0 = 0.0  # eq. (19)_2 with F_y = 0
        r_C = 0.0
        F_y = 0.0
    r_P = r_C + y_P  # eq. (24)
    omega0 = omega20 - Omega0 * s  # eq. (3)
    if not all(math.isfinite(x) for x in (omega20, omega0, r_C, r_P, F_y)):
        raise NoSteadyMotion(
            f"Omega0 = {Omega0:.6g} is beyond floating-point range for this steady motion "
            f"(omega20 = {omega20:.6g}, r_C = {r_C:.6g}): choose 1e-100 < |Omega0| < 1e100")
    if abs(r_C) <= SE_TOL and abs(r_P) <= SE_TOL:
        motion = "spin"
        r_C = r_P = 0.0
    else:
        motion = "circle"
    return SteadyMotion(ground=ground, disk=disk, motion=motion, theta0=theta0, Omega0=Omega0,
                        omega0=omega0, omega20=omega20, omega30=omega30, r_C=r_C, r_P=r_P,
                        F_y=F_y, v_C=abs(v_Cx0), v_Cx0=v_Cx0, v_Cy0=0.0, y_P0=y_P)


def _paper(disk: Disk, kind: str, value, name: str):
    """A dimensional argument in the paper's units: text with a unit or a pint quantity
    converted with the disk's scale (:func:`rollingdisk.model.inputs.to_paper`); a number
    as it is (checked by the caller, with its own message)."""
    if isinstance(value, str) or hasattr(value, "dimensionality"):
        return disk.to_paper(kind, value, name)
    return value


def steady_motion(disk: Disk, ground: str, theta0: float, *, Omega0: float | None = None,
                  r_C: float | None = None, r_P: float | None = None,
                  omega30: float | None = None) -> SteadyMotion:
    """The steady circular motion (or spin in place) at inclination ``theta0``.

    Implements eqs. (24)-(35): give exactly one of ``Omega0``, ``r_C``, ``r_P``,
    ``omega30``.  For a disk with a physical scale each may also be a pint quantity or text
    with a unit (``"30 rad/s"``, ``"5 cm"``; :mod:`rollingdisk.model.inputs`).

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
    theta0 : float
        Inclination in radians, ``-pi/2 < theta0 < pi/2`` (non-zero when ``h > 0``).
    Omega0 : float, optional
        Spin rate ``d psi/dt``, non-zero.  Every ``Omega0 != 0`` gives a steady motion.
    r_C, r_P : float, optional
        Signed radius of the circle of C (of P).  Rough ground only: ``Omega0^2`` then
        follows from eq. (31) (corrected form), and ``Omega0 > 0`` is returned (``-Omega0``
        is the same motion run backwards).
    omega30 : float, optional
        Spin ``omega30`` about the symmetry axis, non-zero: ``Omega0 = omega30 /
        cos(theta0)`` (eq. 3), the second coordinate of the (theta0, omega30) plane of the
        maps and the sweeps.

    Raises
    ------
    NoSteadyMotion
        When no steady motion has these parameters (``Omega0^2 <= 0`` in eq. 31, a radius
        other than eq. (30) at the SE tilt, ``r_C != 0`` on smooth ground, ``Omega0 = 0``
        away from the SE tilt).  The message gives the range that works.
    ValueError
        For invalid arguments, or when the radius does not determine ``Omega0`` (SE tilt
        on rough ground, any tilt on smooth ground): give ``Omega0`` instead.

    Notes
    -----
    Rough ground: ``omega30 = Omega0 cos(theta0)``, ``omega20`` from eq. (28),
    ``r_C = -v_Cx0/Omega0`` with ``v_Cx0 = omega20 - h~ omega30`` (eqs. 24, 26),
    ``r_P = r_C + y_P0``, ``F_y = -r_C Omega0^2`` (eq. 27).  Given ``r_C``::

        Omega0^2 = 12 (tan theta0 - h~)
                   / (cos theta0 [(3 + 4h^2) tan theta0 - 6h~] + 6 (3 + 2h~ tan theta0) r_C)

    which is the paper's eq. (31) with ``-h~/2`` in place of its printed ``-h~`` (the second,
    ``r_P`` form of eq. (31) is right).  Smooth ground: ``r_C = 0``, ``r_P = y_P0`` and
    ``omega20`` from eq. (34).

    Examples
    --------
    >>> m = steady_motion(Disk(h=0.1), "rough", 0.3, r_C=2.0)
    >>> m.motion, round(m.Omega0, 6)
    ('circle', 0.260325)
    """
    ground = check_ground(ground)
    if not isinstance(disk, Disk):
        raise ParameterError(f"disk must be a Disk, got {type(disk).__name__}")
    check_h(disk)  # the sharp-edged disk's (theory.rounded: a rounded rim)
    theta0 = _check_theta0(disk, theta0)
    given = [(n, v) for n, v in (("Omega0", Omega0), ("r_C", r_C), ("r_P", r_P),
                                 ("omega30", omega30)) if v is not None]
    if len(given) != 1:
        raise ParameterError("give exactly one of Omega0, r_C, r_P, omega30 "
                             f"(got {', '.join(n for n, _ in given) or 'none'})")
    name, value = given[0]
    kind = "length" if name in ("r_C", "r_P") else "angular_speed"
    value = check_real(name, _paper(disk, kind, value, name))
    if name == "omega30":
        if value == 0.0:
            raise NoSteadyMotion("omega30 = 0 is no steady circle (Omega0 = omega30 / "
                                 "cos(theta0) = 0): for a straight line use straight_line()")
        name, value = "Omega0", value / math.cos(theta0)  # eq. (3)
    h = disk.h
    ht = h_tilde(h, theta0)
    s, c = math.sin(theta0), math.cos(theta0)
    p = s / c
    y_P = s - ht * c
    se = abs(y_P) <= SE_TOL
    deg = math.degrees(theta0)

    if name == "Omega0":
        if value == 0.0:
            if se:
                raise NoSteadyMotion(
                    "Omega0 = 0 is rolling on a straight line: use straight_line() "
                    "(the 'straight' motion)")
            raise NoSteadyMotion(
                f"Omega0 = 0 (a straight line) is steady only at the static-equilibrium tilt "
                f"theta0 = arctan(h) = {math.atan(h):.6g} rad; at theta0 = {theta0:.6g} rad "
                "every Omega0 != 0 gives a steady circle")
        return _build(disk, ground, theta0, value)

    if ground == "smooth":
        want = 0.0 if name == "r_C" else y_P
        if abs(value - want) > 1e-12 * (1.0 + abs(want)):
            raise NoSteadyMotion(
                f"on smooth ground the centre C is at rest in every steady circle: r_C = 0 and "
                f"r_P = y_P0 = {y_P:.6g} at theta0 = {theta0:.6g} rad, so {name} = {value:.6g} "
                "is impossible; give Omega0 (any non-zero value) instead")
        raise ParameterError(
            f"on smooth ground {name} = {value:.6g} holds for every Omega0 at theta0 = "
            f"{theta0:.6g} rad; give Omega0 instead")

    # rough ground, radius given
    r_C_val = value if name == "r_C" else value - y_P  # eq. (24)
    shift = 0.0 if name == "r_C" else y_P
    if se:
        r_se = se_circle_radius(h, theta0)
        if abs(r_C_val - r_se) > 1e-12 * (1.0 + abs(r_se)):
            raise NoSteadyMotion(
                f"at the static-equilibrium tilt theta0 = arctan(h) = {theta0:.6g} rad "
                f"({deg:.4g} deg) every steady circle has r_C = r_P = {r_se:.6g} (eq. 30), "
                f"not {name} = {value:.6g}; choose another theta0 for other radii")
        raise ParameterError(
            f"at the static-equilibrium tilt r_C = r_P = {r_se:.6g} for every Omega0 (eq. 30):"
            " give Omega0 instead")
    N, A, B = _rough_Omega0_sq_parts(h, ht, s, c, p)
    D = A + B * r_C_val
    Om2 = N / D if D != 0.0 else math.inf
    r_star = -A / B  # eq. (32)
    if not (Om2 > 0.0 and math.isfinite(Om2)):
        if N > 0:
            rng = _describe_r_range(name, r_star + shift, None)
        else:
            rng = _describe_r_range(name, None, r_star + shift)
        raise NoSteadyMotion(
            f"no steady circle with {name} = {value:.6g} at theta0 = {theta0:.6g} rad "
            f"({deg:.4g} deg) on rough ground for h = {h:g}: Omega0^2 = "
            f"{'inf' if not math.isfinite(Om2) else f'{Om2:.6g}'} (eq. 31) must be positive "
            f"and finite; steady circles at this tilt need {rng}")
    return _build(disk, ground, theta0, math.sqrt(Om2))


def straight_line(disk: Disk, ground: str, omega0: float, *, v_Cx0: float | None = None,
                  v_Cy0: float = 0.0, lean: int = 1,
                  theta0: float | None = None) -> SteadyMotion:
    """Steady rolling on a straight line at the SE tilt ``tan(theta0) = h`` (section 3.1).

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
    omega0 : float
        Rolling rate ``d phi/dt = omega20`` (``omega30 = 0``, ``Omega0 = 0``).  For a disk
        with a physical scale also a pint quantity or text with a unit: an angular speed
        (``"10 rad/s"``) or the speed of C rolling without slip (``"0.3 m/s"``, ``v_C =
        a d phi/dt``, eq. 18).
    v_Cx0, v_Cy0 : float, optional
        Velocity of C in Cxyz.  Rough ground: fixed by no slip, ``v_Cx0 = omega0``,
        ``v_Cy0 = 0`` (eq. 18); other values raise :class:`NoSteadyMotion`.  Smooth ground:
        arbitrary, ``v_Cx0 = omega0`` (no slip) by default.
    lean : {1, -1}
        ``theta0 = lean * arctan(h)``.
    theta0 : float, optional
        Instead of ``lean``: the tilt the caller expects; it must be ``+-arctan(h)``
        (to 1e-9), the only tilts of a straight line, else :class:`NoSteadyMotion`.

    Examples
    --------
    >>> m = straight_line(Disk(h=0.5), "rough", 2.0)
    >>> round(m.theta0, 6), m.v_C
    (0.463648, 2.0)
    """
    ground = check_ground(ground)
    if not isinstance(disk, Disk):
        raise ParameterError(f"disk must be a Disk, got {type(disk).__name__}")
    check_h(disk)  # the sharp-edged disk's (theory.rounded: a rounded rim)
    omega0 = check_real("omega0", _paper(disk, "rolling_rate", omega0, "omega0"))
    v_Cx0 = None if v_Cx0 is None else _paper(disk, "speed", v_Cx0, "v_Cx0")
    v_Cy0 = _paper(disk, "speed", v_Cy0, "v_Cy0")
    if isinstance(lean, bool) or lean not in (1, -1):
        raise ParameterError(f"lean must be 1 or -1, got {lean!r}")
    if theta0 is not None:
        theta0 = check_real("theta0", theta0)
        lean = -1 if theta0 < 0 else 1
        if abs(abs(theta0) - disk.static_equilibrium_theta) > 1e-9:
            raise NoSteadyMotion(
                f"a straight line is steady only at the static-equilibrium tilt theta0 = "
                f"+-arctan(h) = +-{disk.static_equilibrium_theta:.6g} rad "
                f"({math.degrees(disk.static_equilibrium_theta):.4g} deg), not {theta0:.6g}")
    v_Cy0 = check_real("v_Cy0", v_Cy0)
    v_Cx0 = omega0 if v_Cx0 is None else check_real("v_Cx0", v_Cx0)
    if ground == "rough" and (v_Cx0 != omega0 or v_Cy0 != 0.0):
        raise NoSteadyMotion(
            "on rough ground the contact point does not slip, so a straight line has "
            f"v_Cx0 = omega0 = {omega0:.6g} and v_Cy0 = 0 (eq. 18)")
    theta0 = lean * disk.static_equilibrium_theta  # y_P0 = 0, eq. (16)
    return SteadyMotion(ground=ground, disk=disk, motion="straight", theta0=theta0, Omega0=0.0,
                        omega0=omega0, omega20=omega0, omega30=0.0, r_C=math.nan,
                        r_P=math.nan, F_y=0.0, v_C=math.hypot(v_Cx0, v_Cy0), v_Cx0=v_Cx0,
                        v_Cy0=v_Cy0, y_P0=0.0)


# ---------------------------------------------------------------------------------------
# vectorized forms for maps
# ---------------------------------------------------------------------------------------
def _map_domain(h, theta0):
    return (h >= 0) & (np.abs(theta0) < np.pi / 2)


def _point_parts(v):
    """``N, A, B`` of eq. (31) and ``r_C*`` (eq. 32) at one in-domain point ``v``."""
    h, theta0 = v["h"], v["theta0"]
    ht = float(h_tilde(h, theta0))
    s, c = math.sin(theta0), math.cos(theta0)
    N, A, B = _rough_Omega0_sq_parts(h, ht, s, c, s / c)
    return N, A, B, -A / B  # B = 6 (3 + 2 h |tan theta0|) > 0 on the domain


def _why_no_Omega0(v) -> str:
    """Why eq. (31) gives no ``Omega0^2`` at the point ``v`` (the SE tilt, ``r_C = r_C*``)."""
    N, A, B, r_star = _point_parts(v)
    if N == 0.0:
        return ("theta0 is the static-equilibrium tilt tan(theta0) = h~ (eq. 30), where "
                "Omega0 is free and r_C fixed: theta0 must differ from arctan(h)")
    if A + B * v["r_C"] == 0.0:
        return (f"r_C = r_C* = {r_star:.6g} (eq. 32), where the denominator of eq. (31) "
                f"vanishes: r_C must differ from r_C*")
    return "the terms of eq. (31) overflow floating-point range here"


def _why_no_circle(v) -> str:
    """Why there is no rough steady circle of radius ``r_C`` at the point ``v``."""
    N, A, B, r_star = _point_parts(v)
    D = A + B * v["r_C"]
    if N == 0.0 or D == 0.0:
        return _why_no_Omega0(v)
    rng = _describe_r_range("r_C", r_star, None) if N > 0 else _describe_r_range(
        "r_C", None, r_star)
    return (f"no steady circle of this radius: Omega0^2 = {N / D:.6g} (eq. 31) must be "
            f"positive; at this (h, theta0) steady circles need {rng} (r_C*, eq. 32)")


@at_a_point(("h", "theta0", "r_C"), _why_no_Omega0)
def Omega0_sq(h, theta0, r_C):
    """``Omega0^2`` of the rough steady circle with radius ``r_C`` (eq. 31, corrected).

    Arrays in (broadcast), array out.  Negative values mean no steady circle (the dark
    regions of Figure 4); NaN outside the domain (``h < 0``, ``|theta0| >= pi/2``), at the
    SE tilt (where ``Omega0`` is free) and where the denominator vanishes (``r_C = r_C*``).
    ``theta0 = 0`` is the limit ``theta0 -> 0+``.  At a single point (scalars in) these
    are refused instead: :class:`~rollingdisk.ParameterError` naming the parameter and
    its range (``0 <= h <= 1e8``, ``|theta0| < pi/2``, ``r_C != r_C*``, eq. 32).
    """
    h, theta0, r_C = np.broadcast_arrays(*(real_array(n, a) for n, a in
                                           (("h", h_of(h)), ("theta0", theta0), ("r_C", r_C))))
    with np.errstate(all="ignore"):
        ht = h_tilde(h, theta0)
        s, c = np.sin(theta0), np.cos(theta0)
        p = s / c
        N, A, B = _rough_Omega0_sq_parts(h, ht, s, c, p)
        D = A + B * r_C
        out = N / D
    bad = ~_map_domain(h, theta0) | (D == 0) | (N == 0)
    return np.where(bad, np.nan, out)[()]


@at_a_point(("h", "theta0"), why_overflow("32"))
def r_C_star(h, theta0):
    """The radius ``r_C*`` where the denominator of eq. (31) vanishes, eq. (32).

    ``-cos(theta0) [(3 + 4h^2) tan(theta0) - 6h~] / (6 (3 + 2h~ tan(theta0)))``.  Steady
    circles need ``r_C < r_C*`` where ``tan(theta0) < h~`` and ``r_C > r_C*`` where
    ``tan(theta0) > h~``.  NaN outside ``h >= 0, |theta0| < pi/2``; at a single point
    (scalars in) that is refused (:class:`~rollingdisk.ParameterError`).
    """
    h, theta0 = np.broadcast_arrays(real_array("h", h_of(h)), real_array("theta0", theta0))
    with np.errstate(all="ignore"):
        ht = h_tilde(h, theta0)
        s, c = np.sin(theta0), np.cos(theta0)
        N, A, B = _rough_Omega0_sq_parts(h, ht, s, c, s / c)
        out = -A / B
    return np.where(_map_domain(h, theta0), out, np.nan)[()]


@at_a_point(("h", "theta0", "r_C"), _why_no_circle)
def mu_required_map(h, theta0, r_C):
    """``mu_required = |F_t|/F_z = |r_C| Omega0^2`` of the rough steady circles (eqs. 19, 27,
    31): the least static friction coefficient that keeps each circle rolling.

    Arrays in (broadcast), array out; NaN where no steady circle has this ``(theta0, r_C)``
    (``Omega0^2 <= 0`` or undefined, see :func:`Omega0_sq`).  A circle survives on Coulomb
    ground with static coefficient ``mu_s`` where ``mu_required_map(...) < mu_s``.  At a
    single point (scalars in) no circle is a :class:`~rollingdisk.ParameterError` giving
    the radii that have one (``r_C`` beyond ``r_C*``, eq. 32).
    """
    Om2 = np.asarray(Omega0_sq.__wrapped__(h_of(h), theta0, r_C), dtype=float)
    r = np.broadcast_to(np.asarray(r_C, dtype=float), Om2.shape)
    with np.errstate(invalid="ignore"):
        return np.where(Om2 > 0, np.abs(r) * Om2, np.nan)[()]
