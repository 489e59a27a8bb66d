"""A whole motion to rest as one table: every phase in the free-body layout.

A :class:`~rollingdisk.phases.motion.MotionResult` is a chain of segments, each with its
own state (a Coulomb trajectory on a rim edge, the closed-form flight, the flat disk's
speed and spin, the line states on the tread).  :func:`motion_columns` writes them all in
one layout, the free-body state :data:`~rollingdisk.phases.flight.FREE_STATE` with the
time, the phase and the total energy, so that a run of several phases is one table
(``rollingdisk simulate --until-rest --out F.csv``); :func:`write_motion_csv` writes it.

Rows: every stored point of a contact, line or flat segment, ``flight_samples`` evenly
spaced points of each flight (its closed form, :func:`~rollingdisk.phases.flight.free_flight`)
and a last row at ``t_end`` with the final state.  A segment's last row and the next one's
first share their time (the phase changes there; an impact changes the velocities).
"""

from __future__ import annotations

import csv

import numpy as np

from rollingdisk.model.coulomb import MODE_NAMES
from rollingdisk.phases.flight import FREE_STATE, _state_energy
from rollingdisk.phases.line_contact import MODE_NAMES as LINE_MODES
from rollingdisk.phases.line_contact import LineSegment
from rollingdisk.phases.motion import _free_from_contact
from rollingdisk.phases.records import FlatSegment, FlightSegment, MotionResult
from rollingdisk.util.checks import check_int
from rollingdisk.util.errors import ParameterTypeError

__all__ = ["MOTION_VARIABLES", "flat_states", "motion_columns", "motion_column_units",
           "write_motion_csv"]

#: Columns of :func:`motion_columns`: name -> (kind of quantity, a key of
#: :data:`rollingdisk.model.units.KINDS`; long name).
MOTION_VARIABLES = {
    "t": ("time", "time"),
    "phase": ("dimensionless", "phase of motion (rolling, sliding, flight, tread, flat, "
                               "rest, ...)"),
    "X_C": ("length", "centre C, X in the inertial frame OXYZ"),
    "Y_C": ("length", "centre C, Y in the inertial frame OXYZ"),
    "Z_C": ("length", "centre C, height above the plane"),
    "psi": ("angle", "spin angle psi (eq. 1)"),
    "theta": ("angle", "inclination theta (eq. 1)"),
    "phi": ("angle", "rotation angle phi (eq. 1)"),
    "V_X": ("speed", "velocity of C, V_X in OXYZ"),
    "V_Y": ("speed", "velocity of C, V_Y in OXYZ"),
    "V_Z": ("speed", "velocity of C, V_Z in OXYZ"),
    "omega1": ("angular_speed", "angular velocity omega1 in C xi eta zeta (eq. 2)"),
    "omega2": ("angular_speed", "angular velocity omega2 in C xi eta zeta (eq. 3)"),
    "omega3": ("angular_speed", "angular velocity omega3 in C xi eta zeta (eq. 3)"),
    "E": ("energy", "mechanical energy, kinetic plus potential (eq. 13)"),
}


def _flat_fraction(seg: FlatSegment, t: np.ndarray, rate: np.ndarray) -> np.ndarray:
    """Share of the segment's whole travel (distance or turn) done by time ``t``: the
    integral of the piecewise-linear ``rate`` over ``seg.t``, exact between samples."""
    ts = np.asarray(seg.t, float)
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(ts))])
    if cum[-1] <= 0.0:
        return np.zeros_like(t)
    j = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, ts.size - 2)
    r = np.interp(t, ts, rate)
    return np.clip((cum[j] + 0.5 * (rate[j] + r) * (t - ts[j])) / cum[-1], 0.0, 1.0)


def flat_states(seg: FlatSegment, t) -> np.ndarray:
    """Free states (rows, shape ``(n, 12)``) of a flat disk at times ``t``: C moves on the
    straight line from ``state0`` to ``state1`` by the integral of the speed, psi turns by
    that of the spin, and the velocities are the segment's speed and spin at ``t``."""
    t = np.atleast_1d(np.asarray(t, float))
    speed, spin = np.asarray(seg.speed, float), np.asarray(seg.spin, float)
    fv = _flat_fraction(seg, t, speed)
    fw = _flat_fraction(seg, t, spin)
    s0, s1 = np.asarray(seg.state0, float), np.asarray(seg.state1, float)
    out = np.repeat(s0[None, :], t.size, axis=0)
    out[:, 0:2] = s0[0:2] + fv[:, None] * (s1[0:2] - s0[0:2])
    out[:, 3] = s0[3] + fw * (s1[3] - s0[3])
    return out


def _flat_velocities(seg: FlatSegment, S: np.ndarray, t: np.ndarray) -> np.ndarray:
    """``S`` with the flat disk's velocity and spin at ``t``: C's velocity keeps the
    direction it had at the start (the friction force opposes it, with no component
    across it), the spin ``omega2`` (along eta, vertical) keeps its sign."""
    S = S.copy()
    s0 = np.asarray(seg.state0, float)
    V0 = float(np.hypot(s0[6], s0[7]))
    d = s0[6:8] / V0 if V0 > 0.0 else np.zeros(2)
    S[:, 6:8] = d[None, :] * np.interp(t, seg.t, seg.speed)[:, None]
    S[:, 8] = S[:, 9] = S[:, 11] = 0.0
    S[:, 10] = np.sign(s0[10]) * np.interp(t, seg.t, seg.spin)
    return S


def _segment_rows(h: float, seg, flight_samples: int):
    """``(t, phases, S)`` of one segment: times, phase names, free states (rows)."""
    if isinstance(seg, FlightSegment):
        t = np.linspace(seg.t0, seg.t1, flight_samples)
        S = np.asarray(seg.state(t), float).reshape(12, -1).T
        return t, ["flight"] * t.size, S
    t = np.asarray(seg.t, float)
    if isinstance(seg, FlatSegment):
        S = _flat_velocities(seg, flat_states(seg, t), t)
        moving = np.asarray(seg.speed) + np.asarray(seg.spin) > 0.0
        return t, ["flat" if m else "rest" for m in moving], S
    if isinstance(seg, LineSegment):
        return t, [LINE_MODES[int(m) & 3] for m in seg.mode], seg.state(t).T
    y = np.asarray(seg.y, float)  # a Coulomb trajectory on one rim edge
    side = 1.0 if y[5, 0] > 0.0 else -1.0
    S = np.array([_free_from_contact(h, y[:, k], side) for k in range(t.size)])
    return t, [MODE_NAMES[int(m)] for m in seg.mode], S


def motion_columns(result: MotionResult, *, flight_samples: int = 24,
                   si: bool = False) -> dict:
    """The whole motion as columns: ``t``, ``phase``, the free-body state
    (:data:`~rollingdisk.phases.flight.FREE_STATE`: ``X_C, Y_C, Z_C, psi, theta, phi,
    V_X, V_Y, V_Z, omega1, omega2, omega3``) and the total energy ``E``.

    Parameters
    ----------
    result : MotionResult
        From :func:`~rollingdisk.phases.motion.simulate_to_rest`.
    flight_samples : int
        Points per flight (its closed form), at least 2.
    si : bool
        Values in SI where the disk's physical scale allows (times, lengths and speeds
        need its radius, energies its mass too); else the paper's units (m = a = g = 1).

    Returns
    -------
    dict of str -> ndarray
        The columns, in time order; ``phase`` an array of str.  On a rim edge the phase
        is the contact mode (:data:`rollingdisk.model.coulomb.MODE_NAMES`: ``rolling``,
        ``sliding``, ...), on the tread the line sub-phase, else ``flight``, ``flat`` or
        ``rest``; the last row (``t_end``) is ``rest`` for a run ``at-rest``, else ``end``.
    """
    if not isinstance(result, MotionResult):
        raise ParameterTypeError(f"result must be a MotionResult (simulate_to_rest), got "
                                 f"{type(result).__name__}")
    flight_samples = check_int("flight_samples", flight_samples, low=2)
    h = result.disk.h
    ts, phases, states = [], [], []
    for seg in result.segments:
        t, ph, S = _segment_rows(h, seg, flight_samples)
        ts.append(t)
        phases.extend(ph)
        states.append(S)
    ts.append(np.array([result.t_end]))
    phases.append("rest" if result.status == "at-rest" else "end")
    states.append(np.asarray(result.final_state, float)[None, :])
    t, S = np.concatenate(ts), np.concatenate(states)
    cols = {"t": t, "phase": np.array(phases)}
    cols.update({name: S[:, i] for i, name in enumerate(FREE_STATE)})
    cols["E"] = np.array([_state_energy(h, s) for s in S])
    if si:
        from rollingdisk.results.dataout import convert_columns

        cols = convert_columns(cols, result.disk, True, MOTION_VARIABLES)
    return cols


def motion_column_units(result: MotionResult, si: bool = False) -> dict:
    """Column name -> unit of :func:`motion_columns` (the paper's units, or SI where the
    disk's scale allows)."""
    from rollingdisk.results.dataout import column_units

    return column_units(MOTION_VARIABLES, result.disk, si, MOTION_VARIABLES)


def write_motion_csv(fh, result: MotionResult, *, si: bool = False,
                     flight_samples: int = 24) -> None:
    """Write :func:`motion_columns` as CSV to the text file ``fh``: a line of names, a
    comment line ``# t [s],X_C [m],...`` with each column's unit, then one row per point
    (``%.17g``, which round-trips a float; the phase as text)."""
    cols = motion_columns(result, si=si, flight_samples=flight_samples)
    units = motion_column_units(result, si)
    fh.write(",".join(cols) + "\n")
    fh.write("# " + ",".join(f"{n} [{units[n]}]" for n in cols) + "\n")
    writer = csv.writer(fh, lineterminator="\n")
    names = list(cols)
    n = cols["t"].size
    for i in range(n):
        writer.writerow([cols[k][i] if k == "phase" else f"{float(cols[k][i]):.17g}"
                         for k in names])
