"""The linear system in ``theta`` of an exact motion and its integration: the coefficients
``D1, D2, D3`` taken from the kernels of eqs. (38)/(49), the theta-ODE swept from
``theta(0)`` to a turning point or an end of the range, and the work budget that bounds
it all.
"""

from __future__ import annotations

import math
import time

import numpy as np

from rollingdisk.model.equations import rough_omega_dot, smooth_omega_dot
from rollingdisk.util.errors import ParameterError

__all__ = ["TIME_LIMIT", "MAX_EVALS", "MAX_TERMS"]

#: Default work budget of one exact motion: wall-clock seconds, right-hand-side
#: evaluations of the theta-ODE, Fourier terms per period.
TIME_LIMIT, MAX_EVALS, MAX_TERMS = 5.0, 200_000, 1 << 17
_EPS = float(np.finfo(float).eps)

_RTOL = 1e-13  # the theta-ODE's tolerance
_FLAT = 0.5 * math.pi - 1e-9  # |theta| where the theta-ODE stops: the disk lies flat
_TINY = 1e-300  # theta "= 0" on the side of the motion (h~ keeps its sign)


def _theta_coefficients(rough: bool, h: float, theta, w2, w3):
    """``(D1 at q=0, dD1/dq, D2, D3)``: eq. (38)/(49) at ``omega1 = 0`` and ``1``.

    ``dD1/dq``, the coefficient of ``omega1^2`` in ``d omega1/dt``, depends on ``theta``
    alone (sympy: ``tests/test_exact_edges.py``), so it is taken at ``omega2 = omega3 = 0``:
    as the difference of the kernel at ``omega1 = 1`` and ``0`` with the orbit's rates it
    lost ``eps (omega2^2 + omega3^2)`` to cancellation, noise that (times ``q``) stalled the
    theta-ODE at rates ~1e5."""
    kernel = rough_omega_dot if rough else smooth_omega_dot
    zero, one = 0.0 * theta, 1.0 + 0.0 * theta
    a1 = kernel(h, theta, zero, w2, w3)[0]
    _, b2, b3 = kernel(h, theta, one, w2, w3)
    c1 = kernel(h, theta, one, zero, zero)[0] - kernel(h, theta, zero, zero, zero)[0]
    return a1, c1, b2, b3


class _BudgetSpent(Exception):
    """The work budget of one exact motion is spent (message says which part)."""


class _Budget:
    """Work budget of one exact motion: a wall-clock deadline, a number of right-hand-side
    evaluations of the theta-ODE and a largest Fourier length."""

    def __init__(self, time_limit: float, max_evals: int, max_terms: int):
        self.time_limit, self.max_evals, self.max_terms = time_limit, max_evals, max_terms
        self.deadline = time.monotonic() + time_limit
        self.evals = 0

    def clock(self, where: str) -> None:
        if time.monotonic() > self.deadline:
            raise _BudgetSpent(f"time_limit = {self.time_limit:g} s was spent in {where}")

    def count(self, theta: float) -> None:
        self.evals += 1
        if self.evals > self.max_evals:
            raise _BudgetSpent(f"max_evals = {self.max_evals} evaluations were spent in "
                               f"{self._where(theta)}")
        if self.evals % 64 == 0 and time.monotonic() > self.deadline:
            self.clock(self._where(theta))

    @staticmethod
    def _where(theta: float) -> str:
        return (f"the quadrature in theta (stuck at theta = {theta:.10g}, "
                f"{0.5 * math.pi - abs(theta):.3g} from flat)")


def _theta_rhs(rough: bool, h: float, budget: _Budget | None = None):
    def f(theta, z):
        if budget is not None:
            budget.count(float(theta))
        w2, w3, q = z
        a1, c1, d2, d3 = _theta_coefficients(rough, h, theta, w2, w3)
        return [d2, d3, 2.0 * (a1 + c1 * q)]
    return f


def _q_event(theta0: float):
    """``q``, the event that ends a sweep at a turning point; ``+1`` at ``theta0`` itself,
    so that a start exactly at a turning point (``q = 0``) is not taken for the end when
    the first step already passes the other one (an amplitude below the step)."""
    def event(theta, z):
        return 1.0 if theta == theta0 else z[2]
    event.terminal = True
    event.direction = -1.0
    return event


def _sweep(rough, h, theta0, z0, end, budget):
    """Integrate the theta-ODE from ``theta0`` to ``end``, stopping where ``q`` falls to 0.

    Returns ``(theta_reached, kind, sol)``; ``kind`` is ``"turn"`` or ``"end"``.

    The absolute tolerances sit just below the rounding floor of the right-hand side:
    ``D1`` is a sum of terms of size ``S = 1 + omega2^2 + omega3^2 + q`` that cancel near a
    steady motion, so it carries noise ``~ eps S``; an absolute tolerance of ``1e-30`` (with
    ``q ~ 1e-12`` at an amplitude of 1e-6) made the error estimate see that noise and cut
    the step to 1e-15 in theta, for ever.  With ``atol = 1e-6 eps S`` noise alone limits a
    step to ~1e-6, and the error accumulated over a sweep is the rounding floor itself."""
    from scipy.integrate import solve_ivp

    if theta0 == end:
        return theta0, "end", None
    S = 1.0 + z0[0] * z0[0] + z0[1] * z0[1] + z0[2]
    atol = [1e-6 * _EPS * math.sqrt(S)] * 2 + [1e-6 * _EPS * S]
    sol = solve_ivp(_theta_rhs(rough, h, budget), (theta0, end), z0, method="DOP853",
                    rtol=_RTOL, atol=atol, dense_output=True, events=_q_event(theta0))
    if sol.status < 0:
        raise ParameterError(f"the quadrature in theta failed ({sol.message}); the state "
                             "is outside what the exact solution can follow")
    if sol.status == 1:
        return float(sol.t_events[0][0]), "turn", sol.sol
    return float(sol.t[-1]), "end", sol.sol


# ---------------------------------------------------------------------------------------
