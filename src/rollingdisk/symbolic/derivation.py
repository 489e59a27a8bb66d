"""Newton-Euler derivation of the equations of motion from first principles (sympy).

Nothing here is copied from the paper: the frames are built from rotation matrices, the
angular velocities from ``R^T dR/dt``, the inertia by integration over the cylinder, the
contact point as the lowest point of the two rim circles, and the equations of motion from
the momentum and angular-momentum balances with the transport theorem.  The printed
equations are compared with these results in :mod:`rollingdisk.symbolic.paper`.

Conventions (those of the paper): OXYZ inertial, Z up; Cxyz is OXYZ turned by ``psi``
about Z; C xi eta zeta is Cxyz turned by ``theta`` about x (so ``eta = cos(theta) y +
sin(theta) z`` is the disk's symmetry axis); the body is C xi eta zeta turned by ``phi``
about eta.  Units m = a = g = 1.  ``ht`` stands for ``h~ = h sgn(theta)``; where an
expression depends on ``h`` only through ``h^2`` it is written with ``ht**2``, and the
comparison with the paper substitutes ``ht = +h`` and ``ht = -h`` in turn.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

__all__ = ["Derivation", "derive", "lambdified"]

t = sp.Symbol("t", real=True)
theta, omega1, omega2, omega3 = sp.symbols("theta omega1 omega2 omega3", real=True)
ht = sp.Symbol("htilde", real=True)  # h~ = h sgn(theta)
h = sp.Symbol("h", nonnegative=True)
psi = sp.Symbol("psi", real=True)
dw1, dw2, dw3 = sp.symbols("domega1 domega2 domega3", real=True)
F_x, F_y, F_z = sp.symbols("F_x F_y F_z", real=True)
M_x, M_y, M_z = sp.symbols("M_x M_y M_z", real=True)
v_Cx, v_Cy, v_Cz = sp.symbols("v_Cx v_Cy v_Cz", real=True)


def _Rz(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def _Rx(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


def _Ry(a):
    return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])


def _require(ok: bool, what: str) -> None:
    """A step of the derivation that must hold (not an ``assert``: it stays under ``-O``)."""
    if not ok:
        raise RuntimeError(f"symbolic derivation: expected {what}, sympy says otherwise")


def _vee(S):
    """The vector of a skew-symmetric matrix."""
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


@dataclass(frozen=True)
class Derivation:
    """Results of the derivation; every expression in the paper's dimensionless units.

    Attributes hold sympy expressions in the symbols of this module (``theta``,
    ``omega1..3``, ``ht`` = h~, the time derivatives ``domega1..3``, forces ``F_x..F_z``
    in Cxyz and moments ``M_x..M_z``).
    """

    angular_velocity: tuple  # (omega1, omega2, omega3) in terms of angle rates, eqs. (2)-(3)
    frame_rates: tuple  # (dpsi/dt, dtheta/dt, dphi/dt) in terms of omega1..3, eq. (2)
    inertia: tuple  # (k1^2, k2^2), eq. (10)
    contact_point: tuple  # (y_P, z_P) in Cxyz, eq. (4)
    contact_point_inertial: tuple  # (X_P - X_C, Y_P - Y_C) in OXYZ, eq. (5)
    contact_velocity: tuple  # (v_Px, v_Py, v_Pz) in Cxyz, eq. (6)
    centre_height: tuple  # (Z_C, v_Cz) under contact, eq. (7)
    newton: tuple  # (8): m (dv_C/dt + Omega x v_C) - (F + m g), components in Cxyz
    euler: tuple  # (9): I domega + w_f x I omega - (r_P x F + M), components in xi eta zeta
    normal_force: object  # F_z, eq. (11)
    energy_rate: object  # dE/dt - (v_P . F_t + omega . M) along (8)-(9): must be 0, eq. (12)
    energy: object  # E, eq. (13), with v_C general
    rough_velocity_of_C: tuple  # (v_Cx, v_Cy) from v_P = 0, eq. (37)
    rough_omega_dot: tuple  # (domega1, domega2, domega3)/dt, cf. eq. (38)
    rough_force: tuple  # (F_x, F_y, F_z) in Cxyz on rough ground
    rough_energy: object  # E on rough ground in terms of theta, omega
    smooth_omega_dot: tuple  # cf. eq. (49)
    smooth_force: tuple  # (0, 0, F_z)
    smooth_energy_internal: object  # E on smooth ground less the constant (V_X^2+V_Y^2)/2


@lru_cache(maxsize=1)
def derive() -> Derivation:
    """Derive the equations of motion (about two seconds; cached)."""
    ang, frame_rates, wf, w = _kinematics()
    k1, k2 = _inertia_moments()
    I = sp.diag(k1, k2, k1)
    y_P, z_P, rP, rP_xyz, contact_inertial = _contact_point()
    b = _balances(frame_rates, wf, w, I, rP, rP_xyz, z_P)
    rough = _rough_ground(b)
    smooth = _smooth_ground(b)
    return Derivation(
        angular_velocity=ang, frame_rates=frame_rates, inertia=(k1, k2),
        contact_point=(y_P, z_P), contact_point_inertial=contact_inertial,
        contact_velocity=tuple(b.vP), centre_height=(b.Z_C, b.v_Cz_contact),
        newton=b.newton, euler=b.euler, normal_force=b.normal_force,
        energy_rate=b.energy_rate, energy=b.E, **rough, **smooth,
    )


def _kinematics():
    """Frames and angular velocities from rotation matrices (eqs. 2-3): the body's angular
    velocity in C xi eta zeta, the frame rates ``(dpsi/dt, dtheta/dt, dphi/dt)`` and the
    frame's angular velocity in terms of ``omega1..3``, and ``omega`` as a column."""
    ph = sp.Symbol("phi", real=True)
    psidot, thetadot, phidot = sp.symbols("psidot thetadot phidot", real=True)

    def ddt_angles(R):  # dR/dt by the chain rule
        return R.diff(psi) * psidot + R.diff(theta) * thetadot + R.diff(ph) * phidot

    pyth = {sp.cos(q)**2: 1 - sp.sin(q)**2 for q in (psi, theta, ph)}

    def trig_reduce(e):  # cos^2 = 1 - sin^2, then expand: exact for these polynomials
        return sp.expand(sp.expand(e).subs(pyth))

    R_frame = _Rz(psi) * _Rx(theta)  # columns: xi, eta, zeta in OXYZ
    R_body = R_frame * _Ry(ph)
    w_frame = _vee(R_frame.T * ddt_angles(R_frame)).applyfunc(trig_reduce)  # xi eta zeta
    # body angular velocity: body components, then turned back into xi eta zeta
    w_body = (_Ry(ph) * _vee(R_body.T * ddt_angles(R_body))).applyfunc(trig_reduce)
    ang = tuple(w_body)
    frame_rates_sol = sp.solve([ang[0] - omega1, ang[1] - omega2, ang[2] - omega3],
                               [psidot, thetadot, phidot], dict=True)[0]
    frame_rates = tuple(sp.simplify(frame_rates_sol[s]) for s in (psidot, thetadot, phidot))
    # frame angular velocity in xi eta zeta, expressed with omega1..3
    wf = sp.Matrix([sp.simplify(c.subs(frame_rates_sol)) for c in w_frame])
    w = sp.Matrix([omega1, omega2, omega3])
    return ang, frame_rates, wf, w


def _inertia_moments():
    """``(k1, k2)`` of the homogeneous cylinder of radius 1, ``|eta| <= h`` (eq. 10)."""
    r, al, e, hh = sp.symbols("r alpha eta_ hh", positive=True)
    vol = sp.integrate(r, (r, 0, 1), (al, 0, 2 * sp.pi), (e, -hh, hh))
    k1 = sp.simplify(sp.integrate((e**2 + (r * sp.sin(al))**2) * r,
                                  (r, 0, 1), (al, 0, 2 * sp.pi), (e, -hh, hh)) / vol)
    k2 = sp.simplify(sp.integrate(r**2 * r, (r, 0, 1), (al, 0, 2 * sp.pi), (e, -hh, hh)) / vol)
    return k1.subs(hh, ht), k2.subs(hh, ht)  # depend on h^2 = ht^2 only


def _contact_point():
    """The contact point, the lowest point of the two rim circles (eq. 4): ``y_P, z_P``
    (Cxyz), ``r_CP`` in C xi eta zeta and in Cxyz, and its inertial ``(X, Y)`` offset."""
    # rim points: C + cos(a) xi + sin(a) zeta + s h eta, s = +-1; height above C:
    a_, s_ = sp.symbols("a_ s_", real=True)
    rim = sp.Matrix([sp.cos(a_), s_ * h, sp.sin(a_)])  # in xi eta zeta
    height = (_Rx(theta) * rim)[2]
    # d height / da = cos(a) cos(theta) = 0 -> a = -pi/2 is the minimum for |theta| < pi/2
    _require(sp.simplify(height.diff(a_).subs(a_, -sp.pi / 2)) == 0
             and sp.simplify(height.diff(a_, 2).subs(a_, -sp.pi / 2) - sp.cos(theta)) == 0,
             "a = -pi/2 is the lowest point of a rim circle")
    # the two edges differ in height by 2 h sin(theta): the lower is s = -sgn(theta)
    _require(sp.simplify(height.subs(s_, 1) - height.subs(s_, -1) - 2 * h * sp.sin(theta)) == 0,
             "the two rim circles differ in height by 2 h sin(theta)")
    rP = sp.Matrix([0, -ht, -1])  # r_CP in xi eta zeta: a = -pi/2, s h = -h sgn(theta)
    rP_xyz = _Rx(theta) * rP
    y_P, z_P = sp.simplify(rP_xyz[1]), sp.simplify(rP_xyz[2])
    _require(sp.simplify(rP_xyz[0]) == 0, "the contact point lies in the plane x = 0")
    P_inertial = _Rz(psi) * rP_xyz
    contact_inertial = (sp.simplify(P_inertial[0]), sp.simplify(P_inertial[1]))
    return y_P, z_P, rP, rP_xyz, contact_inertial


def _balances(frame_rates, wf, w, I, rP, rP_xyz, z_P):
    """The ground-independent equations: contact velocity and constraint (eqs. 6-7),
    momentum and angular-momentum balances (eqs. 8-9), normal force (eq. 11), energy and
    its rate (eqs. 12-13), as a namespace."""
    from types import SimpleNamespace

    # -- velocity of the contact point (eq. 6) and the contact constraint (eq. 7) -------
    w_xyz = _Rx(theta) * w
    vC = sp.Matrix([v_Cx, v_Cy, v_Cz])
    vP = sp.simplify(vC + w_xyz.cross(rP_xyz))
    Z_C = -z_P
    v_Cz_contact = sp.simplify(Z_C.diff(theta) * frame_rates[1])

    # -- momentum balance in the rotating frame Cxyz (eq. 8) ---------------------------
    # Cxyz turns about Z at d psi/dt; transport theorem: a_C = dv/dt|_xyz + Omega Z x v_C
    dvC = sp.Matrix(sp.symbols("dv_Cx dv_Cy dv_Cz", real=True))
    Omega_vec = sp.Matrix([0, 0, frame_rates[0]])
    F = sp.Matrix([F_x, F_y, F_z])
    gravity = sp.Matrix([0, 0, -1])
    newton = tuple(sp.simplify(dvC + Omega_vec.cross(vC) - (F + gravity)))

    # -- angular-momentum balance about C in C xi eta zeta (eq. 9) -----------------------
    dw = sp.Matrix([dw1, dw2, dw3])
    Rx_T = _Rx(theta).T  # Cxyz components -> xi eta zeta components
    F_body = Rx_T * F
    M_body = Rx_T * sp.Matrix([M_x, M_y, M_z])
    euler = tuple(sp.simplify(I * dw + wf.cross(I * w) - (rP.cross(F_body) + M_body)))

    # -- normal force (eq. 11): (8)_3 with v_Cz from (7) ---------------------------------
    dv_Cz = sp.diff(v_Cz_contact, theta) * omega1 + sp.diff(v_Cz_contact, omega1) * dw1
    normal_force = sp.simplify(sp.solve(newton[2].subs({dvC[2]: dv_Cz, v_Cz: v_Cz_contact}),
                                        F_z)[0])

    # -- energy (eqs. 12-13) ------------------------------------------------------------
    E = (vC.dot(vC) / 2 + (w.T * I * w)[0] / 2 + Z_C)
    # dE/dt along (8)-(9), with the contact constraint v_Cz = -omega1 y_P
    sol8 = sp.solve(newton, list(dvC), dict=True)[0]
    sol9 = sp.solve(euler, [dw1, dw2, dw3], dict=True)[0]
    dE = (sum(E.diff(v) * sol8[d] for v, d in zip(vC, dvC))
          + sum(E.diff(wi) * sol9[d] for wi, d in zip(w, (dw1, dw2, dw3)))
          + E.diff(theta) * omega1)
    power = vP[0] * F_x + vP[1] * F_y + w_xyz.dot(sp.Matrix([M_x, M_y, M_z]))
    energy_rate = sp.simplify((dE - power).subs(v_Cz, v_Cz_contact))
    return SimpleNamespace(vP=vP, Z_C=Z_C, v_Cz_contact=v_Cz_contact, dvC=dvC, newton=newton,
                           euler=euler, normal_force=normal_force, E=E,
                           energy_rate=energy_rate)


#: The contact moments vanish on the ideal grounds.
_NO_MOMENTS = {M_x: 0, M_y: 0, M_z: 0}


def _rough_ground(b) -> dict:
    """Rough ground, ``v_P = 0``: the velocity of C, ``d omega/dt``, the contact force and
    the energy (the ``rough_*`` fields of :class:`Derivation`)."""
    vP, dvC, newton, euler = b.vP, b.dvC, b.newton, b.euler
    vC_rough = sp.solve(list(vP[:2]), [v_Cx, v_Cy], dict=True)[0]
    rough_v = {v_Cx: vC_rough[v_Cx], v_Cy: vC_rough[v_Cy], v_Cz: b.v_Cz_contact}
    # accelerations of C in Cxyz: d/dt of the constrained velocity components
    state_rates = {theta: omega1, omega1: dw1, omega2: dw2, omega3: dw3}

    def ddt(expr):
        return sum(sp.diff(expr, q) * qd for q, qd in state_rates.items())

    dv_rough = {dvC[0]: ddt(rough_v[v_Cx]), dvC[1]: ddt(rough_v[v_Cy]),
                dvC[2]: ddt(rough_v[v_Cz])}
    F_rough = sp.solve([eq.subs(dv_rough).subs(rough_v) for eq in newton], [F_x, F_y, F_z],
                       dict=True)[0]
    eqs_rough = [eq.subs(_NO_MOMENTS).subs(F_rough) for eq in euler]
    sol_rough = sp.solve(eqs_rough, [dw1, dw2, dw3], dict=True)[0]
    return dict(
        rough_velocity_of_C=(vC_rough[v_Cx], vC_rough[v_Cy]),
        rough_omega_dot=tuple(sp.factor(sp.simplify(sol_rough[d])) for d in (dw1, dw2, dw3)),
        rough_force=tuple(sp.together(F_rough[f].subs(sol_rough)) for f in (F_x, F_y, F_z)),
        rough_energy=sp.simplify(b.E.subs(rough_v)))


def _smooth_ground(b) -> dict:
    """Smooth ground, ``F_x = F_y = 0`` and ``F_z`` from eq. (11): ``d omega/dt``, the
    contact force and the internal energy (the ``smooth_*`` fields of :class:`Derivation`)."""
    eqs_smooth = [eq.subs(_NO_MOMENTS).subs({F_x: 0, F_y: 0, F_z: b.normal_force})
                  for eq in b.euler]
    sol_smooth = sp.solve(eqs_smooth, [dw1, dw2, dw3], dict=True)[0]
    return dict(
        smooth_omega_dot=tuple(sp.simplify(sol_smooth[d]) for d in (dw1, dw2, dw3)),
        smooth_force=(sp.Integer(0), sp.Integer(0),
                      sp.simplify(b.normal_force.subs(sol_smooth))),
        smooth_energy_internal=sp.simplify(b.E.subs({v_Cx: 0, v_Cy: 0, v_Cz: b.v_Cz_contact})))


@lru_cache(maxsize=1)
def lambdified() -> dict:
    """Numeric (numpy) functions of ``(ht, theta, omega1, omega2, omega3)`` from :func:`derive`.

    Keys: ``rough_omega_dot``, ``rough_force``, ``rough_energy``, ``smooth_omega_dot``,
    ``smooth_force``, ``smooth_energy_internal``, and ``rough_energy_rate`` /
    ``smooth_energy_rate`` (dE/dt along each system, from the symbolic gradient of E).
    """
    d = derive()
    args = (ht, theta, omega1, omega2, omega3)
    out = {}
    for name in ("rough_omega_dot", "rough_force", "smooth_omega_dot", "smooth_force"):
        out[name] = sp.lambdify(args, list(getattr(d, name)), "numpy")
    out["rough_energy"] = sp.lambdify(args, d.rough_energy, "numpy")
    out["smooth_energy_internal"] = sp.lambdify(args, d.smooth_energy_internal, "numpy")
    for ground, E, wd in (("rough", d.rough_energy, d.rough_omega_dot),
                          ("smooth", d.smooth_energy_internal, d.smooth_omega_dot)):
        rate = E.diff(theta) * omega1 + sum(E.diff(wi) * r for wi, r in
                                            zip((omega1, omega2, omega3), wd))
        out[f"{ground}_energy_rate"] = sp.lambdify(args, rate, "numpy")
    return out
