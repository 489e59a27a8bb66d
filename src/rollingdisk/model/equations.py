"""Equations of motion on the paper's two ideal grounds (section 2), numpy only.

Dimensionless units throughout (m = a = g = 1, see :mod:`rollingdisk.model.disk`).  The
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

The kernels of the two ideal grounds live in one namespace (with the geometry and state
kernels they import) because :mod:`rollingdisk.engine.numba_core` compiles them from this
module's source and re-binds the kernels they call.  The Coulomb modes are in
:mod:`rollingdisk.model.coulomb`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from rollingdisk.model.disk import Disk, check_ground, sharp_h
from rollingdisk.model.geometry import _geometry, _inertia
from rollingdisk.model.state import _reduced_state, _shape_error, as_state, state_names
from rollingdisk.util.checks import real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["equations_of_motion", "omega_dot", "contact_force", "energy", "contact_point",
           "velocity_of_C"]



def rough_omega_dot(h, theta, w1, w2, w3):
    """Angular accelerations on rough ground, eq. (38) (confirmed by the derivation)."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    h2 = h * h
    d1 = (6.0 * (3.0 + 2.0 * ht * p) * w2 * w3
          - ((3.0 + 16.0 * h2) * p + 12.0 * ht) * w3 * w3
          + 12.0 * y_P) / (15.0 + 16.0 * h2)
    d2 = -(4.0 * ht * w2 + (2.0 / 3.0) * (3.0 + 4.0 * h2) * w3) * w1 / (3.0 + 8.0 * h2)
    d3 = (-6.0 * w2 / (3.0 + 8.0 * h2) + (p + 4.0 * ht / (3.0 + 8.0 * h2)) * w3) * w1
    return d1, d2, d3


def smooth_omega_dot(h, theta, w1, w2, w3):
    """Angular accelerations on smooth ground, eq. (49) (confirmed by the derivation)."""
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    k1 = _inertia(h)[0]  # eq. (10)
    k2 = 0.5
    d1 = ((k2 * w2 - k1 * w3 * p) * w3 + y_P + y_P * z_P * w1 * w1) / (k1 + y_P * y_P)
    d2 = 0.0 * w1
    d3 = (-k2 * w2 + k1 * w3 * p) * w1 / k1
    return d1, d2, d3


def rough_rhs(h, y):
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


def smooth_rhs(h, y):
    """Right-hand side on smooth ground: eqs. (2), (8) with F_x = F_y = 0, (49)."""
    X_C, Y_C, V_X, V_Y, psi, theta, phi, w1, w2, w3 = y
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    d1, d2, d3 = _smooth_omega_dot(h, theta, w1, w2, w3)
    zero = 0.0 * V_X
    return (V_X, V_Y, zero, zero, w3 / c, w1, w2 - w3 * p, d1, d2, d3)


def reduced_rhs(rough, h, x):
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


def normal_force(rough, h, y):
    """Normal force ``F_z = 1 + z_P omega1^2 - y_P d omega1/dt``, eq. (11)."""
    theta, w1, w2, w3 = _reduced_state(rough, y)
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    if rough:
        d1 = _rough_omega_dot(h, theta, w1, w2, w3)[0]
    else:
        d1 = _smooth_omega_dot(h, theta, w1, w2, w3)[0]
    return 1.0 + z_P * w1 * w1 - y_P * d1  # eq. (11)


def side_normal_force(rough, h, y, side):
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


#: The kernels under the names by which they call each other and by which the compiled
#: namespaces (:mod:`rollingdisk.engine.numba_core`, :mod:`rollingdisk.engine.pycore`)
#: bind their compiled versions.
_rough_omega_dot, _smooth_omega_dot = rough_omega_dot, smooth_omega_dot
_rough_rhs, _smooth_rhs, _reduced_rhs = rough_rhs, smooth_rhs, reduced_rhs
_normal_force, _side_normal_force = normal_force, side_normal_force


# ---------------------------------------------------------------------------------------
# public API
# ---------------------------------------------------------------------------------------
def check_disk(disk) -> Disk:
    """``disk`` if it is a sharp-edged :class:`~rollingdisk.model.disk.Disk`, else
    :class:`~rollingdisk.util.errors.ParameterTypeError` naming it (a rounded rim:
    :class:`~rollingdisk.util.errors.ParameterError`, :func:`~rollingdisk.model.disk.sharp_h`)."""
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got {type(disk).__name__}"
                                 f" {disk!r}")
    sharp_h(disk)  # these equations are the sharp-edged disk's (model.rim: a rounded rim)
    return disk


_check_disk = check_disk  # the name model.coulomb, ivp and phases import


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
        The three angular accelerations.  At a single point (scalars in) finite input
        whose terms overflow floating-point range (e.g. ``omega3 = 1e308``) is a
        :class:`~rollingdisk.ParameterError`, never a NaN.

    Notes
    -----
    These, with ``d theta/dt = omega1``, form the reduced system that governs the
    inclination and the angular velocity; positions and ``psi, phi`` do not enter.
    """
    kernel = _rough_omega_dot if check_ground(ground) == "rough" else _smooth_omega_dot
    named = (("theta", theta), ("omega1", omega1), ("omega2", omega2), ("omega3", omega3))
    arrays = [real_array(name, value) for name, value in named]  # named errors for
    # non-numbers, masked entries and ints beyond float range
    out = kernel(_check_disk(disk).h, theta, omega1, omega2, omega3)
    if all(a.ndim == 0 and np.isfinite(a) for a in arrays) and np.any(np.isnan(out)):
        raise ParameterError("omega_dot: the terms of eq. (38) / (49) overflow floating-point "
                             f"range at theta={theta!r}, omega1={omega1!r}, "
                             f"omega2={omega2!r}, omega3={omega3!r}")
    return out


def velocity_of_C(disk: Disk, ground: str, y):
    """Velocity of the centre C in Cxyz, ``(v_Cx, v_Cy, v_Cz)``, units of ``sqrt(a g)``.

    ``y`` is a state vector or an ``(n, k)`` array of states.  On rough ground the velocity
    follows from the no-slip condition, eq. (37); on smooth ground from the inertial velocity
    ``(V_X, V_Y)`` in the state.  ``v_Cz = -omega1 y_P`` (eq. 7).
    """
    y = as_state(ground, y)
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
    y = as_state(ground, y)
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
    y = as_state(ground, y)
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
    y = as_state(ground, y)
    rough = ground == "rough"
    X_C, Y_C = y[0], y[1]
    psi, theta = (y[2], y[3]) if rough else (y[4], y[5])
    y_P = _geometry(_check_disk(disk).h, theta)[4]
    return X_C - y_P * np.sin(psi), Y_C + y_P * np.cos(psi)  # eq. (5)
