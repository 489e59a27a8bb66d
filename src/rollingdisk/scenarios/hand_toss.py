"""The hand toss: a launch in the variables people use, caught in the hand or landing on a table.

The launch (the variables of Diaconis, Holmes & Montgomery, SIAM Rev. 49 (2007) 211, "DHM"):
the coin leaves the hand flat and heads up (its normal, the axis eta, along +Z: the
library's ``theta = +pi/2``), its centre at height ``height`` [``a``] moving up at
``upward_speed`` [``sqrt(a g)``]; it turns with angular speed ``flip_rate`` [``sqrt(g/a)``]
about an axis such that its angular momentum ``L`` (about the centre) makes the angle
``psi`` with the normal.  ``psi = pi/2`` is Keller's pure flip; ``psi < pi/2`` wobbles.

Free flight is torque-free: ``L`` is fixed in space.  With the inertia of eq. (10),
``J = k1^2 (1 - n n^T) + k2^2 n n^T`` (``k1^2 = 1/4 + h^2/3`` about a diameter, ``k2^2 =
1/2`` about the axis ``n``), ``omega = J^-1 L = L/k1^2 + (1/k2^2 - 1/k1^2)(L.n) n``, so

    dn/dt = omega x n = (L/k1^2) x n:

the normal precesses about ``L`` at the constant angle ``psi`` with the rate
``Omega_p = |L|/k1^2`` (the rate :func:`rollingdisk.phases.flight.free_flight` turns the body
about ``L``).  Starting from ``n(0) = Z`` with ``L`` in the (X, Z) plane,

    n_Z(t) = cos^2 psi + sin^2 psi cos(Omega_p t),                                (H1)

and the flip rate fixes ``Omega_p``: ``|omega|^2 = |L|^2 (sin^2 psi / k1^4 + cos^2 psi /
k2^4)``, so ``Omega_p = |omega| / sqrt(sin^2 psi + (k1^2/k2^2)^2 cos^2 psi)``.       (H2)

Two endings:

* **caught** in the hand at the catch height (default: the release height): the side up at
  the catch is the sign of ``n_Z(T)``, ``T`` the flight time (free flight alone).  Over a
  long uniform spread of flight times the phase ``Omega_p T`` is uniform mod ``2 pi`` and the
  coin shows its starting side for the fraction of phases with ``cos phi > -cot^2 psi``:

      p(psi) = arccos(-cot^2 psi)/pi  (psi >= pi/4),  1  (psi < pi/4),           (H3)

  which is DHM's ``1/2 + arcsin(cot^2 psi)/pi`` (``arccos(-x) = pi/2 + arcsin x``);
* **table**: the launch is handed to :func:`rollingdisk.scenarios.toss.toss_ensemble` (flight,
  bounces, rolling, sliding, rest on the table, ``docs/motion.md``).

Units m = a = g = 1; ``docs/motion.md`` ("The hand toss") has the numbers.
"""

from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass, field

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.equations import check_disk
from rollingdisk.scenarios.toss import EnsembleResult, TossDistribution, toss_ensemble
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["HandLaunch", "precession_rate", "launch_state", "normal_z",
           "same_side_probability", "CaughtResult", "caught_ensemble", "HandTossDistribution",
           "table_ensemble", "ENDINGS"]

#: How a hand toss ends: caught in the hand, or landing on the table.
ENDINGS = ("caught", "table")
_HALF_PI = 0.5 * math.pi
#: Largest launch value accepted, in the paper's units (far beyond any toss).
_BIG = 1e8


@dataclass(frozen=True)
class HandLaunch:
    """A hand toss: the launch variables and their spread.

    Attributes
    ----------
    height : float
        Height of the centre at release [``a``], ``>= 0`` (above the table for the
        ``table`` ending, which needs ``height >= h``).
    upward_speed : float
        Vertical speed of the centre at release [``sqrt(a g)``].
    flip_rate : float
        Angular speed ``|omega|`` at release [``sqrt(g/a)``], ``>= 0``.
    psi : float
        Angle between the angular momentum and the coin's normal [rad], in ``[0, pi/2]``
        (``pi/2``: a pure flip).
    psi_spread : float
        Standard deviation of ``psi`` [rad], ``>= 0``: ``psi`` is drawn normal and folded
        into ``[0, pi/2]`` (``|x|`` then ``pi - x``, period ``pi``: the angle between two
        lines), which keeps the flips' symmetry ``psi <-> pi - psi``.
    flip_rate_spread, upward_speed_spread : float
        Half-widths of the uniform spreads of the flip rate and the upward speed, ``>= 0``;
        a flip rate drawn below 0 is reflected (``|w|``).
    catch_height : float or None
        Height of the centre at the catch [``a``] (``caught``); ``None``: the release height.

    Notes
    -----
    The defaults are an *assumption* of this library, not a measurement: a pure flip in the
    mean with a normal wobble of 10 degrees (``psi_spread = pi/18``), about 8 ``sqrt(g/a)``
    (about 37 rev/s for a coin of radius 12 mm) and a flight of about 14 ``sqrt(a/g)``
    (about half a second).
    """

    height: float = 1.5
    upward_speed: float = 7.0
    flip_rate: float = 8.0
    psi: float = _HALF_PI
    psi_spread: float = math.pi / 18.0
    flip_rate_spread: float = 2.0
    upward_speed_spread: float = 1.0
    catch_height: float | None = None

    def __post_init__(self):
        set_ = object.__setattr__
        # bounds far beyond any toss keep every phase Omega_p T finite
        set_(self, "height", check_real("height", self.height, low=0.0, high=_BIG))
        set_(self, "upward_speed", check_real("upward_speed", self.upward_speed, low=-_BIG,
                                              high=_BIG))
        set_(self, "flip_rate", check_real("flip_rate", self.flip_rate, low=0.0, high=_BIG))
        set_(self, "psi", check_real("psi", self.psi, low=0.0, high=_HALF_PI))
        for name in ("psi_spread", "flip_rate_spread", "upward_speed_spread"):
            set_(self, name, check_real(name, getattr(self, name), low=0.0, high=_BIG))
        if self.catch_height is not None:
            set_(self, "catch_height", check_real("catch_height", self.catch_height, low=0.0,
                                                  high=_BIG))

    def describe(self, ending: str = "caught") -> str:
        """One line naming the launch model, its values (paper units) and the ending."""
        if ending not in ENDINGS:
            raise ParameterError(f"ending must be one of {ENDINGS}, got {ending!r}")
        c = "the release height" if self.catch_height is None else f"{self.catch_height:g} a"
        c = f"caught at {c}" if ending == "caught" else "landing on the table"
        return (f"hand toss (DHM variables): heads up at height {self.height:g} a, upward "
                f"speed {self.upward_speed:g} +- {self.upward_speed_spread:g} sqrt(a g) "
                f"(uniform), flip rate {self.flip_rate:g} +- {self.flip_rate_spread:g} "
                f"sqrt(g/a) (uniform), psi {self.psi:.6g} rad normal sd "
                f"{self.psi_spread:.6g} rad folded into [0, pi/2]; {c}")

    def draw(self, n: int, rng: np.random.Generator):
        """``(psi, flip_rate, upward_speed)``, arrays of ``n`` draws from ``rng`` (that order)."""
        psi = self.psi + self.psi_spread * rng.standard_normal(n)
        psi = np.abs(psi) % math.pi
        psi = np.where(psi > _HALF_PI, math.pi - psi, psi)
        w = self.flip_rate + self.flip_rate_spread * (2.0 * rng.random(n) - 1.0)
        v = self.upward_speed + self.upward_speed_spread * (2.0 * rng.random(n) - 1.0)
        return psi, np.abs(w), v

    def flight_time(self, v):
        """Time [``sqrt(a/g)``] from release to the catch height, ``(v + sqrt(v^2 + 2 (H -
        H_c)))`` (``g = 1``), for upward speeds ``v``.

        Raises
        ------
        ParameterError
            If some launch never comes back down to the catch height.
        """
        dz = self.height - (self.height if self.catch_height is None else self.catch_height)
        v = np.asarray(v, dtype=float)
        disc = v * v + 2.0 * dz
        if np.any(disc < 0.0) or np.any((dz == 0.0) & (v <= 0.0)):
            raise ParameterError(
                "upward_speed: every launch of a caught toss must rise and come back to the "
                f"catch height (upward_speed - upward_speed_spread > 0 and >= sqrt(2 "
                f"(catch_height - height))); got {self.upward_speed:g} +- "
                f"{self.upward_speed_spread:g} with the catch {-dz:g} a above the release")
        return v + np.sqrt(disc)


def precession_rate(disk: Disk, flip_rate, psi):
    """``Omega_p``, the rate at which the normal turns about the angular momentum (H2).

    Parameters
    ----------
    disk : Disk
    flip_rate : float or array_like
        ``|omega|`` [``sqrt(g/a)``].
    psi : float or array_like
        Angle between ``L`` and the normal [rad].

    Returns
    -------
    float or ndarray
        ``|omega| / sqrt(sin^2 psi + (k1^2/k2^2)^2 cos^2 psi)`` [``sqrt(g/a)``] with the
        inertia of eq. (10); for a pure flip (``psi = pi/2``) the flip rate itself.

    Examples
    --------
    >>> float(precession_rate(Disk(0.0), 2.0, 0.0))  # k1^2/k2^2 = 1/2: spin about the axis
    4.0
    """
    disk = check_disk(disk)
    psi = np.asarray(psi, dtype=float)
    r = disk.k1_sq / disk.k2_sq
    out = np.asarray(flip_rate, dtype=float) / np.sqrt(np.sin(psi) ** 2
                                                        + (r * np.cos(psi)) ** 2)
    return float(out) if out.ndim == 0 else out


def launch_state(disk: Disk, height: float, upward_speed: float, flip_rate: float,
                 psi: float) -> np.ndarray:
    """The free-body state of a hand launch (:data:`rollingdisk.phases.flight.FREE_STATE`).

    Heads up (``theta = pi/2``: ``xi = X``, ``eta = Z``), ``omega1 = Omega_p sin psi`` about
    ``xi`` and ``omega2 = (k1^2/k2^2) Omega_p cos psi`` about the axis: ``L = |L| (sin psi X +
    cos psi Z)`` with ``|L| = k1^2 Omega_p`` and ``|omega| = flip_rate``.
    """
    disk = check_disk(disk)
    psi = check_real("psi", psi, low=0.0, high=_HALF_PI)
    flip_rate = check_real("flip_rate", flip_rate, low=0.0)
    om = precession_rate(disk, flip_rate, psi)
    return np.array([0.0, 0.0, check_real("height", height, low=0.0), 0.0, _HALF_PI, 0.0,
                     0.0, 0.0, check_real("upward_speed", upward_speed),
                     om * math.sin(psi), disk.k1_sq / disk.k2_sq * om * math.cos(psi), 0.0])


def normal_z(disk: Disk, flip_rate, psi, t):
    """``n_Z(t)`` of a coin launched heads up (H1), vectorised over all arguments."""
    psi = np.asarray(psi, dtype=float)
    om = precession_rate(disk, flip_rate, psi)
    c2 = np.cos(psi) ** 2
    return c2 + (1.0 - c2) * np.cos(om * np.asarray(t, dtype=float))


def same_side_probability(psi):
    """The exact outcome map of the caught toss: the fraction of a long uniform spread of
    flight times for which the starting side is up (H3).

    Parameters
    ----------
    psi : float or array_like
        Angle between the angular momentum and the normal [rad], in ``[0, pi/2]``.

    Returns
    -------
    float or ndarray
        ``arccos(-min(1, cot^2 psi))/pi``: ``1`` for ``psi <= pi/4``, ``1/2`` at ``pi/2``.

    Notes
    -----
    From (H1): the starting side is up while ``cos phi > -cot^2 psi``, ``phi = Omega_p t``
    uniform mod ``2 pi``; the set is ``|phi| < arccos(-cot^2 psi)``.  Equal to DHM's
    ``1/2 + arcsin(cot^2 psi)/pi``; independent of the flip rate and the thickness.
    """
    p = np.asarray(psi, dtype=float)
    if np.any(~np.isfinite(p)) or np.any(p < 0.0) or np.any(p > _HALF_PI):
        raise ParameterError(f"psi must lie in [0, pi/2], got {psi!r}")
    c = np.minimum(1.0, np.cos(p) / np.sin(np.maximum(p, 1e-300)))  # min(1, cot psi) >= 0
    out = np.arccos(-c * c) / math.pi
    return float(out) if out.ndim == 0 else out


@dataclass(frozen=True, eq=False)
class CaughtResult:
    """Caught hand tosses: how often the coin shows the side it started with.

    Attributes
    ----------
    n, seed : int
    same_side : int
        Tosses caught with the starting side up.
    mean_exact : float
        Mean of the exact map (H3) over the drawn ``psi``: the long-flight limit of the
        same-side probability for these draws.
    launch : HandLaunch
    h : float
    wall_time : float
    """

    n: int
    seed: int
    same_side: int
    mean_exact: float
    launch: HandLaunch
    h: float
    wall_time: float

    @property
    def probability(self) -> float:
        return self.same_side / self.n

    def interval(self, z: float = 1.96) -> tuple[float, float]:
        """Wilson score interval of the same-side probability (``z = 1.96``: 95 %)."""
        n, p = self.n, self.probability
        d = 1.0 + z * z / n
        c = (p + z * z / (2 * n)) / d
        w = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
        return max(0.0, c - w), min(1.0, c + w)

    def as_dict(self) -> dict:
        return {"ending": "caught", "launch_model": self.launch.describe(),
                "launch": asdict(self.launch), "h": self.h, "n": self.n, "seed": self.seed,
                "same_side": self.same_side, "probability": self.probability,
                "interval": list(self.interval()), "mean_exact_map": self.mean_exact,
                "e": None, "mu": None, "e_mu_note": "caught in the hand: free flight alone, "
                "no impact, so restitution e and friction mu do not enter",
                "wall_time": self.wall_time}

    def __repr__(self) -> str:
        lo, hi = self.interval()
        return (f"CaughtResult(n={self.n}, same_side={self.probability:.5f} "
                f"[{lo:.5f}, {hi:.5f}])")


def caught_ensemble(disk: Disk, launch: HandLaunch, n: int, rng_seed: int, *,
                    chunk: int = 1_000_000) -> CaughtResult:
    """Toss ``n`` coins by hand and catch them: free flight alone, in closed form (H1, H2).

    Parameters
    ----------
    disk : Disk
    launch : HandLaunch
    n : int
        Tosses, ``>= 1``.
    rng_seed : int
        Seed of ``numpy.random.default_rng`` (the draws of :meth:`HandLaunch.draw`, a
        chunk at a time: the result depends on ``rng_seed`` and ``chunk``).
    chunk : int
        Tosses drawn at once (memory: about 50 bytes a toss).

    Returns
    -------
    CaughtResult
        The side up at the catch is the starting side iff ``n_Z(T) > 0``.

    Examples
    --------
    >>> r = caught_ensemble(Disk(0.06), HandLaunch(psi_spread=0.0), 100_000, 1)
    >>> abs(r.probability - 0.5) < 0.01  # a pure flip is fair
    True
    """
    disk = check_disk(disk)
    if not isinstance(launch, HandLaunch):
        raise ParameterTypeError(f"launch must be a HandLaunch, got {launch!r}")
    n = check_int("n", n, low=1)
    seed = check_int("rng_seed", rng_seed, low=0)
    chunk = check_int("chunk", chunk, low=1)
    launch.flight_time(np.array([launch.upward_speed - launch.upward_speed_spread,
                                 launch.upward_speed + launch.upward_speed_spread]))
    rng = np.random.default_rng(seed)
    wall0 = time.perf_counter()
    same, exact = 0, 0.0
    for k in range(0, n, chunk):
        m = min(chunk, n - k)
        psi, w, v = launch.draw(m, rng)
        same += int(np.count_nonzero(normal_z(disk, w, psi, launch.flight_time(v)) > 0.0))
        exact += float(np.sum(same_side_probability(psi)))
    return CaughtResult(n, seed, same, exact / n, launch, disk.h, time.perf_counter() - wall0)


@dataclass(frozen=True)
class HandTossDistribution(TossDistribution):
    """The hand launch as a :class:`~rollingdisk.scenarios.toss.TossDistribution`, so that
    :func:`~rollingdisk.scenarios.toss.toss_ensemble` runs it on the table (workers, results
    file, resume).  The uniform ranges of the parent are unused (``None``); ``h`` is the
    disk's, needed to turn the flip rate into body rates (H2).
    """

    lift: tuple | None = None
    velocity: tuple | None = None
    spin: tuple | None = None
    tilt: tuple | None = None
    axial_spin: tuple | None = None
    precession: tuple | None = None
    horizontal_velocity: tuple | None = None
    launch: HandLaunch = field(default_factory=HandLaunch)
    h: float = 0.0

    def draw(self, n: int, seed: int) -> np.ndarray:
        """``(n, 7)`` rows ``lift, velocity, spin, tilt, axial_spin, precession,
        horizontal_velocity`` of :func:`launch_state` for :meth:`HandLaunch.draw`'s launches
        from ``numpy.random.default_rng(seed)``."""
        psi, w, v = self.launch.draw(n, np.random.default_rng(seed))
        disk = Disk(self.h)
        om = precession_rate(disk, w, psi)
        rows = np.zeros((n, 7))
        rows[:, 0] = self.launch.height - 1.0 - self.h  # toss_ensemble adds 1 + h back
        rows[:, 1] = v
        rows[:, 2] = om * np.sin(psi)
        rows[:, 3] = _HALF_PI
        rows[:, 4] = disk.k1_sq / disk.k2_sq * om * np.cos(psi)
        return rows


def table_ensemble(disk: Disk, launch: HandLaunch, n: int, rng_seed: int, *,
                   e: float = 0.5, mu: float = 0.5, **kwargs) -> EnsembleResult:
    """Hand tosses landing on the table: :func:`~rollingdisk.scenarios.toss.toss_ensemble`
    with the launch of :class:`HandTossDistribution` (``heads`` is the starting side).

    ``kwargs`` go to :func:`~rollingdisk.scenarios.toss.toss_ensemble` (``t_end``,
    ``workers``, ``results``, ``max_wall``, ``progress``).

    Raises
    ------
    ParameterError
        ``launch.height < h`` (the coin would start inside the table), ``e`` outside
        ``[0, 1]``, ``mu < 0``.
    """
    disk = check_disk(disk)
    if not isinstance(launch, HandLaunch):
        raise ParameterTypeError(f"launch must be a HandLaunch, got {launch!r}")
    if launch.height < disk.h:
        raise ParameterError(f"height must be at least h = {disk.h:g} (the flat coin would "
                             f"start inside the table), got {launch.height!r}")
    dist = HandTossDistribution(launch=launch, h=disk.h)
    return toss_ensemble(disk, n, rng_seed, e=e, mu=mu, distribution=dist, **kwargs)
