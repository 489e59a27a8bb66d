"""Contact moments beyond Moffatt's film: Bildsten's boundary layer and load-dependent rolling
resistance, plus the air-film coefficient derived from lubrication theory.

Same interface as the moment models of :mod:`rollingdisk.ground` (frozen dataclasses with
``moment(theta, omega1, omega2, omega3, F_z)`` in Cxyz and ``power(...) <= 0``), in the
library's units (m = a = g = 1, time ``sqrt(a/g)``); each has a ``from_si`` constructor.

* :class:`BoundaryLayerAirDrag` - Bildsten, Phys. Rev. E 66 (2002) 056309: the viscous
  layer ``delta = sqrt(nu/Omega)`` is thinner than the gap ``a alpha`` (until ``alpha ~
  (nu^2/(4 g a^3))^(1/3)``, about 5e-3 for the toy in air), so the shear ``a Omega`` acts
  across ``delta``: ``Phi = C mu a^2 (a Omega)^2 / delta = C sqrt(mu rho) a^4 Omega^(5/2)``,
  ``C = pi`` (derivation: :func:`rollingdisk.symbolic.air_film.boundary_layer_law`).
  Exponents on the rolling family: ``alpha ~ (t0 - t)^(4/9)``, ``Omega ~ (t0 - t)^(-2/9)``.
* :class:`LoadRollingResistance` - ``M_h = -c F_z^n omega_h/|omega_h|``, ``0 < n <= 1``:
  a rolling-resistance torque sublinear in the load (adhesion-like; Thorne et al., arXiv
  2603.14520 (2026), on glass).  ``n = 1`` is :class:`rollingdisk.RollingResistance`.
* :func:`air_coefficient_derived` - the coefficient of :class:`rollingdisk.AirDrag` that
  reproduces the lubrication dissipation ``Phi = K mu a^3 Omega^2/alpha`` with ``K =``
  :data:`FILM_CONSTANT` (= 1.28113) instead of Moffatt's ``2 pi`` (see
  ``docs/errata-models.md``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.disk import STANDARD_GRAVITY
from rollingdisk.model.ground import angular_velocity_xyz
from rollingdisk.util.checks import check_real

__all__ = ["BoundaryLayerAirDrag", "LoadRollingResistance", "air_coefficient_derived",
           "FILM_CONSTANT", "MOFFATT_CONSTANT", "BOUNDARY_LAYER_CONSTANT"]

#: ``K`` of ``Phi = K mu a^3 Omega^2 / alpha``: the squeeze film under a disk tilted by
#: ``alpha`` whose contact point precesses at ``Omega`` (Reynolds equation solved exactly,
#: :func:`rollingdisk.symbolic.air_film.film_constant`; ``12 (pi/3 - J)``).
FILM_CONSTANT = 1.2811295384
#: Moffatt's estimate of the same constant (gap sheared at ``a Omega`` everywhere), ``2 pi``.
MOFFATT_CONSTANT = 2.0 * math.pi
#: ``C`` of the boundary-layer estimate ``Phi = C mu a^2 (a Omega)^2 / delta`` (one wall
#: sheared at ``a Omega`` over the disk's area ``pi a^2``; an order-one estimate, not solved).
BOUNDARY_LAYER_CONSTANT = math.pi


def _positive(name, value, *, low_open=True):
    return check_real(name, value, low=0.0, low_open=low_open)


def air_coefficient_derived(mu_air: float, radius: float, mass: float,
                            gravity: float = STANDARD_GRAVITY) -> float:
    """Coefficient ``c`` of :class:`rollingdisk.AirDrag` from the lubrication film.

    ``c = K mu_air a^(3/2) / (m g^(1/2))`` with ``K`` = :data:`FILM_CONSTANT` = 1.28113
    (the library's ``ground.AirDrag`` documents ``K = 2 pi``, Moffatt's estimate; the
    derived value is 4.90 times smaller, so the air-only spin time is 4.90 times longer).

    Parameters
    ----------
    mu_air : float
        Dynamic viscosity [Pa s], ``>= 0``.
    radius, mass, gravity : float
        ``a`` [m], ``m`` [kg], ``g`` [m/s^2], all ``> 0``.

    Examples
    --------
    >>> round(air_coefficient_derived(1.8e-5, 0.038, 0.4) * 1e7, 4)
    1.3637
    """
    mu_air = _positive("mu_air", mu_air, low_open=False)
    a = _positive("radius", radius)
    m = _positive("mass", mass)
    g = _positive("gravity", gravity)
    return FILM_CONSTANT * mu_air * a**1.5 / (m * math.sqrt(g))


@dataclass(frozen=True)
class BoundaryLayerAirDrag:
    """Air drag of the boundary layer under the disk (Bildsten 2002).

    ``M = -c |Omega|^(1/2) Omega e_zeta / cos(theta)``, ``e_zeta = (0, -sin theta, cos
    theta)`` (Cxyz), ``Omega = omega3 / cos(theta)`` (eqs. 2-3): the direction of
    :class:`rollingdisk.AirDrag`.  Power ``omega . M = -c |Omega|^(5/2) <= 0``, independent
    of the tilt (the layer, not the gap, sets the shear) and of ``F_z``.

    ``c = C sqrt(mu_air rho_air) a^(9/4) / (m g^(1/4))`` in the library's units (the
    dimensionless form of ``Phi = C sqrt(mu rho) a^4 Omega^(5/2)``, ``C = pi``); see
    :meth:`from_si`.  Valid while ``delta = sqrt(nu/Omega) < a alpha``; below the crossover
    tilt the film law (:class:`rollingdisk.AirDrag`) applies.

    Parameters
    ----------
    c : float
        Coefficient, ``>= 0`` (dimensionless; power in ``m g^(3/2) a^(1/2)``).

    Raises
    ------
    ParameterError
        ``c`` negative, NaN or infinite (message names ``boundary_layer_air``).
    ParameterTypeError
        ``c`` not a real number.

    Examples
    --------
    >>> d = BoundaryLayerAirDrag(1e-4)
    >>> round(float(d.power(1.5, 0.0, 0.0, 2.0 * math.cos(1.5))), 10)
    -0.0005656854
    """

    c: float

    def __post_init__(self):
        object.__setattr__(self, "c", check_real("boundary_layer_air", self.c, low=0.0))

    @classmethod
    def from_si(cls, mu_air: float = 1.81e-5, rho_air: float = 1.2, radius: float = 0.0375,
                mass: float = 0.45, gravity: float = STANDARD_GRAVITY,
                area_factor: float = BOUNDARY_LAYER_CONSTANT) -> BoundaryLayerAirDrag:
        """From the air's viscosity [Pa s] and density [kg/m^3] and the disk's radius [m],
        mass [kg] and ``g`` [m/s^2]: ``c = C sqrt(mu rho) a^(9/4) / (m g^(1/4))``."""
        mu_air = _positive("mu_air", mu_air, low_open=False)
        rho_air = _positive("rho_air", rho_air, low_open=False)
        a = _positive("radius", radius)
        m = _positive("mass", mass)
        g = _positive("gravity", gravity)
        C = _positive("area_factor", area_factor)
        return cls(C * math.sqrt(mu_air * rho_air) * a**2.25 / (m * g**0.25))

    @staticmethod
    def crossover_tilt(mu_air: float, rho_air: float, radius: float,
                       gravity: float = STANDARD_GRAVITY, w: float = 4.0) -> float:
        """Tilt [rad] at which ``delta = sqrt(nu/Omega)`` equals the gap ``a alpha`` on the
        rolling family ``Omega^2 alpha = w g/a`` (``w = 4``, thin disk):
        ``alpha_c = nu^(2/3) / (a (w g)^(1/3))``.  Film law below, boundary layer above."""
        nu = _positive("mu_air", mu_air) / _positive("rho_air", rho_air)
        return nu ** (2.0 / 3.0) / (_positive("radius", radius)
                                    * (_positive("w", w) * _positive("gravity", gravity))
                                    ** (1.0 / 3.0))

    def _k(self, theta, omega3):
        c = np.cos(theta)
        Om = omega3 / c
        return -self.c * np.sqrt(np.abs(Om)) * Om / c, c

    def moment(self, theta, omega1, omega2, omega3, F_z=None):
        """``(M_x, M_y, M_z)`` in Cxyz, units of ``m g a``."""
        k, c = self._k(theta, omega3)
        return (np.asarray(0.0 * k)[()], np.asarray(-k * np.sin(theta))[()],
                np.asarray(k * c)[()])

    def power(self, theta, omega1, omega2, omega3, F_z=None):
        """``omega . M = -c |Omega|^(5/2) <= 0``, ``Omega = omega3/cos(theta)``."""
        Om = np.abs(omega3 / np.cos(theta))
        return np.asarray(-self.c * Om * Om * np.sqrt(Om))[()]


@dataclass(frozen=True)
class LoadRollingResistance:
    """Rolling resistance sublinear in the load: ``M_h = -c F_z^n omega_h / |omega_h|``.

    ``omega_h = (omega_x, omega_y)`` the horizontal angular velocity in Cxyz, ``M_z = 0``,
    ``F_z^n`` taken as ``max(F_z, 0)^n`` (no torque once the disk lifts off); power ``-c
    F_z^n |omega_h| <= 0``.  With ``F_z ~ m g`` the torque goes as ``m^n``: ``n = 1`` is
    :class:`rollingdisk.RollingResistance`; ``n < 1`` the adhesion-like law that Thorne et
    al. (arXiv 2603.14520, 2026) report on glass.

    Not affine in ``F_z`` for ``n < 1``: the library's equations of motion need moments
    affine in the normal force (``ground`` module docstring), so this model is for the
    adiabatic energy balance along the steady family (``F_z = 1``) or with a known
    ``F_z``; a simulation would iterate on ``F_z``.

    Parameters
    ----------
    c : float
        ``>= 0``, units ``a (m g)^(1-n)`` (a length at ``n = 1``).
    n : float
        Load exponent in ``(0, 1]``.

    Raises
    ------
    ParameterError
        ``c < 0`` or ``n`` outside ``(0, 1]`` (the message names ``rolling_resistance`` or
        ``n``).
    ParameterTypeError
        A non-real coefficient.

    Examples
    --------
    >>> bool(LoadRollingResistance(1e-3, 0.5).power(1.0, 0.0, 0.0, 2.0, 4.0) <= 0)
    True
    """

    c: float
    n: float = 1.0

    def __post_init__(self):
        object.__setattr__(self, "c", check_real("rolling_resistance", self.c, low=0.0))
        object.__setattr__(self, "n", check_real("n", self.n, low=0.0, high=1.0,
                                                    low_open=True))

    @classmethod
    def from_si(cls, c_si: float, n: float = 1.0, radius: float = 0.0375, mass: float = 0.45,
                gravity: float = STANDARD_GRAVITY) -> LoadRollingResistance:
        """From the SI law ``M = c_si F^n`` (``M`` [N m], ``F`` [N], ``c_si`` [N^(1-n) m]):
        ``c = c_si (m g)^(n - 1) / a``."""
        c_si = check_real("c_si", c_si, low=0.0)
        n = check_real("n", n, low=0.0, high=1.0, low_open=True)
        a = _positive("radius", radius)
        W = _positive("mass", mass) * _positive("gravity", gravity)
        return cls(c_si * W ** (n - 1.0) / a, n)

    def _load(self, F_z):
        return np.maximum(np.asarray(F_z, dtype=float), 0.0) ** self.n

    def moment(self, theta, omega1, omega2, omega3, F_z):
        """``(M_x, M_y, M_z)`` in Cxyz, units of ``m g a``."""
        wx, wy, wz = angular_velocity_xyz(theta, omega1, omega2, omega3)
        nh = np.hypot(wx, wy)
        k = np.where(nh > 0, -self.c * self._load(F_z) / np.where(nh > 0, nh, 1.0), 0.0)
        return (k * wx)[()], (k * wy)[()], (0.0 * k)[()]

    def power(self, theta, omega1, omega2, omega3, F_z):
        """``omega . M = -c max(F_z, 0)^n |omega_h| <= 0``."""
        wx, wy, wz = angular_velocity_xyz(theta, omega1, omega2, omega3)
        return np.asarray(-self.c * self._load(F_z) * np.hypot(wx, wy))[()]
