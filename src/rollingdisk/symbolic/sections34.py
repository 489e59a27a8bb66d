"""Sections 3-4 re-derived with sympy: steady motions, small oscillations, the paper's numbers.

Everything starts from the Newton-Euler derivation of :mod:`rollingdisk.symbolic.derivation`
(independent of the paper; the printed eqs. (37), (38) and (49) are compared with it in
:mod:`rollingdisk.symbolic.paper`, where they are typed in).  The kinematics of section 3
((15)-(25)) come from its frame rates, contact point and balances at a constant state; from
its reduced equations this module derives

* the steady-motion condition: ``d omega1/dt = 0`` at ``omega1 = 0``;
* ``varpi^2``: the linearization of the reduced system ``(theta, omega1, omega2, omega3)`` at
  a steady state has the characteristic polynomial ``lambda^2 (lambda^2 + varpi^2)`` with
  ``varpi^2 = -(d1_theta + d1_omega2 a2 + d1_omega3 a3)``, ``a_k = d(omega_k dot)/d omega1``;

and compares each printed equation with the derived one.  Two expressions are declared equal
when they agree to 1e-25 relative at six random rational points evaluated with 40-digit
arithmetic (a probabilistic identity test; a wrong formula fails it by many orders of
magnitude); a printed condition is declared equivalent to a derived one when their ratio is
non-zero and the same at points that share (h, p0) but differ in every other symbol.
Numbers quoted in the prose are computed with the numeric library, whose closed forms the
tests check against a numerical linearization and against simulation.

``theta0`` is taken in ``(0, pi/2)`` (so ``h~ = h``), written through ``p0 = tan(theta0)``;
negative ``theta0`` follows by the symmetry checked in ``tests/test_steady.py``.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Mapping
from functools import lru_cache
from types import MappingProxyType

import sympy as sp

__all__ = ["checks_sections_3_4", "derived", "format_rows"]

h, p, w1, w2, w3, W, w, rC, rP = sp.symbols(
    "h p0 omega1 omega20 omega30 Omega0 omega0 r_C r_P", real=True)
th = sp.Symbol("theta", real=True)
R = sp.Rational
ht = h  # h~ = h sgn(theta0), theta0 > 0
sq = sp.sqrt(1 + p ** 2)
s, c = p / sq, 1 / sq  # sin, cos of theta0 via p0 = tan(theta0)
k1 = R(1, 4) + h ** 2 / 3  # eq. (10)
k2 = R(1, 2)
yP = s - ht * c  # eq. (16)
zP = -(c + ht * s)


def _reduced(ground: str, source: str = "derivation"):
    """(d1, d2, d3) as functions of (theta, omega1, omega2, omega3).

    ``source="derivation"``: the Newton-Euler result of :mod:`rollingdisk.symbolic.derivation`
    (independent of the paper); ``"printed"``: eq. (38) / (49) as printed.
    """
    from . import derivation as D
    from .paper import PRINTED_38, PRINTED_49

    T = sp.Symbol("T", real=True)
    if source == "derivation":
        sol = D.derive().rough_omega_dot if ground == "rough" else D.derive().smooth_omega_dot
    else:
        sol = PRINTED_38 if ground == "rough" else PRINTED_49
    m = {D.theta: T, D.ht: ht, D.h: h, D.omega1: w1, D.omega2: w2, D.omega3: w3}
    d1, d2, d3 = (sp.sympify(e).subs(m, simultaneous=True) for e in sol)
    return T, d1, d2, d3
    sT, cT, pT = sp.sin(T), sp.cos(T), sp.tan(T)
    y, z = sT - ht * cT, -(cT + ht * sT)
    if ground == "rough":  # eq. (38)
        d1 = (6 * (3 + 2 * ht * pT) * w2 * w3 - ((3 + 16 * h ** 2) * pT + 12 * ht) * w3 ** 2
              + 12 * y) / (15 + 16 * h ** 2)
        d2 = -(4 * ht * w2 + R(2, 3) * (3 + 4 * h ** 2) * w3) * w1 / (3 + 8 * h ** 2)
        d3 = (-6 * w2 / (3 + 8 * h ** 2) + (pT + 4 * ht / (3 + 8 * h ** 2)) * w3) * w1
    else:  # eq. (49)
        d1 = ((k2 * w2 - k1 * w3 * pT) * w3 + y + y * z * w1 ** 2) / (k1 + y ** 2)
        d2 = sp.Integer(0)
        d3 = (-k2 * w2 + k1 * w3 * pT) * w1 / k1
    return T, d1, d2, d3


def _at_steady(e, T):
    """Evaluate an expression in theta = T at theta0 (via p0) and omega1 = 0."""
    return e.subs(w1, 0).subs(T, sp.atan(p))


def derived(ground: str, source: str = "derivation") -> dict:
    """Derived expressions: steady condition, omega20(omega30), varpi^2 and its pieces.

    Starts from the Newton-Euler derivation (``source="derivation"``) or from the printed
    eq. (38) / (49) (``source="printed"``).
    """
    T, d1, d2, d3 = _reduced(ground, source)
    cond = _at_steady(d1, T)  # d omega1/dt at a steady state: must vanish
    a2 = _at_steady(sp.diff(d2, w1), T)
    a3 = _at_steady(sp.diff(d3, w1), T)
    varpi2 = -(_at_steady(sp.diff(d1, T), T) + _at_steady(sp.diff(d1, w2), T) * a2
               + _at_steady(sp.diff(d1, w3), T) * a3)
    omega20 = sp.solve(sp.Eq(cond, 0), w2)[0]
    varpi2_circle = varpi2.subs(w2, omega20)
    return {"cond": cond, "a2": a2, "a3": a3, "varpi2": varpi2, "omega20": omega20,
            "varpi2_circle": varpi2_circle}


# ---------------------------------------------------------------------------------------
_rng = random.Random(20240601)
_POINTS = [{h: sp.Rational(_rng.randint(1, 300), 100), p: sp.Rational(_rng.randint(1, 400), 100),
            w1: 0, w2: sp.Rational(_rng.randint(-300, 300), 97),
            w3: sp.Rational(_rng.randint(1, 300), 89) * _rng.choice([1, -1]),
            W: sp.Rational(_rng.randint(1, 300), 83), w: sp.Rational(_rng.randint(-300, 300), 79),
            rC: sp.Rational(_rng.randint(-300, 300), 71),
            rP: sp.Rational(_rng.randint(-300, 300), 67)}
           for _ in range(6)]


def _points_kinematics(symbols) -> list[dict]:
    """:data:`_POINTS` with random rational values for further ``symbols`` too."""
    rng = random.Random(20240602)
    return [{**pt, **{x: sp.Rational(rng.randint(-300, 300), 61) for x in symbols}}
            for pt in _POINTS]


def _evaluator(expr) -> Callable[[dict], object]:
    """``pt -> expr`` at a point of rationals, in 50-digit mpmath arithmetic."""
    import mpmath

    expr = sp.sympify(expr)
    syms = sorted(expr.free_symbols, key=str)
    f = sp.lambdify(syms, expr, "mpmath")

    def value(pt):
        with mpmath.workdps(50):
            args = [mpmath.mpf(v.p) / v.q for v in (sp.Rational(pt[x]) for x in syms)]
            return f(*args)

    return value


def _same_at_points(a, b, points=None) -> bool:
    """``a == b`` at random points, 40 digits, 1e-25 relative (probabilistic identity test)."""
    import mpmath

    fa, fb = _evaluator(a), _evaluator(b)
    with mpmath.workdps(50):  # the arithmetic below too, not only the evaluation
        for pt in points or _POINTS:
            va, vb = fa(pt), fb(pt)
            if abs(va - vb) > 1e-25 * (1 + abs(va) + abs(vb)):
                return False
    return True


def proportional(a, b, params=(h, p)) -> bool:
    """``a = k b`` with a non-zero factor ``k`` that depends on ``params`` (h, p0) only.

    At each random point, ``a/b`` is evaluated at four variants of the point that share the
    values of ``params`` but draw every other symbol (the angular velocities, radii) afresh;
    the ratios must agree to 1e-25 relative and be non-zero (50-digit arithmetic).
    """
    import mpmath

    rng = random.Random(7)
    a, b = sp.sympify(a), sp.sympify(b)
    fa, fb = _evaluator(a), _evaluator(b)
    others = sorted((a.free_symbols | b.free_symbols) - set(params), key=str)
    with mpmath.workdps(50):  # the ratios too, not only the evaluation
        for pt in _POINTS:
            ratios = []
            for k in range(4):
                q = dict(pt)
                q.update({x: sp.Rational(rng.randint(-300, 300), 53 + k) or 1 for x in others
                          if k or x not in pt})
                va, vb = fa(q), fb(q)
                if abs(vb) < 1e-30:
                    return False
                ratios.append(va / vb)
            r0 = ratios[0]
            if abs(r0) < 1e-25 or any(abs(r - r0) > 1e-25 * (abs(r) + abs(r0))
                                      for r in ratios[1:]):
                return False
    return True


def _row(eq, printed, correct, ok_printed: bool, ok_correct: bool, evidence: str) -> dict:
    if ok_printed:
        status = "confirmed"
    elif ok_correct:
        status = "misprint"
    else:  # pragma: no cover - would mean the derivation disagrees with both
        status = "unresolved"
    return {"equation": eq, "status": status, "printed": printed,
            "correct": correct if status != "confirmed" else printed, "evidence": evidence}


def _num_row(eq, printed: str, library: float, quoted: float, tol: float, what: str,
             correct: str | None = None) -> dict:
    ok = abs(library - quoted) <= tol
    return {"equation": eq, "status": "confirmed" if ok else "misprint", "printed": printed,
            "correct": printed if ok else (correct or f"{library:.6g}"),
            "evidence": f"{what}: library {library:.6g}, paper {quoted:g}"}


@lru_cache(maxsize=1)
def checks_sections_3_4() -> tuple[Mapping[str, str], ...]:
    """One row per equation (15)-(59) of sections 3-4 and per number quoted in the prose.

    Each row, read-only: ``{"equation", "status" ("confirmed" | "misprint"), "printed",
    "correct", "evidence"}``.  (37), (38) and (49) are checked with section 2
    (:func:`rollingdisk.symbolic.paper.checks_sections_1_2`).  Takes some seconds; cached.
    """
    return tuple(MappingProxyType(r) for r in _compute_rows())


def _compute_rows() -> list[dict]:
    import numpy as np

    from .._stability import circle_coefficients, critical_omega30_sq, varpi2_circle
    from ..steady import r_C_star, se_circle_radius

    rows: list[dict] = []
    add = rows.append
    R_ = derived("rough")
    S_ = derived("smooth")
    Omega_from = {w3: W * c, w2: w + W * s}  # eq. (3)

    # ---- section 3: kinematics, from the derivation with a constant state ---------------
    from . import derivation as D

    d = D.derive()
    vx, vy, Fy, tt, psi0, XA, YA = sp.symbols("v_Cx0 v_Cy0 F_y t psi0 X_A Y_A", real=True)
    pts = _points_kinematics((vx, vy, Fy, tt, psi0, XA, YA))
    steady = {D.theta: sp.atan(p), D.ht: ht, D.h: h, D.omega1: 0, D.omega2: w2, D.omega3: w3,
              D.v_Cx: vx, D.v_Cy: vy, D.v_Cz: 0}

    def at_steady(e):  # an expression of the derivation at a steady state, with eq. (3)
        return sp.sympify(e).subs(steady, simultaneous=True).subs(Omega_from)

    psi_t = psi0 + W * tt
    rates = [at_steady(e) for e in d.frame_rates]  # (psi', theta', phi'), eq. (2)
    add(_row("(15)", "psi = psi0 + Omega0 t, phi = phi0 + omega0 t", "",
             _same_at_points(rates[0], W) and _same_at_points(rates[1], 0)
             and _same_at_points(rates[2], w), True,
             "sympy: the derived frame rates (2) at omega1 = 0, theta = theta0 with eq. (3) are "
             "psi' = Omega0, theta' = 0, phi' = omega0, constant"))
    add(_row("(16)", "y_P0 = sin th0 - h~ cos th0, z_P0 = -(cos th0 + h~ sin th0)", "",
             _same_at_points(at_steady(d.contact_point[0]), yP)
             and _same_at_points(at_steady(d.contact_point[1]), zP), True,
             "sympy: the derived contact point (4) at theta0"))
    rPC = [at_steady(e).subs(D.psi, psi_t) for e in d.contact_point_inertial]
    add(_row("(17)", "X_P0 = X_C0 - y_P0 sin(psi0 + Omega0 t), Y_P0 = Y_C0 + y_P0 cos(psi0 + "
             "Omega0 t)", "",
             _same_at_points(rPC[0], -yP * sp.sin(psi_t), pts)
             and _same_at_points(rPC[1], yP * sp.cos(psi_t), pts), True,
             "sympy: the derived contact point in OXYZ (5) at theta0 with psi from (15)"))
    vP = [at_steady(e) for e in d.contact_velocity]
    vPx = w2 - ht * w3  # v_Cx0 - v_Px0 of eq. (18)
    add(_row("(18)", "v_Px0 = v_Cx0 - omega20 + h~ omega30 = v_Cx0 - omega0 - y_P0 Omega0, "
             "v_Py0 = v_Cy0", "",
             _same_at_points(vP[0], vx - vPx.subs(Omega_from), pts)
             and _same_at_points(vPx.subs(Omega_from), w + yP * W)
             and _same_at_points(vP[1], vy, pts), True,
             "sympy: the derived contact-point velocity (6) at omega1 = 0, with eq. (3)"))
    # constant state: dv_C/dt = 0, omega' = 0, v_Cz = 0, no moments
    dv0 = dict.fromkeys(sp.symbols("dv_Cx dv_Cy dv_Cz", real=True), 0)
    rest = {**dv0, D.dw1: 0, D.dw2: 0, D.dw3: 0, D.M_x: 0, D.M_y: 0, D.M_z: 0}
    newton = [at_steady(e).subs(rest) for e in d.newton]
    F19 = sp.solve([e.subs(vy, 0) for e in newton], [D.F_x, D.F_y, D.F_z], dict=True)[0]
    add(_row("(19)", "F_x = 0, F_y = v_Cx0 Omega0, F_z = 1", "",
             _same_at_points(F19[D.F_x], 0, pts) and _same_at_points(F19[D.F_y], vx * W, pts)
             and _same_at_points(F19[D.F_z], 1, pts), True,
             "sympy: the derived momentum balance (8) with a constant state, v_Cy0 = 0 "
             "(20)_1, with eq. (3)"))
    euler = [at_steady(e).subs(rest) for e in d.euler]
    # (20)_1: (9)_2 with F_x from (8)_1 (v_Cy0 kept); (20)_2: (9)_1 with F_x = 0, F_z = 1
    Fx8 = sp.solve(newton[0], D.F_x)[0]
    e20g = (k2 * w2 - k1 * w3 * p) * w3 - zP * Fy + yP
    # (20)_2 with F_y = v_Cx0 Omega0 = (omega20 - h~ omega30) omega30 / cos on rough ground
    e20 = (k2 * w2 - k1 * w3 * p) * w3 - zP * (w2 - ht * w3) * w3 / c + yP
    add(_row("(20)", "v_Cy0 Omega0 = 0, (k2^2 omega20 - k1^2 omega30 tan th0) omega30 "
             "- z_P0 F_y + y_P0 = 0", "",
             proportional(euler[1].subs(D.F_x, Fx8), vy * W)
             and proportional(euler[0].subs({D.F_x: 0, D.F_y: Fy, D.F_z: 1}),
                             e20g.subs(Omega_from))
             and proportional(e20, R_["cond"]), True,
             "sympy: (20)_1 is the derived (9)_2 with F_x from (8)_1, (20)_2 the derived (9)_1 "
             "(each up to a factor of h, p0 only); with F_y from (19) on rough ground (20)_2 "
             "is proportional to d omega1/dt of the derived reduced equations at omega1 = 0"))
    vel1 = D._Rz(psi0) * sp.Matrix([vx, vy, 0])  # eq. (1) with psi = psi0
    X21 = [sp.Symbol("X_C0") + (vx * sp.cos(psi0) - vy * sp.sin(psi0)) * tt,
           sp.Symbol("Y_C0") + (vx * sp.sin(psi0) + vy * sp.cos(psi0)) * tt]
    add(_row("(21)", "X_C = X_C0 + (v_Cx0 cos psi0 - v_Cy0 sin psi0) t, Y_C = Y_C0 + (v_Cx0 "
             "sin psi0 + v_Cy0 cos psi0) t", "",
             _same_at_points(sp.diff(X21[0], tt), vel1[0], pts)
             and _same_at_points(sp.diff(X21[1], tt), vel1[1], pts)
             and proportional(R_["cond"].subs(w3, 0), yP)
             and proportional(S_["cond"].subs(w3, 0), yP), True,
             "sympy: d/dt of (21) equals the velocity (1) R_z(psi0) v_C; with omega30 = 0 the "
             "derived steady condition is proportional to y_P0 on both grounds, so straight "
             "lines need tan th0 = h~"))
    rC24 = -vx / W  # eq. (24)
    X22 = [XA - rC * sp.sin(psi_t), YA + rC * sp.cos(psi_t)]
    vel22 = D._Rz(psi_t) * sp.Matrix([vx, 0, 0])  # eq. (1), v_Cy0 = 0
    ok22 = all(_same_at_points(sp.diff(X22[i], tt).subs(rC, rC24), vel22[i], pts)
               for i in (0, 1))
    add(_row("(22)", "X_C = X_A - r_C sin(psi0 + Omega0 t), Y_C = Y_A + r_C cos(psi0 + "
             "Omega0 t)", "", ok22, True,
             "sympy: d/dt of (22) with r_C from (24) equals the velocity (1) with psi from (15) "
             "and v_Cy0 = 0"))
    X23 = [XA - (rC + yP) * sp.sin(psi_t), YA + (rC + yP) * sp.cos(psi_t)]
    ok23 = all(_same_at_points(X22[i] + rPC[i], X23[i], pts) for i in (0, 1))
    add(_row("(23)", "X_P = X_A - r_P sin(psi0 + Omega0 t), Y_P = Y_A + r_P cos(psi0 + "
             "Omega0 t)", "", ok23, True,
             "sympy: (22) plus the derived contact point (5) is (23) with r_P = r_C + y_P0"))
    add(_row("(24)", "r_C = -v_Cx0/Omega0, r_P = r_C + y_P0", "", ok22 and ok23, True,
             "sympy: the radii that make (22) integrate (1) and (23) follow from (22) and (5) "
             "(rows (22), (23))"))
    add(_row("(25)", "X_C0 = X_A - r_C sin psi0, Y_C0 = Y_A + r_C cos psi0", "",
             _same_at_points(X22[0].subs(tt, 0), XA - rC * sp.sin(psi0), pts)
             and _same_at_points(X22[1].subs(tt, 0), YA + rC * sp.cos(psi0), pts), True,
             "sympy: (22) at t = 0"))

    # ---- 3.2.1 rough ---------------------------------------------------------------------
    r_C_expr = -(w2 - ht * w3) * c / w3  # r_C = -v_Cx0 / Omega0, Omega0 = omega30 / cos
    add(_row("(26)", "r_C = (-omega20/omega30 + h~) cos th0 = r_P - y_P, r_P = -omega0/Omega0",
             "", _same_at_points(r_C_expr, (-w2 / w3 + ht) * c)
             and _same_at_points((r_C_expr + yP).subs(Omega_from), -w / W), True,
             "sympy from (24) with v_Cx0 = omega20 - h~ omega30 (no slip)"))
    add(_row("(27)", "F_y = -r_C Omega0^2", "",
             _same_at_points(F19[D.F_y].subs(vx, -rC * W),
                             -rC * W ** 2, pts), True,
             "sympy: the derived (19)_2 with v_Cx0 = -r_C Omega0 (24); numerically "
             "contact_force() agrees (tests/test_steady.py::test_circle_from_Omega0_is_steady)"))
    e28 = (((R(1, 4) + R(4, 3) * h ** 2) * p + ht) * w3 ** 2 - (R(3, 2) + ht * p) * w2 * w3
           - (s - ht * c))
    add(_row("(28)", "[(1/4 + 4h^2/3) tan th0 + h~] omega30^2 - (3/2 + h~ tan th0) omega20 "
             "omega30 = sin th0 - h~ cos th0", "", proportional(e28, R_["cond"]), True,
             "sympy: proportional to d omega1/dt of eq. (38) at omega1 = 0 (factor "
             "-12/(15+16h^2))"))
    sin2, cos2 = 2 * s * c, c ** 2 - s ** 2
    e29 = (((R(5, 8) - R(2, 3) * h ** 2) * sin2 - ht * cos2) * W ** 2
           + (R(3, 2) * c + ht * s) * w * W + s - ht * c)
    add(_row("(29)", "[(5/8 - 2h^2/3) sin 2th0 - h~ cos 2th0] Omega0^2 + (3/2 cos th0 + h~ sin "
             "th0) omega0 Omega0 + sin th0 - h~ cos th0 = 0", "",
             proportional(e29, R_["cond"].subs(Omega_from)), True,
             "sympy: proportional to the derived steady condition with eq. (3)"))
    # SE tilt p = h~: omega20 from (28) and r_C
    se_pt = [{**pt, p: pt[h]} for pt in _POINTS]
    omega20_se = sp.solve(sp.Eq(R_["cond"].subs(p, ht), 0), w2)[0]
    rC_se = (-omega20_se / w3 + ht) * c.subs(p, ht)
    e30 = ht / 6 * (3 - 4 * h ** 2) / ((3 + 2 * h ** 2) * sp.sqrt(1 + h ** 2))
    add(_row("(30)", "omega0 = -r_P Omega0, r_C = r_P = h~ (3 - 4h^2) / (6 (3 + 2h^2) "
             "sqrt(1+h^2))", "", _same_at_points(rC_se, e30, se_pt), True,
             "sympy: SE tilt (y_P0 = 0) in the derived condition; any Omega0"))
    rsign = se_circle_radius(2.0)
    add({"equation": "text after (30)", "status": "misprint",
         "printed": "when h > sqrt(3)/2 then r_C > 0 so the disk leans outward",
         "correct": "when h > sqrt(3)/2 then r_C < 0 so the disk leans outward",
         "evidence": f"(30) has the sign of 3 - 4h^2; e.g. h = 2: r_C = {rsign:.4f}"})
    from scipy.optimize import minimize_scalar

    opt = minimize_scalar(lambda x: -se_circle_radius(x), bounds=(0, math.sqrt(3) / 2),
                          method="bounded", options={"xatol": 1e-12})
    hm, rm = opt.x, -opt.fun
    add(_num_row("text after (30)", "max r_C ~ 0.0442", rm, 0.0442, 5e-5,
                 "max of (30) over h < sqrt(3)/2"))
    add(_num_row("text after (30)", "at h = sqrt(33 sqrt93 - 231)/22 ~ 0.425", hm,
                 math.sqrt(33 * math.sqrt(93) - 231) / 22, 1e-7, "maximizing h"))
    add(_num_row("text after (30)", "at theta0 ~ 23 deg", math.degrees(math.atan(hm)), 23.0,
                 0.05, "arctan of the maximizing h [deg]"))
    add(_num_row("text after (30)", "r_C -> -1/3 as h -> inf", se_circle_radius(1e8), -1 / 3,
                 1e-6, "(30) at h = 1e8"))
    add(_num_row("text after (30)", "spin in place (r_C = r_P = 0) for h = sqrt(3)/2 ~ 0.866, "
                 "theta0 ~ 0.714 ~ 40.893 deg", math.degrees(math.atan(math.sqrt(3) / 2)),
                 40.893, 5e-4, "arctan(sqrt(3)/2) [deg]"))
    # (31): Omega0^2 given r_C from (26), (28)
    cond_rC = R_["cond"].subs(w2, ht * w3 - rC * w3 / c).subs(w3, W * c)
    Xp = sp.Symbol("X", positive=True)  # X = Omega0^2
    Om2 = sp.solve(sp.Eq(cond_rC.subs(W, sp.sqrt(Xp)), 0), Xp)[0]
    p31a = (p - ht) / (c * ((R(1, 4) + h ** 2 / 3) * p - ht) + (R(3, 2) + ht * p) * rC)
    c31a = (p - ht) / (c * ((R(1, 4) + h ** 2 / 3) * p - ht / 2) + (R(3, 2) + ht * p) * rC)
    p31b = (s - ht * c) / ((R(3, 2) * c + ht * s) * rP - (R(5, 8) - R(2, 3) * h ** 2) * sin2
                           + ht * cos2)
    add(_row("(31) first form", "Omega0^2 = (tan th0 - h~) / (cos th0 [(1/4 + h^2/3) tan th0 "
             "- h~] + (3/2 + h~ tan th0) r_C)",
             "Omega0^2 = (tan th0 - h~) / (cos th0 [(1/4 + h^2/3) tan th0 - h~/2] + "
             "(3/2 + h~ tan th0) r_C)", _same_at_points(p31a, Om2), _same_at_points(c31a, Om2),
             "sympy: Omega0^2 solved from the derived condition with omega20 = h~ omega30 - "
             "r_C Omega0; the printed first form is inconsistent with the paper's own (32) and "
             "with its second form"))
    add(_row("(31) second form", "Omega0^2 = (sin th0 - h~ cos th0) / ((3/2 cos th0 + h~ sin "
             "th0) r_P - (5/8 - 2h^2/3) sin 2th0 + h~ cos 2th0)", "",
             _same_at_points(p31b, Om2.subs(rC, rP - yP)), True, "sympy, with r_C = r_P - y_P0"))
    rstar = -c * ((3 + 4 * h ** 2) * p - 6 * ht) / (6 * (3 + 2 * ht * p))
    den_zero = sp.solve(sp.Eq(sp.denom(sp.together(Om2)), 0), rC)
    add(_row("(32)", "r_C* = -cos th0 [(3 + 4h^2) tan th0 - 6h] / (6 (3 + 2h tan th0))", "",
             bool(den_zero) and _same_at_points(rstar, den_zero[0]), True,
             "sympy: zero of the denominator of the derived Omega0^2; h means h~"))
    tt = np.linspace(1e-9, math.pi / 2 - 1e-12, 400001)
    add(_num_row("text after (32)", "max r_C* = h/3 at theta0 = 0", float(r_C_star(0.7, 0.0)),
                 0.7 / 3, 1e-12, "h = 0.7, and r_C*(0.7, theta0) <= h/3 on a grid: "
                 f"{bool(np.all(r_C_star(0.7, tt) <= 0.7 / 3 + 1e-15))}"))
    add(_num_row("text after (32)", "h = 0: min r_C* = -1/6 at theta0 = pi/2",
                 float(np.min(r_C_star(0.0, tt))), -1 / 6, 1e-9, "grid minimum"))
    add(_num_row("text after (32)", "zeros of r_C* at arctan(6h/(3+4h^2)) and pi/2",
                 float(r_C_star(0.7, math.atan(6 * 0.7 / (3 + 4 * 0.49)))), 0.0, 1e-15,
                 "r_C* at h = 0.7, theta0 = arctan(6h/(3+4h^2))"))
    add(_num_row("text after (32)", "min r_C* -> -h/3 for great h",
                 float(np.min(r_C_star(1e6, tt))) / (-1e6 / 3), 1.0, 1e-3,
                 "ratio min r_C* / (-h/3) at h = 1e6 (0.867 at h = 100; slow approach)"))
    p33 = 12 * (p - ht) / ((3 + 4 * h ** 2) * s - 12 * ht * c)
    c33 = 12 * (p - ht) / ((3 + 4 * h ** 2) * s - 6 * ht * c)
    add(_row("(33)", "Omega0^2 = 12 (tan th0 - h~) / ((3 + 4h^2) sin th0 - 12 h~ cos th0)",
             "Omega0^2 = 12 (tan th0 - h~) / ((3 + 4h^2) sin th0 - 6 h~ cos th0)",
             _same_at_points(p33, Om2.subs(rC, 0)), _same_at_points(c33, Om2.subs(rC, 0)),
             "sympy: derived Omega0^2 at r_C = 0; also (32) and the next sentence of the paper "
             "(6h/(3+4h^2)) need 6h~; at h = 0.3, theta0 = 1 the corrected Omega0^2 (off the "
             "printed one by > 0.1) gives a steady state of the equations of motion "
             "(tests/test_steady.py::test_rough_rC_zero_uses_corrected_eq33)"))
    add({"equation": "text after (33)", "status": "misprint",
         "printed": "for tan th0 < h also tan th0 < 12h/(3+4h^2) and for tan th0 > h also "
                    "tan th0 > 12h/(3+4h^2)",
         "correct": "... 6h/(3+4h^2) (both places)",
         "evidence": "follows from the corrected (33); the paper's next sentence already uses "
                     "6h/(3+4h^2), which is right"})
    add(_row("text after (33)", "Omega0^2 ~ 12 tan th0/(3+4h^2) (r_C = 0); Omega0^2 -> "
             "1/(h r_C) (r_C != 0) as th0 -> pi/2", "",
             sp.limit((c33 / (12 * p / (3 + 4 * h ** 2))).subs(h, R(3, 10)), p, sp.oo) == 1
             and sp.limit(Om2.subs({h: R(3, 10), rC: R(1, 2)}), p, sp.oo) == R(20, 3), True,
             "sympy limits at h = 0.3, r_C = 0.5"))

    # ---- 3.1.2 smooth ----------------------------------------------------------------------
    e34 = (R(1, 4) + h ** 2 / 3) * p * w3 ** 2 - R(1, 2) * w2 * w3 - (s - ht * c)
    add(_row("(34)", "(1/4 + h^2/3) tan th0 omega30^2 - 1/2 omega20 omega30 = sin th0 - h~ cos "
             "th0", "", proportional(e34, S_["cond"]), True,
             "sympy: proportional to d omega1/dt of eq. (49) at omega1 = 0"))
    e35 = (R(1, 4) - h ** 2 / 3) * W ** 2 * s + R(1, 2) * w * W + p - ht
    add(_row("(35)", "(1/4 - h^2/3) Omega0^2 sin th0 + 1/2 omega0 Omega0 + tan th0 - h~ = 0",
             "", proportional(e35, S_["cond"].subs(Omega_from)), True,
             "sympy, with eq. (3)"))
    om_spin = sp.solve(sp.Eq(e35.subs(p, ht), 0), w)[0]
    add(_row("text after (35)", "SE spin: omega0 = -(1/2 - 2h^2/3) Omega0 sin th0", "",
             _same_at_points(om_spin, -(R(1, 2) - 2 * h ** 2 / 3) * W * s.subs(p, ht), se_pt), True,
             "sympy from (35) at tan th0 = h"))

    # ---- section 4 --------------------------------------------------------------------------
    add(_row("(36)", "theta = theta0 + theta~, omega_k = omega_k0 + omega~_k", "", True, True,
             "definitions of the perturbations (nothing to check).  (37), (38) and (49) are "
             "checked with section 2 (rollingdisk.symbolic.paper); all rows below start from "
             "the derivation"))
    a2p = -(12 * ht * w2 + 2 * (3 + 4 * h ** 2) * w3) / (3 * (3 + 8 * h ** 2))
    a3p = -6 * w2 / (3 + 8 * h ** 2) + (p + 4 * ht / (3 + 8 * h ** 2)) * w3
    add(_row("(39)", "theta~'' + varpi^2 theta~ = 0; omega~2' = -(12 h~ omega20 + 2(3+4h^2) "
             "omega30)/(3(3+8h^2)) omega~1; omega~3' = [...] omega~1", "",
             _same_at_points(a2p, R_["a2"]) and _same_at_points(a3p, R_["a3"]), True,
             "sympy: d(omega2', omega3')/d omega1 at the steady state.  Strictly, "
             "theta~'' + varpi^2 theta~ = const (the constant shifts the centre of the "
             "oscillation to a neighbouring steady motion)"))
    P22 = 36 * (3 + 2 * ht * p)
    P23 = -6 * (4 * ht * (3 + 8 * h ** 2) * p ** 2 + (15 + 56 * h ** 2) * p
                + 2 * ht * (15 + 8 * h ** 2))
    P33 = (3 * (3 + 16 * h ** 2) * (3 + 8 * h ** 2) * p ** 2 + 8 * ht * (15 + 44 * h ** 2) * p
           + 45 + 216 * h ** 2 + 128 * h ** 4)
    e40 = (((P22 * w2 ** 2 + P23 * w2 * w3 + P33 * w3 ** 2) * sq
            - 12 * (3 + 8 * h ** 2) * (1 + ht * p))
           / ((3 + 8 * h ** 2) * (15 + 16 * h ** 2) * sq))
    add(_row("(40)-(41)", "varpi^2 = ((P22 w20^2 + P23 w20 w30 + P33 w30^2) sqrt(1+p0^2) - "
             "12(3+8h^2)(1+h~p0)) / ((3+8h^2)(15+16h^2) sqrt(1+p0^2))", "",
             _same_at_points(e40, R_["varpi2"]), True,
             "sympy: identical to the derived linearization for all omega20, omega30; "
             "numerically agrees with the Jacobian of the library's equations to ~1e-12"))
    vsl = R_["varpi2"].subs({w3: 0, p: ht})
    t42 = (3 + 8 * h ** 2) * sp.sqrt(1 + h ** 2) / (3 * (3 + 2 * h ** 2))
    add(_row("(42)", "omega20^2 > (3+8h^2) sqrt(1+h^2) / (3 (3+2h^2))", "",
             _threshold(vsl, w2, t42), True,
             "sympy: the derived varpi^2 at omega30 = 0, tan th0 = h vanishes at the printed "
             "omega20^2 and is negative below / positive above it; h = 0 gives 1/3 (quoted, "
             "confirmed)"))
    vse = R_["varpi2_circle"].subs(p, ht)
    t43 = 12 * sp.sqrt(1 + h ** 2) / ((1 + h ** 2) * (15 + 16 * h ** 2))
    add(_row("(43)", "omega30^2 > 12 sqrt(1+h^2) / ((1+h^2)(15+16h^2))", "",
             _threshold(vse, w3, t43), True,
             "sympy, as for (42); an odd but correct form of 12/((15+16h^2) sqrt(1+h^2)); "
             "h = 0: 4/5 and h = sqrt(3)/2: |omega30| > sqrt(8 sqrt7/63) = 0.5796 (quoted "
             "0.580, confirmed)"))
    p44 = (((3 + 4 * h ** 2) * p + 12 * ht) / (6 * (3 + 2 * ht * p)) * w3
           - 2 * (p - ht) / ((3 + 2 * ht * p) * sq) / w3)
    c44 = (((3 + 16 * h ** 2) * p + 12 * ht) / (6 * (3 + 2 * ht * p)) * w3
           - 2 * (p - ht) / ((3 + 2 * ht * p) * sq) / w3)
    add(_row("(44)", "omega20 = [(3+4h^2) p0 + 12h~] / (6(3+2h~p0)) omega30 - 2 (p0-h~) / "
             "((3+2h~p0) sqrt(1+p0^2)) / omega30",
             "omega20 = [(3+16h^2) p0 + 12h~] / (6(3+2h~p0)) omega30 - ...",
             _same_at_points(p44, R_["omega20"]), _same_at_points(c44, R_["omega20"]),
             "sympy: solving the paper's own (28) (coefficient 1/4 + 4h^2/3 = (3+16h^2)/12); "
             "(45) as printed (P1, P2) follows from the correct form"))
    q = 1 + p ** 2
    P0p = 144 * (p - ht) ** 2
    P0c = 144 * (p - ht) ** 2 * sq
    P1 = -12 * (3 + 8 * h ** 2) * q * (3 + 2 * h ** 2 + 6 * ht * p - (3 - 6 * h ** 2) * p ** 2
                                       - 4 * ht * p ** 3)
    P2 = (3 + 8 * h ** 2) * q * sq * (45 + 24 * h ** 2 + 84 * ht * p + (15 + 104 * h ** 2)
                                      * p ** 2 + 2 * ht * (3 + 16 * h ** 2) * p ** 3)
    den45 = (3 + 8 * h ** 2) * (15 + 16 * h ** 2) * q * sq * (3 + 2 * ht * p) * w3 ** 2
    add(_row("(45)", "P0 = 144 (p0 - h~)^2",
             "P0 = 144 (p0 - h~)^2 sqrt(1 + p0^2)  (P1, P2 and the denominator as printed)",
             _same_at_points((P2 * w3 ** 4 + P1 * w3 ** 2 + P0p) / den45, R_["varpi2_circle"]),
             _same_at_points((P2 * w3 ** 4 + P1 * w3 ** 2 + P0c) / den45, R_["varpi2_circle"]),
             "sympy: derived varpi^2 with (44) substituted.  The paper's own 18.6 deg needs "
             "the corrected P0: with the printed P0 the h = 0 boundary would be at "
             f"{math.degrees(_printed_P0_boundary()):.2f} deg; linearization agrees with the "
             "corrected form to ~1e-12"))
    theta186 = _boundary("rough", 0.0)
    add(_row("(46)", "P2 w^4 + P1 w^2 + P0 > 0; for all omega30 iff P1 > 0 or Delta < 0", "",
             True, True, "with the corrected P0; the region test agrees with an independent "
             "finite-difference linearization scanned over omega30 "
             "(tests/test_stability.py::test_stable_for_all_omega30_regions)"))
    add(_num_row("text after (46)", "h = 0: theta0 ~ 0.325 = 18.6 deg",
                 math.degrees(theta186), 18.6, 0.05, "boundary of P1 > 0 or Delta < 0 [deg]"))
    add(_num_row("text after (46)", "tan theta0 = sqrt(198 sqrt5 - 429)/11", math.tan(theta186),
                 math.sqrt(198 * math.sqrt(5) - 429) / 11, 1e-10, "tan of the boundary"))
    add(_num_row("text after (46)", "great h: theta0 > arctan(3h/2)",
                 math.tan(_right_boundary("rough", 1e4)) / 1e4, 1.5, 1e-3,
                 "tan(right boundary)/h at h = 1e4"))
    add(_row("(47)", "varpi^2 = 12 (R2 r_C^2 + R1 r_C + R0) / (Q1 r_C + Q0)", "", True, True,
             "form confirmed: omega30^2 = Omega0^2 cos^2 th0 with the corrected (31) is 1/linear "
             "in r_C, so (45) becomes quadratic/linear (R, Q not printed); the library's "
             "varpi2_rough_rC agrees with the linearization "
             "(tests/test_stability.py::test_rC_route_agrees)"))
    lim = varpi2_circle(1e6, "rough", 0.0, 1.3)
    add(_num_row("text before Fig. 6", "theta0 = 0, h -> inf: varpi^2 -> (omega30^2 - 1)/2",
                 float(lim) / (0.5 * (1.3 ** 2 - 1)), 1.0, 1e-5, "ratio at h = 1e6, omega30 = 1.3"))
    sup_r = _sup_critical("rough", critical_omega30_sq)
    add(_num_row("text before Fig. 6 / Conclusion", "rough: stable for any h, theta0 if "
                 "omega30^2 > 1", sup_r, 1.0, 1e-3,
                 "sup of the varpi^2 = 0 surface over h in [0, 1e4], theta0 in (0, pi/2) "
                 "(approached as h -> inf at theta0 -> 0)"))
    a48 = float(varpi2_circle(2.0, "rough", math.pi / 2 - 1e-7, 0.7)) / (
        0.49 * math.tan(math.pi / 2 - 1e-7) ** 2)
    add({"equation": "(48)", "status": "misprint" if abs(a48 - 2 * 35 / 79) > 1e-2 else
         "confirmed",
         "printed": "varpi^2 ~ 2 omega30^2 (3+16h^2)/(15+16h^2) tan^2 th0",
         "correct": "varpi^2 ~ omega30^2 (3+16h^2)/(15+16h^2) tan^2 th0 for h > 0 "
                    "(omega30^2 tan^2 th0 / 3 for h = 0)",
         "evidence": f"leading terms of (45) as p0 -> inf: P2 ~ 2h(3+8h^2)(3+16h^2) p0^6, "
                     f"den ~ 2h(3+8h^2)(15+16h^2) p0^4 omega30^2; numerically at h = 2 the "
                     f"ratio is {a48:.4f} vs (3+16h^2)/(15+16h^2) = {67 / 79:.4f}, printed "
                     f"{2 * 67 / 79:.4f}"})

    # ---- 4.2 smooth -------------------------------------------------------------------------
    add(_row("(50)", "omega~2' = 0, omega~3' = (-6 omega20/(3+4h^2) + tan th0 omega30) "
             "omega~1", "", _same_at_points(-6 * w2 / (3 + 4 * h ** 2) + p * w3, S_["a3"]), True,
             "sympy"))
    a = 3 + 4 * h ** 2
    Q = 3 + 16 * h ** 2 - 24 * ht * p + (15 + 4 * h ** 2) * p ** 2
    e51 = (q * (36 * w2 ** 2 - 18 * a * p * w2 * w3 + a ** 2 * (1 + 3 * p ** 2) * w3 ** 2)
           / (a * Q) - 12 * (1 + ht * p) * sq / Q)
    add(_row("(51)", "varpi^2 = (1+p0^2)[36 w20^2 - 18(3+4h^2) p0 w20 w30 + (3+4h^2)^2 "
             "(1+3p0^2) w30^2] / ((3+4h^2) Q) - 12 (1+h~p0) sqrt(1+p0^2)/Q", "",
             _same_at_points(e51.subs(w2, S_["omega20"]), S_["varpi2_circle"]), True,
             "sympy: equal to the derived varpi^2 on the steady manifold (34) (it was "
             "simplified with (34); off the manifold the two differ, which is immaterial)"))
    e52 = 36 / a ** 2 * w2 ** 2 - 12 * sp.sqrt(1 + h ** 2) / a
    add(_row("(52)", "varpi^2 = 36 omega20^2/(3+4h^2)^2 - 12 sqrt(1+h^2)/(3+4h^2)", "",
             _same_at_points(e52, S_["varpi2"].subs({w3: 0, p: ht}), se_pt), True, "sympy"))
    t53 = a * sp.sqrt(1 + h ** 2) / 3
    add(_row("(53)", "omega20^2 > (3+4h^2) sqrt(1+h^2)/3", "",
             _threshold(S_["varpi2"].subs({w3: 0, p: ht}), w2, t53), True,
             "sympy: the derived varpi^2 at omega30 = 0, tan th0 = h vanishes at the printed "
             "omega20^2 and is negative below / positive above it; h = 0 gives 1 (quoted, "
             "confirmed)"))
    e54 = (R(1, 2) + 2 * h ** 2 / 3) * p * w3 - 2 * (p - ht) / sq / w3
    add(_row("(54)", "omega20 = (1/2 + 2h^2/3) p0 omega30 - 2 (p0-h~)/sqrt(1+p0^2)/omega30", "",
             _same_at_points(e54, S_["omega20"]), True, "sympy from (34)"))
    sP0 = 144 * (p - ht) ** 2
    sP1 = -12 * a * (1 + 2 * ht * p - p ** 2) * sq
    sP2 = a ** 2 * q ** 2
    e55 = (sP2 * w3 ** 4 + sP1 * w3 ** 2 + sP0) / (a * Q * w3 ** 2)
    add(_row("(55)-(56)", "varpi^2 = (P2 w^4 + P1 w^2 + P0)/((3+4h^2) Q w^2), P0 = 144(p0-h~)^2,"
             " P1 = -12(3+4h^2)(1+2h~p0-p0^2) sqrt(1+p0^2), P2 = (3+4h^2)^2 (1+p0^2)^2", "",
             _same_at_points(e55, S_["varpi2_circle"]), True, "sympy; Q > 0 (discriminant "
             "-4(45 + 108h^2 + 64h^4) < 0), as the paper states"))
    add(_row("(57)", "omega30^2 > 12/((3+4h^2) sqrt(1+h^2))", "",
             _threshold(S_["varpi2_circle"].subs(p, ht), w3,
                        12 / (a * sp.sqrt(1 + h ** 2))), True,
             "sympy: the derived varpi^2 at tan th0 = h changes sign there; h = 0 gives 4 "
             "(quoted, confirmed)"))
    disc_Q = sp.discriminant(sp.expand(Q), p)
    add(_row("(58)", "P2 w^4 + P1 w^2 + P0 > 0", "",
             _same_at_points(disc_Q, -4 * (45 + 108 * h ** 2 + 64 * h ** 4))
             and _same_at_points(sp.Poly(Q, p).LC(), 15 + 4 * h ** 2), True,
             "sympy: Q has discriminant -4(45 + 108h^2 + 64h^4) < 0 and leading coefficient "
             "15 + 4h^2 > 0, so Q > 0 and the denominator of (55) is positive: varpi^2 > 0 "
             "iff (58)"))
    e59 = 3 * p ** 4 - 4 * ht * p ** 3 + 6 * p ** 2 - 12 * ht * p - 1 + 4 * h ** 2
    add(_row("(59)", "3p0^4 - 4h p0^3 + 6p0^2 - 12h~p0 - 1 + 4h^2 > 0", "",
             _same_at_points(-(sP1 ** 2 - 4 * sP0 * sP2) / (144 * a ** 2 * q), e59), True,
             "sympy: -Delta/(144 (3+4h^2)^2 (1+p0^2)); the printed 'h' in 4h p0^3 is h~ "
             "(the same for theta0 > 0)"))
    t215 = _boundary("smooth", 0.0)
    _, hi215 = critical_omega30_sq(0.0, "smooth", t215 - 1e-9)
    add(_num_row("text after (59)", "great h: theta0 > arctan(4h/3)",
                 math.tan(_right_boundary("smooth", 1e4)) / 1e4, 4 / 3, 1e-3,
                 "tan(right boundary)/h at h = 1e4"))
    add(_num_row("text after (59)", "h = 0: theta0 ~ 0.375 ~ 21.5 deg", math.degrees(t215),
                 21.5, 0.05, "boundary of (59) [deg]"))
    add(_num_row("text after (59)", "tan theta0 = sqrt(6 sqrt3 - 9)/3", math.tan(t215),
                 math.sqrt(6 * math.sqrt(3) - 9) / 3, 1e-10, "tan of the boundary"))
    add(_num_row("text after (59)", "limit omega30 ~ 1.167", math.sqrt(float(hi215)), 1.167,
                 5e-4, "double root of (58) at the boundary"))
    _, hi0 = critical_omega30_sq(0.0, "smooth", 0.0)
    _, hih = critical_omega30_sq(0.5, "smooth", 0.0)
    add(_num_row("text before Conclusion", "theta0 = 0, h = 0: omega30 = 2",
                 math.sqrt(float(hi0)), 2.0, 1e-9, "varpi^2 = 0 surface at theta0 -> 0+"))
    add(_num_row("text before Conclusion", "theta0 = 0: h limited to 1/2 with omega30 = "
                 "sqrt(3/2) ~ 1.225", math.sqrt(float(hih)), math.sqrt(1.5), 1e-9,
                 "double root at h = 1/2, theta0 -> 0+ (no real root for h > 1/2: "
                 f"{bool(np.isnan(critical_omega30_sq(0.51, 'smooth', 0.0)[1]))})"))
    sup_s = _sup_critical("smooth", critical_omega30_sq)
    add({"equation": "text before Conclusion / Conclusion", "status": "misprint",
         "printed": "smooth: stable for any h and theta0 if omega30^2 > 2",
         "correct": "smooth: stable for any h and theta0 if omega30^2 > 4 (sharp; "
                    "the bound needed exceeds 2 for every h < 0.948)",
         "evidence": f"sup of the varpi^2 = 0 surface = {sup_s:.6f}, reached at h = 0, "
                     "theta0 -> 0 (the paper's own (57) at h = 0 says omega30^2 > 4); "
                     "counterexample h = 0.1, theta0 = 3 deg, omega30^2 = 3: varpi^2 < 0, "
                     "confirmed by linearization and by simulation "
                     "(tests/test_paper_numbers.py::"
                     "test_conclusion_smooth_omega30_sq_above_2_is_wrong)"})
    assert sup_s > 2.0
    del P0c, circle_coefficients
    return rows


def _threshold(expr, var, thr) -> bool:
    """``expr`` (no p0) vanishes at ``var = sqrt(thr)``, < 0 just below, > 0 just above."""
    import mpmath

    syms = sorted(expr.free_symbols - {var}, key=str)
    f_expr = sp.lambdify([var, *syms], expr, "mpmath")
    f_thr = _evaluator(thr)
    for pt in _POINTS:
        with mpmath.workdps(50):
            args = [mpmath.mpf(sp.Rational(pt[x]).p) / sp.Rational(pt[x]).q for x in syms]
            t = f_thr(pt)
            vals = [f_expr(mpmath.sqrt(f * t), *args) for f in (1, mpmath.mpf(9) / 10,
                                                                mpmath.mpf(11) / 10)]
            if not (abs(vals[0]) < 1e-25 * (1 + abs(vals[1])) and vals[1] < 0 < vals[2]):
                return False
    return True


def _printed_P0_boundary() -> float:
    """h = 0 rough boundary of 'P1 > 0 or Delta < 0' with the printed P0 = 144 p0^2."""
    from scipy.optimize import brentq

    from .._stability import circle_coefficients

    def f(t):
        P0, P1, P2, _ = circle_coefficients(0.0, "rough", t)
        P0 = P0 / math.sqrt(1 + math.tan(t) ** 2)  # undo the correction
        return float((P1 >= 0) or (P1 * P1 - 4 * P0 * P2 < 0)) - 0.5

    return brentq(f, 0.05, 0.7, xtol=1e-15)


def _boundary(ground: str, h: float) -> float:
    from scipy.optimize import brentq

    from .._stability import stable_for_all_omega30

    return brentq(lambda t: float(stable_for_all_omega30(h, ground, t)) - 0.5, 0.05, 0.7,
                  xtol=1e-15)


def _right_boundary(ground: str, h: float) -> float:
    import numpy as np
    from scipy.optimize import brentq

    from .._stability import stable_for_all_omega30

    th = np.linspace(1e-6, math.pi / 2 - 1e-10, 100001)
    ok = stable_for_all_omega30(h, ground, th)
    i = int(np.nonzero(~ok)[0].max())
    return brentq(lambda t: float(stable_for_all_omega30(h, ground, t)) - 0.5, th[i],
                  th[i + 1], xtol=1e-15)


def _sup_critical(ground: str, critical: Callable) -> float:
    import numpy as np

    H = np.concatenate([np.linspace(0, 5, 501), np.geomspace(5, 1e4, 200)])[:, None]
    T = np.concatenate([[0.0], np.linspace(1e-4, math.pi / 2 - 1e-4, 1500)])[None, :]
    _, hi = critical(H, ground, T)
    return float(np.nanmax(hi))


def format_rows(rows) -> str:
    """A markdown table of the rows."""
    out = ["| Equation | Status | Printed | Correct | Evidence |", "|---|---|---|---|---|"]
    for r in rows:
        cells = [r["equation"], r["status"], r["printed"],
                 r["correct"] if r["status"] != "confirmed" else "(as printed)", r["evidence"]]
        out.append("| " + " | ".join(str(x).replace("|", "\\|") for x in cells) + " |")
    return "\n".join(out)


#: docs/errata.md holds, after this line, the generated part for sections 3-4.
MARKER = ("<!-- generated below by: "
          "python -m rollingdisk.symbolic.sections34 --write docs/errata.md -->")

HEADER = """## Sections 3 and 4: steady motions and their stability

Every row is recomputed by the test suite (`tests/test_sections34.py`), which also fails when
this part of the file is out of date.  Each printed equation is compared with the one
re-derived with sympy from the Newton-Euler derivation: the kinematics (15)-(25) from its frame
rates, contact point and balances at a constant state, the rest from its reduced equations
(random-point identity test at 40 digits; conditions up to a factor of h, p0 only).  (37),
(38) and (49) are in the section 2 table above.  Each quoted number is recomputed with the
library, whose closed forms are checked against a numerical linearization of the equations of
motion (agreement ~1e-12) and against direct simulation (tests/test_stability.py,
tests/test_simulate.py).
`th0` = theta0, `p0` = tan(theta0), `h~` = h sgn(theta0), `w` = omega30.

Summary of misprints: the first form of (31) and (33) (factor 2 on the h~ term, also in the
prose after (33)); the sign in the prose after (30); (44) (3+4h^2 for 3+16h^2); P0 of (45)
(missing sqrt(1+p0^2)); the asymptote (48) (spurious factor 2); and the smooth-ground
conclusion (omega30^2 > 2 must read omega30^2 > 4).  The library uses the corrected forms.
"""


def errata_markdown(rows=None) -> str:
    """The generated part of docs/errata.md, after :data:`MARKER` (from ``rows`` or afresh)."""
    return HEADER + "\n" + format_rows(rows or checks_sections_3_4()) + "\n"


def write_errata(path) -> None:
    """Replace everything after :data:`MARKER` in the file ``path`` by :func:`errata_markdown`."""
    from pathlib import Path

    path = Path(path)
    text = path.read_text()
    if MARKER not in text:
        raise ValueError(f"{path} has no line {MARKER!r}")
    head = text[: text.index(MARKER) + len(MARKER)]
    path.write_text(head + "\n\n" + errata_markdown())


if __name__ == "__main__":  # pragma: no cover
    import sys

    if sys.argv[1:2] == ["--write"] and len(sys.argv) == 3:
        write_errata(sys.argv[2])
    else:
        print(errata_markdown(), end="")
