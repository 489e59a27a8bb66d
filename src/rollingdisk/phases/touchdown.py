"""When a free flight comes down: :func:`~rollingdisk.phases.flight.touchdown_time`, and
where its conservative advancement stalls, a scan that holds the run's wall-clock budget.

The scan is a grid of the closed-form height of the lowest point (:func:`free_flight`),
``brentq`` on its first sign change.  A long flight of a tall or fast-spinning disk has
millions of grid points (minutes of Python): the scan looks at the clock every
:data:`SCAN_BLOCK` heights and raises :class:`Spent` past the run's deadline, which the
motion (:mod:`rollingdisk.phases.motion`) ends with status ``time-budget``.
"""

from __future__ import annotations

import math
import time

import numpy as np

from rollingdisk.phases.flight import _lowest_height, free_flight, touchdown_time

__all__ = ["Spent", "touchdown", "SCAN_BLOCK"]

#: Heights the scan evaluates between two looks at the wall clock (~20 ms).
SCAN_BLOCK = 1024


class Spent(Exception):  # noqa: N818 - a state: the wall budget ran out in the scan
    """The wall-clock deadline passed during the scan; ``str()`` is the flight time it had
    searched to."""


def touchdown(disk, s, deadline: float = math.inf) -> float:
    """The time to touchdown of the free state ``s`` [``sqrt(a/g)``].

    :func:`touchdown_time`; where its conservative advancement stalls on a grazing
    flight (the lowest point skimming the plane), a scan of the closed-form height on a
    grid of steps ``<= 0.1/(1 + |omega|)`` and ``brentq`` on the first sign change.

    Raises
    ------
    Spent
        ``time.perf_counter()`` passed ``deadline`` during the scan.
    """
    try:
        return touchdown_time(disk, s, inside_tol=1e-9)
    except RuntimeError:
        pass
    from scipy.optimize import brentq

    h = disk.h

    def H(t):
        x = free_flight(disk, s, t)
        return _lowest_height(h, x[2], x[4])

    V, Z = s[8], s[2]
    T = V + math.sqrt(V * V + 2.0 * max(Z - min(1.0, h), 0.0)) + 1e-9
    dt = 0.1 / (1.0 + float(np.linalg.norm(s[9:12])))
    ts = np.arange(0.0, T + dt, dt)
    for i in range(1, ts.size):
        if i % SCAN_BLOCK == 0 and time.perf_counter() > deadline:
            raise Spent(f"{float(ts[i]):.12g}")
        if H(ts[i]) <= 0.0:
            return brentq(H, ts[i - 1], ts[i], xtol=1e-15, rtol=8.9e-16)
    return float(ts[-1])
