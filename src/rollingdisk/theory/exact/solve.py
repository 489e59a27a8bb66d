"""The exact motion from a state, by quadrature (:func:`exact_motion`), and from a perturbed
steady motion (:func:`exact_steady`): the sweeps to the turning points, the Chebyshev fit,
the end of an orbit that ends (lift-off, edge contact, fell flat) or the Fourier series of
a bounded one.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.equations import check_disk, normal_force
from rollingdisk.model.state import state_index
from rollingdisk.theory.exact.chebyshev import _Fit, _leg_time
from rollingdisk.theory.exact.inputs import _check_budget_keys, _check_ground, _check_state
from rollingdisk.theory.exact.orbit import _Orbit, _orbit_normal_force, _SteadyOrbit
from rollingdisk.theory.exact.quadrature import (
    _FLAT,
    _TINY,
    MAX_EVALS,
    MAX_TERMS,
    TIME_LIMIT,
    _Budget,
    _BudgetSpent,
    _sweep,
    _theta_coefficients,
)
from rollingdisk.theory.exact.result import NOT_CONVERGED_STATUS, ExactMotion
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["exact_motion", "exact_steady"]


def exact_motion(disk: Disk, ground: str, y0, *, time_limit: float = TIME_LIMIT,
                 max_evals: int = MAX_EVALS, max_terms: int = MAX_TERMS) -> ExactMotion:
    """The exact motion from the state ``y0``, by quadrature (:mod:`rollingdisk.theory.exact`).

    Parameters
    ----------
    disk : Disk
    ground : {"rough", "smooth"}
        The ideal grounds of the paper (eqs. 38, 49); the Coulomb ground is not integrable.
    y0 : array_like
        Initial state, layout of :mod:`rollingdisk.model.equations` (8 components on rough,
        10 on smooth ground).  Rates ``|omega_i|`` up to ``1e50`` (units ``sqrt(g/a)``).
    time_limit : float, optional
        Wall-clock budget in seconds (> 0), default :data:`TIME_LIMIT` (5 s).
    max_evals : int, optional
        Budget of right-hand-side evaluations of the theta-ODE (>= 100), default
        :data:`MAX_EVALS`.
    max_terms : int, optional
        Largest Fourier length per period (128 to 2^20; memory O(max_terms)), default
        :data:`MAX_TERMS` (2^17).  When the budget is spent first the status is
        ``"not-converged"`` (with a ``message``), never a hang.

    Returns
    -------
    ExactMotion
        Status, turning points, period, ``delta_psi``, drift, or the end (time, theta).

    Raises
    ------
    ParameterError
        Non-finite state, rates beyond ``1e50``, ``|theta| >= pi/2``, ``theta = 0`` with
        ``h > 0``, ``F_z < 0`` at the start (eq. 11), an orbit the quadrature cannot
        resolve, a state whose arithmetic overflows.
    ParameterTypeError
        ``disk`` not a Disk, ``ground`` not a string, ``y0`` not an array of real numbers.

    Examples
    --------
    >>> import rollingdisk as rd
    >>> from rollingdisk.theory.exact import exact_steady
    >>> m = rd.steady_motion(rd.Disk(h=0.1), "rough", 0.4, Omega0=3.0)
    >>> ex = exact_steady(m, kick=1e-3)
    >>> ex.status, round(ex.frequency / rd.stability(m).varpi, 6)
    ('bounded', 1.0)
    """
    disk = check_disk(disk)
    ground = _check_ground(ground)
    y0 = _check_state(ground, y0)
    budget = _Budget(check_real("time_limit", time_limit, low=0.0, low_open=True),
                     check_int("max_evals", max_evals, low=100),
                     check_int("max_terms", max_terms, low=128, high=1 << 20))
    known = {}
    try:
        with np.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
            return _exact_motion(disk, ground, y0, budget, known)
    except (FloatingPointError, OverflowError) as exc:
        raise ParameterError(f"the state is out of the range the quadrature can follow: "
                             f"its arithmetic overflows ({exc})") from None
    except _BudgetSpent as exc:
        th = float(y0[state_index(ground, "theta")])
        return ExactMotion(status=NOT_CONVERGED_STATUS, theta_min=known.get("a", th),
                           theta_max=known.get("b", th), period=None, delta_psi=None,
                           delta_phi=None, drift=None, t_end=None, theta_end=None,
                           message=str(exc), _fit=known.get("fit"), **known["base"])


def _exact_motion(disk, ground, y0, budget, known):
    rough = ground == "rough"
    h = disk.h
    theta0, w10, w20, w30, lo, hi = _start(disk, ground, y0)
    from rollingdisk.model.equations import energy

    q0 = w10 * w10
    a1, c1, _, _ = _theta_coefficients(rough, h, theta0, w20, w30)
    accel = a1 + c1 * q0  # d omega1/dt at the start
    base = dict(disk=disk, ground=ground, E=float(energy(disk, ground, y0)),
                y0=np.array(y0, float))
    known["base"] = base
    if q0 == 0.0 and abs(accel) <= 1e-14 * (1.0 + w20 * w20 + w30 * w30):
        return _steady_result(base, rough, h, theta0, w20, w30)
    (a, ka, fa), (b, kb, fb) = _turning_sweeps(rough, h, theta0, [w20, w30, q0], accel,
                                               lo, hi, budget)
    known.update(a=float(a), b=float(b))

    def evaluate(theta):
        theta = np.asarray(theta, float)
        out = np.empty((3, theta.size))
        up = theta >= theta0
        if fb is not None and np.any(up):
            out[:, up] = fb(np.clip(theta[up], theta0, b))
        if fa is not None and np.any(~up):
            out[:, ~up] = fa(np.clip(theta[~up], a, theta0))
        if fb is None and np.any(up):
            out[:, up] = fa(np.clip(theta[up], a, theta0))
        if fa is None and np.any(~up):
            out[:, ~up] = fb(np.clip(theta[~up], theta0, b))
        return out

    fit = _Fit(rough, h, a, b, ka == "turn", kb == "turn", evaluate,
               S=1.0 + w20 * w20 + w30 * w30 + q0)
    known["fit"] = fit
    budget.clock("the Chebyshev fit")
    s = 1.0 if (w10 > 0 or (w10 == 0 and accel > 0)) else -1.0
    ended = _open_end(fit, rough, h, theta0, s, {a: _end_kind(h, a, ka),
                                                  b: _end_kind(h, b, kb)}, a, b, base)
    if ended is not None:
        return ended
    orbit = _Orbit(fit, rough, h, np.array(y0, float), ground, budget)
    # drift of the contact point over the first period (eq. 5)
    from rollingdisk.model.equations import contact_point

    P = contact_point(disk, ground, orbit.state(np.array([0.0, orbit.T])).T)
    drift = (float(P[0][1] - P[0][0]), float(P[1][1] - P[1][0]))
    return ExactMotion(status="bounded", theta_min=float(a), theta_max=float(b),
                       period=float(orbit.T), delta_psi=float(orbit.dpsi),
                       delta_phi=float(orbit.dphi), drift=drift, t_end=None,
                       theta_end=None, _fit=fit, _orbit=orbit, **base)


def _start(disk, ground, y0):
    """``(theta0, omega1, omega2, omega3, lo, hi)`` of a start the model admits (``lo, hi``:
    the theta range an orbit may sweep), or ParameterError saying why not."""
    h = disk.h
    it = state_index(ground, "theta")
    theta0, w10, w20, w30 = (float(y0[it]), float(y0[it + 2]), float(y0[it + 3]),
                             float(y0[it + 4]))
    if not abs(theta0) < 0.5 * math.pi:
        raise ParameterError(f"theta must lie in (-pi/2, pi/2), got {theta0!r}")
    if h > 0 and theta0 == 0.0:
        raise ParameterError("theta = 0 is outside the model for h > 0 (the disk stands "
                             "on its rim edge's line); start with theta != 0")
    F_z0 = float(normal_force(ground == "rough", h, y0))
    if F_z0 < 0.0:
        raise ParameterError(f"the normal force F_z (eq. 11) is {F_z0:.6g} < 0 at the "
                             "start: the disk would lift off at once")
    side = 1.0 if theta0 > 0 else -1.0
    lo = -_FLAT if (h == 0.0 or side < 0) else _TINY
    hi = _FLAT if (h == 0.0 or side > 0) else -_TINY
    if not lo < theta0 < hi:
        raise ParameterError(f"theta(0) = {theta0!r} is too close to pi/2 or to 0")
    return theta0, w10, w20, w30, lo, hi


def _turning_sweeps(rough, h, theta0, z0, accel, lo, hi, budget):
    """The sweeps from theta0 down and up to the turning points (or the range's ends):
    ``((a, kind, f), (b, kind, f))``; a start at a turning point sweeps one way only."""
    if z0[2] == 0.0:  # theta0 is a turning point; the motion starts towards accel's sign
        if accel > 0:
            return (theta0, "turn", None), _sweep(rough, h, theta0, z0, hi, budget)
        return _sweep(rough, h, theta0, z0, lo, budget), (theta0, "turn", None)
    return _sweep(rough, h, theta0, z0, lo, budget), _sweep(rough, h, theta0, z0, hi, budget)


def _open_end(fit, rough, h, theta0, s, end_kind, a, b, base):
    """The ExactMotion of an orbit that ends (lift-off: the first zero of F_z, eq. 11, along
    the motion; or an end of the range: edge contact, fell flat), or None if it is bounded.
    ``s``: the sign of the motion's start."""
    xs = np.cos(np.linspace(0.0, np.pi, 4001))[::-1]
    th = fit.m + fit.d * xs
    Fz = _orbit_normal_force(rough, h, th, *fit.functions(th))
    roots = [_root(lambda x: float(_orbit_normal_force(
        rough, h, np.array(x), *fit.functions(np.array(x)))), th[i], th[i + 1])
        for i in np.nonzero(np.sign(Fz[:-1]) * np.sign(Fz[1:]) < 0)[0]]
    near, far = (b, a) if s > 0 else (a, b)
    ahead = [r for r in roots if (r - theta0) * s > 0]
    behind = [r for r in roots if (r - theta0) * s <= 0]
    if ahead:
        theta_end = min(ahead, key=lambda r: abs(r - theta0))
        legs, status = [(theta0, theta_end)], "lift-off"
    elif end_kind[near] != "turn":
        legs, status, theta_end = [(theta0, near)], end_kind[near], near
    elif behind:
        theta_end = min(behind, key=lambda r: abs(r - theta0))
        legs, status = [(theta0, near), (near, theta_end)], "lift-off"
    elif end_kind[far] != "turn":
        legs, status, theta_end = [(theta0, near), (near, far)], end_kind[far], far
    else:
        return None
    t_end = float(sum(_leg_time(fit, p, r) for p, r in legs))
    visited = [0.0 if abs(p) == _TINY else p for leg in legs for p in leg]
    if status == "edge-contact":
        theta_end = 0.0
    elif status == "fell-flat":
        theta_end = math.copysign(0.5 * math.pi, theta_end)
    return ExactMotion(status=status, theta_min=float(min(visited)),
                       theta_max=float(max(visited)), period=None, delta_psi=None,
                       delta_phi=None, drift=None, t_end=t_end, theta_end=theta_end,
                       _fit=fit, **base)


def _end_kind(h, theta, kind):
    if kind == "turn":
        return "turn"
    return "fell-flat" if abs(theta) > 1.0 else "edge-contact"


def _root(f, lo, hi):
    from scipy.optimize import brentq

    return float(brentq(f, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps))


def _steady_result(base, rough, h, theta0, w20, w30):
    from rollingdisk.theory.oscillations import varpi2_closed_form

    varpi2 = float(varpi2_closed_form(h, base["ground"], theta0, w20, w30))
    period = 2.0 * math.pi / math.sqrt(varpi2) if varpi2 > 0 else None
    orbit = _SteadyOrbit(rough, h, base["y0"], base["ground"])
    dpsi = None if period is None else orbit.Omega * period
    dphi = None if period is None else orbit.omega * period
    drift = None
    if period is not None:
        from rollingdisk.model.equations import contact_point

        P = contact_point(base["disk"], base["ground"], orbit.state(np.array([0.0, period])).T)
        drift = (float(P[0][1] - P[0][0]), float(P[1][1] - P[1][0]))
    return ExactMotion(status="steady", theta_min=theta0, theta_max=theta0, period=period,
                       delta_psi=dpsi, delta_phi=dphi, drift=drift, t_end=None,
                       theta_end=None, _orbit=orbit, **base)


def exact_steady(motion, *, perturb: float = 0.0, kick: float = 0.0, psi0: float = 0.0,
                 phi0: float = 0.0, **budget) -> ExactMotion:
    """The exact motion from a steady motion with ``theta(0)`` and/or ``omega1(0)``
    perturbed, exactly as :func:`rollingdisk.simulate_steady` starts it.

    ``perturb`` (rad) and ``kick`` (``sqrt(g/a)``) are added to ``theta(0)`` and
    ``omega1(0)``; ``psi0``, ``phi0`` (rad) start the angles; ``budget`` is
    ``time_limit``, ``max_evals``, ``max_terms`` of :func:`exact_motion`."""
    from rollingdisk.theory.steady import SteadyMotion

    if not isinstance(motion, SteadyMotion):
        raise ParameterTypeError(f"motion must be a SteadyMotion, got {type(motion).__name__}")
    _check_budget_keys(budget)
    perturb = check_real("perturb", perturb)
    kick = check_real("kick", kick)
    psi0 = check_real("psi0", psi0)
    phi0 = check_real("phi0", phi0)
    with np.errstate(all="ignore"):
        y0 = np.array(motion.initial_state(psi0, phi0), dtype=float)
        y0[state_index(motion.ground, "theta")] += perturb
        y0[state_index(motion.ground, "omega1")] += kick
    return exact_motion(motion.disk, motion.ground, y0, **budget)
