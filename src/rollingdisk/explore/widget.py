"""The explorer in a notebook: an anywidget widget (JupyterLab, Notebook 7, VS Code, Colab,
marimo), Python computing and the browser only drawing.

:func:`widget` shows a disk's existence and stability map of steady circles in the
(theta0, omega30) plane (Figure 4's plane; :func:`rollingdisk.existence_codes`); a click
sets the trait ``selected = [theta0, omega30]``, on which Python computes the steady
motion (:func:`rollingdisk.steady_motion`), its stability (:func:`rollingdisk.stability`)
and the motion kicked from it (:func:`rollingdisk.simulate_steady`), and sends them back as
the traits ``motion`` (numbers, with SI values beside them for a disk with a physical
size) and ``frames`` (the drawn disk along the run). :func:`play` draws any computed motion
(a :class:`~rollingdisk.Trajectory` or a motion to rest,
:class:`~rollingdisk.phases.motion.MotionResult`) in 3D with a time slider.

The records are the served explorer's (:mod:`rollingdisk.explore.api`: a click here is
answered as ``/api/steady`` and ``/api/simulate`` answer it there), and the drawing is the
served explorer's too: the ES module ``static/view.js`` (its default export ``{render}`` is
anywidget's entry), shipped in the package; nothing is loaded from the network.  anywidget
is the optional extra ``rollingdisk[notebook]``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["widget", "play", "traits", "ESM_PATH"]

#: The ES module the widget draws with, the served explorer's view module (shipped in the
#: wheel with the package data).
ESM_PATH = Path(__file__).with_name("static") / "view.js"
#: Map resolution (points per axis) and the largest omega30 of the map.
MAP_N, MAP_OMEGA30_MAX = 41, 3.0
#: The kicked motion drawn after a click: tilt kick [rad], span [sqrt(a/g)], stored points.
KICK, T_END, FRAMES = 0.02, 30.0, 600


def _anywidget():
    try:
        import anywidget
        import traitlets
    except ImportError:
        raise ImportError("the notebook widget needs anywidget: pip install "
                          "'rollingdisk[notebook]'") from None
    return anywidget, traitlets


_VIEW = []


def _view_class():
    """The widget class with the view's traits (made once, on first use: anywidget is an
    optional dependency)."""
    if not _VIEW:
        anywidget, traitlets = _anywidget()

        class DiskView(anywidget.AnyWidget):
            _esm = ESM_PATH
            disk = traitlets.Dict().tag(sync=True)
            map = traitlets.Dict().tag(sync=True)
            selected = traitlets.List([]).tag(sync=True)
            motion = traitlets.Dict().tag(sync=True)
            frames = traitlets.Dict().tag(sync=True)

        _VIEW.append(DiskView)
    return _VIEW[0]


def _disk(disk):
    import rollingdisk as rd

    if isinstance(disk, str):
        return rd.disk_from_options(disk=disk)
    if isinstance(disk, rd.Disk):
        return disk
    if isinstance(disk, int | float) and not isinstance(disk, bool):
        return rd.Disk(disk)
    raise ParameterTypeError(f"disk must be a rollingdisk.Disk, a half-thickness h >= 0 or "
                             f"a named disk ('euro-1', ...), got {type(disk).__name__}")


def _disk_record(disk) -> dict:
    rec = {"h": float(disk.h)}
    if disk.radius is not None:
        rec.update(radius_m=float(disk.radius), time_s=float(disk.time_to_si(1.0)),
                   rate_per_s=1.0 / float(disk.time_to_si(1.0)))
    return rec


def _map_record(disk, ground: str) -> dict:
    """The explorer's map of steady circles in the (theta0, omega30) plane (rows omega30,
    columns theta0), each point as a click there answers (:func:`.api.map_payload`)."""
    from rollingdisk.explore import api

    try:
        return api.map_payload({"plane": ["theta0-omega30"], "n": [str(MAP_N)],
                                "ymax": [repr(MAP_OMEGA30_MAX)]}, _defaults(disk, ground))
    except api.ApiError as exc:  # a disk beyond the explorer's (h in [0, 100])
        raise ParameterError(f"disk: {exc}") from None


def _defaults(disk, ground: str) -> dict:
    """What the explorer's server is started with for ``disk``: its ``h`` and ground, and
    the disk itself where it has a physical size (SI values beside the paper's)."""
    return {"h": float(disk.h), "ground": ground,
            "disk": disk if disk.radius is not None else None}


def _steady_record(disk, ground: str, theta0: float, omega30: float) -> tuple[dict, dict]:
    """``(motion, frames)`` after a click at ``(theta0, omega30)``: the explorer's answers
    (:func:`.api.steady_payload`, :func:`.api.simulate_payload`): the steady motion's numbers
    (or why there is none) and its motion kicked by :data:`KICK`, or ``{}`` where it cannot
    be simulated (too fast)."""
    from rollingdisk.explore import api

    query = {"theta0": [repr(theta0)], "omega30": [repr(omega30)]}
    defaults = _defaults(disk, ground)
    try:
        motion = api.steady_payload(query, defaults)
    except api.ApiError as exc:  # outside the explorer's ranges: said like no motion
        return {"exists": False, "theta0": theta0, "omega30": omega30,
                "reason": str(exc)}, {}
    if not motion["exists"]:
        return motion, {}
    try:
        frames = api.simulate_payload({**query, "kick": [repr(KICK)], "t_end": [repr(T_END)],
                                       "points": [str(FRAMES)]}, defaults)
    except api.ApiError:  # faster than the explorer simulates (|Omega0| > 20)
        return motion, {}
    return motion, frames


def traits(disk="euro-1", ground: str = "rough", selected=None) -> dict:
    """The traits :func:`widget` sends the browser, computed without a browser or anywidget
    (a static picture of what the view draws; tests).

    Parameters
    ----------
    disk : Disk, float or str
        As in :func:`widget`.
    ground : {"rough", "smooth"}
    selected : (theta0, omega30), optional
        A click on the map: the tilt [rad] and the spin about the axis [``sqrt(g/a)``].

    Returns
    -------
    dict
        ``disk`` (``h`` [``a``]; ``radius_m``, ``time_s`` = ``sqrt(a/g)`` [s] for a disk with
        a physical size), ``map`` (:func:`.api.map_payload` in the (theta0, omega30) plane);
        with ``selected``, ``motion`` (:func:`.api.steady_payload`) and ``frames``
        (:func:`.api.simulate_payload`: the motion kicked by :data:`KICK` over
        :data:`T_END`, ``{}`` where it is too fast to simulate or does not exist).

    Raises
    ------
    ParameterError
        ``ground`` unknown or the disk beyond the explorer's ``h`` in [0, 100].
    ParameterTypeError
        ``disk`` of another type.
    """
    if ground not in ("rough", "smooth"):
        raise ParameterError(f"ground must be 'rough' or 'smooth', got {ground!r}")
    d = _disk(disk)
    out = {"disk": _disk_record(d), "map": _map_record(d, ground)}
    if selected is not None:
        out["selected"] = [float(selected[0]), float(selected[1])]
        out["motion"], out["frames"] = _steady_record(d, ground, *out["selected"])
    return out


def widget(disk="euro-1", ground: str = "rough"):
    """A notebook view of ``disk``: its map of steady circles; a click shows the steady
    motion with units and its kicked 3D motion.

    Parameters
    ----------
    disk : Disk, float or str
        A :class:`~rollingdisk.Disk`, a half-thickness ``h`` [``a``] or a named disk
        (``"euro-1"``; :func:`rollingdisk.disk_from_options`).
    ground : {"rough", "smooth"}

    Returns
    -------
    anywidget.AnyWidget
        Traits: ``disk`` and ``map`` (sent once), ``selected`` (``[theta0, omega30]``, set
        by a click or from Python), ``motion`` and ``frames`` (computed by Python on each
        selection; ``motion["si"]`` holds SI values for a disk with a physical size).
    """
    anywidget, traitlets = _anywidget()
    first = traits(disk, ground)
    d = _disk(disk)

    class DiskExplorer(_view_class()):
        @traitlets.observe("selected")
        def _on_select(self, change):
            sel = change["new"]
            if len(sel) != 2:
                return
            self.motion, self.frames = _steady_record(d, ground, float(sel[0]), float(sel[1]))

    return DiskExplorer(**first)


def play(result, n_frames: int = 120):
    """A notebook view that plays ``result`` in 3D with a time slider.

    Parameters
    ----------
    result : Trajectory or MotionResult
        A run of :func:`rollingdisk.simulate` / :func:`rollingdisk.simulate_steady`, or of
        :func:`rollingdisk.simulate_to_rest` (a toss's ``motion`` too).
    n_frames : int
        Frames drawn, in [2, 2000].

    Returns
    -------
    anywidget.AnyWidget
        The same view as :func:`widget` without a map: ``frames`` holds the track drawn
        (:func:`.api.pose_track`: per frame ``t``, the centre C and the contact point P, the
        disk's axis and body-fixed radii; ``theta, psi, phi`` too for a Trajectory).
    """
    anywidget, traitlets = _anywidget()
    from rollingdisk.explore import api
    from rollingdisk.phases.motion import MotionResult
    from rollingdisk.results.trajectory import Trajectory
    from rollingdisk.util.checks import check_int

    if not isinstance(result, MotionResult | Trajectory):
        raise ParameterTypeError(f"result must be a Trajectory or a MotionResult, got "
                                 f"{type(result).__name__}")
    n_frames = check_int("n_frames", n_frames, low=2, high=2000)
    h = float(result.disk.h)
    if isinstance(result, MotionResult):
        from rollingdisk.plotting.motion_anim import motion_poses

        t, poses = motion_poses(result, n_frames, n=api.POSE_RIM)
        cols = {"X_C": [p.center[0] for p in poses], "Y_C": [p.center[1] for p in poses],
                "X_P": [p.contact[0] for p in poses], "Y_P": [p.contact[1] for p in poses]}
    else:
        from rollingdisk.plotting.animation import disk_pose

        t = np.linspace(result.t[0], result.t[-1], n_frames)
        cols = {k: np.interp(t, result.t, getattr(result, k))
                for k in ("theta", "psi", "phi", "X_C", "Y_C")}
        poses = [disk_pose(h, *(float(cols[k][i]) for k in ("X_C", "Y_C", "psi", "theta",
                                                               "phi")), n=api.POSE_RIM)
                 for i in range(t.size)]
        cols.update(X_P=[p.contact[0] for p in poses], Y_P=[p.contact[1] for p in poses])
    frames = {"h": h, **api.pose_track(h, poses, t=t, **cols)}
    return _view_class()(disk=_disk_record(result.disk), frames=frames)
