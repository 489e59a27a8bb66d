"""Measurements of a simulation taken as it streams: memory stays flat however long the run.

:class:`StreamSummary` is a ``sink`` for :func:`~rollingdisk.ivp.simulation.simulate`:
it keeps the running energy drift (eq. 13 conserved, eq. 12) and the range of ``theta``
over the whole run, the first ``keep`` points for the measurements that need the signal
itself (frequency, growth rate: :mod:`rollingdisk.results.measure`), and optionally
writes every point to a CSV file as it comes (:func:`write_columns`).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from rollingdisk.results.trajectory import Trajectory
from rollingdisk.util.checks import check_int

__all__ = ["StreamSummary", "write_columns"]


def write_columns(fh, columns: dict, *, header: bool = True, fmt: str = "%.17g",
                  units: str | None = None) -> None:
    """Write named columns as CSV rows (``np.savetxt``; ``%.17g`` round-trips a float).

    Parameters
    ----------
    fh : file
        A text file open for writing.
    columns : dict of str -> array of shape (n,)
        The columns, in order (e.g. :meth:`Trajectory.as_columns`).
    header : bool
        Write the names as the first line.
    fmt : str
        Number format.
    units : str, optional
        With ``header``: a second line ``# <units>`` after the names (e.g.
        :meth:`Trajectory.csv_header`, ``t [s],X_C [m],...``), a comment that
        ``np.genfromtxt(names=True)``, ``np.loadtxt`` and ``pandas.read_csv(comment="#")``
        skip, so that the names stay plain.
    """
    text = ",".join(columns) if header else ""
    if header and units:
        text += "\n# " + units
    np.savetxt(fh, np.column_stack([np.asarray(v, dtype=float) for v in columns.values()]),
               delimiter=",", header=text, comments="", fmt=fmt)


class StreamSummary:
    """A ``sink(t, y)`` that measures a run as it streams (and may write it as CSV).

    Parameters
    ----------
    disk : Disk
        The disk simulated.
    ground : {"rough", "smooth"}
        Its ground (the layout of ``y``).
    csv : file, optional
        A text file: every point is written as a row of :meth:`Trajectory.as_columns`,
        the header once.
    keep : int
        The first ``keep`` points are kept for :meth:`kept` (default 200000).
    si : bool
        Write the CSV in SI units where the disk's scale allows
        (:meth:`Trajectory.as_columns`), with a second header line naming each column's
        unit (:func:`write_columns`).

    Attributes
    ----------
    theta_min, theta_max : float
        Range of ``theta`` over every point seen (rad).
    n_seen : int
        Points seen.

    Examples
    --------
    >>> import rollingdisk as rd
    >>> m = rd.steady_motion(rd.Disk(h=0.1), "rough", 0.3, Omega0=3.0)
    >>> s = StreamSummary(m.disk, "rough")
    >>> tr = rd.simulate_steady(m, 5.0, sink=s)
    >>> s.energy_drift() < 1e-9, s.n_seen == s.kept(tr).t.size
    (True, True)
    """

    def __init__(self, disk, ground: str, csv=None, *, keep: int = 200_000, si: bool = False):
        self.disk, self.ground, self.csv, self.si = disk, ground, csv, bool(si)
        self.keep = check_int("keep", keep, low=0)
        self._t, self._y = [], []
        self.n_kept = 0
        self.n_seen = 0
        self.E0 = None
        self.dE = 0.0
        self.theta_min, self.theta_max = math.inf, -math.inf
        self._header = True

    def __repr__(self) -> str:
        return (f"StreamSummary(ground={self.ground!r}, n_seen={self.n_seen}, "
                f"n_kept={self.n_kept})")

    def __call__(self, t, y) -> None:
        """Take a chunk: ``t`` shape ``(k,)``, ``y`` shape ``(n_state, k)``."""
        t = np.asarray(t, dtype=float)
        y = np.asarray(y, dtype=float)
        if t.size == 0:
            return
        part = Trajectory(disk=self.disk, ground=self.ground, t=t, y=y, status="completed",
                          message="", n_steps=0, n_rhs=0)
        E = part.E
        if self.E0 is None:
            self.E0 = float(E[0])
        self.dE = max(self.dE, float(np.max(np.abs(E - self.E0))))
        self.theta_min = min(self.theta_min, float(np.min(part.theta)))
        self.theta_max = max(self.theta_max, float(np.max(part.theta)))
        self.n_seen += t.size
        if self.n_kept < self.keep:
            k = min(t.size, self.keep - self.n_kept)
            self._t.append(np.array(t[:k]))
            self._y.append(np.array(y[:, :k]))
            self.n_kept += k
        if self.csv is not None:
            write_columns(self.csv, part.as_columns(si=self.si), header=self._header,
                          units=part.csv_header(si=True) if self.si else None)
            self._header = False

    def kept(self, traj: Trajectory) -> Trajectory:
        """``traj`` (the run's result, its own points streamed away) with the points kept:
        the whole run if it fitted in ``keep``."""
        if not self._t:
            return traj
        return dataclasses.replace(traj, t=np.concatenate(self._t),
                                   y=np.concatenate(self._y, axis=1))

    def energy_drift(self) -> float:
        """``max |E(t) - E(0)| / |E(0)|`` over every point seen (eq. 13), as
        :func:`~rollingdisk.results.measure.energy_drift` of the whole run."""
        if self.E0 is None:
            return math.nan
        return self.dE / max(abs(self.E0), np.finfo(float).tiny)
