"""Grounds as values: the paper's two ideal grounds and real ground with Coulomb friction.

The paper (section 2) leaves the friction force ``F_t = (F_x, F_y)`` and the contact moment
``M = (M_x, M_y, M_z)`` (components in Cxyz) to constitutive laws that obey eq. (14):
``v_P . F_t <= 0`` and ``omega . M <= 0``.  The ideal grounds are the strings ``"rough"``
(no slip) and ``"smooth"`` (no friction), accepted everywhere as before.  This module adds

* :class:`Coulomb` - dry friction with static and kinetic coefficients ``mu_s >= mu_k >= 0``:
  the disk rolls while ``|F_t| <= mu_s F_z`` and slides with ``F_t = -mu_k F_z u/|u|``
  (``u`` the slip velocity of the contact point, eq. 6) otherwise;
* the dissipative contact moments it may carry, each a separate model with its source:
  :class:`RollingResistance`, :class:`PivotFriction` and :class:`AirDrag`.

Every moment model is *affine in the normal force*: ``M = M0 + F_z M1`` with ``M0``, ``M1``
functions of the state, so the equations of motion stay linear in the unknown
accelerations and forces (see :mod:`rollingdisk.symbolic.coulomb`).  Each model gives its
moment and its power ``omega . M``, which is ``<= 0`` whenever ``F_z >= 0``.  Dimensionless
units (m = a = g = 1); the physical meaning of each coefficient is in ``docs/friction.md``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rollingdisk.model.disk import GROUNDS
from rollingdisk.util.checks import check_real, real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["Coulomb", "RollingResistance", "PivotFriction", "AirDrag", "check_any_ground",
           "ground_name", "angular_velocity_xyz"]


def angular_velocity_xyz(theta, omega1, omega2, omega3):
    """Angular velocity of the disk in Cxyz, ``(omega_x, omega_y, omega_z)``.

    ``omega`` is given in C xi eta zeta (eqs. 2-3); C xi eta zeta is Cxyz turned by
    ``theta`` about x, so ``omega_y = omega2 cos(theta) - omega3 sin(theta)`` and
    ``omega_z = omega2 sin(theta) + omega3 cos(theta)`` (``omega_z = d psi/dt + ...``, the
    spin about the vertical).  Element-wise on arrays.
    """
    for name, value in (("theta", theta), ("omega1", omega1), ("omega2", omega2),
                        ("omega3", omega3)):
        real_array(name, value)  # named errors for non-numbers and ints beyond float range
    s, c = np.sin(theta), np.cos(theta)
    return omega1, omega2 * c - omega3 * s, omega2 * s + omega3 * c


# kernels of the moment models: scalars, numba-compilable; the classes below evaluate them
def _coulomb_moments(c_roll, c_pivot, c_air, theta, w1, w2, w3):
    """``M0, M1`` (6 floats, Cxyz) of the dissipative moments, ``M = M0 + F_z M1``.

    Rolling resistance ``-c F_z omega_h/|omega_h|``, pivot ``-c F_z sgn(omega_z) e_z``, air
    ``-c omega3 e_zeta / cos^3(theta)`` (the classes below).  Scalars only."""
    s = np.sin(theta)
    c = np.cos(theta)
    wx = w1
    wy = w2 * c - w3 * s
    wz = w2 * s + w3 * c
    n = np.sqrt(wx * wx + wy * wy)
    kr = 0.0
    if n > 0.0:
        kr = -c_roll / n
    ka = -c_air * w3 / (c * c * c)  # air: -c omega3 zeta / cos^3(theta), zeta = (0, -s, c)
    M1z = -c_pivot * np.sign(wz)
    return 0.0, -ka * s, ka * c, kr * wx, kr * wy, M1z


def _coulomb_powers(c_roll, c_pivot, c_air, theta, w1, w2, w3, F_z):
    """Power ``omega . M`` of each moment: ``(rolling resistance, pivot, air)``, each <= 0."""
    s = np.sin(theta)
    c = np.cos(theta)
    wx = w1
    wy = w2 * c - w3 * s
    wz = w2 * s + w3 * c
    wh2 = wx * wx + wy * wy
    return -c_roll * F_z * np.sqrt(wh2), -c_pivot * F_z * np.abs(wz), -c_air * w3 * w3 / (c * c * c)


def _moment(c_roll, c_pivot, c_air, theta, omega1, omega2, omega3, F_z):
    """``M = M0 + F_z M1`` of :func:`_coulomb_moments`, element-wise on arrays."""
    def one(th, w1, w2, w3, fz):
        m = _coulomb_moments(c_roll, c_pivot, c_air, th, w1, w2, w3)
        return m[0] + fz * m[3], m[1] + fz * m[4], m[2] + fz * m[5]

    out = np.vectorize(one, otypes=[float] * 3)(theta, omega1, omega2, omega3, F_z)
    return tuple(np.asarray(a)[()] for a in out)


def _power(which, c_roll, c_pivot, c_air, theta, omega1, omega2, omega3, F_z):
    """Power ``omega . M`` of one moment (``which``: 0 rolling resistance, 1 pivot, 2 air)
    of :func:`_coulomb_powers`, element-wise on arrays."""
    def one(th, w1, w2, w3, fz):
        return _coulomb_powers(c_roll, c_pivot, c_air, th, w1, w2, w3, fz)[which]

    return np.asarray(np.vectorize(one, otypes=[float])(theta, omega1, omega2, omega3,
                                                        F_z))[()]


def _coefficient(name, value):
    return check_real(name, value, low=0.0)


@dataclass(frozen=True)
class RollingResistance:
    """Rolling resistance: a Coulomb-type moment opposing the rolling (tilting) rotation.

    ``M_h = -c F_z omega_h / |omega_h|`` with ``omega_h = (omega_x, omega_y)`` the horizontal
    part of the angular velocity in Cxyz, ``M_z = 0``; zero when ``omega_h = 0`` (these
    methods).  Its power is ``-c F_z |omega_h| <= 0``.  ``c`` (units of ``a``) is the
    rolling-resistance length, the lever arm by which the normal force is offset ahead of
    the contact point.

    The law is set-valued at ``omega_h = 0``: there ``|M_h| <= c F_z``.  The hybrid
    simulation (:func:`rollingdisk.simulate_coulomb`) treats it so: where ``omega_h``
    stops, the moment that holds it at zero (derived in
    :func:`rollingdisk.symbolic.coulomb.derive_roll_stuck`) is taken if it fits in
    ``c F_z`` (a "roll stuck" mode, left when that moment reaches ``c F_z``), else the
    moment flips.

    Source: the set-valued rolling friction law of Le Saux, Leine & Glocker, "Dynamics of a
    rolling disk in the presence of dry friction", J. Nonlinear Sci. 15 (2005) 27 (their
    rolling-friction torque bounded by ``F_z`` times a length), its sliding branch here
    and its sticking branch in the hybrid driver; the same form is Chrono's rolling
    friction.  See ``docs/friction.md``.
    """

    c: float

    def __post_init__(self):
        object.__setattr__(self, "c", _coefficient("rolling_resistance", self.c))

    def moment(self, theta, omega1, omega2, omega3, F_z):
        """``(M_x, M_y, M_z)`` in Cxyz, units of ``m g a``."""
        return _moment(self.c, 0.0, 0.0, theta, omega1, omega2, omega3, F_z)

    def power(self, theta, omega1, omega2, omega3, F_z):
        """``omega . M = -c F_z |omega_h|`` (eq. 12), ``<= 0`` for ``F_z >= 0``."""
        return _power(0, self.c, 0.0, 0.0, theta, omega1, omega2, omega3, F_z)


@dataclass(frozen=True)
class PivotFriction:
    """Pivoting (drilling) friction: a Coulomb-type moment about the vertical.

    ``M_z = -c F_z sgn(omega_z)``, ``M_x = M_y = 0``, with ``omega_z`` the vertical component
    of the angular velocity (Cxyz); power ``-c F_z |omega_z| <= 0``.  ``c`` (units of ``a``)
    is the pivoting-friction length: for a contact patch of radius ``r`` with uniform
    pressure and friction coefficient ``mu``, ``c = 2 mu r / 3``.

    Source: Le Saux, Leine & Glocker, J. Nonlinear Sci. 15 (2005) 27 (pivoting friction as
    a set-valued torque bounded by ``F_z`` times a length; its sliding branch here); Leine,
    Arch. Appl. Mech. 79 (2009) 1063.  See ``docs/friction.md``.
    """

    c: float

    def __post_init__(self):
        object.__setattr__(self, "c", _coefficient("pivot", self.c))

    def moment(self, theta, omega1, omega2, omega3, F_z):
        """``(M_x, M_y, M_z)`` in Cxyz, units of ``m g a``."""
        return _moment(0.0, self.c, 0.0, theta, omega1, omega2, omega3, F_z)

    def power(self, theta, omega1, omega2, omega3, F_z):
        """``omega . M = -c F_z |omega_z|``, ``<= 0`` for ``F_z >= 0``."""
        return _power(1, 0.0, self.c, 0.0, theta, omega1, omega2, omega3, F_z)


@dataclass(frozen=True)
class AirDrag:
    """Viscous drag of the air film under the disk, after Moffatt's model of Euler's disk.

    ``M = -c omega3 e_zeta / cos^3(theta)`` with ``e_zeta = (0, -sin theta, cos theta)`` (Cxyz)
    the in-plane axis of C xi eta zeta that turns with the precession; power
    ``-c omega3^2 / cos^3(theta) = -c Omega^2 / cos(theta) <= 0`` (``omega3 = Omega cos
    theta``, eq. 3).  Near the end of Euler's disk the tilt ``alpha = pi/2 - |theta|`` is
    small and ``cos(theta) = sin(alpha) ~ alpha``: the power is ``-c Omega^2 / alpha``,
    the dissipation ``Phi = K mu_air a^3 Omega^2 / alpha`` of the squeeze film under the
    disk, ``K`` = 1.28113 from the Reynolds equation solved exactly
    (:mod:`rollingdisk.symbolic.air_film`; Moffatt estimated ``K = 2 pi``, a gap of
    thickness ``a alpha`` sheared at ``a Omega``, 4.90 times too large:
    ``docs/errata-models.md``).  Hence ``c = K mu_air a^(3/2) / (m g^(1/2))`` in the
    library's units (``mu_air ~ 1.8e-5 Pa s``; :func:`.air_models.air_coefficient_derived`):
    ``c`` is a moment per angular speed, in units of ``m g a / sqrt(g/a) = m a^(3/2)
    g^(1/2)``.  Independent of ``F_z``.

    Source: H. K. Moffatt, "Euler's disk and its finite-time singularity", Nature 404
    (2000) 833 (with rolling, ``Omega^2 alpha = 4 g/a`` and ``E ~ (3/2) m g a alpha``, it
    predicts ``alpha ~ (t0 - t)^(1/3)``, ``Omega ~ (t0 - t)^(-1/6)``).  The form away from
    small ``alpha`` (the ``omega3`` moment and ``1/cos^3``) is this library's choice, see
    ``docs/friction.md``.
    """

    c: float

    def __post_init__(self):
        object.__setattr__(self, "c", _coefficient("air", self.c))

    def moment(self, theta, omega1, omega2, omega3, F_z=None):
        """``(M_x, M_y, M_z)`` in Cxyz, units of ``m g a``."""
        return _moment(0.0, 0.0, self.c, theta, omega1, omega2, omega3, 0.0)

    def power(self, theta, omega1, omega2, omega3, F_z=None):
        """``omega . M = -c omega3^2 / cos^3(theta) <= 0``."""
        return _power(2, 0.0, 0.0, self.c, theta, omega1, omega2, omega3, 0.0)


#: Largest friction coefficient :class:`Coulomb` takes: beyond it the ground is rough for
#: every purpose (the friction a rolling disk needs is of order 1), and ``mu F_z`` would only
#: bring the sliding equations to the edge of floating-point range (issue 18, item 4).
MU_MAX = 1e6


def _check_mu(name, value):
    mu = check_real(name, value, low=0.0)
    if mu > MU_MAX:
        raise ParameterError(f"{name} must lie in [0, {MU_MAX:g}], got {mu!r}: beyond it the "
                             "ground is perfectly rough for every purpose; use the rough "
                             "ground (rolling without slip) instead")
    return mu


def _model(name, cls, value):
    if value is None or isinstance(value, cls):
        return value
    if isinstance(value, (bool, str)) or not isinstance(value, (int, float, np.integer,
                                                                 np.floating)):
        raise ParameterTypeError(f"{name} must be a {cls.__name__} or a real number >= 0, got "
                                 f"{type(value).__name__} {value!r}")
    value = check_real(name, value, low=0.0)  # NaN, infinities, 10**400: named errors
    return cls(value) if value != 0.0 else None


@dataclass(frozen=True)
class Coulomb:
    """Real ground: Coulomb friction, rolling while it can, sliding when it cannot.

    Parameters
    ----------
    mu_s : float
        Static friction coefficient (dimensionless), ``>= 0``: the disk rolls while the
        friction force needed for rolling stays inside the cone, ``|F_t| <= mu_s F_z``.
    mu_k : float, optional
        Kinetic coefficient (dimensionless), ``0 <= mu_k <= mu_s``; ``mu_s`` by default.
        Sliding friction is ``F_t = -mu_k F_z u/|u|``, ``u`` the slip velocity of the
        contact point (eq. 6).
    rolling_resistance : RollingResistance or float, optional
    pivot : PivotFriction or float, optional
    air : AirDrag or float, optional
        Dissipative contact moments (a number ``c`` means ``Model(c)``; 0 or ``None``
        means none); ``c`` of rolling resistance and pivoting is a length in units of the
        radius ``a``, of the air film in units of ``m a^(3/2) g^(1/2)`` (see each model).

    Raises
    ------
    ParameterError
        A negative, NaN or infinite coefficient, or ``mu_k > mu_s`` (message names it).
    ParameterTypeError
        A coefficient that is not a real number.

    Examples
    --------
    >>> g = Coulomb(0.3)
    >>> g.mu_k, g.dissipative
    (0.3, False)
    >>> Coulomb(0.3, 0.2, pivot=0.01).pivot
    PivotFriction(c=0.01)
    """

    mu_s: float
    mu_k: float | None = None
    rolling_resistance: RollingResistance | None = None
    pivot: PivotFriction | None = None
    air: AirDrag | None = None

    def __post_init__(self):
        mu_s = _check_mu("mu_s", self.mu_s)
        mu_k = mu_s if self.mu_k is None else _check_mu("mu_k", self.mu_k)
        if mu_k > mu_s:
            raise ParameterError(f"mu_k must lie in [0, mu_s] = [0, {mu_s:g}] (kinetic "
                                 f"friction cannot exceed static friction), got {mu_k!r}")
        object.__setattr__(self, "mu_s", mu_s)
        object.__setattr__(self, "mu_k", mu_k)
        object.__setattr__(self, "rolling_resistance",
                           _model("rolling_resistance", RollingResistance,
                                  self.rolling_resistance))
        object.__setattr__(self, "pivot", _model("pivot", PivotFriction, self.pivot))
        object.__setattr__(self, "air", _model("air", AirDrag, self.air))

    name = "coulomb"

    @property
    def dissipative(self) -> bool:
        """Whether any dissipative moment is on (then ``dE/dt <= 0`` even while rolling)."""
        return any(m is not None for m in self.moments)

    @property
    def moments(self) -> tuple:
        """The moment models, in the order rolling resistance, pivot, air (``None`` if off)."""
        return (self.rolling_resistance, self.pivot, self.air)

    @property
    def coefficients(self) -> tuple[float, float, float]:
        """``(c_roll, c_pivot, c_air)``, zero for a term that is off (kernel arguments)."""
        return tuple(0.0 if m is None else m.c for m in self.moments)

    def as_dict(self) -> dict:
        """Plain dict: ``{"ground": "coulomb", "mu_s", "mu_k", "rolling_resistance",
        "pivot", "air"}`` (coefficients ``c``, ``None`` when off)."""
        return {"ground": "coulomb", "mu_s": self.mu_s, "mu_k": self.mu_k,
                **{n: (None if m is None else m.c) for n, m in
                   zip(("rolling_resistance", "pivot", "air"), self.moments)}}


def check_any_ground(ground):
    """``"rough"``, ``"smooth"`` or a :class:`Coulomb` value, else raise.

    Strings other than the two ideal grounds raise :class:`ParameterError`; other objects
    :class:`ParameterTypeError`.
    """
    if isinstance(ground, Coulomb):
        return ground
    if isinstance(ground, str):
        if ground in GROUNDS:
            return ground
        raise ParameterError(f"ground must be one of {GROUNDS} or a Coulomb(...) value, got "
                             f"{ground!r}")
    raise ParameterTypeError(f"ground must be one of {GROUNDS} or a Coulomb(...) value, got "
                             f"{type(ground).__name__} {ground!r}")


def ground_name(ground) -> str:
    """``"rough"``, ``"smooth"`` or ``"coulomb"``."""
    g = check_any_ground(ground)
    return g if isinstance(g, str) else "coulomb"
