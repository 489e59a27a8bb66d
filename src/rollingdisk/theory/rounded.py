"""Steady motions and their stability for the disk with a rounded rim.

Sections 3-4 of the paper generalised to the body of :mod:`rollingdisk.model.rim`: the
contact below C at ``r_CP = (0, -H, -A)`` in C xi eta zeta, ``A = 1 - rho + rho cos``,
``H = hp + rho sin``, ``hp = (h - rho) sgn(theta)``, inertia ``k1^2, k2^2`` of the rounded
body.  Dimensionless units (m = a = g = 1): angles in rad, angular speeds in ``sqrt(g/a)``,
lengths in ``a``, ``varpi^2`` in ``g/a``.

With ``omega1 = 0`` the equations of :func:`rollingdisk.model.rim.rounded_omega_dot` give
the conditions of steady motion (eq. 20 generalised, ``N = 0`` below):

- rough: ``(A^2 + A H p + k2) omega2 omega3 - (A H + (H^2 + k1) p) omega3^2 + y_P = 0``
  (eq. 28 at ``rho = 0``), with ``v_Cx = A omega2 - H omega3 = -r_C Omega0``, so that

      Omega0^2 = y_P / (cos [k1 sin - k2 H cos / A + r_C (A + H tan + k2 / A)])

  (the corrected eq. 31 at ``rho = 0``, docs/errata.md);
- smooth: ``k2 omega2 omega3 - k1 p omega3^2 + y_P = 0`` (eq. 34), ``r_C = 0``.

Small oscillations (section 4): on both grounds ``d omega2/dt = G2 omega1``, ``d
omega3/dt = G3 omega1`` and ``d omega1/dt = N / J`` with ``N = 0`` at the steady state, so

    varpi^2 = -(dN/dtheta + dN/domega2 G2 + dN/domega3 G3) / J

(``J = k1 + A^2 + H^2`` rough, ``k1 + y_P^2`` smooth), eqs. (40), (51) at ``rho = 0``.
The thresholds follow from it in closed form: straight rolling at the static tilt
``tan theta0 = (h - rho)/(1 - rho)`` (eqs. 42, 53), the circle there (43) and the spin in
place (57).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.disk import Disk, check_ground
from rollingdisk.model.rim import rim_contact, rim_inertia, rounded_reduced_rhs
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["RoundedSteadyMotion", "RoundedThresholds", "rounded_Omega0_sq",
           "rounded_r_C_star", "rounded_omega20", "rounded_steady_motion", "rounded_varpi2",
           "rounded_varpi2_linearized", "rounded_thresholds", "rounded_static_tilt"]


def _disk(disk) -> Disk:
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got {type(disk).__name__}"
                                 f" {disk!r}")
    return disk


def _theta0(disk: Disk, theta0) -> float:
    t = check_real("theta0", theta0, low=-math.pi / 2, high=math.pi / 2, low_open=True,
                   high_open=True)
    if t == 0.0 and disk.rim_radius < disk.h:
        raise ParameterError("theta0 = 0 puts the disk on its tread (a line contact, outside "
                             "the theory unless rim_radius = h); theta0 must lie in "
                             "(-pi/2, 0) or (0, pi/2)")
    return t


def _parts(disk: Disk, theta0):
    """``k1, k2, s, c, p, A, H, y_P, dy_P/dtheta`` at ``theta0``."""
    h, rho = disk.h, disk.rim_radius
    k1, k2 = rim_inertia(h, rho)
    hp, A, H, y_P, z_P = (float(v) for v in rim_contact(h, rho, theta0))
    s, c = math.sin(theta0), math.cos(theta0)
    return k1, k2, s, c, s / c, A, H, y_P, -(z_P + rho)


def rounded_static_tilt(disk: Disk) -> float:
    """The static-equilibrium tilt [rad] of the rounded disk, where ``y_P = 0``:
    ``tan theta0 = (h - rho) / (1 - rho)`` (``arctan h`` at ``rho = 0``, Figure 3b; ``0``
    for a sphere, which rests at any tilt)."""
    disk = _disk(disk)
    return math.atan2(disk.h - disk.rim_radius, 1.0 - disk.rim_radius)


def rounded_omega20(disk: Disk, ground: str, theta0: float, omega30: float) -> float:
    """``omega20`` [``sqrt(g/a)``] of the steady motion at tilt ``theta0`` [rad] with
    ``omega30`` (the condition ``N = 0`` of the module docstring; eqs. 44, 54 at
    ``rho = 0``).  ``omega30 = 0`` only at the static tilt, where any ``omega20`` is
    steady (a straight line): then :class:`~rollingdisk.ParameterError`."""
    disk = _disk(disk)
    ground = check_ground(ground)
    theta0 = _theta0(disk, theta0)
    w3 = check_real("omega30", omega30)
    if w3 == 0.0:
        raise ParameterError("omega30 = 0 is a straight line: omega20 is free there (at the "
                             "static tilt) and no steady motion elsewhere; give omega30 != 0")
    k1, k2, s, c, p, A, H, y_P, _ = _parts(disk, theta0)
    if ground == "rough":
        return ((A * H + (H * H + k1) * p) * w3 * w3 - y_P) / ((A * A + A * H * p + k2) * w3)
    return (k1 * p * w3 * w3 - y_P) / (k2 * w3)


def rounded_Omega0_sq(disk: Disk, theta0: float, r_C: float) -> float:
    """``Omega0^2`` [``g/a``] of the circle of C-radius ``r_C`` [``a``] at tilt ``theta0``
    on rough ground (eq. 31 generalised, the module docstring); a steady motion exists
    where it is positive."""
    disk = _disk(disk)
    theta0 = _theta0(disk, theta0)
    r_C = check_real("r_C", r_C)
    k1, k2, s, c, p, A, H, y_P, _ = _parts(disk, theta0)
    return y_P / (c * (k1 * s - k2 * H * c / A + r_C * (A + H * p + k2 / A)))


def rounded_r_C_star(disk: Disk, theta0: float) -> float:
    """The radius ``r_C*`` [``a``] where the denominator of :func:`rounded_Omega0_sq`
    vanishes (eq. 32 at ``rho = 0``): circles exist on one side of it."""
    disk = _disk(disk)
    theta0 = _theta0(disk, theta0)
    k1, k2, s, c, p, A, H, y_P, _ = _parts(disk, theta0)
    return -(k1 * s - k2 * H * c / A) / (A + H * p + k2 / A)


@dataclass(frozen=True)
class RoundedSteadyMotion:
    """A steady circular motion of the rounded disk (dimensionless units).

    Attributes: ``disk``, ``ground``, ``theta0`` [rad], ``Omega0``, ``omega0``,
    ``omega20``, ``omega30`` [``sqrt(g/a)``], ``r_C``, ``r_P`` [``a``], ``varpi2``
    [``g/a``] (closed form), ``stable`` (``varpi2 > 0``).
    """

    disk: Disk
    ground: str
    theta0: float
    Omega0: float
    omega0: float
    omega20: float
    omega30: float
    r_C: float
    r_P: float
    varpi2: float

    @property
    def stable(self) -> bool:
        return self.varpi2 > 0.0

    def initial_state(self) -> np.ndarray:
        """``(theta, omega1, omega2, omega3)``, the reduced state at this motion."""
        return np.array([self.theta0, 0.0, self.omega20, self.omega30])


def rounded_steady_motion(disk: Disk, ground: str, theta0: float, *,
                          Omega0: float | None = None,
                          r_C: float | None = None) -> RoundedSteadyMotion:
    """The steady circular motion at tilt ``theta0`` [rad] with ``Omega0`` [``sqrt(g/a)``]
    or (rough ground) the C-radius ``r_C`` [``a``] (sections 3.2.1, 3.1.2 generalised).

    Raises :class:`~rollingdisk.ParameterError` when no circle exists (``Omega0^2 <= 0``).
    """
    disk = _disk(disk)
    ground = check_ground(ground)
    theta0 = _theta0(disk, theta0)
    if (Omega0 is None) == (r_C is None):
        raise ParameterError("give exactly one of Omega0 and r_C")
    if r_C is not None:
        if ground != "rough":
            raise ParameterError("r_C is set on rough ground only (on smooth ground r_C = 0)")
        sq = rounded_Omega0_sq(disk, theta0, r_C)
        if not sq > 0.0:
            raise ParameterError(f"no steady circle of r_C = {r_C!r} at theta0 = {theta0!r} "
                                 f"(Omega0^2 = {sq!r} <= 0)")
        Omega0 = math.sqrt(sq)
    Omega0 = check_real("Omega0", Omega0)
    if Omega0 == 0.0:
        raise ParameterError("Omega0 must be != 0 (Omega0 = 0 is a straight line)")
    k1, k2, s, c, p, A, H, y_P, _ = _parts(disk, theta0)
    w3 = Omega0 * c
    w2 = _finite(rounded_omega20(disk, ground, theta0, w3), "omega20")
    if ground == "rough":
        r_C_value = -(A * w2 - H * w3) / Omega0  # v_Cx = -r_C Omega0, eq. (24)
    else:
        r_C_value = 0.0
    return RoundedSteadyMotion(
        disk=disk, ground=ground, theta0=theta0, Omega0=Omega0,
        omega0=_finite(w2 - Omega0 * s, "omega0"), omega20=w2, omega30=w3,
        r_C=_finite(r_C_value, "r_C"), r_P=r_C_value + y_P,
        varpi2=rounded_varpi2(disk, ground, theta0, w2, w3))


def _finite(x: float, name: str) -> float:
    """``x``, or :class:`~rollingdisk.ParameterError` when the inputs made it overflow."""
    if not math.isfinite(x):
        raise ParameterError(f"{name} leaves floating-point range for these inputs (got {x!r});"
                             " give smaller speeds")
    return x


def _varpi2_J(k1, k2, rho, s, c, p, A, H, y_P, dy_P, rough, w2, w3):
    """``(varpi^2 J, J)``: the numerator and denominator of the module docstring."""
    dA, dH = -rho * s, rho * c  # the contact moves over the arc
    dp = 1.0 + p * p
    if rough:
        a2 = (A * A + A * H * p + k2) * w3
        a3 = (A * A + A * H * p + k2) * w2 - 2.0 * (A * H + (H * H + k1) * p) * w3
        dN = ((2.0 * A * dA + dA * H * p + A * dH * p + A * H * dp) * w2 * w3
              - (dA * H + A * dH + 2.0 * H * dH * p + (H * H + k1) * dp) * w3 * w3 + dy_P)
        D = k1 * k2 + k1 * A * A + k2 * H * H
        G2 = -A * (k1 * (1.0 - rho) * w3 + (k2 * H - k1 * rho * s) * w2) / D
        G3 = p * w3 - k2 * ((A * A + k2 + rho * s * H) * w2 - (1.0 - rho) * H * w3) / D
        return -(dN + a2 * G2 + a3 * G3), k1 + A * A + H * H
    a3 = k2 * w2 - 2.0 * k1 * p * w3
    dN = -k1 * dp * w3 * w3 + dy_P
    G3 = p * w3 - k2 * w2 / k1
    return -(dN + a3 * G3), k1 + y_P * y_P


def rounded_varpi2(disk: Disk, ground: str, theta0: float, omega20: float,
                   omega30: float) -> float:
    """``varpi^2`` [``g/a``] of small oscillations about a steady motion of the rounded
    disk, in closed form (the module docstring; eqs. 40-41 and 51 at ``rho = 0``).

    Parameters
    ----------
    disk : Disk
        Its ``h`` and ``rim_radius`` enter.
    ground : {"rough", "smooth"}
    theta0 : float
        Tilt [rad], ``0 < |theta0| < pi/2`` (``0`` allowed when ``rim_radius = h``).
    omega20, omega30 : float
        The steady state [``sqrt(g/a)``]: the steady condition must hold (as eq. 40, the
        formula uses it: ``N = 0``).

    Returns
    -------
    float
        ``varpi^2``; the motion is stable where it is positive.
    """
    disk = _disk(disk)
    ground = check_ground(ground)
    theta0 = _theta0(disk, theta0)
    w2, w3 = check_real("omega20", omega20), check_real("omega30", omega30)
    k1, k2, s, c, p, A, H, y_P, dy_P = _parts(disk, theta0)
    num, J = _varpi2_J(k1, k2, disk.rim_radius, s, c, p, A, H, y_P, dy_P, ground == "rough",
                       w2, w3)
    return _finite(num / J, "varpi^2")


def rounded_varpi2_linearized(disk: Disk, ground: str, theta0: float, omega20: float,
                              omega30: float) -> float:
    """``varpi^2`` [``g/a``] from the Jacobian of the rounded equations of motion
    (:func:`rollingdisk.model.rim.rounded_reduced_rhs`) at a steady state: every column by
    complex step (exact to rounding; the sign of ``theta`` is taken from its real part),
    and ``varpi^2 = -trace(J^2)/2`` (the eigenvalues are ``0, 0, +-i varpi``, as for the
    sharp disk, :func:`rollingdisk.theory.oscillations.varpi2_linearized`)."""
    disk = _disk(disk)
    rough = check_ground(ground) == "rough"
    theta0 = _theta0(disk, theta0)
    h, rho = disk.h, disk.rim_radius
    k1, k2 = rim_inertia(h, rho)
    x0 = np.array([theta0, 0.0, check_real("omega20", omega20),
                   check_real("omega30", omega30)], dtype=complex)
    Jm = np.empty((4, 4))
    eps = 1e-30
    for j in range(4):
        x = x0.copy()
        x[j] += 1j * eps
        Jm[:, j] = np.array(rounded_reduced_rhs(rough, h, rho, k1, k2, x)).imag / eps
    return float(-0.5 * np.trace(Jm @ Jm))


@dataclass(frozen=True)
class RoundedThresholds:
    """The stability thresholds of the rounded disk (stable above), squared angular
    speeds in units ``g/a``: eqs. (42), (43), (53), (57) generalised.

    Attributes
    ----------
    h, rim_radius : float
        The disk (units of ``a``).
    static_tilt : float
        ``theta0`` [rad] of straight rolling and of the circles and spins counted here.
    rough_straight_line_omega20_sq, rough_se_circle_omega30_sq,
    smooth_straight_line_omega20_sq, smooth_spin_omega30_sq : float
        The four thresholds, as in :class:`rollingdisk.theory.oscillations.Thresholds`.
    rough_straight_line_speed_sq : float
        The straight-rolling threshold as the squared speed of C, ``(A omega20)^2``
        [``a g``] (``A = 1`` at ``rho = 0``).
    """

    h: float
    rim_radius: float
    static_tilt: float
    rough_straight_line_omega20_sq: float
    rough_se_circle_omega30_sq: float
    smooth_straight_line_omega20_sq: float
    smooth_spin_omega30_sq: float
    rough_straight_line_speed_sq: float

    def as_dict(self) -> dict:
        """``{"rim_radius", "static_tilt", "rough": {...}, "smooth": {...}}``."""
        return {"rim_radius": self.rim_radius, "static_tilt": self.static_tilt,
                "rough": {"straight_line_omega20_sq": self.rough_straight_line_omega20_sq,
                          "straight_line_speed_sq": self.rough_straight_line_speed_sq,
                          "se_circle_omega30_sq": self.rough_se_circle_omega30_sq},
                "smooth": {"straight_line_omega20_sq": self.smooth_straight_line_omega20_sq,
                           "spin_omega30_sq": self.smooth_spin_omega30_sq}}


def rounded_thresholds(disk: Disk) -> RoundedThresholds:
    """The four stability thresholds of the rounded disk at its static tilt.

    At ``y_P = 0`` the numerator of ``varpi^2`` is ``Q w^2 - dy_P/dtheta`` in the speed
    ``w`` (``omega20`` on straight lines, ``omega30`` on the circle and the spin), so each
    threshold is ``w^2 = (dy_P/dtheta) / Q`` with ``Q`` from the closed form at ``w = 1``.
    At ``rim_radius = 0`` they are eqs. (42), (43), (53), (57).

    Examples
    --------
    >>> t = rounded_thresholds(Disk(0.0))
    >>> round(t.rough_straight_line_omega20_sq, 12), round(t.rough_se_circle_omega30_sq, 12)
    (0.333333333333, 0.8)
    """
    disk = _disk(disk)
    rho = disk.rim_radius
    t0 = rounded_static_tilt(disk)
    if t0 == 0.0 and rho < disk.h:
        raise ParameterError("a disk whose static tilt is 0 stands on its tread")
    k1, k2, s, c, p, A, H, y_P, dy_P = _parts(disk, t0)
    args = (k1, k2, rho, s, c, p, A, H, 0.0, dy_P)  # y_P = 0 there (to rounding)

    def threshold(rough, w2, w3):
        Q = _varpi2_J(*args, rough, w2, w3)[0] + dy_P
        return dy_P / Q

    w2_circle = (A * H + (H * H + k1) * p) / (A * A + A * H * p + k2)  # N = 0, omega30 = 1
    line = threshold(True, 1.0, 0.0)
    return RoundedThresholds(
        h=disk.h, rim_radius=rho, static_tilt=t0,
        rough_straight_line_omega20_sq=line,
        rough_se_circle_omega30_sq=threshold(True, w2_circle, 1.0),
        smooth_straight_line_omega20_sq=threshold(False, 1.0, 0.0),
        smooth_spin_omega30_sq=threshold(False, k1 * p / k2, 1.0),
        rough_straight_line_speed_sq=A * A * line)
