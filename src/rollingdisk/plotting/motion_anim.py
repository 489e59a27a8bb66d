"""3D animation of a whole motion to rest (:func:`rollingdisk.phases.motion.simulate_to_rest`).

A :class:`~rollingdisk.phases.motion.MotionResult` is a chain of segments: contact on a
rim edge (a Coulomb :class:`~rollingdisk.Trajectory`), free flight
(:class:`~rollingdisk.phases.motion.FlightSegment`, closed form) and the disk lying flat
(:class:`~rollingdisk.phases.motion.FlatSegment`).  :func:`motion_poses` samples the
drawn disk at evenly spaced times across all of them, each pose from its own segment's
state; :func:`animate_motion` paints them with the drawing code of
:mod:`rollingdisk.plotting.animation` (:func:`~rollingdisk.plotting.animation.draw_scene`).

Heights: touching a rim edge ``Z_C = -z_P`` (eq. 7, the contact constraint); in flight
``Z_C`` of the free-body state (:data:`~rollingdisk.phases.flight.FREE_STATE`); flat
``Z_C = h``.  Units m = a = g = 1.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from rollingdisk.phases.columns import flat_states as _flat_states
from rollingdisk.phases.line_contact import MODE_NAMES as LINE_MODES
from rollingdisk.phases.line_contact import LineSegment
from rollingdisk.phases.motion import FlatSegment, FlightSegment, MotionResult
from rollingdisk.plotting.animation import (
    FRAMES_RANGE,
    DiskPose,
    check_animation,
    disk_pose,
    draw_scene,
    write_frames,
    writer_for,
)
from rollingdisk.plotting.plots import disk_of, trajectory_series
from rollingdisk.util.checks import check_int
from rollingdisk.util.errors import ParameterTypeError

__all__ = ["motion_poses", "motion_phases", "motion_paths", "animate_motion"]

_ANGLES = ("X_C", "Y_C", "psi", "theta", "phi")
_FLIGHT_SAMPLES = 24  # points of C's path drawn per flight


def _check_result(result) -> MotionResult:
    if not isinstance(result, MotionResult):
        raise ParameterTypeError(f"result must be a MotionResult (simulate_to_rest), got "
                                 f"{type(result).__name__}")
    return result


def _span(seg) -> tuple[float, float]:
    """Start and end time of a segment."""
    if isinstance(seg, FlightSegment):
        return seg.t0, seg.t1
    t = np.asarray(seg.t, float)
    return float(t[0]), float(t[-1])


def _frame_times(result: MotionResult, n_frames: int) -> np.ndarray:
    t0 = _span(result.segments[0])[0] if result.segments else result.t_end
    return np.linspace(t0, result.t_end, n_frames)


def _segment_of(result: MotionResult, tf: np.ndarray) -> np.ndarray:
    """Index of the segment each time lies in; ``-1`` past the last one (the final state)."""
    if not result.segments:
        return np.full(tf.shape, -1)
    starts = np.array([_span(s)[0] for s in result.segments])
    j = np.clip(np.searchsorted(starts, tf, side="right") - 1, 0, None)
    end = _span(result.segments[-1])[1]
    return np.where(tf >= end, -1, j)


def _flight_states(seg: FlightSegment, t: np.ndarray) -> np.ndarray:
    """Free states (rows) in flight at times ``t``: the closed form (``free_flight``)."""
    return np.asarray(seg.state(np.asarray(t, float)), float).reshape(12, -1).T


def _pose_of_segment(h: float, seg, t: np.ndarray, n: int) -> list[DiskPose]:
    """The poses of one segment at the times ``t`` inside it."""
    if isinstance(seg, FlightSegment | FlatSegment | LineSegment):
        S = (_flat_states(seg, t) if isinstance(seg, FlatSegment) else
             np.asarray(seg.state(np.asarray(t, float)), float).reshape(12, -1).T)
        return [disk_pose(h, s[0], s[1], s[3], s[4], s[5], n=n, Z_C=s[2]) for s in S]
    ts = np.asarray(seg.t, float)  # contact: Z_C from the contact constraint (eq. 7)
    v = {k: np.interp(t, ts, trajectory_series(seg, k)) for k in _ANGLES}
    return [disk_pose(h, *(v[k][i] for k in _ANGLES), n=n) for i in range(t.size)]


def motion_poses(result: MotionResult, n_frames: int = 90, *,
                 n: int = 48) -> tuple[np.ndarray, list[DiskPose]]:
    """Frame times, evenly spaced over the whole run, and the disk's pose at each.

    Parameters
    ----------
    result : MotionResult
        From :func:`~rollingdisk.phases.motion.simulate_to_rest`.
    n_frames : int
        Number of frames, in :data:`~rollingdisk.plotting.animation.FRAMES_RANGE`.
    n : int
        Points on each rim circle.

    Returns
    -------
    (times, poses) : (ndarray, list of DiskPose)
        Times [``sqrt(a/g)``] from the start of the first segment to ``result.t_end``.
        Each pose comes from the state of the segment the time lies in: on a rim edge the
        centre's height is ``Z_C = -z_P`` (eq. 7), so the disk touches the plane; in
        flight it is the closed-form free flight's ``Z_C``; lying flat ``Z_C = h``; past
        the last segment, ``result.final_state``.

    Raises
    ------
    ParameterTypeError
        ``result`` is not a :class:`~rollingdisk.phases.motion.MotionResult`.
    ParameterError
        ``n_frames`` or ``n`` out of range.
    """
    result = _check_result(result)
    n_frames = check_int("n_frames", n_frames, low=FRAMES_RANGE[0], high=FRAMES_RANGE[1])
    n = check_int("n", n, low=3)
    h = result.disk.h
    tf = _frame_times(result, n_frames)
    which = _segment_of(result, tf)
    frames: list[DiskPose | None] = [None] * tf.size
    for j in np.unique(which):
        idx = np.nonzero(which == j)[0]
        if j < 0:
            s = result.final_state
            got = [disk_pose(h, s[0], s[1], s[3], s[4], s[5], n=n, Z_C=s[2])] * idx.size
        else:
            got = _pose_of_segment(h, result.segments[j], tf[idx], n)
        for i, p in zip(idx, got, strict=True):
            frames[i] = p
    return tf, frames


def motion_phases(result: MotionResult, times) -> list[str]:
    """The phase at each time: ``"rolling"``, ``"sliding"`` (and the pivot-stuck modes of
    :data:`~rollingdisk.model.coulomb.MODE_NAMES`) on a rim edge, ``"flight"``, ``"flat"``, or
    ``"rest"`` (past the last segment of a run ``"at-rest"``, or a flat disk stopped)."""
    from rollingdisk.model.coulomb import MODE_NAMES

    result = _check_result(result)
    tf = np.atleast_1d(np.asarray(times, float))
    which = _segment_of(result, tf)
    out = []
    for ti, j in zip(tf, which, strict=True):
        seg = result.segments[j] if j >= 0 else None
        if seg is None:
            out.append("rest" if result.status == "at-rest" else "end")
        elif isinstance(seg, FlightSegment):
            out.append("flight")
        elif isinstance(seg, FlatSegment):
            moving = np.interp(ti, seg.t, seg.speed) + np.interp(ti, seg.t, seg.spin) > 0
            out.append("flat" if moving else "rest")
        elif isinstance(seg, LineSegment):
            k = int(np.clip(np.searchsorted(seg.t, ti, side="right") - 1, 0, seg.t.size - 1))
            out.append(LINE_MODES[int(seg.mode[k]) & 3])
        else:
            k = int(np.clip(np.searchsorted(seg.t, ti, side="right") - 1, 0, seg.t.size - 1))
            out.append(MODE_NAMES[int(seg.mode[k])])
    return out


def motion_paths(result: MotionResult) -> tuple[np.ndarray, ...]:
    """``(t, X_P, Y_P, X_C, Y_C)`` over the whole run, in time order: the contact point P
    on a rim edge (eq. 5; NaN in flight and lying flat, and between contact segments, so
    the drawn path breaks there) and the centre C projected on the plane."""
    result = _check_result(result)
    parts = []
    nan1 = np.array([np.nan])
    for seg in result.segments:
        if isinstance(seg, FlightSegment):
            t = np.linspace(seg.t0, seg.t1, _FLIGHT_SAMPLES)
            S = _flight_states(seg, t)
            parts.append((t, t * np.nan, t * np.nan, S[:, 0], S[:, 1]))
        elif isinstance(seg, FlatSegment | LineSegment):
            t = np.asarray(seg.t, float)
            S = _flat_states(seg, t) if isinstance(seg, FlatSegment) else seg.state(t).T
            parts.append((t, t * np.nan, t * np.nan, S[:, 0], S[:, 1]))
        else:
            t = np.asarray(seg.t, float)
            parts.append((t, *(trajectory_series(seg, k) for k in ("X_P", "Y_P", "X_C",
                                                                    "Y_C"))))
            parts.append((t[-1:], nan1, nan1, nan1, nan1))  # break P's path
    s = result.final_state
    parts.append((np.array([result.t_end]), nan1, nan1, s[0:1], s[1:2]))
    return tuple(np.concatenate([p[i] for p in parts]) for i in range(5))


def animate_motion(result: MotionResult, out, *, n_frames: int = 90, fps: int = 15,
                   dpi: int = 70, size: tuple[float, float] = (5.0, 4.4),
                   title: str | None = None,
                   progress: Callable[[int, int], None] | None = None) -> Path:
    """Write a 3D animation of a whole motion to rest to ``out`` (``.gif`` or ``.mp4``).

    The disk flies, bounces, rolls or slides on a rim edge, rocks over its tread, falls
    flat and stops, drawn as :func:`~rollingdisk.plotting.animation.animate` draws it (a
    cylinder of thickness ``2h`` with body-fixed red sectors and its shadow): the path of
    the contact point P in red (broken in flight), C's projection dashed, and in the title
    the phase and a clock (seconds when the disk has a physical scale, else
    ``sqrt(a/g)``).  Written under a temporary name and renamed at the end: the file
    appears whole or not at all.

    Parameters
    ----------
    result : MotionResult
        From :func:`~rollingdisk.phases.motion.simulate_to_rest`.
    out : path-like
        ``.gif``, or ``.mp4`` when ffmpeg is installed; its folder must exist.
    n_frames, fps, dpi, size
        Checked by :func:`~rollingdisk.plotting.animation.check_animation`; the frames are
        evenly spaced in time (:func:`motion_poses`).
    title : str, optional
        Text before the phase and the clock (default: ``h`` and the number of impacts).
    progress : callable, optional
        Called with ``(frame, n_frames)`` after each frame.

    Returns
    -------
    Path
        ``out``.
    """
    from matplotlib.figure import Figure

    from rollingdisk.util.files import check_writable

    result = _check_result(result)
    n_frames, fps, dpi, size = check_animation(n_frames, fps, dpi, size)
    writer = writer_for(out, fps)
    out = Path(out)
    check_writable(out, name="out")
    tf, frames = motion_poses(result, n_frames)
    phases = motion_phases(result, tf)
    text = (title if title is not None
            else f"h = {result.disk.h:.4g}, {len(result.impacts)} impacts")
    fig = Figure(figsize=size)
    draw = draw_scene(fig, tf, frames, motion_paths(result),
                      lambda i: f"{text}   {phases[i]:<8}", disk_of(result))
    return write_frames(fig, len(tf), draw, out, writer, dpi, progress)
