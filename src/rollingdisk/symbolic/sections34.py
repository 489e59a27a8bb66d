"""Sections 3-4 re-derived with sympy and checked, one registered check per printed statement.

Owns the derived quantities of sections 3-4 (:func:`derived`, :func:`kinematics`), the
registry of checks (:func:`check` registers a small function under a key of
:data:`rollingdisk.symbolic.printed.PRINTED`; the functions live in :mod:`.checks3` and
:mod:`.checks4`), :func:`checks_sections_3_4` and :func:`run` that run them, and the generated
part of docs/errata.md (:func:`errata_markdown`, :func:`write_errata`).

Everything starts from the Newton-Euler derivation of :mod:`rollingdisk.symbolic.derivation`
(independent of the paper).  The kinematics of section 3 ((15)-(25)) come from its frame
rates, contact point and balances at a constant state; from its reduced equations this module
derives

* the steady-motion condition: ``d omega1/dt = 0`` at ``omega1 = 0``;
* ``varpi^2``: the linearization of the reduced system ``(theta, omega1, omega2, omega3)`` at
  a steady state has the characteristic polynomial ``lambda^2 (lambda^2 + varpi^2)`` with
  ``varpi^2 = -(d1_theta + d1_omega2 a2 + d1_omega3 a3)``, ``a_k = d(omega_k dot)/d omega1``.

A check compares the printed form with the derived one (:mod:`.identity`: random rational
points, 50 digits) or a quoted number with the one computed by the numeric library (whose
closed forms the tests check against a numerical linearization and against simulation), within
a tolerance stated in the check; :func:`rollingdisk.symbolic.rows.verdict` turns that into the
row's status.  A check takes the printed statement as its argument, so a test can hand it a
wrong one and see the row fail.

``theta0`` is taken in ``(0, pi/2)`` (so ``h~ = h``), written through ``p0 = tan(theta0)``;
negative ``theta0`` follows by the symmetry checked in ``tests/test_steady.py``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cache, lru_cache

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
from .rows import EquationCheck, Printed, markdown_table, verdict

__all__ = ["CHECKS", "check", "checks_sections_3_4", "derived", "errata_markdown", "run",
           "write_errata"]

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


def _register() -> None:
    """Import the modules whose functions register themselves with :func:`check`."""
    from . import checks3, checks4  # noqa: F401

    missing = [k for k in PRINTED if k not in CHECKS]
    if missing:
        raise LookupError(f"printed statements without a check: {missing}")


def run(key: str, printed: Printed | None = None) -> EquationCheck:
    """The row of ``PRINTED[key]``, or of ``printed`` put in its place (to test the check)."""
    _register()
    return CHECKS[key](PRINTED[key] if printed is None else printed)


@lru_cache(maxsize=1)
def checks_sections_3_4() -> tuple[EquationCheck, ...]:
    """One row per printed statement of sections 3-4: eqs. (15)-(59) and the quoted numbers.

    (37), (38) and (49) are checked with section 2
    (:func:`rollingdisk.symbolic.paper.checks_sections_1_2`).  Takes some seconds; cached.
    """
    _register()
    return tuple(run(key) for key in PRINTED)


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


# ---- the generated part of docs/errata.md ---------------------------------------------------
#: docs/errata.md holds, after this line, the generated part for sections 3-4.
MARKER = ("<!-- generated below by: "
          "python -m rollingdisk.symbolic.sections34 --write docs/errata.md -->")

HEADER = """## Sections 3 and 4: steady motions and their stability

Every row is recomputed by the test suite (`tests/test_sections34.py`), which also fails when
this part of the file is out of date.  Each printed equation is compared with the one
re-derived with sympy from the Newton-Euler derivation: the kinematics (15)-(25) from its frame
rates, contact point and balances at a constant state, the rest from its reduced equations
(random-point identity test at 50 digits; conditions up to a factor of h, p0 only).  (37),
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
    return HEADER + "\n" + markdown_table(rows or checks_sections_3_4()) + "\n"


def write_errata(path) -> None:
    """Replace everything after :data:`MARKER` in the file ``path`` by :func:`errata_markdown`."""
    from pathlib import Path

    from rollingdisk.util.files import atomic_file

    path = Path(path)
    text = path.read_text()
    if MARKER not in text:
        raise ValueError(f"{path} has no line {MARKER!r}")
    head = text[: text.index(MARKER) + len(MARKER)]
    body = errata_markdown()
    with atomic_file(path) as fh:
        fh.write(head + "\n\n" + body)


if __name__ == "__main__":  # pragma: no cover
    import sys

    # the registry lives in the imported module, not in this __main__ copy of it
    from rollingdisk.symbolic import sections34 as _module

    if sys.argv[1:2] == ["--write"] and len(sys.argv) == 3:
        _module.write_errata(sys.argv[2])
    else:
        print(_module.errata_markdown(), end="")
