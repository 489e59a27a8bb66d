"""The paper's printed statements of sections 3-4, typed in once: :data:`PRINTED`.

Each entry is a :class:`~rollingdisk.symbolic.rows.Printed`: the row label, the text as printed
(ASCII), the form a check compares (sympy, in the symbols below, or the quoted number) and,
where the paper is wrong, the correction.  Only :mod:`.sections34` reads this table, to compare
it with the derivation; the library never uses it.  (Section 2 and eqs. (37), (38), (49) are
typed in :mod:`.paper`.)

``theta0`` is taken in ``(0, pi/2)`` (so ``h~ = h``) and written through ``p0 = tan(theta0)``.
"""

from __future__ import annotations

import math

import sympy as sp

from .rows import Printed

__all__ = ["PRINTED"]

h, p, w1, w2, w3, W, w, rC, rP = sp.symbols(
    "h p0 omega1 omega20 omega30 Omega0 omega0 r_C r_P", real=True)
vx, vy, Fy, tt, psi0, XA, YA, XC0, YC0 = sp.symbols(
    "v_Cx0 v_Cy0 F_y t psi0 X_A Y_A X_C0 Y_C0", real=True)
R = sp.Rational
ht = h  # h~ = h sgn(theta0), theta0 > 0
sq = sp.sqrt(1 + p ** 2)
q = 1 + p ** 2
s, c = p / sq, 1 / sq  # sin, cos of theta0
sin2, cos2 = 2 * s * c, c ** 2 - s ** 2
k1, k2 = R(1, 4) + h ** 2 / 3, R(1, 2)  # printed (10)
yP, zP = s - ht * c, -(c + ht * s)  # printed (16)
psi_t = psi0 + W * tt  # printed (15)
a3, a8, a16 = 3 + 4 * h ** 2, 3 + 8 * h ** 2, 15 + 16 * h ** 2
Q = 3 + 16 * h ** 2 - 24 * ht * p + (15 + 4 * h ** 2) * p ** 2  # printed (55)
sP0 = 144 * (p - ht) ** 2  # printed (56)
sP1 = -12 * a3 * (1 + 2 * ht * p - p ** 2) * sq
sP2 = a3 ** 2 * q ** 2
# printed (45): P1, P2 and the denominator (P0 is the misprint, in the row)
P1 = -12 * a8 * q * (3 + 2 * h ** 2 + 6 * ht * p - (3 - 6 * h ** 2) * p ** 2 - 4 * ht * p ** 3)
P2 = a8 * q * sq * (45 + 24 * h ** 2 + 84 * ht * p + (15 + 104 * h ** 2) * p ** 2
                    + 2 * ht * (3 + 16 * h ** 2) * p ** 3)
den45 = a8 * a16 * q * sq * (3 + 2 * ht * p) * w3 ** 2
PP0, PP1, PP2 = sp.symbols("P0 P1 P2", real=True)  # the coefficients as symbols, for (46)


def _row(equation, text, form=None, correct="", correct_form=None) -> Printed:
    return Printed(equation, text, form, correct, correct_form)


_T30, _T32, _T33 = "text after (30)", "text after (32)", "text after (33)"
_T46, _T59, _TC = "text after (46)", "text after (59)", "text before Conclusion"

#: Key: a unique name of the statement (the row label, with a bracketed tag where a label has
#: several rows).  The order is the order of the errata table.
PRINTED: dict[str, Printed] = {
    # ---- section 3: kinematics of a steady motion
    "(15)": _row("(15)", "psi = psi0 + Omega0 t, phi = phi0 + omega0 t",
                 (W, 0, w)),  # (psi', theta', phi')
    "(16)": _row("(16)", "y_P0 = sin th0 - h~ cos th0, z_P0 = -(cos th0 + h~ sin th0)",
                 (yP, zP)),
    "(17)": _row("(17)", "X_P0 = X_C0 - y_P0 sin(psi0 + Omega0 t), Y_P0 = Y_C0 + y_P0 "
                 "cos(psi0 + Omega0 t)", (-yP * sp.sin(psi_t), yP * sp.cos(psi_t))),
    "(18)": _row("(18)", "v_Px0 = v_Cx0 - omega20 + h~ omega30 = v_Cx0 - omega0 - y_P0 "
                 "Omega0, v_Py0 = v_Cy0", (vx - w2 + ht * w3, vx - w - yP * W, vy)),
    "(19)": _row("(19)", "F_x = 0, F_y = v_Cx0 Omega0, F_z = 1", (0, vx * W, 1)),
    "(20)": _row("(20)", "v_Cy0 Omega0 = 0, (k2^2 omega20 - k1^2 omega30 tan th0) omega30 "
                 "- z_P0 F_y + y_P0 = 0",
                 (vy * W, (k2 * w2 - k1 * w3 * p) * w3 - zP * Fy + yP)),
    "(21)": _row("(21)", "X_C = X_C0 + (v_Cx0 cos psi0 - v_Cy0 sin psi0) t, Y_C = Y_C0 + "
                 "(v_Cx0 sin psi0 + v_Cy0 cos psi0) t",
                 (XC0 + (vx * sp.cos(psi0) - vy * sp.sin(psi0)) * tt,
                  YC0 + (vx * sp.sin(psi0) + vy * sp.cos(psi0)) * tt)),
    "(22)": _row("(22)", "X_C = X_A - r_C sin(psi0 + Omega0 t), Y_C = Y_A + r_C cos(psi0 + "
                 "Omega0 t)", (XA - rC * sp.sin(psi_t), YA + rC * sp.cos(psi_t))),
    "(23)": _row("(23)", "X_P = X_A - r_P sin(psi0 + Omega0 t), Y_P = Y_A + r_P cos(psi0 + "
                 "Omega0 t)", (XA - rP * sp.sin(psi_t), YA + rP * sp.cos(psi_t))),
    "(24)": _row("(24)", "r_C = -v_Cx0/Omega0, r_P = r_C + y_P0", (-vx / W, rC + yP)),
    "(25)": _row("(25)", "X_C0 = X_A - r_C sin psi0, Y_C0 = Y_A + r_C cos psi0",
                 (XA - rC * sp.sin(psi0), YA + rC * sp.cos(psi0))),
    # ---- 3.1.1 rough ground
    "(26)": _row("(26)", "r_C = (-omega20/omega30 + h~) cos th0 = r_P - y_P, r_P = "
                 "-omega0/Omega0", ((-w2 / w3 + ht) * c, -w / W)),
    "(27)": _row("(27)", "F_y = -r_C Omega0^2", -rC * W ** 2),
    "(28)": _row("(28)", "[(1/4 + 4h^2/3) tan th0 + h~] omega30^2 - (3/2 + h~ tan th0) "
                 "omega20 omega30 = sin th0 - h~ cos th0",
                 ((R(1, 4) + R(4, 3) * h ** 2) * p + ht) * w3 ** 2
                 - (R(3, 2) + ht * p) * w2 * w3 - (s - ht * c)),
    "(29)": _row("(29)", "[(5/8 - 2h^2/3) sin 2th0 - h~ cos 2th0] Omega0^2 + (3/2 cos th0 + "
                 "h~ sin th0) omega0 Omega0 + sin th0 - h~ cos th0 = 0",
                 ((R(5, 8) - R(2, 3) * h ** 2) * sin2 - ht * cos2) * W ** 2
                 + (R(3, 2) * c + ht * s) * w * W + s - ht * c),
    "(30)": _row("(30)", "omega0 = -r_P Omega0, r_C = r_P = h~ (3 - 4h^2) / (6 (3 + 2h^2) "
                 "sqrt(1+h^2))", ht / 6 * (3 - 4 * h ** 2) / ((3 + 2 * h ** 2)
                                                               * sp.sqrt(1 + h ** 2))),
    "text after (30) [sign]": _row(
        _T30, "when h > sqrt(3)/2 then r_C > 0 so the disk leans outward", 1,
        "when h > sqrt(3)/2 then r_C < 0 so the disk leans outward", -1),  # the sign of r_C
    "text after (30) [max]": _row(_T30, "max r_C ~ 0.0442", 0.0442),
    "text after (30) [argmax]": _row(_T30, "at h = sqrt(33 sqrt93 - 231)/22 ~ 0.425",
                                     math.sqrt(33 * math.sqrt(93) - 231) / 22),
    "text after (30) [theta0]": _row(_T30, "at theta0 ~ 23 deg", 23.0),
    "text after (30) [limit]": _row(_T30, "r_C -> -1/3 as h -> inf", -1 / 3),
    "text after (30) [spin]": _row(_T30, "spin in place (r_C = r_P = 0) for h = sqrt(3)/2 ~ "
                                   "0.866, theta0 ~ 0.714 ~ 40.893 deg", 40.893),
    "(31) first form": _row(
        "(31) first form", "Omega0^2 = (tan th0 - h~) / (cos th0 [(1/4 + h^2/3) tan th0 - h~] "
        "+ (3/2 + h~ tan th0) r_C)",
        (p - ht) / (c * ((R(1, 4) + h ** 2 / 3) * p - ht) + (R(3, 2) + ht * p) * rC),
        "Omega0^2 = (tan th0 - h~) / (cos th0 [(1/4 + h^2/3) tan th0 - h~/2] + (3/2 + h~ "
        "tan th0) r_C)",
        (p - ht) / (c * ((R(1, 4) + h ** 2 / 3) * p - ht / 2) + (R(3, 2) + ht * p) * rC)),
    "(31) second form": _row(
        "(31) second form", "Omega0^2 = (sin th0 - h~ cos th0) / ((3/2 cos th0 + h~ sin th0) "
        "r_P - (5/8 - 2h^2/3) sin 2th0 + h~ cos 2th0)",
        (s - ht * c) / ((R(3, 2) * c + ht * s) * rP - (R(5, 8) - R(2, 3) * h ** 2) * sin2
                        + ht * cos2)),
    "(32)": _row("(32)", "r_C* = -cos th0 [(3 + 4h^2) tan th0 - 6h] / (6 (3 + 2h tan th0))",
                 -c * (a3 * p - 6 * ht) / (6 * (3 + 2 * ht * p))),
    "text after (32) [max]": _row(_T32, "max r_C* = h/3 at theta0 = 0", h / 3),
    "text after (32) [min]": _row(_T32, "h = 0: min r_C* = -1/6 at theta0 = pi/2", -1 / 6),
    "text after (32) [zeros]": _row(_T32, "zeros of r_C* at arctan(6h/(3+4h^2)) and pi/2",
                                    sp.atan(6 * h / a3)),
    "text after (32) [great h]": _row(_T32, "min r_C* -> -h/3 for great h", -h / 3),
    "(33)": _row("(33)", "Omega0^2 = 12 (tan th0 - h~) / ((3 + 4h^2) sin th0 - 12 h~ cos th0)",
                 12 * (p - ht) / (a3 * s - 12 * ht * c),
                 "Omega0^2 = 12 (tan th0 - h~) / ((3 + 4h^2) sin th0 - 6 h~ cos th0)",
                 12 * (p - ht) / (a3 * s - 6 * ht * c)),
    "text after (33) [bound]": _row(  # the tan th0 where the denominator of (33) vanishes
        _T33, "for tan th0 < h also tan th0 < 12h/(3+4h^2) and for tan th0 > h also tan th0 > "
        "12h/(3+4h^2)", 12 * h / a3, "... 6h/(3+4h^2) (both places)", 6 * h / a3),
    "text after (33) [limits]": _row(_T33, "Omega0^2 ~ 12 tan th0/(3+4h^2) (r_C = 0); "
                                     "Omega0^2 -> 1/(h r_C) (r_C != 0) as th0 -> pi/2",
                                     (12 * p / a3, 1 / (h * rC))),
    # ---- 3.1.2 smooth ground
    "(34)": _row("(34)", "(1/4 + h^2/3) tan th0 omega30^2 - 1/2 omega20 omega30 = sin th0 - h~ "
                 "cos th0", k1 * p * w3 ** 2 - R(1, 2) * w2 * w3 - (s - ht * c)),
    "(35)": _row("(35)", "(1/4 - h^2/3) Omega0^2 sin th0 + 1/2 omega0 Omega0 + tan th0 - h~ = 0",
                 (R(1, 4) - h ** 2 / 3) * W ** 2 * s + R(1, 2) * w * W + p - ht),
    "text after (35)": _row("text after (35)", "SE spin: omega0 = -(1/2 - 2h^2/3) Omega0 sin "
                            "th0", -(R(1, 2) - 2 * h ** 2 / 3) * W * s.subs(p, ht)),
    # ---- section 4.1: rough ground
    "(36)": _row("(36)", "theta = theta0 + theta~, omega_k = omega_k0 + omega~_k",
                 (0, 0, 0, 0)),  # (theta~, omega~1..3) at the steady motion itself
    "(39)": _row("(39)", "theta~'' + varpi^2 theta~ = 0; omega~2' = -(12 h~ omega20 + "
                 "2(3+4h^2) omega30)/(3(3+8h^2)) omega~1; omega~3' = [...] omega~1",
                 (-(12 * ht * w2 + 2 * a3 * w3) / (3 * a8),
                  -6 * w2 / a8 + (p + 4 * ht / a8) * w3)),
    "(40)-(41)": _row(
        "(40)-(41)", "varpi^2 = ((P22 w20^2 + P23 w20 w30 + P33 w30^2) sqrt(1+p0^2) - "
        "12(3+8h^2)(1+h~p0)) / ((3+8h^2)(15+16h^2) sqrt(1+p0^2))",
        ((36 * (3 + 2 * ht * p) * w2 ** 2
          - 6 * (4 * ht * a8 * p ** 2 + (15 + 56 * h ** 2) * p + 2 * ht * (15 + 8 * h ** 2))
          * w2 * w3
          + (3 * (3 + 16 * h ** 2) * a8 * p ** 2 + 8 * ht * (15 + 44 * h ** 2) * p + 45
             + 216 * h ** 2 + 128 * h ** 4) * w3 ** 2) * sq - 12 * a8 * (1 + ht * p))
        / (a8 * a16 * sq)),
    "(42)": _row("(42)", "omega20^2 > (3+8h^2) sqrt(1+h^2) / (3 (3+2h^2))",
                 (a8 * sp.sqrt(1 + h ** 2) / (3 * (3 + 2 * h ** 2)), R(1, 3))),  # h = 0: 1/3
    "(43)": _row("(43)", "omega30^2 > 12 sqrt(1+h^2) / ((1+h^2)(15+16h^2))",
                 (12 * sp.sqrt(1 + h ** 2) / ((1 + h ** 2) * a16), R(4, 5), 0.580)),
    # (43): the bound, then the quoted h = 0: 4/5 and h = sqrt(3)/2: |omega30| > 0.580
    "(44)": _row("(44)", "omega20 = [(3+4h^2) p0 + 12h~] / (6(3+2h~p0)) omega30 - 2 (p0-h~) / "
                 "((3+2h~p0) sqrt(1+p0^2)) / omega30",
                 (a3 * p + 12 * ht) / (6 * (3 + 2 * ht * p)) * w3
                 - 2 * (p - ht) / ((3 + 2 * ht * p) * sq) / w3,
                 "omega20 = [(3+16h^2) p0 + 12h~] / (6(3+2h~p0)) omega30 - ...",
                 ((3 + 16 * h ** 2) * p + 12 * ht) / (6 * (3 + 2 * ht * p)) * w3
                 - 2 * (p - ht) / ((3 + 2 * ht * p) * sq) / w3),
    "(45)": _row("(45)", "P0 = 144 (p0 - h~)^2", (144 * (p - ht) ** 2, P1, P2, den45),
                 "P0 = 144 (p0 - h~)^2 sqrt(1 + p0^2)  (P1, P2 and the denominator as printed)",
                 (144 * (p - ht) ** 2 * sq, P1, P2, den45)),
    "(46)": _row("(46)", "P2 w^4 + P1 w^2 + P0 > 0; for all omega30 iff P1 > 0 or Delta < 0",
                 sp.Or(PP1 > 0, PP1 ** 2 - 4 * PP0 * PP2 < 0)),  # in the symbols P0, P1, P2
    "text after (46) [h = 0]": _row(_T46, "h = 0: theta0 ~ 0.325 = 18.6 deg", 18.6),
    "text after (46) [tan]": _row(_T46, "tan theta0 = sqrt(198 sqrt5 - 429)/11",
                                  math.sqrt(198 * math.sqrt(5) - 429) / 11),
    "text after (46) [great h]": _row(_T46, "great h: theta0 > arctan(3h/2)", 1.5),
    "(47)": _row("(47)", "varpi^2 = 12 (R2 r_C^2 + R1 r_C + R0) / (Q1 r_C + Q0)",
                 (2, 1)),  # degrees in r_C of numerator and denominator
    "text before Fig. 6": _row("text before Fig. 6", "theta0 = 0, h -> inf: varpi^2 -> "
                               "(omega30^2 - 1)/2", (w3 ** 2 - 1) / 2),
    "text before Fig. 6 / Conclusion": _row("text before Fig. 6 / Conclusion", "rough: stable "
                                            "for any h, theta0 if omega30^2 > 1", 1.0),
    "(48)": _row("(48)", "varpi^2 ~ 2 omega30^2 (3+16h^2)/(15+16h^2) tan^2 th0",
                 2 * (3 + 16 * h ** 2) / a16,  # varpi^2 / (omega30^2 tan^2 th0)
                 "varpi^2 ~ omega30^2 (3+16h^2)/(15+16h^2) tan^2 th0 for h > 0 "
                 "(omega30^2 tan^2 th0 / 3 for h = 0)", (3 + 16 * h ** 2) / a16),
    # ---- section 4.2: smooth ground
    "(50)": _row("(50)", "omega~2' = 0, omega~3' = (-6 omega20/(3+4h^2) + tan th0 omega30) "
                 "omega~1", (0, -6 * w2 / a3 + p * w3)),
    "(51)": _row("(51)", "varpi^2 = (1+p0^2)[36 w20^2 - 18(3+4h^2) p0 w20 w30 + (3+4h^2)^2 "
                 "(1+3p0^2) w30^2] / ((3+4h^2) Q) - 12 (1+h~p0) sqrt(1+p0^2)/Q",
                 q * (36 * w2 ** 2 - 18 * a3 * p * w2 * w3 + a3 ** 2 * (1 + 3 * p ** 2) * w3 ** 2)
                 / (a3 * Q) - 12 * (1 + ht * p) * sq / Q),
    "(52)": _row("(52)", "varpi^2 = 36 omega20^2/(3+4h^2)^2 - 12 sqrt(1+h^2)/(3+4h^2)",
                 36 / a3 ** 2 * w2 ** 2 - 12 * sp.sqrt(1 + h ** 2) / a3),
    "(53)": _row("(53)", "omega20^2 > (3+4h^2) sqrt(1+h^2)/3",
                 (a3 * sp.sqrt(1 + h ** 2) / 3, 1)),  # h = 0: 1
    "(54)": _row("(54)", "omega20 = (1/2 + 2h^2/3) p0 omega30 - 2 (p0-h~)/sqrt(1+p0^2)/omega30",
                 (R(1, 2) + 2 * h ** 2 / 3) * p * w3 - 2 * (p - ht) / sq / w3),
    "(55)-(56)": _row("(55)-(56)", "varpi^2 = (P2 w^4 + P1 w^2 + P0)/((3+4h^2) Q w^2), P0 = "
                      "144(p0-h~)^2, P1 = -12(3+4h^2)(1+2h~p0-p0^2) sqrt(1+p0^2), P2 = "
                      "(3+4h^2)^2 (1+p0^2)^2",
                      (sP2 * w3 ** 4 + sP1 * w3 ** 2 + sP0) / (a3 * Q * w3 ** 2)),
    "(57)": _row("(57)", "omega30^2 > 12/((3+4h^2) sqrt(1+h^2))",
                 (12 / (a3 * sp.sqrt(1 + h ** 2)), 4)),  # h = 0: 4
    "(58)": _row("(58)", "P2 w^4 + P1 w^2 + P0 > 0",
                 (-4 * (45 + 108 * h ** 2 + 64 * h ** 4), 15 + 4 * h ** 2)),  # disc., LC of Q
    "(59)": _row("(59)", "3p0^4 - 4h p0^3 + 6p0^2 - 12h~p0 - 1 + 4h^2 > 0",
                 3 * p ** 4 - 4 * ht * p ** 3 + 6 * p ** 2 - 12 * ht * p - 1 + 4 * h ** 2),
    "text after (59) [great h]": _row(_T59, "great h: theta0 > arctan(4h/3)", 4 / 3),
    "text after (59) [h = 0]": _row(_T59, "h = 0: theta0 ~ 0.375 ~ 21.5 deg", 21.5),
    "text after (59) [tan]": _row(_T59, "tan theta0 = sqrt(6 sqrt3 - 9)/3",
                                  math.sqrt(6 * math.sqrt(3) - 9) / 3),
    "text after (59) [omega30]": _row(_T59, "limit omega30 ~ 1.167", 1.167),
    "text before Conclusion [h = 0]": _row(_TC, "theta0 = 0, h = 0: omega30 = 2", 2.0),
    "text before Conclusion [h = 1/2]": _row(_TC, "theta0 = 0: h limited to 1/2 with omega30 "
                                             "= sqrt(3/2) ~ 1.225", math.sqrt(1.5)),
    "text before Conclusion / Conclusion": _row(
        "text before Conclusion / Conclusion",
        "smooth: stable for any h and theta0 if omega30^2 > 2", 2.0,
        "smooth: stable for any h and theta0 if omega30^2 > 4 (sharp; the bound needed exceeds "
        "2 for every h < 0.948)", 4.0),
}
