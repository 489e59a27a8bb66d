"""The disk with a rounded rim (Routh's body of revolution), derived twice in sympy.

The body: half-thickness ``h``, radius 1, rim rounded with radius ``rho`` (``0 <= rho <=
h``); its meridian is a flat face, a quarter circle of radius ``rho`` centred at radial
distance ``1 - rho`` and axial offset ``+-(h - rho)``, a flat tread, a quarter circle, a
flat face (:mod:`rollingdisk.model.rim`).

- :func:`rounded_inertia`: the mass and the radii of gyration by integration over the body.
- :func:`derive_rounded`: Newton-Euler, the balances of :mod:`.derivation` (frames from
  rotation matrices, transport theorem) with the contact point found here as the lowest
  point of the rounded rim and the inertia ``diag(K1, K2, K1)`` of any body of revolution.
- :func:`lagrange_rounded`: a second, independent derivation: the Lagrangian of the body
  in the inertial frame with generalized coordinates ``(X_C, Y_C, psi, theta, phi)``, the
  height of C from the contact, and on rough ground the two no-slip constraints with
  Lagrange multipliers; its accelerations are found numerically (a linear solve) at a
  given state.

Symbols: ``hp`` stands for ``(h - rho) sgn(theta)`` (the offset of the touching arc's
centre, the rounded ``h~``), ``rho`` for the rim radius, ``K1, K2`` for ``k1^2, k2^2``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import sympy as sp

from rollingdisk.symbolic.derivation import (
    _balances,
    _kinematics,
    _require,
    _rough_ground,
    _Rx,
    _Ry,
    _Rz,
    _smooth_ground,
    omega1,
    omega2,
    omega3,
    theta,
)

__all__ = ["RoundedDerivation", "derive_rounded", "lagrange_rounded", "rounded_inertia",
           "rounded_lambdified", "hp", "rho", "K1", "K2"]

hp = sp.Symbol("hp", real=True)  # (h - rho) sgn(theta)
rho = sp.Symbol("rho", nonnegative=True)
K1, K2 = sp.symbols("K1 K2", positive=True)


@lru_cache(maxsize=1)
def rounded_inertia():
    """``(V, k1^2, k2^2, h)``: the rounded disk's inertia as sympy expressions in ``h, rho``
    (``h`` the half-thickness symbol they use, ``rho`` this module's).

    ``V`` is the volume (units ``a^3``), ``k1^2`` the squared radius of gyration about a
    diameter and ``k2^2`` about the axis (units ``a^2``): the cylinder ``r <= 1, |z| <= h``
    less, at each of its two rim edges, the corner square ``[1 - rho, 1] x [h - rho, h]``
    outside the quarter disc of radius ``rho`` (integrated in polar coordinates).
    """
    h, r, z, s, al = sp.symbols("h r z s alpha", nonnegative=True)
    b, d = 1 - rho, h - rho

    def integral(f):
        dv = 2 * sp.pi * r * f
        full = sp.integrate(dv, (r, 0, 1), (z, -h, h))
        square = sp.integrate(dv, (r, b, 1), (z, d, h))
        quarter = sp.integrate(sp.expand(dv.subs({r: b + s * sp.cos(al),
                                                   z: d + s * sp.sin(al)}) * s),
                               (al, 0, sp.pi / 2), (s, 0, rho))
        return sp.simplify(full - 2 * (square - quarter))

    V, R2, Z2 = integral(1), integral(r**2), integral(z**2)
    return V, sp.simplify((R2 / 2 + Z2) / V), sp.simplify(R2 / V), h


def _contact_point():
    """``r_CP`` in C xi eta zeta: the lowest point of the rounded rim at tilt theta.

    The lower arc (for ``theta > 0``) has its centre at ``Q = (0, -hp, -(1 - rho))``; its
    points are ``Q + rho n`` with ``n = (0, -sin b, -cos b)``, ``0 <= b <= pi/2``.  The
    height above C of such a point is the ``Z`` component of ``R_x(theta)`` applied to it;
    it is least where ``n`` points straight down, ``b = theta``.
    """
    b = sp.Symbol("b", real=True)
    Q = sp.Matrix([0, -hp, -(1 - rho)])
    point = Q + rho * sp.Matrix([0, -sp.sin(b), -sp.cos(b)])
    height = (_Rx(theta) * point)[2]
    _require(sp.simplify(height.diff(b).subs(b, theta)) == 0
             and sp.simplify(height.diff(b, 2).subs(b, theta) - rho) == 0,
             "b = theta is the lowest point of the rim arc")
    return sp.simplify(point.subs(b, theta))


@dataclass(frozen=True)
class RoundedDerivation:
    """Newton-Euler results for the rounded disk (symbols of this module and of
    :mod:`.derivation`; ``K1, K2`` are the inertia symbols)."""

    contact_point: tuple  # (y_P, z_P) in Cxyz
    contact_body: tuple  # r_CP in C xi eta zeta
    centre_height: object  # Z_C(theta)
    rough_velocity_of_C: tuple
    rough_omega_dot: tuple
    rough_force: tuple
    rough_energy: object
    smooth_omega_dot: tuple
    smooth_force: tuple
    smooth_energy_internal: object
    energy_rate: object  # dE/dt - power of the contact force and moment: 0


@lru_cache(maxsize=1)
def derive_rounded() -> RoundedDerivation:
    """Newton-Euler for the rounded disk (a few seconds; cached)."""
    ang, frame_rates, wf, w = _kinematics()
    I = sp.diag(K1, K2, K1)
    rP = _contact_point()
    rP_xyz = (_Rx(theta) * rP).applyfunc(sp.simplify)
    _require(rP_xyz[0] == 0, "the contact point lies in the plane x = 0")
    b = _balances(frame_rates, wf, w, I, rP, rP_xyz, rP_xyz[2])
    rough = _rough_ground(b)
    smooth = _smooth_ground(b)
    smooth.pop("smooth_energy_internal")
    E_int = b.E.subs({sp.Symbol("v_Cx", real=True): 0, sp.Symbol("v_Cy", real=True): 0,
                      sp.Symbol("v_Cz", real=True): b.v_Cz_contact})
    return RoundedDerivation(contact_point=(rP_xyz[1], rP_xyz[2]), contact_body=tuple(rP),
                             centre_height=b.Z_C, energy_rate=b.energy_rate,
                             smooth_energy_internal=sp.simplify(E_int), **rough, **smooth)


@lru_cache(maxsize=1)
def rounded_lambdified() -> dict:
    """numpy functions of ``(hp, rho, K1, K2, theta, omega1, omega2, omega3)`` from
    :func:`derive_rounded`: ``rough_omega_dot``, ``smooth_omega_dot``, ``rough_force``,
    ``smooth_force``, ``rough_energy``, ``smooth_energy_internal``, ``contact_point``."""
    d = derive_rounded()
    args = (hp, rho, K1, K2, theta, omega1, omega2, omega3)
    out = {name: sp.lambdify(args, list(getattr(d, name)), "numpy")
           for name in ("rough_omega_dot", "smooth_omega_dot", "rough_force",
                        "smooth_force", "contact_point")}
    for name in ("rough_energy", "smooth_energy_internal"):
        out[name] = sp.lambdify(args, getattr(d, name), "numpy")
    return out


# ---------------------------------------------------------------------------------------
# the second derivation: Lagrange's equations with multipliers, inertial frame
# ---------------------------------------------------------------------------------------
@lru_cache(maxsize=2)
def _lagrange_parts(rough: bool):
    """Mass matrix, the rest of Lagrange's equations, constraint rows and their rate, as
    numpy functions of ``(q, qd, hp, rho, K1, K2)``."""
    X, Y, ps, th, ph = sp.symbols("X Y psi_ theta_ phi_", real=True)
    q = [X, Y, ps, th, ph]
    qd = list(sp.symbols("Xd Yd psid thetad phid", real=True))
    hpp, rr, k1, k2 = sp.symbols("hpp rr k1 k2", real=True)
    R = _Rz(ps) * _Rx(th) * _Ry(ph)  # body -> inertial; body axis 2 is the symmetry axis
    Rdot = sum((R.diff(qi) * qdi for qi, qdi in zip(q, qd)), sp.zeros(3, 3))
    S = R.T * Rdot
    w_body = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])  # body components
    # the lowest point of the body, found over the whole rim: the arc centres form the
    # circle of radius 1 - rho at axial offset -hpp; its lowest point is then lowered by rho
    R_tilt = _Rz(ps) * _Rx(th)  # the frame in which the lowest rim point is at angle -pi/2
    centre = R_tilt * sp.Matrix([0, -hpp, -(1 - rr)])
    r_P = centre + sp.Matrix([0, 0, -rr])  # P - C, inertial
    Z_C = -r_P[2]
    Zd = sum(Z_C.diff(qi) * qdi for qi, qdi in zip(q, qd))
    T = (Xd2 := sp.Matrix([qd[0], qd[1], Zd])).dot(Xd2) / 2 + (
        w_body.T * sp.diag(k1, k2, k1) * w_body)[0] / 2
    L = T - Z_C
    M = sp.Matrix(5, 5, lambda i, j: sp.diff(L, qd[i], qd[j]))
    rest = sp.Matrix([sum(sp.diff(L, qd[i], q[j]) * qd[j] for j in range(5)) - sp.diff(L, q[i])
                      for i in range(5)])
    args = (q, qd, hpp, rr, k1, k2)
    fM = sp.lambdify(args, M, "numpy")
    frest = sp.lambdify(args, rest, "numpy")
    # the angular velocity in C xi eta zeta (body components turned back by phi), and its
    # derivatives with respect to the coordinates and their rates
    w_frame = (_Ry(ph) * w_body).applyfunc(sp.simplify)
    fW = (sp.lambdify(args, w_frame.jacobian(q), "numpy"),
          sp.lambdify(args, w_frame.jacobian(qd), "numpy"))
    if not rough:
        return fM, frest, None, None, fW
    # no slip: the material point at P has zero horizontal velocity, v_C + w x r_P
    w_in = R * w_body
    vP = sp.Matrix([qd[0], qd[1], Zd]) + w_in.cross(r_P)
    A = sp.Matrix(2, 5, lambda i, j: sp.diff(vP[i], qd[j]))  # v_P = A(q) qd exactly
    _require(all(sp.simplify(sp.expand(vP[i] - sum(A[i, j] * qd[j] for j in range(5)))) == 0
                 for i in range(2)), "the constraint is linear in the rates")
    Adot_qd = sp.Matrix([sum(sp.diff(vP[i], q[j]) * qd[j] for j in range(5)) for i in range(2)])
    return (fM, frest, sp.lambdify(args, A, "numpy"), sp.lambdify(args, Adot_qd, "numpy"),
            fW)


def lagrange_rounded(ground: str, hp_value: float, rho_value: float, k1: float, k2: float,
                     theta_value: float, w1: float, w2: float, w3: float,
                     psi_value: float = 0.3, phi_value: float = -0.7):
    """``(d omega1/dt, d omega2/dt, d omega3/dt)`` by Lagrange's equations at one state.

    The state is given as in the library (``theta``, ``omega1..3`` in C xi eta zeta); the
    rates of ``psi, theta, phi`` are solved from the angular velocity written with the
    coordinates (``R^T dR/dt`` of this derivation, not eq. 2), the rates of ``X_C, Y_C``
    from the no-slip constraint (rough) or are taken as 0.3 and -0.2 (smooth: they do not
    enter).  The accelerations of the coordinates are solved from ``M qdd + rest = A^T
    lambda``, ``A qdd + dA/dt qd = 0`` and turned back into ``d omega/dt`` through the same
    angular velocity.
    """
    rough = ground == "rough"
    fM, frest, fA, fAd, (fWq, fWqd) = _lagrange_parts(rough)
    q = [0.1, -0.4, psi_value, theta_value, phi_value]
    args = (hp_value, rho_value, k1, k2)
    Wqd = np.asarray(fWqd(q, [0.0] * 5, *args), dtype=float)  # omega = Wqd qd (linear)
    psid, thd, phid = np.linalg.solve(Wqd[:, 2:], np.array([w1, w2, w3], dtype=float))
    qd = [0.3, -0.2, psid, thd, phid]
    if rough:  # X_C, Y_C rates from v_P = 0 (the constraint is linear in them)
        A = np.asarray(fA(q, [0.0, 0.0, psid, thd, phid], *args), dtype=float)
        qd[0], qd[1] = -A[:, 2:] @ np.array([psid, thd, phid])
    M = np.asarray(fM(q, qd, *args), dtype=float)
    rest = np.asarray(frest(q, qd, *args), dtype=float).ravel()
    if rough:
        A = np.asarray(fA(q, qd, *args), dtype=float)
        Ad = np.asarray(fAd(q, qd, *args), dtype=float).ravel()
        K = np.block([[M, -A.T], [A, np.zeros((2, 2))]])
        sol = np.linalg.solve(K, np.concatenate([-rest, -Ad]))
        qdd = sol[:5]
    else:
        qdd = np.linalg.solve(M, -rest)
    wdot = (np.asarray(fWq(q, qd, *args), dtype=float) @ np.asarray(qd, dtype=float)
            + np.asarray(fWqd(q, qd, *args), dtype=float) @ qdd)
    return float(wdot[0]), float(wdot[1]), float(wdot[2])
