"""Coulomb ground: both modes derived from the Newton-Euler balances (8), (9) (sympy).

Starts from :func:`rollingdisk.symbolic.derivation.derive` (balances with a general contact
force ``F = (F_x, F_y, F_z)`` and moment ``M = (M_x, M_y, M_z)`` in Cxyz) and closes them
with the contact laws of :mod:`rollingdisk.model.ground`; nothing is taken from the paper:

* the moment is affine in the normal force, ``M = M0 + F_z M1`` (symbols ``M0x..M1z``);
* rolling: the no-slip constraint ``v_Px = v_Py = 0`` (eq. 6) gives ``v_Cx, v_Cy``; its time
  derivative gives the accelerations of C; ``(8)`` and ``(9)`` are then solved, as one
  linear system, for ``d omega/dt`` and ``F``;
* sliding: ``F_x = -mu F_z e_x``, ``F_y = -mu F_z e_y`` (``e`` the unit slip direction,
  symbols ``e_x, e_y``), ``F_z`` from the vertical constraint (eq. 11); (9) and (11) are
  solved jointly for ``d omega/dt`` and ``F_z``, and (8)_1,2 give the acceleration of C.

The numeric kernels ``_rolling_solve`` / ``_sliding_solve`` of :mod:`rollingdisk.model.equations`
are written by hand and compared with these results by ``tests/test_coulomb_eqs.py``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

from .derivation import (
    F_x,
    F_y,
    F_z,
    M_x,
    M_y,
    M_z,
    derive,
    dw1,
    dw2,
    dw3,
    ht,
    omega1,
    omega2,
    omega3,
    theta,
    v_Cx,
    v_Cy,
    v_Cz,
)

__all__ = ["CoulombDerivation", "derive_coulomb", "lambdified_coulomb", "classic_transition",
           "derive_pivot_stuck", "lambdified_pivot_stuck", "derive_roll_stuck",
           "lambdified_roll_stuck"]

mu, e_x, e_y = sp.symbols("mu e_x e_y", real=True)
M0 = sp.symbols("M0x M0y M0z", real=True)
M1 = sp.symbols("M1x M1y M1z", real=True)
dv = sp.symbols("dv_Cx dv_Cy dv_Cz", real=True)


@dataclass(frozen=True)
class CoulombDerivation:
    """Sympy results, in the symbols of :mod:`.derivation` plus ``mu, e_x, e_y, M0*, M1*``.

    ``rolling`` and ``sliding`` map ``"domega1".."domega3", "F_x", "F_y", "F_z"`` (and, for
    sliding, ``"dv_Cx", "dv_Cy"``: accelerations of C relative to the rotating frame Cxyz,
    the time derivatives of its components) to expressions; the rolling ones depend on
    ``(ht, theta, omega1..3, M0*, M1*)``, the sliding ones also on ``v_Cx, v_Cy, mu, e_x,
    e_y``."""

    rolling: dict
    sliding: dict
    rolling_velocity: tuple  # (v_Cx, v_Cy) from v_P = 0


def _linear_solve(eqs, unknowns):
    """Solve equations linear in ``unknowns`` (checked) by LU: no simplification."""
    A, b = sp.linear_eq_to_matrix([sp.expand(e) for e in eqs], unknowns)
    assert not any(A.has(u) for u in unknowns)
    x = A.LUsolve(b)
    return dict(zip(unknowns, x))


@lru_cache(maxsize=1)
def derive_coulomb() -> CoulombDerivation:
    """Derive the rolling and sliding modes with friction and contact moments (cached)."""
    d = derive()
    moment = {M_x: M0[0] + F_z * M1[0], M_y: M0[1] + F_z * M1[1], M_z: M0[2] + F_z * M1[2]}
    euler = [e.subs(moment) for e in d.euler]
    vP = d.contact_velocity
    v_Cz_c = d.centre_height[1]
    dvC = sp.symbols("dv_Cx dv_Cy dv_Cz", real=True)
    rates = {theta: omega1, omega1: dw1, omega2: dw2, omega3: dw3}

    def ddt(expr):
        return sum(sp.diff(expr, q) * r for q, r in rates.items())

    # -- rolling: v_P = 0 ------------------------------------------------------------------
    vr = sp.solve(list(vP[:2]), [v_Cx, v_Cy], dict=True)[0]
    vel = {v_Cx: vr[v_Cx], v_Cy: vr[v_Cy], v_Cz: v_Cz_c}
    acc = {dvC[0]: ddt(vel[v_Cx]), dvC[1]: ddt(vel[v_Cy]), dvC[2]: ddt(v_Cz_c)}
    eqs = [n.subs(acc).subs(vel) for n in d.newton] + euler
    unknowns = [dw1, dw2, dw3, F_x, F_y, F_z]
    sol = _linear_solve(eqs, unknowns)
    rolling = {str(u): sol[u] for u in unknowns}

    # -- sliding: F_t = -mu F_z e, F_z from the vertical constraint (11) --------------------
    fric = {F_x: -mu * F_z * e_x, F_y: -mu * F_z * e_y}
    vert = d.newton[2].subs({dvC[2]: ddt(v_Cz_c), v_Cz: v_Cz_c})  # (8)_3 under contact
    eqs = [vert.subs(fric)] + [e.subs(fric) for e in euler]
    sol = _linear_solve(eqs, [dw1, dw2, dw3, F_z])
    sliding = {str(u): sol[u] for u in (dw1, dw2, dw3, F_z)}
    sliding["F_x"] = fric[F_x].subs(F_z, sol[F_z])
    sliding["F_y"] = fric[F_y].subs(F_z, sol[F_z])
    horiz = sp.solve([n.subs(fric).subs(F_z, sol[F_z]) for n in d.newton[:2]],
                     [dvC[0], dvC[1]], dict=True)[0]
    sliding["dv_Cx"], sliding["dv_Cy"] = horiz[dvC[0]], horiz[dvC[1]]
    return CoulombDerivation(rolling=rolling, sliding=sliding,
                             rolling_velocity=(vr[v_Cx], vr[v_Cy]))


@lru_cache(maxsize=1)
def lambdified_coulomb() -> dict:
    """Numpy functions from :func:`derive_coulomb`.

    ``rolling(ht, theta, w1, w2, w3, M0x, M0y, M0z, M1x, M1y, M1z)`` and
    ``sliding(ht, theta, w1, w2, w3, v_Cx, v_Cy, mu, e_x, e_y, M0x, ..., M1z)`` return
    ``[dw1, dw2, dw3, F_x, F_y, F_z]`` (sliding adds ``dv_Cx, dv_Cy``)."""
    c = derive_coulomb()
    base = (ht, theta, omega1, omega2, omega3)
    keys = ("domega1", "domega2", "domega3", "F_x", "F_y", "F_z")
    rolling = sp.lambdify(base + M0 + M1, [c.rolling[k] for k in keys], "numpy")
    sliding = sp.lambdify(base + (v_Cx, v_Cy, mu, e_x, e_y) + M0 + M1,
                          [c.sliding[k] for k in keys + ("dv_Cx", "dv_Cy")], "numpy")
    return {"rolling": rolling, "sliding": sliding}


def classic_transition():
    """The upright thin disk (``h = 0``, ``theta = 0``) sliding with ``V_X = v0``, no rotation.

    From the derived sliding equations at ``theta = omega = 0``, ``v_Cy = 0``, slip
    direction ``e = (1, 0)``: constant accelerations, integrated exactly.  Returns
    ``(t_star, V_X_star, omega2_star)`` in terms of the symbols ``v0, mu`` (the slip
    ``u_x = v_Cx - omega2`` reaches 0): ``(v0/(3 mu), 2 v0/3, 2 v0/3)``."""
    c = derive_coulomb()
    v0, t = sp.symbols("v0 t", positive=True)
    at = {ht: 0, theta: 0, omega1: 0, omega3: 0, v_Cy: 0, e_x: 1, e_y: 0,
          **{s: 0 for s in M0 + M1}}
    a_v = sp.simplify(c.sliding["dv_Cx"].subs(at))  # independent of v_Cx, omega2 here
    a_w = sp.simplify(c.sliding["domega2"].subs(at))
    assert not (a_v.free_symbols | a_w.free_symbols) - {mu}
    u = (v0 + a_v * t) - (a_w * t)  # eq. (6): u_x = v_Cx - omega2 (a = 1, h = 0)
    t_star = sp.solve(sp.Eq(u, 0), t)[0]
    return sp.simplify(t_star), sp.simplify(v0 + a_v * t_star), sp.simplify(a_w * t_star)


# ---------------------------------------------------------------------------------------
# Set-valued pivoting friction: the "pivot stuck" sub-modes (issue 22)
# ---------------------------------------------------------------------------------------
#: The pivot moment while the pivot sticks: an unknown of the constrained system.
M_piv = sp.Symbol("M_piv", real=True)


@lru_cache(maxsize=1)
def derive_pivot_stuck() -> dict:
    """Rolling and sliding with the vertical spin held at zero (pivot stuck), derived.

    While the pivot sticks, the pivoting-friction moment is not ``-c F_z sgn(omega_z)`` but
    whatever keeps ``omega_z = omega2 sin(theta) + omega3 cos(theta)`` (the vertical
    component of the angular velocity, Cxyz) at zero, as long as it stays within
    ``|M_piv| <= c F_z``.  So the contact moment is ``M = M0 + F_z M1 + M_piv e_z`` with the
    extra unknown ``M_piv`` and the extra equation (the constraint differentiated along the
    motion, ``d theta/dt = omega1``; ``e_z`` is vertical, so the turning of Cxyz about it
    leaves ``d omega_z/dt`` the derivative of the component)::

        d omega_z/dt = domega2 sin(theta) + domega3 cos(theta)
                       + omega1 (omega2 cos(theta) - omega3 sin(theta)) = 0.

    Rolling: (8), (9), the no-slip accelerations and this equation, linear in
    ``domega1..3, F_x, F_y, F_z, M_piv``.  Sliding: (9), (11) with ``F_t = -mu F_z e`` and
    this equation, linear in ``domega1..3, F_z, M_piv``; (8)_1,2 give ``dv_Cx, dv_Cy``.

    Returns
    -------
    dict
        ``{"rolling": {...}, "sliding": {...}}``, each mapping ``"domega1".."domega3",
        "F_x", "F_y", "F_z", "M_piv"`` (sliding adds ``"dv_Cx", "dv_Cy"``) to expressions in
        the symbols of :func:`derive_coulomb` (``M1z`` kept general; the stuck kernels use
        it with the pivot term removed).
    """
    d = derive()
    moment = {M_x: M0[0] + F_z * M1[0], M_y: M0[1] + F_z * M1[1],
              M_z: M0[2] + F_z * M1[2] + M_piv}
    euler = [e.subs(moment) for e in d.euler]
    vP = d.contact_velocity
    v_Cz_c = d.centre_height[1]
    rates = {theta: omega1, omega1: dw1, omega2: dw2, omega3: dw3}

    def ddt(expr):
        return sum(sp.diff(expr, q) * r for q, r in rates.items())

    omega_z = omega2 * sp.sin(theta) + omega3 * sp.cos(theta)
    stuck = ddt(omega_z)  # = 0

    vr = sp.solve(list(vP[:2]), [v_Cx, v_Cy], dict=True)[0]
    vel = {v_Cx: vr[v_Cx], v_Cy: vr[v_Cy], v_Cz: v_Cz_c}
    acc = {dv[0]: ddt(vel[v_Cx]), dv[1]: ddt(vel[v_Cy]), dv[2]: ddt(v_Cz_c)}
    eqs = [n.subs(acc).subs(vel) for n in d.newton] + euler + [stuck]
    unknowns = [dw1, dw2, dw3, F_x, F_y, F_z, M_piv]
    sol = _linear_solve(eqs, unknowns)
    rolling = {("M_piv" if u is M_piv else str(u)): sol[u] for u in unknowns}

    fric = {F_x: -mu * F_z * e_x, F_y: -mu * F_z * e_y}
    vert = d.newton[2].subs({dv[2]: ddt(v_Cz_c), v_Cz: v_Cz_c})  # (8)_3 under contact
    eqs = [vert.subs(fric)] + [e.subs(fric) for e in euler] + [stuck]
    unknowns = [dw1, dw2, dw3, F_z, M_piv]
    sol = _linear_solve(eqs, unknowns)
    sliding = {str(u): sol[u] for u in unknowns}
    sliding["F_x"] = fric[F_x].subs(F_z, sol[F_z])
    sliding["F_y"] = fric[F_y].subs(F_z, sol[F_z])
    horiz = sp.solve([n.subs(fric).subs(F_z, sol[F_z]) for n in d.newton[:2]],
                     [dv[0], dv[1]], dict=True)[0]
    sliding["dv_Cx"], sliding["dv_Cy"] = horiz[dv[0]], horiz[dv[1]]
    return {"rolling": rolling, "sliding": sliding}


@lru_cache(maxsize=1)
def lambdified_pivot_stuck() -> dict:
    """Numpy functions from :func:`derive_pivot_stuck`, arguments as in
    :func:`lambdified_coulomb`; they return ``[dw1, dw2, dw3, F_x, F_y, F_z, M_piv]``
    (sliding adds ``dv_Cx, dv_Cy``)."""
    c = derive_pivot_stuck()
    base = (ht, theta, omega1, omega2, omega3)
    keys = ("domega1", "domega2", "domega3", "F_x", "F_y", "F_z", "M_piv")
    rolling = sp.lambdify(base + M0 + M1, [c["rolling"][k] for k in keys], "numpy")
    sliding = sp.lambdify(base + (v_Cx, v_Cy, mu, e_x, e_y) + M0 + M1,
                          [c["sliding"][k] for k in keys + ("dv_Cx", "dv_Cy")], "numpy")
    return {"rolling": rolling, "sliding": sliding}


# ---------------------------------------------------------------------------------------
# Set-valued rolling resistance: the "roll stuck" sub-modes
# ---------------------------------------------------------------------------------------
#: The horizontal moment (Cxyz) while the rolling resistance sticks: unknowns.
M_hx, M_hy = sp.symbols("M_hx M_hy", real=True)


@lru_cache(maxsize=1)
def derive_roll_stuck() -> dict:
    """Rolling and sliding with the horizontal angular velocity held at zero (roll stuck).

    Rolling resistance ``-c F_z omega_h/|omega_h|`` is set-valued at ``omega_h = 0``
    (``omega_h = (omega_x, omega_y) = (omega1, omega2 cos(theta) - omega3 sin(theta))``, the
    horizontal angular velocity in Cxyz): there the moment ``(M_hx, M_hy)`` is whatever
    keeps ``omega_h = 0``, as long as ``|M_h| <= c F_z``.  The contact moment is
    ``M = M0 + F_z M1 + (M_hx, M_hy, 0)``: the held moment adds to ``M0``, so the modes of
    :func:`derive_coulomb` (solved for any ``M0``) hold with ``M0 -> M0 + M_h``, and the two
    extra unknowns follow from two extra equations, the components of ``omega_h`` held
    constant (``d theta/dt = omega1``; at ``omega_h = 0`` the turning of Cxyz about the
    vertical adds nothing, so holding the components holds the vector)::

        d omega_x/dt = domega1 = 0,
        d omega_y/dt = domega2 cos(theta) - domega3 sin(theta)
                       - omega1 (omega2 sin(theta) + omega3 cos(theta)) = 0.

    With the pivot stuck as well (``"..._pivot"``), the vertical moment ``M_piv`` and the
    equation of :func:`derive_pivot_stuck` join: all of ``omega`` is held.

    Returns
    -------
    dict
        ``{"rolling", "sliding", "rolling_pivot", "sliding_pivot"}``, each mapping
        ``"domega1".."domega3", "F_x", "F_y", "F_z", "M_hx", "M_hy"`` (with the pivot stuck
        also ``"M_piv"``; sliding adds ``"dv_Cx", "dv_Cy"``) to expressions in the symbols
        of :func:`derive_coulomb` (``M1`` kept general; the stuck kernels use it with the
        rolling-resistance term removed).
    """
    free = derive_coulomb()
    s, c = sp.sin(theta), sp.cos(theta)
    out = {}
    for pivot in (False, True):
        extra = [M_hx, M_hy] + ([M_piv] if pivot else [])
        # the held moments do not scale with F_z: they add to M0 (the free modes are affine
        # in M0, derive_coulomb solved them for any M0)
        add = {M0[0]: M0[0] + M_hx, M0[1]: M0[1] + M_hy,
               M0[2]: M0[2] + (M_piv if pivot else 0)}
        for name, sol in (("rolling", free.rolling), ("sliding", free.sliding)):
            sol = {k: v.xreplace(add) for k, v in sol.items()}
            d1, d2, d3 = sol["domega1"], sol["domega2"], sol["domega3"]
            # the components of omega_h (and omega_z) held: d/dt along d theta/dt = omega1
            cons = [d1, d2 * c - d3 * s - omega1 * (omega2 * s + omega3 * c)]
            if pivot:
                cons.append(d2 * s + d3 * c + omega1 * (omega2 * c - omega3 * s))
            # linear in the held moments: coefficients by differentiation (no expansion
            # of the large rational expressions of derive_coulomb)
            A = sp.Matrix([[sp.diff(e, u) for u in extra] for e in cons])
            b = sp.Matrix([-e.xreplace({u: 0 for u in extra}) for e in cons])
            assert not any(A.has(u) for u in extra)
            held = dict(zip(extra, A.LUsolve(b)))
            res = {k: v.xreplace(held) for k, v in sol.items()}
            res.update({str(u): held[u] for u in extra})
            out[name + ("_pivot" if pivot else "")] = res
    return out


@lru_cache(maxsize=1)
def lambdified_roll_stuck() -> dict:
    """Numpy functions from :func:`derive_roll_stuck`, arguments as in
    :func:`lambdified_coulomb`; they return ``[dw1, dw2, dw3, F_x, F_y, F_z, M_hx, M_hy]``
    (with the pivot stuck ``M_piv`` follows; sliding adds ``dv_Cx, dv_Cy``)."""
    c = derive_roll_stuck()
    base = (ht, theta, omega1, omega2, omega3)
    out = {}
    for key, expr in c.items():
        keys = ["domega1", "domega2", "domega3", "F_x", "F_y", "F_z", "M_hx", "M_hy"]
        if key.endswith("_pivot"):
            keys.append("M_piv")
        if key.startswith("sliding"):
            keys += ["dv_Cx", "dv_Cy"]
            args = base + (v_Cx, v_Cy, mu, e_x, e_y) + M0 + M1
        else:
            args = base + M0 + M1
        out[key] = sp.lambdify(args, [expr[k] for k in keys], "numpy")
    return out
