"""Small oscillations about steady motion and their stability, section 4 of the paper.

Near a steady motion the inclination obeys ``theta~'' + varpi^2 theta~ = 0`` (eqs. 39, 50);
the motion is stable when ``varpi^2 > 0``.  ``varpi^2`` is computed two independent ways:

* closed forms: eqs. (40)-(41) (rough) and (51) (smooth) in terms of ``omega20, omega30``;
  eqs. (45)-(46) (rough, with the corrected ``P0``) and (55)-(56) (smooth) in terms of
  ``omega30`` alone; thresholds (42), (43), (53), (57); all-``omega30`` regions (46), (59);
* :func:`varpi2_linearized`: a numerical Jacobian of the reduced system
  ``(theta, omega1, omega2, omega3)`` of :func:`rollingdisk.model.equations.omega_dot`.

All closed forms were re-derived with sympy (:mod:`rollingdisk.symbolic.sections34`).  The
paper's ``P0`` of eq. (45) lacks a factor ``sqrt(1 + p0^2)`` and its eq. (44) has
``3 + 4h^2`` for ``3 + 16h^2``; this module uses the derived forms (docs/errata.md).

Every function that takes a half-thickness ``h`` also takes a :class:`~rollingdisk.Disk`
(its ``h``; :func:`thresholds` keeps the disk, for the SI view of its speeds).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rollingdisk.model.disk import Disk, check_ground, check_h, h_of
from rollingdisk.model.equations import reduced_rhs
from rollingdisk.model.geometry import h_tilde
from rollingdisk.theory._points import at_a_point, why_overflow
from rollingdisk.theory.steady import Omega0_sq, SteadyMotion, _map_domain, _why_no_circle
from rollingdisk.util.checks import check_real, real_array
from rollingdisk.util.errors import ParameterError

__all__ = [
    "Stability",
    "stability",
    "varpi2_closed_form",
    "varpi2_linearized",
    "reduced_jacobian",
    "varpi2_circle",
    "varpi2_rough_rC",
    "circle_coefficients",
    "critical_omega30_sq",
    "stable_for_all_omega30",
    "Thresholds",
    "thresholds",
]


@dataclass(frozen=True)
class Stability:
    """Small oscillations of ``theta`` about a steady motion (eqs. 39, 50).

    Attributes
    ----------
    varpi2 : float
        Squared angular frequency ``varpi^2`` (units of ``g/a``); finite.
    stable : bool
        ``varpi2 > 0``.
    varpi : float
        ``sqrt(varpi2)``, nan if unstable.
    period : float or None
        ``2 pi / varpi`` (units of ``sqrt(a/g)``), None if unstable.
    growth_rate : float or None
        ``sqrt(-varpi2)`` (e-folding rate of a perturbation), None if stable.

    Examples
    --------
    >>> Stability(4.0).period == math.pi
    True
    """

    varpi2: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "varpi2", check_real("varpi2", self.varpi2))

    @property
    def stable(self) -> bool:
        return self.varpi2 > 0.0

    @property
    def varpi(self) -> float:
        return math.sqrt(self.varpi2) if self.stable else math.nan

    @property
    def period(self) -> float | None:
        return 2.0 * math.pi / self.varpi if self.stable else None

    @property
    def growth_rate(self) -> float | None:
        return None if self.stable else math.sqrt(-self.varpi2) + 0.0

    def as_dict(self) -> dict:
        """``varpi2, stable, varpi, period, growth_rate`` (``varpi`` None when unstable)."""
        return {"varpi2": self.varpi2, "stable": self.stable,
                "varpi": self.varpi if self.stable else None, "period": self.period,
                "growth_rate": self.growth_rate}

    def __repr__(self) -> str:
        from rollingdisk.util.display import short_repr

        return short_repr("Stability", {k: v for k, v in self.as_dict().items()
                                        if k != "varpi" and (v is not None or k == "period")})

    def to_si(self, disk: Disk) -> dict:
        """The fields (:meth:`as_dict`) with SI values beside them through ``disk``'s scale:
        ``varpi2_si`` [1/s^2], ``varpi_si`` [rad/s], ``period_si`` [s], ``growth_rate_si``
        [1/s], and a ``"units"`` map.

        Examples
        --------
        >>> Stability(4.0).to_si(Disk(0.1, radius=9.80665))["period_si"] == math.pi
        True
        """
        from rollingdisk.model.units import si_view

        if not isinstance(disk, Disk):
            raise ParameterError(f"disk must be a Disk with a physical scale, got "
                                 f"{type(disk).__name__}")
        disk._need("radius")
        return si_view(disk, self.as_dict(), STABILITY_KINDS)

    def _repr_html_(self) -> str:
        from rollingdisk.model.units import result_html

        return result_html("Stability (eqs. 39, 50)", None, self.as_dict(), STABILITY_KINDS)


#: The kind of quantity of each field of :class:`Stability` (keys of
#: :data:`rollingdisk.model.units.KINDS`).
STABILITY_KINDS = {"varpi2": "rate_sq", "stable": "dimensionless", "varpi": "angular_speed",
                   "period": "time", "growth_rate": "rate"}


# ---------------------------------------------------------------------------------------
# closed forms in (omega20, omega30): eqs. (40)-(41) and (51)
# ---------------------------------------------------------------------------------------
@at_a_point(("h", "theta0", "omega20", "omega30"), why_overflow("40)-(41) / (51"))
def varpi2_closed_form(h, ground: str, theta0, omega20, omega30):
    """``varpi^2`` at a steady state, eq. (40)-(41) (rough) or eq. (51) (smooth).

    Parameters
    ----------
    ground : {"rough", "smooth"}
    h, theta0, omega20, omega30 : float or array_like
        Broadcast together; a steady state of that ground.

    Returns
    -------
    float or ndarray
        ``varpi^2``; NaN outside ``h >= 0, |theta0| < pi/2`` (at a single point, scalars
        in, a :class:`~rollingdisk.ParameterError` naming the parameter instead).

    Notes
    -----
    Element-wise on arrays.  ``(theta0, omega20, omega30)`` must be a steady state (eq. 28
    or 34 holds); off the steady manifold the printed eq. (51) differs from the
    linearization (it was simplified with eq. (34)), eq. (40) does not.  ``h~ = h sgn
    theta0``, with ``theta0 = 0`` taken as ``0+`` (only meaningful for ``h = 0``).
    """
    ground = check_ground(ground)
    h, t, w2, w3 = (real_array(n, a) for n, a in (("h", h_of(h)), ("theta0", theta0),
                                                  ("omega20", omega20), ("omega30", omega30)))
    ht = h_tilde(h, t)
    p = np.tan(t)
    h2 = h * h
    sq = np.sqrt(1.0 + p * p)
    with np.errstate(all="ignore"):
        out = _varpi2_closed_form(ground, h2, ht, p, sq, w2, w3)
    return np.where(_map_domain(h, t), out, np.nan)[()]


def _varpi2_closed_form(ground, h2, ht, p, sq, w2, w3):
    """Eq. (40)-(41) on rough, eq. (51) on smooth ground (element-wise)."""
    if ground == "rough":
        P22 = 36.0 * (3.0 + 2.0 * ht * p)  # eq. (41)
        P23 = -6.0 * (4.0 * ht * (3.0 + 8.0 * h2) * p * p + (15.0 + 56.0 * h2) * p
                      + 2.0 * ht * (15.0 + 8.0 * h2))
        P33 = (3.0 * (3.0 + 16.0 * h2) * (3.0 + 8.0 * h2) * p * p
               + 8.0 * ht * (15.0 + 44.0 * h2) * p + 45.0 + 216.0 * h2 + 128.0 * h2 * h2)
        out = (((P22 * w2 * w2 + P23 * w2 * w3 + P33 * w3 * w3) * sq
                - 12.0 * (3.0 + 8.0 * h2) * (1.0 + ht * p))
               / ((3.0 + 8.0 * h2) * (15.0 + 16.0 * h2) * sq))  # eq. (40)
        return out
    a = 3.0 + 4.0 * h2
    Q = 3.0 + 16.0 * h2 - 24.0 * ht * p + (15.0 + 4.0 * h2) * p * p
    return ((1.0 + p * p) * (36.0 * w2 * w2 - 18.0 * a * p * w2 * w3
                             + a * a * (1.0 + 3.0 * p * p) * w3 * w3) / (a * Q)
            - 12.0 * (1.0 + ht * p) * sq / Q)  # eq. (51)


def stability(motion: SteadyMotion) -> Stability:
    """Stability of a steady motion from the closed forms, eqs. (40) / (51).

    These reduce to (42) / (52)-(53) for straight lines and to (43) / (57) for spinning at
    the SE tilt.  Agrees with :func:`varpi2_linearized` (tested to 1e-8 relative).

    Examples
    --------
    >>> from rollingdisk import Disk
    >>> from rollingdisk.theory.steady import straight_line
    >>> stability(straight_line(Disk(h=0.0), "rough", 1.0)).stable   # omega20^2 > 1/3
    True
    """
    if not isinstance(motion, SteadyMotion):
        raise ParameterError(f"motion must be a SteadyMotion, got {type(motion).__name__}")
    v = float(varpi2_closed_form(motion.h, motion.ground, motion.theta0, motion.omega20,
                                 motion.omega30))
    if not math.isfinite(v):
        raise ParameterError(f"varpi^2 of this steady motion is not a finite number ({v}): "
                         "its speeds are beyond floating-point range (Omega0 too large or too "
                         "small)")
    return Stability(v)


# ---------------------------------------------------------------------------------------
# numerical linearization of the derived equations
# ---------------------------------------------------------------------------------------
def reduced_jacobian(h: float, ground: str, theta0: float, omega20: float,
                     omega30: float) -> np.ndarray:
    """Jacobian of the reduced system ``d/dt (theta, omega1, omega2, omega3)`` at a steady state.

    Parameters
    ----------
    ground : {"rough", "smooth"}
    h : float
        Half-thickness, ``h >= 0``.
    theta0, omega20, omega30 : float
        The steady state (``omega1 = 0``), ``|theta0| < pi/2``.

    Returns
    -------
    ndarray, shape (4, 4)
        ``J[i, j] = d f_i / d x_j`` with ``x = (theta, omega1, omega2, omega3)``.

    Notes
    -----
    The right-hand side is the library's derived equations of motion
    (:func:`rollingdisk.model.equations.omega_dot`, eqs. 38 / 49).  Columns ``omega1..3`` are
    complex-step derivatives (exact to rounding).  The ``theta`` column is a central
    difference with two Richardson extrapolations (error ``O(delta^6)``, about 1e-12
    relative here), because ``h~ = h sgn(theta)`` jumps at ``theta = 0``: stencil points
    on the other side of ``theta = 0`` are evaluated with ``-h`` so that ``h~`` keeps its
    value at ``theta0`` (the kernels take the sign of the real part of ``theta``, so the
    complex steps on ``omega1..3`` leave ``h~`` alone).
    """
    ground = check_ground(ground)
    h = check_h(h)
    theta0 = check_real("theta0", theta0, low=-math.pi / 2, high=math.pi / 2, low_open=True,
                        high_open=True)
    omega20 = check_real("omega20", omega20)
    omega30 = check_real("omega30", omega30)
    x0 = np.array([theta0, 0.0, omega20, omega30], dtype=float)
    J = np.empty((4, 4))
    eps = 1e-30
    for j in (1, 2, 3):
        xc = x0.astype(complex)
        xc[j] += 1j * eps
        J[:, j] = np.array(reduced_rhs(ground == "rough", h, xc)).imag / eps
    # theta column: stay away from pi/2.  Near theta = 0 the stencil may cross zero, where
    # h~ = h sgn(theta) jumps; evaluating there with -h (h enters only as h~ and h^2)
    # continues the branch of theta0 analytically across zero.
    d = 2e-3 * min(1.0, math.cos(theta0) * 2.0)
    while any(theta0 + sgn * d / k == 0.0 for k in (1, 2, 4) for sgn in (1, -1)):
        d *= 0.9  # never evaluate at theta = 0 itself, which has no side
    side = 1.0 if theta0 >= 0 else -1.0

    def g(theta):
        x = x0.copy()
        x[0] = theta
        return np.array(reduced_rhs(ground == "rough", h if theta * side > 0 else -h, x))

    def central(delta):
        return (g(theta0 + delta) - g(theta0 - delta)) / (2.0 * delta)

    D1, D2, D3 = central(d), central(d / 2), central(d / 4)
    R1 = (4.0 * D2 - D1) / 3.0
    R2 = (4.0 * D3 - D2) / 3.0
    J[:, 0] = (16.0 * R2 - R1) / 15.0
    return J


def varpi2_linearized(motion: SteadyMotion) -> float:
    """``varpi^2`` from a numerical linearization of the derived equations of motion.

    Zero modes: the reduced system has first integrals (energy, and one more through
    ``omega2, omega3``; a one-parameter family of steady states passes through each one), so
    its Jacobian ``J`` at a steady state has rank 2 and the eigenvalues
    ``0, 0, +-sqrt(-varpi^2)``.  Rather than picking the non-zero pair out of the
    eigenvalues (ill-conditioned when ``varpi^2`` is near 0), this uses the invariant
    ``trace(J^2) = sum(lambda_i^2) = -2 varpi^2``, to which the zero modes contribute
    nothing.  The structure (two zero eigenvalues) is checked in the tests.
    """
    if not isinstance(motion, SteadyMotion):
        raise ParameterError(f"motion must be a SteadyMotion, got {type(motion).__name__}")
    J = reduced_jacobian(motion.h, motion.ground, motion.theta0, motion.omega20,
                         motion.omega30)
    return float(-0.5 * np.trace(J @ J))


# ---------------------------------------------------------------------------------------
# circles in terms of omega30: eqs. (45)-(46) and (55)-(56)
# ---------------------------------------------------------------------------------------
@at_a_point(("h", "theta0"), why_overflow("45) / (55"))
def circle_coefficients(h, ground: str, theta0):
    """``(P0, P1, P2, den)`` with ``varpi^2 = (P2 w^4 + P1 w^2 + P0) / (den w^2)``, ``w = omega30``.

    Parameters
    ----------
    ground : {"rough", "smooth"}
    h, theta0 : float or array_like
        Broadcast together.

    Returns
    -------
    tuple of ndarray
        ``(P0, P1, P2, den)``, NaN outside ``h >= 0, |theta0| < pi/2`` (at a single
        point, scalars in, a :class:`~rollingdisk.ParameterError` instead).

    Notes
    -----
    Rough: eq. (45) with the corrected ``P0 = 144 (p0 - h~)^2 sqrt(1 + p0^2)`` (the paper
    prints it without the square root), ``P1``, ``P2`` as printed.  Smooth: eqs. (55)-(56).
    ``den > 0`` everywhere.  Element-wise; ``theta0 = 0`` is the limit ``0+``.
    """
    ground = check_ground(ground)
    h, t = np.broadcast_arrays(real_array("h", h_of(h)), real_array("theta0", theta0))
    ht = h_tilde(h, t)
    p = np.tan(t)
    h2 = h * h
    q = 1.0 + p * p
    sq = np.sqrt(q)
    if ground == "rough":
        b = 3.0 + 8.0 * h2
        P0 = 144.0 * (p - ht) ** 2 * sq  # eq. (45) corrected
        P1 = -12.0 * b * q * (3.0 + 2.0 * h2 + 6.0 * ht * p - (3.0 - 6.0 * h2) * p * p
                              - 4.0 * ht * p ** 3)
        P2 = b * q * sq * (45.0 + 24.0 * h2 + 84.0 * ht * p + (15.0 + 104.0 * h2) * p * p
                           + 2.0 * ht * (3.0 + 16.0 * h2) * p ** 3)
        den = b * (15.0 + 16.0 * h2) * q * sq * (3.0 + 2.0 * ht * p)
    else:
        a = 3.0 + 4.0 * h2
        P0 = 144.0 * (p - ht) ** 2  # eq. (56)
        P1 = -12.0 * a * (1.0 + 2.0 * ht * p - p * p) * sq
        P2 = a * a * q * q
        den = a * (3.0 + 16.0 * h2 - 24.0 * ht * p + (15.0 + 4.0 * h2) * p * p)
    out = np.where(_map_domain(h, t), 0.0, np.nan)  # NaN outside the domain
    return P0 + out, P1 + out, P2 + out, den + out


def _why_no_circle_at(v) -> str:
    if v["omega30"] == 0.0:
        return ("omega30 must be non-zero: eqs. (45) / (55) divide by omega30^2 (any "
                "omega30 != 0 is a steady circle, section 3.2)")
    return why_overflow("45) / (55")(v)


@at_a_point(("h", "theta0", "omega30"), _why_no_circle_at)
def varpi2_circle(h, ground: str, theta0, omega30):
    """``varpi^2`` of the steady circle with given ``omega30``: eq. (45) corrected / (55).

    Arrays in (broadcast), array out; NaN where ``omega30 = 0`` or outside
    ``h >= 0, |theta0| < pi/2``.  Any ``omega30 != 0`` is a steady circle (section 3.2).
    At a single point (scalars in) those are a :class:`~rollingdisk.ParameterError`.
    """
    h, t, w = np.broadcast_arrays(*(real_array(n, a) for n, a in
                                    (("h", h_of(h)), ("theta0", theta0), ("omega30", omega30))))
    with np.errstate(all="ignore"):
        P0, P1, P2, den = circle_coefficients(h, ground, t)
        w2 = w * w
        out = (P2 * w2 * w2 + P1 * w2 + P0) / (den * w2)
    return np.where(_map_domain(h, t) & (w != 0), out, np.nan)[()]


@at_a_point(("h", "theta0", "r_C"), _why_no_circle)
def varpi2_rough_rC(h, theta0, r_C):
    """``varpi^2`` of the rough steady circle of radius ``r_C`` (the eq. (47) route).

    ``Omega0^2`` from eq. (31) (corrected), ``omega30^2 = Omega0^2 cos^2 theta0``, then
    eq. (45).  NaN where ``Omega0^2 <= 0`` (no steady motion) or outside the domain; at a
    single point (scalars in) a :class:`~rollingdisk.ParameterError` giving the radii
    that have a steady circle (beyond ``r_C*``, eq. 32).
    """
    h = h_of(h)
    Om2 = Omega0_sq.__wrapped__(h, theta0, r_C)
    with np.errstate(all="ignore"):
        ok = Om2 > 0
        w = np.sqrt(np.where(ok, Om2, np.nan)) * np.cos(theta0)
        return np.where(ok, varpi2_circle.__wrapped__(h, "rough", theta0, w), np.nan)[()]


@at_a_point(("h", "theta0"))
def critical_omega30_sq(h, ground: str, theta0):
    """The ``varpi^2 = 0`` surface (Figures 6, 8): roots ``(lower, upper)`` in ``omega30^2``.

    Parameters
    ----------
    ground : {"rough", "smooth"}
    h, theta0 : float or array_like
        Broadcast together.

    Returns
    -------
    (lower, upper) : tuple of float or ndarray

    Notes
    -----
    Circles with ``lower < omega30^2 < upper`` are unstable, all others stable.  Both NaN
    where there is no real positive root (stable for every ``omega30``): an answer, kept
    at a single point too.  Outside ``0 <= h <= 1e8, |theta0| < pi/2`` a map holds NaN, a
    single point (scalars in) is a :class:`~rollingdisk.ParameterError`.
    """
    h = h_of(h)
    P0, P1, P2, den = circle_coefficients(h, ground, theta0)
    with np.errstate(all="ignore"):
        D = P1 * P1 - 4.0 * P0 * P2
        sD = np.sqrt(np.where(D >= 0, D, np.nan))
        lo = (-P1 - sD) / (2.0 * P2)
        hi = (-P1 + sD) / (2.0 * P2)
    ok = (D >= 0) & (hi > 0) & _map_domain(np.asarray(h, float), np.asarray(theta0, float))
    return np.where(ok, np.maximum(lo, 0.0), np.nan)[()], np.where(ok, hi, np.nan)[()]


@at_a_point(("h", "theta0"))
def stable_for_all_omega30(h, ground: str, theta0):
    """Where every steady circle is stable, whatever ``omega30``: regions (46) / (59).

    Parameters
    ----------
    ground : {"rough", "smooth"}
    h, theta0 : float or array_like
        Broadcast together.

    Returns
    -------
    bool or ndarray of bool
        True where no ``omega30`` gives ``varpi^2 < 0``.

    Notes
    -----
    ``P2 w^4 + P1 w^2 + P0 > 0`` for all ``w^2 > 0`` iff ``P1 >= 0`` or
    ``Delta = P1^2 - 4 P0 P2 < 0`` (``P0 >= 0``, ``P2 > 0``).  On smooth ground ``Delta < 0``
    is eq. (59): ``3p^4 - 4h~p^3 + 6p^2 - 12h~p - 1 + 4h^2 > 0``.  Boolean array (False
    outside the domain; a single point outside it, scalars in, is a
    :class:`~rollingdisk.ParameterError`).
    """
    h_a, t_a = np.broadcast_arrays(real_array("h", h_of(h)), real_array("theta0", theta0))
    lower, upper = critical_omega30_sq(h_a, ground, t_a)  # no positive root: stable for all
    return (np.isnan(upper) & _map_domain(h_a, t_a))[()]


# ---------------------------------------------------------------------------------------
# thresholds
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Thresholds:
    """Critical squared speeds for the disk of half-thickness ``h`` (stable above them).

    Attributes
    ----------
    h : float
        Half-thickness (units of the radius ``a``).
    rough_straight_line_omega20_sq : float
        eq. (42): ``(3 + 8h^2) sqrt(1 + h^2) / (3 (3 + 2h^2))``.
    rough_se_circle_omega30_sq : float
        eq. (43): ``12 / ((15 + 16h^2) sqrt(1 + h^2))`` (the paper's
        ``12 sqrt(1+h^2)/((1+h^2)(15+16h^2))``, the same number).
    smooth_straight_line_omega20_sq : float
        eq. (53): ``(3 + 4h^2) sqrt(1 + h^2) / 3``.
    smooth_spin_omega30_sq : float
        eq. (57): ``12 / ((3 + 4h^2) sqrt(1 + h^2))``.
    disk : Disk or None
        The disk when :func:`thresholds` was given one: its physical scale gives the SI
        view (:meth:`to_si`).

    All four are squared angular speeds, units of ``g/a``.  On a straight line on rough
    ground C moves at ``v_C = omega20`` (units ``sqrt(a g)``, no slip, eq. 18), so the
    first threshold is also the squared rolling speed: :meth:`to_si` gives it in m/s.
    """

    h: float
    rough_straight_line_omega20_sq: float
    rough_se_circle_omega30_sq: float
    smooth_straight_line_omega20_sq: float
    smooth_spin_omega30_sq: float
    disk: Disk | None = field(default=None, compare=False)

    def speeds(self) -> dict:
        """The thresholds as speeds (square roots), paper's units: the rough straight-line
        rolling speed ``rough_straight_line_speed`` (``sqrt(a g)``, the speed of C) and the
        critical angular speeds ``*_omega20``, ``*_omega30`` (``sqrt(g/a)``)."""
        return {"rough_straight_line_speed": math.sqrt(self.rough_straight_line_omega20_sq),
                "rough_straight_line_omega20": math.sqrt(self.rough_straight_line_omega20_sq),
                "rough_se_circle_omega30": math.sqrt(self.rough_se_circle_omega30_sq),
                "smooth_straight_line_omega20": math.sqrt(self.smooth_straight_line_omega20_sq),
                "smooth_spin_omega30": math.sqrt(self.smooth_spin_omega30_sq)}

    def to_si(self, disk: Disk | None = None) -> dict:
        """The thresholds as speeds in SI units: :meth:`speeds` with ``<name>_si`` beside
        each (``rough_straight_line_speed_si`` in m/s, the critical angular speeds in rad/s)
        and a ``"units"`` map; the squared dimensionless numbers too (no SI values).

        ``disk`` defaults to the disk given to :func:`thresholds`; it must have a radius.

        Examples
        --------
        >>> t = thresholds(Disk.from_dimensions(radius=0.011625, thickness=0.00233))
        >>> round(t.to_si()["rough_straight_line_speed_si"], 3)   # a 1-euro coin, m/s
        0.197
        """
        from rollingdisk.model.units import si_view

        disk = self.disk if disk is None else disk
        if not isinstance(disk, Disk):
            raise ParameterError("Thresholds.to_si needs a Disk with a physical scale: call "
                                 "thresholds(disk) with one, or pass it here")
        disk._need("radius")
        values = {"h": self.h, **self.speeds(),
                  **{k: getattr(self, k) for k in THRESHOLD_KINDS if k.endswith("_sq")}}
        return si_view(disk, values, THRESHOLD_KINDS)

    def _repr_html_(self) -> str:
        from rollingdisk.model.units import result_html

        values = {"h": self.h, **{k: getattr(self, k) for k in THRESHOLD_KINDS
                                  if k.endswith("_sq")}, **self.speeds()}
        return result_html("Thresholds (eqs. 42, 43, 53, 57): stable above", self.disk,
                           values, THRESHOLD_KINDS)

    def as_dict(self) -> dict:
        """``{"rough": {...}, "smooth": {...}}``: the layout of ``thresholds --json``."""
        return {
            "rough": {"straight_line_omega20_sq": self.rough_straight_line_omega20_sq,
                      "se_circle_omega30_sq": self.rough_se_circle_omega30_sq},
            "smooth": {"straight_line_omega20_sq": self.smooth_straight_line_omega20_sq,
                       "spin_omega30_sq": self.smooth_spin_omega30_sq},
        }


def thresholds(h: float | Disk) -> Thresholds:
    """Stability thresholds of eqs. (42), (43), (53), (57) (all confirmed by derivation).

    Parameters
    ----------
    h : float or Disk
        Half-thickness, ``h >= 0``, or a disk (kept in the result: with a physical scale,
        :meth:`Thresholds.to_si` gives the thresholds in m/s and rad/s).

    Returns
    -------
    Thresholds
        Critical squared speeds: steady motions faster than these are stable.

    Examples
    --------
    >>> t = thresholds(0.0)
    >>> t.rough_straight_line_omega20_sq, t.rough_se_circle_omega30_sq
    (0.3333333333333333, 0.8)
    """
    disk = h if isinstance(h, Disk) else None
    h = check_h(h)
    h2 = h * h
    r = math.sqrt(1.0 + h2)
    return Thresholds(
        disk=disk,
        h=h,
        rough_straight_line_omega20_sq=(3.0 + 8.0 * h2) * r / (3.0 * (3.0 + 2.0 * h2)),  # (42)
        rough_se_circle_omega30_sq=12.0 / ((15.0 + 16.0 * h2) * r),  # (43)
        smooth_straight_line_omega20_sq=(3.0 + 4.0 * h2) * r / 3.0,  # (53)
        smooth_spin_omega30_sq=12.0 / ((3.0 + 4.0 * h2) * r),  # (57)
    )


#: The kind of quantity of each field of :class:`Thresholds` and of its speeds (keys of
#: :data:`rollingdisk.model.units.KINDS`).
THRESHOLD_KINDS = {"h": "dimensionless", "rough_straight_line_omega20_sq": "rate_sq",
                   "rough_se_circle_omega30_sq": "rate_sq",
                   "smooth_straight_line_omega20_sq": "rate_sq",
                   "smooth_spin_omega30_sq": "rate_sq",
                   "rough_straight_line_speed": "speed",
                   "rough_straight_line_omega20": "angular_speed",
                   "rough_se_circle_omega30": "angular_speed",
                   "smooth_straight_line_omega20": "angular_speed",
                   "smooth_spin_omega30": "angular_speed"}

