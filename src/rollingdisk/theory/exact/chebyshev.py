"""``omega2, omega3`` and ``q = omega1^2`` of an exact motion as Chebyshev series in
``theta`` over the range it sweeps, the turning points divided out of ``q``, and the time
along one monotone leg of an orbit that ends (Gauss-Legendre after the substitution that
removes the turning point's square-root singularity).
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.theory.exact.quadrature import _EPS
from rollingdisk.util.errors import ParameterError


class _Fit:
    """``omega2, omega3, q`` on ``[a, b]`` as Chebyshev series in ``x = (theta - m)/d``,
    and ``H = q / (d^2 (1 + x)^ra (1 - x)^rb)`` with the turning points divided out."""

    def __init__(self, rough, h, a, b, ra, rb, evaluate, S=1.0):
        from numpy.polynomial import chebyshev as C

        self.rough, self.h, self.a, self.b, self.ra, self.rb = rough, h, a, b, ra, rb
        self.m, self.d = 0.5 * (a + b), 0.5 * (b - a)
        # rounding floor of q: D1 carries noise ~ eps S, a step (<= the range) adds it up
        floors = (0.0, 0.0, 16.0 * _EPS * S * self.d)
        prev = None
        for deg in (24, 48, 96, 192, 384):
            x = np.cos(np.pi * (np.arange(deg + 1) + 0.5) / (deg + 1))  # first kind
            z = evaluate(self.m + self.d * x)
            coef = [C.chebfit(x, zi, deg) for zi in z]
            tails = [_tail(c) for c in coef]
            if all(t <= 1e-13 or t * float(np.max(np.abs(c))) <= f
                   for t, c, f in zip(tails, coef, floors)):
                break
            if prev is not None and max(prev[1]) < 1e-10 and all(
                    t > 0.3 * p for t, p in zip(tails, prev[1]) if p > 1e-13):
                coef = prev[0]  # a noise plateau (rounding in q' = 2 D1): keep the lower degree
                break
            prev = (coef, tails)
        else:
            raise ParameterError("omega2, omega3 and omega1^2 along this orbit are not "
                                 "resolved by a Chebyshev series of degree 384 (the orbit "
                                 "comes too close to |theta| = pi/2)")
        self.c2, self.c3, self.cq = (_chop(c) for c in coef)
        divisor = np.array([1.0])
        if ra:
            divisor = C.chebmul(divisor, [1.0, 1.0])
        if rb:
            divisor = C.chebmul(divisor, [1.0, -1.0])
        quot, rem = C.chebdiv(self.cq, divisor)
        self.cH = quot / (self.d * self.d)
        self.remainder = float(np.max(np.abs(rem))) / max(float(np.max(np.abs(self.cq))),
                                                          1e-300)
        xs = np.linspace(-1.0, 1.0, 2001)
        if np.min(C.chebval(xs, self.cH)) <= 0.0:
            raise ParameterError("omega1^2 vanishes inside the range of theta: the orbit is "
                                 "too close to a steady motion or a separatrix to be "
                                 "followed by quadrature")

    def x(self, theta):
        return (theta - self.m) / self.d

    def H(self, x):
        from numpy.polynomial import chebyshev as C

        return C.chebval(x, self.cH)

    def functions(self, theta):
        from numpy.polynomial import chebyshev as C

        x = self.x(theta)
        return C.chebval(x, self.c2), C.chebval(x, self.c3), C.chebval(x, self.cq)


def _chop(c):
    """Drop the coefficients at the noise floor (estimated from the last quarter): noise
    in high coefficients of ``q`` would be amplified by the division by ``1 - x^2``."""
    noise = float(np.max(np.abs(c[-max(4, c.size // 4):])))
    big = np.nonzero(np.abs(c) > 10.0 * noise)[0]
    return c[:big[-1] + 1] if big.size else c[:1]


def _tail(c) -> float:
    """Size of the last four Chebyshev coefficients relative to the largest."""
    scale = max(float(np.max(np.abs(c))), 1e-300)
    return float(np.max(np.abs(c[-4:]))) / scale


# ---------------------------------------------------------------------------------------


def _leg_time(fit: _Fit, th1: float, th2: float) -> float:
    """Time to go from ``th1`` to ``th2`` (one monotone leg inside ``[a, b]``)."""
    ra, rb = fit.ra, fit.rb
    x1, x2 = sorted((min(1.0, max(-1.0, fit.x(th1))), min(1.0, max(-1.0, fit.x(th2)))))
    if ra and rb:
        def to_w(x):
            return math.asin(x)

        def rate(w):
            return 1.0 / np.sqrt(fit.H(np.sin(w)))
    elif ra:  # x = -cos w, w = 0 at the turning point x = -1
        def to_w(x):
            return math.acos(-x)

        def rate(w):
            return math.sqrt(2.0) * np.cos(0.5 * w) / np.sqrt(fit.H(-np.cos(w)))
    elif rb:  # x = cos w, w = 0 at the turning point x = 1
        def to_w(x):
            return math.acos(x)

        def rate(w):
            return math.sqrt(2.0) * np.cos(0.5 * w) / np.sqrt(fit.H(np.cos(w)))
    else:
        def to_w(x):
            return x

        def rate(w):
            return 1.0 / np.sqrt(fit.H(w))
    w1, w2 = sorted((to_w(x1), to_w(x2)))
    xg, wg = np.polynomial.legendre.leggauss(40)
    edges = np.linspace(w1, w2, 9)
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:]):
        ww = 0.5 * (hi - lo) * xg + 0.5 * (hi + lo)
        total += 0.5 * (hi - lo) * float(np.sum(wg * rate(ww)))
    return total
