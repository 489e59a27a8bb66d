"""The disk lying on a face: Coulomb friction under uniform pressure in closed form, and
the sliding and spinning it brings to rest.

A flat disk (radius a = 1, mass m = 1, g = 1) slides with velocity ``V`` of its centre and
spins with ``Omega`` about the vertical; the pressure is uniform, ``p = 1/pi``, and each
point's friction opposes its slip ``w = V + Omega z x r`` (Coulomb).  For ``Omega != 0``
the slip field is a rotation about the instantaneous centre ``r0`` (``|r0| = eps = |V| /
|Omega|``, a across V): in polar coordinates ``(s, alpha)`` about ``r0`` the friction at
each point is ``mu p z x u(alpha)`` and both integrals reduce to one over ``alpha`` with
the chord ``S(alpha)`` of the disk, which are complete elliptic integrals.  With
``q(alpha) = sqrt(1 - eps^2 sin^2 alpha)``:

- force (along ``-V``): ``f = (eps/pi) int_0^{2 pi} cos^2 alpha q dalpha`` for ``eps < 1``
  and ``(2 eps/pi) int_{-beta}^{beta} cos^2 alpha q dalpha`` (``sin beta = 1/eps``) for
  ``eps > 1``;
- torque (against the spin): ``tau = (1/(3 pi)) int_0^{2 pi} q^3 dalpha`` and
  ``(2/(3 pi)) int_{-beta}^{beta} q^3 dalpha``.

In Legendre's complete integrals ``K(m), E(m)`` (parameter ``m``, scipy's convention):

- ``eps < 1``, ``m = eps^2``: ``f = 4 ((1 + m) E - (1 - m) K) / (3 pi eps)``,
  ``tau = 4 (2 (2 - m) E - (1 - m) K) / (9 pi)`` (Farkas, Bartels, Unger & Wolf, PRL 90,
  248302 (2003), for the force);
- ``eps > 1``, ``m = 1/eps^2``: ``f = 4 ((1 + m) E - (1 - m) K) / (3 pi m)``,
  ``tau = 4 J4(m) / (3 pi eps)`` with ``J4(m) = int_0^{pi/2} cos^4 t / sqrt(1 - m sin^2 t)
  dt``;
- ``eps = 1``: ``f = 8/(3 pi)``, ``tau = 8/(9 pi)``; ``eps -> 0``: ``f -> eps``, ``tau ->
  2/3`` (pure spin); ``eps -> inf``: ``f -> 1``, ``tau -> 1/(4 eps)`` (pure sliding).

``tests/test_flat.py`` checks them against the alpha-integrals by mpmath at 30 digits.
Where a form cancels (``m -> 0``) it is evaluated without cancellation: ``((1 + m) E - (1 -
m) K) / (3 m) = (E + K - D) / 3`` with ``D = (K - E)/m = R_D(0, 1 - m, 1)/3`` (Carlson), and
``J4`` by its power series in ``m``.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import ellipe, ellipk, elliprd

from rollingdisk.model.geometry import K2
from rollingdisk.util.checks import check_real

__all__ = ["flat_friction", "flat_run"]



def _cos2_delta(m: float) -> float:
    """``int_0^{pi/2} cos^2 t sqrt(1 - m sin^2 t) dt = ((1 + m) E - (1 - m) K) / (3 m)``."""
    if m < 0.5:
        return (ellipe(m) + ellipk(m) - elliprd(0.0, 1.0 - m, 1.0) / 3.0) / 3.0
    return ((1.0 + m) * ellipe(m) - (1.0 - m) * ellipk(m)) / (3.0 * m)


def _j4(m: float) -> float:
    """``int_0^{pi/2} cos^4 t / sqrt(1 - m sin^2 t) dt`` for ``0 < m < 1``."""
    if m >= 0.5:
        K, E = ellipk(m), ellipe(m)
        return K - 2.0 * (K - E) / m + ((2.0 + m) * K - 2.0 * (1.0 + m) * E) / (3.0 * m * m)
    # sum_n C(2n, n)/4^n m^n int sin^2n cos^4, the integrals 3 pi/16 * prod (2k+1)/(2k+6)
    term, total, n = 3.0 * math.pi / 16.0, 0.0, 0
    while True:
        total += term
        term *= m * (2 * n + 1) / (2 * n + 2) * (2 * n + 1) / (2 * n + 6)
        n += 1
        if term < 1e-17 * total:
            return total + term


def flat_friction(speed: float, spin: float) -> tuple[float, float]:
    """Friction on a flat disk sliding and spinning on its face, per unit ``mu m g``.

    Parameters
    ----------
    speed : float
        ``|V| >= 0`` of the centre [``sqrt(a g)``].
    spin : float
        ``Omega >= 0`` about the vertical [``sqrt(g/a)``].

    Returns
    -------
    (f, tau) : (float, float)
        The force opposes ``V`` with magnitude ``mu m g f`` and the torque opposes the
        spin with magnitude ``mu m g a tau``.

    Notes
    -----
    Uniform pressure ``p = m g/(pi a^2)`` and Coulomb friction at each point against its
    slip ``w = V + Omega z x r``: ``F = -mu int p w/|w| dA``, ``T = -mu int p r x w/|w| dA``.
    By the mirror symmetry across ``V`` the force has no component across ``V``.  In closed
    form by complete elliptic integrals of ``eps = |V| / (a Omega)`` (the module's notes);
    the limits ``f = 1, tau = 0`` for pure sliding and ``f = 0, tau = 2/3`` for pure spin.

    Examples
    --------
    >>> flat_friction(1.0, 0.0), [round(x, 6) for x in flat_friction(0.0, 1.0)]
    ((1.0, 0.0), [0.0, 0.666667])
    >>> [round(x, 12) for x in flat_friction(1.0, 1.0)]  # 8/(3 pi), 8/(9 pi)
    [0.848826363157, 0.282942121052]
    """
    v = check_real("speed", speed, low=0.0)
    om = check_real("spin", spin, low=0.0)
    if om == 0.0:
        return (1.0 if v > 0.0 else 0.0), 0.0
    if v == 0.0:
        return 0.0, 2.0 / 3.0
    eps = v / om
    if eps == 1.0:
        return 8.0 / (3.0 * math.pi), 8.0 / (9.0 * math.pi)
    if eps < 1.0:
        m = eps * eps
        f = 4.0 * eps / math.pi * _cos2_delta(m)
        tau = 4.0 / (9.0 * math.pi) * (2.0 * (2.0 - m) * ellipe(m) - (1.0 - m) * ellipk(m))
    else:
        m = 1.0 / (eps * eps)
        if m == 0.0:  # eps beyond floating-point range of its square
            return 1.0, 1.0 / (4.0 * eps)
        f = 4.0 / math.pi * _cos2_delta(m)
        tau = 4.0 / (3.0 * math.pi) * _j4(m) / eps
    return float(f), float(tau)


def flat_run(mu, speed, spin, t0, t1):
    """Integrate ``dV/dt = -mu f``, ``k2 dOmega/dt = -mu tau`` from ``(speed, spin)`` until
    both vanish or ``t1``; returns ``t, V, Omega, D, distance, angle``."""
    from scipy.integrate import solve_ivp

    if mu == 0.0 or (speed == 0.0 and spin == 0.0):
        T = t1 - t0 if mu == 0.0 else 0.0
        t = np.array([t0, t0 + T])
        return (t, np.array([speed, speed]), np.array([spin, spin]), np.zeros(2),
                speed * T, spin * T)

    def rhs(t, z):
        v, om = max(z[0], 0.0), max(z[1], 0.0)
        f, tau = flat_friction(v, om)
        return [-mu * f, -mu * tau / K2, mu * (f * v + tau * om), v, om]

    def stop_v(t, z):
        return z[0]

    def stop_w(t, z):
        return z[1]

    stop_v.terminal = stop_w.terminal = True
    stop_v.direction = stop_w.direction = -1
    events = [e for e, x in ((stop_v, speed), (stop_w, spin)) if x > 0.0]
    z0 = [speed, spin, 0.0, 0.0, 0.0]
    if speed == 0.0 or spin == 0.0:  # the classic closed forms: f = 1 or tau = 2/3
        rate = mu if spin == 0.0 else mu * (2.0 / 3.0) / K2
        x0 = speed if spin == 0.0 else spin
        T = min(x0 / rate, t1 - t0)
        ts = np.linspace(0.0, T, 9)
        x = x0 - rate * ts
        scale = 1.0 if spin == 0.0 else K2
        D = 0.5 * scale * (x0 * x0 - x * x)
        dist = x0 * T - 0.5 * rate * T * T
        zero = np.zeros_like(ts)
        return (t0 + ts, x if spin == 0.0 else zero, zero if spin == 0.0 else x, D,
                dist if spin == 0.0 else 0.0, 0.0 if spin == 0.0 else dist)
    sol = solve_ivp(rhs, (t0, t1), z0, method="DOP853", rtol=1e-10, atol=1e-13,
                    events=events)
    t, Z = sol.t, sol.y
    V, W, D = np.maximum(Z[0], 0.0), np.maximum(Z[1], 0.0), Z[2].copy()
    if sol.status != 1:
        return t, V, W, D, Z[3, -1], Z[4, -1]
    # one of them vanished (to rounding); on that invariant line the other ends by its
    # closed form (f = 1 or tau = 2/3); the rounding remainder counts as dissipated
    v_hit = events[0] is stop_v and sol.t_events[0].size > 0
    if v_hit:
        D[-1] += 0.5 * Z[0, -1] ** 2
        V[-1] = 0.0
        x0, rate, scale = W[-1], mu * (2.0 / 3.0) / K2, K2
    else:
        D[-1] += 0.5 * K2 * Z[1, -1] ** 2
        W[-1] = 0.0
        x0, rate, scale = V[-1], mu, 1.0
    T = min(x0 / rate, t1 - t[-1])
    x = max(x0 - rate * T, 0.0) if T < t1 - t[-1] else x0 - rate * T
    more = x0 * T - 0.5 * rate * T * T
    t = np.append(t, t[-1] + T)
    V = np.append(V, 0.0 if v_hit else x)
    W = np.append(W, x if v_hit else 0.0)
    D = np.append(D, D[-1] + 0.5 * scale * (x0 * x0 - x * x))
    if T >= x0 / rate:
        V[-1] = W[-1] = 0.0
    return (t, V, W, D, Z[3, -1] + (0.0 if v_hit else more),
            Z[4, -1] + (more if v_hit else 0.0))
