"""Measurements on simulated trajectories, and their comparison with the stability theory.

:func:`energy_drift` (the integration error, energy being conserved, eq. 12),
:func:`oscillation_frequency` and :func:`growth_rate` (to compare with ``varpi`` of eqs.
40 / 51), :func:`fit_circle` (the circles of C and P, eqs. 22-24), and
:func:`compare_with_theory`, the one rule by which the command line and the atlas compare
a simulation started near a steady motion with its linear stability (section 4).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.equations import omega_dot
from rollingdisk.results.trajectory import Trajectory
from rollingdisk.util.checks import check_instance, check_int, check_real, real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["energy_drift", "oscillation_frequency", "growth_rate", "fit_circle",
           "TheoryComparison", "compare_with_theory", "LINEAR_RANGE"]

def _check_trajectory(traj) -> Trajectory:
    """``traj`` itself, or :class:`ParameterTypeError` if it is not a :class:`Trajectory`."""
    if not isinstance(traj, Trajectory):
        raise ParameterTypeError(f"traj must be a rollingdisk.Trajectory, got "
                                 f"{type(traj).__name__}")
    return traj


def energy_drift(traj: Trajectory) -> float:
    """Largest relative change of the energy (eq. 13) along ``traj``.

    The equations conserve energy on both grounds (eq. 12: the contact force does no work
    without slip or without friction), so this measures the integration error.

    Parameters
    ----------
    traj : Trajectory
        A simulated motion.

    Returns
    -------
    float
        ``max |E(t) - E(t0)| / |E(t0)|`` over the stored points, ``E`` of eq. (13).
    """
    E = _check_trajectory(traj).E
    return float(np.max(np.abs(E - E[0])) / max(abs(E[0]), np.finfo(float).tiny))


def _hermite5_root(t0, t1, v0, v1, d0, d1, a0, a1):
    """Root in [t0, t1] of the quintic Hermite interpolant of (value, slope, curvature)."""
    dt = t1 - t0

    def p(s):
        # quintic Hermite basis on s in [0, 1]
        s2 = s * s
        s3 = s2 * s
        s4 = s3 * s
        s5 = s4 * s
        h0 = 1 - 10 * s3 + 15 * s4 - 6 * s5
        h1 = s - 6 * s3 + 8 * s4 - 3 * s5
        h2 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5)
        h5 = 10 * s3 - 15 * s4 + 6 * s5
        h4 = -4 * s3 + 7 * s4 - 3 * s5
        h3 = 0.5 * (s3 - 2 * s4 + s5)
        return (h0 * v0 + h1 * dt * d0 + h2 * dt * dt * a0
                + h5 * v1 + h4 * dt * d1 + h3 * dt * dt * a1)

    lo, hi = 0.0, 1.0
    plo = p(lo)
    for _ in range(60):  # bisection to round-off (the bracket is known)
        mid = 0.5 * (lo + hi)
        pm = p(mid)
        if (pm > 0) == (plo > 0):
            lo, plo = mid, pm
        else:
            hi = mid
        if hi - lo < 1e-16:
            break
    return t0 + 0.5 * (lo + hi) * dt


def oscillation_frequency(traj: Trajectory, *, min_periods: int = 2) -> float | None:
    """Angular frequency of the oscillation of ``theta`` along ``traj``, or None.

    The upward crossings of ``theta - c`` (``c`` the time average of ``theta``) are found
    on the quintic Hermite interpolant of ``theta, d theta/dt = omega1`` and
    ``d^2 theta/dt^2 = d omega1/dt`` (eq. 38 / 49) between stored points; the period is the
    least-squares slope of the crossing times against their index, so the offset ``c``
    does not bias it.  Compare with ``varpi`` of eq. (40) / (51).

    Parameters
    ----------
    traj : Trajectory
        A simulated motion, e.g. from :func:`simulate_steady` with a small ``perturb``;
        store points densely enough (``max_step``) that each crossing is bracketed.
    min_periods : int
        Fewest whole periods to measure, at least 1 (a period needs two crossings).

    Returns
    -------
    float or None
        The angular frequency ``2 pi / period``; None if ``theta`` crosses its mean upward
        fewer than ``min_periods + 1`` times.
    """
    t = _check_trajectory(traj).t
    min_periods = check_int("min_periods", min_periods, low=1)
    th = traj.theta
    if t.size < 3:
        return None
    c = float(np.trapezoid(th, t) / (t[-1] - t[0]))
    v = th - c
    w1, w2, w3 = traj.omega1, traj.omega2, traj.omega3
    acc = np.asarray(omega_dot(traj.disk, traj.ground, th, w1, w2, w3)[0])
    up = np.nonzero((v[:-1] < 0) & (v[1:] >= 0))[0]
    if up.size < min_periods + 1:
        return None
    tc = np.array([_hermite5_root(t[i], t[i + 1], v[i], v[i + 1], w1[i], w1[i + 1],
                                  acc[i], acc[i + 1]) for i in up])
    k = np.arange(tc.size, dtype=float)
    period = np.polyfit(k, tc, 1)[0]
    return float(2 * math.pi / period)


def growth_rate(traj: Trajectory, *, theta_ref: float | None = None,
                max_amplitude: float = 1e-6) -> float | None:
    """Exponential growth rate of an unstable departure from a steady motion, or None.

    In the linear regime (eq. 39 / 50 with ``varpi^2 < 0``)
    ``omega1 = alpha e^{lambda t} + beta e^{-lambda t}`` exactly; ``lambda`` (to compare
    with ``sqrt(-varpi^2)``) is fitted by variable projection (``alpha, beta`` by linear
    least squares for each trial ``lambda``, relative residuals) over the stored points
    where ``|theta - theta_ref| <= max_amplitude``, the part still linear.

    Parameters
    ----------
    traj : Trajectory
        A simulated motion started near an unstable steady motion (:func:`simulate_steady`
        with a tiny ``perturb``).
    theta_ref : float, optional
        The steady inclination; ``traj.theta_ref`` (set by :func:`simulate_steady`) or
        ``theta(0)`` by default.
    max_amplitude : float
        Largest departure ``|theta - theta_ref|`` counted as linear.  The nonlinear terms
        bias the result by about this much, relatively.

    Returns
    -------
    float or None
        The growth rate ``lambda``; None when the linear part holds fewer than 8 points or
        shows no growth.
    """
    from scipy.optimize import minimize_scalar

    _check_trajectory(traj)
    max_amplitude = check_real("max_amplitude", max_amplitude, low=0.0, low_open=True)
    if theta_ref is not None:
        theta_ref = check_real("theta_ref", theta_ref)
    ref = theta_ref if theta_ref is not None else (
        traj.theta_ref if traj.theta_ref is not None else float(traj.theta[0]))
    dev = np.abs(traj.theta - ref)
    over = np.nonzero(dev > max_amplitude)[0]
    end = over[0] if over.size else traj.t.size
    tau = traj.t[:end] - traj.t[0]
    w = traj.omega1[:end]
    if tau.size < 8 or not np.any(w != 0):
        return None
    scale = np.abs(w) + 1e-3 * np.max(np.abs(w))  # relative residuals, floored near 0

    def misfit(lam):
        e = np.exp(-lam * (tau[-1] - tau))  # e^{lam tau}, normalised at the end
        f = np.exp(-lam * tau)
        M = np.column_stack([e, f]) / scale[:, None]
        coef, *_ = np.linalg.lstsq(M, w / scale, rcond=None)
        r = M @ coef - w / scale
        return float(r @ r)

    # a first guess from the log-slope of the second half
    half = tau >= 0.5 * tau[-1]
    ok = half & (w != 0)
    if np.count_nonzero(ok) < 2:
        return None
    lam0 = np.polyfit(tau[ok], np.log(np.abs(w[ok])), 1)[0]
    if not lam0 > 0:
        return None
    res = minimize_scalar(misfit, bounds=(0.5 * lam0, 2.0 * lam0), method="bounded",
                          options={"xatol": 1e-10 * lam0})
    lam = float(res.x)
    return lam if lam > 0 else None


def fit_circle(x, y) -> tuple[float, float, float]:
    """Algebraic least-squares circle through points ``(x, y)``.

    Solves ``x^2 + y^2 + D x + E y + F = 0`` in the least-squares sense (Kasa fit) on
    coordinates centred at their mean (for conditioning).  Exact for points on a circle.
    Used to check that C and P trace concentric circles about A (eqs. 22-24).

    Parameters
    ----------
    x, y : array_like
        Coordinates of the points (e.g. ``traj.X_P, traj.Y_P``), equally many, at least 3.

    Returns
    -------
    x_c, y_c, r : float
        Centre and radius of the circle.

    Raises
    ------
    ValueError
        If ``x`` and ``y`` differ in length or hold fewer than 3 points.
    """
    x = real_array("x", x).ravel()
    y = real_array("y", y).ravel()
    if x.shape != y.shape or x.size < 3:
        raise ParameterError("x and y must be equally long with at least 3 points")
    mx, my = x.mean(), y.mean()
    u, v = x - mx, y - my
    M = np.column_stack([u, v, np.ones_like(u)])
    rhs = -(u * u + v * v)
    (D, E, F), *_ = np.linalg.lstsq(M, rhs, rcond=None)
    uc, vc = -0.5 * D, -0.5 * E
    r = math.sqrt(max(uc * uc + vc * vc - F, 0.0))
    return float(uc + mx), float(vc + my), r


# ---------------------------------------------------------------------------- theory
#: The linear range of :func:`compare_with_theory`: a departure ``|theta - theta0|`` up to
#: 1000 times the initial departure counts as linear, but never less than 1e-4 nor more
#: than 1e-3 (the nonlinear terms bias a fitted growth rate by about this much,
#: relatively).
LINEAR_RANGE = (1e3, 1e-4, 1e-3)


def _linear_amplitude(departure: float) -> float:
    factor, low, high = LINEAR_RANGE
    return min(high, max(low, factor * departure))


@dataclass(frozen=True)
class TheoryComparison:
    """A simulation started near a steady motion, compared with its linear stability.

    Attributes
    ----------
    kind : {"frequency", "growth"}
        ``"frequency"`` for a stable motion (``varpi^2 >= 0``): the measured angular
        frequency of ``theta`` against ``varpi``; ``"growth"`` for an unstable one: the
        measured e-folding rate against ``sqrt(-varpi^2)`` (eqs. 39-40 / 50-51).
    varpi2 : float
        ``varpi^2`` of the steady motion (eq. 40 / 51).
    predicted : float
        ``sqrt(|varpi^2|)``.
    measured : float or None
        From :func:`oscillation_frequency` or :func:`growth_rate`; None when the run is too
        short to measure it.
    rel_error : float or None
        ``|measured - predicted| / predicted``; None without a measurement.
    departure : float
        The initial departure from the steady motion,
        ``max(|theta(0) - theta0|, |omega1(0)| / sqrt(|varpi^2|))``.
    linear_amplitude : float
        The largest ``|theta - theta0|`` counted as linear (:data:`LINEAR_RANGE`).
    max_departure : float
        The largest ``|theta - theta0|`` along the run.
    """

    kind: str
    varpi2: float
    predicted: float
    measured: float | None
    rel_error: float | None
    departure: float
    linear_amplitude: float
    max_departure: float

    def as_dict(self) -> dict:
        """The fields as a plain dict."""
        return dict(self.__dict__)

    def _repr_html_(self) -> str:
        from rollingdisk.model.units import result_html

        rate = "angular_speed" if self.kind == "frequency" else "rate"
        kinds = {"varpi2": "rate_sq", "predicted": rate, "measured": rate,
                 "rel_error": "dimensionless", "departure": "angle",
                 "linear_amplitude": "angle", "max_departure": "angle"}
        return result_html(f"Simulation vs linear theory ({self.kind})", None,
                           self.as_dict(), kinds)


def compare_with_theory(traj: Trajectory, stability=None) -> TheoryComparison:
    """Compare a run started near a steady motion with the linear theory of section 4.

    One rule for the linear range (:data:`LINEAR_RANGE`), used by the command line
    (``rollingdisk simulate``) and the atlas alike.

    Parameters
    ----------
    traj : Trajectory
        From :func:`rollingdisk.simulate_steady` (it carries the motion).
    stability : Stability, optional
        ``rollingdisk.stability(traj.motion)``, computed when not given.

    Returns
    -------
    TheoryComparison

    Raises
    ------
    ParameterTypeError
        If ``traj`` is not a Trajectory started from a steady motion.

    Examples
    --------
    >>> import rollingdisk as rd
    >>> m = rd.steady_motion(rd.Disk(h=0.1), "rough", 0.3, Omega0=3.0)
    >>> c = compare_with_theory(rd.simulate_steady(m, 40.0, perturb=1e-6))
    >>> c.kind, bool(c.rel_error < 1e-3)
    ('frequency', True)
    """
    from rollingdisk.theory.oscillations import stability as _stab

    if not isinstance(traj, Trajectory) or traj.motion is None:
        raise ParameterTypeError("traj must be a Trajectory from simulate_steady (one that "
                                 "knows its steady motion)")
    from rollingdisk.theory.oscillations import Stability

    if stability is not None:
        check_instance("stability", stability, Stability,
                       "a Stability (rollingdisk.stability(traj.motion)) or None")
    stab = _stab(traj.motion) if stability is None else stability
    varpi2 = float(stab.varpi2)
    predicted = math.sqrt(abs(varpi2))
    theta0 = float(traj.motion.theta0)
    scale = predicted if predicted > 0 else 1.0
    departure = max(abs(float(traj.theta[0]) - theta0), abs(float(traj.omega1[0])) / scale)
    amp = _linear_amplitude(departure)
    if varpi2 >= 0:
        kind, measured = "frequency", oscillation_frequency(traj)
    else:
        kind, measured = "growth", growth_rate(traj, theta_ref=theta0, max_amplitude=amp)
    rel = None if measured is None or predicted == 0 else abs(measured - predicted) / predicted
    return TheoryComparison(kind=kind, varpi2=varpi2, predicted=predicted,
                            measured=None if measured is None else float(measured),
                            rel_error=rel, departure=departure, linear_amplitude=amp,
                            max_departure=float(np.max(np.abs(traj.theta - theta0))))
