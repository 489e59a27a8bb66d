"""The registered checks of section 3 (steady motions): eqs. (15)-(35) and the prose about them.

One small function per printed statement of :data:`rollingdisk.symbolic.printed.PRINTED`,
registered with :func:`rollingdisk.symbolic.sections34.check`; each compares the printed form
it is given with the derivation (:mod:`.sections34`) or with the numeric library, so that the
status is computed.  Imported (for its registrations) by :mod:`.sections34` when the checks run.
"""

from __future__ import annotations

import math
from functools import cache

import sympy as sp

from .identity import proportional
from .printed import (
    PRINTED,
    Fy,
    R,
    W,
    c,
    h,
    ht,
    p,
    psi0,
    psi_t,
    rC,
    rP,
    tt,
    vx,
    vy,
    w,
    w2,
    w3,
    yP,
)
from .registry import (
    Omega_from,
    _deg,
    _Omega0_sq,
    _quoted,
    _same,
    _se_radius,
    check,
    derived,
    kinematics,
)
from .rows import verdict


# ---- section 3: kinematics, from the derivation at a constant state -----------------------
@check("(15)")
def _eq15(pr):
    return verdict(pr, lambda f: _same(kinematics()["rates"], f),
                   "sympy: the derived frame rates (2) at omega1 = 0, theta = theta0 with eq. "
                   "(3) are psi' = Omega0, theta' = 0, phi' = omega0, constant")


@check("(16)")
def _eq16(pr):
    return verdict(pr, lambda f: _same(kinematics()["contact"], f),
                   "sympy: the derived contact point (4) at theta0")


@check("(17)")
def _eq17(pr):
    return verdict(pr, lambda f: _same(kinematics()["contact_XY"], f),
                   "sympy: the derived contact point in OXYZ (5) at theta0 with psi from (15)")


@check("(18)")
def _eq18(pr):
    vP = kinematics()["v_P"]
    return verdict(pr, lambda f: _same((vP[0], vP[0], vP[1]),
                                       (sp.sympify(f[0]).subs(Omega_from), f[1], f[2])),
                   "sympy: the derived contact-point velocity (6) at omega1 = 0, with eq. (3)")


@check("(19)")
def _eq19(pr):
    return verdict(pr, lambda f: _same(kinematics()["F"], f),
                   "sympy: the derived momentum balance (8) with a constant state, v_Cy0 = 0 "
                   "(20)_1, with eq. (3)")


@check("(20)")
def _eq20(pr):
    k = kinematics()
    F_y_rough = (w2 - ht * w3) * w3 / c  # (19): F_y = v_Cx0 Omega0 with no slip

    def ok(f):
        return (proportional(k["euler_2"], f[0])
                and proportional(k["euler_1"], sp.sympify(f[1]).subs(Omega_from))
                and proportional(sp.sympify(f[1]).subs(Fy, F_y_rough), derived("rough")["cond"]))

    return verdict(pr, ok, "sympy: (20)_1 is the derived (9)_2 with F_x from (8)_1, (20)_2 the "
                   "derived (9)_1 (each up to a factor of h, p0 only); with F_y from (19) on "
                   "rough ground (20)_2 is proportional to d omega1/dt of the derived reduced "
                   "equations at omega1 = 0")


@check("(21)")
def _eq21(pr):
    vel = kinematics()["velocity"](psi0)
    straight = all(proportional(derived(g)["cond"].subs(w3, 0), yP) for g in ("rough", "smooth"))
    return verdict(pr, lambda f: straight and _same([sp.diff(x, tt) for x in f], vel[:2]),
                   "sympy: d/dt of (21) equals the velocity (1) R_z(psi0) v_C; with omega30 = 0 "
                   "the derived steady condition is proportional to y_P0 on both grounds, so "
                   "straight lines need tan th0 = h~")


def _circle_of_C(f22, r_C=None):
    """Does the printed (22) integrate the velocity (1), with r_C from the printed (24)?"""
    r_C = PRINTED["(24)"].form[0] if r_C is None else r_C
    vel = kinematics()["velocity"](psi_t).subs(vy, 0)
    return _same([sp.diff(x, tt).subs(rC, r_C) for x in f22], vel[:2])


@check("(22)")
def _eq22(pr):
    return verdict(pr, _circle_of_C, "sympy: d/dt of (22) with r_C from (24) equals the "
                   "velocity (1) with psi from (15) and v_Cy0 = 0")


def _circle_of_P(f23, r_P=None):
    """Is the printed (23) the printed (22) plus the derived contact point (5)?"""
    r_P = PRINTED["(24)"].form[1] if r_P is None else r_P
    X22 = PRINTED["(22)"].form
    return _same([X22[i] + kinematics()["contact_XY"][i] for i in (0, 1)],
                 [sp.sympify(x).subs(rP, r_P) for x in f23])


@check("(23)")
def _eq23(pr):
    return verdict(pr, _circle_of_P, "sympy: (22) plus the derived contact point (5) is (23) "
                   "with r_P = r_C + y_P0 (24)")


@check("(24)")
def _eq24(pr):
    return verdict(pr, lambda f: (_circle_of_C(PRINTED["(22)"].form, f[0])
                                  and _circle_of_P(PRINTED["(23)"].form, f[1])),
                   "sympy: the radii that make (22) integrate (1) and (23) follow from (22) and "
                   "(5) (rows (22), (23))")


@check("(25)")
def _eq25(pr):
    return verdict(pr, lambda f: _same([sp.sympify(x).subs(tt, 0)
                                        for x in PRINTED["(22)"].form], f),
                   "sympy: (22) at t = 0")


# ---- 3.1.1 rough ------------------------------------------------------------------------
@check("(26)")
def _eq26(pr):
    r_C = -kinematics()["v_Cx_rough"] * c / w3  # -v_Cx0 / Omega0, Omega0 = omega30 / cos
    return verdict(pr, lambda f: _same((r_C, (r_C + yP).subs(Omega_from)), f),
                   "sympy from (24) with v_Cx0 = omega20 - h~ omega30 (no slip)")


@check("(27)")
def _eq27(pr):
    return verdict(pr, lambda f: _same(kinematics()["F"][1].subs(vx, -rC * W), f),
                   "sympy: the derived (19)_2 with v_Cx0 = -r_C Omega0 (24); numerically "
                   "contact_force() agrees (tests/test_steady.py::"
                   "test_circle_from_Omega0_is_steady)")


@check("(28)")
def _eq28(pr):
    return verdict(pr, lambda f: proportional(f, derived("rough")["cond"]),
                   "sympy: proportional to d omega1/dt of eq. (38) at omega1 = 0 (factor "
                   "-12/(15+16h^2))")


@check("(29)")
def _eq29(pr):
    return verdict(pr, lambda f: proportional(f, derived("rough")["cond"].subs(Omega_from)),
                   "sympy: proportional to the derived steady condition with eq. (3)")


@check("(30)")
def _eq30(pr):
    return verdict(pr, lambda f: _same(_se_radius(), f),
                   "sympy: SE tilt (y_P0 = 0) in the derived condition; any Omega0")


@check("text after (30) [sign]")
def _after30_sign(pr):
    values = [float(_se_radius().subs(h, x)) for x in (R(9, 10), 2, 10, 1000)]
    sign = math.copysign(1, values[0]) if len({v > 0 for v in values}) == 1 else 0
    return verdict(pr, lambda f: sign == f, "(30) has the sign of 3 - 4h^2; e.g. h = 2: r_C = "
                   f"{values[1]:.4f}")


@cache
def _se_max():
    from scipy.optimize import minimize_scalar

    from rollingdisk.theory.steady import se_circle_radius

    opt = minimize_scalar(lambda x: -se_circle_radius(x), bounds=(0, math.sqrt(3) / 2),
                          method="bounded", options={"xatol": 1e-12})
    return opt.x, -opt.fun


@check("text after (30) [max]")
def _after30_max(pr):
    return _quoted(pr, _se_max()[1], 5e-5, "max of (30) over h < sqrt(3)/2")


@check("text after (30) [argmax]")
def _after30_argmax(pr):
    return _quoted(pr, _se_max()[0], 1e-7, "maximizing h")


@check("text after (30) [theta0]")
def _after30_theta0(pr):
    return _quoted(pr, _deg(math.atan(_se_max()[0])), 0.05, "arctan of the maximizing h [deg]")


@check("text after (30) [limit]")
def _after30_limit(pr):
    from rollingdisk.theory.steady import se_circle_radius

    return _quoted(pr, se_circle_radius(1e8), 1e-6, "(30) at h = 1e8")


@check("text after (30) [spin]")
def _after30_spin(pr):
    x = sp.Symbol("x", positive=True)
    zeros = sp.solve(sp.simplify(_se_radius().subs(h, x)), x)  # the derived (30)
    if len(zeros) != 1:
        raise RuntimeError(f"expected one positive zero of the derived (30), got {zeros}")
    return _quoted(pr, _deg(math.atan(float(zeros[0]))), 5e-4,
                   "arctan of the positive zero of the derived (30) [deg]")


@check("(31) first form")
def _eq31a(pr):
    return verdict(pr, lambda f: _same(f, _Omega0_sq()),
                   "sympy: Omega0^2 solved from the derived condition with omega20 = h~ omega30 "
                   "- r_C Omega0; the printed first form is inconsistent with the paper's own "
                   "(32) and with its second form")


@check("(31) second form")
def _eq31b(pr):
    return verdict(pr, lambda f: _same(f, _Omega0_sq().subs(rC, rP - yP)),
                   "sympy, with r_C = r_P - y_P0")


@check("(32)")
def _eq32(pr):
    zeros = sp.solve(sp.Eq(sp.denom(sp.together(_Omega0_sq())), 0), rC)
    return verdict(pr, lambda f: len(zeros) == 1 and _same(f, zeros[0]),
                   "sympy: zero of the denominator of the derived Omega0^2; h means h~")


def _theta_grid():
    import numpy as np

    return np.linspace(1e-9, math.pi / 2 - 1e-12, 400001)


@check("text after (32) [max]")
def _after32_max(pr):
    import numpy as np

    from rollingdisk.theory.steady import r_C_star

    grid = r_C_star(0.7, _theta_grid())
    at0 = float(r_C_star(0.7, 0.0))

    def ok(f):  # the maximum is the value at theta0 = 0, and that value is the printed one
        bound = float(f.subs(h, 0.7))
        return bool(np.all(grid <= bound + 1e-15)) and abs(at0 - bound) <= 1e-12

    return verdict(pr, ok, f"h = 0.7, and r_C*(0.7, theta0) <= h/3 on a grid: {ok(pr.form)}: "
                   f"library {at0:.6g}, paper {float(pr.form.subs(h, 0.7)):g}")


@check("text after (32) [min]")
def _after32_min(pr):
    import numpy as np

    from rollingdisk.theory.steady import r_C_star

    return _quoted(pr, float(np.min(r_C_star(0.0, _theta_grid()))), 1e-9, "grid minimum")


@check("text after (32) [zeros]")
def _after32_zeros(pr):
    from rollingdisk.theory.steady import r_C_star

    end = abs(float(r_C_star(0.7, math.pi / 2 - 1e-9)))  # -> 0 as theta0 -> pi/2

    def ok(f):
        return abs(float(r_C_star(0.7, float(f.subs(h, 0.7))))) <= 1e-15 and end <= 1e-8

    return verdict(pr, ok, "r_C* at h = 0.7, theta0 = arctan(6h/(3+4h^2)): "
                   f"{float(r_C_star(0.7, float(pr.form.subs(h, 0.7)))):.2g}, at pi/2 - 1e-9: "
                   f"{end:.2g}")


@check("text after (32) [great h]")
def _after32_great_h(pr):
    import numpy as np

    from rollingdisk.theory.steady import r_C_star

    low = float(np.min(r_C_star(1e6, _theta_grid())))

    def ratio(f):  # grid minimum of r_C* over the printed limit, at h = 1e6
        return low / float(f.subs(h, 1e6))

    return verdict(pr, lambda f: abs(ratio(f) - 1) <= 1e-3,
                   f"ratio min r_C* / (-h/3) at h = 1e6: {ratio(pr.form):.6g} (tolerance 1e-3; "
                   "0.867 at h = 100, a slow approach)")


@check("(33)")
def _eq33(pr):
    return verdict(pr, lambda f: _same(f, _Omega0_sq().subs(rC, 0)),
                   "sympy: derived Omega0^2 at r_C = 0; also (32) and the next sentence of the "
                   "paper (6h/(3+4h^2)) need 6h~; at h = 0.3, theta0 = 1 the corrected Omega0^2 "
                   "(off the printed one by > 0.1) gives a steady state of the equations of "
                   "motion (tests/test_steady.py::test_rough_rC_zero_uses_corrected_eq33)")


@check("text after (33) [bound]")
def _after33_bound(pr):
    den = sp.denom(sp.together(_Omega0_sq().subs(rC, 0)))
    return verdict(pr, lambda f: _same(den.subs(p, f), 0),
                   "the denominator of the derived Omega0^2 at r_C = 0 vanishes at tan th0 = "
                   "6h/(3+4h^2), as the corrected (33) says; the paper's next sentence already "
                   "uses 6h/(3+4h^2), which is right")


@check("text after (33) [limits]")
def _after33_limits(pr):
    at = {h: R(3, 10), rC: R(1, 2)}
    Om2 = _Omega0_sq().subs(h, at[h])

    def ok(f):
        return (sp.limit(Om2.subs(rC, 0) / f[0].subs(at), p, sp.oo) == 1
                and sp.limit(Om2.subs(rC, at[rC]), p, sp.oo) == f[1].subs(at))

    return verdict(pr, ok, "sympy limits of the derived Omega0^2 at h = 0.3, r_C = 0.5")


# ---- 3.1.2 smooth ------------------------------------------------------------------------
@check("(34)")
def _eq34(pr):
    return verdict(pr, lambda f: proportional(f, derived("smooth")["cond"]),
                   "sympy: proportional to d omega1/dt of eq. (49) at omega1 = 0")


@check("(35)")
def _eq35(pr):
    return verdict(pr, lambda f: proportional(f, derived("smooth")["cond"].subs(Omega_from)),
                   "sympy, with eq. (3)")


@check("text after (35)")
def _after35(pr):
    spin = sp.solve(sp.Eq(derived("smooth")["cond"].subs(Omega_from).subs(p, ht), 0), w)
    return verdict(pr, lambda f: len(spin) == 1 and _same(spin[0], f),
                   "sympy from the derived steady condition at tan th0 = h")
