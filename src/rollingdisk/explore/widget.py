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

The drawing is the ES module ``static/widget.js`` shipped in the package: nothing is
loaded from the network.  anywidget is the optional extra ``rollingdisk[notebook]``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["widget", "play", "ESM_PATH"]

#: The ES module the widget draws with (shipped in the wheel with the package data).
ESM_PATH = Path(__file__).with_name("static") / "widget.js"
#: Map resolution (points per axis) and the largest omega30 of the map.
MAP_N, MAP_OMEGA30_MAX = 41, 3.0
#: The kicked motion drawn after a click: tilt kick [rad], span [sqrt(a/g)], frames.
KICK, T_END, FRAMES = 0.02, 30.0, 120


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
    columns theta0), each point as a click there answers (:mod:`rollingdisk.explore.api`)."""
    from rollingdisk.explore.api import _map

    return _map(ground, float(disk.h), "theta0-omega30", MAP_N, MAP_OMEGA30_MAX)


def _pose_frames(h: float, X, Y, psi, theta, phi, Z=None, t=None) -> dict:
    """The drawn disk at each point: rim circles and contact point, as flat lists."""
    from rollingdisk.plotting.animation import disk_pose

    rims, contact = [], []
    for i in range(len(X)):
        kw = {} if Z is None else {"Z_C": float(Z[i])}
        pose = disk_pose(h, float(X[i]), float(Y[i]), float(psi[i]), float(theta[i]),
                         float(phi[i]), n=24, **kw)
        rims.append([np.round(r.T, 5).tolist() for r in pose.rims])
        contact.append(np.round(pose.contact, 5).tolist())
    return {"t": [float(x) for x in (t if t is not None else range(len(X)))],
            "rims": rims, "contact": contact, "h": h}


def _steady_record(disk, ground: str, theta0: float, omega30: float) -> tuple[dict, dict]:
    """``(motion, frames)`` after a click: the numbers and the kicked motion."""
    import rollingdisk as rd

    try:
        m = rd.steady_motion(disk, ground, theta0, omega30=omega30)
    except rd.NoSteadyMotion as exc:
        return {"exists": False, "theta0": theta0, "omega30": omega30,
                "reason": str(exc)}, {}
    s = rd.stability(m)
    rec = {k: v for k, v in {**m.as_dict(), **s.as_dict()}.items()
           if isinstance(v, (int, float, str, bool)) or v is None}
    rec = {k: (None if isinstance(v, float) and not math.isfinite(v) else v)
           for k, v in rec.items()}
    rec["exists"] = True
    if disk.radius is not None:
        ts = float(disk.time_to_si(1.0))
        rec["si"] = {"Omega0 [rad/s]": m.Omega0 / ts, "omega30 [rad/s]": m.omega30 / ts,
                     "omega20 [rad/s]": m.omega20 / ts,
                     "r_C [m]": float(disk.length_to_si(m.r_C)),
                     "period [s]": (s.period * ts if s.period is not None
                                    and math.isfinite(s.period) else None)}
    frames = {}
    if abs(m.Omega0) <= 20.0:
        t = np.linspace(0.0, T_END, FRAMES)
        tr = rd.simulate_steady(m, T_END, perturb=KICK, t_eval=t, max_steps=20_000)
        frames = _pose_frames(disk.h, tr.X_C, tr.Y_C, tr.psi, tr.theta, tr.phi, t=tr.t)
        frames["status"] = tr.status
    return rec, frames


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
    if ground not in ("rough", "smooth"):
        raise ParameterError(f"ground must be 'rough' or 'smooth', got {ground!r}")
    d = _disk(disk)

    class DiskExplorer(_view_class()):
        @traitlets.observe("selected")
        def _on_select(self, change):
            sel = change["new"]
            if len(sel) != 2:
                return
            self.motion, self.frames = _steady_record(d, ground, float(sel[0]), float(sel[1]))

    return DiskExplorer(disk=_disk_record(d), map=_map_record(d, ground))


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
        The same view as :func:`widget` without a map: ``frames`` holds the drawn disk.
    """
    anywidget, traitlets = _anywidget()
    from rollingdisk.phases.motion import MotionResult
    from rollingdisk.results.trajectory import Trajectory
    from rollingdisk.util.checks import check_int

    n_frames = check_int("n_frames", n_frames, low=2, high=2000)
    if isinstance(result, MotionResult):
        from rollingdisk.plotting.motion_anim import motion_poses

        t, poses = motion_poses(result, n_frames, n=24)
        frames = {"t": [float(x) for x in t], "h": float(result.disk.h),
                  "rims": [[np.round(r.T, 5).tolist() for r in p.rims] for p in poses],
                  "contact": [np.round(p.contact, 5).tolist() for p in poses]}
        disk = result.disk
    elif isinstance(result, Trajectory):
        t = np.linspace(result.t[0], result.t[-1], n_frames)
        cols = {k: np.interp(t, result.t, getattr(result, k))
                for k in ("X_C", "Y_C", "psi", "theta", "phi")}
        frames = _pose_frames(result.disk.h, cols["X_C"], cols["Y_C"], cols["psi"],
                              cols["theta"], cols["phi"], t=t)
        disk = result.disk
    else:
        raise ParameterTypeError(f"result must be a Trajectory or a MotionResult, got "
                                 f"{type(result).__name__}")

    return _view_class()(disk=_disk_record(disk), frames=frames)
