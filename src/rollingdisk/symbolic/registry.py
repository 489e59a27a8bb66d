"""The registry of checks of sections 3-4, and the derived quantities the checks share.

:func:`check` registers a small function under a key of
:data:`rollingdisk.symbolic.printed.PRINTED`; the functions live in :mod:`.checks3` and
:mod:`.checks4`, which import this module and nothing of their users; :mod:`.sections34`
imports them all and runs the registered checks.  The derived quantities
(:func:`derived`, :func:`kinematics`) start from the Newton-Euler derivation of
:mod:`rollingdisk.symbolic.derivation`, independent of the paper (see :mod:`.sections34`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cache

import sympy as sp

from .identity import same
from .printed import (
    PRINTED,
    Fy,
    W,
    c,
    h,
    ht,
    p,
    psi_t,
    rC,
    s,
    vx,
    vy,
    w,
    w1,
    w2,
    w3,
)
from .rows import EquationCheck, Printed, verdict

__all__ = ["CHECKS", "check", "derived", "kinematics"]

Omega_from = {w3: W * c, w2: w + W * s}  # eq. (3) at a steady state

#: key of :data:`PRINTED` -> the check of that statement.
CHECKS: dict[str, Callable[[Printed], EquationCheck]] = {}


def check(key: str):
    """Register the decorated ``f(printed) -> EquationCheck`` as the check of ``PRINTED[key]``."""
    if key not in PRINTED:
        raise KeyError(f"no printed statement {key!r} in rollingdisk.symbolic.printed")

    def register(f):
        if key in CHECKS:
            raise ValueError(f"two checks registered for {key!r}")
        CHECKS[key] = f
        return f

    return register


def _same(a, b) -> bool:
    return same(a, b)[0]


def _quoted(pr: Printed, value: float, tol: float, what: str, at=None) -> EquationCheck:
    """Row for a quoted number: ``|value - quoted| <= tol`` (a formula evaluated ``at``)."""
    def num(f):
        return float(sp.sympify(f).subs(at)) if at else float(f)

    return verdict(pr, lambda f: abs(value - num(f)) <= tol,
                   f"{what}: library {value:.6g}, paper {num(pr.form):g}")


# ---- the derivation at a steady state ------------------------------------------------------
@cache
def _reduced(ground: str):
    """(T, d1, d2, d3): the derived omega-dot of the reduced system, theta = T."""
    from . import derivation as D

    T = sp.Symbol("T", real=True)
    sol = D.derive().rough_omega_dot if ground == "rough" else D.derive().smooth_omega_dot
    m = {D.theta: T, D.ht: ht, D.h: h, D.omega1: w1, D.omega2: w2, D.omega3: w3}
    return (T, *(sp.sympify(e).subs(m, simultaneous=True) for e in sol))


@cache
def derived(ground: str) -> dict:
    """Derived steady condition, omega20(omega30), varpi^2 and its pieces on ``ground``."""
    T, d1, d2, d3 = _reduced(ground)

    def at0(e):  # at theta = theta0 (via p0), omega1 = 0
        return e.subs(w1, 0).subs(T, sp.atan(p))

    cond = at0(d1)  # d omega1/dt at a steady state: must vanish
    a2, a3 = at0(sp.diff(d2, w1)), at0(sp.diff(d3, w1))
    varpi2 = -(at0(sp.diff(d1, T)) + at0(sp.diff(d1, w2)) * a2 + at0(sp.diff(d1, w3)) * a3)
    omega20 = sp.solve(sp.Eq(cond, 0), w2)[0]
    return {"cond": cond, "a2": a2, "a3": a3, "varpi2": varpi2, "omega20": omega20,
            "varpi2_circle": varpi2.subs(w2, omega20)}


@cache
def kinematics() -> dict:
    """The derivation's kinematics and balances at a constant state (omega1 = 0, eq. (3))."""
    from . import derivation as D

    d = D.derive()
    steady = {D.theta: sp.atan(p), D.ht: ht, D.h: h, D.omega1: 0, D.omega2: w2, D.omega3: w3,
              D.v_Cx: vx, D.v_Cy: vy, D.v_Cz: 0}

    def at(e):
        return sp.sympify(e).subs(steady, simultaneous=True).subs(Omega_from)

    rest = {**dict.fromkeys(sp.symbols("dv_Cx dv_Cy dv_Cz", real=True), 0), D.dw1: 0, D.dw2: 0,
            D.dw3: 0, D.M_x: 0, D.M_y: 0, D.M_z: 0}  # constant state, no moments
    newton = [at(e).subs(rest) for e in d.newton]
    F = sp.solve([e.subs(vy, 0) for e in newton], [D.F_x, D.F_y, D.F_z], dict=True)[0]
    euler = [at(e).subs(rest) for e in d.euler]
    return {
        "rates": tuple(at(e) for e in d.frame_rates),
        "contact": tuple(at(e) for e in d.contact_point),
        "contact_XY": tuple(at(e).subs(D.psi, psi_t) for e in d.contact_point_inertial),
        "v_P": tuple(at(e) for e in d.contact_velocity),
        "F": (F[D.F_x], F[D.F_y], F[D.F_z]),
        "euler_2": euler[1].subs(D.F_x, sp.solve(newton[0], D.F_x)[0]),
        "euler_1": euler[0].subs({D.F_x: 0, D.F_y: Fy, D.F_z: 1}),
        "velocity": lambda psi: D._Rz(psi) * sp.Matrix([vx, vy, 0]),  # eq. (1)
        "v_Cx_rough": sp.sympify(d.rough_velocity_of_C[0]).subs(steady, simultaneous=True),
    }


@cache
def _Omega0_sq():
    """Omega0^2 from the derived rough steady condition with r_C (24), (26): Omega0^2(r_C)."""
    cond_rC = derived("rough")["cond"].subs(w2, ht * w3 - rC * w3 / c).subs(w3, W * c)
    X = sp.Symbol("X", positive=True)
    return sp.solve(sp.Eq(cond_rC.subs(W, sp.sqrt(X)), 0), X)[0]


@cache
def _se_radius():
    """r_C at the SE tilt (tan theta0 = h~, y_P0 = 0) from the derived rough condition."""
    omega20 = sp.solve(sp.Eq(derived("rough")["cond"].subs(p, ht), 0), w2)[0]
    return (-omega20 / w3 + ht) * c.subs(p, ht)


def _deg(x: float) -> float:
    return math.degrees(x)


