"""The backbone curve: the exact nutation period and frequency against amplitude about one
steady motion, which tends to ``varpi`` (eq. 39) at zero amplitude.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rollingdisk.theory.exact.inputs import _check_budget_keys, _real_array
from rollingdisk.theory.exact.solve import exact_steady
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["Backbone", "backbone"]


@dataclass(frozen=True)
class Backbone:
    """Nutation period and frequency against amplitude about one steady motion.

    Attributes
    ----------
    kick : numpy.ndarray
        The ``omega1(0)`` kicks.
    amplitude, theta_min, theta_max, period, frequency : numpy.ndarray
        Per kick (``nan`` where the orbit is not bounded; see ``status``).
    status : tuple of str
    varpi : float
        Linear frequency of eq. (39)/(50) (nan if unstable): the limit of ``frequency``.
    """

    kick: np.ndarray
    amplitude: np.ndarray
    theta_min: np.ndarray
    theta_max: np.ndarray
    period: np.ndarray
    frequency: np.ndarray
    status: tuple
    varpi: float


def backbone(motion, kicks, **budget) -> Backbone:
    """Exact nutation period and frequency against amplitude (kicks ``omega1(0)``) about a
    steady motion: the backbone curve, which tends to ``varpi`` (eq. 39) at zero
    amplitude.  ``budget`` (``time_limit``, ``max_evals``, ``max_terms``) applies to each
    kick's exact motion; a kick whose quadrature is not-converged gets NaN."""
    from rollingdisk.theory.oscillations import stability
    from rollingdisk.theory.steady import SteadyMotion

    if not isinstance(motion, SteadyMotion):
        raise ParameterTypeError(f"motion must be a SteadyMotion, got {type(motion).__name__}")
    _check_budget_keys(budget)
    kicks = _real_array("kicks", kicks, max_size=10_000).ravel()
    if kicks.size == 0 or not np.all(np.isfinite(kicks)):
        raise ParameterError("kicks must be a non-empty array of finite numbers")
    rows = [exact_steady(motion, kick=float(k), **budget) for k in kicks]

    def col(name):
        return np.array([np.nan if getattr(r, name) is None else getattr(r, name)
                         for r in rows], float)

    ok = np.array([r.status == "bounded" for r in rows])
    amp = np.where(ok, [r.amplitude for r in rows], np.nan)
    return Backbone(kick=kicks, amplitude=amp, theta_min=np.where(ok, col("theta_min"), np.nan),
                    theta_max=np.where(ok, col("theta_max"), np.nan),
                    period=col("period"), frequency=np.where(ok, 2 * np.pi / col("period"),
                                                             np.nan),
                    status=tuple(r.status for r in rows),
                    varpi=float(stability(motion).varpi))
