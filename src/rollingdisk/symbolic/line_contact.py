"""Line contact: the upright disk on its tread line, derived (sympy).

The disk stands upright (``theta = 0``, ``h > 0``) and touches the plane along its tread
line, the segment between its two rim-edge points.  In the plane section through the axis
the contact is two corners; they carry the contact forces.  Corner ``s`` (``s = +1, -1``) is
the lowest point of rim edge ``s`` (the edge a disk tilted to ``sgn(theta) = s`` stands on,
eq. 4 with ``h~ = s h``): in Cxyz it sits at ``r_s = (0, -s h, -1)``.  Each corner carries a
unilateral normal force ``lambda_s >= 0`` and a Coulomb friction force ``F_s`` (set-valued:
``|F_s| <= mu lambda_s``, ``F_s = -mu lambda_s u_s/|u_s|`` while corner ``s`` slips with
``u_s``), as Glocker (Set-Valued Force Laws, 2001, ch. 7) poses a frictional contact; the
contact moment ``M`` of the ground model (rolling resistance, pivot, air) acts besides.
Units ``m = a = g = 1``.

Two routes, compared by ``tests/test_line_contact.py`` at random states:

* :func:`newton_euler` - momentum and angular momentum balances in the frame Cxyz turning at
  ``(omega1, 0, omega3)`` (``theta = 0``), with ``omega1 = d omega1/dt = 0`` and
  ``v_z = d v_z/dt = 0`` imposed (both corners stay down);
* :func:`lagrange` - Lagrange's equations of the free body in ``(X, Y, Z, psi, theta,
  phi)`` with ``R = R_Z(psi) R_x(theta) R_eta(phi)`` and ``omega`` from ``R^T dR/dt``, the
  corner forces entering as generalised forces through the velocities of the material
  points at the corners, then ``theta = theta' = theta'' = 0`` and ``Z = 1, Z' = Z'' = 0``.

:func:`sub_phases` gives what the phase in :mod:`rollingdisk.phases.line_contact` uses:

* ``lambda_+ + lambda_- = 1`` identically: the line is never left into flight;
* the normal forces when both corners slide, and where one of them reaches 0 (the disk
  tilts onto the other corner: rocking);
* rolling upright without slip needs ``omega3 = 0`` (two corners ``2h`` apart cannot both
  roll while the disk turns), and then ``d omega2/dt = M_y/(1 + k2^2)``, ``lambda_s = 1/2``;
* the spin about the vertical: the friction moment is ``-sum_s y_s F_sx``, bounded by
  ``mu h (lambda_+ + lambda_-) = mu h``, so ``|d omega3/dt| <= mu h/k1^2`` from friction;
  spinning in place it decays at exactly that rate, ``k1^2 = 1/4 + h^2/3`` (eq. 10, the
  moment of inertia about the vertical diameter, :func:`rollingdisk.symbolic.impact.inertia`);
* the energy rate ``dE/dt = sum_s F_s . u_s + omega . M`` (the friction power).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

__all__ = ["newton_euler", "lagrange", "sub_phases", "LineEquations", "SubPhases",
           "UNKNOWNS", "INPUTS"]

h = sp.Symbol("h", positive=True)
k1, k2 = sp.symbols("k1_sq k2_sq", positive=True)
vx, vy, w2, w3 = sp.symbols("v_x v_y omega2 omega3", real=True)
F = sp.symbols("F_px F_py F_mx F_my", real=True)  # corner +: (F_px, F_py); corner -: ...
Mx, My, Mz = sp.symbols("M_x M_y M_z", real=True)
lam_p, lam_m = sp.symbols("lambda_p lambda_m", real=True)
dvx, dvy, dw2, dw3 = sp.symbols("dv_x dv_y domega2 domega3", real=True)
mu = sp.Symbol("mu", nonnegative=True)

#: The unknowns each route solves for: accelerations (Cxyz components, turning frame) and
#: the two normal forces.
UNKNOWNS = (dvx, dvy, dw2, dw3, lam_p, lam_m)
#: The inputs of both routes: state, corner friction forces (Cxyz) and the contact moment.
INPUTS = (h, k1, k2, vx, vy, w2, w3, *F, Mx, My, Mz)

#: Corner s in Cxyz: r_s = (0, -s h, -1).
Y_CORNER = {1: -h, -1: h}


def _cross(a, b):
    return sp.Matrix([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                      a[0] * b[1] - a[1] * b[0]])


def _corner_forces():
    return {1: sp.Matrix([F[0], F[1], lam_p]), -1: sp.Matrix([F[2], F[3], lam_m])}


@dataclass(frozen=True)
class LineEquations:
    """The equations of line contact solved for :data:`UNKNOWNS`.

    Attributes
    ----------
    solution : dict
        ``{unknown: expression in INPUTS}``.
    """

    solution: dict


@cache
def newton_euler() -> LineEquations:
    """Newton-Euler in Cxyz at ``theta = 0``, both corners down.

    The frame Cxyz turns at ``(d theta/dt, 0, d psi/dt) = (omega1, 0, omega3)`` at
    ``theta = 0``; the body's angular velocity in it is ``(omega1, omega2, omega3)`` and the
    angular momentum about C is ``(k1^2 omega1, k2^2 omega2, k1^2 omega3)``.  Both corners
    stay on the plane: ``v_z = 0`` and ``omega1 = 0`` with their rates.
    """
    w1, dw1, vz, dvz = sp.symbols("omega1 domega1 v_z dv_z", real=True)
    Om = sp.Matrix([w1, 0, w3])  # frame rate
    v = sp.Matrix([vx, vy, vz])
    dv = sp.Matrix([dvx, dvy, dvz])
    H = sp.Matrix([k1 * w1, k2 * w2, k1 * w3])
    dH = sp.Matrix([k1 * dw1, k2 * dw2, k1 * dw3])
    Fc = _corner_forces()
    force = Fc[1] + Fc[-1] + sp.Matrix([0, 0, -1])
    moment = sp.Matrix([Mx, My, Mz])
    for s in (1, -1):
        moment += _cross(sp.Matrix([0, Y_CORNER[s], -1]), Fc[s])
    eqs = list(dv + _cross(Om, v) - force) + list(dH + _cross(Om, H) - moment)
    eqs = [e.subs({w1: 0, dw1: 0, vz: 0, dvz: 0}) for e in eqs]
    sol = sp.solve(eqs, UNKNOWNS, dict=True)[0]
    return LineEquations({k: sp.simplify(v_) for k, v_ in sol.items()})


@cache
def lagrange() -> LineEquations:
    """Lagrange's equations of the free body, then both corners held down.

    ``T = 1/2 |dC/dt|^2 + 1/2 w_b . diag(k1^2, k2^2, k1^2) w_b`` with ``w_b`` the body
    angular velocity from ``R^T dR/dt`` (eta the body's second axis); the potential ``Z``.
    A force ``F`` at a corner does the virtual work of the material point there:
    ``Q_q = F . d(v_C + omega x r)/d(q')``; a moment ``M`` (Cxyz): ``Q_q = M . d omega/d(q')``.
    Written in the inertial frame and angles, nothing of the turning frame Cxyz enters
    until the results are expressed in its components at the end.
    """
    t = sp.Symbol("t", real=True)
    X, Y, Z, ps, th, ph = (sp.Function(n)(t) for n in ("X", "Y", "Z", "psi", "theta", "phi"))
    q = [X, Y, Z, ps, th, ph]
    qd = [sp.diff(x, t) for x in q]

    def rz(a):
        return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])

    def rx(a):
        return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])

    def ry(a):
        return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])

    R = rz(ps) * rx(th) * ry(ph)
    Wb = sp.simplify(R.T * sp.diff(R, t))
    wb = sp.Matrix([Wb[2, 1], Wb[0, 2], Wb[1, 0]])
    w_in = R * wb  # inertial components
    vC = sp.Matrix(qd[:3])
    T = (vC.dot(vC) + k1 * wb[0] ** 2 + k2 * wb[1] ** 2 + k1 * wb[2] ** 2) / 2
    V = Z
    Fc = _corner_forces()
    Rxyz = rz(ps)  # Cxyz -> inertial (theta = 0 there; kept general in the velocities)
    # material points at the corners, r from C, in inertial components: Cxyz vector at
    # theta = 0 is (0, y, -1); for the virtual velocities the point is the material point
    # currently there, r = Rz(psi) Rx(theta) (0, y, -1) (the corner's place in C xi eta
    # zeta is fixed: it is the lowest point of its rim edge)
    Q = [sp.S(0)] * 6
    for s in (1, -1):
        r = rz(ps) * rx(th) * sp.Matrix([0, Y_CORNER[s], -1])
        vP = vC + _cross(w_in, r)
        Fin = Rxyz * Fc[s]
        for i in range(6):
            Q[i] += Fin.dot(vP.diff(qd[i]))
    Min = Rxyz * sp.Matrix([Mx, My, Mz])
    for i in range(6):
        Q[i] += Min.dot(w_in.diff(qd[i]))
    L = T - V
    eqs = [sp.diff(L.diff(qd[i]), t) - L.diff(q[i]) - Q[i] for i in range(6)]
    # hold both corners down: theta = theta' = theta'' = 0, Z = 1, Z' = Z'' = 0
    acc = [sp.diff(x, t, 2) for x in q]
    A = sp.symbols("Xdd Ydd Zdd psidd thetadd phidd", real=True)
    Vv = sp.symbols("Xd Yd Zd psid thetad phid", real=True)
    P = sp.symbols("X0 Y0 Z0 psi0 theta0 phi0", real=True)
    sub = dict(zip(acc, A))
    e2 = [e.subs(sub) for e in eqs]
    e2 = [e.subs(dict(zip(qd, Vv))) for e in e2]
    e2 = [e.subs(dict(zip(q, P))) for e in e2]
    hold = {P[4]: 0, Vv[4]: 0, A[4]: 0, P[2]: 1, Vv[2]: 0, A[2]: 0}
    e2 = [sp.simplify(e.subs(hold)) for e in e2]
    # in the turning frame's components: psi' = omega3, phi' = omega2 (theta = 0, eq. 2)
    c, s_ = sp.cos(P[3]), sp.sin(P[3])
    to_frame = {Vv[0]: vx * c - vy * s_, Vv[1]: vx * s_ + vy * c, Vv[3]: w3, Vv[5]: w2,
                # d/dt of v = Rz(psi)^T (X', Y'): dv = Rz^T (X'', Y'') - omega3 J v
                A[0]: (dvx - w3 * vy) * c - (dvy + w3 * vx) * s_,
                A[1]: (dvx - w3 * vy) * s_ + (dvy + w3 * vx) * c,
                A[3]: dw3, A[5]: dw2}
    e3 = [sp.simplify(e.subs(to_frame)) for e in e2]
    sol = sp.solve(e3, UNKNOWNS, dict=True)[0]
    return LineEquations({k: sp.simplify(v_) for k, v_ in sol.items()})


@dataclass(frozen=True)
class SubPhases:
    """Closed forms of the sub-phases (sympy), each derived from :func:`newton_euler`.

    Attributes
    ----------
    normal_sum : Expr
        ``lambda_+ + lambda_-`` (identically 1: no flight from the line).
    lambda_sliding : dict
        ``{lambda_p, lambda_m}`` when both corners slide, friction ``-mu lambda_s d_s``
        with unit directions ``d_s = (dpx, dpy)``, ``(dmx, dmy)``.
    leave : dict
        ``{lambda_p, lambda_m}`` in terms of the tipping moment ``G = k2^2 omega2 omega3 +
        F_y + M_x``: ``lambda_+ = (h + G)/(2h)``, ``lambda_- = (h - G)/(2h)``.  Corner ``-s``
        unloads where ``s G`` reaches ``h``; past it the tilt accelerates towards
        ``sgn(theta) = s`` (``k1^2 d omega1/dt = G - s h`` pivoting on corner ``s``).
    rolling : dict
        Both corners sticking (``omega3 = 0``, ``v_y = 0``, ``v_x = omega2``): ``domega2``,
        ``lambda_p``, ``lambda_m``, and the corner forces ``F_px = F_mx``.
    spin_rate : Expr
        ``d omega3/dt`` spinning in place (``v = omega2 = 0``, both corners sliding, ``M =
        0``), in terms of ``sigma = sgn(omega3)``: ``-mu h sigma/k1^2``.
    friction_moment : Expr
        The vertical moment of the corner forces about C, ``-sum_s y_s F_sx``.
    energy_rate : Expr
        ``dE/dt - (sum_s F_s . u_s + omega . M)``, identically 0.
    """

    normal_sum: sp.Expr
    lambda_sliding: dict
    leave: dict
    rolling: dict
    spin_rate: sp.Expr
    friction_moment: sp.Expr
    energy_rate: sp.Expr


def slips():
    """``{s: (u_sx, u_sy)}``: velocity of the material point at corner ``s`` (Cxyz),
    ``v_C + omega x r_s`` with ``omega = (0, omega2, omega3)``; its z-component is 0."""
    out = {}
    for s in (1, -1):
        u = sp.Matrix([vx, vy, 0]) + _cross(sp.Matrix([0, w2, w3]),
                                           sp.Matrix([0, Y_CORNER[s], -1]))
        assert sp.simplify(u[2]) == 0
        out[s] = (sp.expand(u[0]), sp.expand(u[1]))
    return out


@cache
def sub_phases() -> SubPhases:
    """Derive the sub-phases of line contact from :func:`newton_euler`."""
    sol = newton_euler().solution
    u = slips()
    normal_sum = sp.simplify(sol[lam_p] + sol[lam_m])
    # both corners sliding: F_s = -mu lambda_s d_s; lambda_s are themselves unknowns
    d = sp.symbols("d_px d_py d_mx d_my", real=True)
    fr = {F[0]: -mu * lam_p * d[0], F[1]: -mu * lam_p * d[1],
          F[2]: -mu * lam_m * d[2], F[3]: -mu * lam_m * d[3]}
    eqs = [sp.Eq(lam_p, sol[lam_p].subs(fr)), sp.Eq(lam_m, sol[lam_m].subs(fr))]
    lam_sl = sp.solve(eqs, (lam_p, lam_m), dict=True)[0]
    lam_sl = {k: sp.simplify(v_) for k, v_ in lam_sl.items()}
    G = sp.Symbol("G", real=True)
    Fy = F[1] + F[3]
    leave = {lam_p: sp.simplify(sol[lam_p].subs(Mx, G - k2 * w2 * w3 - Fy)),
             lam_m: sp.simplify(sol[lam_m].subs(Mx, G - k2 * w2 * w3 - Fy))}
    # rolling: both corners stick, which needs omega3 = 0 (d u_+x/dt - d u_-x/dt =
    # -2h domega3 and u_+x - u_-x = 2h omega3), v_y = 0, v_x = omega2; the sideways split of
    # the friction is then free and zero will do (F_y = d v_y/dt + omega3 v_x = 0), and
    # rolling needs no moment about x or about the vertical (M_x = M_z = 0)
    roll = {w3: 0, vy: 0, vx: w2, F[1]: 0, F[3]: 0, Mx: 0, Mz: 0}
    acc = {k: sol[k].subs(roll) for k in (dvx, dw2, dw3)}
    fx = sp.solve([acc[dw3], acc[dvx] - acc[dw2]], (F[0], F[2]), dict=True)[0]
    rolling = {dw2: sp.simplify(acc[dw2].subs(fx)), F[0]: sp.simplify(fx[F[0]]),
               F[2]: sp.simplify(fx[F[2]]), lam_p: sp.simplify(sol[lam_p].subs(roll)),
               lam_m: sp.simplify(sol[lam_m].subs(roll)),
               dvy: sp.simplify(sol[dvy].subs(roll))}
    # spinning in place: v = omega2 = 0, u_+ = (h omega3, 0), u_- = (-h omega3, 0)
    sg = sp.Symbol("sigma", real=True)  # sgn(omega3)
    spin_fr = {F[0]: -mu * lam_p * sg, F[1]: 0, F[2]: mu * lam_m * sg, F[3]: 0}
    st = {vx: 0, vy: 0, w2: 0, Mx: 0, My: 0, Mz: 0}
    lam_sp = sp.solve([sp.Eq(lam_p, sol[lam_p].subs(spin_fr).subs(st)),
                       sp.Eq(lam_m, sol[lam_m].subs(spin_fr).subs(st))], (lam_p, lam_m),
                      dict=True)[0]
    spin_rate = sp.simplify(sol[dw3].subs(spin_fr).subs(st).subs(lam_sp))
    fm = sp.expand(-(Y_CORNER[1] * F[0] + Y_CORNER[-1] * F[2]))
    # energy: E = (v_x^2 + v_y^2)/2 + k2^2 omega2^2/2 + k1^2 omega3^2/2 + Z (Z = 1 fixed)
    dE = vx * sol[dvx] + vy * sol[dvy] + k2 * w2 * sol[dw2] + k1 * w3 * sol[dw3]
    power = (F[0] * u[1][0] + F[1] * u[1][1] + F[2] * u[-1][0] + F[3] * u[-1][1]
             + w2 * My + w3 * Mz)
    energy_rate = sp.simplify(dE - power)
    return SubPhases(normal_sum, lam_sl, leave, rolling, spin_rate, fm, energy_rate)
