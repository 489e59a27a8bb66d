"""Edge odds as a curve: heads, tails and edge against the coin's thickness, for hand tosses
landing on a table.

A coin of thickness ``t`` and diameter ``d`` is a disk of half-thickness ``h = t/(2a) = t/d``
(units of the radius ``a``): the ratio ``t/d`` *is* the library's ``h``.  For each ratio an
ensemble of hand tosses (:class:`~rollingdisk.scenarios.hand_toss.HandLaunch`) lands on the
table and runs through its bounces, rolling, sliding, line contact and rest
(:func:`~rollingdisk.scenarios.hand_toss.table_ensemble`); every ratio takes the same launches
(one seed: common random numbers, so the curve's wiggles are not the draws').

Beside it, the two *no-bounce* edge probabilities of a coin that stays where it lands (Yong &
Mahadevan, Am. J. Phys. 79 (2011) 1195, derived here, not transcribed): the coin rests on its
tread if its centre lands above the tread, i.e. the angle between its axis and the vertical
is within ``arctan(t/d)`` of 90 degrees.  With the axis uniform on the sphere the band has the
area fraction ``sin(arctan r) = r/sqrt(1 + r^2)`` (:func:`no_bounce_edge_sphere`, 1/3 at
``r = 1/sqrt(8) = 0.354``); with the angle uniform, ``(2/pi) arctan r``
(:func:`no_bounce_edge_angle`, 1/3 at ``r = tan(pi/6) = 0.577``).
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from rollingdisk.model.disk import Disk
from rollingdisk.scenarios.hand_toss import HandLaunch, table_ensemble
from rollingdisk.scenarios.toss import N_MAX, TOSS_OUTCOMES
from rollingdisk.util.checks import check_int, check_real, real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError
from rollingdisk.util.files import check_writable

__all__ = ["EDGE_RATIOS", "EdgeOdds", "edge_odds", "no_bounce_edge_sphere",
           "no_bounce_edge_angle", "NICKEL_RATIO", "YM_THIRD_SPHERE", "YM_THIRD_ANGLE"]

#: The default thicknesses ``t/d``: 12 from a thin coin to a cylinder as tall as it is wide,
#: the two ratios at which the no-bounce edge probabilities are 1/3 among them.
EDGE_RATIOS = (0.02, 0.05, 0.0919, 0.15, 0.2, 0.25, 0.3, 1 / math.sqrt(8.0), 0.45,
               1 / math.sqrt(3.0), 0.75, 1.0)
#: A US nickel, 1.95 mm thick and 21.21 mm across (Murray & Teare, Phys. Rev. E 48 (1993)
#: 2547, simulate it landing on edge about once in 6000 tosses).
NICKEL_RATIO = 1.95 / 21.21
#: ``t/d`` with no-bounce edge probability 1/3: axis uniform on the sphere, angle uniform.
YM_THIRD_SPHERE = 1.0 / math.sqrt(8.0)
YM_THIRD_ANGLE = 1.0 / math.sqrt(3.0)

_Z95 = 1.959963984540054  # the standard normal's 97.5 % quantile


def no_bounce_edge_sphere(ratio):
    """Edge probability of a coin that stays as it lands, its axis uniform on the sphere:
    ``r/sqrt(1 + r^2)``, ``r = t/d`` (the area fraction of the band within ``arctan r`` of
    the equator)."""
    r = np.asarray(real_array("ratio", ratio), float)
    return r / np.sqrt(1.0 + r * r)


def no_bounce_edge_angle(ratio):
    """Edge probability of a coin that stays as it lands, the angle between its axis and the
    vertical uniform in ``[0, pi/2]``: ``(2/pi) arctan r``, ``r = t/d``."""
    r = np.asarray(real_array("ratio", ratio), float)
    return 2.0 / math.pi * np.arctan(r)


def _wilson(k, n, z=_Z95):
    """Wilson score interval of ``k`` successes in ``n`` (element-wise)."""
    k, n = np.asarray(k, float), np.asarray(n, float)
    p = k / n
    d = 1.0 + z * z / n
    c = (p + z * z / (2 * n)) / d
    w = z * np.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
    # exact at the ends (0 and 1 are the bounds there; the formula leaves round-off)
    return (np.where(k == 0, 0.0, np.maximum(0.0, c - w)),
            np.where(k == n, 1.0, np.minimum(1.0, c + w)))


@dataclass(frozen=True, eq=False)
class EdgeOdds:
    """Outcome counts of hand tosses on a table against the thickness ``t/d``.

    Attributes
    ----------
    ratio : ndarray, shape (m,)
        ``t/d`` (equal to the half-thickness ``h`` in units of the radius).
    counts : dict
        ``{outcome: ndarray (m,) of int}`` over ``heads, tails, edge, undecided``.
    n : int
        Tosses per ratio.
    seed : int
        The seed of the launches (the same for every ratio).
    e, mu : float
        Restitution and friction of the table.
    launch : HandLaunch
        The launch model.
    wall_time : float
        Seconds this call took (a resumed run counts only the new tosses).
    """

    ratio: np.ndarray
    counts: dict
    n: int
    seed: int
    e: float
    mu: float
    launch: HandLaunch = field(default_factory=HandLaunch)
    wall_time: float = 0.0

    def probability(self, outcome: str) -> np.ndarray:
        """The frequency of ``outcome`` per ratio (among all tosses, undecided included)."""
        return self.counts[_outcome(outcome)] / self.n

    def interval(self, outcome: str) -> tuple[np.ndarray, np.ndarray]:
        """95 % Wilson score interval of the probability of ``outcome`` per ratio."""
        return _wilson(self.counts[_outcome(outcome)], self.n)

    @property
    def model(self) -> str:
        """One line: the launch model, its ending, ``e`` and ``mu``."""
        return f"{self.launch.describe('table')}; restitution e = {self.e:g}, mu = {self.mu:g}"

    def as_dict(self) -> dict:
        return {"ratio": self.ratio.tolist(), "n": self.n, "seed": self.seed, "e": self.e,
                "mu": self.mu, "model": self.model, "wall_time": self.wall_time,
                "counts": {k: v.tolist() for k, v in self.counts.items()},
                "intervals": {k: [a.tolist() for a in self.interval(k)] for k in TOSS_OUTCOMES}}

    def to_xarray(self):
        """An ``xarray.Dataset`` over ``ratio`` with CF attributes (``Conventions``,
        ``long_name``, ``units``): counts, probabilities with their 95 % intervals, and the
        two no-bounce edge probabilities."""
        from importlib.metadata import PackageNotFoundError, version

        from rollingdisk.results.xrload import xr

        try:
            release = version("rollingdisk")
        except PackageNotFoundError:  # a source tree that was not installed
            release = "(not installed)"

        one = {"units": "1"}
        data = {}
        for k in TOSS_OUTCOMES:
            lo, hi = self.interval(k)
            data[f"count_{k}"] = ("ratio", self.counts[k].astype(np.int64),
                                  {"long_name": f"tosses ending {k}", "units": "1"})
            data[f"p_{k}"] = ("ratio", self.probability(k),
                              {"long_name": f"frequency of {k} among all tosses", **one})
            data[f"p_{k}_low"] = ("ratio", lo, {"long_name": f"{k}: 95 % Wilson interval, "
                                                "lower bound", **one})
            data[f"p_{k}_high"] = ("ratio", hi, {"long_name": f"{k}: 95 % Wilson interval, "
                                                 "upper bound", **one})
        data["p_edge_no_bounce_sphere"] = (
            "ratio", no_bounce_edge_sphere(self.ratio),
            {"long_name": "edge probability without bounce, axis uniform on the sphere", **one})
        data["p_edge_no_bounce_angle"] = (
            "ratio", no_bounce_edge_angle(self.ratio),
            {"long_name": "edge probability without bounce, tilt angle uniform", **one})
        return xr.Dataset(
            data,
            coords={"ratio": ("ratio", np.asarray(self.ratio, float),
                              {"long_name": "thickness over diameter t/d (= h/a)",
                               "units": "1"})},
            attrs={"Conventions": "CF-1.10",
                   "title": "Edge odds of hand-tossed coins landing on a table",
                   "source": f"rollingdisk {release}: rollingdisk.edge_odds",
                   "comment": self.model,
                   "tosses_per_ratio": self.n, "seed": self.seed,
                   "references": "Yong & Mahadevan, Am. J. Phys. 79 (2011) 1195; Murray & "
                                 "Teare, Phys. Rev. E 48 (1993) 2547; Diaconis, Holmes & "
                                 "Montgomery, SIAM Rev. 49 (2007) 211"})

    def save(self, path) -> Path:
        """Write :meth:`to_xarray` as a netCDF file (scipy's writer, NETCDF3_64BIT), whole or
        not at all (:func:`rollingdisk.util.files.atomic_file`)."""
        from rollingdisk.util.files import atomic_file, check_writable

        target = check_writable(path, name="path")
        ds = self.to_xarray()
        with atomic_file(target, "wb") as f:
            f.write(ds.to_netcdf(None, engine="scipy"))
        return target

    def __repr__(self) -> str:
        edge = ", ".join(f"{r:.3g}:{p:.3g}" for r, p in zip(self.ratio, self.probability("edge"),
                                                             strict=True))
        return f"EdgeOdds(n={self.n} per ratio, P(edge) {edge})"

    def _repr_html_(self) -> str:
        from rollingdisk.util.display import html_table

        rows = [[f"{r:.4g}", *(f"{p:.4g}" for p in ps)] for r, *ps in zip(
            self.ratio, *(self.probability(k) for k in TOSS_OUTCOMES), strict=True)]
        return html_table(f"Edge odds ({self.n} tosses a ratio)", ("t/d", *TOSS_OUTCOMES), rows,
                          note=self.model)


def _outcome(outcome: str) -> str:
    if outcome not in TOSS_OUTCOMES:
        raise ParameterError(f"outcome must be one of {', '.join(TOSS_OUTCOMES)}, got "
                             f"{outcome!r}")
    return outcome


def edge_odds(ratios: Sequence[float] = EDGE_RATIOS, n: int = 20_000, rng_seed: int = 0, *,
              launch: HandLaunch | None = None, e: float = 0.5, mu: float = 0.5,
              workers: int = 1, results: str | os.PathLike | None = None,
              max_wall: float = 20.0, t_end: float = 1000.0,
              progress: Callable[[int, int], None] | None = None) -> EdgeOdds:
    """Heads, tails and edge of hand tosses landing on a table, against ``t/d``.

    Parameters
    ----------
    ratios : sequence of float
        Thicknesses ``t/d``, each in ``(0, 1]`` (default :data:`EDGE_RATIOS`).
    n : int
        Tosses per ratio, in ``[1, N_MAX]`` (10**7).
    rng_seed : int
        Seed of the launches, the same for every ratio.
    launch : HandLaunch, optional
        The launch model (default :class:`HandLaunch`: an assumption, see its notes); its
        ``height`` must be at least the largest ratio (the flat coin starts above the
        table).
    e, mu : float
        Restitution in ``[0, 1]`` and friction ``>= 0`` of the table.
    workers : int
        Processes for each ensemble.
    results : path, optional
        A folder (created) holding one toss-results file per ratio
        (``edge-odds-<ratio>.jsonl``): an interrupted curve resumes where it stopped, with
        the same counts.
    max_wall : float
        Wall-clock budget of one toss [s]; beyond it the toss is ``undecided``.
    t_end : float
        Longest simulated time of one toss [``sqrt(a/g)``].
    progress : callable, optional
        ``progress(done, total)`` over all tosses of all ratios.

    Returns
    -------
    EdgeOdds
    """
    r = np.asarray(real_array("ratios", ratios), float).ravel()
    if r.size == 0 or not np.all((r > 0.0) & (r <= 1.0)):
        raise ParameterError(f"ratios must be thicknesses t/d in (0, 1], got {ratios!r}")
    n = check_int("n", n, low=1, high=N_MAX)
    launch = HandLaunch() if launch is None else launch
    if not isinstance(launch, HandLaunch):
        raise ParameterTypeError(f"launch must be a HandLaunch, got {launch!r}")
    e = check_real("e", e, low=0.0, high=1.0)
    mu = check_real("mu", mu, low=0.0)
    folder = None
    if results is not None:
        try:
            folder = check_writable(results, name="results", folder=True)
            folder.mkdir(exist_ok=True)
        except OSError as exc:
            raise ParameterError(f"results: the folder cannot be made ({exc.strerror})") \
                from None
    counts = {k: np.zeros(r.size, dtype=np.int64) for k in TOSS_OUTCOMES}
    wall = 0.0
    for i, h in enumerate(r):
        step = None if progress is None else (
            lambda d, m, i=i: progress(i * n + d, r.size * n))
        path = None if folder is None else folder / f"edge-odds-{h:.6g}.jsonl"
        res = table_ensemble(Disk(float(h)), launch, n, rng_seed, e=e, mu=mu, workers=workers,
                             results=path, max_wall=max_wall, t_end=t_end,
                             progress=step)
        for k in TOSS_OUTCOMES:
            counts[k][i] = res.counts[k]
        wall += res.wall_time
    return EdgeOdds(r, counts, n, rng_seed, e, mu, launch, wall)
