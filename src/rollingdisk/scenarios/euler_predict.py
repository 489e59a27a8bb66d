"""What Euler's disk should do, by the adiabatic decay along the steady spin-in-place
family: the predicted end time and exponents, and the exponents fitted to a run.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.model.geometry import inertia
from rollingdisk.scenarios.euler_toy import EXPONENT_NAMES, EulerDisk
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["predicted_end_time", "predicted_exponents"]


def _family(h, alpha):
    """The spin-in-place family at tilt ``alpha`` (``theta0 = pi/2 - alpha > 0``):
    ``(E, Omega, |omega_h|, omega3, y_P)``, written in ``alpha`` (so that small tilts keep
    their precision; complex ``alpha`` passes through for complex-step derivatives).

    ``r_C = 0`` in eq. (31): ``Omega^2 = 12 (s - h c) / (c [(3 + 4 h^2) s - 6 h c])`` with
    ``s = sin theta0 = cos alpha``, ``c = cos theta0 = sin alpha``; ``omega3 = Omega c``
    (eq. 3), ``omega2 = h omega3`` (``v_Cx0 = 0``, eqs. 24, 26); energy (13) with ``v_C =
    0``, ``omega1 = 0``; ``|omega_h| = |omega2 c - omega3 s|``; ``y_P = s - h c`` (eq. 4).
    Checked against :func:`rollingdisk.steady_motion` in the tests."""
    s, c = np.cos(alpha), np.sin(alpha)
    Om2 = 12.0 * (s - h * c) / (c * ((3.0 + 4.0 * h * h) * s - 6.0 * h * c))
    Om = np.sqrt(Om2)
    w3 = Om * c
    w2 = h * w3
    k1 = inertia(h)[0]  # eq. (10)
    E = 0.5 * k1 * w3 * w3 + 0.25 * w2 * w2 + c + h * s  # -z_P = c + h s
    return E, Om, abs(w2 * c - w3 * s), w3, s - h * c


def _family_power(toy: EulerDisk, alpha):
    """Dissipated power ``|P|`` on the family (``F_z = 1``, no slip): rolling resistance
    ``c |omega_h|`` and air (the film's ``c Omega^2 / sin(alpha)`` or the boundary layer's
    ``c Omega^(5/2)``).

    The rolling resistance is taken unsmoothed: its smoothing changes the power by a
    factor ``1 - (eps/|omega_h|)^2/2``, less than 1e-8 in the toy's fit window, but it
    would switch the resistance off below ``alpha ~ (eps/2)^2`` and make ``t0`` (the
    integral down to ``alpha = 0``) diverge logarithmically."""
    E, Om, wh, w3, y_P = _family(toy.h, alpha)
    P = toy.rolling_resistance * wh
    if toy.c_air:  # omega3^2 / cos^3(theta) = Omega^2 / sin(alpha), no underflow
        P += toy.c_air * Om * Om / math.sin(alpha)
    if toy.c_boundary_layer:
        P += toy.c_boundary_layer * Om * Om * np.sqrt(Om)
    return P


def _decay_integrand(toy: EulerDisk):
    """``s -> 2 s E'(s^2) / |P(s^2)|``: ``d(t0 - t)/ds`` of the adiabatic decay with
    ``alpha = s^2`` (``E'`` by complex step, exact to rounding)."""
    h = toy.h

    def dE(a):
        return float(np.imag(_family(h, complex(a, 1e-30))[0]) / 1e-30)

    def integrand(s):
        a = s * s
        return 2.0 * s * dE(a) / _family_power(toy, a)

    return integrand


def _no_dissipation(toy: EulerDisk) -> bool:
    """True if the family loses no energy (no rolling resistance, no air)."""
    return toy.rolling_resistance == 0.0 and toy.c_air == 0.0 and toy.c_boundary_layer == 0.0


def _window(name: str, window) -> tuple[float, float]:
    """``(lo, hi)`` of a window of tilts given as a pair of positive numbers, or raise
    naming ``name``."""
    if isinstance(window, (str, bytes)) or not hasattr(window, "__len__") \
            or getattr(window, "ndim", 1) != 1 or len(window) != 2:
        raise ParameterTypeError(f"{name} must be a pair (lo, hi) of tilts in radians, got "
                                 f"{type(window).__name__} {window!r:.60}")
    return (check_real(f"{name}[0]", window[0], low=0.0, low_open=True),
            check_real(f"{name}[1]", window[1], low=0.0, low_open=True))


def _check_toy(toy) -> EulerDisk:
    if not isinstance(toy, EulerDisk):
        raise ParameterTypeError(f"toy must be an EulerDisk, got {type(toy).__name__}")
    return toy


def predicted_end_time(toy: EulerDisk, alpha_end: float = 1e-3) -> tuple[float, float]:
    """The adiabatic decay along the steady family from ``alpha0``: the time it reaches
    ``alpha_end`` and the time ``t0`` it reaches ``alpha = 0`` (units ``sqrt(a/g)``).

    ``t(alpha) = int_alpha^alpha0 E'(a) / |P(a)| da`` (see :func:`predicted_exponents`);
    slip is not in ``P`` (no slip on the family), so a run with creep ends a little
    earlier.  ``(inf, inf)`` without dissipation."""
    from scipy.integrate import quad

    toy = _check_toy(toy)
    # below 1e-12 rad the quadrature of the tail meets 0 * inf (subnormal tilts)
    alpha_end = check_real("alpha_end", alpha_end, low=1e-12, high=toy.alpha0, high_open=True)
    if _no_dissipation(toy):
        return math.inf, math.inf
    f = _decay_integrand(toy)
    tail = quad(f, 0.0, math.sqrt(alpha_end), epsabs=0.0, epsrel=1e-11, limit=400)[0]
    body = quad(f, math.sqrt(alpha_end), math.sqrt(toy.alpha0), epsabs=0.0, epsrel=1e-11,
                limit=400)[0]
    return body, body + tail


def predicted_exponents(toy: EulerDisk, window=(2e-3, 2e-2), n: int = 40) -> dict:
    """Exponents of ``alpha``, ``Omega`` and the contact-point speed against ``t0 - t``
    predicted by the adiabatic decay along the steady spin-in-place family.

    ``t0 - t(alpha) = int_0^alpha E'(a) / |P(a)| da`` (energy balance, eq. 12, with the
    family's energy ``E(alpha)`` and power ``P(alpha)``; substitution ``a = s^2`` for the
    ``a^(-1/2)`` end point of rolling resistance); the exponents are least-squares slopes
    over ``n`` tilts spaced evenly in ``log alpha`` across ``window``.  With rolling
    resistance alone they tend to ``2, -1, -1`` as the window shrinks to 0 (``E - E_inf ~
    alpha``, ``|omega_h| ~ alpha^(1/2)``), with Moffatt's film to ``1/3, -1/6, -1/6``, with
    Bildsten's boundary layer (``P ~ Omega^(5/2) ~ alpha^(-5/4)``) to ``4/9, -2/9, -2/9``.
    """
    from scipy.integrate import quad

    toy = _check_toy(toy)
    lo, hi = _window("window", window)
    n = check_int("n", n, low=2, high=10_000)
    if not (0.0 < lo < hi < toy.alpha0):
        raise ParameterError(f"window must satisfy 0 < lo < hi < alpha0 = {toy.alpha0:g}, "
                             f"got {window!r}")
    if _no_dissipation(toy):
        return {k: math.nan for k in EXPONENT_NAMES}
    h = toy.h
    integrand = _decay_integrand(toy)
    alphas = np.geomspace(lo, hi, n)
    edges = np.sqrt(np.concatenate([[0.0], alphas]))
    tau = np.cumsum([quad(integrand, edges[i], edges[i + 1], epsabs=0.0, epsrel=1e-11,
                          limit=200)[0] for i in range(n)])
    fam = [_family(h, a) for a in alphas]
    Om = np.array([f[1] for f in fam])
    vp = np.array([abs(f[4]) * f[1] for f in fam])  # contact point: |y_P| Omega
    lt = np.log(tau)
    return {"alpha": float(np.polyfit(lt, np.log(alphas), 1)[0]),
            "Omega": float(np.polyfit(lt, np.log(Om), 1)[0]),
            "contact_speed": float(np.polyfit(lt, np.log(vp), 1)[0])}


def _fit_exponents(t, alpha, Omega, vp, window):
    """Fit ``alpha = A (t0 - t)^p`` (``t0`` free) over ``alpha`` in ``window``; then the
    slopes of ``log Omega`` and ``log v_P`` against ``log(t0 - t)`` with that ``t0``."""
    from scipy.optimize import least_squares

    lo, hi = window
    w = (alpha > lo) & (alpha < hi)
    nan = {k: math.nan for k in EXPONENT_NAMES}
    if np.count_nonzero(w) < 20 or alpha[-1] > lo:
        return math.nan, nan
    tw, aw = t[w], np.log(alpha[w])
    span = tw[-1] - tw[0]
    t_last = tw[-1]

    def res(q):
        t0, p, b = q
        return aw - (b + p * np.log(np.maximum(t0 - tw, 1e-300)))

    best = None
    for guess in (1.0, 0.5, 0.3):  # a few starts: t0 beyond the window's last time
        tau0 = max(span * 0.1, 1e-9)
        q0 = [t_last + tau0 * guess * 10, 1.0, 0.0]
        r = least_squares(res, q0, bounds=([t_last + 1e-12 * (1 + t_last), -10, -1e3],
                                           [np.inf, 10, 1e3]), x_scale="jac")
        if best is None or r.cost < best.cost:
            best = r
    t0, p = float(best.x[0]), float(best.x[1])
    lt = np.log(t0 - tw)
    return t0, {"alpha": p, "Omega": float(np.polyfit(lt, np.log(Omega[w]), 1)[0]),
                "contact_speed": float(np.polyfit(lt, np.log(vp[w]), 1)[0])}
