"""The one identity test of :mod:`rollingdisk.symbolic`: expressions compared at random points.

Every comparison of a printed formula with a derived one (sections 2-4) goes through
:func:`same`, :func:`proportional` or :func:`changes_sign_at`.  They evaluate both sides with
mpmath at :data:`N_POINTS` random *rational* points in :data:`DIGITS`-digit arithmetic and
require agreement to :data:`RTOL` relative: a probabilistic identity test (two different
rational-trigonometric expressions agree at a random point only by accident, and a wrong
formula misses by many orders of magnitude more than the tolerance).  This replaces
``sympy.simplify``, which is slower and, when it cannot decide, says nothing.

Values are drawn per symbol *name* from a seeded generator, so a symbol takes the same value
at point ``i`` whatever expression it appears in.  Domains: ``h`` in [0.01, 3], ``p0`` (tan
theta0) in [0.01, 4], ``theta`` in [0.05, 1.4], ``Omega0`` > 0, every other symbol a non-zero
rational in [-3.1, 3.1]; ``htilde`` (h~ of :mod:`.derivation`) is ``+h`` at even points and
``-h`` at odd ones, so both signs of h~ are covered.
"""

from __future__ import annotations

import random
from collections.abc import Iterable

import mpmath
import sympy as sp

__all__ = ["DIGITS", "N_POINTS", "RTOL", "changes_sign_at", "proportional", "same"]

N_POINTS = 6
DIGITS = 50
RTOL = "1e-25"  # relative; a string so that mpmath reads it at DIGITS digits


def _draw(name: str, i: int, k: int) -> sp.Rational:
    rng = random.Random(f"rollingdisk.symbolic:{name}:{i}:{k}")
    if name == "h":
        return sp.Rational(rng.randint(1, 300), 100)
    if name == "p0":
        return sp.Rational(rng.randint(1, 400), 100)
    if name == "theta":
        return sp.Rational(rng.randint(5, 140), 100)
    if name == "Omega0":
        return sp.Rational(rng.randint(1, 300), 83)
    return sp.Rational(rng.randint(1, 300) * rng.choice((1, -1)), 97)


def point(symbols: Iterable[sp.Symbol], i: int, *, variant: int = 0,
          fixed: Iterable[sp.Symbol] = ()) -> dict:
    """Random rational values of ``symbols`` at point ``i``.

    ``variant`` redraws every symbol except those in ``fixed`` (and h~, which follows h).
    """
    fixed = {x.name for x in fixed}
    out = {}
    for x in symbols:
        name = "h" if x.name == "htilde" else x.name
        value = _draw(name, i, 0 if name in fixed else variant)
        out[x] = -value if x.name == "htilde" and i % 2 else value
    return out


def _evaluator(expr):
    """``values -> expr`` for a dict of rationals, in mpmath (call inside ``workdps``)."""
    expr = sp.sympify(expr)
    syms = sorted(expr.free_symbols, key=str)
    f = sp.lambdify(syms, expr, "mpmath")
    return lambda vals: f(*(mpmath.mpf(vals[x].p) / vals[x].q for x in syms))


def _flat(a) -> list:
    if isinstance(a, (sp.MatrixBase, list, tuple)):
        return [sp.sympify(e) for e in (a if not isinstance(a, sp.MatrixBase) else list(a))]
    return [sp.sympify(a)]


def same(a, b) -> tuple[bool, str]:
    """Are ``a`` and ``b`` (expressions, or equally long tuples/matrices) identical?

    Returns ``(equal, how)``; ``how`` says where they differ (the element, the point).
    """
    a, b = _flat(a), _flat(b)
    if len(a) != len(b):
        return False, f"differs: {len(a)} components against {len(b)}"
    syms = set().union(*(x.free_symbols for x in a + b))
    pts = [point(syms, i) for i in range(N_POINTS)]
    with mpmath.workdps(DIGITS):
        tol = mpmath.mpf(RTOL)
        for n, (x, y) in enumerate(zip(a, b, strict=True)):
            fx, fy = _evaluator(x), _evaluator(y)
            for pt in pts:
                vx, vy = fx(pt), fy(pt)
                if abs(vx - vy) > tol * (1 + abs(vx) + abs(vy)):
                    where = f" (component {n + 1})" if len(a) > 1 else ""
                    return False, (f"differs{where}: {mpmath.nstr(vx, 8)} against "
                                   f"{mpmath.nstr(vy, 8)} at a random point")
    return True, (f"equal to {RTOL} at {N_POINTS} random rational points ({DIGITS} digits, "
                  "h~ = +h and -h)")


def proportional(a, b, params: Iterable[sp.Symbol] = ()) -> bool:
    """``a = k b`` with a non-zero factor ``k`` that depends on ``params`` only.

    At each random point ``a/b`` is evaluated at four variants that share the values of
    ``params`` but draw every other symbol afresh; the ratios must agree and be non-zero.
    ``params`` defaults to the symbols named ``h`` and ``p0``.
    """
    a, b = sp.sympify(a), sp.sympify(b)
    syms = a.free_symbols | b.free_symbols
    params = set(params) or {x for x in syms if x.name in ("h", "p0")}
    with mpmath.workdps(DIGITS):
        tol = mpmath.mpf(RTOL)
        fa, fb = _evaluator(a), _evaluator(b)
        for i in range(N_POINTS):
            ratios = []
            for k in range(4):
                pt = point(syms, i, variant=k, fixed=params)
                va, vb = fa(pt), fb(pt)
                if abs(vb) < tol**1.2:
                    return False
                ratios.append(va / vb)
            r0 = ratios[0]
            if abs(r0) < tol or any(abs(r - r0) > tol * (abs(r) + abs(r0)) for r in ratios[1:]):
                return False
    return True


def changes_sign_at(expr, var: sp.Symbol, threshold) -> bool:
    """``expr`` vanishes at ``var = sqrt(threshold)``, is < 0 just below and > 0 just above.

    (``threshold`` may depend on the other symbols of ``expr``; 10 % either side.)
    """
    expr, threshold = sp.sympify(expr), sp.sympify(threshold)
    syms = sorted((expr.free_symbols | threshold.free_symbols) - {var}, key=str)
    f = sp.lambdify([var, *syms], expr, "mpmath")
    with mpmath.workdps(DIGITS):
        tol = mpmath.mpf(RTOL)
        f_thr = _evaluator(threshold)
        for i in range(N_POINTS):
            pt = point(syms, i)
            args = [mpmath.mpf(pt[x].p) / pt[x].q for x in syms]
            t = f_thr(pt)
            v0, below, above = (f(mpmath.sqrt(m * t), *args)
                                for m in (1, mpmath.mpf(9) / 10, mpmath.mpf(11) / 10))
            if not (abs(v0) < tol * (1 + abs(below)) and below < 0 < above):
                return False
    return True
