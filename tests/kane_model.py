"""Independent second derivation of the equations of motion: Kane's method (sympy.mechanics).

Test-side helper (not a test file).  The library's equations (``rollingdisk.model.equations``) and
the lead's Newton-Euler derivation (``rollingdisk.symbolic``) both go through the contact
force, eqs. (8)-(11).  Here the contact force never enters the dynamics: on rough ground it
is non-contributing because the contact point is at rest (nonholonomic constraints); on
smooth ground it is vertical, and the generalized coordinates are chosen so that the
contact point never moves vertically, so the normal force is non-contributing too.

Nothing is copied from the paper except the choice of frames and angles, so that the
results map one-to-one onto the paper's variables:

* ``N`` = OXYZ (inertial), ``A`` = Cxyz = ``N`` rotated by ``psi`` about Z,
  ``B`` = C xi eta zeta = ``A`` rotated by ``theta`` about x, body ``D`` = ``B`` rotated by
  ``phi`` about eta (the disk axis).  Generalized speeds ``omega1..3`` = components of the
  body angular velocity in ``B`` (eqs. 2-3 are *not* imposed; sympy works out
  ``d psi/dt, d theta/dt, d phi/dt`` from ``omega = omega1 xi + omega2 eta + omega3 zeta``).
* Homogeneous cylinder, radius 1, half-thickness ``h``, mass 1, ``g = 1``; its central
  inertia is obtained here by integrating over the volume (a check of eq. 10).
* The contact point is derived as the lowest point of the two rim circles (a check of eq. 4);
  the height of C, ``Z_C``, is then a function of ``theta`` (holonomic contact constraint
  built into the coordinates ``X_C, Y_C, psi, theta, phi``).
* Rough ground: speeds ``omega1..3`` independent, ``v_Cx, v_Cy`` (velocity of C in Cxyz)
  dependent through "material point of the disk at P has zero horizontal velocity".
* Smooth ground: speeds ``omega1..3, v_Cx, v_Cy``, all independent; gravity is the only
  contributing force.

Each derivation (sign of theta x ground) takes under a second; it is cached (functools.cache),
so all tests of a session share it.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me

__all__ = [
    "KaneModel",
    "kane_model",
    "inertia_by_integration",
    "contact_offset",
    "kane_omega_dot",
    "kane_contact_force",
    "kane_energy",
    "kane_energy_rate",
    "kane_dependent_speeds",
    "kane_state_derivatives",
    "kane_rhs",
]

h_sym = sm.Symbol("h", nonnegative=True)


# ---------------------------------------------------------------------------------------
# inertia of the homogeneous cylinder (check of eq. 10)
# ---------------------------------------------------------------------------------------
@functools.cache
def inertia_by_integration():
    """``(I_diameter, I_axis)`` per unit mass of the cylinder, radius 1, half-thickness h.

    Integrates ``rho (eta^2 + zeta^2)`` and ``rho (xi^2 + zeta^2)`` over the volume in
    cylindrical coordinates about the axis eta, ``rho = 1 / (2 pi h)`` (mass 1).
    """
    h = sm.Symbol("h", positive=True)
    r, a, e = sm.symbols("r alpha e", real=True)
    rho = 1 / (sm.pi * 2 * h)
    xi, zeta = r * sm.cos(a), r * sm.sin(a)
    vol = [(r, 0, 1), (a, 0, 2 * sm.pi), (e, -h, h)]
    i_diam = sm.integrate(rho * (e**2 + zeta**2) * r, *vol)
    i_axis = sm.integrate(rho * (xi**2 + zeta**2) * r, *vol)
    i_diam, i_axis = sm.simplify(i_diam), sm.simplify(i_axis)
    # polynomial in h, so valid at h = 0 by continuity (the thin disk)
    return i_diam.subs(h, h_sym), i_axis.subs(h, h_sym)


# ---------------------------------------------------------------------------------------
# contact point (check of eq. 4)
# ---------------------------------------------------------------------------------------
@functools.cache
def contact_offset(sign: int):
    """``(c_eta, c_zeta)`` with ``r_CP = c_eta eta + c_zeta zeta``, for ``sgn theta = sign``.

    The rim consists of two circles ``sigma h eta + cos(alpha) xi + sin(alpha) zeta``
    (``sigma = +-1``).  On each circle the stationary points of the height (Z component) are
    found with ``sympy.solve``; the lowest of the four candidates is selected at a sample
    inclination of the given sign and confirmed against a brute-force minimisation over a
    dense grid of rim points, inclinations of that sign in (0, 1.5) and h in [0, 3].
    """
    theta, alpha = sm.symbols("theta alpha", real=True)
    # Z components of xi, eta, zeta (rotation about x by theta): 0, sin, cos
    z_of = {"xi": 0, "eta": sm.sin(theta), "zeta": sm.cos(theta)}
    cands = []
    for sigma in (1, -1):
        c_xi, c_eta, c_zeta = sm.cos(alpha), sigma * h_sym, sm.sin(alpha)
        height = c_xi * z_of["xi"] + c_eta * z_of["eta"] + c_zeta * z_of["zeta"]
        for a0 in sm.solve(sm.diff(height, alpha), alpha):
            cands.append((sm.simplify(c_xi.subs(alpha, a0)), c_eta,
                          sm.simplify(c_zeta.subs(alpha, a0)), height.subs(alpha, a0)))
    sample = {theta: sign * 0.3, h_sym: 0.5}
    best = min(cands, key=lambda c: float(c[3].subs(sample)))
    assert best[0] == 0, "the lowest rim point lies in the plane eta-zeta"
    # brute-force confirmation
    f_best = sm.lambdify((h_sym, theta), best[3], "numpy")
    al = np.linspace(0.0, 2.0 * np.pi, 721)
    for hv in (0.0, 0.3, 1.0, 3.0):
        for tv in sign * np.linspace(0.01, 1.5, 40):
            brute = min(float(np.min(s * hv * np.sin(tv) + np.sin(al) * np.cos(tv)))
                        for s in (1, -1))
            assert float(f_best(hv, tv)) <= brute + 1e-12, (hv, tv)
    return best[1], best[2]


# ---------------------------------------------------------------------------------------
# Kane's equations
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class KaneModel:
    """Lambdified pieces of one derivation (``sign`` of theta, ``ground``).

    All functions take ``(h, X, Y, psi, theta, phi, *u)`` with ``u`` the full list of
    generalized speeds (``omega1, omega2, omega3, v_Cx, v_Cy``); ``mass_matrix`` and
    ``forcing`` give ``M u' = f`` for all speeds (for rough ground the last two rows are the
    time derivatives of the no-slip constraints), ``accel_C`` the acceleration of C in
    Cxyz as a function of ``(h, q, u, u')``, ``energy`` the total energy and
    ``energy_grad_q`` / ``energy_grad_u`` its gradients; ``qdot`` the kinematic equations;
    ``dependent`` (rough only) ``(v_Cx, v_Cy)`` from ``(h, theta, omega1..3)``.
    """

    sign: int
    ground: str
    mass_matrix: object
    forcing: object
    accel_C: object
    energy: object
    energy_grad_q: object
    energy_grad_u: object
    qdot: object
    dependent: object
    vertical_slip: sm.Expr  # v_P . Z, symbolically zero (contact constraint holds)


@functools.cache
def kane_model(sign: int, ground: str) -> KaneModel:
    """Derive (once, cached) Kane's equations for ``sgn theta = sign`` on ``ground``."""
    if sign not in (1, -1) or ground not in ("rough", "smooth"):
        raise ValueError("sign must be +-1 and ground 'rough' or 'smooth'")
    t = me.dynamicsymbols._t
    X, Y, psi, theta, phi = me.dynamicsymbols("X Y psi theta phi")
    w1, w2, w3, vx, vy = me.dynamicsymbols("omega1 omega2 omega3 v_Cx v_Cy")
    q = [X, Y, psi, theta, phi]
    u = [w1, w2, w3, vx, vy]

    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [psi, N.z])
    B = A.orientnew("B", "Axis", [theta, A.x])
    D = B.orientnew("D", "Axis", [phi, B.y])
    w_qd = D.ang_vel_in(N)
    D.set_ang_vel(N, w1 * B.x + w2 * B.y + w3 * B.z)

    # contact point from the rim geometry; height of C from "P lies on the plane"
    c_eta, c_zeta = contact_offset(sign)
    r_CP = c_eta * B.y + c_zeta * B.z
    Z_C = -r_CP.dot(N.z)  # P at height 0

    O = me.Point("O")
    O.set_vel(N, 0)
    C = O.locatenew("C", X * N.x + Y * N.y + Z_C * N.z)
    # velocity of C in terms of the speeds: horizontal part = v_Cx, v_Cy (in Cxyz)
    C.set_vel(N, vx * A.x + vy * A.y + sm.diff(Z_C, t) * N.z)
    P = C.locatenew("P", r_CP)
    P.v2pt_theory(C, N, D)  # material point of the disk at the contact

    # kinematic differential equations: angular velocity and horizontal velocity of C
    v_C_qd = X.diff(t) * N.x + Y.diff(t) * N.y
    kd = [(D.ang_vel_in(N) - w_qd).dot(e) for e in B]
    kd += [(vx * A.x + vy * A.y - v_C_qd).dot(e) for e in (A.x, A.y)]

    i_diam, i_axis = inertia_by_integration()
    # axisymmetric about eta = D.y, so this dyadic is the same in B and in D
    body = me.RigidBody("disk", C, D, 1, (me.inertia(B, i_diam, i_axis, i_diam), C))
    loads = [(C, -1 * N.z)]  # gravity, m = g = 1

    if ground == "rough":
        constraints = [P.vel(N).dot(A.x), P.vel(N).dot(A.y)]
        km = me.KanesMethod(N, q_ind=q, u_ind=[w1, w2, w3], u_dependent=[vx, vy],
                            kd_eqs=kd, velocity_constraints=constraints)
    else:
        km = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    km.kanes_equations([body], loads)
    kdd = km.kindiffdict()

    # plain symbols for lambdify
    qs = sm.symbols("X Y psi theta phi")
    us = sm.symbols("omega1 omega2 omega3 v_Cx v_Cy")
    uds = sm.symbols("omega1d omega2d omega3d v_Cxd v_Cyd")
    udots = [ui.diff(t) for ui in u]
    rep = dict(zip(udots, uds, strict=True))
    rep.update(zip(q, qs, strict=True))
    rep.update(zip(u, us, strict=True))

    def plain(expr):
        return me.msubs(expr, kdd).xreplace(rep)

    args = (h_sym, *qs, *us)
    mm = sm.lambdify(args, plain(km.mass_matrix), "numpy", cse=True)
    fo = sm.lambdify(args, plain(km.forcing), "numpy", cse=True)

    # acceleration of C (in Cxyz) as a function of q, u, u'
    a_C = me.msubs(C.vel(N), kdd).dt(N)
    a_C = [plain(a_C.dot(e)) for e in A]
    acc = sm.lambdify((*args, *uds), a_C, "numpy", cse=True)

    # energy: kinetic (translation + rotation about C) + potential Z_C
    v_C = me.msubs(C.vel(N), kdd)
    omega = D.ang_vel_in(N)
    E = (v_C.dot(v_C) / 2 + omega.dot(body.central_inertia.dot(omega)) / 2 + Z_C)
    E = plain(E)
    energy = sm.lambdify(args, E, "numpy", cse=True)
    grad_q = sm.lambdify(args, [sm.diff(E, s) for s in qs], "numpy", cse=True)
    grad_u = sm.lambdify(args, [sm.diff(E, s) for s in us], "numpy", cse=True)
    qdot = sm.lambdify(args, [plain(qi.diff(t)) for qi in q], "numpy", cse=True)

    vertical = plain(P.vel(N).dot(N.z))
    vertical = sm.simplify(sm.expand_trig(vertical))

    dependent = None
    if ground == "rough":
        cons = [plain(c) for c in constraints]
        sol = sm.solve(cons, us[3:], dict=True)[0]
        dependent = sm.lambdify((h_sym, qs[3], *us[:3]), [sol[us[3]], sol[us[4]]], "numpy")
    return KaneModel(sign, ground, mm, fo, acc, energy, grad_q, grad_u, qdot, dependent,
                     vertical)


# ---------------------------------------------------------------------------------------
# numeric wrappers (single states, floats)
# ---------------------------------------------------------------------------------------
def _sign(h, theta):
    return 1 if theta >= 0.0 else -1


def kane_dependent_speeds(h, theta, w1, w2, w3):
    """``(v_Cx, v_Cy)`` on rough ground from the no-slip constraints."""
    m = kane_model(_sign(h, theta), "rough")
    vx, vy = m.dependent(h, theta, w1, w2, w3)
    return float(vx), float(vy)


def _full_speeds(ground, h, theta, w1, w2, w3, vx, vy):
    if ground == "rough":
        vx, vy = kane_dependent_speeds(h, theta, w1, w2, w3)
    return (w1, w2, w3, vx, vy)


def _udot(ground, h, q, u):
    m = kane_model(_sign(h, q[3]), ground)
    M = np.array(m.mass_matrix(h, *q, *u), dtype=float)
    f = np.array(m.forcing(h, *q, *u), dtype=float).ravel()
    return np.linalg.solve(M, f)


def kane_state_derivatives(ground, h, theta, w1, w2, w3, *, vx=0.0, vy=0.0,
                           X=0.0, Y=0.0, psi=0.0, phi=0.0):
    """``(q, u, u')`` from Kane's equations at one state (rough: ``vx, vy`` are ignored)."""
    u = _full_speeds(ground, h, theta, w1, w2, w3, vx, vy)
    q = (X, Y, psi, theta, phi)
    return q, u, _udot(ground, h, q, u)


def kane_omega_dot(ground, h, theta, w1, w2, w3, **kw):
    """``(d omega1/dt, d omega2/dt, d omega3/dt)`` from Kane's equations."""
    _, _, ud = kane_state_derivatives(ground, h, theta, w1, w2, w3, **kw)
    return tuple(float(x) for x in ud[:3])


def kane_contact_force(ground, h, theta, w1, w2, w3, **kw):
    """Contact force in Cxyz, ``F = m a_C - m g`` (Newton for C) with Kane's accelerations."""
    q, u, ud = kane_state_derivatives(ground, h, theta, w1, w2, w3, **kw)
    m = kane_model(_sign(h, theta), ground)
    a = np.array(m.accel_C(h, *q, *u, *ud), dtype=float)
    return a[0], a[1], a[2] + 1.0  # F = a_C - g, g = -Z (m = g = 1)


def kane_energy(ground, h, theta, w1, w2, w3, **kw):
    """Total energy (kinetic + potential ``Z_C``) of the Kane model."""
    u = _full_speeds(ground, h, theta, w1, w2, w3, kw.get("vx", 0.0), kw.get("vy", 0.0))
    q = (kw.get("X", 0.0), kw.get("Y", 0.0), kw.get("psi", 0.0), theta, kw.get("phi", 0.0))
    return float(kane_model(_sign(h, theta), ground).energy(h, *q, *u))


def kane_energy_rate(ground, h, theta, w1, w2, w3, **kw):
    """``dE/dt = dE/dq . q' + dE/du . u'`` along Kane's equations, and a scale for it."""
    q, u, ud = kane_state_derivatives(ground, h, theta, w1, w2, w3, **kw)
    m = kane_model(_sign(h, theta), ground)
    gq = np.array(m.energy_grad_q(h, *q, *u), dtype=float)
    gu = np.array(m.energy_grad_u(h, *q, *u), dtype=float)
    qd = np.array(m.qdot(h, *q, *u), dtype=float)
    terms = np.concatenate([gq * qd, gu * ud])
    return float(np.sum(terms)), float(np.sum(np.abs(terms)))


def kane_rhs(ground, h):
    """``f(t, x)`` of Kane's equations in Kane's own state layout, for ``solve_ivp``.

    rough: ``x = [X_C, Y_C, psi, theta, phi, omega1, omega2, omega3]`` (``v_Cx, v_Cy``
    from the no-slip constraints); smooth: the same followed by ``v_Cx, v_Cy`` (velocity of
    C in Cxyz).  Positions and angles advance by sympy's kinematic equations, not eqs. (1)-(2).
    """

    def f(t, x):
        q = tuple(x[:5])
        vx, vy = (x[8], x[9]) if ground == "smooth" else (0.0, 0.0)
        u = _full_speeds(ground, h, q[3], x[5], x[6], x[7], vx, vy)
        m = kane_model(_sign(h, q[3]), ground)
        qd = np.array(m.qdot(h, *q, *u), dtype=float)
        ud = _udot(ground, h, q, u)
        return np.concatenate([qd, ud[:3]] if ground == "rough" else [qd, ud])

    return f
