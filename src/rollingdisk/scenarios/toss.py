"""The coin toss: heads, tails or edge, from a launch to the state the coin is caught in.

One toss is :func:`rollingdisk.phases.motion.simulate_to_rest` from a launch in free
flight; an ensemble repeats it over random launches (``docs/motion.md``).  Units
m = a = g = 1.
"""

from __future__ import annotations

import contextlib
import itertools
import json
import math
import os
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.model.ground import Coulomb
from rollingdisk.phases.motion import MotionResult, simulate_to_rest
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError
from rollingdisk.util.files import helpers_block_sigint
from rollingdisk.util.journal import open_journal

__all__ = ["TOSS_OUTCOMES", "TossResult", "toss", "TossDistribution", "EnsembleResult",
           "toss_ensemble", "energy_barrier"]

#: What a toss gives: ``heads`` (lying flat, axis eta up), ``tails`` (eta down), ``edge``
#: (upright on its tread), ``undecided`` (the run ended otherwise: end time, a budget).
TOSS_OUTCOMES = ("heads", "tails", "edge", "undecided")


def energy_barrier(h: float, rolling_resistance: float = 0.0) -> float:
    """The least energy [``m g a``] at which the disk can stand still on a rim edge:
    ``sqrt(1 + h^2 - c^2)`` with the rolling resistance ``c`` (``sqrt(1 + h^2)`` without
    it, the height of the centre when the disk balances on a rim edge with its centre
    straight above it, ``theta = +-arctan h``).

    Below this energy the outcome is decided: touching a rim edge the centre's height is
    ``Z_C = sqrt(1 + h^2) cos(|theta| - arctan h)`` (eq. 7), and the energy ``E >= Z_C``
    never grows (impacts, friction), so the disk can never again reach the tilts where
    ``Z_C >= E``; those include the balance tilt (it cannot cross from one side to the
    other) and every tilt where rolling resistance can hold it still (the arm of gravity
    about the edge, ``sqrt(1 + h^2) |sin(|theta| - arctan h)|``, at most ``c``, so ``Z_C >=
    sqrt(1 + h^2 - c^2)``): it cannot come to rest on the edge.

    Parameters
    ----------
    h : float
        Half-thickness [``a``], ``>= 0``.
    rolling_resistance : float
        Rolling-resistance length ``c`` of the ground [``a``], in ``[0, sqrt(1 + h^2))``
        (a ground that holds the disk at every tilt has no such energy).
    """
    h = check_real("h", h, low=0.0)
    top = 1.0 + h * h
    c = check_real("rolling_resistance", rolling_resistance, low=0.0, high=math.sqrt(top),
                   high_open=True)
    return math.sqrt(top - c * c)


def _trap(h, c_roll=0.0):
    Eb = energy_barrier(h, c_roll)
    s_b = h / math.sqrt(1.0 + h * h)  # sin(arctan h): the balance tilt

    def decide(E, s):
        if E >= Eb * (1.0 - 1e-12):
            return None
        ez = math.sin(s[4])  # eta_Z
        side = "heads" if ez > s_b else "tails" if ez < -s_b else "edge"
        return f"energy {E:.9g} below the barrier sqrt(1 + h^2 - c^2) = {Eb:.9g}: {side}"
    return decide


@dataclass(frozen=True, eq=False)
class TossResult:
    """One toss.

    Attributes
    ----------
    outcome : {"heads", "tails", "edge", "undecided"}
    decided_by : {"rest", "energy", "none"}
        ``rest``: the run reached rest; ``energy``: the energy fell below
        :func:`energy_barrier` with the axis in one basin (the outcome can no longer
        change); ``none``: undecided.
    t : float
        When it was decided [``sqrt(a/g)``].
    n_impacts : int
    motion : MotionResult
    """

    outcome: str
    decided_by: str
    t: float
    n_impacts: int
    motion: MotionResult

    def __repr__(self) -> str:
        return (f"TossResult(outcome={self.outcome!r}, decided_by={self.decided_by!r}, "
                f"t={self.t:.6g}, n_impacts={self.n_impacts})")


#: Mode events a contact segment of a toss may take (stick-slip chatter on the rim): a
#: toss that chatters past them is ``undecided`` either way, so it stops early (a ten
#: times larger budget gave the same verdicts at a ten times larger cost).
TOSS_MAX_TRANSITIONS = 1000


def _classify(h, res: MotionResult):
    s = res.final_state
    if res.status == "at-rest":
        st = math.sin(s[4])
        if abs(st) < 0.5:
            return "edge", "rest"
        return ("heads" if st > 0 else "tails"), "rest"
    if res.status == "completed" and "below the barrier" in res.message:
        return res.message.rsplit(": ", 1)[-1], "energy"
    return "undecided", "none"


def toss(disk: Disk, height: float, velocity: float, spin: float, tilt: float = 0.0, *,
         e: float = 0.5, mu: float = 0.5, axial_spin: float = 0.0, precession: float = 0.0,
         horizontal_velocity: float = 0.0, rolling_resistance: float = 0.01,
         t_end: float = 1000.0, early: bool = True, max_wall: float = 120.0,
         rtol: float = 1e-8, atol: float = 1e-10) -> TossResult:
    """Toss the coin and see how it lands.

    Parameters
    ----------
    disk : Disk
    height : float
        Height of the centre at launch [``a``]; the disk must be above the plane,
        ``height >= |cos tilt| + h |sin tilt|``.
    velocity : float
        Vertical velocity of the centre at launch [``sqrt(a g)``], up if positive.
    spin : float
        Angular velocity about the horizontal diameter xi, ``omega1`` [``sqrt(g/a)``]: the
        flipping of the toss.
    tilt : float
        ``theta`` at launch [rad]: 0 the coin stands upright, ``+pi/2`` heads up.
    e, mu : float
        Restitution ``[0, 1]`` and friction ``>= 0`` of the impacts and of the ground
        (``Coulomb(mu)``).
    axial_spin, precession : float
        ``omega2`` (about the axis eta) and ``omega3`` at launch [``sqrt(g/a)``].
    horizontal_velocity : float
        ``V_X`` at launch [``sqrt(a g)``].
    rolling_resistance : float
        Coefficient ``c`` of :class:`~rollingdisk.model.ground.RollingResistance` of the
        ground [``a``], ``>= 0``: without it a coin rolling on its rim never stops.
    t_end : float
        Longest simulated time.
    early : bool
        Stop as soon as the energy falls below :func:`energy_barrier` (the outcome is
        then certain); ``False`` runs on to rest.
    max_wall : float
        Wall-clock budget [s].
    rtol, atol : float
        Tolerances of the contact phases (looser than :func:`simulate_to_rest`'s default:
        the outcome, not the last digit, is wanted).

    Returns
    -------
    TossResult

    Raises
    ------
    ParameterError
        ``height`` puts the disk inside the plane; ``e`` outside ``[0, 1]``; ``mu < 0``.

    Examples
    --------
    >>> r = toss(Disk(0.1), height=3.0, velocity=2.0, spin=5.0, tilt=0.3, e=0.3)
    >>> r.outcome in ("heads", "tails"), r.decided_by
    (True, 'energy')
    """
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got {disk!r}")
    h = disk.h
    tilt = check_real("tilt", tilt)
    low = abs(math.cos(tilt)) + h * abs(math.sin(tilt))
    height = check_real("height", height)
    if height < low:
        raise ParameterError(f"height must be at least |cos tilt| + h |sin tilt| = {low:.6g} "
                             f"(the disk would start inside the plane), got {height!r}")
    vals = [check_real(n, v) for n, v in (("velocity", velocity), ("spin", spin),
                                          ("axial_spin", axial_spin),
                                          ("precession", precession),
                                          ("horizontal_velocity", horizontal_velocity))]
    e = check_real("e", e, low=0.0, high=1.0)
    mu = check_real("mu", mu, low=0.0)
    t_end = check_real("t_end", t_end, low=0.0, low_open=True)
    v, w1, w2, w3, vx = vals
    s0 = [0.0, 0.0, height, 0.0, tilt, 0.0, vx, 0.0, v, w1, w2, w3]
    c_roll = check_real("rolling_resistance", rolling_resistance, low=0.0)
    res = simulate_to_rest(disk, Coulomb(mu, rolling_resistance=c_roll), (0.0, t_end), s0,
                           e=e, mu_impact=mu,
                           decide=_trap(h, c_roll) if early and c_roll ** 2 < 1.0 + h * h
                           else None,
                           chunk=1.0, max_wall=max_wall, rtol=rtol, atol=atol,
                           max_steps=20_000, max_transitions=TOSS_MAX_TRANSITIONS)
    out, by = _classify(h, res)
    return TossResult(out, by, res.t_end, len(res.impacts), res)


@dataclass(frozen=True)
class TossDistribution:
    """Random launch conditions, each uniform on ``[low, high]`` (independent).

    Attributes (``(low, high)`` each)
    ----------
    lift : height of the centre above ``1 + h`` [``a``]
    velocity : vertical launch velocity [``sqrt(a g)``]
    spin : ``omega1``, the flip [``sqrt(g/a)``]
    tilt : ``theta`` [rad]
    axial_spin, precession : ``omega2``, ``omega3`` [``sqrt(g/a)``]
    horizontal_velocity : ``V_X`` [``sqrt(a g)``]
    """

    lift: tuple = (0.5, 2.5)
    velocity: tuple = (0.0, 4.0)
    spin: tuple = (-10.0, 10.0)
    tilt: tuple = (-0.5 * math.pi, 0.5 * math.pi)
    axial_spin: tuple = (-1.0, 1.0)
    precession: tuple = (-1.0, 1.0)
    horizontal_velocity: tuple = (-0.5, 0.5)

    NAMES = ("lift", "velocity", "spin", "tilt", "axial_spin", "precession",
             "horizontal_velocity")

    def draw(self, n: int, seed: int) -> np.ndarray:
        """``(n, 7)`` launches, columns :attr:`NAMES`, from ``numpy.random.default_rng(seed)``
        (the same for any number of workers or a resumed run)."""
        rng = np.random.default_rng(seed)
        lo = np.array([getattr(self, k)[0] for k in self.NAMES], float)
        hi = np.array([getattr(self, k)[1] for k in self.NAMES], float)
        return lo + (hi - lo) * rng.random((n, len(self.NAMES)))


@dataclass(frozen=True, eq=False)
class EnsembleResult:
    """Outcome frequencies over random tosses.

    Attributes
    ----------
    h : float
    n : int
    seed : int
    outcomes : tuple of str
        Per toss, in launch order.
    counts : dict
        ``{outcome: count}`` over :data:`TOSS_OUTCOMES`.
    wall_time : float
        Seconds (this call; a resumed run counts only the new tosses).
    params : dict
        ``e``, ``mu`` and the distribution.
    """

    h: float
    n: int
    seed: int
    outcomes: tuple
    counts: dict
    wall_time: float
    params: dict = field(default_factory=dict)

    @property
    def frequencies(self) -> dict:
        """``{outcome: count/n}``."""
        return {k: c / self.n for k, c in self.counts.items()}

    def interval(self, outcome: str, z: float = 1.96) -> tuple[float, float]:
        """Wilson score interval of the probability of ``outcome`` (``z = 1.96``: 95 %)."""
        n, k = self.n, self.counts[outcome]
        p = k / n
        d = 1.0 + z * z / n
        c = (p + z * z / (2 * n)) / d
        w = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
        return max(0.0, c - w), min(1.0, c + w)

    def as_dict(self) -> dict:
        return {"h": self.h, "n": self.n, "seed": self.seed, "counts": self.counts,
                "frequencies": self.frequencies, "wall_time": self.wall_time,
                "params": self.params,
                "intervals": {k: list(self.interval(k)) for k in TOSS_OUTCOMES}}

    def __repr__(self) -> str:
        c = ", ".join(f"{k}={v}" for k, v in self.counts.items())
        return f"EnsembleResult(h={self.h:g}, n={self.n}, {c})"


def _load_compiled():
    """An ensemble is a long job: load the compiled contact phase
    (:mod:`rollingdisk.ivp.fastsegment`) and line contact's kernels
    (:mod:`rollingdisk.phases.line_kernel`) at once instead of after the process's
    uncompiled budget (compiling it if numba's cache is cold, once per machine); without
    numba the tosses run on the scipy path."""
    from rollingdisk.ivp import fastsegment as _fs
    from rollingdisk.phases import line_kernel

    if _fs.available():
        try:
            _fs.compiled()
        except Exception:  # noqa: BLE001 - numba broken: the scipy path still works
            pass
        line_kernel.load_compiled()


def _one(args):
    h, row, e, mu, t_end, max_wall = args
    lift, v, w1, tilt, w2, w3, vx = row
    r = toss(Disk(h), 1.0 + h + lift, v, w1, tilt, e=e, mu=mu, axial_spin=w2,
             precession=w3, horizontal_velocity=vx, t_end=t_end, max_wall=max_wall)
    return r.outcome, r.decided_by, r.t, r.n_impacts


#: Most tosses of one ensemble (its outcomes are kept, 8 bytes a toss).
N_MAX = 10_000_000

#: Launches drawn, and tosses handed to the workers, per block: the ensemble streams
#: (memory flat in ``n``); the draws are the same as :meth:`TossDistribution.draw`'s.
BLOCK = 1024


def max_workers() -> int:
    """The most worker processes an ensemble takes: the CPUs this process may use (a
    toss is CPU-bound; each worker holds about 180 MB, so more processes than CPUs only
    cost memory)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def _launches(dist: TossDistribution, n: int, seed: int):
    """``(i, row)`` for ``i < n``: the rows of ``dist.draw(n, seed)``, drawn a block at a
    time (``Generator.random`` fills row after row from one stream, so blocks give the
    same numbers).  A distribution with its own ``draw`` (a subclass) is drawn whole by
    it: its stream may differ."""
    if type(dist).draw is not TossDistribution.draw:
        yield from ((i, tuple(row)) for i, row in enumerate(dist.draw(n, seed)))
        return
    rng = np.random.default_rng(seed)
    lo = np.array([getattr(dist, k)[0] for k in dist.NAMES], float)
    hi = np.array([getattr(dist, k)[1] for k in dist.NAMES], float)
    for start in range(0, n, BLOCK):
        rows = lo + (hi - lo) * rng.random((min(BLOCK, n - start), len(dist.NAMES)))
        for k, row in enumerate(rows):
            yield start + k, tuple(row)


def _record_check(n: int):
    """The check of one journal record of an ensemble of ``n`` tosses (its index and
    outcome kept)."""
    def check(rec):
        i = rec["i"]
        if type(i) is not int or not 0 <= i < n:
            raise ValueError(f"toss index {i!r} outside [0, {n})")
        if rec["outcome"] not in TOSS_OUTCOMES:
            raise ValueError(f"outcome {rec['outcome']!r} not one of {TOSS_OUTCOMES}")
        if rec["decided_by"] not in ("rest", "energy", "none"):
            raise ValueError(f"decided_by {rec['decided_by']!r}")
        k = rec["n_impacts"]
        if type(k) is not int or k < 0:
            raise ValueError(f"n_impacts {k!r}")
        t = rec["t"]
        if t is not None and (type(t) not in (int, float) or not math.isfinite(t)):
            raise ValueError(f"t {t!r}")
        return i, rec["outcome"]
    return check


def toss_ensemble(disk: Disk, n: int, rng_seed: int, *, e: float = 0.5, mu: float = 0.5,
                  distribution: TossDistribution | None = None, t_end: float = 1000.0,
                  workers: int = 1, results: str | os.PathLike | None = None,
                  max_wall: float = 20.0,
                  progress: Callable[[int, int], None] | None = None) -> EnsembleResult:
    """Estimate the probabilities of heads, tails and edge over random launches.

    Parameters
    ----------
    disk : Disk
    n : int
        Number of tosses, in ``[1, N_MAX]`` (10**7).
    rng_seed : int
        Seed of ``numpy.random.default_rng``: the launches (:meth:`TossDistribution.draw`)
        and so the result depend on it alone.
    e, mu : float
        Restitution and friction (:func:`toss`).
    distribution : TossDistribution, optional
        The launch conditions (default :class:`TossDistribution`).
    t_end : float
        Longest simulated time of one toss.
    workers : int
        Processes (``1``: this one), at most ``max_workers()`` (the CPUs this process
        may use).
    results : path, optional
        A JSON-lines file of ours (:mod:`rollingdisk.util.journal`): a header, then one
        line per toss as it finishes, written whole.  If it exists for the same ensemble
        (disk, seed, n, e, mu, distribution), the tosses in it are not run again: an
        interrupted ensemble resumes.  One writer at a time: another process writing it
        is refused (its pid named), as is a file that is not a toss-results file, a line
        that is not a toss, a folder, a device or a full disk (the file is left whole).
    max_wall : float
        Wall-clock budget of one toss [s] (beyond it: ``undecided``).
    progress : callable, optional
        ``progress(done, n)``.

    Returns
    -------
    EnsembleResult

    Raises
    ------
    ParameterError
        A value out of its range, or ``results`` refused (see above).

    Notes
    -----
    The launches are drawn, and handed to the workers, :data:`BLOCK` at a time: memory
    stays flat in ``n`` and nothing is built up front.
    """
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got {disk!r}")
    n = check_int("n", n, low=1, high=N_MAX)
    seed = check_int("rng_seed", rng_seed, low=0)
    workers = check_int("workers", workers, low=1, high=max_workers())
    e = check_real("e", e, low=0.0, high=1.0)
    mu = check_real("mu", mu, low=0.0)
    t_end = check_real("t_end", t_end, low=0.0, low_open=True)
    max_wall = check_real("max_wall", max_wall, low=0.0, low_open=True)
    dist = TossDistribution() if distribution is None else distribution
    if not isinstance(dist, TossDistribution):
        raise ParameterTypeError(f"distribution must be a TossDistribution, got {dist!r}")
    params = {"e": e, "mu": mu, "t_end": t_end, "distribution": asdict(dist)}
    header = {"ensemble": {"h": disk.h, "n": n, "seed": seed, **params}}
    header = json.loads(json.dumps(header))  # tuples as lists, as read back
    with contextlib.ExitStack() as stack:
        journal, outcomes = None, [None] * n
        if results is not None:
            journal, kept = stack.enter_context(
                open_journal(results, header, _record_check(n), name="results",
                             kind="toss-results file"))
            for i, out in kept:
                outcomes[i] = out
        n_done = sum(o is not None for o in outcomes)
        wall0 = time.perf_counter()
        todo = ((i, (disk.h, row, e, mu, t_end, max_wall))
                for i, row in _launches(dist, n, seed) if outcomes[i] is None)
        if n_done < n:
            _load_compiled()  # compiled once here, so that the workers only load it
        if workers == 1 or n - n_done < 2:
            _collect(((i, _one(a)) for i, a in todo), outcomes, n_done, journal, progress, n)
        else:
            import multiprocessing as mp

            with helpers_block_sigint():  # a Ctrl-C is the parent's to report
                pool = stack.enter_context(mp.get_context("spawn").Pool(
                    min(workers, n - n_done), initializer=_load_compiled))
            _collect(_blocks(pool, todo, workers), outcomes, n_done, journal, progress, n)
    outcomes = tuple(outcomes)
    counts = {k: outcomes.count(k) for k in TOSS_OUTCOMES}
    return EnsembleResult(disk.h, n, seed, outcomes, counts, time.perf_counter() - wall0,
                          params)


def _blocks(pool, todo, workers):
    """``(i, result)`` of the tosses ``todo`` run by ``pool``, handed over a block at a
    time (``Pool.imap`` would take the whole iterable at once)."""
    while True:
        block = list(itertools.islice(todo, BLOCK))
        if not block:
            return
        ids = [i for i, _ in block]
        chunk = max(1, min(4, len(block) // (4 * workers)))
        yield from zip(ids, pool.imap(_one, [a for _, a in block], chunksize=chunk))


def _collect(it, outcomes, n_done, journal, progress, n):
    for i, (out, by, t, k) in it:
        outcomes[i] = out
        n_done += 1
        if journal is not None:
            journal.append({"i": i, "outcome": out, "decided_by": by,
                            "t": t if math.isfinite(t) else None, "n_impacts": k})
        if progress is not None:
            progress(n_done, n)
