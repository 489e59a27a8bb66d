"""Numeric equations of motion, contact force and energy (section 2 and eqs. 37, 38, 49).

Dimensionless units throughout (m = a = g = 1, see :mod:`rollingdisk.disk`).  The
functions whose names start with an underscore are the kernels: plain arithmetic on floats
(or, element-wise, on numpy arrays) with no Python objects, so that the very same source can
be compiled with numba for batch work.  The public functions wrap them for a :class:`Disk`.

State vectors
-------------
rough ground (no slip), 8 components::

    y = [X_C, Y_C, psi, theta, phi, omega1, omega2, omega3]

smooth ground (no friction), 10 components::

    y = [X_C, Y_C, V_X, V_Y, psi, theta, phi, omega1, omega2, omega3]

``(X_C, Y_C)`` is the centre C in the inertial frame OXYZ, ``(V_X, V_Y)`` the inertial
horizontal velocity of C (constant on smooth ground), ``psi, theta, phi`` the spin,
inclination and rotation angles, ``omega1..3`` the angular velocity in C xi eta zeta
(eqs. 2-3).  ``Z_C`` is not a state: the contact constraint gives ``Z_C = -z_P`` (eq. 7).

Every formula here is checked against the sympy derivation in :mod:`rollingdisk.symbolic`
by ``tests/test_derivation.py``; see ``docs/errata.md``.

Why one module of ~650 lines: the kernels of every ground and mode (rough, smooth, and the
Coulomb rolling/sliding modes at the end) must live in one namespace, because
:mod:`rollingdisk._numba_core` compiles them from this module's source and re-binds the
kernels they call; splitting them would split that namespace.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .disk import Disk, check_ground
from .errors import ParameterError, ParameterTypeError

__all__ = [
    "ROUGH_STATE",
    "SMOOTH_STATE",
    "state_names",
    "state_index",
    "equations_of_motion",
    "omega_dot",
    "contact_force",
    "energy",
    "contact_point",
    "velocity_of_C",
]

#: Names of the rough-ground state components, in order.
ROUGH_STATE = ("X_C", "Y_C", "psi", "theta", "phi", "omega1", "omega2", "omega3")
#: Names of the smooth-ground state components, in order.
SMOOTH_STATE = ("X_C", "Y_C", "V_X", "V_Y", "psi", "theta", "phi", "omega1", "omega2", "omega3")


def state_names(ground: str) -> tuple[str, ...]:
    """The names of the state components for ``ground`` (``"rough"`` or ``"smooth"``)."""
    return ROUGH_STATE if check_ground(ground) == "rough" else SMOOTH_STATE


def state_index(ground: str, name: str) -> int:
    """Index of the component ``name`` in the state vector of ``ground``."""
    names = state_names(ground)
    if name not in names:
        raise ParameterError(f"name must be one of {names} on {ground} ground, got {name!r}")
    return names.index(name)


# ---------------------------------------------------------------------------------------
# kernels: plain arithmetic, numba-compilable, element-wise on arrays
# ---------------------------------------------------------------------------------------
def _geometry(h, theta):
    """``h~, sin, cos, tan, y_P, z_P`` at inclination ``theta`` (eq. 4, a = 1).

    This is the library's one definition of ``h~ = h sgn(theta)`` (which rim edge touches
    the plane); every other place takes ``h~`` from here (:func:`rollingdisk.disk.h_tilde`,
    the maps of :mod:`rollingdisk.steady` and :mod:`rollingdisk._stability`).  Convention:
    ``theta = 0`` counts as the limit ``theta -> 0+``, so ``h~ = +h`` there (and ``-0.0``
    too).  For ``h = 0`` nothing depends on it; for ``h > 0``, ``theta = 0`` (the disk on
    the line of its rim edge) is outside the theory, and a simulation stops there (the
    edge-contact guard).  Only the real part of ``theta`` decides the sign, so that the
    complex-step derivatives of :func:`rollingdisk.reduced_jacobian` pass through, and the
    expression compiles with numba, element-wise on arrays.
    """
    ht = h * np.sign(np.sign(np.real(theta)) + 0.5)  # sgn with sgn(0) = +1
    s = np.sin(theta)
    c = np.cos(theta)
    y_P = s - ht * c  # eq. (4)
    z_P = -(c + ht * s)  # eq. (4)
    return ht, s, c, s / c, y_P, z_P


def _rough_omega_dot(h, theta, w1, w2, w3):
    """Angular accelerations on rough ground, eq. (38) (confirmed by the derivation)."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    h2 = h * h
    d1 = (6.0 * (3.0 + 2.0 * ht * p) * w2 * w3
          - ((3.0 + 16.0 * h2) * p + 12.0 * ht) * w3 * w3
          + 12.0 * y_P) / (15.0 + 16.0 * h2)
    d2 = -(4.0 * ht * w2 + (2.0 / 3.0) * (3.0 + 4.0 * h2) * w3) * w1 / (3.0 + 8.0 * h2)
    d3 = (-6.0 * w2 / (3.0 + 8.0 * h2) + (p + 4.0 * ht / (3.0 + 8.0 * h2)) * w3) * w1
    return d1, d2, d3


def _smooth_omega_dot(h, theta, w1, w2, w3):
    """Angular accelerations on smooth ground, eq. (49) (confirmed by the derivation)."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = 0.25 + h * h / 3.0  # eq. (10)
    k2 = 0.5
    d1 = ((k2 * w2 - k1 * w3 * p) * w3 + y_P + y_P * z_P * w1 * w1) / (k1 + y_P * y_P)
    d2 = 0.0 * w1
    d3 = (-k2 * w2 + k1 * w3 * p) * w1 / k1
    return d1, d2, d3


def _rough_rhs(h, y):
    """Right-hand side on rough ground: eqs. (1), (2), (37), (38)."""
    X_C, Y_C, psi, theta, phi, w1, w2, w3 = y
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    v_Cx = w2 - ht * w3  # eq. (37)
    v_Cy = w1 * z_P  # eq. (37)
    cp = np.cos(psi)
    sp = np.sin(psi)
    d1, d2, d3 = _rough_omega_dot(h, theta, w1, w2, w3)
    return (v_Cx * cp - v_Cy * sp,  # eq. (1)
            v_Cx * sp + v_Cy * cp,
            w3 / c,  # eq. (2)
            w1,
            w2 - w3 * p,
            d1, d2, d3)


def _smooth_rhs(h, y):
    """Right-hand side on smooth ground: eqs. (2), (8) with F_x = F_y = 0, (49)."""
    X_C, Y_C, V_X, V_Y, psi, theta, phi, w1, w2, w3 = y
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    d1, d2, d3 = _smooth_omega_dot(h, theta, w1, w2, w3)
    zero = 0.0 * V_X
    return (V_X, V_Y, zero, zero, w3 / c, w1, w2 - w3 * p, d1, d2, d3)


def _reduced_rhs(rough, h, x):
    """Right-hand side of the reduced system ``x = (theta, omega1, omega2, omega3)``:
    ``d theta/dt = omega1`` (eq. 2) and eq. (38) on rough / (49) on smooth ground.

    It is autonomous and closed on both grounds; ``X_C, Y_C, psi, phi`` (and nothing else)
    follow from it by quadrature (eqs. 1, 2, 37)."""
    theta, w1, w2, w3 = x[0], x[1], x[2], x[3]
    if rough:
        d1, d2, d3 = _rough_omega_dot(h, theta, w1, w2, w3)
    else:
        d1, d2, d3 = _smooth_omega_dot(h, theta, w1, w2, w3)
    return w1, d1, d2, d3


def _reduced_state(rough, y):
    """``(theta, omega1, omega2, omega3)`` out of a state vector of either ground, or of a
    reduced state (4 components, returned as they are)."""
    if y.shape[0] == 4:
        return y[0], y[1], y[2], y[3]
    if rough:
        return y[3], y[5], y[6], y[7]
    return y[5], y[7], y[8], y[9]


def _normal_force(rough, h, y):
    """Normal force ``F_z = 1 + z_P omega1^2 - y_P d omega1/dt``, eq. (11)."""
    theta, w1, w2, w3 = _reduced_state(rough, y)
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    if rough:
        d1 = _rough_omega_dot(h, theta, w1, w2, w3)[0]
    else:
        d1 = _smooth_omega_dot(h, theta, w1, w2, w3)[0]
    return 1.0 + z_P * w1 * w1 - y_P * d1  # eq. (11)


def _side_normal_force(rough, h, y, side):
    """``F_z`` of eq. (11) with ``h~ = h side`` whatever the sign of ``theta``.

    The normal force of the motion on the side ``side = sgn(theta)`` it started on,
    continued across ``theta = 0`` (where ``h~ = h sgn(theta)`` jumps): the lift-off guard,
    which must not fire at that jump (an edge contact, not a lift-off).  The kernels use
    ``h`` only through ``h~`` and ``h^2``, so ``-h`` on the other side gives ``h~ = h side``.
    """
    theta = _reduced_state(rough, y)[0]
    if theta * side < 0.0:
        return _normal_force(rough, -h, y)
    return _normal_force(rough, h, y)


def _velocity_of_C(rough, h, y):
    """``(v_Cx, v_Cy, v_Cz)`` in Cxyz (eqs. 1, 7, 37)."""
    theta, w1, w2, w3 = _reduced_state(rough, y)
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    if rough:
        v_Cx = w2 - ht * w3  # eq. (37)
        v_Cy = w1 * z_P
    else:
        psi, V_X, V_Y = y[4], y[2], y[3]
        v_Cx = V_X * np.cos(psi) + V_Y * np.sin(psi)  # eq. (1) inverted
        v_Cy = -V_X * np.sin(psi) + V_Y * np.cos(psi)
    return v_Cx, v_Cy, -w1 * y_P  # eq. (7)


# ---------------------------------------------------------------------------------------
# public API
# ---------------------------------------------------------------------------------------
def _check_disk(disk) -> Disk:
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got {type(disk).__name__}"
                                 f" {disk!r}")
    return disk


def _shape_error(ground: str, y) -> ParameterError:
    names = state_names(ground)
    return ParameterError(f"y must have {len(names)} components on {ground} ground "
                          f"({', '.join(names)}), got {np.shape(y)}")


def _as_state(ground: str, y) -> np.ndarray:
    """``y`` as a float array of states: right length, finite (never a silent NaN)."""
    try:
        y = np.asarray(y, dtype=float)
    except (TypeError, ValueError):
        raise ParameterTypeError(f"y must be an array of real numbers, got {y!r}") from None
    if y.shape[:1] != (len(state_names(ground)),):
        raise _shape_error(ground, y)
    if not np.all(np.isfinite(y)):
        raise ParameterError("y must be finite (no NaN or infinity)")
    return y


def equations_of_motion(disk: Disk, ground: str) -> Callable[[float, np.ndarray], np.ndarray]:
    """The right-hand side ``f(t, y)`` of the equations of motion, for ``solve_ivp``.

    Parameters
    ----------
    disk : Disk
        The disk; only ``disk.h`` enters (dimensionless units).
    ground : {"rough", "smooth"}
        Rough: rolling without slip, eqs. (1), (2), (37), (38).  Smooth: no friction,
        eqs. (2), (8) with ``F_x = F_y = 0`` and (49).

    Returns
    -------
    callable
        ``f(t, y) -> dy/dt`` with ``y`` laid out as in :data:`ROUGH_STATE` or
        :data:`SMOOTH_STATE`; ``y`` may also be an ``(n, k)`` array of ``k`` states.

    Examples
    --------
    >>> from scipy.integrate import solve_ivp
    >>> f = equations_of_motion(Disk(h=0.1), "rough")
    >>> sol = solve_ivp(f, (0, 1), [0, 0, 0, 0.3, 0, 0, 2.0, 0.5], rtol=1e-10)
    >>> bool(sol.success)
    True
    """
    h = _check_disk(disk).h
    ground = check_ground(ground)
    kernel = _rough_rhs if ground == "rough" else _smooth_rhs
    n = len(state_names(ground))

    def f(t, y):
        y = np.asarray(y, dtype=float)  # a hot path: the shape only is checked per call
        if y.shape[:1] != (n,):
            raise _shape_error(ground, y)
        return np.array(kernel(h, y))

    f.__doc__ = f"dy/dt on {ground} ground for h = {h:g}."
    return f


def omega_dot(disk: Disk, ground: str, theta, omega1, omega2, omega3):
    """``(d omega1/dt, d omega2/dt, d omega3/dt)``: eq. (38) on rough, (49) on smooth ground.

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
    theta, omega1, omega2, omega3 : float or ndarray
        Inclination and angular velocity in C xi eta zeta (element-wise on arrays).

    Returns
    -------
    tuple
        The three angular accelerations.

    Notes
    -----
    These, with ``d theta/dt = omega1``, form the reduced system that governs the
    inclination and the angular velocity; positions and ``psi, phi`` do not enter.
    """
    kernel = _rough_omega_dot if check_ground(ground) == "rough" else _smooth_omega_dot
    return kernel(_check_disk(disk).h, theta, omega1, omega2, omega3)


def velocity_of_C(disk: Disk, ground: str, y):
    """Velocity of the centre C in Cxyz, ``(v_Cx, v_Cy, v_Cz)``, units of ``sqrt(a g)``.

    ``y`` is a state vector or an ``(n, k)`` array of states.  On rough ground the velocity
    follows from the no-slip condition, eq. (37); on smooth ground from the inertial velocity
    ``(V_X, V_Y)`` in the state.  ``v_Cz = -omega1 y_P`` (eq. 7).
    """
    y = _as_state(ground, y)
    return _velocity_of_C(ground == "rough", _check_disk(disk).h, y)


def contact_force(disk: Disk, ground: str, y):
    """Contact force ``(F_x, F_y, F_z)`` at P in Cxyz, units of ``m g`` (eqs. 8, 11).

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
    y : array_like
        A state vector, or an ``(n, k)`` array of ``k`` states (layout of
        :data:`ROUGH_STATE` / :data:`SMOOTH_STATE`).

    Returns
    -------
    tuple of float or ndarray
        ``(F_x, F_y, F_z)``.  On smooth ground ``F_x = F_y = 0``; contact is maintained
        while ``F_z > 0``.
    """
    y = _as_state(ground, y)
    h = _check_disk(disk).h
    rough = ground == "rough"
    F_z = _normal_force(rough, h, y)  # eq. (11)
    if not rough:
        return 0.0 * F_z, 0.0 * F_z, F_z
    theta, w1, w2, w3 = _reduced_state(rough, y)
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    d1, d2, d3 = _rough_omega_dot(h, theta, w1, w2, w3)
    v_Cx, v_Cy, v_Cz = _velocity_of_C(rough, h, y)  # eq. (37)
    Omega = w3 / c  # eq. (2)
    # eq. (8) with the time derivatives of (37): d y_P/d theta = -z_P, d z_P/d theta = y_P
    F_x = (d2 - ht * d3) - v_Cy * Omega
    F_y = (z_P * d1 + y_P * w1 * w1) + v_Cx * Omega
    return F_x, F_y, F_z


def energy(disk: Disk, ground: str, y):
    """Total mechanical energy, units of ``m g a`` (eq. 13), potential energy ``Z_C``.

    ``y`` is a state vector or an ``(n, k)`` array of states; returns a float or an array.
    ``Z_C = -z_P`` (eq. 7), so a disk standing upright at rest (h = 0) has ``E = 1``.
    """
    y = _as_state(ground, y)
    h = _check_disk(disk).h
    rough = ground == "rough"
    theta, w1, w2, w3 = _reduced_state(rough, y)
    z_P = _geometry(h, theta)[5]
    v_Cx, v_Cy, v_Cz = _velocity_of_C(rough, h, y)
    k1 = disk.k1_sq
    k2 = disk.k2_sq
    return (0.5 * (v_Cx * v_Cx + v_Cy * v_Cy + v_Cz * v_Cz)
            + 0.5 * k1 * (w1 * w1 + w3 * w3) + 0.5 * k2 * w2 * w2 - z_P)


def contact_point(disk: Disk, ground: str, y):
    """Contact point P on the plane, ``(X_P, Y_P)`` in OXYZ (eq. 5).

    ``y`` is a state vector or an ``(n, k)`` array of states; returns floats or arrays.
    """
    y = _as_state(ground, y)
    rough = ground == "rough"
    X_C, Y_C = y[0], y[1]
    psi, theta = (y[2], y[3]) if rough else (y[4], y[5])
    y_P = _geometry(_check_disk(disk).h, theta)[4]
    return X_C - y_P * np.sin(psi), Y_C + y_P * np.cos(psi)  # eq. (5)


# =======================================================================================
# Coulomb ground: rolling and sliding modes with friction and contact moments (issue 10)
# =======================================================================================
# Derived in rollingdisk.symbolic.coulomb and checked against it by tests/test_coulomb_eqs.py.
# State: the smooth one, y = [X_C, Y_C, V_X, V_Y, psi, theta, phi, omega1, omega2, omega3],
# V_X, V_Y the inertial horizontal velocity of C (no longer constant).  Contact moments are
# affine in the normal force, M = M0 + F_z M1 (components in Cxyz), see rollingdisk.ground.
#: Names of the Coulomb-ground state components (the smooth layout).
COULOMB_STATE = SMOOTH_STATE
#: Integer codes of the two modes of a Coulomb run (``Trajectory.mode``).
ROLLING, SLIDING = 0, 1
#: Mode code -> name.
MODE_NAMES = ("rolling", "sliding")


def _coulomb_moments(c_roll, c_pivot, c_air, theta, w1, w2, w3):
    """``M0, M1`` (6 floats, Cxyz) of the dissipative moments, ``M = M0 + F_z M1``.

    Rolling resistance ``-c F_z omega_h/|omega_h|``, pivot ``-c F_z sgn(omega_z) e_z``, air
    ``-c omega3 e_zeta / cos^3(theta)`` (see :mod:`rollingdisk.ground`).  Scalars only."""
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


def _rolling_solve(h, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z):
    """Rolling (no slip) with a contact moment ``M = M0 + F_z M1``: eqs. (8), (9), (11) with
    the constraint (37).  Returns ``(dw1, dw2, dw3, F_x, F_y, F_z)`` (forces in Cxyz)."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = 0.25 + h * h / 3.0  # eq. (10)
    k2 = 0.5
    Om = w3 / c  # eq. (2)
    v_Cx = w2 - ht * w3  # eq. (37)
    v_Cy = w1 * z_P
    G1 = (k2 * w2 - k1 * w3 * p) * w3
    G3 = (-k2 * w2 + k1 * w3 * p) * w1
    # (9)_1 with F_y from (8)_2 and F_z from (11): the omega1^2 terms cancel
    d1 = ((G1 - z_P * v_Cx * Om + y_P + M0x + M1x * (1.0 + z_P * w1 * w1))
          / (k1 + z_P * z_P + y_P * y_P + y_P * M1x))
    F_z = 1.0 + z_P * w1 * w1 - y_P * d1  # eq. (11)
    My = M0y + F_z * M1y
    Mz = M0z + F_z * M1z
    Meta = c * My + s * Mz
    Mzeta = -s * My + c * Mz
    # (9)_2, (9)_3 with F_x = d v_Cx/dt - v_Cy Omega, d v_Cx/dt = dw2 - h~ dw3
    a11 = k2 + 1.0
    a22 = k1 + ht * ht
    b1 = v_Cy * Om + Meta
    b2 = G3 - ht * v_Cy * Om + Mzeta
    det = a11 * a22 - ht * ht
    d2 = (b1 * a22 + ht * b2) / det
    d3 = (a11 * b2 + ht * b1) / det
    F_x = d2 - ht * d3 - v_Cy * Om  # eq. (8)_1
    F_y = z_P * d1 + y_P * w1 * w1 + v_Cx * Om  # eq. (8)_2
    return d1, d2, d3, F_x, F_y, F_z


def _sliding_solve(h, mu, e_x, e_y, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z):
    """Sliding with friction ``F_t = -mu F_z e`` (``e`` a unit vector in Cxyz) and a contact
    moment ``M = M0 + F_z M1``: (9) with ``F_z`` from (11), solved jointly with
    ``d omega1/dt``.  Returns ``(dw1, dw2, dw3, F_x, F_y, F_z)`` (forces in Cxyz)."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = 0.25 + h * h / 3.0  # eq. (10)
    k2 = 0.5
    G1 = (k2 * w2 - k1 * w3 * p) * w3
    G3 = (-k2 * w2 + k1 * w3 * p) * w1
    q = mu * z_P * e_y + y_P + M1x  # (9)_1 = G1 + q F_z + M0x
    d1 = (G1 + M0x + q * (1.0 + z_P * w1 * w1)) / (k1 + y_P * q)
    F_z = 1.0 + z_P * w1 * w1 - y_P * d1  # eq. (11)
    F_x = -mu * F_z * e_x
    F_y = -mu * F_z * e_y
    My = M0y + F_z * M1y
    Mz = M0z + F_z * M1z
    d2 = (-F_x + c * My + s * Mz) / k2  # eq. (9)_2
    d3 = (G3 + ht * F_x - s * My + c * Mz) / k1  # eq. (9)_3
    return d1, d2, d3, F_x, F_y, F_z


def _slip_velocity(h, y):
    """Slip velocity of the contact point ``(u_x, u_y)`` in Cxyz (eq. 6), Coulomb state."""
    V_X, V_Y, psi, theta, w1, w2, w3 = y[2], y[3], y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    cp = np.cos(psi)
    sp = np.sin(psi)
    v_Cx = V_X * cp + V_Y * sp
    v_Cy = -V_X * sp + V_Y * cp
    return v_Cx - w2 + ht * w3, v_Cy - w1 * z_P  # eq. (6)


def _coulomb_rolling(h, c_roll, c_pivot, c_air, y):
    """Rolling mode at a Coulomb state: ``(dy[0:10], F_x, F_y, F_z, P_roll, P_pivot,
    P_air)``; ``X_C, Y_C`` move with the no-slip velocity (37), ``V_X, V_Y`` with the force."""
    psi, theta, w1, w2, w3 = y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    M0x, M0y, M0z, M1x, M1y, M1z = _coulomb_moments(c_roll, c_pivot, c_air, theta, w1, w2, w3)
    d1, d2, d3, F_x, F_y, F_z = _rolling_solve(h, theta, w1, w2, w3,
                                               M0x, M0y, M0z, M1x, M1y, M1z)
    cp = np.cos(psi)
    sp = np.sin(psi)
    v_Cx = w2 - ht * w3  # eq. (37)
    v_Cy = w1 * z_P
    P1, P2, P3 = _coulomb_powers(c_roll, c_pivot, c_air, theta, w1, w2, w3, F_z)
    dy = (v_Cx * cp - v_Cy * sp, v_Cx * sp + v_Cy * cp,  # eq. (1)
          F_x * cp - F_y * sp, F_x * sp + F_y * cp,  # eq. (8), inertial components
          w3 / c, w1, w2 - w3 * p, d1, d2, d3)  # eq. (2)
    return dy, F_x, F_y, F_z, P1, P2, P3


def _coulomb_sliding(h, mu_k, c_roll, c_pivot, c_air, y, ref_X, ref_Y, u_eps=0.0):
    """Sliding mode at a Coulomb state: ``(dy[0:10], F_x, F_y, F_z, P_slip, P_roll,
    P_pivot, P_air)``.

    The friction direction is ``e = sigma u/|u|`` with ``sigma = sgn(u . ref)`` for the
    inertial reference direction ``ref`` (the slip direction when the step began): equal
    to ``u/|u|`` while the slip keeps its direction, and the smooth continuation of the
    sliding solution through ``u = 0``, where the hybrid driver stops it (an event).  Where
    ``|u| <= u_eps`` (the slip just started from rest, its direction not yet resolved
    above rounding), ``e = ref``."""
    psi, theta, w1, w2, w3 = y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    cp = np.cos(psi)
    sp = np.sin(psi)
    u_x, u_y = _slip_velocity(h, y)
    n = np.sqrt(u_x * u_x + u_y * u_y)
    r_x = ref_X * cp + ref_Y * sp  # ref in Cxyz
    r_y = -ref_X * sp + ref_Y * cp
    if n > u_eps and n > 0.0:
        sig = 1.0
        if u_x * r_x + u_y * r_y < 0.0:
            sig = -1.0
        e_x = sig * u_x / n
        e_y = sig * u_y / n
    else:
        e_x = r_x
        e_y = r_y
    M0x, M0y, M0z, M1x, M1y, M1z = _coulomb_moments(c_roll, c_pivot, c_air, theta, w1, w2, w3)
    d1, d2, d3, F_x, F_y, F_z = _sliding_solve(h, mu_k, e_x, e_y, theta, w1, w2, w3,
                                               M0x, M0y, M0z, M1x, M1y, M1z)
    P1, P2, P3 = _coulomb_powers(c_roll, c_pivot, c_air, theta, w1, w2, w3, F_z)
    dy = (y[2], y[3],  # eq. (1)
          F_x * cp - F_y * sp, F_x * sp + F_y * cp,  # eq. (8), inertial components
          w3 / c, w1, w2 - w3 * p, d1, d2, d3)  # eq. (2)
    return dy, F_x, F_y, F_z, F_x * u_x + F_y * u_y, P1, P2, P3


def _coulomb_energy(h, y):
    """Energy (eq. 13) at a Coulomb state: ``V_X, V_Y`` from the state, ``v_Cz`` from (7)."""
    V_X, V_Y, theta, w1, w2, w3 = y[2], y[3], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = 0.25 + h * h / 3.0
    v_Cz = -w1 * y_P
    return (0.5 * (V_X * V_X + V_Y * V_Y + v_Cz * v_Cz) + 0.5 * k1 * (w1 * w1 + w3 * w3)
            + 0.25 * w2 * w2 - z_P)


def _rolling_velocity(h, y):
    """Inertial ``(V_X, V_Y)`` of C that rolling (no slip, eq. 37) implies at state ``y``."""
    psi, theta, w1, w2, w3 = y[4], y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    v_Cx = w2 - ht * w3
    v_Cy = w1 * z_P
    cp = np.cos(psi)
    sp = np.sin(psi)
    return v_Cx * cp - v_Cy * sp, v_Cx * sp + v_Cy * cp


# ------------------------------------------------------------------- public wrappers
def _check_coulomb(ground):
    from .ground import Coulomb

    if not isinstance(ground, Coulomb):
        raise ParameterError(f"ground must be a rollingdisk.Coulomb(...) value here, got "
                             f"{ground!r}")
    return ground


def _check_mode(mode) -> int:
    if mode in ("rolling", ROLLING) and not isinstance(mode, bool):
        return ROLLING
    if mode in ("sliding", SLIDING) and not isinstance(mode, bool):
        return SLIDING
    raise ParameterError(f"mode must be 'rolling' or 'sliding', got {mode!r}")


def coulomb_rhs(disk: Disk, ground, mode, y, slip_reference=None) -> np.ndarray:
    """``dy/dt`` on Coulomb ground in one mode, state layout :data:`COULOMB_STATE`.

    Parameters
    ----------
    disk : Disk
    ground : Coulomb
    mode : {"rolling", "sliding"}
        Rolling: no slip, the contact force follows from the constraint (eqs. 8, 9, 11, 37)
        with the contact moments of ``ground``; ``X_C, Y_C`` move with the no-slip velocity.
        Sliding: ``F_t = -mu_k F_z u/|u|`` (``u`` from eq. 6), ``F_z`` from eq. (11).
    y : array_like, shape (10,)
    slip_reference : (float, float), optional
        Sliding only: the inertial direction used when ``u = 0`` (default: ``(1, 0)``).

    Returns
    -------
    ndarray, shape (10,)
    """
    g = _check_coulomb(ground)
    y = _as_state("smooth", y)
    cr, cpv, ca = g.coefficients
    if _check_mode(mode) == ROLLING:
        return np.array(_coulomb_rolling(disk.h, cr, cpv, ca, y)[0])
    rx, ry = (1.0, 0.0) if slip_reference is None else slip_reference
    u = _slip_velocity(disk.h, y)
    if slip_reference is None and (u[0] or u[1]):
        rx, ry = _to_inertial(y[4], *u)
    return np.array(_coulomb_sliding(disk.h, g.mu_k, cr, cpv, ca, y, rx, ry)[0])


def _to_inertial(psi, ax, ay):
    cp, sp = np.cos(psi), np.sin(psi)
    return ax * cp - ay * sp, ax * sp + ay * cp


def coulomb_contact(disk: Disk, ground, mode, y) -> dict:
    """Contact quantities on Coulomb ground in one mode at state ``y`` (shape (10,)).

    Returns
    -------
    dict
        ``F_x, F_y, F_z`` (contact force in Cxyz, units ``m g``), ``F_t = |(F_x, F_y)|``,
        ``u_x, u_y`` (slip velocity, eq. 6), ``power_slip`` (``v_P . F_t``), and the
        powers ``power_rolling_resistance``, ``power_pivot``, ``power_air`` (``omega . M``
        of each moment; all powers ``<= 0``, eq. 14).
    """
    g = _check_coulomb(ground)
    y = _as_state("smooth", y)
    cr, cpv, ca = g.coefficients
    u_x, u_y = _slip_velocity(disk.h, y)
    if _check_mode(mode) == ROLLING:
        _, F_x, F_y, F_z, P1, P2, P3 = _coulomb_rolling(disk.h, cr, cpv, ca, y)
        P0 = 0.0
    else:
        rx, ry = _to_inertial(y[4], u_x, u_y) if (u_x or u_y) else (1.0, 0.0)
        _, F_x, F_y, F_z, P0, P1, P2, P3 = _coulomb_sliding(disk.h, g.mu_k, cr, cpv, ca, y,
                                                            rx, ry)
    return {"F_x": F_x, "F_y": F_y, "F_z": F_z, "F_t": float(np.hypot(F_x, F_y)),
            "u_x": u_x, "u_y": u_y, "power_slip": P0, "power_rolling_resistance": P1,
            "power_pivot": P2, "power_air": P3}


def coulomb_energy(disk: Disk, y):
    """Total mechanical energy (eq. 13) at a Coulomb state (layout :data:`COULOMB_STATE`)."""
    y = _as_state("smooth", y)
    return _coulomb_energy(disk.h, y)


def rolling_state(disk: Disk, y_rough) -> np.ndarray:
    """The Coulomb (smooth-layout) state of a rough-ground state: ``V_X, V_Y`` from the
    no-slip condition (eq. 37) rotated into OXYZ (eq. 1)."""
    y_rough = _as_state("rough", y_rough)
    X_C, Y_C, psi, theta, phi, w1, w2, w3 = y_rough
    y = np.array([X_C, Y_C, 0.0, 0.0, psi, theta, phi, w1, w2, w3])
    y[2], y[3] = _rolling_velocity(disk.h, y)
    return y


__all__ += ["COULOMB_STATE", "MODE_NAMES", "coulomb_rhs", "coulomb_contact", "coulomb_energy",
            "rolling_state"]
