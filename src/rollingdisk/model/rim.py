"""The rounded rim: geometry, inertia and equations of motion of a disk whose rim edges are
rounded with radius ``rho``.  Dimensionless units (m = a = g = 1).

The body is the homogeneous solid of revolution whose meridian is a flat face, a quarter
circle of radius ``rho``, a flat tread of length ``2 (h - rho)``, a quarter circle and a
flat face (``0 <= rho <= min(h, 1)``; at ``rho = h`` the tread is a half circle, at ``rho = 0`` the
paper's sharp-edged disk).  In the tilted frame C xi eta zeta (eta the symmetry axis) the
centre of the arc that touches sits at radial distance ``1 - rho`` below C and axial offset
``-hp``, ``hp = (h - rho) sgn(theta)`` (the rounded ``h~``).  For ``0 < |theta| < pi/2``
the contact is on that arc, where its normal points down:

    r_CP = (0, -H, -A),   A = 1 - rho + rho cos(theta),   H = hp + rho sin(theta)

so the contact moves continuously over the arc with the tilt.  In Cxyz (eq. 4 rounded):

    y_P = A sin(theta) - H cos(theta) = (1 - rho) sin(theta) - hp cos(theta)
    z_P = -(A cos(theta) + H sin(theta)) = -((1 - rho) cos(theta) + hp sin(theta) + rho)

At ``theta = 0`` a disk with ``rho < h`` touches along its tread (a line; the contact
jumps from one arc to the other, as the sharp disk's jumps between its edges); at
``|theta| = pi/2`` it lies on a face.  At ``rho = 0``, ``A = 1`` and ``H = h~``: eq. (4).

The equations of motion are those of a body of revolution (Routh), derived in
:mod:`rollingdisk.symbolic.rounded` by Newton-Euler and checked by Lagrange's equations;
the kernels below are that derivation written in ``A, H`` and checked against it by
``tests/test_rounded.py``.  The inertia is the rounded body's, by integration.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.model.geometry import inertia

__all__ = ["rim_inertia", "rim_contact", "contact_part", "centre_height",
           "rounded_omega_dot", "rounded_normal_force", "rounded_energy",
           "rounded_reduced_rhs", "rounded_rough_omega_dot"]

_PI = math.pi


def rim_inertia(h, rho):
    """``(k1^2, k2^2)`` of the rounded disk, in units of ``a^2``.

    Parameters
    ----------
    h : float
        Half-thickness (units of ``a``).
    rho : float
        Rim radius, ``0 <= rho <= min(h, 1)`` (units of ``a``).

    Returns
    -------
    tuple of float
        Squared radii of gyration about a diameter through C and about the axis: the
        integrals over the body (the cylinder less its two rounded-off corners, derived in
        :func:`rollingdisk.symbolic.rounded.rounded_inertia`).  At ``rho = 0`` exactly
        eq. (10) (:func:`rollingdisk.model.geometry.inertia`); at ``h = rho = 1`` the
        sphere's ``(2/5, 2/5)``.

    Examples
    --------
    >>> rim_inertia(0.17, 0.0) == inertia(0.17)
    True
    >>> [round(k, 12) for k in rim_inertia(1.0, 1.0)]
    [0.4, 0.4]
    """
    if rho == 0.0:
        return inertia(h)
    p = _PI
    r2, r3, r4, r5 = rho**2, rho**3, rho**4, rho**5
    V = (6.0 * h - 3.0 * p * r3 + 10.0 * r3 - 12.0 * r2 + 3.0 * p * r2) / 3.0
    R2 = (60.0 * h + (332.0 - 105.0 * p) * r5 + (225.0 * p - 720.0) * r4
          + (600.0 - 180.0 * p) * r3 + (60.0 * p - 240.0) * r2) / 60.0
    Z2 = (40.0 * h**3 + h * h * ((200.0 - 60.0 * p) * r3 + (60.0 * p - 240.0) * r2)
          + h * ((120.0 * p - 380.0) * r4 + (400.0 - 120.0 * p) * r3)
          + (236.0 - 75.0 * p) * r5 + (75.0 * p - 240.0) * r4) / 60.0
    return (0.5 * R2 + Z2) / V, R2 / V


def rim_contact(h, rho, theta):
    """``(hp, A, H, y_P, z_P)``: where the rounded rim touches at tilt ``theta``.

    Parameters
    ----------
    h, rho : float
        Half-thickness and rim radius (units of ``a``), ``0 <= rho <= min(h, 1)``.
    theta : float or ndarray
        Inclination [rad], ``|theta| < pi/2``; ``theta = 0`` counts as ``0+`` (as in
        :func:`rollingdisk.model.geometry.contact_geometry`).

    Returns
    -------
    tuple
        ``hp = (h - rho) sgn(theta)``; ``A``, ``H``: the contact below C and along the
        axis in C xi eta zeta, ``r_CP = (0, -H, -A)``; ``y_P, z_P``: the contact in Cxyz
        (units of ``a``).  At ``rho = 0``: ``(h~, 1, h~, y_P, z_P)`` of eq. (4).
    """
    hp = (h - rho) * np.sign(np.sign(np.real(theta)) + 0.5)
    s = np.sin(theta)
    c = np.cos(theta)
    A = 1.0 - rho + rho * c
    H = hp + rho * s
    return hp, A, H, A * s - H * c, -(A * c + H * s)


def centre_height(h, rho, theta):
    """Height of C above the plane, ``Z_C = -z_P = (1 - rho) cos(theta) + hp sin(theta)
    + rho`` (units of ``a``); ``dZ_C/dtheta = -y_P`` (the contact is the lowest point)."""
    return -rim_contact(h, rho, theta)[4]


def contact_part(h, rho, theta) -> str:
    """Which part of the meridian touches the plane at tilt ``theta`` [rad].

    Returns
    -------
    str
        ``"edge"`` (``rho = 0``, ``0 < |theta| < pi/2``: the sharp rim edge of eq. 4),
        ``"arc"`` (``rho > 0``, ``0 < |theta| < pi/2``: the rounded rim, the contact moves
        with the tilt), ``"tread"`` (``theta = 0`` and ``rho < h``: a line along the flat
        tread), ``"face"`` (``|theta| >= pi/2``), or ``"arc"`` at ``theta = 0`` when
        ``rho = h`` (the half-circle tread).
    """
    t = abs(float(theta))
    if t >= _PI / 2:
        return "face"
    if t == 0.0:
        return "arc" if rho == h and rho > 0.0 else "tread"
    return "arc" if rho > 0.0 else "edge"


# ---------------------------------------------------------------------------------------
# kernels: plain arithmetic, element-wise on arrays, complex-step safe
# ---------------------------------------------------------------------------------------
def rounded_omega_dot(rough, h, rho, k1, k2, theta, w1, w2, w3):
    """``d omega_i/dt`` of the rounded disk (rough: no slip; smooth: no friction).

    Parameters
    ----------
    rough : bool
        Rough (no slip) or smooth (no friction) ground.
    h, rho : float
        Half-thickness and rim radius (units of ``a``).
    k1, k2 : float
        Squared radii of gyration (:func:`rim_inertia`, units of ``a^2``).
    theta, w1, w2, w3 : float or ndarray
        Inclination [rad] and angular velocity in C xi eta zeta [units ``sqrt(g/a)``].

    Returns
    -------
    tuple
        ``(d omega1/dt, d omega2/dt, d omega3/dt)`` [units ``g/a``]: the Newton-Euler
        equations of a body of revolution with ``r_CP = (0, -H, -A)``, ``A' = -rho sin``,
        ``H' = rho cos`` (derivation in :mod:`rollingdisk.symbolic.rounded`).  At
        ``rho = 0``, ``k1 = 1/4 + h^2/3``, ``k2 = 1/2`` they are eqs. (38) and (49).
    """
    hp, A, H, y_P, z_P = rim_contact(h, rho, theta)
    s = np.sin(theta)
    c = np.cos(theta)
    p = s / c
    # the gyroscopic moment about xi and the weight's moment (eq. 9_1 with F_z = 1)
    gyro = (k2 * w2 - k1 * w3 * p) * w3
    if rough:
        return rounded_rough_omega_dot(rho, k1, k2, s, c, p, A, H, y_P, z_P, gyro, w1, w2,
                                       w3)
    d1 = (gyro + y_P + y_P * (z_P + rho) * w1 * w1) / (k1 + y_P * y_P)
    d2 = 0.0 * w1
    d3 = (-k2 * w2 + k1 * w3 * p) * w1 / k1
    return d1, d2, d3


def rounded_rough_omega_dot(rho, k1, k2, s, c, p, A, H, y_P, z_P, gyro, w1, w2, w3):
    """The rough-ground kernel of :func:`rounded_omega_dot`: with ``A' = -rho sin``,
    ``H' = rho cos`` the derivation's ``omega1^2`` terms collapse to ``rho y_P omega1^2``,
    and its denominators to ``k1 + A^2 + H^2`` (the moment of inertia about the contact
    line, over m) and ``D = k1 k2 + k1 A^2 + k2 H^2``.  Public because compiled code that
    calls :func:`rounded_omega_dot` must compile it too (:mod:`rollingdisk.ivp.rounded`
    lists it among its model's helpers)."""
    d1 = ((A * A + A * H * p) * w2 * w3 - (A * H + H * H * p) * w3 * w3 + gyro
          + y_P * (1.0 + rho * w1 * w1)) / (k1 + A * A + H * H)
    D = k1 * k2 + k1 * A * A + k2 * H * H
    d2 = -A * w1 * (k1 * (1.0 - rho) * w3 + (k2 * H - k1 * rho * s) * w2) / D
    d3 = w1 * (p * w3 - k2 * ((A * A + k2 + rho * s * H) * w2 - (1.0 - rho) * H * w3) / D)
    return d1, d2, d3


def rounded_normal_force(rough, h, rho, k1, k2, theta, w1, w2, w3):
    """Normal force ``F_z = 1 + (z_P + rho) omega1^2 - y_P d omega1/dt`` [units ``m g``]:
    eq. (11) with the rounded contact (``d y_P/d theta = -(z_P + rho)``, derived in
    :mod:`rollingdisk.symbolic.rounded`).  Arguments as :func:`rounded_omega_dot`."""
    y_P, z_P = rim_contact(h, rho, theta)[3:]
    d1 = rounded_omega_dot(rough, h, rho, k1, k2, theta, w1, w2, w3)[0]
    return 1.0 + (z_P + rho) * w1 * w1 - y_P * d1


def rounded_energy(rough, h, rho, k1, k2, theta, w1, w2, w3):
    """Mechanical energy [units ``m g a``], eq. (13) with ``Z_C`` of :func:`centre_height`:
    on rough ground with ``v_C = -omega x r_CP``, on smooth ground less the constant
    kinetic energy of the horizontal motion of C.  Arguments as :func:`rounded_omega_dot`;
    conserved along it (tested)."""
    hp, A, H, y_P, z_P = rim_contact(h, rho, theta)
    if rough:
        v_x = A * w2 - H * w3  # v_P = 0: v_C = -omega x r_CP (eq. 37 rounded)
        v_y = w1 * z_P
    else:
        v_x = 0.0 * w1
        v_y = 0.0 * w1
    v_z = -w1 * y_P
    return (0.5 * (v_x * v_x + v_y * v_y + v_z * v_z) + 0.5 * k1 * (w1 * w1 + w3 * w3)
            + 0.5 * k2 * w2 * w2 - z_P)


def rounded_reduced_rhs(rough, h, rho, k1, k2, x):
    """Right-hand side of the reduced system ``x = (theta, omega1, omega2, omega3)``
    [rad, ``sqrt(g/a)``]: ``d theta/dt = omega1`` (eq. 2) and :func:`rounded_omega_dot`;
    autonomous and closed on both grounds, as for the sharp disk."""
    theta, w1, w2, w3 = x[0], x[1], x[2], x[3]
    d1, d2, d3 = rounded_omega_dot(rough, h, rho, k1, k2, theta, w1, w2, w3)
    return w1, d1, d2, d3
