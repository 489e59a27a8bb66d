"""The grid of a sweep: its steady motions (:class:`SweepGrid`), the perturbation added to
each (:class:`Perturbation`), the whole specification of a run (:class:`_Spec`) and the
set-up of each chunk's initial states and closed-form columns."""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, field

import numpy as np

from rollingdisk.model.disk import Disk, check_ground, check_h
from rollingdisk.util.checks import check_real, real_array
from rollingdisk.util.errors import ParameterError

__all__ = ["SweepGrid", "Perturbation", "BOUND_FACTOR", "GROW_LO", "GROW_HI"]

#: A run counts as bounded (``stable_simulated``) if ``max|theta - theta0|`` stays within
#: ``BOUND_FACTOR`` times the initial departure ``a0``.
BOUND_FACTOR = 20.0
#: ``growth_rate`` is the log-slope of ``|theta - theta0|`` between the first times it
#: exceeds ``GROW_LO * a0`` and ``GROW_HI * a0``.
GROW_LO = 2.0
#: Upper end of the growth-rate window (see :data:`GROW_LO`).
GROW_HI = 10.0
_SECOND = ("omega30", "r_C", "Omega0", "omega0")


@dataclass(frozen=True)
class Perturbation:
    """Perturbation of the steady state: ``tilt`` added to theta, ``kick`` set as omega1.

    Either may be a sequence (the ``amplitude`` axis of the sweep); a scalar is repeated.
    """

    kick: tuple = (1e-3,)
    tilt: tuple = (0.0,)

    def __post_init__(self):
        k = np.atleast_1d(real_array("kick", self.kick))
        e = np.atleast_1d(real_array("tilt", self.tilt))
        if k.ndim != 1 or e.ndim != 1:
            raise ParameterError("kick and tilt must be scalars or 1-d sequences")
        n = max(k.size, e.size)
        if k.size not in (1, n) or e.size not in (1, n):
            raise ParameterError(f"kick ({k.size}) and tilt ({e.size}) must have equal lengths"
                                 " or length 1")
        k = np.broadcast_to(k, (n,))
        e = np.broadcast_to(e, (n,))
        for name, v in (("kick", k), ("tilt", e)):
            if not np.all(np.isfinite(v)):
                raise ParameterError(f"{name} must be finite")
        if np.any(np.abs(k) + np.abs(e) == 0):
            raise ParameterError("each amplitude needs kick != 0 or tilt != 0")
        object.__setattr__(self, "kick", tuple(float(x) for x in k))
        object.__setattr__(self, "tilt", tuple(float(x) for x in e))


@dataclass(frozen=True)
class SweepGrid:
    """A grid of steady motions on one ground: circles ``h x theta0 x (omega30 | r_C |
    Omega0)`` or straight lines ``h x omega0``.

    Give exactly one of ``omega30``, ``r_C`` (rough ground: Omega0^2 from eq. 31, NaN where
    no steady motion has that radius), ``Omega0`` (each with ``theta0``), or ``omega0``
    (without ``theta0``): straight lines rolling at ``omega20 = omega0`` at the
    static-equilibrium tilt ``theta0 = arctan(h)`` of each h (section 3.1; the lean
    ``-arctan(h)`` is the mirror image, eq. 18's symmetry, with the same stability).
    Alternatively give ``states``, a list of arbitrary reduced initial states ``(theta,
    omega1, omega2, omega3)`` (then theta0 of each is its own theta and no perturbation is
    added).

    Examples
    --------
    >>> SweepGrid("rough", h=(0.0, 0.5), omega0=(0.5, 1.0, 2.0)).shape
    (2, 3)
    >>> SweepGrid("rough", theta0=(0.1, 0.2), omega30=(1.0,)).dims
    ('h', 'theta0', 'omega30')
    """

    ground: str
    h: tuple = (0.17,)
    theta0: tuple = ()
    omega30: tuple | None = None
    r_C: tuple | None = None
    Omega0: tuple | None = None
    omega0: tuple | None = None
    states: tuple | None = None

    def __post_init__(self):
        check_ground(self.ground)
        hs = tuple(check_h(x) for x in np.atleast_1d(real_array("h", self.h)))
        object.__setattr__(self, "h", hs)
        if self.states is not None:
            s = real_array("states", self.states)
            if s.ndim != 2 or s.shape[1] != 4 or not np.all(np.isfinite(s)):
                raise ParameterError("states must be a list of finite (theta, omega1, omega2,"
                                     " omega3)")
            if len(hs) != 1:
                raise ParameterError("states need a single h")
            object.__setattr__(self, "states", tuple(map(tuple, s.tolist())))
            return
        given = [k for k in _SECOND if getattr(self, k) is not None]
        if len(given) != 1:
            raise ParameterError(f"give exactly one of {_SECOND}, got {given}")
        if given[0] == "r_C" and self.ground != "rough":
            raise ParameterError("r_C determines Omega0 on rough ground only (eq. 31)")
        if given[0] == "omega0":
            if np.size(self.theta0):
                raise ParameterError("omega0 (straight lines) fixes theta0 = arctan(h); "
                                     "do not give theta0")
            object.__setattr__(self, "theta0", ())
            v = tuple(check_real("omega0", x) for x in np.atleast_1d(self.omega0))
            if not v:
                raise ParameterError("omega0 must not be empty")
            object.__setattr__(self, "omega0", v)
            return
        th = tuple(check_real("theta0", x, low=-math.pi / 2, high=math.pi / 2, low_open=True,
                              high_open=True) for x in np.atleast_1d(self.theta0))
        if not th:
            raise ParameterError("theta0 must not be empty")
        object.__setattr__(self, "theta0", th)
        v = tuple(check_real(given[0], x) for x in np.atleast_1d(getattr(self, given[0])))
        if not v:
            raise ParameterError(f"{given[0]} must not be empty")
        object.__setattr__(self, given[0], v)

    @property
    def second(self) -> str:
        return next(k for k in _SECOND if getattr(self, k) is not None)

    @property
    def straight(self) -> bool:
        """True for a grid of straight lines (``omega0``)."""
        return self.states is None and self.omega0 is not None

    @property
    def dims(self) -> tuple:
        """Names of the grid's axes (the dataset's dims before ``amplitude``)."""
        if self.states is not None:
            return ("point",)
        if self.straight:
            return ("h", "omega0")
        return ("h", "theta0", self.second)

    @property
    def shape(self) -> tuple:
        if self.states is not None:
            return (len(self.states),)
        if self.straight:
            return (len(self.h), len(self.omega0))
        return (len(self.h), len(self.theta0), len(getattr(self, self.second)))

    def coords(self) -> dict:
        """The grid's coordinates for an ``xarray.Dataset`` (straight lines also carry
        their tilt ``theta0`` along h)."""
        if self.states is not None:
            return {"theta_init": ("point", [s[0] for s in self.states])}
        if self.straight:
            return {"h": list(self.h), "omega0": list(self.omega0),
                    "theta0": ("h", [math.atan(x) for x in self.h])}
        return {"h": list(self.h), "theta0": list(self.theta0),
                self.second: list(getattr(self, self.second))}


@dataclass(frozen=True)
class _Spec:
    """Everything that determines a sweep's results: two runs with equal specs compute the
    same numbers, and a partial store is resumed only by a run with its spec.
    ``layout`` numbers the format of the stored chunks (2: status 10 = no steady motion)."""

    grid: SweepGrid
    perturbation: Perturbation
    t_end: float
    rtol: float
    atol: float
    max_steps: int
    chunk: int
    n: int = field(default=0)
    method: str = "taylor"
    layout: int = 2

    def to_json(self) -> str:
        return json.dumps(asdict(self), sort_keys=True, allow_nan=False)


def _setup(spec: _Spec, i0: int, i1: int):
    """Initial states and closed-form columns of the flat points i0 ... i1 - 1:
    ``(x0, h, theta_ref, varpi2, stable, a0)``, NaN rows of ``x0`` (and ``stable = -1``)
    where there is no steady motion."""
    g = spec.grid
    p = spec.perturbation
    na = len(p.kick)
    idx = np.arange(i0, i1)
    a_i = idx % na
    q = idx // na
    n = i1 - i0
    kick = np.asarray(p.kick)[a_i]
    tilt = np.asarray(p.tilt)[a_i]
    if g.states is not None:
        s = np.asarray(g.states)[q]
        return (s.copy(), np.full(n, g.h[0]), s[:, 0].copy(), np.full(n, np.nan),
                np.full(n, -1, dtype=np.int8), np.full(n, np.nan))
    second = g.second
    vals = np.asarray(getattr(g, second))
    if g.straight:
        ih, iv = np.unravel_index(q, g.shape)
        it = ih
        thetas = [math.atan(x) for x in g.h]  # the SE tilt of each h (section 3.1)
    else:
        ih, it, iv = np.unravel_index(q, g.shape)
        thetas = g.theta0
    if second in ("omega30", "Omega0"):  # the whole chunk at once
        return _setup_circles(g, second, np.asarray(g.h)[ih], np.asarray(thetas)[it],
                              vals[iv], tilt, kick)
    points = [(g.h[ih[j]], thetas[it[j]], vals[iv[j]]) for j in range(n)]
    return _setup_points(g.ground, second, points, tilt, kick)


def _setup_points(ground, second, points, tilt, kick):
    """:func:`_setup` point by point through :func:`rollingdisk.theory.steady.steady_motion`
    / ``straight_line`` and :func:`rollingdisk.theory.oscillations.stability` (grids of
    ``r_C`` and ``omega0``); ``points`` lists ``(h, theta0, value)``."""
    from rollingdisk.theory import oscillations as _stability
    from rollingdisk.theory import steady

    n = len(points)
    x0 = np.full((n, 4), np.nan)
    h = np.array([pt[0] for pt in points], dtype=float)
    theta_ref = np.array([pt[1] for pt in points], dtype=float)
    varpi2 = np.full(n, np.nan)
    stable = np.full(n, -1, dtype=np.int8)
    for j, (hh, th, v) in enumerate(points):
        disk = Disk(hh)
        try:
            if second == "omega0":
                m = steady.straight_line(disk, ground, v)
                th = theta_ref[j] = m.theta0
            elif second == "r_C":
                m = steady.steady_motion(disk, ground, th, r_C=v)
            elif v == 0:  # Omega0 = 0 is no circle
                continue
            else:
                omega = v / math.cos(th) if second == "omega30" else v  # eq. (3)
                m = steady.steady_motion(disk, ground, th, Omega0=omega)
        except ValueError:  # NoSteadyMotion or no motion with these parameters
            continue
        x0[j] = (th + tilt[j], kick[j], m.omega20, m.omega30)
        w = _stability.stability(m).varpi2
        varpi2[j] = w
        stable[j] = 1 if w > 0 else 0
    return x0, h, theta_ref, varpi2, stable, np.abs(kick) + np.abs(tilt)


def _setup_circles(g, second, h, theta0, v, tilt, kick):
    """:func:`_setup` for circles given by omega30 or Omega0, element-wise on the chunk
    (eqs. 3, 28/34 through :func:`rollingdisk.theory.steady.steady_omega20`, and eq. 40/51
    through :func:`rollingdisk.theory.oscillations.varpi2_closed_form`), so that the Python set-up
    does not limit the speed-up of the threads."""
    from rollingdisk.model.geometry import h_tilde
    from rollingdisk.theory import oscillations as _stability
    from rollingdisk.theory.steady import steady_omega20

    s, c = np.sin(theta0), np.cos(theta0)
    omega30 = v if second == "omega30" else v * c  # eq. (3)
    ht = h_tilde(h, theta0)
    with np.errstate(all="ignore"):
        omega20 = steady_omega20(g.ground, h, ht, s, c, omega30)
    # as steady_motion: Omega0 = 0 is no circle, theta0 = 0 is outside the theory for h > 0
    ok = (v != 0) & ~((h > 0) & (theta0 == 0)) & np.isfinite(omega20)
    n = h.size
    varpi2 = np.full(n, np.nan)
    varpi2[ok] = _stability.varpi2_closed_form(h[ok], g.ground, theta0[ok], omega20[ok],
                                               omega30[ok])
    ok &= np.isfinite(varpi2)
    varpi2[~ok] = np.nan
    x0 = np.full((n, 4), np.nan)
    x0[ok] = np.column_stack([theta0 + tilt, kick, omega20, omega30])[ok]
    stable = np.where(ok, (varpi2 > 0).astype(np.int8), -1).astype(np.int8)
    return x0, h, theta0.copy(), varpi2, stable, np.abs(kick) + np.abs(tilt)
