"""The thin disk (h = 0) on rough ground in closed form: ``omega2`` and ``omega3`` as
functions of ``theta`` through Legendre-type (hypergeometric) functions, an independent check
of the quadrature.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.theory.exact.inputs import _real_array
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["thin_disk_omega3", "THIN_DISK_MAX_POINTS"]

#: Most points :func:`thin_disk_omega3` evaluates in one call.
THIN_DISK_MAX_POINTS = 2_000


def thin_disk_omega3(theta, theta0: float, omega20: float, omega30: float):
    """``(omega2, omega3)(theta)`` of the thin disk (h = 0) on rough ground in closed form.

    With ``h = 0`` eq. (38) gives ``omega2' = -(2/3) omega3`` and
    ``omega3' = -2 omega2 + tan(theta) omega3`` (``' = d/d theta``).  Eliminating
    ``omega3 = -(3/2) omega2'`` and writing ``z = sin theta``::

        (1 - z^2) d^2 omega2/dz^2 - 2 z d omega2/dz - (4/3) omega2 = 0,

    Legendre's equation with ``nu (nu + 1) = -4/3`` (Appell 1900, Korteweg 1899; in this
    form Przybylska & Rauch-Wojciechowski, Regul. Chaotic Dyn. 21 (2016); for h > 0 Batista,
    Int. J. Non-Linear Mech. 41 (2006)).  Its even and odd solutions are
    ``y1 = 2F1(a, b; 1/2; z^2)`` and ``y2 = z 2F1(a + 1/2, b + 1/2; 3/2; z^2)`` with
    ``a + b = 1/2``, ``a b = 1/3``, i.e. ``a, b = 1/4 +- (i/2) sqrt(13/12)``; then
    ``omega2 = A y1 + B y2``, ``omega3 = -(3/2) cos(theta) (A y1' + B y2')`` (``' = d/dz``),
    ``A, B`` from the values at ``theta0``.  Evaluated with ``mpmath.hyp2f1`` (complex
    parameters); an independent check of the quadrature of :func:`exact_motion`
    (derived in ``docs/exact.md``).

    Parameters
    ----------
    theta : float or array_like
        Tilt(s) in rad, finite, ``|theta| < pi/2``; at most :data:`THIN_DISK_MAX_POINTS`
        values (each costs four hypergeometric sums in mpmath, ~30 ms).
    theta0, omega20, omega30 : float
        The point of the orbit that fixes ``A, B``: ``|theta0| < pi/2`` (rad) and the rates
        there (``sqrt(g/a)``), finite.

    Returns
    -------
    (omega2, omega3) : numpy.ndarray
        One-dimensional, one value per ``theta``.

    Raises
    ------
    ParameterTypeError, ParameterError
        Non-numbers; non-finite values, ``|theta| >= pi/2``, too many points.
    """
    import mpmath

    half = 0.5 * math.pi
    theta0 = check_real("theta0", theta0, low=-half, high=half, low_open=True, high_open=True)
    omega20 = check_real("omega20", omega20)
    omega30 = check_real("omega30", omega30)
    theta = np.atleast_1d(_real_array("theta", theta, max_size=THIN_DISK_MAX_POINTS)).ravel()
    if not np.all(np.isfinite(theta)) or np.any(np.abs(theta) >= half):
        raise ParameterError("theta must be finite and lie in (-pi/2, pi/2) (the closed "
                             "form has a logarithmic singularity at |theta| = pi/2)")
    r = mpmath.sqrt(mpmath.mpf(13) / 12) / 2
    a, b = mpmath.mpf(1) / 4 + 1j * r, mpmath.mpf(1) / 4 - 1j * r

    def ys(th):
        z = mpmath.sin(th)
        z2 = z * z
        y1 = mpmath.hyp2f1(a, b, 0.5, z2)
        y2 = z * mpmath.hyp2f1(a + 0.5, b + 0.5, 1.5, z2)
        d1 = 2 * z * (a * b / 0.5) * mpmath.hyp2f1(a + 1, b + 1, 1.5, z2)
        d2 = (mpmath.hyp2f1(a + 0.5, b + 0.5, 1.5, z2)
              + 2 * z2 * ((a + 0.5) * (b + 0.5) / 1.5) * mpmath.hyp2f1(a + 1.5, b + 1.5,
                                                                      2.5, z2))
        c = mpmath.cos(th)
        return ([float(mpmath.re(y1)), float(mpmath.re(y2))],
                [float(mpmath.re(-1.5 * c * d1)), float(mpmath.re(-1.5 * c * d2))])

    (p1, p2), (q1, q2) = ys(theta0)
    with np.errstate(all="ignore"):
        A, B = np.linalg.solve([[p1, p2], [q1, q2]], [omega20, omega30])
    w2 = np.full(theta.size, np.nan)
    w3 = np.full(theta.size, np.nan)
    for i, th in enumerate(theta if math.isfinite(A) and math.isfinite(B) else ()):
        (y1, y2), (d1, d2) = ys(float(th))
        with np.errstate(all="ignore"):
            w2[i] = A * y1 + B * y2
            w3[i] = A * d1 + B * d2
    if not (np.all(np.isfinite(w2)) and np.all(np.isfinite(w3))):
        raise ParameterError("the closed form overflows at these values (theta or theta0 "
                             "too close to pi/2, or omega20, omega30 too large)")
    return w2, w3
