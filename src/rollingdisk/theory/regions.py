"""Where steady circles exist and are stable: class codes, the surface varpi^2 = 0, examples.

The maps of the paper's Figures 4-8 and of the atlas are drawn by
:mod:`rollingdisk.plotting.plots`; what they show is computed here, in the numeric core, from
:mod:`rollingdisk.theory.steady` (eq. 31) and :mod:`rollingdisk.theory.oscillations` (eqs. 45, 47,
55):

* :func:`existence_codes`: for the rough steady circle of given ``(theta0, r_C)``, is there
  one (``Omega0^2 > 0``) and is it stable (``varpi^2 > 0``)?  Class codes
  :data:`NO_MOTION`, :data:`UNSTABLE`, :data:`STABLE` (Figure 4);
* :func:`varpi2_zero_surface`: the roots ``omega30 > 0`` of ``varpi^2 = 0`` (Figures 6, 8);
* :func:`example_motions`: one clearly stable and one clearly unstable steady circle of a
  disk, the two motions the atlas simulates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.disk import Disk, check_ground, check_h, h_of
from rollingdisk.theory._points import at_a_point
from rollingdisk.theory.steady import SteadyMotion
from rollingdisk.util.checks import real_array
from rollingdisk.util.errors import ParameterError

__all__ = ["NO_MOTION", "UNSTABLE", "STABLE", "existence_codes", "varpi2_zero_surface",
           "ExampleMotions", "example_motions"]

#: Class codes of :func:`existence_codes`: no steady motion (``Omega0^2 <= 0``), a steady
#: motion with ``varpi^2 < 0`` (unstable), a steady motion with ``varpi^2 > 0`` (stable).
NO_MOTION, UNSTABLE, STABLE = 0, 1, 2


def existence_codes(h: float, theta0, r_C) -> np.ndarray:
    """Class codes of the rough-ground steady circle with given ``theta0`` and ``r_C``.

    Parameters
    ----------
    h : float
        Half-thickness, ``0 <= h <= 1e8``.
    theta0, r_C : float or array_like
        Tilt [rad] and signed radius of the circle of C; broadcast together.

    Returns
    -------
    ndarray of int8
        :data:`NO_MOTION` where ``Omega0^2`` of eq. (31) (corrected) is not positive (or
        outside ``|theta0| < pi/2``), else :data:`STABLE` or :data:`UNSTABLE` by the sign
        of ``varpi^2`` (eq. 45 at the ``omega30`` of that circle, the eq. (47) route).

    Examples
    --------
    >>> existence_codes(0.0, [0.1, 1.0], 0.75).tolist()  # a thin disk on a wide circle
    [1, 2]
    """
    from rollingdisk.theory.oscillations import varpi2_rough_rC
    from rollingdisk.theory.steady import Omega0_sq

    h = check_h(h)
    theta0, r_C = np.broadcast_arrays(real_array("theta0", theta0), real_array("r_C", r_C))
    with np.errstate(all="ignore"):
        O2 = np.asarray(Omega0_sq(h, theta0, r_C), float)
        exists = np.isfinite(O2) & (O2 > 0)
        v2 = np.asarray(varpi2_rough_rC(h, theta0, r_C), float)
    codes = np.full(theta0.shape, NO_MOTION, dtype=np.int8)
    codes[exists] = UNSTABLE
    codes[exists & np.isfinite(v2) & (v2 > 0)] = STABLE
    return codes


@at_a_point(("h", "theta0"))
def varpi2_zero_surface(h, ground: str, theta0):
    """The roots ``omega30 > 0`` of ``varpi^2 = 0`` (eqs. 45 / 55) at each ``(h, theta0)``.

    Parameters
    ----------
    h, theta0 : float or array_like
        Half-thickness and tilt [rad]; broadcast together.
    ground : {"rough", "smooth"}

    Returns
    -------
    (lower, upper) : tuple of float or ndarray
        ``omega30`` of the lower and the upper sheet (the square roots of
        :func:`rollingdisk.critical_omega30_sq`); NaN where there is no positive root (an
        answer, kept at a single point too).  Outside ``0 <= h <= 1e8, |theta0| < pi/2``
        a single point (scalars in) is a :class:`~rollingdisk.ParameterError`.
        Steady circles with ``lower < |omega30| < upper`` are unstable.

    Examples
    --------
    >>> lower, upper = varpi2_zero_surface(0.0, "smooth", 1e-6)  # section 4.2: h = 0
    >>> round(float(upper), 4)
    2.0
    """
    from rollingdisk.theory.oscillations import critical_omega30_sq

    check_ground(ground)
    lower, upper = critical_omega30_sq(real_array("h", h_of(h)), ground,
                                       real_array("theta0", theta0))
    with np.errstate(all="ignore"):
        return np.sqrt(np.where(lower > 0, lower, np.nan))[()], np.sqrt(upper)[()]


@dataclass(frozen=True)
class ExampleMotions:
    """Two steady circles of one disk on rough ground (:func:`example_motions`).

    Attributes
    ----------
    stable : SteadyMotion
        ``varpi^2 > 0``.
    unstable : SteadyMotion
        ``varpi^2 < 0``, with a growth rate ``sqrt(-varpi^2)`` near 0.35.
    """

    stable: SteadyMotion
    unstable: SteadyMotion


#: Growth rate aimed at by the unstable example: fast enough to show within a short
#: simulation, slow enough to be seen starting from the steady motion.
EXAMPLE_GROWTH_RATE = 0.35


def example_motions(h: float) -> ExampleMotions:
    """One clearly stable and one clearly unstable steady circle on rough ground.

    Parameters
    ----------
    h : float
        Half-thickness, ``0 <= h <= 1e8``.

    Returns
    -------
    ExampleMotions
        Stable: ``theta0 = 0.5`` rad with ``omega30 = 1.5``, above the uniform bound
        ``omega30^2 > 1`` of the paper's conclusion (confirmed, docs/errata.md), so stable
        for every ``h``.  Unstable: on a grid of ``theta0`` in ``[0.05, 1.4]`` and
        ``omega30`` in ``[0.15, 2]``, the circle with ``varpi^2 < 0`` (eq. 45) whose growth
        rate is closest to :data:`EXAMPLE_GROWTH_RATE`.

    Raises
    ------
    ParameterError
        If the grid holds no unstable circle for this ``h``.

    Examples
    --------
    >>> m = example_motions(0.17)
    >>> m.stable.theta0, m.unstable.Omega0 > 0
    (0.5, True)
    """
    from rollingdisk.theory.oscillations import varpi2_circle
    from rollingdisk.theory.steady import steady_motion

    disk = h if isinstance(h, Disk) else Disk(check_h(h))  # a Disk keeps its scale
    h = disk.h
    th = np.linspace(0.05, 1.4, 55)
    w = np.linspace(0.15, 2.0, 38)
    TH, W = np.meshgrid(th, w)
    with np.errstate(all="ignore"):
        v2 = np.asarray(varpi2_circle(h, "rough", TH, W), float)
        score = np.where(np.isfinite(v2) & (v2 < 0),
                         -np.abs(np.sqrt(np.abs(v2)) - EXAMPLE_GROWTH_RATE), -np.inf)
    i = np.unravel_index(int(np.argmax(score)), score.shape)
    if not np.isfinite(score[i]):
        raise ParameterError(f"h = {h:g}: found no unstable steady circle with theta0 in "
                             "[0.05, 1.4] rad and omega30 in [0.15, 2]")
    th_u, w_u = float(TH[i]), float(W[i])
    th_s, w_s = 0.5, 1.5
    return ExampleMotions(
        stable=steady_motion(disk, "rough", th_s, Omega0=w_s / math.cos(th_s)),
        unstable=steady_motion(disk, "rough", th_u, Omega0=w_u / math.cos(th_u)))
