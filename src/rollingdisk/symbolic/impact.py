"""Free flight, the lowest point, the Delassus matrix and the impact law, derived (sympy).

Nothing is taken from :mod:`rollingdisk.phases.flight` or :mod:`rollingdisk.phases.impact`;
the numeric functions there are compared with these results by ``tests/test_impact.py``.
Frames and angles as in ``docs/notation.md``: ``R = R_Z(psi) R_x(theta) R_eta(phi)``,
C xi eta zeta = ``R_Z(psi) R_x(theta)``, eta the symmetry axis; ``m = a = g = 1``.

* :func:`inertia` - eq. (10) by integration over the cylinder.
* :func:`free_flight` - the kinematics (eq. 2) from ``dR/dt R^T``; Euler's equations of the
  torque-free body in C xi eta zeta and in the body frame; the exact solution of the
  symmetric top (``omega2`` constant, the transverse body components turning at
  ``(k2^2 - k1^2)/k1^2 omega2``, ``L`` fixed in space), each checked by substitution.
* :func:`lowest_point` - the height of the lowest point for the three contact kinds.
* :func:`delassus` - ``W`` from the impulse-momentum balances (``d gamma+/d Lam``).
* :func:`energy_balance` - Glocker's energy identity of the Newton-Coulomb law, and the
  energy a law with tangential restitution 0 and normal restitution 1 can create.
* :func:`rocking_ratio` - the rim-change ratio of an upright disk, and Housner's block.

(In the library's notation the axis is the 2nd direction: ``k2^2 = 1/2`` and ``omega2``
are the axial inertia and spin that the literature often calls ``k3^2`` and ``omega3``.)
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

__all__ = ["inertia", "free_flight", "FreeFlight", "lowest_point", "delassus",
           "energy_balance", "rocking_ratio"]

t = sp.Symbol("t", real=True)
h = sp.Symbol("h", nonnegative=True)
k1, k2 = sp.symbols("k1_sq k2_sq", positive=True)
theta, psi, phi = sp.symbols("theta psi phi", real=True)
w1, w2, w3 = sp.symbols("omega1 omega2 omega3", real=True)
Z_C = sp.Symbol("Z_C", real=True)


_S = sp.symbols("S_psi S_theta S_phi", real=True)
_C = sp.symbols("C_psi C_theta C_phi", real=True)
_TO = {f(a): x for a, s_, c_ in zip((psi, theta, phi), _S, _C)
       for f, x in ((sp.sin, s_), (sp.cos, c_))}
_BACK = {v: k for k, v in _TO.items()}
_PYTH = [s_ ** 2 + c_ ** 2 - 1 for s_, c_ in zip(_S, _C)]


def _ts(expr):
    """Simplify a rational function of sines and cosines of ``psi, theta, phi``: the
    numerator and denominator reduced modulo ``sin^2 + cos^2 = 1`` (a Groebner basis), which
    is exact and much faster than :func:`sympy.simplify` on these expressions."""
    e = sp.together(sp.expand(sp.sympify(expr)).subs(_TO))
    n, d = sp.fraction(e)
    n = sp.reduced(sp.expand(n), _PYTH, *_S, *_C)[1]
    d = sp.reduced(sp.expand(d), _PYTH, *_S, *_C)[1]
    return sp.factor(n.subs(_BACK)) / sp.factor(d.subs(_BACK))


def _rz(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def _rx(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


def _ry(a):
    return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])


def _vee(S):
    """Axial vector of a skew matrix."""
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


def _cross_matrix(r):
    return sp.Matrix([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])


@cache
def inertia() -> tuple[sp.Expr, sp.Expr]:
    """``(k1^2, k2^2)`` of a homogeneous cylinder of radius 1, length ``2h``, mass 1.

    Integrates ``rho^2`` (axis) and ``x^2 + s^2`` (a diameter x) over the volume in
    cylindrical coordinates ``(rho, alpha, s)``; eq. (10) says ``1/4 + h^2/3`` and ``1/2``.
    """
    rho, al, s = sp.symbols("rho alpha s", real=True)
    vol = 2 * sp.pi * h
    dens = 1 / vol

    def integ(f):
        return sp.integrate(f * rho, (rho, 0, 1), (al, 0, 2 * sp.pi), (s, -h, h)) * dens

    axial = sp.simplify(integ(rho ** 2))
    diam = sp.simplify(integ((rho * sp.cos(al)) ** 2 + s ** 2))
    return diam, axial


@dataclass(frozen=True)
class FreeFlight:
    """Results of :func:`free_flight` (sympy expressions).

    Attributes
    ----------
    kinematics : tuple
        ``(omega1, omega2, omega3)`` in C xi eta zeta in terms of the angle rates
        (``psi', theta', phi'`` as symbols ``dpsi, dtheta, dphi``), eq. (2).
    domega : tuple
        ``d omega_i/dt`` in C xi eta zeta, torque-free (Euler's equations in the library's
        angles).
    body_domega : tuple
        Euler's equations in the body frame, ``(dOmega1, dOmega2, dOmega3)``.
    precession_rate : Expr
        Rate at which the transverse body components turn about the axis:
        ``(k2^2 - k1^2)/k1^2 omega2``.
    spin_rate : Expr
        ``nu = (k1^2 - k2^2)/k1^2 omega2``: the body's rotation about its axis relative to
        the frame that turns about ``L`` at ``|L|/k1^2``.
    residuals : dict
        Each check, simplified; all zero.
    """

    kinematics: tuple
    domega: tuple
    body_domega: tuple
    precession_rate: sp.Expr
    spin_rate: sp.Expr
    residuals: dict


@cache
def free_flight() -> FreeFlight:
    """Derive the torque-free motion of the disk and check its exact solution.

    1. ``omega`` (space) is the axial vector of ``dR/dt R^T`` with
       ``R = R_Z(psi) R_x(theta) R_eta(phi)``; its components in C xi eta zeta give eq. (2).
    2. ``dL/dt = 0`` with ``L = Q diag(k1^2, k2^2, k1^2) omega_xez``, ``Q = R_Z R_x``, the
       angle rates eliminated with (2), solved for ``d omega/dt``.
    3. In the body frame ``Omega = R_eta(phi)^T omega_xez``: Euler's equations.
    4. The exact solution: ``Omega = (A cos lam t + B sin lam t, omega2, -A sin lam t +
       B cos lam t)`` with ``lam`` the precession rate solves 3; and
       ``omega = L/k1^2 + nu eta`` has ``J omega = L`` whenever ``eta . L = k2^2 omega2``,
       which fixes ``nu`` (``eta`` turns about ``L``, so ``eta . L`` stays constant).
    """
    dpsi, dth, dph = sp.symbols("dpsi dtheta dphi", real=True)
    angles_rates = ((psi, dpsi), (theta, dth), (phi, dph))

    def ddt(M, extra=()):
        """Time derivative of a matrix of the angles (and of ``extra`` symbols)."""
        return sum((M.diff(a) * da for a, da in (*angles_rates, *extra)), sp.zeros(*M.shape))

    R = _rz(psi) * _rx(theta) * _ry(phi)
    Q = _rz(psi) * _rx(theta)
    w_space = _vee((ddt(R) * R.T).applyfunc(_ts))
    kin = tuple(_ts(c) for c in Q.T * w_space)
    # invert (2): dtheta = omega1, dpsi = omega3/cos, dphi = omega2 - omega3 tan
    sol = sp.solve([sp.Eq(kin[0], w1), sp.Eq(kin[1], w2), sp.Eq(kin[2], w3)],
                   [dpsi, dth, dph], dict=True)[0]
    # dL/dt = 0 with L = Q J omega_xez
    dW = sp.symbols("dw1 dw2 dw3", real=True)
    L = Q * sp.diag(k1, k2, k1) * sp.Matrix([w1, w2, w3])
    dL = ddt(L, ((w1, dW[0]), (w2, dW[1]), (w3, dW[2])))
    eqs = (Q.T * dL.subs(sol)).applyfunc(_ts)
    dsol = sp.solve(list(eqs), list(dW), dict=True)[0]
    domega = tuple(_ts(dsol[d]) for d in dW)
    # body frame: d/dt (R Jb Omega) = R (Omega x Jb Omega + Jb dOmega) = 0
    Om = sp.Matrix(sp.symbols("Omega1 Omega2 Omega3", real=True))
    dOm = sp.symbols("dOmega1 dOmega2 dOmega3", real=True)
    Jb = sp.diag(k1, k2, k1)
    eqb = Om.cross(Jb * Om) + Jb * sp.Matrix(dOm)
    bsol = sp.solve(list(eqb), list(dOm), dict=True)[0]
    body = tuple(_ts(bsol[d]) for d in dOm)
    # exact solution in the body frame
    lam = (k2 - k1) / k1 * w2
    A, B = sp.symbols("A B", real=True)
    Ot = sp.Matrix([A * sp.cos(lam * t) + B * sp.sin(lam * t), w2,
                    -A * sp.sin(lam * t) + B * sp.cos(lam * t)])
    subs_t = {Om[0]: Ot[0], Om[1]: Ot[1], Om[2]: Ot[2]}
    res_body = [_ts(Ot[i].diff(t) - body[i].subs(subs_t)) for i in range(3)]
    # exact solution in space: omega = L/k1 + nu eta gives J omega - L = c eta with
    # c = (k2 - k1)/k1 (eta . L) + nu k2, zero for eta . L = k2 omega2
    nu = (k1 - k2) / k1 * w2
    Lv = sp.Matrix(sp.symbols("L_X L_Y L_Z", real=True))
    eta = Q[:, 1]
    J_space = Q * sp.diag(k1, k2, k1) * Q.T
    res = J_space * (Lv / k1 + nu * eta) - Lv
    eta_L = (eta.T * Lv)[0]
    coef = _ts((eta.T * res)[0])
    residuals = {"kinematics (2)": [_ts(kin[0] - dth),
                                    _ts(kin[1] - (dph + dpsi * sp.sin(theta))),
                                    _ts(kin[2] - dpsi * sp.cos(theta))],
                 "domega2 = 0": domega[1],
                 "body solution": res_body,
                 "J omega - L along eta": [_ts(c) for c in res - coef * eta],
                 "J omega - L: coefficient": _ts(
                     coef - ((k2 - k1) / k1 * eta_L + nu * k2)),
                 "eta . L = k2 omega2 cancels it": _ts((k2 - k1) / k1 * k2 * w2
                                                               + nu * k2),
                 "omega2 = eta . omega": _ts(
                     sp.expand(k1 * ((eta.T * (Lv / k1 + nu * eta))[0] - w2))
                     - (eta_L - k2 * w2)).subs(eta_L, k2 * w2)}
    return FreeFlight(kin, domega, body, sp.factor(lam), sp.factor(nu), residuals)


@cache
def lowest_point() -> dict:
    """Height of the lowest point of the disk above the plane, per contact kind.

    A point of the disk is ``C + s eta + rho (cos alpha xi + sin alpha zeta)``,
    ``|s| <= h``, ``0 <= rho <= 1``; its height ``Z_C + s sin theta + rho sin alpha
    cos theta`` is linear in ``s`` and in ``q = rho sin alpha in [-1, 1]``, so it is least
    at ``s = -h sgn(sin theta)``, ``q = -sgn(cos theta)``: a point of the rim circle of the
    lower face.  Where a coefficient vanishes the whole range touches: ``sin theta = 0``
    (``h > 0``) the tread line, ``cos theta = 0`` the face.

    Returns
    -------
    dict
        ``"Z"`` (height of a general point), ``"rim"``, ``"tread"``, ``"face"`` (the least
        height), ``"r_xyz"`` (``P - C`` in Cxyz for ``0 < theta < pi/2``: eq. 4 with
        ``h~ = h``).
    """
    s, q = sp.symbols("s q", real=True)
    Q = _rx(theta)  # xi, eta, zeta in Cxyz
    point = s * Q[:, 1] + q * Q[:, 2]
    Z = Z_C + point[2]
    coeff_s, coeff_q = sp.diff(Z, s), sp.diff(Z, q)
    rim = Z_C - sp.Abs(coeff_s) * h - sp.Abs(coeff_q)
    tread = Z.subs(theta, 0).subs(q, -1)  # independent of s
    face = Z.subs(theta, sp.pi / 2).subs(s, -h)  # independent of q
    r = point.subs({s: -h, q: -1})
    return {"Z": Z, "rim": rim, "tread": sp.simplify(tread), "face": sp.simplify(face),
            "r_xyz": sp.simplify(r), "d/ds": coeff_s, "d/dq": coeff_q}


@cache
def delassus() -> sp.Matrix:
    """The Delassus matrix ``W`` of a rim point, in Cxyz, from the impulse balances.

    ``r = P - C = -sigma h eta - c zeta`` (``sigma`` the rim edge, ``c = sgn cos theta``);
    an impulse ``Lam`` at P changes ``V`` by ``Lam`` (m = 1) and ``omega`` by
    ``J^-1 (r x Lam)`` with ``J = Q diag(k1^2, k2^2, k1^2) Q^T``; ``W`` is the Jacobian of
    the jump of P's velocity ``dV + d omega x r`` with respect to ``Lam``.  Symbols:
    ``theta, h, k1_sq, k2_sq, sigma, c``.
    """
    sig, c = sp.symbols("sigma c", real=True)
    Q = _rx(theta)
    r = -sig * h * Q[:, 1] - c * Q[:, 2]
    J = Q * sp.diag(k1, k2, k1) * Q.T
    Lam = sp.Matrix(sp.symbols("Lam_x Lam_y Lam_z", real=True))
    dV = Lam
    dw = J.inv().applyfunc(_ts) * r.cross(Lam)
    dv_P = dV + dw.cross(r)
    W = dv_P.jacobian(Lam)
    return W.applyfunc(_ts)


@cache
def energy_balance() -> dict:
    """Energy of the Newton-Coulomb law at one contact (Glocker 2001, ch. 7).

    For a symmetric ``W`` and ``gamma+ = gamma- + W Lam``, the kinetic energy changes by
    ``Delta T = Lam . (gamma- + gamma+)/2``.  With ``xi = gamma+ + e gamma-`` (one ``e`` for
    all three directions) it is identically ``(Lam . xi - (1-e) Lam.W Lam/2)/(1+e)``; the
    law makes ``Lam . xi = Lam_T . xi_T <= 0`` (``Lam_N xi_N = 0``, and ``xi_T`` opposes
    ``Lam_T`` on the cone's boundary, vanishes inside), so ``Delta T <= 0`` for
    ``0 <= e <= 1``.  With normal restitution 1 and tangential restitution 0 a sticking
    impact (``gamma+ = (0, 0, -gamma-_N)``) changes the energy by ``"kane"``, which has
    the sign of ``-M_NT gamma_N gamma_T`` for small ``gamma_T`` (``M = W^-1``): energy is
    created whenever the normal and tangential directions couple.

    Returns
    -------
    dict
        ``"identity"`` (the residual, zero), ``"kane"`` (``Delta T`` of that sticking
        impact, in terms of ``M`` entries ``M_ij`` and ``gamma-``).
    """
    e = sp.Symbol("e", real=True)
    Ws = sp.symbols("W11 W12 W13 W22 W23 W33", real=True)
    W = sp.Matrix([[Ws[0], Ws[1], Ws[2]], [Ws[1], Ws[3], Ws[4]], [Ws[2], Ws[4], Ws[5]]])
    Lam = sp.Matrix(sp.symbols("Lx Ly Lz", real=True))
    gm = sp.Matrix(sp.symbols("gx gy gz", real=True))
    gp = gm + W * Lam
    dT = (Lam.T * (gm + gp))[0] / 2
    xi = gp + e * gm
    ident = sp.simplify(dT - ((Lam.T * xi)[0] - (1 - e) * (Lam.T * W * Lam)[0] / 2) / (1 + e))
    # Kane-type: stick tangentially (gamma_T+ = 0), reverse normally (gamma_N+ = -gamma_N-)
    Ms = sp.symbols("M11 M12 M13 M22 M23 M33", real=True)
    M = sp.Matrix([[Ms[0], Ms[1], Ms[2]], [Ms[1], Ms[3], Ms[4]], [Ms[2], Ms[4], Ms[5]]])
    gplus = sp.Matrix([0, 0, -gm[2]])
    L_k = M * (gplus - gm)
    kane = sp.expand((L_k.T * (gm + gplus))[0] / 2)
    return {"identity": ident, "kane": kane}


@cache
def rocking_ratio() -> dict:
    """Rim-change ratio ``omega+/omega-`` of an upright body rocking in a vertical plane.

    The cross-section through the axis is a rectangle of half-width ``b`` (here ``h``)
    and half-height ``d`` (here 1); the body turns about the edge O at ``(b, -d)`` from C
    and lands on O' at ``(-b, -d)``.  A perfectly inelastic, sticking impact at O' leaves
    the angular momentum about O' unchanged (the impulse passes through O'):
    ``(I_C + b^2 + d^2) omega+ = I_C omega- + ((C - O') x V_C-)_x`` with
    ``V_C- = omega- x (C - O)``.

    Returns
    -------
    dict
        ``"general"`` (``I_C, b, d``), ``"disk"`` (``I_C = k1^2 = 1/4 + h^2/3``, ``b = h``,
        ``d = 1``), ``"housner"`` (the block, ``I_C = (b^2 + d^2)/3``, in terms of
        ``alpha``, ``tan alpha = b/d``) and ``"housner_printed"`` (``1 - 3/2 sin^2
        alpha``, Housner 1963, for comparison).
    """
    I_C, b, d, om = sp.symbols("I_C b d omega", positive=True)
    al = sp.Symbol("alpha", positive=True)
    ex = sp.Matrix([1, 0, 0])
    C_O = sp.Matrix([0, -b, d])  # C - O
    C_O2 = sp.Matrix([0, b, d])  # C - O'
    V = (om * ex).cross(C_O)
    H_before = I_C * om + C_O2.cross(V)[0]
    w_plus = sp.Symbol("omega_plus")
    H_after = I_C * w_plus + C_O2.cross((w_plus * ex).cross(C_O2))[0]
    ratio = sp.simplify(sp.solve(sp.Eq(H_after, H_before), w_plus)[0] / om)
    disk = sp.factor(ratio.subs({I_C: sp.Rational(1, 4) + h ** 2 / 3, b: h, d: 1}))
    R = sp.Symbol("R", positive=True)
    block = ratio.subs(I_C, (b ** 2 + d ** 2) / 3).subs({b: R * sp.sin(al), d: R * sp.cos(al)})
    return {"general": ratio, "disk": disk, "housner": sp.simplify(block),
            "housner_printed": 1 - sp.Rational(3, 2) * sp.sin(al) ** 2}
